//! Linear algebra over any [`Field`]: Gaussian elimination, exact over exact fields.

use super::Field;
use std::cmp::Ordering;

/// Solves a linear system `A x = b` by Gaussian elimination over any field.
///
/// Exact fields take the first nonzero pivot (every choice is exact); float fields use partial
/// pivoting (the largest magnitude). Returns `None` when the system is singular.
///
/// # Examples
/// ```
/// use rodimpact::field::linear::solve_linear;
/// use rodimpact::field::{q, Q};
/// let a = vec![vec![q(0, 1), q(1, 1)], vec![q(2, 1), q(1, 1)]];
/// let x = solve_linear(a, vec![q(3, 1), q(5, 1)]).unwrap();
/// assert_eq!(x, vec![q(1, 1), q(3, 1)]);
/// ```
pub fn solve_linear<F: Field>(mut a: Vec<Vec<F>>, mut b: Vec<F>) -> Option<Vec<F>> {
    let n = b.len();
    for col in 0..n {
        let candidates = (col..n).filter(|&r| !a[r][col].is_zero());
        let pivot = if F::EXACT {
            candidates.min()?
        } else {
            candidates.max_by(|&r, &s| {
                let (x, y) = (a[r][col].nearest_f64().abs(), a[s][col].nearest_f64().abs());
                x.partial_cmp(&y).unwrap_or(Ordering::Equal)
            })?
        };
        a.swap(col, pivot);
        b.swap(col, pivot);
        for row in col + 1..n {
            if a[row][col].is_zero() {
                continue;
            }
            let factor = a[row][col].clone() / &a[col][col];
            let (upper, lower) = a.split_at_mut(row);
            for (target, pivot_entry) in lower[0][col..].iter_mut().zip(&upper[col][col..]) {
                *target = target.clone() - &(factor.clone() * pivot_entry);
            }
            let delta = factor * &b[col];
            b[row] = b[row].clone() - &delta;
        }
    }
    let mut x = vec![F::zero(); n];
    for row in (0..n).rev() {
        let mut acc = b[row].clone();
        for k in row + 1..n {
            acc = acc - &(a[row][k].clone() * &x[k]);
        }
        x[row] = acc.checked_div(&a[row][row])?;
    }
    Some(x)
}
