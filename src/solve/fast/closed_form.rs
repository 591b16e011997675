//! The closed-form route ([`Route::ClosedForm`](crate::solve::Route::ClosedForm)): the paper's
//! formulas, generalised to restitution e and to a pivot, over any [`Field`]. A second path,
//! independent of the linear solve; the naive float formula is this route in f64.
//!
//! A fast case of the core: over Q it must equal `impact::solve_contact(&scene.system(),
//! Law::Newton)`, which `tests/lib/fast_routes.rs` checks on random scenes.

use crate::field::Field;
use crate::scene::{Groups, Motion};
use crate::scene::{Params, Support};

/// The closed forms: the paper's Eqs. (v), (V), (omega) generalised to restitution e, and the
/// fixed-axis formula for a pivoted rod. A second path, independent of [`super::linear::solve`].
///
/// Free rod, with the paper's groups ([`Groups`]) r = m/M, s = m a^2/I, q = r + s:
/// `v = (q - e)/(1 + q) v0`, `V = (1 + e) r/(1 + q) v0`, `omega = (1 + e)(m a/I)/(1 + q) v0`
/// (for e = 1 exactly the paper's `v = -(1 - m/M - m a^2/I)/D v0` with D = 1 + q).
/// Pivot at p, d = a - p: `omega = (1 + e) m d v0/(I_p + m d^2)`, `v = d omega - e v0`,
/// `V = -p omega`. `None` if a denominator vanishes (float underflow only).
///
/// # Examples
/// ```
/// use rodimpact::{scene::Scene, solve::fast::closed_form::closed_form, field::{q, Q}};
/// let p = Scene::builder(q(1, 1), q(3, 1)).pivot(q(0, 1)).e(q(0, 1)).build().unwrap().params::<Q>();
/// let m = closed_form(&p).unwrap();
/// assert_eq!((m.v, m.omega), (q(1, 2), q(1, 2)));
/// ```
pub fn closed_form<F: Field>(p: &Params<F>) -> Option<Motion<F>> {
    let one_plus_e = F::one() + &p.e;
    match &p.support {
        Support::Free => {
            let Groups {
                r, ma_over_i, q, d, ..
            } = Groups::of_params(p)?;
            Some(Motion {
                v: (q - &p.e).checked_div(&d)? * &p.v0,
                rod_v: (one_plus_e.clone() * &r).checked_div(&d)? * &p.v0,
                omega: (one_plus_e * &ma_over_i).checked_div(&d)? * &p.v0,
            })
        }
        Support::Pivot(pivot) => {
            let d = p.a.clone() - pivot;
            let md = p.m.clone() * &d;
            let denominator = p.inertia_about_axis() + &(md.clone() * &d);
            let omega = (one_plus_e * &md * &p.v0).checked_div(&denominator)?;
            Some(Motion {
                v: omega.clone() * &d - &(p.e.clone() * &p.v0),
                rod_v: -(pivot.clone() * &omega),
                omega,
            })
        }
    }
}
