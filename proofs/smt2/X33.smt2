; rodimpact prove --export: claim X33 (beyond the paper)
; Stronge's energetic law never gains energy in one planar contact with Coulomb friction, whatever the slip does; neither does Poisson's law while the slip keeps its mode through the impact
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const Wc Real)
(declare-const Wf Real)
(declare-const Wr Real)
(declare-const e Real)
(declare-const k Real)
(declare-const lc Real)
(declare-const vn Real)
; hypothesis of the claim
(assert (> vn 0))
; hypothesis of the claim
(assert (<= 0 e))
; hypothesis of the claim
(assert (<= e 1))
; hypothesis of the claim
(assert (<= Wc 0))
; hypothesis of the claim
(assert (<= Wf 0))
; check 1: energetic: Wr = -e^2 Wc, so the energy change Wc + Wr + Wf <= 0
; the hypotheses are consistent
(push 1)
(assert (= Wr (* (- (* e e)) Wc)))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= Wr (* (- (* e e)) Wc)))
(assert (not (<= (+ (+ Wc Wr) Wf) 0)))
(check-sat-using qfnra)
(pop 1)
; check 2: Poisson with one slope k through the impact: Wc = -vn^2/(2k), Wr = k (e lam_c)^2/2 = -e^2 Wc
; the hypotheses are consistent
(push 1)
(assert (> k 0))
(assert (= lc (/ vn k)))
(assert (= Wc (+ (* (- vn) lc) (/ (* k (* lc lc)) 2))))
(assert (= Wr (/ (* k (* (* e lc) (* e lc))) 2)))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (> k 0))
(assert (= lc (/ vn k)))
(assert (= Wc (+ (* (- vn) lc) (/ (* k (* lc lc)) 2))))
(assert (= Wr (/ (* k (* (* e lc) (* e lc))) 2)))
(assert (not (= Wr (* (- (* e e)) Wc))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat
