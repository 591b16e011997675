; rodimpact prove --export: claim X14 (beyond the paper)
; The far end moves with V(1 - a l/r_G^2): it moves backwards iff a > r_G^2/l (uniform rod: a > l/3)
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
(assert (> l 0))
; check 1: the far end moves with V (1 - a l/r_G^2)
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (= (- V (* omega l)) (* V (- 1 (/ (* a l) (* r r)))))))
(check-sat-using qfnra)
(pop 1)
; check 2: backwards iff a > r_G^2/l
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (and (=> (< (- V (* omega l)) 0) (> (* a l) (* r r))) (=> (> (* a l) (* r r)) (< (- V (* omega l)) 0)))))
(check-sat-using qfnra)
(pop 1)
; check 3: uniform rod: iff a > l/3
; the hypotheses are consistent
(push 1)
(assert (= (* 3 (* r r)) (* l l)))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= (* 3 (* r r)) (* l l)))
(assert (not (and (=> (< (- V (* omega l)) 0) (> a (/ l 3))) (=> (> a (/ l 3)) (< (- V (* omega l)) 0)))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat sat unsat
