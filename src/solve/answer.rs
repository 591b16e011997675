//! The front door of the library: the whole answer to any scene the library accepts.
//!
//! [`Answer::of`] answers a [`Scene`] completely and exactly, whatever it holds: the paper's
//! scene, a pivot, an oblique or frictional impact, a spinning disc, a rod moving before the
//! impact. It solves the normal impulse problem at the approach speed (fraction-free, the laws
//! checked as integer identities), completes it along the rod when the scene is oblique
//! ([`oblique::complete`]: both impulses, the contact mode and `mu*`), and adds the optimum
//! a* with omega_max where it applies (the rod not turning before the impact).
//!
//! A partial answer is asked for by name: [`Impact::of`] is the impact without the optimum
//! (what `batch` needs per row); [`super::with`] runs one named route on the paper's scene only
//! and refuses an oblique one ([`super::Why::Oblique`]).

use super::fast::oblique;
use super::optimum::{Optimum, PaperForm, optimum};
use super::{Outcome, Route, Solved};
use crate::field::int::{FixedInt, I256, U256, Unreduced, UnreducedInt, Wide, within};
use crate::field::{Field, Q};
use crate::impact::Mode;
use crate::scene::Motion;
use crate::scene::Scene;
use oblique::ObliqueOutcome;

/// The impact of a scene solved exactly: the normal problem's outcome and, for an oblique or
/// frictional scene, its completion along the rod. No optimum (see [`Answer`]).
///
/// # Examples
/// A rod drifting at V0 = 1 before a projectile at v0 = 3 arrives: the normal problem is the
/// paper's at the approach speed 2, shifted back by the drift.
/// ```
/// use rodimpact::{field::q, scene::Scene, solve::answer::Impact};
/// let s = Scene::builder(q(1, 1), q(1, 1)).v0(q(3, 1)).rod_before(q(1, 1), q(0, 1), q(0, 1)).build()?;
/// let impact = Impact::of(&s);
/// let after = &impact.oblique.as_ref().expect("a moving rod is oblique").after;
/// // At rest with v0 = 2: v = 6/5, V = 4/5, omega = 12/5; add the drift 1 to the velocities.
/// assert_eq!((&after.v, &after.rod.v, &after.rod.omega), (&q(11, 5), &q(9, 5), &q(12, 5)));
/// assert!(impact.laws_hold);
/// # Ok::<(), rodimpact::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Impact {
    /// The normal problem's velocities, energies, pivot impulse and residuals: the scene's own
    /// for the paper's scene; for an oblique one the paper's scene at the approach speed
    /// ([`Scene::normal_problem`]), whose velocities are relative to the rod's before.
    pub outcome: Outcome<Q>,
    /// The whole impact of an oblique or frictional scene (both axes, the contact mode, the
    /// disc's spin, the rod's motion before), `None` for the paper's scene.
    pub oblique: Option<ObliqueOutcome<Q>>,
    /// Every conservation law that applies holds exactly (for an oblique scene also the
    /// energy loss equal to its closed forms).
    pub laws_hold: bool,
}

impl Impact {
    /// Solves `scene`'s impact exactly: the normal problem by the fraction-free route, then
    /// the completion along the rod when the scene is oblique.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, scene::Scene, solve::answer::Impact};
    /// let s = Scene::builder(q(1, 1), q(1, 1)).build()?;
    /// let impact = Impact::of(&s);
    /// assert_eq!(impact.outcome.after.omega, q(6, 5));
    /// assert!(impact.oblique.is_none() && impact.laws_hold);
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn of(scene: &Scene) -> Impact {
        match scene.oblique() {
            None => Impact::normal(scene),
            Some(o) => Impact::completed(scene, o),
        }
    }

    /// [`Impact::of`] answered on both axes even for the paper's scene (its motion along the
    /// rod then stays zero): what a table with columns along the rod prints for every row.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, scene::Scene, solve::answer::Impact};
    /// let plain = Scene::builder(q(1, 1), q(1, 1)).build()?;
    /// let both = Impact::on_both_axes(&plain);
    /// let o = both.oblique.as_ref().expect("always answered along the rod");
    /// assert_eq!((&o.after.rod.omega, &o.after.vt, &o.tangential_impulse), (&q(6, 5), &q(0, 1), &q(0, 1)));
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn on_both_axes(scene: &Scene) -> Impact {
        let at_rest = crate::scene::Oblique::default();
        Impact::completed(scene, scene.oblique().unwrap_or(&at_rest))
    }

    /// The normal problem solved, then completed along the rod with the oblique part `o`.
    fn completed(scene: &Scene, o: &crate::scene::Oblique) -> Impact {
        let normal = Impact::normal(&scene.normal_problem());
        let done = complete_exactly(scene, o, &normal.outcome.after);
        Impact {
            laws_hold: normal.laws_hold && done.residuals.all_zero(),
            outcome: normal.outcome,
            oblique: Some(done),
        }
    }

    /// The paper's scene (no oblique part) solved by the fraction-free route.
    fn normal(scene: &Scene) -> Impact {
        let solved = fraction_free(scene);
        let laws_hold = solved.laws_hold == Some(true);
        Impact {
            outcome: outcome_exactly(scene, solved),
            oblique: None,
            laws_hold,
        }
    }

    /// The contact mode when friction acts (`None` without friction or for the paper's scene).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, scene::Scene, impact::Mode, solve::answer::Impact};
    /// let s = Scene::builder(q(1, 1), q(1, 1)).v0t(q(1, 1)).mu(q(1, 2)).build()?;
    /// assert_eq!(Impact::of(&s).contact(), Some(Mode::Slide { forward: true }));
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn contact(&self) -> Option<Mode> {
        self.oblique.as_ref().and_then(|o| o.contact)
    }
}

/// The whole answer to a scene: its [`Impact`], the normal impulse on the rod, and the
/// optimum a* with omega_max and the paper's form of omega(a) where they apply.
///
/// # Examples
/// ```
/// use rodimpact::prelude::*;
/// let s = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).v0t(q(1, 1)).mu(q(1, 4)).build()?;
/// let answer = Answer::of(&s);
/// let o = answer.impact.oblique.as_ref().expect("oblique");
/// // Friction along the rod never changes the spin (X27): omega is the paper's 12/11
/// // (J = 2/(1/m + 1/M + a^2/I) = 8/11, omega = J a/I); sticking needs |u_t|/(k_t J) = 11/16.
/// assert_eq!(o.after.rod.omega, q(12, 11));
/// assert_eq!(answer.mu_star(), Some(q(11, 16)));
/// assert_eq!(answer.optimum.expect("rod at rest").squared, q(2, 3));
/// # Ok::<(), rodimpact::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Answer {
    /// The scene answered.
    pub scene: Scene,
    /// The impact: velocities, energies, impulses, residuals and, when oblique, both axes.
    pub impact: Impact,
    /// The normal impulse J of the projectile on the rod, m (approach - v) of the normal
    /// problem.
    pub impulse: Q,
    /// a*, its placement and the exact maximum of omega; `None` when the rod turns before the
    /// impact (the approach speed then depends on a).
    pub optimum: Option<Optimum>,
    /// The paper's form of omega(a) for the normal problem (`omega = K x/(b^2 + c^2 x^2)`)
    /// and whether it was verified as an identity in a; present with the optimum.
    pub paper_form: Option<(PaperForm, bool)>,
}

impl Answer {
    /// Answers `scene` completely and exactly.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, scene::Scene, solve::answer::Answer};
    /// let answer = Answer::of(&Scene::builder(q(1, 1), q(3, 1)).pivot(q(-1, 1)).e(q(0, 1)).build()?);
    /// // I_p = I + M p^2 = 4, J = 1/(1/m + (a - p)^2/I_p) = 1/2, omega = J (a - p)/I_p = 1/4,
    /// // V = -omega p = 1/4: the pivot pushes with M V - J = 1/4.
    /// assert_eq!(answer.impact.outcome.pivot_impulse, Some(q(1, 4)));
    /// assert_eq!(answer.impulse, q(1, 2));
    /// assert!(answer.laws_hold());
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn of(scene: &Scene) -> Answer {
        let impact = Impact::of(scene);
        let normal = scene.normal_problem();
        let impulse = impact.outcome.impulse(&normal.params());
        let optimum = optimum(scene);
        let paper_form = optimum.as_ref().map(|_| {
            let form = PaperForm::of(&normal);
            let verified = form.verify(&normal);
            (form, verified)
        });
        Answer {
            scene: scene.clone(),
            impact,
            impulse,
            optimum,
            paper_form,
        }
    }

    /// Whether every conservation law that applies holds exactly.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, scene::Scene, solve::answer::Answer};
    /// assert!(Answer::of(&Scene::builder(q(2, 7), q(5, 3)).e(q(1, 3)).build()?).laws_hold());
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn laws_hold(&self) -> bool {
        self.impact.laws_hold
    }

    /// The friction coefficient at which the contact just sticks, mu* = |Jt_stick|/J, when
    /// friction acts.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, scene::Scene, solve::answer::Answer};
    /// let plain = Answer::of(&Scene::builder(q(1, 1), q(1, 1)).build()?);
    /// assert_eq!(plain.mu_star(), None);
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn mu_star(&self) -> Option<Q> {
        let o = self.impact.oblique.as_ref()?;
        o.contact.map(|_| o.mu_star())
    }
}

/// [`Solved::outcome`] (energies, pivot impulse, residuals) over Q, worked as
/// [`complete_exactly`] works: two kinetic energies over reduced rationals were most of an
/// oblique batch row's normal problem.
fn outcome_exactly(scene: &Scene, solved: Solved<Q>) -> Outcome<Q> {
    fn on_words<T: UnreducedInt>(scene: &Scene, solved: &Solved<Q>) -> Option<Outcome<Q>> {
        // Lifted inside `within`, which clears the overflow flag as it starts.
        within(|| {
            let lifted = Solved {
                route: solved.route,
                after: solved.after.as_ref().map(Unreduced::<T>::from_rational),
                laws_hold: solved.laws_hold,
            };
            lifted.outcome(&scene.params())
        })
        .map(|done| done.map(Unreduced::to_q))
    }
    on_words::<I256>(scene, &solved)
        .or_else(|| on_words::<Wide>(scene, &solved))
        .unwrap_or_else(|| solved.outcome(&scene.params()))
}

/// [`oblique::complete`] over Q, worked on unreduced fractions of 256-bit, else 512-bit,
/// integers and reduced once at the end: the same exact values and decisions (every comparison
/// is a cross-multiplication) without a GCD per operation, which was 80 % of an oblique batch
/// row. Over Q itself when a value leaves 512 bits.
fn complete_exactly(
    scene: &Scene,
    o: &crate::scene::Oblique,
    response: &Motion<Q>,
) -> ObliqueOutcome<Q> {
    complete_in::<I256>(scene, o, response)
        .map(|done| done.map(Unreduced::to_q))
        .or_else(|| complete_in::<Wide>(scene, o, response).map(|done| done.map(Unreduced::to_q)))
        .unwrap_or_else(|| complete_over_q(scene, o, response))
}

/// The paper's scene `scene` (an oblique scene's normal problem) solved by the fraction-free
/// route, with its laws checked.
fn fraction_free(scene: &Scene) -> Solved<Q> {
    super::with::<Q>(scene, Route::FractionFree)
        .expect("the fraction-free route takes every paper scene in Q")
}

/// [`oblique::complete`] over Q itself: the last resort of the fixed widths.
fn complete_over_q(
    scene: &Scene,
    o: &crate::scene::Oblique,
    response: &Motion<Q>,
) -> ObliqueOutcome<Q> {
    oblique::complete(&scene.params(), &o.params(), response.clone(), None)
        .expect("Q decides stick or slide, and every mass is positive")
}

/// [`oblique::complete`] of `scene` with the oblique part `o` and the normal problem's
/// answer `response`, over unreduced fractions of `T`; `None` when a value leaves `T`'s width
/// on the way.
fn complete_in<T: UnreducedInt>(
    scene: &Scene,
    o: &crate::scene::Oblique,
    response: &Motion<Q>,
) -> Option<ObliqueOutcome<Unreduced<T>>> {
    // Lifted inside `within`, which clears the overflow flag as it starts.
    within(|| {
        let response = response.as_ref().map(Unreduced::<T>::from_rational);
        oblique::complete(&scene.params(), &o.params(), response, None)
    })?
    .ok()
}

/// An oblique scene's exact answer as a batch's engine row writes and compares it: each value
/// reduced on words, with no rational built.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct AfterOnWords {
    /// The motion after the impact: sign, numerator and denominator of each velocity.
    pub(crate) after: oblique::State<(bool, U256, U256)>,
    /// The tangential impulse Jt, as the velocities.
    pub(crate) tangential_impulse: (bool, U256, U256),
    /// Stick or slide, when friction acts.
    pub(crate) contact: Option<Mode>,
    /// [`Impact::laws_hold`].
    pub(crate) laws_hold: bool,
}

impl AfterOnWords {
    /// [`Impact::on_both_axes`] of `scene` as far as the motion after, Jt, the contact and
    /// `laws_hold` go, and by the same work (the normal problem by the fraction-free route,
    /// completed by [`oblique::complete`] on unreduced fractions of 128, 256, else 512-bit
    /// integers, else over Q), without what a batch row does not write: the normal problem's
    /// energies and residuals, and a rational for every number of the outcome. `None` when a
    /// value passes 256 bits reduced.
    ///
    /// The batch's oblique engine row ([`crate::batch`]) reads its answers here; the general
    /// row reads [`Impact::on_both_axes`], and the tests hold the two to the same lines.
    pub(crate) fn of(scene: &Scene) -> Option<AfterOnWords> {
        let normal = fraction_free(&scene.normal_problem());
        let normal_laws_hold = normal.laws_hold == Some(true);
        let at_rest = crate::scene::Oblique::default();
        let o = scene.oblique().unwrap_or(&at_rest);
        let response = &normal.after;
        fn on_words<T: FixedInt>(
            scene: &Scene,
            o: &crate::scene::Oblique,
            response: &Motion<Q>,
            normal_laws_hold: bool,
        ) -> Option<Option<AfterOnWords>> {
            let done = complete_in::<T>(scene, o, response)?;
            Some(AfterOnWords::reduced(
                done,
                normal_laws_hold,
                Unreduced::reduced_words,
            ))
        }
        on_words::<i128>(scene, o, response, normal_laws_hold)
            .or_else(|| on_words::<I256>(scene, o, response, normal_laws_hold))
            .or_else(|| on_words::<Wide>(scene, o, response, normal_laws_hold))
            .unwrap_or_else(|| {
                let done = complete_over_q(scene, o, response);
                AfterOnWords::reduced(done, normal_laws_hold, |x| U256::parts_of(&x))
            })
    }

    /// The oblique outcome `done` as the batch writes it, each value on words by `words`
    /// (reduced); `laws_hold` when `normal_laws_hold` (the normal problem's, as the
    /// fraction-free route checked them) and every residual of `done` is zero. `None` when a
    /// value passes 256 bits.
    pub(crate) fn reduced<F: Field>(
        done: ObliqueOutcome<F>,
        normal_laws_hold: bool,
        words: impl Fn(F) -> Option<(bool, U256, U256)>,
    ) -> Option<AfterOnWords> {
        let laws_hold = normal_laws_hold && done.residuals.all_zero();
        let after = done.after;
        Some(AfterOnWords {
            after: oblique::State {
                v: words(after.v)?,
                vt: words(after.vt)?,
                spin: match after.spin {
                    Some(spin) => Some(words(spin)?),
                    None => None,
                },
                rod: crate::scene::RodMotion {
                    v: words(after.rod.v)?,
                    vt: words(after.rod.vt)?,
                    omega: words(after.rod.omega)?,
                },
            },
            tangential_impulse: words(done.tangential_impulse)?,
            contact: done.contact,
            laws_hold,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::q;
    use proptest::prelude::*;

    fn ratio() -> impl Strategy<Value = Q> {
        (-40i64..40, 1i64..12).prop_map(|(n, d)| q(n, d))
    }

    /// The fixed-width completions are the reduced rationals', value for value.
    fn agree(s: &Scene) {
        let normal = super::super::with::<Q>(&s.normal_problem(), Route::FractionFree).unwrap();
        let slow = normal.clone().outcome(&s.normal_problem().params());
        assert_eq!(outcome_exactly(&s.normal_problem(), normal), slow);
        if let Some(o) = s.oblique() {
            let want =
                oblique::complete(&s.params(), &o.params(), slow.after.clone(), None).unwrap();
            assert_eq!(complete_exactly(s, o, &slow.after), want);
        }
        agree_on_words(s);
    }

    /// The answer on words is the rationals', value for value; none only when a value
    /// passes 256 bits reduced.
    fn agree_on_words(s: &Scene) {
        let full = Impact::on_both_axes(s);
        let done = full.oblique.as_ref().expect("answered on both axes");
        let a = &done.after;
        let rationals = [
            Some(&a.v),
            Some(&a.vt),
            a.spin.as_ref(),
            Some(&a.rod.v),
            Some(&a.rod.vt),
            Some(&a.rod.omega),
            Some(&done.tangential_impulse),
        ];
        let wanted: Option<Vec<_>> = rationals
            .into_iter()
            .flatten()
            .map(U256::parts_of)
            .collect();
        let Some(w) = AfterOnWords::of(s) else {
            assert!(wanted.is_none(), "a value passes 256 bits");
            return;
        };
        let got = [
            Some(w.after.v),
            Some(w.after.vt),
            w.after.spin,
            Some(w.after.rod.v),
            Some(w.after.rod.vt),
            Some(w.after.rod.omega),
            Some(w.tangential_impulse),
        ];
        assert_eq!(Some(got.into_iter().flatten().collect()), wanted);
        assert_eq!((w.contact, w.laws_hold), (done.contact, full.laws_hold));
    }

    proptest! {
        #[test]
        fn completions_on_words_are_the_rationals(
            m in 1i64..9, big_m in 1i64..9, huge: bool, a in ratio(), e in 0i64..=4, v0t in ratio(),
            mu in 0i64..6, disc in prop::option::of((1i64..5, ratio())),
            before in prop::option::of((ratio(), ratio(), ratio())), pivot in prop::option::of(ratio()),
        ) {
            // A rod of 10^80/7 passes 256 bits in the scene itself: the 512-bit and then the
            // rational fallbacks answer (the regression test below covers an answer that
            // passes 256 bits while its scene does not).
            let big_m = if huge { q(big_m, 7) * q(10, 1).pow(80) } else { q(big_m, 1) };
            let mut b = Scene::builder(q(m, 1), big_m)
                .a(a / q(40, 1))
                .e(q(e, 4))
                .v0t(v0t)
                .mu(q(mu, 4));
            if let Some((r, spin)) = disc {
                b = b.disc(q(r, 20), spin);
            }
            if let Some((v, vt, omega)) = before {
                b = b.rod_before(v, vt, omega);
            }
            if let Some(p) = pivot {
                b = b.pivot(p / q(40, 1));
            }
            if let Ok(s) = b.build() {
                agree(&s);
            }
        }
    }

    #[test]
    fn a_normal_answer_wider_than_its_scene_is_caught_as_it_is_lifted() {
        // A fuzzed engine row: the scene fits 256 bits, the normal answer (a 15-digit a over a
        // 10^60 rod) does not, so lifting it overflows before any arithmetic does.
        let number = |text: &str| crate::number::parse(text).unwrap();
        let s = Scene::builder(
            q(5, 68),
            number("1000000000000000000000000000000000000000000000000000000000000/7"),
        )
        .a(number("0.148857829090292"))
        .v0(q(3, 2))
        .rod(crate::scene::RodInertia::Gyration(q(3, 10)))
        .v0t(q(4, 1))
        .mu(q(3, 10))
        .disc(q(1, 20), number("2.357439029228876"))
        .build()
        .unwrap();
        agree(&s);
    }

    #[test]
    fn completions_past_512_bits_are_the_rationals() {
        // Masses of 200 digits leave every fixed width: Q answers, the same.
        let huge = q(10, 1).pow(200) / q(3, 1);
        let s = Scene::builder(huge.clone(), q(7, 1) * &huge)
            .a(q(1, 3))
            .v0t(q(2, 1))
            .mu(q(1, 5))
            .build()
            .unwrap();
        agree(&s);
    }
}
