; rodimpact prove --export: claim C20 (Eq. (maximal-a-general))
; omega = 2 v0 a/(a*^2 + a^2), so the unconstrained maximum over a > 0 is at a* = sqrt((M+m)I/(mM))
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const I Real)
(declare-const M Real)
(declare-const V Real)
(declare-const V_s Real)
(declare-const a Real)
(declare-const m Real)
(declare-const omega Real)
(declare-const omega_s Real)
(declare-const s Real)
(declare-const v Real)
(declare-const v0 Real)
(declare-const v_s Real)
; projectile mass and speed
(assert (and (> m 0) (> v0 0)))
; rod mass, moment of inertia about its centre
(assert (and (> M 0) (> I 0)))
; linear momentum
(assert (= (* m v0) (+ (* m v) (* M V))))
; angular momentum about the fixed point at the rod's centre
(assert (= (* (* m v0) a) (+ (* (* m v) a) (* I omega))))
; Newton's law, e = 1
(assert (= (- (+ V (* omega a)) v) v0))
; linear momentum (impact s, at s)
(assert (= (* m v0) (+ (* m v_s) (* M V_s))))
; angular momentum about the fixed point at the rod's centre (impact s, at s)
(assert (= (* (* m v0) s) (+ (* (* m v_s) s) (* I omega_s))))
; Newton's law, e = 1 (impact s, at s)
(assert (= (- (+ V_s (* omega_s s)) v_s) v0))
; hypothesis of the claim
(assert (> s 0))
; hypothesis of the claim
(assert (= (* s s) (/ (* (+ M m) I) (* m M))))
; check 1: omega = 2 v0 a/(a*^2 + a^2)
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (= omega (/ (* (* 2 v0) a) (+ (* s s) (* a a))))))
(check-sat-using qfnra)
(pop 1)
; check 2: the maximum over a >= 0 is at a* and only there
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (=> (and (>= a 0) (not (= a s))) (< omega omega_s))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat
