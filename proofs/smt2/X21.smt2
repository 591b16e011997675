; rodimpact prove --export: claim X21 (beyond the paper)
; The struck point's speed after the impact, (1+e) v0 m/(m + M_eff(a)), increases strictly with a: intuition holds for the struck point but not for omega
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const I Real)
(declare-const M Real)
(declare-const V Real)
(declare-const V_1 Real)
(declare-const V_2 Real)
(declare-const a Real)
(declare-const a1 Real)
(declare-const a2 Real)
(declare-const e Real)
(declare-const m Real)
(declare-const omega Real)
(declare-const omega_1 Real)
(declare-const omega_2 Real)
(declare-const r Real)
(declare-const v Real)
(declare-const v0 Real)
(declare-const v_1 Real)
(declare-const v_2 Real)
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
; linear momentum (impact 1, at a1)
(assert (= (* m v0) (+ (* m v_1) (* M V_1))))
; angular momentum about the fixed point at the rod's centre (impact 1, at a1)
(assert (= (* (* m v0) a1) (+ (* (* m v_1) a1) (* I omega_1))))
; Newton's law, restitution e (impact 1, at a1)
(assert (= (- (+ V_1 (* omega_1 a1)) v_1) (* e v0)))
; linear momentum (impact 2, at a2)
(assert (= (* m v0) (+ (* m v_2) (* M V_2))))
; angular momentum about the fixed point at the rod's centre (impact 2, at a2)
(assert (= (* (* m v0) a2) (+ (* (* m v_2) a2) (* I omega_2))))
; Newton's law, restitution e (impact 2, at a2)
(assert (= (- (+ V_2 (* omega_2 a2)) v_2) (* e v0)))
; check 1: the struck point's speed is (1+e) v0 m/(m + M_eff)
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (= (+ V (* omega a)) (/ (* (* (+ 1 e) v0) m) (+ m (/ (* M (* r r)) (+ (* r r) (* a a))))))))
(check-sat-using qfnra)
(pop 1)
; check 2: it increases strictly with a >= 0
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (=> (and (<= 0 a1) (< a1 a2)) (< (+ V_1 (* omega_1 a1)) (+ V_2 (* omega_2 a2))))))
(check-sat-using qfnra)
(pop 1)
; check 3: omega does not: M = m, r_G = l/2, omega(0.7 l) > omega(l)
; a witness
(push 1)
(assert (= m 1))
(assert (= M 1))
(assert (= r (/ 1 2)))
(assert (= v0 1))
(assert (= e 1))
(assert (= a1 (/ 7 10)))
(assert (= a2 1))
(assert (> omega_1 omega_2))
(check-sat-using qfnra)
(get-model)
(pop 1)
; expect: sat unsat sat unsat sat
