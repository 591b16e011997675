; rodimpact prove --export: claim X37 (beyond the paper)
; A frictionless w x h box (h^2 < 2 w^2) falling flat at v > 0 onto both bottom corners while spinning at omega > 0, 0 <= e <= 1: under simultaneous Newton and Poisson the rising corner takes no impulse exactly when omega >= omega_s = (2v/w) ((6 + 2e) w^2 - e h^2)/((2 - 2e) w^2 + (2 + e) h^2), a threshold above the kinematic 2v/w at which that corner starts to rise; for the 2 x 1 box falling at 1 with e = 1/2, omega_s = 55/13
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const a Real)
(declare-const b Real)
(declare-const c Real)
(declare-const cs Real)
(declare-const e Real)
(declare-const h2 Real)
(declare-const l1 Real)
(declare-const m Real)
(declare-const v Real)
(declare-const w2 Real)
; hypothesis of the claim
(assert (> m 0))
; hypothesis of the claim
(assert (> v 0))
; hypothesis of the claim
(assert (> c 0))
; hypothesis of the claim
(assert (> w2 0))
; hypothesis of the claim
(assert (> h2 0))
; hypothesis of the claim
(assert (< h2 (* 2 w2)))
; hypothesis of the claim
(assert (<= 0 e))
; hypothesis of the claim
(assert (<= e 1))
; hypothesis of the claim
(assert (= a (/ (+ (* 4 w2) h2) (* m (+ w2 h2)))))
; hypothesis of the claim
(assert (= b (/ (- h2 (* 2 w2)) (* m (+ w2 h2)))))
; hypothesis of the claim
(assert (= l1 (/ (* (+ 1 e) (+ v c)) a)))
; hypothesis of the claim
(assert (= cs (/ (* v (- (* (+ 6 (* 2 e)) w2) (* e h2))) (+ (* (- 2 (* 2 e)) w2) (* (+ 2 e) h2)))))
; check 1: the rising corner moving up (c >= v): after the leading corner's impulse it leaves (Newton's condition) iff c >= cs
; the hypotheses are consistent
(push 1)
(assert (>= c v))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (>= c v))
(assert (not (and (=> (>= (+ (- c v) (* b l1)) 0) (>= c cs)) (=> (>= c cs) (>= (+ (- c v) (* b l1)) 0)))))
(check-sat-using qfnra)
(pop 1)
; check 2: the rising corner still approaching (c < v): Newton's condition fails, so that corner pushes
; the hypotheses are consistent
(push 1)
(assert (< c v))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (< c v))
(assert (not (< (+ (* (+ 1 e) (- c v)) (* b l1)) 0)))
(check-sat-using qfnra)
(pop 1)
; check 3: the threshold is above the kinematic one (c = v)
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (> cs v)))
(check-sat-using qfnra)
(pop 1)
; check 4: Poisson's compression condition (e = 0) is weaker than Newton's
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (<= (/ (* (* v 6) w2) (+ (* 2 w2) (* 2 h2))) cs)))
(check-sat-using qfnra)
(pop 1)
; check 5: the 2 x 1 box at v = 1, e = 1/2: omega_s = cs = 55/13
; the hypotheses are consistent
(push 1)
(assert (= w2 4))
(assert (= h2 1))
(assert (= v 1))
(assert (= e (/ 1 2)))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= w2 4))
(assert (= h2 1))
(assert (= v 1))
(assert (= e (/ 1 2)))
(assert (not (= cs (/ 55 13))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat sat unsat sat unsat sat unsat
