; rodimpact prove --export: claim C43 (§inhomogeneous)
; Mass concentrated near the ends (r_G close to l): a* < l only for M << m
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const I Real)
(declare-const M Real)
(declare-const l Real)
(declare-const m Real)
(declare-const r Real)
(declare-const s Real)
(declare-const u Real)
(declare-const v0 Real)
; projectile mass and speed
(assert (and (> m 0) (> v0 0)))
; rod mass, radius of gyration
(assert (and (> M 0) (> r 0)))
; moment of inertia about the centre
(assert (= I (* M (* r r))))
; hypothesis of the claim
(assert (> l 0))
; hypothesis of the claim
(assert (> u 0))
; hypothesis of the claim
(assert (< u l))
; hypothesis of the claim
(assert (= r (- l u)))
; hypothesis of the claim
(assert (> s 0))
; hypothesis of the claim
(assert (= (* s s) (/ (* (+ M m) (* r r)) m)))
; check 1: a* < l iff M/m < l^2/r_G^2 - 1 = u (2l - u)/(l - u)^2 for r_G = l - u, a bound that vanishes as u -> 0+
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (and (=> (< s l) (< (/ M m) (/ (* u (- (* 2 l) u)) (* (- l u) (- l u))))) (=> (< (/ M m) (/ (* u (- (* 2 l) u)) (* (- l u) (- l u)))) (< s l)))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat
