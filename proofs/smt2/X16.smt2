; rodimpact prove --export: claim X16 (beyond the paper)
; M -> 0 with r_G fixed: v -> v0, V -> 2v0 r^2/(r^2 + a^2), omega -> 2v0 a/(r^2 + a^2), the struck point -> 2v0, a* -> r_G
; Not stated here: the struck point's limit (1+e) v0 with restitution (the elastic case is stated)
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
(declare-const s Real)
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
; hypothesis of the claim
(assert (> s 0))
; hypothesis of the claim
(assert (= (* s s) (/ (* (+ M m) (* r r)) m)))
; check 1: bounds vanishing as M -> 0+: |v - v0|, |V - 2 v0 r^2/(r^2 + a^2)| and |V + omega a - 2 v0| are at most 2 v0 M/m, |omega - 2 v0 a/(r^2 + a^2)| at most 2 v0 |a| M/(m (r^2 + a^2))
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (and (<= (* (- v v0) (- v v0)) (* (/ (* (* 2 v0) M) m) (/ (* (* 2 v0) M) m))) (<= (* (- V (/ (* (* 2 v0) (* r r)) (+ (* r r) (* a a)))) (- V (/ (* (* 2 v0) (* r r)) (+ (* r r) (* a a))))) (* (/ (* (* 2 v0) M) m) (/ (* (* 2 v0) M) m))) (<= (* (- omega (/ (* (* 2 v0) a) (+ (* r r) (* a a)))) (- omega (/ (* (* 2 v0) a) (+ (* r r) (* a a))))) (* (/ (* (* (* 2 v0) a) M) (* m (+ (* r r) (* a a)))) (/ (* (* (* 2 v0) a) M) (* m (+ (* r r) (* a a)))))) (<= (* (- (+ V (* omega a)) (* 2 v0)) (- (+ V (* omega a)) (* 2 v0))) (* (/ (* (* 2 v0) M) m) (/ (* (* 2 v0) M) m))))))
(check-sat-using qfnra)
(pop 1)
; check 2: a*^2 - r_G^2 = (M/m) r_G^2
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (= (- (* s s) (* r r)) (* (/ M m) (* r r)))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat
