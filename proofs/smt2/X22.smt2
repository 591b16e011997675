; rodimpact prove --export: claim X22 (beyond the paper)
; Rod not symmetric: every formula holds with a replaced by a - c (c the CM offset; I taken about the CM)
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const I Real)
(declare-const M Real)
(declare-const V Real)
(declare-const a Real)
(declare-const c Real)
(declare-const e Real)
(declare-const l Real)
(declare-const m Real)
(declare-const omega Real)
(declare-const v Real)
(declare-const v0 Real)
; hypothesis of the claim
(assert (> m 0))
; hypothesis of the claim
(assert (> M 0))
; hypothesis of the claim
(assert (> I 0))
; hypothesis of the claim
(assert (> v0 0))
; hypothesis of the claim
(assert (<= 0 e))
; hypothesis of the claim
(assert (<= e 1))
; hypothesis of the claim
(assert (> l 0))
; hypothesis of the claim
(assert (= (+ (* m v) (* M V)) (* m v0)))
; hypothesis of the claim
(assert (= (+ (+ (* (* m a) v) (* (* M c) V)) (* I omega)) (* (* m a) v0)))
; hypothesis of the claim
(assert (= (- (+ V (* omega (- a c))) v) (* e v0)))
; check 1: the solution is the symmetric rod's with a -> a - c
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (and (= v (- v0 (/ (/ (* (+ 1 e) v0) (+ (+ (/ 1 m) (/ 1 M)) (/ (* (- a c) (- a c)) I))) m))) (= V (/ (/ (* (+ 1 e) v0) (+ (+ (/ 1 m) (/ 1 M)) (/ (* (- a c) (- a c)) I))) M)) (= omega (/ (/ (* (* (+ 1 e) v0) (- a c)) I) (+ (+ (/ 1 m) (/ 1 M)) (/ (* (- a c) (- a c)) I)))))))
(check-sat-using qfnra)
(pop 1)
; check 2: reading: every formula, e.g. the far end's velocity V (1 - a l/r_G^2) of X14, with a -> a - c; refuted at m = M = I = v0 = e = l = 1, a = 1, c = 1/2 (the far end is at -(l + c) from the CM)
; the negation of the reading is satisfiable
(push 1)
(assert (= m 1))
(assert (= M 1))
(assert (= I 1))
(assert (= v0 1))
(assert (= e 1))
(assert (= l 1))
(assert (= a 1))
(assert (= c (/ 1 2)))
(assert (not (= (- V (* omega (+ l c))) (* V (- 1 (/ (* (* (- a c) l) M) I))))))
(check-sat-using qfnra)
(get-model)
(pop 1)
; expect: sat unsat sat
