; rodimpact prove --export: claim X1 (beyond the paper)
; General restitution e in [0,1] (Newton's law at the contact): the solution is unique (det = -(mI + MI + Mma^2)), with J = (1+e) v0/(1/m + 1/M + a^2/I), v = v0 - J/m, V = J/M, omega = J a/I
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const I Real)
(declare-const J Real)
(declare-const J_2 Real)
(declare-const M Real)
(declare-const V Real)
(declare-const V_2 Real)
(declare-const a Real)
(declare-const e Real)
(declare-const m Real)
(declare-const omega Real)
(declare-const omega_2 Real)
(declare-const v Real)
(declare-const v0 Real)
(declare-const v_2 Real)
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
; projectile: impulse -J (impact 2, at a)
(assert (= (- (* m v_2) (* m v0)) (- J_2)))
; rod, linear: impulse J (impact 2, at a)
(assert (= (* M V_2) J_2))
; rod, angular: moment of J (impact 2, at a)
(assert (= (* I omega_2) (* J_2 a)))
; Newton's law, restitution e (impact 2, at a)
(assert (= (- (+ V_2 (* omega_2 a)) v_2) (* e v0)))
; check 1: the impulse and the velocities
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (and (= J (/ (* (+ 1 e) v0) (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I)))) (= v (- v0 (/ J m))) (= V (/ J M)) (= omega (/ (* J a) I)))))
(check-sat-using qfnra)
(pop 1)
; check 2: the solution is unique: two solutions of the same equations agree
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (and (= v v_2) (= V V_2) (= omega omega_2) (= J J_2))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat
