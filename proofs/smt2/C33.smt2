; rodimpact prove --export: claim C33 (§intuition ¶1)
; A given impulse J gives the largest omega at a = l
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const I Real)
(declare-const J Real)
(declare-const M Real)
(declare-const a Real)
(declare-const l Real)
(declare-const omega Real)
(declare-const omega_l Real)
; hypothesis of the claim
(assert (> M 0))
; hypothesis of the claim
(assert (> l 0))
; hypothesis of the claim
(assert (> J 0))
; hypothesis of the claim
(assert (= I (/ (* M (* l l)) 3)))
; hypothesis of the claim
(assert (= (* I omega) (* J a)))
; hypothesis of the claim
(assert (= (* I omega_l) (* J l)))
; check 1: for a given impulse J > 0, omega = J a/I is largest at a = l
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
