; rodimpact prove --export: claim X29 (beyond the paper)
; Galilean invariance: a rod sliding with (V0, Vt0) before the impact gives, relative to that frame, exactly the answer of the rod at rest struck with (v0 - V0, v0t - Vt0): the velocities shift by the frame's, omega, the disc's spin, both impulses and the contact do not change
; Not stated here: the sliding contact (the same invariance) is certified by rodimpact only: one scene per exported statement
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const I Real)
(declare-const J Real)
(declare-const Jt Real)
(declare-const M Real)
(declare-const V Real)
(declare-const V0 Real)
(declare-const Vt Real)
(declare-const Vt0 Real)
(declare-const a Real)
(declare-const d Real)
(declare-const e Real)
(declare-const m Real)
(declare-const omega Real)
(declare-const rd Real)
(declare-const spin Real)
(declare-const v Real)
(declare-const v0 Real)
(declare-const v0t Real)
(declare-const vt Real)
(declare-const w Real)
; projectile mass and speed
(assert (and (> m 0) (> v0 0)))
; rod mass, moment of inertia about its centre
(assert (and (> M 0) (> I 0)))
; restitution coefficient
(assert (and (<= 0 e) (<= e 1)))
; the projectile a solid disc of radius rd (rd = 0: a point), moment m*rd^2/2 about its centre
(assert (>= rd 0))
; the rod struck on its axis: the contact point is (d, a) from the centre, d = 0 (a thin rod)
(assert (= d 0))
; projectile: impulse -J
(assert (= (- (* m v) (* m v0)) (- J)))
; rod, linear: impulse J
(assert (= (* M (- V V0)) J))
; rod, angular: moment of (J, Jt) applied at (d, a)
(assert (= (* I omega) (- (* a J) (* d Jt))))
; Newton's law, restitution e
(assert (= (- (+ V (* omega a)) v) (* e (- v0 V0))))
; projectile, along the rod: impulse -Jt
(assert (= (- (* m vt) (* m v0t)) (- Jt)))
; rod, along its axis: impulse Jt
(assert (= (* M (- Vt Vt0)) Jt))
; disc, angular about its centre: moment of -Jt at its rim
(assert (= (* (* m (* rd rd)) (- spin w)) (* (* (- 2) rd) Jt)))
; sticking: the disc's contact point ends moving with the rod's, along the rod
(assert (= (+ vt (* spin rd)) (- Vt (* omega d))))
; check 1: disc: the rod at rest's answer in the relative velocities (v0 - V0, v0t - Vt0): J, Jt and omega from the relative approach, each velocity shifted by the frame's
; the hypotheses are consistent
(push 1)
(assert (> rd 0))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (> rd 0))
(assert (not (and (= (* J (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I))) (* (+ 1 e) (- v0 V0))) (= (* Jt (+ (/ 3 m) (/ 1 M))) (+ (- v0t Vt0) (* w rd))) (= (* I omega) (* a J)) (= (- v V0) (- (- v0 V0) (/ J m))) (= (- vt Vt0) (- (- v0t Vt0) (/ Jt m))) (= (- V V0) (/ J M)) (= (- Vt Vt0) (/ Jt M)) (= spin (- w (/ (* 2 Jt) (* m rd)))))))
(check-sat-using qfnra)
(pop 1)
; check 2: point (rd = 0): the rod at rest's answer in the relative velocities, k_t = 1/m + 1/M
; the hypotheses are consistent
(push 1)
(assert (= rd 0))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= rd 0))
(assert (not (and (= (* J (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I))) (* (+ 1 e) (- v0 V0))) (= (* Jt (+ (/ 1 m) (/ 1 M))) (- v0t Vt0)) (= (* I omega) (* a J)) (= (- v V0) (- (- v0 V0) (/ J m))) (= (- vt Vt0) (- (- v0t Vt0) (/ Jt m))) (= (- V V0) (/ J M)) (= (- Vt Vt0) (/ Jt M)))))
(check-sat-using qfnra)
(pop 1)
; check 3: reading: the rod's drift does not enter the impulse (J k_n = (1 + e) v0); refuted
; the negation of the reading is satisfiable
(push 1)
(assert (= rd 0))
(assert (not (= (* J (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I))) (* (+ 1 e) v0))))
(check-sat-using qfnra)
(get-model)
(pop 1)
; expect: sat unsat sat unsat sat
