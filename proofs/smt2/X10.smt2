; rodimpact prove --export: claim X10 (beyond the paper)
; General e, at a*: v - V = (1-e) v0/2, V = (1+e) m v0/(2(M+m)), K_rot = ((1+e)/2)^2 mu v0^2/2
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const I Real)
(declare-const M Real)
(declare-const V_s Real)
(declare-const e Real)
(declare-const m Real)
(declare-const omega_s Real)
(declare-const s Real)
(declare-const v0 Real)
(declare-const v_s Real)
; projectile mass and speed
(assert (and (> m 0) (> v0 0)))
; rod mass, moment of inertia about its centre
(assert (and (> M 0) (> I 0)))
; restitution coefficient
(assert (and (<= 0 e) (<= e 1)))
; linear momentum (impact s, at s)
(assert (= (* m v0) (+ (* m v_s) (* M V_s))))
; angular momentum about the fixed point at the rod's centre (impact s, at s)
(assert (= (* (* m v0) s) (+ (* (* m v_s) s) (* I omega_s))))
; Newton's law, restitution e (impact s, at s)
(assert (= (- (+ V_s (* omega_s s)) v_s) (* e v0)))
; hypothesis of the claim
(assert (> s 0))
; hypothesis of the claim
(assert (= (* s s) (/ (* (+ M m) I) (* m M))))
; check 1: at a*: v - V, V and the rotational energy
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (and (= (- v_s V_s) (/ (* (- 1 e) v0) 2)) (= V_s (/ (* (* (+ 1 e) m) v0) (* 2 (+ M m)))) (= (* I (* omega_s omega_s)) (* (* (* (/ (+ 1 e) 2) (/ (+ 1 e) 2)) (/ (* m M) (+ M m))) (* v0 v0))))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat
