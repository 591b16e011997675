//! A claim as a statement in real arithmetic: the physics of a scene (the balance equations in
//! fresh unknowns, the contact law, the domain), the hypotheses the claim adds, and what is
//! concluded. Each claim file writes its own ([`Entry::export`](super::super::Entry)).

/// How a claim is exported for an independent checker.
#[derive(Debug, Clone, Copy)]
pub enum Export {
    /// Stated in nonlinear real arithmetic.
    Stated(Statement),
    /// Not statable so; the reason.
    Unstated(&'static str),
}

/// A claim in nonlinear real arithmetic.
#[derive(Debug, Clone, Copy)]
pub struct Statement {
    /// The scene whose physics is assumed.
    pub scene: Setting,
    /// The impacts considered (the same scene struck at each point, with its own unknowns).
    pub impacts: &'static [StrikePoint],
    /// Hypotheses every check shares, in the statement language.
    pub given: &'static [&'static str],
    /// The checks, in order.
    pub checks: &'static [Check],
    /// The part of the claim the checks leave out, and why (empty when they state it whole).
    pub outside: &'static str,
}

/// One impact of the scene: where it strikes and the suffix of its unknowns (`v_1`, `V_1`,
/// `omega_1` for the tag `1`; `v`, `V`, `omega` for the empty tag).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct StrikePoint {
    /// The point struck: the signed distance from the rod's centre (from the pivot for a
    /// pivoted rod), an expression.
    pub at: &'static str,
    /// The suffix of the unknowns.
    pub tag: &'static str,
}

/// The single impact at `a` with the unknowns `v`, `V`, `omega`.
pub const AT_A: &[StrikePoint] = &[StrikePoint { at: "a", tag: "" }];

/// The body struck and how its moment of inertia is given.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rod {
    /// A free rod, centre of mass at its centre, moment of inertia `I > 0` about it.
    Free,
    /// A free uniform rod of length `2l`: `I = M l^2/3`.
    Uniform,
    /// A free rod with radius of gyration `r > 0`: `I = M r^2`.
    Gyration,
    /// The ideal dumbbell, all mass at the ends `±l`: `I = M l^2`.
    Dumbbell,
    /// A rod on a fixed pivot: moment `Ip > 0` about the pivot, centre of mass at `h` from it,
    /// struck at the distance given by the impact.
    Pivot,
    /// No body: a statement of pure algebra.
    Nothing,
}

/// The form of the balance equations.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BalanceForm {
    /// Conservation of the system's linear momentum and of its angular momentum about the
    /// fixed point at the rod's centre (about the pivot for a pivoted rod).
    Momentum,
    /// Each body's impulse-momentum law with the contact impulse `J` as a further unknown
    /// (and the pivot's impulse `P` for a pivoted rod).
    Impulses,
}

/// The contact law closing the equations.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ExportLaw {
    /// Newton's law with `e = 1`: the struck point separates at `v0`.
    Elastic,
    /// Newton's law with a restitution coefficient `0 <= e <= 1`.
    Restitution,
    /// Sticking: the projectile moves with the struck point (`e = 0`).
    Sticking,
    /// Conservation of kinetic energy instead of a contact law.
    Energy,
}

/// The friction law along the rod for an oblique impact (the projectile also moving along the
/// rod, `v0t`), with the tangential impulse `Jt` on the rod.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Friction {
    /// No law: any tangential impulse `Jt` (a claim that holds for every friction law).
    Any,
    /// The contact sticks: the disc's contact point ends moving with the rod's along the rod.
    Stick,
    /// The contact slides forward (the slip along +y): Coulomb's `Jt = mu_f J`; sliding
    /// backward is its mirror image.
    Slide,
}

/// The oblique impact of issue 20: the projectile a solid disc of radius `rd >= 0` (`rd = 0`: a
/// point) spinning at `w`, moving with `v0` across and `v0t` along the rod, the rod struck at the
/// point `(d, a)` of its axis (`d = 0`), a friction law, and the rod at rest or drifting with
/// `(V0, Vt0)` without turning.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ObliqueSetting {
    /// The law along the rod.
    pub friction: Friction,
    /// Whether the rod drifts with `(V0, Vt0)` before the impact.
    pub moving: bool,
}

/// The physics assumed: body, balance and contact law.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Setting {
    /// The body struck.
    pub rod: Rod,
    /// The balance equations.
    pub balance: BalanceForm,
    /// The contact law.
    pub law: ExportLaw,
    /// The motion along the rod and its friction, for an oblique impact.
    pub oblique: Option<ObliqueSetting>,
}

impl Setting {
    /// The scene with the momentum balances.
    pub const fn new(rod: Rod, law: ExportLaw) -> Setting {
        Setting {
            rod,
            balance: BalanceForm::Momentum,
            law,
            oblique: None,
        }
    }

    /// The oblique scene with `friction` along the rod, written with the impulses of each body
    /// (the tangential impulse is one of the unknowns).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::export::{BalanceForm, Friction, ExportLaw, Rod, Setting};
    /// let scene = Setting::new(Rod::Free, ExportLaw::Restitution).oblique(Friction::Stick);
    /// assert_eq!(scene.balance, BalanceForm::Impulses);
    /// assert!(!scene.oblique.unwrap().moving);
    /// ```
    pub const fn oblique(self, friction: Friction) -> Setting {
        Setting {
            balance: BalanceForm::Impulses,
            oblique: Some(ObliqueSetting {
                friction,
                moving: false,
            }),
            ..self
        }
    }

    /// The oblique scene with the rod drifting with `(V0, Vt0)` before the impact (a scene
    /// without [`Setting::oblique`] stays as it is).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::export::{Friction, ExportLaw, Rod, Setting};
    /// let scene = Setting::new(Rod::Free, ExportLaw::Restitution).oblique(Friction::Any).moving();
    /// assert!(scene.oblique.unwrap().moving);
    /// ```
    pub const fn moving(self) -> Setting {
        let oblique = match self.oblique {
            Some(o) => Some(ObliqueSetting { moving: true, ..o }),
            None => None,
        };
        Setting { oblique, ..self }
    }

    /// The same scene written with the impulses of each body.
    pub const fn impulses(self) -> Setting {
        Setting {
            balance: BalanceForm::Impulses,
            ..self
        }
    }
}

/// What a check's answer means.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Expect {
    /// The conclusion holds under the hypotheses: its negation is unsatisfiable.
    Holds,
    /// A reading that fails: its negation is satisfiable under the hypotheses (the model is a
    /// counterexample).
    Fails,
    /// Some values satisfy the hypotheses and the conclusion (the model is a witness).
    Exists,
}

/// One check of a statement.
#[derive(Debug, Clone, Copy)]
pub struct Check {
    /// What is checked, in words.
    pub what: &'static str,
    /// What the answer means.
    pub expect: Expect,
    /// Hypotheses of this check alone.
    pub given: &'static [&'static str],
    /// The conclusion, in the statement language.
    pub claim: &'static str,
    /// Earlier checks (0-based) of the same statement whose conclusions, already proved, z3 may
    /// assume as lemmas: a proof split into steps that each decide fast. Each must be a
    /// `holds` check whose own hypotheses are among this one's, so the chain stays sound (the
    /// exporter refuses anything else). SymPy solves the balance equations outright and needs
    /// none.
    pub using: &'static [usize],
}

impl Check {
    /// The conclusion holds under the hypotheses.
    pub const fn holds(what: &'static str, claim: &'static str) -> Check {
        Check {
            what,
            expect: Expect::Holds,
            given: &[],
            claim,
            using: &[],
        }
    }

    /// A reading refuted: some values satisfy the hypotheses and violate `claim`.
    pub const fn fails(what: &'static str, claim: &'static str) -> Check {
        Check {
            what,
            expect: Expect::Fails,
            given: &[],
            claim,
            using: &[],
        }
    }

    /// Some values satisfy the hypotheses and `claim`.
    pub const fn exists(what: &'static str, claim: &'static str) -> Check {
        Check {
            what,
            expect: Expect::Exists,
            given: &[],
            claim,
            using: &[],
        }
    }

    /// The check with hypotheses of its own.
    pub const fn given(self, given: &'static [&'static str]) -> Check {
        Check { given, ..self }
    }

    /// The check with the conclusions of the earlier checks `using` (0-based, already proved
    /// under hypotheses this check also has) as lemmas for z3.
    pub const fn using(self, using: &'static [usize]) -> Check {
        Check { using, ..self }
    }
}

impl Statement {
    /// The statement of `checks` about one impact at `a`, with no further hypotheses.
    pub const fn new(scene: Setting, checks: &'static [Check]) -> Statement {
        Statement {
            scene,
            impacts: AT_A,
            given: &[],
            checks,
            outside: "",
        }
    }

    /// The statement about these impacts.
    pub const fn at(self, impacts: &'static [StrikePoint]) -> Statement {
        Statement { impacts, ..self }
    }

    /// The statement with hypotheses every check shares.
    pub const fn given(self, given: &'static [&'static str]) -> Statement {
        Statement { given, ..self }
    }

    /// The statement of part of the claim: `outside` says what is left out and why.
    pub const fn partly(self, outside: &'static str) -> Statement {
        Statement { outside, ..self }
    }
}
