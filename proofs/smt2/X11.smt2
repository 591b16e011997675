; rodimpact prove --export: claim X11 (beyond the paper)
; Energy lost ΔK = (1 - e^2) m_eff v0^2/2 >= 0; for e = 0, ΔK/K0 = 1/D; at a*, ΔK/K0 = (1 - e^2) M/(2(M+m))
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
(declare-const e Real)
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
; restitution coefficient
(assert (and (<= 0 e) (<= e 1)))
; linear momentum
(assert (= (* m v0) (+ (* m v) (* M V))))
; angular momentum about the fixed point at the rod's centre
(assert (= (* (* m v0) a) (+ (* (* m v) a) (* I omega))))
; Newton's law, restitution e
(assert (= (- (+ V (* omega a)) v) (* e v0)))
; linear momentum (impact s, at s)
(assert (= (* m v0) (+ (* m v_s) (* M V_s))))
; angular momentum about the fixed point at the rod's centre (impact s, at s)
(assert (= (* (* m v0) s) (+ (* (* m v_s) s) (* I omega_s))))
; Newton's law, restitution e (impact s, at s)
(assert (= (- (+ V_s (* omega_s s)) v_s) (* e v0)))
; hypothesis of the claim
(assert (> s 0))
; hypothesis of the claim
(assert (= (* s s) (/ (* (+ M m) I) (* m M))))
; check 1: energy lost: 2 dK = (1 - e^2) m_eff v0^2, m_eff = 1/(1/m + 1/M + a^2/I)
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (= (- (* m (* v0 v0)) (+ (+ (* m (* v v)) (* M (* V V))) (* I (* omega omega)))) (/ (* (- 1 (* e e)) (* v0 v0)) (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I))))))
(check-sat-using qfnra)
(pop 1)
; check 2: dK >= 0
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (<= (+ (+ (* m (* v v)) (* M (* V V))) (* I (* omega omega))) (* m (* v0 v0)))))
(check-sat-using qfnra)
(pop 1)
; check 3: e = 0: dK/K0 = 1/D
; the hypotheses are consistent
(push 1)
(assert (= e 0))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= e 0))
(assert (not (= (/ (- (* m (* v0 v0)) (+ (+ (* m (* v v)) (* M (* V V))) (* I (* omega omega)))) (* m (* v0 v0))) (/ 1 (+ (+ 1 (/ m M)) (/ (* m (* a a)) I))))))
(check-sat-using qfnra)
(pop 1)
; check 4: at a*: dK/K0 = (1 - e^2) M/(2(M+m))
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (= (/ (- (* m (* v0 v0)) (+ (+ (* m (* v_s v_s)) (* M (* V_s V_s))) (* I (* omega_s omega_s)))) (* m (* v0 v0))) (/ (* (- 1 (* e e)) M) (* 2 (+ M m))))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat sat unsat sat unsat
