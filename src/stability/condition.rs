//! Exact componentwise relative condition numbers of v, V and omega for a free rod
//! (`docs/stability.md`), in the inputs m, M, I, a, v0 (and e when e is not a float of the format).

use crate::field::{Field, abs};
use crate::scene::Params;
use crate::scene::{Groups, Motion};

/// The condition numbers of (v, V, omega); `None` (infinite) for v when q = e, where the
/// projectile stops. `e_rounds` adds the e terms (e is not exactly a float of the format).
///
/// cond_v = 1 + (1+e)(2r+4s)/(|q-e|(1+q)) [+ e/|q-e|],
/// cond_V = 1 + (2+4s)/(1+q) [+ e/(1+e)],
/// cond_omega = 1 + (2+2r+|1+r-s|)/(1+q) [+ e/(1+e)], with the paper's groups ([`Groups`]) r = m/M, s = m a^2/I, q = r + s.
///
/// # Examples
/// ```
/// use rodimpact::{scene::Scene, field::{q, Q}, stability::condition};
/// let s = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?; // r = 1, s = 3/4
/// let c = condition(&s.params::<Q>(), false);
/// assert_eq!(c.rod_v, Some(q(31, 11))); // 1 + (2 + 3)/(11/4)
/// assert_eq!(c.omega, Some(q(32, 11))); // 1 + (2 + 2 + 5/4)/(11/4)
/// let stop = Scene::builder(q(4, 7), q(1, 1)).a(q(1, 2)).build()?; // q = 1 = e
/// assert_eq!(condition(&stop.params::<Q>(), false).v, None);
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn condition<F: Field>(p: &Params<F>, e_rounds: bool) -> Motion<Option<F>> {
    let one = F::one();
    let two = F::from_i64(2);
    let four = F::from_i64(4);
    let e = &p.e;
    let Groups { r, s, q, d, .. } = Groups::of(&p.m, &p.rod_mass, &p.inertia, &p.a);
    let e_term = |denominator: &F| {
        if e_rounds {
            e.clone() / denominator
        } else {
            F::zero()
        }
    };
    let gap = abs(q - e);
    let v = (!gap.is_zero()).then(|| {
        let spread = two.clone() * &r + &(four.clone() * &s);
        one.clone() + &((one.clone() + e) * &spread / &(gap.clone() * &d)) + &e_term(&gap)
    });
    let one_plus_e = one.clone() + e;
    let rod_v = one.clone() + &((two.clone() + &(four * &s)) / &d) + &e_term(&one_plus_e);
    let lever = abs(one.clone() + &r - &s);
    let omega = one.clone() + &((two.clone() + &(two * &r) + &lever) / &d) + &e_term(&one_plus_e);
    Motion {
        v,
        rod_v: Some(rod_v),
        omega: Some(omega),
    }
}
