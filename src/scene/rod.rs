//! How the rod's mass is distributed: the four kinds of inertia and their one definition.

use crate::error::{Error, ErrorKind};
use crate::field::{Field, Q};
use crate::units::{Dimension, parse_si};
use std::fmt;

/// How the rod's mass is distributed (always symmetric about its centre).
#[derive(Debug, Clone, PartialEq)]
pub enum RodInertia {
    /// A uniform rod: I = M l^2 / 3.
    Uniform,
    /// An ideal dumbbell, all the mass at the two ends: I = M l^2.
    Dumbbell,
    /// Given radius of gyration r_G: I = M r_G^2, with 0 < r_G <= l.
    Gyration(Q),
    /// Given moment of inertia about the centre: 0 < I <= M l^2.
    Moment(Q),
}

impl RodInertia {
    /// The moment of inertia about the rod's centre for rod mass `mass` and half-length `l`, in
    /// any field: the one definition of the four mass distributions (I = M l^2/3, M l^2,
    /// M r_G^2, or I as given). Over rational functions it gives the symbolic inertia.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::RodInertia;
    /// use rodimpact::field::{q, RatFn};
    /// assert_eq!(RodInertia::Uniform.moment(&q(3, 1), &q(2, 1)), q(4, 1));
    /// assert_eq!(RodInertia::Gyration(q(1, 2)).moment(&q(3, 1), &q(2, 1)), q(3, 4));
    /// let (big_m, l) = (RatFn::symbol("M"), RatFn::symbol("l"));
    /// assert_eq!(RodInertia::Uniform.moment(&big_m, &l).to_string(), "1/3*M*l^2");
    /// ```
    pub fn moment<F: Field>(&self, mass: &F, l: &F) -> F {
        match self {
            RodInertia::Uniform => mass.clone() * l * l / F::from_i64(3),
            RodInertia::Dumbbell => mass.clone() * l * l,
            RodInertia::Gyration(r) => gyration_moment(mass, &F::from_rational(r)),
            RodInertia::Moment(i) => F::from_rational(i),
        }
    }

    /// [`RodInertia::moment`] over the rationals, the same value, computed as one fraction
    /// (the products of the numerators over those of the denominators) reduced once on machine
    /// words: num-rational reduces after every product with num-bigint's GCD, which cost more
    /// than a whole batch row's solve.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::RodInertia;
    /// use rodimpact::field::q;
    /// let (big_m, l) = (q(93531, 184198), q(104159, 300644));
    /// for rod in [RodInertia::Uniform, RodInertia::Dumbbell, RodInertia::Gyration(q(3, 7))] {
    ///     assert_eq!(rod.exact_moment(&big_m, &l), rod.moment(&big_m, &l));
    /// }
    /// ```
    pub fn exact_moment(&self, mass: &Q, l: &Q) -> Q {
        let product = |x: &Q, y: &Q, divisor: u32| {
            crate::field::int::reduce(
                x.numer() * y.numer() * y.numer(),
                x.denom() * y.denom() * y.denom() * divisor,
            )
        };
        match self {
            RodInertia::Uniform => product(mass, l, 3),
            RodInertia::Dumbbell => product(mass, l, 1),
            RodInertia::Gyration(r) => product(mass, r, 1),
            RodInertia::Moment(i) => i.clone(),
        }
    }

    /// Parses the `--rod` forms `uniform`, `dumbbell`, `rg=Q`, `I=Q` (a radius may carry a
    /// length unit, a moment of inertia `kg*m^2`).
    ///
    /// # Errors
    /// `rod: ...` naming the accepted forms, or the number's own parse error.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::RodInertia;
    /// use rodimpact::field::q;
    /// assert_eq!(RodInertia::parse("rg=1/2").unwrap(), RodInertia::Gyration(q(1, 2)));
    /// assert_eq!(RodInertia::parse("rg=25 cm").unwrap(), RodInertia::Gyration(q(1, 4)));
    /// assert!(RodInertia::parse("steel").is_err());
    /// ```
    pub fn parse(text: &str) -> Result<Self, Error> {
        let text = text.trim();
        match text {
            "uniform" => Ok(RodInertia::Uniform),
            "dumbbell" => Ok(RodInertia::Dumbbell),
            _ => {
                if let Some(r) = text.strip_prefix("rg=") {
                    Ok(RodInertia::Gyration(parse_si("rod", r, Dimension::Length)?))
                } else if let Some(i) = text.strip_prefix("I=") {
                    Ok(RodInertia::Moment(parse_si(
                        "rod",
                        i,
                        Dimension::MomentOfInertia,
                    )?))
                } else {
                    Err(Error::new(
                        "rod",
                        ErrorKind::Invalid(format!(
                            "expected uniform, dumbbell, rg=<radius> or I=<inertia>, got '{}'",
                            crate::echo::echo(text)
                        )),
                    ))
                }
            }
        }
    }
}

impl fmt::Display for RodInertia {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RodInertia::Uniform => write!(f, "uniform"),
            RodInertia::Dumbbell => write!(f, "dumbbell"),
            RodInertia::Gyration(r) => write!(f, "rg={r}"),
            RodInertia::Moment(i) => write!(f, "I={i}"),
        }
    }
}

/// `I = M r^2`: the moment of inertia about the centre of a rod of mass `mass` with radius of
/// gyration `r`, over any field (a symbol `r` as well as a number: [`RodInertia::moment`] is this
/// for a rational `r`).
///
/// # Examples
/// ```
/// use rodimpact::{field::RatFn, scene::gyration_moment};
/// let i = gyration_moment(&RatFn::symbol("M"), &RatFn::symbol("r_G"));
/// assert_eq!(i.to_string(), "M*r_G^2");
/// ```
pub fn gyration_moment<F: Field>(mass: &F, r: &F) -> F {
    mass.clone() * r * r
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// A rational of up to ~150 bits either side (so that the products pass 256 bits and take
    /// the big-integer reduction too), any sign for the numerator.
    fn rational() -> impl Strategy<Value = Q> {
        (any::<i64>(), any::<u64>(), 1u64.., 0u32..3).prop_map(|(n, big, d, scale)| {
            let n = num_bigint::BigInt::from(n) * num_bigint::BigInt::from(big).pow(scale);
            Q::new(n, num_bigint::BigInt::from(d))
        })
    }

    proptest! {
        /// The machine-word moment of inertia is the generic one, value and representation.
        #[test]
        fn exact_moment_is_the_moment(mass in rational(), l in rational(), r in rational()) {
            for rod in [RodInertia::Uniform, RodInertia::Dumbbell, RodInertia::Gyration(r.clone()), RodInertia::Moment(r.clone())] {
                let fast = rod.exact_moment(&mass, &l);
                let slow = rod.moment(&mass, &l);
                prop_assert_eq!((fast.numer(), fast.denom()), (slow.numer(), slow.denom()));
            }
        }
    }
}
