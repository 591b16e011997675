; rodimpact prove --export: claim X7 (beyond the paper)
; Universal curve: omega(a)/omega(a*) = 2s/(1+s^2) with s = a/a*; reciprocity omega(a) = omega(a*^2/a)
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const I Real)
(declare-const M Real)
(declare-const V Real)
(declare-const V_r Real)
(declare-const V_s Real)
(declare-const a Real)
(declare-const e Real)
(declare-const m Real)
(declare-const omega Real)
(declare-const omega_r Real)
(declare-const omega_s Real)
(declare-const s Real)
(declare-const v Real)
(declare-const v0 Real)
(declare-const v_r Real)
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
; linear momentum (impact r, at s^2/a)
(assert (= (* m v0) (+ (* m v_r) (* M V_r))))
; angular momentum about the fixed point at the rod's centre (impact r, at s^2/a)
(assert (= (* (* m v0) (/ (* s s) a)) (+ (* (* m v_r) (/ (* s s) a)) (* I omega_r))))
; Newton's law, restitution e (impact r, at s^2/a)
(assert (= (- (+ V_r (* omega_r (/ (* s s) a))) v_r) (* e v0)))
; hypothesis of the claim
(assert (> a 0))
; hypothesis of the claim
(assert (> s 0))
; hypothesis of the claim
(assert (= (* s s) (/ (* (+ M m) I) (* m M))))
; check 1: omega(a)/omega(a*) = 2s/(1+s^2) with s = a/a*
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (= (/ omega omega_s) (/ (* 2 (/ a s)) (+ 1 (* (/ a s) (/ a s)))))))
(check-sat-using qfnra)
(pop 1)
; check 2: reciprocity omega(a) = omega(a*^2/a)
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (= omega omega_r)))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat
