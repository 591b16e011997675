; rodimpact prove --export: claim X18 (beyond the paper)
; Pivoted rod (fixed axis): omega = (1+e) m d v0/(I_p + m d^2), maximal at d* = sqrt(I_p/m) (inside a door iff M < 3m). The pivot impulse vanishes at d = I_p/(M h), the centre of percussion (2L/3 for a door)
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const Ip Real)
(declare-const J Real)
(declare-const J_s Real)
(declare-const L Real)
(declare-const M Real)
(declare-const P Real)
(declare-const P_s Real)
(declare-const d Real)
(declare-const ds Real)
(declare-const e Real)
(declare-const h Real)
(declare-const m Real)
(declare-const omega Real)
(declare-const omega_s Real)
(declare-const v Real)
(declare-const v0 Real)
(declare-const v_s Real)
; projectile mass and speed
(assert (and (> m 0) (> v0 0)))
; rod mass, moment about the pivot
(assert (and (> M 0) (> Ip 0)))
; restitution coefficient
(assert (and (<= 0 e) (<= e 1)))
; projectile: impulse -J
(assert (= (- (* m v) (* m v0)) (- J)))
; rod, linear: impulses J and the pivot's P
(assert (= (* (* M h) omega) (+ J P)))
; rod, angular: moment of J
(assert (= (* Ip omega) (* J d)))
; Newton's law, restitution e
(assert (= (- (* omega d) v) (* e v0)))
; projectile: impulse -J (impact s, at ds)
(assert (= (- (* m v_s) (* m v0)) (- J_s)))
; rod, linear: impulses J and the pivot's P (impact s, at ds)
(assert (= (* (* M h) omega_s) (+ J_s P_s)))
; rod, angular: moment of J (impact s, at ds)
(assert (= (* Ip omega_s) (* J_s ds)))
; Newton's law, restitution e (impact s, at ds)
(assert (= (- (* omega_s ds) v_s) (* e v0)))
; hypothesis of the claim
(assert (> ds 0))
; hypothesis of the claim
(assert (= (* ds ds) (/ Ip m)))
; check 1: omega = (1+e) m d v0/(I_p + m d^2)
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (= omega (/ (* (* (* (+ 1 e) m) d) v0) (+ Ip (* m (* d d)))))))
(check-sat-using qfnra)
(pop 1)
; check 2: the unique maximum over d >= 0 is at d* = sqrt(I_p/m)
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (=> (and (>= d 0) (not (= d ds))) (< omega omega_s))))
(check-sat-using qfnra)
(pop 1)
; check 3: door (I_p = M L^2/3): d* < L iff M < 3m
; the hypotheses are consistent
(push 1)
(assert (> L 0))
(assert (= Ip (/ (* M (* L L)) 3)))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (> L 0))
(assert (= Ip (/ (* M (* L L)) 3)))
(assert (not (and (=> (< ds L) (< M (* 3 m))) (=> (< M (* 3 m)) (< ds L)))))
(check-sat-using qfnra)
(pop 1)
; check 4: the pivot's impulse vanishes iff d = I_p/(M h), the centre of percussion
; the hypotheses are consistent
(push 1)
(assert (> h 0))
(assert (> d 0))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (> h 0))
(assert (> d 0))
(assert (not (and (=> (= P 0) (= (* (* d M) h) Ip)) (=> (= (* (* d M) h) Ip) (= P 0)))))
(check-sat-using qfnra)
(pop 1)
; check 5: reading: a wrong centre of percussion, d = I_p/(2 M h), where the impulse would vanish; refuted
; the negation of the reading is satisfiable
(push 1)
(assert (> h 0))
(assert (> d 0))
(assert (not (=> (= (* (* (* 2 d) M) h) Ip) (= P 0))))
(check-sat-using qfnra)
(get-model)
(pop 1)
; check 6: reading: the impulse vanishes only at d = I_p/(2 M h); refuted
; the negation of the reading is satisfiable
(push 1)
(assert (> h 0))
(assert (> d 0))
(assert (not (=> (= P 0) (= (* (* (* 2 d) M) h) Ip))))
(check-sat-using qfnra)
(get-model)
(pop 1)
; check 7: door: at 2L/3 from the hinge
; the hypotheses are consistent
(push 1)
(assert (> L 0))
(assert (= Ip (/ (* M (* L L)) 3)))
(assert (= h (/ L 2)))
(assert (= d (/ (* 2 L) 3)))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (> L 0))
(assert (= Ip (/ (* M (* L L)) 3)))
(assert (= h (/ L 2)))
(assert (= d (/ (* 2 L) 3)))
(assert (not (= P 0)))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat sat unsat sat unsat sat sat sat unsat
