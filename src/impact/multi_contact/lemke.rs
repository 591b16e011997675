//! Lemke's complementary pivoting for the linear complementarity problem
//! `z >= 0, w = q + W z >= 0, z . w = 0`, exactly: a dense tableau over any [`Field`], the
//! covering vector all ones, and the lexicographic minimum-ratio rule, so degenerate problems
//! (contacts already touching, `q_i = 0`) never cycle and no tolerance is needed.
//!
//! For a positive semidefinite W (every Delassus matrix is one) Lemke's method ends either with
//! a solution or on a ray, and a ray means the problem has no solution (Cottle, Pang and Stone,
//! *The Linear Complementarity Problem*, theorem 4.4.13, W copositive-plus). The velocities
//! `q + W z` are the same for every solution of such a problem (the problem is the optimality
//! condition of a convex quadratic program), so the one solution Lemke finds gives every model's
//! answer; where W is singular the impulses themselves may be split otherwise.

use crate::field::Field;
use crate::impact::work::{Meter, Stopped, Work};
use std::cmp::Ordering;

/// The tableau `B^-1 [I | -W | -1 | q]` of the basis B, one row per basic variable.
struct Tableau<F> {
    /// Row i: the coefficients of `w_1..w_n, z_1..z_n, z0`.
    rows: Vec<Vec<F>>,
    /// Row i: the value of its basic variable.
    values: Vec<F>,
    /// Row i: the index of its basic variable (`0..n` the w's, `n..2n` the z's, `2n` z0).
    basic: Vec<usize>,
}

impl<F: Field> Tableau<F> {
    fn new(w: &[Vec<F>], q: &[F]) -> Tableau<F> {
        let n = q.len();
        let rows = (0..n)
            .map(|i| {
                let mut row = vec![F::zero(); 2 * n + 1];
                row[i] = F::one();
                for (j, wij) in w[i].iter().enumerate() {
                    row[n + j] = -wij.clone();
                }
                row[2 * n] = -F::one();
                row
            })
            .collect();
        Tableau {
            rows,
            values: q.to_vec(),
            basic: (0..n).collect(),
        }
    }

    /// Makes `column` basic in row `r`; returns the variable that leaves.
    fn pivot(&mut self, r: usize, column: usize) -> usize {
        let p = self.rows[r][column].clone();
        for x in self.rows[r].iter_mut() {
            *x = x.clone() / &p;
        }
        self.values[r] = self.values[r].clone() / &p;
        let (pivot_row, pivot_value) = (self.rows[r].clone(), self.values[r].clone());
        for i in (0..self.rows.len()).filter(|&i| i != r) {
            let factor = self.rows[i][column].clone();
            if factor.is_zero() {
                continue;
            }
            for (x, y) in self.rows[i].iter_mut().zip(&pivot_row) {
                *x = x.clone() - &(factor.clone() * y);
            }
            self.values[i] = self.values[i].clone() - &(factor * &pivot_value);
        }
        std::mem::replace(&mut self.basic[r], column)
    }

    /// Row i's lexicographic key `(value, B^-1 row)` divided by `by_i`, compared with row k's
    /// divided by `by_k` (both positive): the perturbed ratio test.
    fn lex_cmp(&self, (i, by_i): (usize, &F), (k, by_k): (usize, &F)) -> Ordering {
        let n = self.values.len();
        std::iter::once((&self.values[i], &self.values[k]))
            .chain((0..n).map(|j| (&self.rows[i][j], &self.rows[k][j])))
            .map(|(x, y)| {
                (x.clone() * by_k - &(y.clone() * by_i))
                    .sign()
                    .unwrap_or(Ordering::Equal)
            })
            .find(|o| *o != Ordering::Equal)
            .unwrap_or(Ordering::Equal)
    }
}

/// One solution `z` of `z >= 0, q + W z >= 0, z . (q + W z) = 0`, or `None` when Lemke's
/// method ends on a ray (for a positive semidefinite W: no solution exists).
///
/// A sign the field cannot decide counts as not positive.
///
/// For Newton's cradle of three unit balls (W = [2, -1; -1, 2], q = (1 + e) u0 = (-2, 0) at
/// e = 1) it gives z = (4/3, 2/3) (the tests below).
///
/// # Errors
/// [`Stopped`] when its pivots pass their work limit or the host interrupts.
pub(super) fn lemke<F: Field>(w: &[Vec<F>], q: &[F]) -> Result<Option<Vec<F>>, Stopped> {
    let n = q.len();
    let negative = |x: &F| x.sign() == Some(Ordering::Less);
    if !q.iter().any(negative) {
        return Ok(Some(vec![F::zero(); n]));
    }
    let mut meter = Meter::new(Work::Pivots);
    let mut t = Tableau::new(w, q);
    let one = F::one();
    // z0 enters where it lifts the most negative q to zero (lexicographically least row).
    let first = (0..n)
        .min_by(|&i, &k| t.lex_cmp((i, &one), (k, &one)))
        .expect("n >= 1: some q is negative");
    let mut entering = complement(t.pivot(first, 2 * n), n);
    loop {
        // A pivot updates every entry of the tableau: n rows of 2n + 1 numbers.
        meter.charge(n * (2 * n + 1), t.values.iter())?;
        let candidates: Vec<usize> = (0..n)
            .filter(|&i| t.rows[i][entering].sign() == Some(Ordering::Greater))
            .collect();
        let Some(r) = candidates
            .into_iter()
            .min_by(|&i, &k| t.lex_cmp((i, &t.rows[i][entering]), (k, &t.rows[k][entering])))
        else {
            return Ok(None);
        };
        let leaving = t.pivot(r, entering);
        if leaving == 2 * n {
            let mut z = vec![F::zero(); n];
            for (row, &var) in t.basic.iter().enumerate() {
                if (n..2 * n).contains(&var) {
                    z[var - n] = t.values[row].clone();
                }
            }
            return Ok(Some(z));
        }
        entering = complement(leaving, n);
    }
}

/// The complement of variable `var` (`w_i` and `z_i`).
fn complement(var: usize, n: usize) -> usize {
    if var < n { var + n } else { var - n }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::{Q, q};

    fn matrix(rows: &[&[i64]]) -> Vec<Vec<Q>> {
        rows.iter()
            .map(|r| r.iter().map(|&x| q(x, 1)).collect())
            .collect()
    }

    #[test]
    fn the_cradle_pushes_both_contacts() {
        let w = matrix(&[&[2, -1], &[-1, 2]]);
        assert_eq!(
            lemke(&w, &[q(-2, 1), q(0, 1)]).unwrap(),
            Some(vec![q(4, 3), q(2, 3)])
        );
    }

    #[test]
    fn a_contact_already_leaving_takes_nothing() {
        let w = matrix(&[&[2, -1], &[-1, 2]]);
        assert_eq!(
            lemke(&w, &[q(1, 1), q(3, 1)]).unwrap(),
            Some(vec![q(0, 1), q(0, 1)])
        );
        // The second contact leaves once the first pushes: z = (1/2, 0), w = (0, 5/2).
        assert_eq!(
            lemke(&w, &[q(-1, 1), q(3, 1)]).unwrap(),
            Some(vec![q(1, 2), q(0, 1)])
        );
    }

    #[test]
    fn no_solution_ends_on_a_ray() {
        // W = 0 and q < 0: nothing can lift the velocity.
        let w = matrix(&[&[0, 0], &[0, 0]]);
        assert_eq!(lemke(&w, &[q(-1, 1), q(0, 1)]).unwrap(), None);
    }

    #[test]
    fn degenerate_ties_do_not_cycle() {
        // Three contacts on one rigid bar (W singular, rank 2) with equal, touching and
        // approaching velocities: the lexicographic rule ends, and w = q + W z is complementary.
        let w = matrix(&[&[2, 1, 0], &[1, 1, 1], &[0, 1, 2]]);
        let before = [q(-1, 1), q(-1, 1), q(0, 1)];
        let z = lemke(&w, &before).unwrap().expect("feasible");
        let after: Vec<Q> = (0..3)
            .map(|i| (0..3).fold(before[i].clone(), |acc, j| acc + &w[i][j] * &z[j]))
            .collect();
        for i in 0..3 {
            assert!(z[i] >= q(0, 1) && after[i] >= q(0, 1), "{z:?} {after:?}");
            assert_eq!(&z[i] * &after[i], q(0, 1));
        }
    }
}
