; rodimpact prove --export: claim X19 (beyond the paper)
; Elastic, at a*: the projectile is at rest relative to the rod's centre, so half a turn later (t = pi a*/v0) the other arm hits it from behind at closing speed v0. A second impact is unavoidable
; Not stated here: the kinematic step after the impact (the rod turns by pi in time pi a*/v0), argued by hand as in the certificate
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const I Real)
(declare-const M Real)
(declare-const V_s Real)
(declare-const m Real)
(declare-const omega_s Real)
(declare-const s Real)
(declare-const v0 Real)
(declare-const v_s Real)
; projectile mass and speed
(assert (and (> m 0) (> v0 0)))
; rod mass, moment of inertia about its centre
(assert (and (> M 0) (> I 0)))
; linear momentum (impact s, at s)
(assert (= (* m v0) (+ (* m v_s) (* M V_s))))
; angular momentum about the fixed point at the rod's centre (impact s, at s)
(assert (= (* (* m v0) s) (+ (* (* m v_s) s) (* I omega_s))))
; Newton's law, e = 1 (impact s, at s)
(assert (= (- (+ V_s (* omega_s s)) v_s) v0))
; hypothesis of the claim
(assert (> s 0))
; hypothesis of the claim
(assert (= (* s s) (/ (* (+ M m) I) (* m M))))
; check 1: at a*: v = V = m v0/(M + m) and omega a* = v0 (the projectile rests relative to the rod's centre, which meets it again after half a turn with closing speed omega a* = v0)
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (and (= v_s (/ (* m v0) (+ M m))) (= V_s (/ (* m v0) (+ M m))) (= (* omega_s s) v0))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat
