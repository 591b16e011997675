; rodimpact prove --export: claim C45 (§inhomogeneous)
; Intuition is fully vindicated only for the ideal dumbbell
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const I Real)
(declare-const M Real)
(declare-const V_l Real)
(declare-const V_s Real)
(declare-const l Real)
(declare-const m Real)
(declare-const omega_l Real)
(declare-const omega_s Real)
(declare-const r Real)
(declare-const s Real)
(declare-const v0 Real)
(declare-const v_l Real)
(declare-const v_s Real)
; projectile mass and speed
(assert (and (> m 0) (> v0 0)))
; rod mass, radius of gyration
(assert (and (> M 0) (> r 0)))
; moment of inertia about the centre
(assert (= I (* M (* r r))))
; linear momentum (impact s, at s)
(assert (= (* m v0) (+ (* m v_s) (* M V_s))))
; angular momentum about the fixed point at the rod's centre (impact s, at s)
(assert (= (* (* m v0) s) (+ (* (* m v_s) s) (* I omega_s))))
; Newton's law, e = 1 (impact s, at s)
(assert (= (- (+ V_s (* omega_s s)) v_s) v0))
; linear momentum (impact l, at l)
(assert (= (* m v0) (+ (* m v_l) (* M V_l))))
; angular momentum about the fixed point at the rod's centre (impact l, at l)
(assert (= (* (* m v0) l) (+ (* (* m v_l) l) (* I omega_l))))
; Newton's law, e = 1 (impact l, at l)
(assert (= (- (+ V_l (* omega_l l)) v_l) v0))
; hypothesis of the claim
(assert (> l 0))
; hypothesis of the claim
(assert (> s 0))
; hypothesis of the claim
(assert (= (* s s) (/ (* (+ M m) (* r r)) m)))
; check 1: every r_G < l has masses with an interior optimum: M = m (l^2 - r_G^2)/(2 r_G^2) gives a* < l and omega(a*) > omega(l)
; the hypotheses are consistent
(push 1)
(assert (< r l))
(assert (= M (/ (* m (- (* l l) (* r r))) (* 2 (* r r)))))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (< r l))
(assert (= M (/ (* m (- (* l l) (* r r))) (* 2 (* r r)))))
(assert (not (and (< s l) (> omega_s omega_l))))
(check-sat-using qfnra)
(pop 1)
; check 2: r_G = l (the dumbbell): a* > l for all masses
; the hypotheses are consistent
(push 1)
(assert (= r l))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= r l))
(assert (not (> s l)))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat
