; rodimpact prove --export: claim X8 (beyond the paper)
; Uniform rod with k = M/m <= 2: (omega(l)/omega_max)^2 = 12(1+k)/(4+k)^2, which lies in (3/4, 1]; at M = m the ratio is 2sqrt6/5 = 0.9798. Aiming at a* therefore gains less than 2/sqrt3 - 1 = 15.5% over hitting the end. For a general r_G the gain is unbounded
; Not stated here: the unbounded gain for a general r_G (a statement about a limit over rods)
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const I Real)
(declare-const M Real)
(declare-const V_l Real)
(declare-const V_s Real)
(declare-const e Real)
(declare-const l Real)
(declare-const m Real)
(declare-const omega_l Real)
(declare-const omega_s Real)
(declare-const q Real)
(declare-const s Real)
(declare-const v0 Real)
(declare-const v_l Real)
(declare-const v_s Real)
; projectile mass and speed
(assert (and (> m 0) (> v0 0)))
; rod mass, half-length
(assert (and (> M 0) (> l 0)))
; uniform rod of length 2l
(assert (= I (/ (* M (* l l)) 3)))
; restitution coefficient
(assert (and (<= 0 e) (<= e 1)))
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
(assert (= (* s s) (/ (* (+ M m) (* l l)) (* 3 m))))
; check 1: (omega(l)/omega(a*))^2 = 12(1+k)/(4+k)^2, k = M/m
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (= (* (/ omega_l omega_s) (/ omega_l omega_s)) (/ (* 12 (+ 1 (/ M m))) (* (+ 4 (/ M m)) (+ 4 (/ M m)))))))
(check-sat-using qfnra)
(pop 1)
; check 2: which lies in (3/4, 1] for k <= 2
; the hypotheses are consistent
(push 1)
(assert (<= M (* 2 m)))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (<= M (* 2 m)))
(assert (not (and (< (/ 3 4) (* (/ omega_l omega_s) (/ omega_l omega_s))) (<= (* (/ omega_l omega_s) (/ omega_l omega_s)) 1))))
(check-sat-using qfnra)
(pop 1)
; check 3: at M = m the ratio is 2 sqrt6/5, so the gain is below 2/sqrt3 - 1
; the hypotheses are consistent
(push 1)
(assert (= M m))
(assert (> q 0))
(assert (= (* q q) 3))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= M m))
(assert (> q 0))
(assert (= (* q q) 3))
(assert (not (and (= (* (/ omega_l omega_s) (/ omega_l omega_s)) (/ 24 25)) (< (/ omega_s omega_l) (/ (* 2 q) 3)))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat sat unsat
