; rodimpact prove --export: claim X15 (beyond the paper)
; The elastic rod takes all of K0 where the projectile stops (a0), not at a*: a*^2 - a0^2 = 2l^2/3
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
(declare-const l Real)
(declare-const m Real)
(declare-const omega Real)
(declare-const omega_s Real)
(declare-const s Real)
(declare-const v Real)
(declare-const v0 Real)
(declare-const v_s Real)
(declare-const z Real)
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
; linear momentum (impact s, at s)
(assert (= (* m v0) (+ (* m v_s) (* M V_s))))
; angular momentum about the fixed point at the rod's centre (impact s, at s)
(assert (= (* (* m v0) s) (+ (* (* m v_s) s) (* I omega_s))))
; Newton's law, e = 1 (impact s, at s)
(assert (= (- (+ V_s (* omega_s s)) v_s) v0))
; hypothesis of the claim
(assert (= z (/ (* (* l l) (- M m)) (* 3 m))))
; hypothesis of the claim
(assert (> s 0))
; hypothesis of the claim
(assert (= (* s s) (/ (* (+ M m) (* l l)) (* 3 m))))
; check 1: v = v0 (a^2 - a0^2)/(a^2 + a*^2), a0^2 = l^2 (M - m)/(3m)
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (= v (/ (* v0 (- (* a a) z)) (+ (* a a) (* s s))))))
(check-sat-using qfnra)
(pop 1)
; check 2: the rod's energy is K0 (1 - (v/v0)^2): all of K0 exactly where v = 0
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (= (+ (* M (* V V)) (* I (* omega omega))) (* (* m (* v0 v0)) (- 1 (* (/ v v0) (/ v v0)))))))
(check-sat-using qfnra)
(pop 1)
; check 3: a*^2 - a0^2 = 2 l^2/3
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (= (- (* s s) z) (/ (* 2 (* l l)) 3))))
(check-sat-using qfnra)
(pop 1)
; check 4: at a* the projectile keeps v = v0 l^2/(3 a*^2) > 0
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (and (= v_s (/ (* v0 (* l l)) (* 3 (* s s)))) (> v_s 0))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat sat unsat sat unsat
