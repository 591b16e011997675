; rodimpact prove --export: claim X35 (beyond the paper)
; Newton's cradle of three equal balls (e = 1), the first striking the two at rest: simultaneous Newton and Poisson both conserve momentum and energy yet send the first ball back at -v/3 and the others on at 2v/3; sequential impacts, in either order, conserve both too and leave only the last ball moving, at v
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const l1 Real)
(declare-const l2 Real)
(declare-const m Real)
(declare-const s1 Real)
(declare-const s2 Real)
(declare-const v Real)
; hypothesis of the claim
(assert (> m 0))
; hypothesis of the claim
(assert (> v 0))
; check 1: simultaneous Newton, both contacts pushing (l1, l2 > 0) and leaving at v and 0: the velocities are (-v/3, 2v/3, 2v/3), momentum and energy kept
; the hypotheses are consistent
(push 1)
(assert (= (/ (- (* 2 l1) l2) m) (* 2 v)))
(assert (= (/ (+ (- l1) (* 2 l2)) m) 0))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= (/ (- (* 2 l1) l2) m) (* 2 v)))
(assert (= (/ (+ (- l1) (* 2 l2)) m) 0))
(assert (not (and (> l1 0) (> l2 0) (= (- v (/ l1 m)) (/ (- v) 3)) (= (/ (- l1 l2) m) (/ (* 2 v) 3)) (= (/ l2 m) (/ (* 2 v) 3)) (= (+ (+ (* m (- v (/ l1 m))) (/ (* m (- l1 l2)) m)) (/ (* m l2) m)) (* m v)) (= (/ (* m (+ (+ (* (- v (/ l1 m)) (- v (/ l1 m))) (* (/ (- l1 l2) m) (/ (- l1 l2) m))) (* (/ l2 m) (/ l2 m)))) 2) (/ (* m (* v v)) 2)))))
(check-sat-using qfnra)
(pop 1)
; check 2: sequential, contact 1 then 2: each fires the single-contact impulse (1 + e) |u|/W_ii = m |u|, leaving (0, 0, v)
; the hypotheses are consistent
(push 1)
(assert (= s1 (/ (* 2 v) (/ 2 m))))
(assert (= s2 (/ (* 2 (/ s1 m)) (/ 2 m))))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (= s1 (/ (* 2 v) (/ 2 m))))
(assert (= s2 (/ (* 2 (/ s1 m)) (/ 2 m))))
(assert (not (and (= (- v (/ s1 m)) 0) (= (- (/ s1 m) (/ s2 m)) 0) (= (/ s2 m) v))))
(check-sat-using qfnra)
(pop 1)
; expect: sat unsat sat unsat
