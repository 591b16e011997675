; rodimpact prove --export: claim C31 (§optimum ¶2)
; The inelastic case needs the shifted CM and the modified I
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
; check 1: the reading that omega after sticking needs the composite's CM and I_c is refuted: the momentum balances about the rod's centre with the rod's own I give the composite's omega = mu a v0/(I + mu a^2), mu = m M/(M + m), for every a
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (= omega (/ (/ (* (* (* m M) a) v0) (+ M m)) (+ I (/ (* (* m M) (* a a)) (+ M m)))))))
(check-sat-using qfnra)
(pop 1)
; check 2: what is true: the pair's CM y_c = m a/(M + m) moves at V_c = m v0/(M + m), and the energy after is (M + m) V_c^2/2 + I_c omega^2/2 with I_c = I + mu a^2
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (and (= (/ (+ (* m v) (* M V)) (+ M m)) (/ (* m v0) (+ M m))) (= (+ (+ (* m (* v v)) (* M (* V V))) (* I (* omega omega))) (+ (* (+ M m) (* (/ (* m v0) (+ M m)) (/ (* m v0) (+ M m)))) (* (+ I (/ (* (* m M) (* a a)) (+ M m))) (* omega omega)))))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat
