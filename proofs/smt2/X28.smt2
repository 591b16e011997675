; rodimpact prove --export: claim X28 (beyond the paper)
; The stick/slide threshold in closed form (mu_f the Coulomb friction coefficient): the contact sticks iff mu_f >= mu_f* = |u_t| k_n/((1+e) u_n k_t), u_t the slip, u_n the approach speed, k_n = 1/m + 1/M + a^2/I and k_t = 1/m + 1/M (+ 2/m for a solid disc); at mu_f = mu_f* sliding and sticking give the same impulse
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
(declare-const Vt Real)
(declare-const a Real)
(declare-const d Real)
(declare-const e Real)
(declare-const m Real)
(declare-const mu_f Real)
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
(assert (= (* M V) J))
; rod, angular: moment of (J, Jt) applied at (d, a)
(assert (= (* I omega) (- (* a J) (* d Jt))))
; Newton's law, restitution e
(assert (= (- (+ V (* omega a)) v) (* e v0)))
; projectile, along the rod: impulse -Jt
(assert (= (- (* m vt) (* m v0t)) (- Jt)))
; rod, along its axis: impulse Jt
(assert (= (* M Vt) Jt))
; disc, angular about its centre: moment of -Jt at its rim
(assert (= (* (* m (* rd rd)) (- spin w)) (* (* (- 2) rd) Jt)))
; sticking: the disc's contact point ends moving with the rod's, along the rod
(assert (= (+ vt (* spin rd)) (- Vt (* omega d))))
; check 1: disc: the sticking impulse over the normal one is u_t k_n/((1+e) v0 k_t), k_t = 3/m + 1/M
; the hypotheses are consistent
(push 1)
(assert (> rd 0))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (> rd 0))
(assert (not (= (* (* (* Jt (+ 1 e)) v0) (+ (/ 3 m) (/ 1 M))) (* (* J (+ v0t (* w rd))) (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I))))))
(check-sat-using qfnra)
(pop 1)
; check 2: point (rd = 0): the sticking impulse over the normal one is v0t k_n/((1+e) v0 k_t), k_t = 1/m + 1/M
; the hypotheses are consistent
(push 1)
(assert (= rd 0))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= rd 0))
(assert (not (= (* (* (* Jt (+ 1 e)) v0) (+ (/ 1 m) (/ 1 M))) (* (* J v0t) (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I))))))
(check-sat-using qfnra)
(pop 1)
; check 3: disc, u_t >= 0: the sticking impulse is within the friction cone (|Jt| <= mu_f J) exactly when mu_f >= mu_f*
; the hypotheses are consistent
(push 1)
(assert (> rd 0))
(assert (>= mu_f 0))
(assert (>= (+ v0t (* w rd)) 0))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (> rd 0))
(assert (>= mu_f 0))
(assert (>= (+ v0t (* w rd)) 0))
(assert (not (and (=> (and (<= Jt (* mu_f J)) (<= (- Jt) (* mu_f J))) (>= (* (* (* mu_f (+ 1 e)) v0) (+ (/ 3 m) (/ 1 M))) (* (+ v0t (* w rd)) (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I))))) (=> (>= (* (* (* mu_f (+ 1 e)) v0) (+ (/ 3 m) (/ 1 M))) (* (+ v0t (* w rd)) (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I)))) (and (<= Jt (* mu_f J)) (<= (- Jt) (* mu_f J)))))))
(check-sat-using qfnra)
(pop 1)
; check 4: disc, at mu_f = mu_f*: the sticking impulse obeys the sliding law Jt = mu_f J, so slide and stick coincide
; the hypotheses are consistent
(push 1)
(assert (> rd 0))
(assert (= (* (* (* mu_f (+ 1 e)) v0) (+ (/ 3 m) (/ 1 M))) (* (+ v0t (* w rd)) (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I)))))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (> rd 0))
(assert (= (* (* (* mu_f (+ 1 e)) v0) (+ (/ 3 m) (/ 1 M))) (* (+ v0t (* w rd)) (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I)))))
(assert (not (= Jt (* mu_f J))))
(check-sat-using qfnra)
(pop 1)
; check 5: point, u_t >= 0: the sticking impulse is within the friction cone (|Jt| <= mu_f J) exactly when mu_f >= mu_f*
; the hypotheses are consistent
(push 1)
(assert (= rd 0))
(assert (>= mu_f 0))
(assert (>= v0t 0))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= rd 0))
(assert (>= mu_f 0))
(assert (>= v0t 0))
(assert (not (and (=> (and (<= Jt (* mu_f J)) (<= (- Jt) (* mu_f J))) (>= (* (* (* mu_f (+ 1 e)) v0) (+ (/ 1 m) (/ 1 M))) (* v0t (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I))))) (=> (>= (* (* (* mu_f (+ 1 e)) v0) (+ (/ 1 m) (/ 1 M))) (* v0t (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I)))) (and (<= Jt (* mu_f J)) (<= (- Jt) (* mu_f J)))))))
(check-sat-using qfnra)
(pop 1)
; check 6: point, at mu_f = mu_f*: the sticking impulse obeys the sliding law Jt = mu_f J
; the hypotheses are consistent
(push 1)
(assert (= rd 0))
(assert (= (* (* (* mu_f (+ 1 e)) v0) (+ (/ 1 m) (/ 1 M))) (* v0t (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I)))))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= rd 0))
(assert (= (* (* (* mu_f (+ 1 e)) v0) (+ (/ 1 m) (/ 1 M))) (* v0t (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I)))))
(assert (not (= Jt (* mu_f J))))
(check-sat-using qfnra)
(pop 1)
; check 7: reading: the disc's moment of inertia taken as m rd^2/4 (k_t = 5/m + 1/M), it sticks once mu_f reaches that lower threshold; refuted
; the negation of the reading is satisfiable
(push 1)
(assert (> rd 0))
(assert (>= mu_f 0))
(assert (>= (+ v0t (* w rd)) 0))
(assert (not (=> (>= (* (* (* mu_f (+ 1 e)) v0) (+ (/ 5 m) (/ 1 M))) (* (+ v0t (* w rd)) (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I)))) (and (<= Jt (* mu_f J)) (<= (- Jt) (* mu_f J))))))
(check-sat-using qfnra)
(get-model)
(pop 1)
; check 8: reading: a disc sticks only above the point's threshold (k_t = 1/m + 1/M); refuted
; the negation of the reading is satisfiable
(push 1)
(assert (> rd 0))
(assert (>= mu_f 0))
(assert (>= (+ v0t (* w rd)) 0))
(assert (not (=> (and (<= Jt (* mu_f J)) (<= (- Jt) (* mu_f J))) (>= (* (* (* mu_f (+ 1 e)) v0) (+ (/ 1 m) (/ 1 M))) (* (+ v0t (* w rd)) (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I)))))))
(check-sat-using qfnra)
(get-model)
(pop 1)
; expect: sat unsat sat unsat sat unsat sat unsat sat unsat sat unsat sat sat
