; rodimpact prove --export: claim C34 (§intuition ¶1)
; The impulse depends on a
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const I Real)
(declare-const J_1 Real)
(declare-const J_2 Real)
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
; projectile: impulse -J (impact 1, at a1)
(assert (= (- (* m v_1) (* m v0)) (- J_1)))
; rod, linear: impulse J (impact 1, at a1)
(assert (= (* M V_1) J_1))
; rod, angular: moment of J (impact 1, at a1)
(assert (= (* I omega_1) (* J_1 a1)))
; Newton's law, e = 1 (impact 1, at a1)
(assert (= (- (+ V_1 (* omega_1 a1)) v_1) v0))
; projectile: impulse -J (impact 2, at a2)
(assert (= (- (* m v_2) (* m v0)) (- J_2)))
; rod, linear: impulse J (impact 2, at a2)
(assert (= (* M V_2) J_2))
; rod, angular: moment of J (impact 2, at a2)
(assert (= (* I omega_2) (* J_2 a2)))
; Newton's law, e = 1 (impact 2, at a2)
(assert (= (- (+ V_2 (* omega_2 a2)) v_2) v0))
; check 1: the impulse differs between a = 0 and a = l (M = m = l = v0 = 1)
; a witness
(push 1)
(assert (= m 1))
(assert (= M 1))
(assert (= l 1))
(assert (= v0 1))
(assert (= a1 0))
(assert (= a2 1))
(assert (not (= J_1 J_2)))
(check-sat-using qfnra)
(get-model)
(pop 1)
; expect: sat
