; rodimpact prove --export: claim X36 (beyond the paper)
; Projected Gauss-Seidel on Newton's cradle of three equal balls (e = 1): one sweep from zero impulses loses exactly half the energy, and each further sweep shrinks the impulses' error from the simultaneous Newton answer by exactly 1/4
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const a Real)
(declare-const b Real)
(declare-const d Real)
(declare-const m Real)
(declare-const v Real)
; hypothesis of the claim
(assert (> m 0))
; hypothesis of the claim
(assert (> v 0))
; check 1: from lam = (4mv/3, 2mv/3 + d): one sweep gives (4mv/3 + d/2, 2mv/3 + d/4)
; the hypotheses are consistent
(push 1)
(assert (= a (/ (+ (* (* 2 m) v) (+ (/ (* (* 2 m) v) 3) d)) 2)))
(assert (= b (/ a 2)))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= a (/ (+ (* (* 2 m) v) (+ (/ (* (* 2 m) v) 3) d)) 2)))
(assert (= b (/ a 2)))
(assert (not (and (= a (+ (/ (* (* 4 m) v) 3) (/ d 2))) (= b (+ (/ (* (* 2 m) v) 3) (/ d 4))))))
(check-sat-using qfnra)
(pop 1)
; check 2: one sweep from zero: lam = (m v, m v/2), the balls at (0, v/2, v/2), energy m v^2/4
; the hypotheses are consistent
(push 1)
(assert (= a (* m v)))
(assert (= b (/ a 2)))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= a (* m v)))
(assert (= b (/ a 2)))
(assert (not (= (/ (* m (+ (+ (* (- v (/ a m)) (- v (/ a m))) (* (/ (- a b) m) (/ (- a b) m))) (* (/ b m) (/ b m)))) 2) (/ (* m (* v v)) 4))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat
