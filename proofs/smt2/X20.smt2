; rodimpact prove --export: claim X20 (beyond the paper)
; The rod's share of the angular momentum, I omega/(m v0 a) = (1+e)/D, decreases strictly with a
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
(declare-const v Real)
(declare-const v0 Real)
(declare-const v_1 Real)
(declare-const v_2 Real)
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
; check 1: the rod's share I omega/(m v0 a) = (1+e)/D
; the hypotheses are consistent
(push 1)
(assert (> a 0))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (> a 0))
(assert (not (= (/ (* I omega) (* (* m v0) a)) (/ (+ 1 e) (+ (+ 1 (/ m M)) (/ (* m (* a a)) I))))))
(check-sat-using qfnra)
(pop 1)
; check 2: the share decreases strictly with a > 0
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (=> (and (< 0 a1) (< a1 a2)) (< (/ (* I omega_2) (* (* m v0) a2)) (/ (* I omega_1) (* (* m v0) a1))))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat
