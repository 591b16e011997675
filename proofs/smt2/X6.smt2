; rodimpact prove --export: claim X6 (beyond the paper)
; omega(a*) = (1+e) v0/(2a*) = (1+e)(v0/2) sqrt(mu/I); uniform rod: (1+e)(v0/2l) sqrt(3m/(M+m)); maximum on [0,l] is omega(min(a*, l))
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const I Real)
(declare-const M Real)
(declare-const V Real)
(declare-const V_l Real)
(declare-const V_s Real)
(declare-const a Real)
(declare-const e Real)
(declare-const l Real)
(declare-const m Real)
(declare-const omega Real)
(declare-const omega_l Real)
(declare-const omega_s Real)
(declare-const s Real)
(declare-const v Real)
(declare-const v0 Real)
(declare-const v_l Real)
(declare-const v_s Real)
; projectile mass and speed
(assert (and (> m 0) (> v0 0)))
; rod mass, moment of inertia about its centre
(assert (and (> M 0) (> I 0)))
; restitution coefficient
(assert (and (<= 0 e) (<= e 1)))
; linear momentum
(assert (= (* m v0) (+ (* m v) (* M V))))
; angular momentum about the fixed point at the rod's centre
(assert (= (* (* m v0) a) (+ (* (* m v) a) (* I omega))))
; Newton's law, restitution e
(assert (= (- (+ V (* omega a)) v) (* e v0)))
; linear momentum (impact s, at s)
(assert (= (* m v0) (+ (* m v_s) (* M V_s))))
; angular momentum about the fixed point at the rod's centre (impact s, at s)
(assert (= (* (* m v0) s) (+ (* (* m v_s) s) (* I omega_s))))
; Newton's law, restitution e (impact s, at s)
(assert (= (- (+ V_s (* omega_s s)) v_s) (* e v0)))
; linear momentum (impact l, at l)
(assert (= (* m v0) (+ (* m v_l) (* M V_l))))
; angular momentum about the fixed point at the rod's centre (impact l, at l)
(assert (= (* (* m v0) l) (+ (* (* m v_l) l) (* I omega_l))))
; Newton's law, restitution e (impact l, at l)
(assert (= (- (+ V_l (* omega_l l)) v_l) (* e v0)))
; hypothesis of the claim
(assert (> s 0))
; hypothesis of the claim
(assert (= (* s s) (/ (* (+ M m) I) (* m M))))
; check 1: omega(a*) = (1+e) v0/(2a*)
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (= omega_s (/ (* (+ 1 e) v0) (* 2 s)))))
(check-sat-using qfnra)
(pop 1)
; check 2: omega(a*)^2 = ((1+e) v0/2)^2 mu/I
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (= (* omega_s omega_s) (/ (* (* (/ (* (+ 1 e) v0) 2) (/ (* (+ 1 e) v0) 2)) (/ (* m M) (+ M m))) I))))
(check-sat-using qfnra)
(pop 1)
; check 3: the maximum on [0, l] is omega(min(a*, l))
; the hypotheses are consistent
(push 1)
(assert (> l 0))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (> l 0))
(assert (not (and (=> (and (<= s l) (<= 0 a) (<= a l)) (<= omega omega_s)) (=> (and (> s l) (<= 0 a) (<= a l)) (<= omega omega_l)))))
(check-sat-using qfnra)
(pop 1)
; check 4: uniform rod: omega(a*) = (1+e)(v0/2l) sqrt(3m/(M+m))
; the hypotheses are consistent
(push 1)
(assert (= I (/ (* M (* l l)) 3)))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= I (/ (* M (* l l)) 3)))
(assert (not (= (* omega_s omega_s) (/ (* (* (* (/ (* (+ 1 e) v0) (* 2 l)) (/ (* (+ 1 e) v0) (* 2 l))) 3) m) (+ M m)))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat sat unsat sat unsat
