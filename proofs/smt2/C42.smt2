; rodimpact prove --export: claim C42 (§inhomogeneous)
; Mass concentrated near the middle (r_G << l) gives a* < l "even for M >> m"
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
(assert (< r l))
; hypothesis of the claim
(assert (> s 0))
; hypothesis of the claim
(assert (= (* s s) (/ (* (+ M m) (* r r)) m)))
; check 1: reading: a small r_G/l gives a* < l even for M >> m; refuted at r_G = l/20, M = 1000 m
; the negation of the reading is satisfiable
(push 1)
(assert (= m 1))
(assert (= M 1000))
(assert (= l 20))
(assert (= r 1))
(assert (not (< s l)))
(check-sat-using qfnra)
(get-model)
(pop 1)
; check 2: qualified: M < m (l^2/r_G^2 - 1) gives a* < l
; the hypotheses are consistent
(push 1)
(assert (< M (* m (- (/ (* l l) (* r r)) 1))))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (< M (* m (- (/ (* l l) (* r r)) 1))))
(assert (not (< s l)))
(check-sat-using qfnra)
(pop 1)
; check 3: and only it
; the hypotheses are consistent
(push 1)
(assert (>= M (* m (- (/ (* l l) (* r r)) 1))))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (>= M (* m (- (/ (* l l) (* r r)) 1))))
(assert (not (>= s l)))
(check-sat-using qfnra)
(pop 1)
; expect: sat sat unsat sat unsat
