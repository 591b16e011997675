; rodimpact prove --export: claim X23 (beyond the paper)
; Sticking loses (mu v0^2/2) I/(I + mu a^2) = K0/D; at a*, I_c = 2I and omega = v0/(2a*)
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
; sticking: the projectile moves with the struck point
(assert (= v (+ V (* omega a))))
; linear momentum (impact s, at s)
(assert (= (* m v0) (+ (* m v_s) (* M V_s))))
; angular momentum about the fixed point at the rod's centre (impact s, at s)
(assert (= (* (* m v0) s) (+ (* (* m v_s) s) (* I omega_s))))
; sticking: the projectile moves with the struck point (impact s, at s)
(assert (= v_s (+ V_s (* omega_s s))))
; hypothesis of the claim
(assert (> s 0))
; hypothesis of the claim
(assert (= (* s s) (/ (* (+ M m) I) (* m M))))
; check 1: sticking loses (mu v0^2/2) I/(I + mu a^2) = K0/D
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (and (= (- (* m (* v0 v0)) (+ (+ (* m (* v v)) (* M (* V V))) (* I (* omega omega)))) (/ (* (* (/ (* m M) (+ M m)) (* v0 v0)) I) (+ I (* (/ (* m M) (+ M m)) (* a a))))) (= (/ (* (* (/ (* m M) (+ M m)) (* v0 v0)) I) (+ I (* (/ (* m M) (+ M m)) (* a a)))) (/ (* m (* v0 v0)) (+ (+ 1 (/ m M)) (/ (* m (* a a)) I)))))))
(check-sat-using qfnra)
(pop 1)
; check 2: at a*: I_c = 2I and omega = v0/(2a*)
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (and (= (+ I (* (/ (* m M) (+ M m)) (* s s))) (* 2 I)) (= omega_s (/ v0 (* 2 s))))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat
