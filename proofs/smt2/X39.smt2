; rodimpact prove --export: claim X39 (beyond the paper)
; The law pymunk, Box2D 2.3 and Bullet converge to, lcp-newton (Newton's target on the final normal velocity and Coulomb's law on the final slip, in one phase), has one answer on the tilted rod landing on a rough floor (e = 1, mu = 1/3): the end sticks, and the rod gains exactly 1/10 of its 1 J, the work of the friction impulse; Newton's law followed through the slip reversal gains 197125/9435168 J
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const lam Real)
(declare-const tau Real)
(declare-const un Real)
(declare-const ut Real)
(declare-const vx Real)
(declare-const vy Real)
(declare-const w Real)
; hypothesis of the claim
(assert (= vx (- 1 tau)))
; hypothesis of the claim
(assert (= vy (+ (- 1) lam)))
; hypothesis of the claim
(assert (= w (* 3 (- (/ (* (- 3) lam) 5) (/ (* 4 tau) 5)))))
; hypothesis of the claim
(assert (= un (- vy (/ (* 3 w) 5))))
; hypothesis of the claim
(assert (= ut (- (+ vx (/ (* 4 w) 5)))))
; hypothesis of the claim
(assert (and (>= lam 0) (>= un 1) (= (* lam (- un 1)) 0)))
; hypothesis of the claim
(assert (and (<= (/ (- lam) 3) tau) (<= tau (/ lam 3)) (=> (> ut 0) (= tau (/ (- lam) 3))) (=> (< ut 0) (= tau (/ lam 3)))))
; check 1: the complementarity problem has a solution
; a witness
(push 1)
(assert (>= lam 0))
(check-sat-using qfnra)
(get-model)
(pop 1)
; check 2: its solution is unique: the end sticks
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (and (= lam (/ 11 10)) (= tau (/ (- 1) 5)) (= ut 0))))
(check-sat-using qfnra)
(pop 1)
; check 3: every solution gains exactly 1/10 J (the unique impulse as a lemma)
; the hypotheses are consistent
(push 1)
; proved above (check 2), a lemma
(assert (and (= lam (/ 11 10)) (= tau (/ (- 1) 5)) (= ut 0)))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
; proved above (check 2), a lemma
(assert (and (= lam (/ 11 10)) (= tau (/ (- 1) 5)) (= ut 0)))
(assert (not (= (+ (/ (+ (* vx vx) (* vy vy)) 2) (/ (* w w) 6)) (/ 11 10))))
(check-sat-using qfnra)
(pop 1)
; expect: sat sat unsat sat unsat
