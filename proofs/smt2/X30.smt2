; rodimpact prove --export: claim X30 (beyond the paper)
; The frictional energy loss: the kinetic energy lost is (1 - e^2) u_n^2/(2 k_n) to restitution plus u_t^2/(2 k_t) when the contact sticks or mu_f J (|u_t| - mu_f J k_t/2) when it slides; the sliding loss is positive
; Not stated here: the sticking loss u_t^2/(2 k_t) is certified by rodimpact only: one scene per exported statement
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
; Coulomb friction coefficient
(assert (>= mu_f 0))
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
; sliding forward: Coulomb's law, Jt = mu_f J
(assert (= Jt (* mu_f J)))
; check 1: the normal impulse: J k_n = (1 + e) v0, k_n = 1/m + 1/M + a^2/I
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (= (* J (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I))) (* (+ 1 e) v0))))
(check-sat-using qfnra)
(pop 1)
; check 2: sliding: energy lost = (1 - e^2) v0^2/(2 k_n) + mu_f J (u_t - mu_f J k_t/2), u_t = v0t + w rd, k_t = 3/m + 1/M
; the hypotheses are consistent
(push 1)
(assert (> rd 0))
; proved above (check 1), a lemma
(assert (= (* J (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I))) (* (+ 1 e) v0)))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (> rd 0))
; proved above (check 1), a lemma
(assert (= (* J (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I))) (* (+ 1 e) v0)))
(assert (not (= (- (+ (/ (* m (+ (* v0 v0) (* v0t v0t))) 2) (/ (* (* m (* rd rd)) (* w w)) 4)) (+ (+ (+ (/ (* m (+ (* v v) (* vt vt))) 2) (/ (* M (+ (* V V) (* Vt Vt))) 2)) (/ (* I (* omega omega)) 2)) (/ (* (* m (* rd rd)) (* spin spin)) 4))) (+ (/ (* (- 1 (* e e)) (* v0 v0)) (* 2 (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I)))) (* (* mu_f J) (- (+ v0t (* w rd)) (/ (* (* mu_f J) (+ (/ 3 m) (/ 1 M))) 2)))))))
(check-sat-using qfnra)
(pop 1)
; check 3: the normal motion's part of the loss: (1 - e^2) v0^2/(2 k_n)
; the hypotheses are consistent
(push 1)
; proved above (check 1), a lemma
(assert (= (* J (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I))) (* (+ 1 e) v0)))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
; proved above (check 1), a lemma
(assert (= (* J (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I))) (* (+ 1 e) v0)))
(assert (not (= (- (/ (* m (* v0 v0)) 2) (+ (+ (/ (* m (* v v)) 2) (/ (* M (* V V)) 2)) (/ (* I (* omega omega)) 2))) (/ (* (- 1 (* e e)) (* v0 v0)) (* 2 (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I)))))))
(check-sat-using qfnra)
(pop 1)
; check 4: the translation along the rod's part: Jt (v0t - Jt (1/m + 1/M)/2)
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (= (- (/ (* m (* v0t v0t)) 2) (+ (/ (* m (* vt vt)) 2) (/ (* M (* Vt Vt)) 2))) (* Jt (- v0t (/ (* Jt (+ (/ 1 m) (/ 1 M))) 2))))))
(check-sat-using qfnra)
(pop 1)
; check 5: point (rd = 0), sliding: energy lost = (1 - e^2) v0^2/(2 k_n) + mu_f J (v0t - mu_f J k_t/2), k_t = 1/m + 1/M
; the hypotheses are consistent
(push 1)
(assert (= rd 0))
; proved above (check 3), a lemma
(assert (= (- (/ (* m (* v0 v0)) 2) (+ (+ (/ (* m (* v v)) 2) (/ (* M (* V V)) 2)) (/ (* I (* omega omega)) 2))) (/ (* (- 1 (* e e)) (* v0 v0)) (* 2 (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I))))))
; proved above (check 4), a lemma
(assert (= (- (/ (* m (* v0t v0t)) 2) (+ (/ (* m (* vt vt)) 2) (/ (* M (* Vt Vt)) 2))) (* Jt (- v0t (/ (* Jt (+ (/ 1 m) (/ 1 M))) 2)))))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= rd 0))
; proved above (check 3), a lemma
(assert (= (- (/ (* m (* v0 v0)) 2) (+ (+ (/ (* m (* v v)) 2) (/ (* M (* V V)) 2)) (/ (* I (* omega omega)) 2))) (/ (* (- 1 (* e e)) (* v0 v0)) (* 2 (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I))))))
; proved above (check 4), a lemma
(assert (= (- (/ (* m (* v0t v0t)) 2) (+ (/ (* m (* vt vt)) 2) (/ (* M (* Vt Vt)) 2))) (* Jt (- v0t (/ (* Jt (+ (/ 1 m) (/ 1 M))) 2)))))
(assert (not (= (- (/ (* m (+ (* v0 v0) (* v0t v0t))) 2) (+ (+ (/ (* m (+ (* v v) (* vt vt))) 2) (/ (* M (+ (* V V) (* Vt Vt))) 2)) (/ (* I (* omega omega)) 2))) (+ (/ (* (- 1 (* e e)) (* v0 v0)) (* 2 (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I)))) (* (* mu_f J) (- v0t (/ (* (* mu_f J) (+ (/ 1 m) (/ 1 M))) 2)))))))
(check-sat-using qfnra)
(pop 1)
; check 6: point, still sliding at the end (v0t > mu_f J k_t): the frictional loss is positive
; the hypotheses are consistent
(push 1)
(assert (= rd 0))
(assert (> mu_f 0))
(assert (> (- v0t (* (* mu_f J) (+ (/ 1 m) (/ 1 M)))) 0))
; proved above (check 1), a lemma
(assert (= (* J (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I))) (* (+ 1 e) v0)))
; proved above (check 5), a lemma
(assert (= (- (/ (* m (+ (* v0 v0) (* v0t v0t))) 2) (+ (+ (/ (* m (+ (* v v) (* vt vt))) 2) (/ (* M (+ (* V V) (* Vt Vt))) 2)) (/ (* I (* omega omega)) 2))) (+ (/ (* (- 1 (* e e)) (* v0 v0)) (* 2 (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I)))) (* (* mu_f J) (- v0t (/ (* (* mu_f J) (+ (/ 1 m) (/ 1 M))) 2))))))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= rd 0))
(assert (> mu_f 0))
(assert (> (- v0t (* (* mu_f J) (+ (/ 1 m) (/ 1 M)))) 0))
; proved above (check 1), a lemma
(assert (= (* J (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I))) (* (+ 1 e) v0)))
; proved above (check 5), a lemma
(assert (= (- (/ (* m (+ (* v0 v0) (* v0t v0t))) 2) (+ (+ (/ (* m (+ (* v v) (* vt vt))) 2) (/ (* M (+ (* V V) (* Vt Vt))) 2)) (/ (* I (* omega omega)) 2))) (+ (/ (* (- 1 (* e e)) (* v0 v0)) (* 2 (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I)))) (* (* mu_f J) (- v0t (/ (* (* mu_f J) (+ (/ 1 m) (/ 1 M))) 2))))))
(assert (not (> (- (- (/ (* m (+ (* v0 v0) (* v0t v0t))) 2) (+ (+ (/ (* m (+ (* v v) (* vt vt))) 2) (/ (* M (+ (* V V) (* Vt Vt))) 2)) (/ (* I (* omega omega)) 2))) (/ (* (- 1 (* e e)) (* v0 v0)) (* 2 (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I))))) 0)))
(check-sat-using qfnra)
(pop 1)
; check 7: disc, still sliding at the end (u_t > mu_f J k_t): the frictional loss is positive
; the hypotheses are consistent
(push 1)
(assert (> rd 0))
(assert (> mu_f 0))
(assert (> (- (+ v0t (* w rd)) (* (* mu_f J) (+ (/ 3 m) (/ 1 M)))) 0))
; proved above (check 1), a lemma
(assert (= (* J (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I))) (* (+ 1 e) v0)))
; proved above (check 2), a lemma
(assert (= (- (+ (/ (* m (+ (* v0 v0) (* v0t v0t))) 2) (/ (* (* m (* rd rd)) (* w w)) 4)) (+ (+ (+ (/ (* m (+ (* v v) (* vt vt))) 2) (/ (* M (+ (* V V) (* Vt Vt))) 2)) (/ (* I (* omega omega)) 2)) (/ (* (* m (* rd rd)) (* spin spin)) 4))) (+ (/ (* (- 1 (* e e)) (* v0 v0)) (* 2 (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I)))) (* (* mu_f J) (- (+ v0t (* w rd)) (/ (* (* mu_f J) (+ (/ 3 m) (/ 1 M))) 2))))))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (> rd 0))
(assert (> mu_f 0))
(assert (> (- (+ v0t (* w rd)) (* (* mu_f J) (+ (/ 3 m) (/ 1 M)))) 0))
; proved above (check 1), a lemma
(assert (= (* J (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I))) (* (+ 1 e) v0)))
; proved above (check 2), a lemma
(assert (= (- (+ (/ (* m (+ (* v0 v0) (* v0t v0t))) 2) (/ (* (* m (* rd rd)) (* w w)) 4)) (+ (+ (+ (/ (* m (+ (* v v) (* vt vt))) 2) (/ (* M (+ (* V V) (* Vt Vt))) 2)) (/ (* I (* omega omega)) 2)) (/ (* (* m (* rd rd)) (* spin spin)) 4))) (+ (/ (* (- 1 (* e e)) (* v0 v0)) (* 2 (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I)))) (* (* mu_f J) (- (+ v0t (* w rd)) (/ (* (* mu_f J) (+ (/ 3 m) (/ 1 M))) 2))))))
(assert (not (> (- (- (+ (/ (* m (+ (* v0 v0) (* v0t v0t))) 2) (/ (* (* m (* rd rd)) (* w w)) 4)) (+ (+ (+ (/ (* m (+ (* v v) (* vt vt))) 2) (/ (* M (+ (* V V) (* Vt Vt))) 2)) (/ (* I (* omega omega)) 2)) (/ (* (* m (* rd rd)) (* spin spin)) 4))) (/ (* (- 1 (* e e)) (* v0 v0)) (* 2 (+ (+ (/ 1 m) (/ 1 M)) (/ (* a a) I))))) 0)))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat sat unsat sat unsat sat unsat sat unsat sat unsat
