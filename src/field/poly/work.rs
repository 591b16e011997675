//! A work meter for polynomial arithmetic, so that a symbolic solve on user input can be
//! refused by a count of work rather than run for minutes.
//!
//! The field operations of [`RatFn`](crate::field::RatFn) cannot return an error (the solver is
//! generic over [`Field`](crate::field::Field)), so the meter stops a computation by unwinding:
//! [`metered`] arms a limit for the current thread and runs a closure; every polynomial
//! product charges `(words of a) * (words of b)` (the 64-bit words of every coefficient, as
//! [`Poly::words`] counts them: the schoolbook cost of the product with its coefficient
//! reductions); once the total passes the limit the computation unwinds with
//! [`std::panic::resume_unwind`] (which runs no panic hook, so nothing is printed) and
//! [`metered`] returns [`WorkExhausted`]. The count is deterministic: a refusal does not
//! depend on the machine or its load. Outside [`metered`] nothing is counted or limited.
//!
//! On a target built with `panic = "abort"` (WebAssembly by default) an exhausted meter aborts
//! instead of returning; the native library and the command-line tool unwind.

use super::Poly;
use std::cell::Cell;
use std::panic::{AssertUnwindSafe, catch_unwind, resume_unwind};

/// The meter of the current thread: work spent and the limit, when armed.
#[derive(Clone, Copy)]
struct Meter {
    spent: u64,
    limit: u64,
}

thread_local! {
    static METER: Cell<Option<Meter>> = const { Cell::new(None) };
}

/// A metered computation passed its limit and was stopped.
///
/// # Examples
/// ```
/// use rodimpact::field::poly::{metered, WorkExhausted};
/// assert_eq!(metered(0, || rodimpact::field::RatFn::symbol("m") * rodimpact::field::RatFn::symbol("M")).err(), Some(WorkExhausted));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct WorkExhausted;

/// Runs `f` with at most `limit` units of polynomial work; returns its value and the work it
/// spent, or [`WorkExhausted`] once the work passes `limit` (the computation is abandoned).
/// A metered run inside another counts against both: it is limited by its own limit and by
/// what the outer one has left, and the outer one is charged what it spent.
///
/// # Errors
/// [`WorkExhausted`] when `f` needs more than `limit` units.
///
/// # Examples
/// ```
/// use rodimpact::field::{poly::metered, RatFn};
/// use num_traits::One;
/// let (m, big_m) = (RatFn::symbol("m"), RatFn::symbol("M"));
/// let (ratio, work) = metered(1_000, || m.clone() / (m.clone() + big_m.clone())).unwrap();
/// assert_eq!(ratio.to_string(), "m/(M + m)");
/// assert!(work > 0);
/// let power = |x: &RatFn| (0..64).fold(RatFn::one(), |p, _| p * x.clone());
/// assert!(metered(1_000, || power(&(m.clone() + big_m.clone()))).is_err());
/// ```
pub fn metered<T>(limit: u64, f: impl FnOnce() -> T) -> Result<(T, u64), WorkExhausted> {
    let outer = METER.with(Cell::get);
    let limit = outer.map_or(limit, |o| limit.min(o.limit.saturating_sub(o.spent)));
    METER.with(|m| m.set(Some(Meter { spent: 0, limit })));
    let result = catch_unwind(AssertUnwindSafe(f));
    let spent = METER.with(Cell::get).map_or(0, |m| m.spent);
    METER.with(|m| {
        m.set(outer.map(|o| Meter {
            spent: o.spent.saturating_add(spent),
            ..o
        }))
    });
    match result {
        Ok(value) => Ok((value, spent)),
        Err(payload) if payload.is::<WorkExhausted>() => {
            if outer.is_some_and(|o| o.spent.saturating_add(spent) > o.limit) {
                // The outer run is exhausted too: stop it as well.
                resume_unwind(Box::new(WorkExhausted));
            }
            Err(WorkExhausted)
        }
        Err(payload) => resume_unwind(payload),
    }
}

/// Charges the product of `a` and `b` to the armed meter, if any, and stops the computation
/// when it passes its limit.
pub(super) fn charge_product(a: &Poly, b: &Poly) {
    let Some(mut meter) = METER.with(Cell::get) else {
        return;
    };
    meter.spent = meter
        .spent
        .saturating_add(a.words().saturating_mul(b.words()));
    METER.with(|m| m.set(Some(meter)));
    if meter.spent > meter.limit {
        resume_unwind(Box::new(WorkExhausted));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::RatFn;
    use num_traits::One;

    fn power(x: &RatFn, n: usize) -> RatFn {
        (0..n).fold(RatFn::one(), |p, _| p * x.clone())
    }

    #[test]
    fn work_is_counted_and_limited_deterministically() {
        let x = RatFn::symbol("m") + RatFn::symbol("M");
        let (value, work) = metered(u64::MAX, || power(&x, 8)).unwrap();
        assert_eq!(value, power(&x, 8));
        assert_eq!(metered(u64::MAX, || power(&x, 8)).unwrap().1, work);
        assert_eq!(metered(work, || power(&x, 8)).unwrap().1, work);
        assert_eq!(metered(work - 1, || power(&x, 8)), Err(WorkExhausted));
    }

    #[test]
    fn nothing_is_charged_outside_a_metered_run() {
        let x = RatFn::symbol("m") + RatFn::symbol("M");
        let _ = metered(0, || ());
        assert_eq!(power(&x, 3), power(&x, 3)); // no meter armed: no unwinding
    }

    #[test]
    fn an_inner_run_is_charged_to_the_outer_one() {
        let x = RatFn::symbol("m") + RatFn::symbol("M");
        let (_, inner) = metered(u64::MAX, || power(&x, 5)).unwrap();
        let (spent_inside, outer) =
            metered(u64::MAX, || metered(u64::MAX, || power(&x, 5)).unwrap().1).unwrap();
        assert_eq!(spent_inside, inner);
        assert_eq!(outer, inner);
        // The inner run is limited by what the outer one has left.
        assert_eq!(
            metered(inner, || metered(u64::MAX, || power(&x, 5)).map(|r| r.1)),
            Ok((Ok(inner), inner))
        );
        assert_eq!(
            metered(inner - 1, || metered(u64::MAX, || power(&x, 5)).is_err()),
            Err(WorkExhausted)
        );
    }

    #[test]
    fn other_panics_pass_through() {
        let caught = catch_unwind(|| metered(u64::MAX, || panic!("not a meter")));
        assert!(caught.is_err());
        assert_eq!(metered(10, || 1).unwrap().0, 1);
    }
}
