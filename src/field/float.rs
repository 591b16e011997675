//! [`Field`] for the IEEE floats `f64` and `f32`: the backends whose error the exact ones measure.
//!
//! `from_rational` rounds to nearest (through num-rational's `to_f64`, which rounds the exact
//! ratio, not its parts); `sign` is `None` for NaN.

use super::{Field, Q};
use num_traits::ToPrimitive;
use std::cmp::Ordering;

macro_rules! float_field {
    ($t:ty, $name:literal, $to:ident) => {
        impl Field for $t {
            const NAME: &'static str = $name;
            const EXACT: bool = false;

            fn from_rational(q: &Q) -> Self {
                q.$to().unwrap_or(<$t>::NAN)
            }

            fn sign(&self) -> Option<Ordering> {
                self.partial_cmp(&0.0)
            }

            fn nearest_f64(&self) -> f64 {
                f64::from(*self)
            }
        }
    };
}

float_field!(f64, "f64", to_f64);
float_field!(f32, "f32", to_f32);

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::{laws, q};

    /// Within 8 ulps of the larger magnitude, absolute below 1 (cancellation in the laws).
    fn close_f64(a: &f64, b: &f64) -> bool {
        let scale = a.abs().max(b.abs()).max(1.0);
        (a - b).abs() <= 8.0 * f64::EPSILON * scale
    }

    fn close_f32(a: &f32, b: &f32) -> bool {
        let scale = a.abs().max(b.abs()).max(1.0);
        (a - b).abs() <= 8.0 * f32::EPSILON * scale
    }

    #[test]
    fn f64_field_laws_hold_to_eight_ulps() {
        let samples: Vec<f64> = [q(0, 1), q(1, 1), q(-1, 1), q(1, 3), q(-22, 7)]
            .iter()
            .map(f64::from_rational)
            .chain([1e100, 1e-100])
            .collect();
        laws::check_field(&samples, close_f64);
    }

    #[test]
    fn f32_field_laws_hold_to_eight_ulps() {
        let samples: Vec<f32> = [q(0, 1), q(1, 1), q(-1, 1), q(1, 3), q(-22, 7)]
            .iter()
            .map(f32::from_rational)
            .chain([1e12, 1e-12])
            .collect();
        laws::check_field(&samples, close_f32);
    }

    #[test]
    fn from_rational_rounds_the_ratio_to_nearest() {
        assert_eq!(f64::from_rational(&q(1, 3)), 1.0 / 3.0);
        assert_eq!(f32::from_rational(&q(1, 10)), 0.1f32);
        assert_eq!(f64::NAN.sign(), None);
        assert_eq!((-0.5f64).sign(), Some(Ordering::Less));
    }
}
