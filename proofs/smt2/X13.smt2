; rodimpact prove --export: claim X13 (beyond the paper)
; The rod point momentarily at rest after the impact is at y0 = -r_G^2/a, whatever m, v0 and e are; a·|y0| = r_G^2 (centre-of-percussion conjugacy). Uniform rod: y0 is on the rod iff a >= l/3; an end hit gives y0 = -l/3
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
(declare-const l Real)
(declare-const m Real)
(declare-const omega Real)
(declare-const r Real)
(declare-const v Real)
(declare-const v0 Real)
(declare-const y0 Real)
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
; hypothesis of the claim
(assert (> a 0))
; hypothesis of the claim
(assert (= y0 (/ (- (* r r)) a)))
; check 1: the rod point y0 = -r_G^2/a is at rest after the impact
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (and (= (+ V (* omega y0)) 0) (= (* a (- y0)) (* r r)))))
(check-sat-using qfnra)
(pop 1)
; check 2: uniform rod: y0 on the rod iff a >= l/3
; the hypotheses are consistent
(push 1)
(assert (= (* 3 (* r r)) (* l l)))
(assert (> l 0))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= (* 3 (* r r)) (* l l)))
(assert (> l 0))
(assert (not (and (=> (<= (- y0) l) (>= a (/ l 3))) (=> (>= a (/ l 3)) (<= (- y0) l)))))
(check-sat-using qfnra)
(pop 1)
; check 3: uniform rod hit at the end: y0 = -l/3
; the hypotheses are consistent
(push 1)
(assert (= (* 3 (* r r)) (* l l)))
(assert (> l 0))
(assert (= a l))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= (* 3 (* r r)) (* l l)))
(assert (> l 0))
(assert (= a l))
(assert (not (= y0 (/ (- l) 3))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat sat unsat
