; rodimpact prove --export: claim X17 (beyond the paper)
; M -> oo: omega ~ 2m a v0/(M r_G^2), v + v0 ~ 2m v0(1 + a^2/r_G^2)/M; with restitution, v -> -e v0
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
(declare-const r Real)
(declare-const v Real)
(declare-const v0 Real)
; projectile mass and speed
(assert (and (> m 0) (> v0 0)))
; rod mass, radius of gyration
(assert (and (> M 0) (> r 0)))
; moment of inertia about the centre
(assert (= I (* M (* r r))))
; restitution coefficient
(assert (and (<= 0 e) (<= e 1)))
; linear momentum
(assert (= (* m v0) (+ (* m v) (* M V))))
; angular momentum about the fixed point at the rod's centre
(assert (= (* (* m v0) a) (+ (* (* m v) a) (* I omega))))
; Newton's law, restitution e
(assert (= (- (+ V (* omega a)) v) (* e v0)))
; check 1: bounds vanishing as M -> oo: |v + e v0| <= (1+e) v0 m (r^2 + a^2)/(M r^2), |M omega - (1+e) m a v0/r^2| <= (1+e) m^2 |a| v0 (r^2 + a^2)/(M r^4)
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (and (<= (* (+ v (* e v0)) (+ v (* e v0))) (* (/ (* (* (* (+ 1 e) v0) m) (+ (* r r) (* a a))) (* M (* r r))) (/ (* (* (* (+ 1 e) v0) m) (+ (* r r) (* a a))) (* M (* r r))))) (<= (* (- (* M omega) (/ (* (* (* (+ 1 e) m) a) v0) (* r r))) (- (* M omega) (/ (* (* (* (+ 1 e) m) a) v0) (* r r)))) (* (/ (* (* (* (* (+ 1 e) (* m m)) a) v0) (+ (* r r) (* a a))) (* M (* r r r r))) (/ (* (* (* (* (+ 1 e) (* m m)) a) v0) (+ (* r r) (* a a))) (* M (* r r r r))))))))
(check-sat-using qfnra)
(pop 1)
; check 2: elastic: |M (v + v0) - 2 m v0 (1 + a^2/r^2)| <= 2 m^2 v0 (r^2 + a^2)^2/(M r^4)
; the hypotheses are consistent
(push 1)
(assert (= e 1))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= e 1))
(assert (not (<= (* (- (* M (+ v v0)) (* (* (* 2 m) v0) (+ 1 (/ (* a a) (* r r))))) (- (* M (+ v v0)) (* (* (* 2 m) v0) (+ 1 (/ (* a a) (* r r)))))) (* (/ (* (* (* 2 (* m m)) v0) (* (+ (* r r) (* a a)) (+ (* r r) (* a a)))) (* M (* r r r r))) (/ (* (* (* 2 (* m m)) v0) (* (+ (* r r) (* a a)) (+ (* r r) (* a a)))) (* M (* r r r r)))))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat
