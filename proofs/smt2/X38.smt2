; rodimpact prove --export: claim X38 (beyond the paper)
; Simultaneous Poisson impacts with Coulomb friction at two contacts can create kinetic energy: a uniform 1 x 3 box (mass 1) moving at (-1/2, -1/2) onto a plastic peg below it (e = 0) and an elastic peg beside it (e = 1), mu = 1/2 at both, has one Poisson answer, and it raises the energy from 1/4 to 7261587/25088000 (+15.8 %)
; The hypotheses are the physics (balance equations and contact law in fresh unknowns,
; the domain), not rodimpact's solution. Each check asserts the negation of its
; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the
; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,
; or a witness, answers `sat` with a model. Run: z3 FILE
(set-logic QF_NRA)
(declare-const n1 Real)
(declare-const n2 Real)
(declare-const p1 Real)
(declare-const p2 Real)
(declare-const q1 Real)
(declare-const q2 Real)
(declare-const t1 Real)
(declare-const t2 Real)
(declare-const un1c Real)
(declare-const un1f Real)
(declare-const un2c Real)
(declare-const un2f Real)
(declare-const ut1c Real)
(declare-const ut1f Real)
(declare-const ut2c Real)
(declare-const ut2f Real)
(declare-const vxc Real)
(declare-const vxf Real)
(declare-const vyc Real)
(declare-const vyf Real)
(declare-const wc Real)
(declare-const wf Real)
(declare-const x1 Real)
(declare-const x2 Real)
; hypothesis of the claim
(assert (= vxc (+ (- (/ (- 1) 2) t1) n2)))
; hypothesis of the claim
(assert (= vyc (+ (+ (/ (- 1) 2) n1) t2)))
; hypothesis of the claim
(assert (= wc (/ (* 6 (- (+ (- (/ (* (- 3) n1) 8) (/ (* 3 t1) 2)) (/ (* 9 n2) 8)) (/ t2 2))) 5)))
; hypothesis of the claim
(assert (= un1c (- vyc (/ (* 3 wc) 8))))
; hypothesis of the claim
(assert (= ut1c (- (- vxc) (/ (* 3 wc) 2))))
; hypothesis of the claim
(assert (= un2c (+ vxc (/ (* 9 wc) 8))))
; hypothesis of the claim
(assert (= ut2c (- vyc (/ wc 2))))
; hypothesis of the claim
(assert (and (>= n1 0) (>= un1c 0) (= (* n1 un1c) 0)))
; hypothesis of the claim
(assert (and (>= n2 0) (>= un2c 0) (= (* n2 un2c) 0)))
; hypothesis of the claim
(assert (and (<= (/ (- n1) 2) t1) (<= t1 (/ n1 2)) (=> (> ut1c 0) (= t1 (/ (- n1) 2))) (=> (< ut1c 0) (= t1 (/ n1 2)))))
; hypothesis of the claim
(assert (and (<= (/ (- n2) 2) t2) (<= t2 (/ n2 2)) (=> (> ut2c 0) (= t2 (/ (- n2) 2))) (=> (< ut2c 0) (= t2 (/ n2 2)))))
; hypothesis of the claim
(assert (= p1 x1))
; hypothesis of the claim
(assert (= p2 (+ n2 x2)))
; hypothesis of the claim
(assert (= vxf (+ (- vxc q1) p2)))
; hypothesis of the claim
(assert (= vyf (+ (+ vyc p1) q2)))
; hypothesis of the claim
(assert (= wf (+ wc (/ (* 6 (- (+ (- (/ (* (- 3) p1) 8) (/ (* 3 q1) 2)) (/ (* 9 p2) 8)) (/ q2 2))) 5))))
; hypothesis of the claim
(assert (= un1f (- vyf (/ (* 3 wf) 8))))
; hypothesis of the claim
(assert (= ut1f (- (- vxf) (/ (* 3 wf) 2))))
; hypothesis of the claim
(assert (= un2f (+ vxf (/ (* 9 wf) 8))))
; hypothesis of the claim
(assert (= ut2f (- vyf (/ wf 2))))
; hypothesis of the claim
(assert (and (>= x1 0) (>= un1f 0) (= (* x1 un1f) 0)))
; hypothesis of the claim
(assert (and (>= x2 0) (>= un2f 0) (= (* x2 un2f) 0)))
; hypothesis of the claim
(assert (and (<= (/ (- p1) 2) q1) (<= q1 (/ p1 2)) (=> (> ut1f 0) (= q1 (/ (- p1) 2))) (=> (< ut1f 0) (= q1 (/ p1 2)))))
; hypothesis of the claim
(assert (and (<= (/ (- p2) 2) q2) (<= q2 (/ p2 2)) (=> (> ut2f 0) (= q2 (/ (- p2) 2))) (=> (< ut2f 0) (= q2 (/ p2 2)))))
; check 1: the two-phase problem has a solution
; a witness
(push 1)
(assert (and (>= n1 0) (>= n2 0)))
(check-sat-using qfnra)
(get-model)
(pop 1)
; check 2: its solution is unique: the impulses found
; the hypotheses are consistent
(push 1)
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
(assert (not (and (= n1 (/ 83 280)) (= n2 (/ 141 280)) (= t1 (/ 83 560)) (= t2 (/ 141 560)) (= x1 0) (= x2 0) (= q1 0) (= q2 (/ 141 560)))))
(check-sat-using qfnra)
(pop 1)
; check 3: every solution raises the kinetic energy above 1/4 (the unique impulses as a lemma)
; the hypotheses are consistent
(push 1)
; proved above (check 2), a lemma
(assert (and (= n1 (/ 83 280)) (= n2 (/ 141 280)) (= t1 (/ 83 560)) (= t2 (/ 141 560)) (= x1 0) (= x2 0) (= q1 0) (= q2 (/ 141 560))))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
; proved above (check 2), a lemma
(assert (and (= n1 (/ 83 280)) (= n2 (/ 141 280)) (= t1 (/ 83 560)) (= t2 (/ 141 560)) (= x1 0) (= x2 0) (= q1 0) (= q2 (/ 141 560))))
(assert (not (> (+ (/ (+ (* vxf vxf) (* vyf vyf)) 2) (/ (* 5 (* wf wf)) 12)) (/ 1 4))))
(check-sat-using qfnra)
(pop 1)
; check 4: to exactly 7261587/25088000
; the hypotheses are consistent
(push 1)
; proved above (check 2), a lemma
(assert (and (= n1 (/ 83 280)) (= n2 (/ 141 280)) (= t1 (/ 83 560)) (= t2 (/ 141 560)) (= x1 0) (= x2 0) (= q1 0) (= q2 (/ 141 560))))
(check-sat-using qfnra)
(get-model)
(pop 1)
; the negation of the conclusion is not
(push 1)
; proved above (check 2), a lemma
(assert (and (= n1 (/ 83 280)) (= n2 (/ 141 280)) (= t1 (/ 83 560)) (= t2 (/ 141 560)) (= x1 0) (= x2 0) (= q1 0) (= q2 (/ 141 560))))
(assert (not (= (+ (/ (+ (* vxf vxf) (* vyf vyf)) 2) (/ (* 5 (* wf wf)) 12)) (/ 7261587 25088000))))
(check-sat-using qfnra)
(pop 1)
; expect: sat sat unsat sat unsat sat unsat
