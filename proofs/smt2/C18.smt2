; rodimpact prove --export: claim C18 (case (iii))
; M -> oo (I -> oo) gives v -> -v0, V -> 0, omega -> 0
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
(declare-const r Real)
(declare-const v Real)
(declare-const v0 Real)
; projectile mass and speed
(assert (and (> m 0) (> v0 0)))
; rod mass, radius of gyration
(assert (and (> M 0) (> r 0)))
; moment of inertia about the centre
(assert (= I (* M (* r r))))
; linear momentum
(assert (= (* m v0) (+ (* m v) (* M V))))
; angular momentum about the fixed point at the rod's centre
(assert (= (* (* m v0) a) (+ (* (* m v) a) (* I omega))))
; Newton's law, e = 1
(assert (= (- (+ V (* omega a)) v) v0))
; check 1: bounds vanishing as M -> oo with r fixed: |v + v0| <= 2 v0 (m/M)(1 + a^2/r^2), |V| <= 2 m v0/M, |omega| <= 2 m |a| v0/(M r^2); hence v -> -v0, V -> 0, omega -> 0
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (and (<= (* (+ v v0) (+ v v0)) (* (* (* (* 2 v0) (/ m M)) (+ 1 (/ (* a a) (* r r)))) (* (* (* 2 v0) (/ m M)) (+ 1 (/ (* a a) (* r r)))))) (<= (* V V) (* (/ (* (* 2 m) v0) M) (/ (* (* 2 m) v0) M))) (<= (* omega omega) (* (/ (* (* (* 2 m) a) v0) (* M (* r r))) (/ (* (* (* 2 m) a) v0) (* M (* r r))))))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat
