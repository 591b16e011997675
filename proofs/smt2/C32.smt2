; rodimpact prove --export: claim C32 (§intuition ¶1)
; About a fixed axis (doors, levers), the farther from the axis one strikes, the bigger the angular velocity (decide it in this paper's setting: a projectile of mass m, speed v0, striking a rod on a fixed pivot)
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const Ip Real)
(declare-const M Real)
(declare-const d1 Real)
(declare-const d2 Real)
(declare-const ds Real)
(declare-const e Real)
(declare-const m Real)
(declare-const omega_1 Real)
(declare-const omega_2 Real)
(declare-const v0 Real)
(declare-const v_1 Real)
(declare-const v_2 Real)
; projectile mass and speed
(assert (and (> m 0) (> v0 0)))
; rod mass, moment about the pivot
(assert (and (> M 0) (> Ip 0)))
; restitution coefficient
(assert (and (<= 0 e) (<= e 1)))
; angular momentum about the pivot (impact 1, at d1)
(assert (= (* (* m v0) d1) (+ (* (* m v_1) d1) (* Ip omega_1))))
; Newton's law, restitution e (impact 1, at d1)
(assert (= (- (* omega_1 d1) v_1) (* e v0)))
; angular momentum about the pivot (impact 2, at d2)
(assert (= (* (* m v0) d2) (+ (* (* m v_2) d2) (* Ip omega_2))))
; Newton's law, restitution e (impact 2, at d2)
(assert (= (- (* omega_2 d2) v_2) (* e v0)))
; check 1: reading: omega grows with the arm d; refuted for a door (Ip = M (2l)^2/3) with M = m = l = v0 = 1, e = 1 between d1 = 1 and d2 = 2
; the negation of the reading is satisfiable
(push 1)
(assert (= m 1))
(assert (= M 1))
(assert (= Ip (/ 4 3)))
(assert (= v0 1))
(assert (= e 1))
(assert (= d1 1))
(assert (= d2 2))
(assert (not (=> (and (< 0 d1) (< d1 d2)) (< omega_1 omega_2))))
(check-sat-using qfnra)
(get-model)
(pop 1)
; check 2: qualified: it grows on every arm up to d* = sqrt(Ip/m)
; the hypotheses are consistent
(push 1)
(assert (> ds 0))
(assert (= (* ds ds) (/ Ip m)))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (> ds 0))
(assert (= (* ds ds) (/ Ip m)))
(assert (not (=> (and (<= 0 d1) (< d1 d2) (<= d2 ds)) (< omega_1 omega_2))))
(check-sat-using qfnra)
(pop 1)
; expect: sat sat unsat
