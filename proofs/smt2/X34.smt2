; rodimpact prove --export: claim X34 (beyond the paper)
; Newton's law with Coulomb friction never gains energy in one planar contact
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const a Real)
(declare-const b Real)
(declare-const c Real)
(declare-const dK Real)
(declare-const e Real)
(declare-const lam_s Real)
(declare-const lf Real)
(declare-const mu Real)
(declare-const tf Real)
(declare-const ut Real)
(declare-const vn Real)
; check 1: a tilted rod (length 2, mass 1, axis (3, 4)/5) landing on its end at 1 while sliding at 1 on a floor with mu = 1, e = 1: the slip stops before the impact ends, sticks, and the kinetic energy rises by 1/10
; a witness
(push 1)
(assert (= a (/ 52 25)))
(assert (= b (/ 36 25)))
(assert (= c (/ 73 25)))
(assert (= vn 1))
(assert (= ut (- 1)))
(assert (= e 1))
(assert (= mu 1))
(assert (= lam_s (/ (- ut) (+ b (* mu c)))))
(assert (= lf (/ (+ (* (* c (+ 1 e)) vn) (* b ut)) (- (* a c) (* b b)))))
(assert (= tf (/ (- (* (* (- b) (+ 1 e)) vn) (* a ut)) (- (* a c) (* b b)))))
(assert (= dK (/ (+ (* (* lf (- e 1)) vn) (* tf ut)) 2)))
(assert (and (< lam_s lf) (>= (* mu c) b) (= dK (/ 1 10)) (> dK 0)))
(check-sat-using qfnra)
(get-model)
(pop 1)
; expect: sat
