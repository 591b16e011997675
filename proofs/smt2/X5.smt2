; rodimpact prove --export: claim X5 (beyond the paper)
; omega_e = (1+e) v0 a/(a*^2 + a^2): a* does not depend on e or v0. At a* the rotational compliance a^2/I equals the translational compliance 1/m + 1/M, and J(a*) = J(0)/2
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const I Real)
(declare-const J Real)
(declare-const J_0 Real)
(declare-const J_s Real)
(declare-const M Real)
(declare-const V Real)
(declare-const V_0 Real)
(declare-const V_s Real)
(declare-const a Real)
(declare-const e Real)
(declare-const m Real)
(declare-const omega Real)
(declare-const omega_0 Real)
(declare-const omega_s Real)
(declare-const s Real)
(declare-const v Real)
(declare-const v0 Real)
(declare-const v_0 Real)
(declare-const v_s Real)
; projectile mass and speed
(assert (and (> m 0) (> v0 0)))
; rod mass, moment of inertia about its centre
(assert (and (> M 0) (> I 0)))
; restitution coefficient
(assert (and (<= 0 e) (<= e 1)))
; projectile: impulse -J
(assert (= (- (* m v) (* m v0)) (- J)))
; rod, linear: impulse J
(assert (= (* M V) J))
; rod, angular: moment of J
(assert (= (* I omega) (* J a)))
; Newton's law, restitution e
(assert (= (- (+ V (* omega a)) v) (* e v0)))
; projectile: impulse -J (impact s, at s)
(assert (= (- (* m v_s) (* m v0)) (- J_s)))
; rod, linear: impulse J (impact s, at s)
(assert (= (* M V_s) J_s))
; rod, angular: moment of J (impact s, at s)
(assert (= (* I omega_s) (* J_s s)))
; Newton's law, restitution e (impact s, at s)
(assert (= (- (+ V_s (* omega_s s)) v_s) (* e v0)))
; projectile: impulse -J (impact 0, at 0)
(assert (= (- (* m v_0) (* m v0)) (- J_0)))
; rod, linear: impulse J (impact 0, at 0)
(assert (= (* M V_0) J_0))
; rod, angular: moment of J (impact 0, at 0)
(assert (= (* I omega_0) (* J_0 0)))
; Newton's law, restitution e (impact 0, at 0)
(assert (= (- (+ V_0 (* omega_0 0)) v_0) (* e v0)))
; hypothesis of the claim
(assert (> s 0))
; hypothesis of the claim
(assert (= (* s s) (/ (* (+ M m) I) (* m M))))
; check 1: omega_e = (1+e) v0 a/(a*^2 + a^2)
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (= omega (/ (* (* (+ 1 e) v0) a) (+ (* s s) (* a a))))))
(check-sat-using qfnra)
(pop 1)
; check 2: a* maximises omega_e over a >= 0 for every e and v0
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
; check 3: at a* the rotational compliance equals the translational one
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (= (/ (* s s) I) (+ (/ 1 m) (/ 1 M)))))
(check-sat-using qfnra)
(pop 1)
; check 4: J(a*) = J(0)/2
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (= J_s (/ J_0 2))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat sat unsat sat unsat
