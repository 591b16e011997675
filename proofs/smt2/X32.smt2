; rodimpact prove --export: claim X32 (beyond the paper)
; One planar contact whose contact matrix W is diagonal (W_nt = 0: every scene of the paper's family): Newton's, Poisson's and Stronge's energetic laws end the impact at the same normal impulse lam_f = (1 + e) v_n/W_nn, and no law gains energy; the normal impulse's work is -(1 - e^2) v_n^2/(2 W_nn)
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const e Real)
(declare-const lf Real)
(declare-const lg Real)
(declare-const ln Real)
(declare-const vn Real)
(declare-const w Real)
; hypothesis of the claim
(assert (> w 0))
; hypothesis of the claim
(assert (> vn 0))
; hypothesis of the claim
(assert (<= 0 e))
; hypothesis of the claim
(assert (<= e 1))
; check 1: Newton's end (u_n = e vn) is Poisson's (1 + e) lam_c, lam_c = vn/w
; the hypotheses are consistent
(push 1)
(assert (= (- (* w ln) vn) (* e vn)))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= (- (* w ln) vn) (* e vn)))
(assert (not (= ln (/ (* (+ 1 e) vn) w))))
(check-sat-using qfnra)
(pop 1)
; check 2: the energetic end (restitution work e^2 times the compression work vn^2/(2 w), after lam_c) is Poisson's too
; the hypotheses are consistent
(push 1)
(assert (= (/ (* w (* (- lg (/ vn w)) (- lg (/ vn w)))) 2) (/ (* (* e e) (* vn vn)) (* 2 w))))
(assert (>= lg (/ vn w)))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= (/ (* w (* (- lg (/ vn w)) (- lg (/ vn w)))) 2) (/ (* (* e e) (* vn vn)) (* 2 w))))
(assert (>= lg (/ vn w)))
(assert (not (= lg (/ (* (+ 1 e) vn) w))))
(check-sat-using qfnra)
(pop 1)
; check 3: the normal work at lam_f = (1 + e) vn/w is -(1 - e^2) vn^2/(2 w), never positive
; the hypotheses are consistent
(push 1)
(assert (= lf (/ (* (+ 1 e) vn) w)))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= lf (/ (* (+ 1 e) vn) w)))
(assert (not (and (= (+ (* (- vn) lf) (/ (* w (* lf lf)) 2)) (/ (* (- (- 1 (* e e))) (* vn vn)) (* 2 w))) (<= (+ (* (- vn) lf) (/ (* w (* lf lf)) 2)) 0))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat sat unsat
