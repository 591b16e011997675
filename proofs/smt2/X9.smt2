; rodimpact prove --export: claim X9 (beyond the paper)
; Elastic, at a*: v = V = m v0/(M+m), the CM velocity of the system. The rotational KE is mu v0^2/2, all of the CM-frame energy, which is a fraction M/(M+m) of K0. König's theorem gives I omega^2/2 = mu v0^2/2 - [m(v - v_cm)^2 + M(V - v_cm)^2]/2, an energy proof that omega <= v0/a*
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const I Real)
(declare-const M Real)
(declare-const V Real)
(declare-const V_s Real)
(declare-const a Real)
(declare-const m Real)
(declare-const omega Real)
(declare-const omega_s Real)
(declare-const s Real)
(declare-const v Real)
(declare-const v0 Real)
(declare-const v_s Real)
; projectile mass and speed
(assert (and (> m 0) (> v0 0)))
; rod mass, moment of inertia about its centre
(assert (and (> M 0) (> I 0)))
; linear momentum
(assert (= (* m v0) (+ (* m v) (* M V))))
; angular momentum about the fixed point at the rod's centre
(assert (= (* (* m v0) a) (+ (* (* m v) a) (* I omega))))
; Newton's law, e = 1
(assert (= (- (+ V (* omega a)) v) v0))
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
; check 1: at a*: v = V = m v0/(M + m), the CM velocity
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (and (= v_s (/ (* m v0) (+ M m))) (= V_s (/ (* m v0) (+ M m))))))
(check-sat-using qfnra)
(pop 1)
; check 2: at a* the rotational energy is mu v0^2/2, a fraction M/(M+m) of K0
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (and (= (* I (* omega_s omega_s)) (* (/ (* m M) (+ M m)) (* v0 v0))) (= (* (/ (* m M) (+ M m)) (* v0 v0)) (* (/ M (+ M m)) (* m (* v0 v0)))))))
(check-sat-using qfnra)
(pop 1)
; check 3: König: I omega^2/2 = mu v0^2/2 - [m (v - v_cm)^2 + M (V - v_cm)^2]/2
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (= (* I (* omega omega)) (- (* (/ (* m M) (+ M m)) (* v0 v0)) (+ (* m (* (- v (/ (* m v0) (+ M m))) (- v (/ (* m v0) (+ M m))))) (* M (* (- V (/ (* m v0) (+ M m))) (- V (/ (* m v0) (+ M m))))))))))
(check-sat-using qfnra)
(pop 1)
; check 4: hence omega <= v0/a* for a >= 0
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (=> (>= a 0) (<= omega (/ v0 s)))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat sat unsat sat unsat
