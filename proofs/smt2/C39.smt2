; rodimpact prove --export: claim C39 (after (impulse-angular))
; For M large enough, a = l wins
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const I Real)
(declare-const M Real)
(declare-const V Real)
(declare-const V_l Real)
(declare-const a Real)
(declare-const l Real)
(declare-const m Real)
(declare-const omega Real)
(declare-const omega_l Real)
(declare-const v Real)
(declare-const v0 Real)
(declare-const v_l Real)
; projectile mass and speed
(assert (and (> m 0) (> v0 0)))
; rod mass, half-length
(assert (and (> M 0) (> l 0)))
; uniform rod of length 2l
(assert (= I (/ (* M (* l l)) 3)))
; linear momentum
(assert (= (* m v0) (+ (* m v) (* M V))))
; angular momentum about the fixed point at the rod's centre
(assert (= (* (* m v0) a) (+ (* (* m v) a) (* I omega))))
; Newton's law, e = 1
(assert (= (- (+ V (* omega a)) v) v0))
; linear momentum (impact l, at l)
(assert (= (* m v0) (+ (* m v_l) (* M V_l))))
; angular momentum about the fixed point at the rod's centre (impact l, at l)
(assert (= (* (* m v0) l) (+ (* (* m v_l) l) (* I omega_l))))
; Newton's law, e = 1 (impact l, at l)
(assert (= (- (+ V_l (* omega_l l)) v_l) v0))
; hypothesis of the claim
(assert (>= M (* 2 m)))
; check 1: M >= 2m: a = l wins on [0, l]
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (=> (and (<= 0 a) (< a l)) (< omega omega_l))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat
