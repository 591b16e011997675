; rodimpact prove --export: claim X2 (beyond the paper)
; e = 1 reproduces Eqs. (v), (V), (omega) and conserves energy exactly; with C7, energy conservation is equivalent to e = 1
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
(declare-const e Real)
(declare-const m Real)
(declare-const omega Real)
(declare-const v Real)
(declare-const v0 Real)
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
; check 1: e = 1 gives Eqs. (v), (V), (omega)
; the hypotheses are consistent
(push 1)
(assert (= e 1))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= e 1))
(assert (not (and (= v (* (/ (- (- (- 1 (/ m M)) (/ (* m (* a a)) I))) (+ (+ 1 (/ m M)) (/ (* m (* a a)) I))) v0)) (= V (* (/ (/ (* 2 m) M) (+ (+ 1 (/ m M)) (/ (* m (* a a)) I))) v0)) (= omega (* (/ (/ (* (* 2 m) a) I) (+ (+ 1 (/ m M)) (/ (* m (* a a)) I))) v0)))))
(check-sat-using qfnra)
(pop 1)
; check 2: e = 1 conserves kinetic energy
; the hypotheses are consistent
(push 1)
(assert (= e 1))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= e 1))
(assert (not (= (* m (* v0 v0)) (+ (+ (* m (* v v)) (* M (* V V))) (* I (* omega omega))))))
(check-sat-using qfnra)
(pop 1)
; check 3: conserved kinetic energy forces e = 1
; the hypotheses are consistent
(push 1)
(assert (= (* m (* v0 v0)) (+ (+ (* m (* v v)) (* M (* V V))) (* I (* omega omega)))))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= (* m (* v0 v0)) (+ (+ (* m (* v v)) (* M (* V V))) (* I (* omega omega)))))
(assert (not (= e 1)))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat sat unsat
