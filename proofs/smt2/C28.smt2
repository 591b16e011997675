; rodimpact prove --export: claim C28 (§optimum ¶2)
; M = m gives a* = sqrt(2/3) l
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
(declare-const s Real)
(declare-const v0 Real)
; projectile mass and speed
(assert (and (> m 0) (> v0 0)))
; rod mass, half-length
(assert (and (> M 0) (> l 0)))
; uniform rod of length 2l
(assert (= I (/ (* M (* l l)) 3)))
; hypothesis of the claim
(assert (= M m))
; hypothesis of the claim
(assert (> s 0))
; hypothesis of the claim
(assert (= (* s s) (/ (* (+ M m) (* l l)) (* 3 m))))
; check 1: M = m: a*^2 = 2 l^2/3
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (= (* s s) (/ (* 2 (* l l)) 3))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat
