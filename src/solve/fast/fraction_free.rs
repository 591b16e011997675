//! The fraction-free route ([`Route::FractionFree`](crate::solve::Route::FractionFree)): the same v,
//! V, omega as the linear solve ([`super::linear::solve`]) over [`Q`], bit for bit, without a
//! GCD after every operation.
//!
//! The straightforward path spends about 91 % of its time in num-bigint's GCD, because
//! `BigRational` reduces after every operation (README, Performance). Here, for a free rod, the
//! scene's numbers are split once into integer numerators and denominators, the closed form is
//! evaluated on integers over one common denominator, the conservation laws are checked as integer
//! identities, and each output is reduced once.
//!
//! With I = M g (g = l^2/3 uniform, l^2 dumbbell, r_G^2 by radius of gyration, I/M given) every
//! term carries a factor M, which cancels. Over the common denominator md Md gd ad^2 of the
//! masses, g and a^2:
//!
//! - `A = mn gn Md ad^2` (m g), `B = Mn gn md ad^2` (M g), `C = mn an^2 Md gd` (m a^2);
//! - `dd = ed (A + B + C)`, `nv = ed (A + C) - en B`, `nV = (ed + en) A`,
//!   `nw = (ed + en) mn an Md gd ad`;
//! - `v = v0 nv/dd`, `V = v0 nV/dd`, `omega = v0 nw/dd`.
//!
//! The laws are homogeneous in (v0, v, V, omega), so they are checked on (dd, nv, nV, nw):
//! linear momentum `mn Md nv + Mn md nV = mn Md dd`, angular momentum about the centre
//! `mn Md an gd nv + Mn md gn ad nw = mn Md an gd dd` (I = M g), and for e = 1 the kinetic
//! energy `mn Md gd nv^2 + Mn md gd nV^2 + Mn md gn nw^2 = mn Md gd dd^2`.
//!
//! The integers are first tried in checked `i128` (energy in 256 bits, its terms are
//! non-negative), then in a checked 512-bit integer (`wide`), and only then in big integers
//! (dashu's `IBig`, or malachite's `Integer` with the cargo feature
//! `malachite`): the first overflow restarts the scene in the next width
//! ([`crate::field::int`]). A pivoted rod takes the same route with its own fixed-axis formulas
//! (see `pivoted`). The GCDs of the final reductions run on machine words up to 256 bits.
//!
//! A fast case of the core: it must equal `impact::solve_contact(&scene.system(),
//! Law::Newton)` in Q, which `tests/lib/fast_routes.rs` checks on random scenes.

use crate::field::Q;
use crate::field::int::{Big, Int, Wide, split};
use crate::scene::Motion;
use crate::scene::{RodInertia, Scene, Support};
use num_traits::One;

/// Which integer width produced a [`FractionFree`].
///
/// # Examples
/// ```
/// use rodimpact::{solve::fast::fraction_free::{solve, Width}, scene::Scene, field::q};
/// let big = q(1 << 62, 3);
/// let s = Scene::builder(big.clone(), big.clone() * q(7, 5)).build().unwrap();
/// assert_eq!(solve(&s).width, Width::Wide); // beyond i128
/// let huge = big.clone() * &big * &big * &big * &big;
/// let s = Scene::builder(huge.clone(), huge * q(7, 5)).build().unwrap();
/// assert_eq!(solve(&s).width, Width::Big); // beyond 512 bits
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Width {
    /// Fraction-free in checked `i128` (energy in 256-bit unsigned).
    Fixed,
    /// Fraction-free in a checked 512-bit integer (`i128` overflowed).
    Wide,
    /// Fraction-free in big integers, dashu's `IBig` or, with the feature `malachite`,
    /// malachite's `Integer` (the fixed width overflowed, or was not tried).
    Big,
}

/// The velocities after the impact, exact and reduced, and whether the laws held.
///
/// # Examples
/// ```
/// use rodimpact::{solve::fast::fraction_free::solve, scene::Scene, field::q};
/// let s = Scene::builder(q(1, 1), q(1, 1)).e(q(0, 1)).build().unwrap();
/// let out = solve(&s);
/// assert_eq!((out.after.v, out.after.omega), (q(4, 5), q(3, 5))); // sticking
/// assert!(out.laws_hold); // momentum balances; energy is not conserved for e = 0
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct FractionFree {
    /// v, V, omega exactly as [`super::linear::solve`] over [`Q`] gives them.
    pub after: Motion<Q>,
    /// Every applicable conservation law holds exactly (linear momentum for a free rod, angular
    /// momentum, energy when e = 1).
    pub laws_hold: bool,
    /// The integer width that was used.
    pub width: Width,
}

/// Solves the scene exactly on the fastest path that fits, fixed width then big integers: free
/// or pivoted rod, any inertia, any e.
///
/// # Examples
/// ```
/// use rodimpact::{solve::fast::fraction_free::{solve, Width}, scene::Scene, field::q};
/// let s = Scene::builder(q(1, 1), q(1, 1)).build().unwrap();
/// let out = solve(&s);
/// assert_eq!((out.after.v, out.after.rod_v, out.after.omega), (q(3, 5), q(2, 5), q(6, 5)));
/// assert!(out.laws_hold);
/// assert_eq!(out.width, Width::Fixed);
/// ```
pub fn solve(scene: &Scene) -> FractionFree {
    let fixed = || {
        (input_bits(scene) <= I128_INPUT_BITS)
            .then(|| in_width::<i128>(scene))
            .flatten()
            .map(|s| s.with(Width::Fixed))
    };
    fixed()
        .or_else(|| in_width::<Wide>(scene).map(|s| s.with(Width::Wide)))
        .unwrap_or_else(|| solve_big(scene))
}

/// Above this many input bits (see `input_bits`) `i128` is not tried: the law identities grow
/// like the product of the inputs, and every 10^6-sized scene (about 280 bits) overflowed it.
/// A choice of route only: every route gives the same exact result.
const I128_INPUT_BITS: u64 = 200;

/// The bits of every numerator and denominator of the scene, summed.
fn input_bits(scene: &Scene) -> u64 {
    let bits = |x: &Q| x.numer().bits() + x.denom().bits();
    [
        scene.m(),
        scene.rod_mass(),
        scene.half_length(),
        scene.a(),
        scene.v0(),
        scene.e(),
    ]
    .into_iter()
    .map(bits)
    .sum()
}

/// [`solve`] without the fixed-width attempt: fraction-free in big integers (the fallback on
/// its own, for tests and benchmarks): dashu's `IBig` (MIT/Apache-2.0), or malachite's `Integer` with
/// the cargo feature `malachite` (LGPL-3.0; subquadratic GCD). The result is the same.
///
/// # Examples
/// ```
/// use rodimpact::{solve::fast::fraction_free::{solve, solve_big}, scene::Scene, field::q};
/// let s = Scene::builder(q(2, 7), q(5, 3)).a(q(-1, 3)).e(q(1, 2)).build().unwrap();
/// assert_eq!(solve_big(&s).after, solve(&s).after);
/// ```
pub fn solve_big(scene: &Scene) -> FractionFree {
    in_width::<Big>(scene)
        .expect("big integers never overflow")
        .with(Width::Big)
}

impl FractionFree {
    fn with(self, width: Width) -> Self {
        FractionFree { width, ..self }
    }
}

/// g = I/M as (gn, gd), gd > 0, not necessarily reduced: [`RodInertia::moment`] of a unit
/// mass, written on integers (a rational `l^2/3` would reduce, which this route avoids).
fn inertia_per_mass<T: Int>(scene: &Scene) -> Option<(T, T)> {
    let square = |x: &Q| -> Option<(T, T)> {
        let (n, d) = split::<T>(x)?;
        Some((n.mul(&n)?, d.mul(&d)?))
    };
    match scene.rod() {
        RodInertia::Uniform => {
            let (n, d) = square(scene.half_length())?;
            Some((n, d.mul(&T::small(3))?))
        }
        RodInertia::Dumbbell => square(scene.half_length()),
        RodInertia::Gyration(r) => square(r),
        RodInertia::Moment(i) => {
            let (in_, id) = split::<T>(i)?;
            let (mn, md) = split::<T>(scene.rod_mass())?;
            Some((in_.mul(&md)?, id.mul(&mn)?))
        }
    }
}

/// The scene's numbers split once into numerators and denominators (I = M g): what the
/// fraction-free formulas take, from a [`Scene`] or straight from a batch row's cells.
pub(crate) struct Parts<T> {
    pub(crate) mn: T,
    pub(crate) md: T,
    pub(crate) big_n: T,
    pub(crate) big_d: T,
    pub(crate) an: T,
    pub(crate) ad: T,
    pub(crate) en: T,
    pub(crate) ed: T,
    pub(crate) gn: T,
    pub(crate) gd: T,
    /// The pivot `p = pn/pd`, if any.
    pub(crate) pivot: Option<(T, T)>,
}

/// The solution over one common denominator, before v0: `v = v0 nv/den`, and so on.
pub(crate) struct Raw<T> {
    pub(crate) nv: T,
    pub(crate) n_big_v: T,
    pub(crate) nw: T,
    pub(crate) den: T,
    /// Every law that applies held: the momentum laws, and energy when e = 1.
    pub(crate) laws_hold: bool,
}

impl<T: Int> Parts<T> {
    /// The weights of twice the kinetic energy over the common denominator `md Md gd`:
    /// `m v^2 + M V^2 + M g omega^2` times it is `wv v^2 + wV V^2 + ww omega^2` with
    /// `[wv, wV, ww] = [mn Md gd, Mn md gd, Mn md gn]`; `None` on overflow.
    pub(crate) fn kinetic_weights(&self) -> Option<[T; 3]> {
        let big_n_md = self.big_n.mul(&self.md)?;
        Some([
            self.mn.mul(&self.big_d)?.mul(&self.gd)?,
            big_n_md.mul(&self.gd)?,
            big_n_md.mul(&self.gn)?,
        ])
    }
}

/// The scene's parts in `T`; `None` when one does not fit.
fn parts_of<T: Int>(scene: &Scene) -> Option<Parts<T>> {
    let (mn, md) = split::<T>(scene.m())?;
    let (big_n, big_d) = split::<T>(scene.rod_mass())?;
    let (an, ad) = split::<T>(scene.a())?;
    let (en, ed) = split::<T>(scene.e())?;
    let (gn, gd) = inertia_per_mass::<T>(scene)?;
    let pivot = match scene.support() {
        Support::Free => None,
        Support::Pivot(p) => Some(split::<T>(p)?),
    };
    Some(Parts {
        mn,
        md,
        big_n,
        big_d,
        an,
        ad,
        en,
        ed,
        gn,
        gd,
        pivot,
    })
}

/// The fraction-free solve in `T`; `None` on overflow.
fn in_width<T: Int>(scene: &Scene) -> Option<FractionFree> {
    let raw = raw_of(&parts_of::<T>(scene)?, scene.e().is_one())?;
    let (vn, vd) = split::<T>(scene.v0())?;
    let den = vd.mul(&raw.den)?;
    let after = Motion {
        v: T::ratio(vn.mul(&raw.nv)?, den.clone()),
        rod_v: T::ratio(vn.mul(&raw.n_big_v)?, den.clone()),
        omega: T::ratio(vn.mul(&raw.nw)?, den),
    };
    Some(FractionFree {
        after,
        laws_hold: raw.laws_hold,
        width: Width::Big,
    })
}

/// The raw solution of a free or pivoted rod and its laws checked as integer identities
/// (energy when `elastic`, e = 1); `None` on overflow.
pub(crate) fn raw_of<T: Int>(parts: &Parts<T>, elastic: bool) -> Option<Raw<T>> {
    let (raw, momentum) = match &parts.pivot {
        None => free_rod(parts)?,
        Some(p) => pivoted(parts, p)?,
    };
    // Energy, m v^2 + M V^2 + M g omega^2 = m v0^2, times md Md gd: the same for both supports.
    let energy = if elastic {
        let [wv, w_big_v, ww] = parts.kinetic_weights()?;
        T::squares_balance(
            [(&wv, &raw.nv), (&w_big_v, &raw.n_big_v), (&ww, &raw.nw)],
            (&wv, &raw.den),
        )?
    } else {
        true
    };
    Some(Raw {
        laws_hold: momentum && energy,
        ..raw
    })
}

/// Free rod: see the module documentation for the formulas and the identities.
fn free_rod<T: Int>(s: &Parts<T>) -> Option<(Raw<T>, bool)> {
    let ad2 = s.ad.mul(&s.ad)?;
    let mn_big_d = s.mn.mul(&s.big_d)?;
    let big_n_md = s.big_n.mul(&s.md)?;
    let a_term = mn_big_d.mul(&s.gn)?.mul(&ad2)?;
    let b_term = big_n_md.mul(&s.gn)?.mul(&ad2)?;
    let c_term = mn_big_d.mul(&s.an)?.mul(&s.an)?.mul(&s.gd)?;
    let a_plus_c = a_term.add(&c_term)?;
    let den = s.ed.mul(&a_plus_c.add(&b_term)?)?;
    let ne = s.ed.add(&s.en)?;
    let nv = s.ed.mul(&a_plus_c)?.sub(&s.en.mul(&b_term)?)?;
    let n_big_v = ne.mul(&a_term)?;
    let nw = ne.mul(&mn_big_d)?.mul(&s.an)?.mul(&s.gd)?.mul(&s.ad)?;

    let linear = mn_big_d.mul(&nv)?.add(&big_n_md.mul(&n_big_v)?)? == mn_big_d.mul(&den)?;
    let mn_an_gd = mn_big_d.mul(&s.an)?.mul(&s.gd)?;
    let angular = mn_an_gd
        .mul(&nv)?
        .add(&big_n_md.mul(&s.gn)?.mul(&s.ad)?.mul(&nw)?)?
        == mn_an_gd.mul(&den)?;
    let raw = Raw {
        nv,
        n_big_v,
        nw,
        den,
        laws_hold: true,
    };
    Some((raw, linear && angular))
}

/// Pivot at p, d = a - p = dn/dq: with s = mn Md gd pd^2 and
/// `K = Mn md dq^2 (gn pd^2 + pn^2 gd) + s dn^2` (I_p + m d^2 over the common denominator),
/// `den = ed K`, `nw = ne s dn dq`, `nv = ne s dn^2 - en K`, `nV = -ne mn Md gd pd pn dn dq`.
/// Checked: angular momentum about the pivot, m d v + I omega - p M V = m d v0, times
/// md dq Md gd pd.
fn pivoted<T: Int>(s: &Parts<T>, (pn, pd): &(T, T)) -> Option<(Raw<T>, bool)> {
    let dn = s.an.mul(pd)?.sub(&pn.mul(&s.ad)?)?;
    let dq = s.ad.mul(pd)?;
    let mn_big_d_gd = s.mn.mul(&s.big_d)?.mul(&s.gd)?;
    let big_n_md = s.big_n.mul(&s.md)?;
    let scale = mn_big_d_gd.mul(pd)?.mul(pd)?;
    let inertia = s.gn.mul(pd)?.mul(pd)?.add(&pn.mul(pn)?.mul(&s.gd)?)?;
    let k = big_n_md
        .mul(&dq)?
        .mul(&dq)?
        .mul(&inertia)?
        .add(&scale.mul(&dn)?.mul(&dn)?)?;
    let ne = s.ed.add(&s.en)?;
    let den = s.ed.mul(&k)?;
    let ne_dn_dq = ne.mul(&dn)?.mul(&dq)?;
    let nw = scale.mul(&ne_dn_dq)?;
    let nv = ne.mul(&scale)?.mul(&dn)?.mul(&dn)?.sub(&s.en.mul(&k)?)?;
    let n_big_v = T::small(0).sub(&mn_big_d_gd.mul(pd)?.mul(pn)?.mul(&ne_dn_dq)?)?;

    let m_d = s.mn.mul(&dn)?.mul(&s.big_d)?.mul(&s.gd)?.mul(pd)?;
    let big_n_md_dq = big_n_md.mul(&dq)?;
    let angular = m_d
        .mul(&nv)?
        .add(&big_n_md_dq.mul(&s.gn)?.mul(pd)?.mul(&nw)?)?
        .sub(&pn.mul(&big_n_md_dq)?.mul(&s.gd)?.mul(&n_big_v)?)?
        == m_d.mul(&den)?;
    let raw = Raw {
        nv,
        n_big_v,
        nw,
        den,
        laws_hold: true,
    };
    Some((raw, angular))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::q;
    use num_traits::{Signed, Zero};

    #[test]
    fn every_width_is_reached() {
        let paper = Scene::builder(q(1, 1), q(1, 1)).build().unwrap();
        assert_eq!(solve(&paper).width, Width::Fixed);
        let wide = q(i64::MAX, 3) * q(i64::MAX, 1);
        let s = Scene::builder(wide.clone(), wide.clone()).build().unwrap();
        assert_eq!(solve(&s).width, Width::Wide);
        let huge = wide.clone() * &wide * &wide;
        let s = Scene::builder(huge.clone(), huge).build().unwrap();
        let out = solve(&s);
        assert_eq!(out.width, Width::Big);
        assert_eq!(out.after, solve_big(&s).after);
        let pivoted = Scene::builder(q(1, 1), q(3, 1))
            .pivot(q(0, 1))
            .build()
            .unwrap();
        let out = solve(&pivoted);
        assert_eq!(out.width, Width::Fixed);
        assert_eq!((out.after.v, out.after.omega), (q(0, 1), q(1, 1)));
    }

    #[test]
    fn a_negative_projectile_velocity_is_reduced_with_its_sign() {
        // M = 3m, hit at the centre: v = -v0/2.
        let s = Scene::builder(q(1, 1), q(3, 1))
            .a(q(0, 1))
            .v0(q(4, 6))
            .build()
            .unwrap();
        let out = solve(&s);
        assert_eq!(out.after.v, q(-1, 3));
        assert!(out.after.v.denom().is_positive());
        assert!(out.after.omega.is_zero());
        assert!(out.laws_hold);
    }
}
