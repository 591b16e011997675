; rodimpact prove --export: claim C36 (after (impulse-linear))
; I_lin decreases as a increases
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const I Real)
(declare-const M Real)
(declare-const V_1 Real)
(declare-const V_2 Real)
(declare-const a1 Real)
(declare-const a2 Real)
(declare-const l Real)
(declare-const m Real)
(declare-const omega_1 Real)
(declare-const omega_2 Real)
(declare-const v0 Real)
(declare-const v_1 Real)
(declare-const v_2 Real)
; projectile mass and speed
(assert (and (> m 0) (> v0 0)))
; rod mass, half-length
(assert (and (> M 0) (> l 0)))
; uniform rod of length 2l
(assert (= I (/ (* M (* l l)) 3)))
; linear momentum (impact 1, at a1)
(assert (= (* m v0) (+ (* m v_1) (* M V_1))))
; angular momentum about the fixed point at the rod's centre (impact 1, at a1)
(assert (= (* (* m v0) a1) (+ (* (* m v_1) a1) (* I omega_1))))
; Newton's law, e = 1 (impact 1, at a1)
(assert (= (- (+ V_1 (* omega_1 a1)) v_1) v0))
; linear momentum (impact 2, at a2)
(assert (= (* m v0) (+ (* m v_2) (* M V_2))))
; angular momentum about the fixed point at the rod's centre (impact 2, at a2)
(assert (= (* (* m v0) a2) (+ (* (* m v_2) a2) (* I omega_2))))
; Newton's law, e = 1 (impact 2, at a2)
(assert (= (- (+ V_2 (* omega_2 a2)) v_2) v0))
; check 1: I_lin = M V decreases as a increases (a >= 0)
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (=> (and (<= 0 a1) (< a1 a2)) (< (* M V_2) (* M V_1)))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat
