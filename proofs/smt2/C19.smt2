; rodimpact prove --export: claim C19 (§optimum ¶1)
; For b, c > 0, f(x) = x/(b^2 + c^2 x^2) has its unique maximum on x > 0 at x = b/c, with value 1/(2bc)
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const b Real)
(declare-const c Real)
(declare-const x Real)
; hypothesis of the claim
(assert (> b 0))
; hypothesis of the claim
(assert (> c 0))
; check 1: f(b/c) = 1/(2bc)
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (= (/ (/ b c) (+ (* b b) (* (* c c) (* (/ b c) (/ b c))))) (/ 1 (* (* 2 b) c)))))
(check-sat-using qfnra)
(pop 1)
; check 2: b/c is the unique maximiser of f on x >= 0
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (=> (and (>= x 0) (not (= x (/ b c)))) (< (/ x (+ (* b b) (* (* c c) (* x x)))) (/ 1 (* (* 2 b) c))))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat
