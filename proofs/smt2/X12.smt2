; rodimpact prove --export: claim X12 (beyond the paper)
; v = v0 (m - e M_eff)/(m + M_eff) with M_eff = M r_G^2/(r_G^2 + a^2): the projectile bounces back iff m < e M_eff, stops iff m = e M_eff, goes on iff m > e M_eff. Uniform rod, e = 1: M_eff runs over [M/4, M] and the projectile stops at a0 = l sqrt((M - m)/(3m)), which lies on the rod for m <= M <= 4m. It always goes on for e = 0, and at a* for e = 1
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const I Real)
(declare-const M Real)
(declare-const Me Real)
(declare-const V Real)
(declare-const V_s Real)
(declare-const a Real)
(declare-const e Real)
(declare-const l Real)
(declare-const m Real)
(declare-const omega Real)
(declare-const omega_s Real)
(declare-const r Real)
(declare-const s Real)
(declare-const v Real)
(declare-const v0 Real)
(declare-const v_s Real)
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
; linear momentum (impact s, at s)
(assert (= (* m v0) (+ (* m v_s) (* M V_s))))
; angular momentum about the fixed point at the rod's centre (impact s, at s)
(assert (= (* (* m v0) s) (+ (* (* m v_s) s) (* I omega_s))))
; Newton's law, restitution e (impact s, at s)
(assert (= (- (+ V_s (* omega_s s)) v_s) (* e v0)))
; hypothesis of the claim
(assert (> l 0))
; hypothesis of the claim
(assert (= Me (/ (* M (* r r)) (+ (* r r) (* a a)))))
; hypothesis of the claim
(assert (> s 0))
; hypothesis of the claim
(assert (= (* s s) (/ (* (+ M m) (* r r)) m)))
; check 1: v = v0 (m - e M_eff)/(m + M_eff), M_eff = M r_G^2/(r_G^2 + a^2)
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (= v (/ (* v0 (- m (* e Me))) (+ m Me)))))
(check-sat-using qfnra)
(pop 1)
; check 2: bounces back iff m < e M_eff, stops iff m = e M_eff
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (and (=> (< v 0) (< m (* e Me))) (=> (< m (* e Me)) (< v 0)) (=> (= v 0) (= m (* e Me))) (=> (= m (* e Me)) (= v 0)))))
(check-sat-using qfnra)
(pop 1)
; check 3: uniform rod: M_eff in [M/4, M] on the rod
; the hypotheses are consistent
(push 1)
(assert (= (* 3 (* r r)) (* l l)))
(assert (<= 0 a))
(assert (<= a l))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= (* 3 (* r r)) (* l l)))
(assert (<= 0 a))
(assert (<= a l))
(assert (not (and (<= (/ M 4) Me) (<= Me M))))
(check-sat-using qfnra)
(pop 1)
; check 4: uniform rod, e = 1: the projectile stops at a0 = l sqrt((M - m)/(3m)), on the rod iff M <= 4m
; the hypotheses are consistent
(push 1)
(assert (= e 1))
(assert (= (* 3 (* r r)) (* l l)))
(assert (>= M m))
(assert (>= a 0))
(assert (= (* a a) (/ (* (* l l) (- M m)) (* 3 m))))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= e 1))
(assert (= (* 3 (* r r)) (* l l)))
(assert (>= M m))
(assert (>= a 0))
(assert (= (* a a) (/ (* (* l l) (- M m)) (* 3 m))))
(assert (not (and (= v 0) (=> (<= a l) (<= M (* 4 m))) (=> (<= M (* 4 m)) (<= a l)))))
(check-sat-using qfnra)
(pop 1)
; check 5: e = 0: it always goes on
; the hypotheses are consistent
(push 1)
(assert (= e 0))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= e 0))
(assert (not (> v 0)))
(check-sat-using qfnra)
(pop 1)
; check 6: e = 1 at a*: it goes on
; the hypotheses are consistent
(push 1)
(assert (= e 1))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= e 1))
(assert (not (> v_s 0)))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat sat unsat sat unsat sat unsat sat unsat
