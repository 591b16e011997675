//! Routh's construction: the impact of one contact followed in the normal impulse `lam` (P = lam n + tau t),
//! the tangential impulse `tau` following the slip's mode, until the law in force ends it.
//!
//! - **slide** with slip sign s: Coulomb's friction opposes the slip, `dtau/dlam = -s mu`;
//! - **stick**: tau keeps the slip zero, `dtau/dlam = -W_nt/W_tt`, allowed while
//!   `|W_nt| <= mu W_tt`;
//! - where the slip reaches zero it sticks if it may, otherwise it reverses
//!   (`s = sign(W_nt)`); a reversed slip never stops again, and a stuck one stays stuck, so
//!   the path has at most two phases. Without friction there is one (`tau` = 0).
//!
//! Along the path `u = u0 + W (lam, tau)` is piecewise linear. Compression ends where u_n
//! first reaches 0 (`lam_c`). The laws differ only in where the impact ends:
//! **newton**, where u_n = -e u_n(0); **poisson**, at `lam_f = (1 + e) lam_c`; **energetic**
//! (Stronge), where the normal work in restitution, the integral of u_n dlam from `lam_c`,
//! is e^2 times minus its work in compression: a root of a quadratic in the last phase.

use crate::field::{Field, Q, QSqrt, TrySqrt};
use crate::impact::coulomb::{Mode, within_cone};
use crate::impact::jacobian::ContactMatrix;
use crate::impact::law::Law;
use std::cmp::Ordering;
use std::fmt;

/// A field whose positive elements have square roots there: exact Q(sqrt d) (a rational
/// adjoins its own root) and floats.
pub trait Roots: Field {
    /// The non-negative square root of `self >= 0`; `None` when it lies outside the field.
    fn root(&self) -> Option<Self>;
}

impl Roots for QSqrt {
    fn root(&self) -> Option<Self> {
        self.try_sqrt().or_else(|| {
            (self.d().is_none() && self.sign() != Some(Ordering::Less))
                .then(|| QSqrt::sqrt_of(self.x()))
        })
    }
}

impl Roots for Q {
    /// A rational's rational root, when it has one: Newton's and Poisson's laws never need a
    /// root, and the energetic law's end is rational when its discriminant is a square.
    fn root(&self) -> Option<Self> {
        self.try_sqrt()
    }
}

impl Roots for f64 {
    fn root(&self) -> Option<Self> {
        (*self >= 0.0).then(|| self.sqrt())
    }
}

/// One phase of the path: from `lam = from` on, `u_n`, `u_t` and `tau` change by `slope` per
/// unit of lam.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Segment<F> {
    pub(crate) mode: Mode,
    pub(crate) from: F,
    /// Where the phase ends (`None`: it lasts to the end of the impact).
    pub(crate) to: Option<F>,
    /// (u_n, u_t, tau) at `from`.
    pub(crate) start: [F; 3],
    /// d(u_n, u_t, tau)/dlam.
    pub(crate) slope: [F; 3],
}

impl<F: Field> Segment<F> {
    /// (u_n, u_t, tau) at `lam` (in or at the end of the phase).
    pub(crate) fn at(&self, lam: &F) -> [F; 3] {
        let d = lam.clone() - &self.from;
        std::array::from_fn(|i| self.start[i].clone() + &(self.slope[i].clone() * &d))
    }
}

/// Why the impact has no end under a law.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Jam {
    /// The normal relative velocity stops rising while the bodies still approach: the
    /// impulse cannot end the approach (a jam, as in Painlevé's paradox).
    Compression,
    /// The normal velocity stops rising after compression (the contact stuck with no room to
    /// separate), so this law's end is never reached.
    Restitution(Law),
    /// A sign could not be decided in this number type.
    Undecided,
}

impl fmt::Display for Jam {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Jam::Compression => f.write_str(
                "the normal relative velocity stops rising while the bodies still approach: the impact jams (Painlevé), and Routh's construction has no end",
            ),
            Jam::Restitution(law) => write!(
                f,
                "under {law}'s law the impact never ends: after compression the normal relative velocity stops rising (the contact sticks with no room to separate)"
            ),
            Jam::Undecided => f.write_str("a sign cannot be decided in this number type"),
        }
    }
}

fn sign<F: Field>(x: &F) -> Result<Ordering, Jam> {
    x.sign().ok_or(Jam::Undecided)
}

/// The path of the impact from `lam = 0`: its phases, in order, the last open-ended.
pub(crate) fn path<F: Field>(
    w: &ContactMatrix<F>,
    u0: [F; 2],
    mu: &F,
) -> Result<Vec<Segment<F>>, Jam> {
    // Sticking needs the tangential impulse -W_nt/W_tt per unit of lam, inside the cone.
    let stick_allowed =
        || -> Result<bool, Jam> { within_cone(&w.nt, &(mu.clone() * &w.tt)).ok_or(Jam::Undecided) };
    let after_stop = || -> Result<Mode, Jam> {
        if stick_allowed()? {
            Ok(Mode::Stick)
        } else {
            Ok(Mode::Slide {
                forward: sign(&w.nt)? == Ordering::Greater,
            })
        }
    };
    let mut mode = match (sign(mu)?, sign(&u0[1])?) {
        (Ordering::Equal, _) => Mode::Frictionless,
        (_, Ordering::Equal) => after_stop()?,
        (_, slip) => Mode::Slide {
            forward: slip == Ordering::Greater,
        },
    };
    let mut segments = Vec::new();
    let mut from = F::zero();
    let mut start = [u0[0].clone(), u0[1].clone(), F::zero()];
    loop {
        let tau_slope = match mode {
            Mode::Frictionless => F::zero(),
            Mode::Slide { forward } => {
                if forward {
                    -mu.clone()
                } else {
                    mu.clone()
                }
            }
            Mode::Stick => {
                if w.tt.is_zero() {
                    F::zero()
                } else {
                    -(w.nt.clone() / &w.tt)
                }
            }
        };
        let slope = [
            w.nn.clone() + &(w.nt.clone() * &tau_slope),
            w.nt.clone() + &(w.tt.clone() * &tau_slope),
            tau_slope,
        ];
        // A slide ends where the slip reaches zero, if it runs towards zero.
        let stop = match mode {
            Mode::Slide { forward } => {
                let towards = if forward {
                    sign(&slope[1])? == Ordering::Less
                } else {
                    sign(&slope[1])? == Ordering::Greater
                };
                towards.then(|| from.clone() - &(start[1].clone() / &slope[1]))
            }
            _ => None,
        };
        let segment = Segment {
            mode,
            from: from.clone(),
            to: stop.clone(),
            start: start.clone(),
            slope,
        };
        let Some(stop) = stop else {
            segments.push(segment);
            return Ok(segments);
        };
        let mut at_stop = segment.at(&stop);
        at_stop[1] = F::zero(); // exactly zero (floats round)
        segments.push(segment);
        mode = after_stop()?;
        from = stop;
        start = at_stop;
    }
}

/// The path of a law that imposes itself at once (an engine's law): straight stages in the
/// impulse plane, each adding `(d_lam, d_tau)` (`friction`: whether Coulomb's law acts in it),
/// the relative velocity linear along each; a stage that adds no normal impulse adds nothing.
/// A stage's mode is what friction does at its end: none (no friction), stick (no slip) or a
/// slide with the slip's sign.
pub(crate) fn staged<F: Field>(
    w: &ContactMatrix<F>,
    u0: [F; 2],
    mu: &F,
    stages: &[(F, F, bool)],
) -> Result<Vec<Segment<F>>, Jam> {
    let mut segments: Vec<Segment<F>> = Vec::new();
    let mut from = F::zero();
    let mut start = [u0[0].clone(), u0[1].clone(), F::zero()];
    for (d_lam, d_tau, friction) in stages {
        if d_lam.is_zero() {
            continue;
        }
        let tau_slope = d_tau.clone() / d_lam;
        let slope = [
            w.nn.clone() + &(w.nt.clone() * &tau_slope),
            w.nt.clone() + &(w.tt.clone() * &tau_slope),
            tau_slope,
        ];
        let to = from.clone() + d_lam;
        let end: [F; 3] = std::array::from_fn(|k| start[k].clone() + &(slope[k].clone() * d_lam));
        let mode = if !friction || mu.is_zero() {
            Mode::Frictionless
        } else {
            match sign(&end[1])? {
                Ordering::Equal => Mode::Stick,
                slip => Mode::Slide {
                    forward: slip == Ordering::Greater,
                },
            }
        };
        if let Some(last) = segments.last_mut() {
            last.to = Some(from.clone());
        }
        segments.push(Segment {
            mode,
            from: from.clone(),
            to: None,
            start: start.clone(),
            slope,
        });
        from = to;
        start = end;
    }
    Ok(segments)
}

/// The segment holding `lam` (the last one past the end).
pub(crate) fn segment_at<'a, F: Field>(path: &'a [Segment<F>], lam: &F) -> &'a Segment<F> {
    path.iter()
        .find(|s| {
            s.to.as_ref()
                .is_none_or(|to| (lam.clone() - to).sign() == Some(Ordering::Less))
        })
        .unwrap_or_else(|| path.last().expect("a path has a phase"))
}

/// The first lam at which u_n reaches `target` (>= the value at `from`), searching from
/// `from` on; `None` when u_n never gets there.
fn reach<F: Field>(path: &[Segment<F>], from: &F, target: &F) -> Result<Option<F>, Jam> {
    for s in path {
        if let Some(to) = &s.to
            && sign(&(to.clone() - from))? != Ordering::Greater
        {
            continue; // the phase ends before `from`
        }
        let begin = if sign(&(s.from.clone() - from))? == Ordering::Less {
            from.clone()
        } else {
            s.from.clone()
        };
        let un = s.at(&begin)[0].clone();
        let gap = target.clone() - &un;
        if sign(&gap)? != Ordering::Greater {
            return Ok(Some(begin));
        }
        if sign(&s.slope[0])? != Ordering::Greater {
            continue;
        }
        let lam = begin + &(gap / &s.slope[0]);
        match &s.to {
            Some(to) if sign(&(lam.clone() - to))? == Ordering::Greater => continue,
            _ => return Ok(Some(lam)),
        }
    }
    Ok(None)
}

/// The end of compression, lam_c: where u_n first reaches 0.
pub(crate) fn compression_end<F: Field>(path: &[Segment<F>]) -> Result<F, Jam> {
    reach(path, &F::zero(), &F::zero())?.ok_or(Jam::Compression)
}

/// The normal work `integral of u_n dlam` from `a` to `b` along the path.
pub(crate) fn normal_work<F: Field>(path: &[Segment<F>], a: &F, b: &F) -> F {
    let two = F::from_i64(2);
    let mut work = F::zero();
    for s in path {
        let lo = max(&s.from, a);
        let hi = match &s.to {
            Some(to) => min(to, b),
            None => b.clone(),
        };
        if (hi.clone() - &lo).sign() != Some(Ordering::Greater) {
            continue;
        }
        let (u_lo, u_hi) = (s.at(&lo)[0].clone(), s.at(&hi)[0].clone());
        work = work + &((u_lo + &u_hi) * &(hi - &lo) / &two);
    }
    work
}

/// The friction's work `integral of u_t dtau` from 0 to `b` along the path.
pub(crate) fn friction_work<F: Field>(path: &[Segment<F>], b: &F) -> F {
    let two = F::from_i64(2);
    let mut work = F::zero();
    for s in path {
        let hi = match &s.to {
            Some(to) => min(to, b),
            None => b.clone(),
        };
        if (hi.clone() - &s.from).sign() != Some(Ordering::Greater) {
            continue;
        }
        let (lo, at_hi) = (&s.start, s.at(&hi));
        // u_t and tau are linear in lam: the integral of u_t dtau is the trapezoid.
        work = work + &((lo[1].clone() + &at_hi[1]) * &(at_hi[2].clone() - &lo[2]) / &two);
    }
    work
}

fn max<F: Field>(a: &F, b: &F) -> F {
    if (a.clone() - b).sign() == Some(Ordering::Less) {
        b.clone()
    } else {
        a.clone()
    }
}

fn min<F: Field>(a: &F, b: &F) -> F {
    if (a.clone() - b).sign() == Some(Ordering::Greater) {
        b.clone()
    } else {
        a.clone()
    }
}

/// Where the impact ends under `law`: lam_f.
pub(crate) fn end<F: Roots>(
    path: &[Segment<F>],
    lam_c: &F,
    u_n0: &F,
    e: &F,
    law: Law,
) -> Result<F, Jam> {
    match law {
        Law::LcpNewton | Law::LcpPoisson | Law::Split => {
            unreachable!("the engines' laws end no path: one_contact solves them apart")
        }
        Law::Poisson => Ok(lam_c.clone() + &Law::poisson_restitution(e, lam_c)),
        Law::Newton => {
            let target = Law::newton_leaving(e, u_n0);
            reach(path, lam_c, &target)?.ok_or(Jam::Restitution(law))
        }
        Law::Energetic => {
            let compression = normal_work(path, &F::zero(), lam_c);
            let mut remaining = Law::energetic_restitution(e, &compression);
            if remaining.is_zero() {
                return Ok(lam_c.clone());
            }
            for s in path {
                if let Some(to) = &s.to
                    && sign(&(to.clone() - lam_c))? != Ordering::Greater
                {
                    continue;
                }
                let begin = max(&s.from, lam_c);
                let u = s.at(&begin)[0].clone();
                let k = s.slope[0].clone();
                // Within the phase the work from `begin` to begin + x is u x + k x^2/2.
                let x = if k.is_zero() {
                    if sign(&u)? != Ordering::Greater {
                        None
                    } else {
                        Some(remaining.clone() / &u)
                    }
                } else {
                    let discriminant = u.clone() * &u + &(F::from_i64(2) * &k * &remaining);
                    discriminant
                        .root()
                        .map(|root| (root - &u) / &k)
                        .filter(|x| x.sign() != Some(Ordering::Less))
                };
                if let Some(x) = x {
                    let lam = begin.clone() + &x;
                    match &s.to {
                        Some(to) if sign(&(lam.clone() - to))? == Ordering::Greater => {}
                        _ => return Ok(lam),
                    }
                }
                if let Some(to) = &s.to {
                    remaining = remaining - &normal_work(std::slice::from_ref(s), &begin, to);
                }
            }
            Err(Jam::Restitution(law))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::q;

    fn qs(n: i64, d: i64) -> QSqrt {
        QSqrt::rational(q(n, d))
    }

    /// The tilted rod of the oracle (W = [52/25, 36/25; 36/25, 73/25], u0 = (-1, -1),
    /// mu = 1/3): the slip stops at 75/181 and reverses; lam_c = 25/64.
    #[test]
    fn the_slip_stops_then_reverses() {
        let w = ContactMatrix {
            nn: qs(52, 25),
            nt: qs(36, 25),
            tt: qs(73, 25),
        };
        let p = path(&w, [qs(-1, 1), qs(-1, 1)], &qs(1, 3)).unwrap();
        assert_eq!(p.len(), 2);
        assert_eq!(p[0].mode, Mode::Slide { forward: false });
        assert_eq!(p[0].to, Some(qs(75, 181)));
        assert_eq!(p[1].mode, Mode::Slide { forward: true });
        assert_eq!(compression_end(&p).unwrap(), qs(25, 64));
        // Newton's end: u_n = 1 at lam = 725/724 (the oracle's).
        let lam_c = compression_end(&p).unwrap();
        assert_eq!(
            end(&p, &lam_c, &qs(-1, 1), &qs(1, 1), Law::Newton).unwrap(),
            qs(725, 724)
        );
        assert_eq!(
            end(&p, &lam_c, &qs(-1, 1), &qs(1, 1), Law::Poisson).unwrap(),
            qs(25, 32)
        );
    }
}
