; rodimpact prove --export: claim X3 (beyond the paper)
; Sticking model: y_c = ma/(M+m), V_c = m v0/(M+m), I_c = I + mu a^2, omega = mu a v0/(I + mu a^2). It is identical to Newton e = 0 at the impact instant
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const I Real)
(declare-const M Real)
(declare-const V Real)
(declare-const a Real)
(declare-const m Real)
(declare-const omega Real)
(declare-const v Real)
(declare-const v0 Real)
; projectile mass and speed
(assert (and (> m 0) (> v0 0)))
; rod mass, moment of inertia about its centre
(assert (and (> M 0) (> I 0)))
; linear momentum
(assert (= (* m v0) (+ (* m v) (* M V))))
; angular momentum about the fixed point at the rod's centre
(assert (= (* (* m v0) a) (+ (* (* m v) a) (* I omega))))
; sticking: the projectile moves with the struck point
(assert (= v (+ V (* omega a))))
; check 1: omega = mu a v0/(I + mu a^2), mu = m M/(M + m)
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (= omega (/ (* (* (/ (* m M) (+ M m)) a) v0) (+ I (* (/ (* m M) (+ M m)) (* a a)))))))
(check-sat-using qfnra)
(pop 1)
; check 2: the pair moves as one rigid body: its CM y_c = m a/(M + m) at V_c = m v0/(M + m), each point y at V_c + omega (y - y_c)
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (and (= (/ (+ (* m v) (* M V)) (+ M m)) (/ (* m v0) (+ M m))) (= v (+ (/ (* m v0) (+ M m)) (* omega (- a (/ (* m a) (+ M m)))))) (= V (+ (/ (* m v0) (+ M m)) (* omega (- 0 (/ (* m a) (+ M m)))))))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat
