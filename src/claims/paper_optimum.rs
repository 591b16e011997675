//! Claims C19-C31: the optimum and the totally inelastic case.
//!
//! The optimum rests on one shape: omega(a) = k a/(b^2 + c^2 a^2) once the parameters are
//! written through a positive symbol `A` standing for a* (C19, C20, C27, C30). [`Peak`] turns a
//! function of that shape into three certificates: the gap to the peak is a square over a
//! positive denominator (>= 0 everywhere), and it is strictly positive on either side.

use super::build::*;
use super::model::*;
use super::{Certificate, Claim, Decision, Entry, Formula, Group, Paper, PosExpr, Relation};
use crate::field::{RatFn, Sym};
use crate::mechanics::{Motion, angular_momentum, kinetic_energy, linear_momentum};

/// The registered claims of this part of the paper.
pub(super) const ENTRIES: &[Entry] = &[
    Entry {
        id: "C19",
        build: c19,
    },
    Entry {
        id: "C20",
        build: c20,
    },
    Entry {
        id: "C21",
        build: c21,
    },
    Entry {
        id: "C22",
        build: c22,
    },
    Entry {
        id: "C23",
        build: c23,
    },
    Entry {
        id: "C24",
        build: c24,
    },
    Entry {
        id: "C25",
        build: c25,
    },
    Entry {
        id: "C26",
        build: c26,
    },
    Entry {
        id: "C27",
        build: c27,
    },
    Entry {
        id: "C28",
        build: c28,
    },
    Entry {
        id: "C29",
        build: c29,
    },
    Entry {
        id: "C30",
        build: c30,
    },
    Entry {
        id: "C31",
        build: c31,
    },
];

// ---------------------------------------------------------------------------------------------
// Small builders.

/// `model` with `domain` substituted into its values, followed by `domain`: the single
/// simultaneous substitution that applies `model` first and then `domain`.
fn compose<'a>(model: &[(&'a str, RatFn)], domain: &[(&'a str, RatFn)]) -> Vec<(&'a str, RatFn)> {
    let mut all: Vec<(&str, RatFn)> = model.iter().map(|(s, v)| (*s, subs(v, domain))).collect();
    all.extend(domain.iter().cloned());
    all
}

// ---------------------------------------------------------------------------------------------
// The model quantities.

/// Elastic omega from the generic solver, moment of inertia `inertia`.
fn elastic_omega(inertia: RatFn) -> RatFn {
    motion(&free_rod(inertia, k(1, 1))).omega
}

/// Elastic omega of the uniform rod (I = M l^2/3) from the generic solver.
fn uniform_omega() -> RatFn {
    elastic_omega(uniform_inertia())
}

/// `I = A^2 m M/(M + m)`: the general rod written through A, a positive symbol for a*.
fn inertia_through_a_star() -> RatFn {
    let (m, big_m) = (sym("m"), sym("M"));
    sq(&sym("A")) * &m * &big_m / (big_m.clone() + &m)
}

/// `M = 3 m A^2/l^2 - m`: the uniform rod's mass written through A, a positive symbol for a*.
/// Every m, M, l > 0 is reached, with A = sqrt((M + m)/(3m)) l.
fn mass_through_a_star() -> RatFn {
    let (m, l) = (sym("m"), sym("l"));
    k(3, 1) * &m * &sq(&sym("A")) / sq(&l) - &m
}

/// The claim `printed = A^2` once the model is written through A: A is the paper's a*.
fn a_star_link(what: &str, printed: &Formula, model: (&str, RatFn)) -> Certificate {
    let (name, value) = model;
    Certificate::identity_at(
        format!("the printed {what} equals A^2 when {name} = {value}, so A is the paper's a*"),
        printed.clone(),
        Formula::sym("A").pow(2),
        &[(name, value.clone())],
    )
}

/// `2 v0 a/(a*^2 + a^2)`, the paper's shape of omega, for the given `a*^2`.
fn peak_shape(a_star_squared: Formula) -> Formula {
    let a = Formula::sym("a");
    Formula::int(2) * &Formula::sym("v0") * &a / &(a_star_squared + &a.pow(2))
}

/// The composite body of the sticking model, from first principles (rod centre at y = 0,
/// projectile stuck at y = a).
struct Sticking {
    /// The composite's centre of mass.
    y_c: RatFn,
    /// Its velocity: total momentum over total mass.
    v_c: RatFn,
    /// Moment of inertia about y_c (parallel axes).
    i_c: RatFn,
    /// Angular momentum about y_c (taken before the impact) over I_c.
    omega: RatFn,
}

fn sticking(inertia: RatFn) -> Sticking {
    let p = free_rod(inertia.clone(), k(0, 1));
    let (m, big_m, a) = (sym("m"), sym("M"), sym("a"));
    let total = big_m.clone() + &m;
    let y_c = m.clone() * &a / total.clone();
    let before = Motion::before(sym("v0"));
    let v_c = linear_momentum(&p, &before) / total;
    let i_c = inertia + &(big_m * &sq(&y_c)) + &(m * &sq(&(a - &y_c)));
    let omega = angular_momentum(&p, &before, &y_c) / i_c.clone();
    Sticking {
        y_c,
        v_c,
        i_c,
        omega,
    }
}

/// `mu = m M/(M + m)`.
fn reduced_mass() -> RatFn {
    let (m, big_m) = (sym("m"), sym("M"));
    m.clone() * &big_m / (big_m + &m)
}

// ---------------------------------------------------------------------------------------------
// The peak of k x/(b^2 + c^2 x^2).

/// A function `f` of the symbol `x` that, after the substitution `model`, has the shape
/// `k x/(b^2 + c^2 x^2)` with b, c > 0 (c = 1 when `c` is `None`).
struct Peak {
    /// The function's name in titles (`f`, `omega`).
    name: &'static str,
    /// The function, before the model substitution.
    f: RatFn,
    x: &'static str,
    /// The name of the peak in titles (`b/c`, `a*`).
    peak_name: &'static str,
    b: &'static str,
    c: Option<&'static str>,
    /// The factor k, visibly positive.
    k: PosExpr,
    /// Writes the parameters through b and c (empty when f already has the shape).
    model: Vec<(&'static str, RatFn)>,
    /// Symbols positive on the domain besides b, c, x and the slack t.
    positive: Vec<&'static str>,
}

impl Peak {
    fn c_value(&self) -> RatFn {
        self.c.map_or(k(1, 1), sym)
    }

    /// `factors` times c^`power` (nothing when c = 1), as a product.
    fn times_c(&self, mut factors: Vec<PosExpr>, power: usize) -> PosExpr {
        factors.extend(self.c.iter().cycle().take(power).map(|c| ps(c)));
        PosExpr::Product(factors)
    }

    /// f(b/c) - f(x).
    fn gap(&self) -> RatFn {
        let peak = sym(self.b) / self.c_value();
        subs(&self.f, &[(self.x, peak)]) - &self.f
    }

    fn domain(&self, extra: &[&'static str]) -> Vec<&'static str> {
        let mut all = self.positive.clone();
        all.push(self.b);
        all.extend(self.c);
        all.extend_from_slice(extra);
        all
    }

    fn certificate(
        &self,
        title: String,
        strict: bool,
        domain: &[(&'static str, RatFn)],
        signs: (&[&'static str], &[&str]),
        form: PosExpr,
    ) -> Certificate {
        let substitutions = compose(&self.model, domain);
        positive(
            title,
            self.gap(),
            strict,
            &substitutions,
            &self.domain(signs.0),
            signs.1,
            form,
        )
    }

    /// k c^2 t^2/(2 b c (b^2 + (c x)^2)) with the given b and c x (both visibly signed).
    fn gap_form(&self, numerator: PosExpr, b: PosExpr, cx: PosExpr) -> PosExpr {
        PosExpr::quotient(
            numerator,
            self.times_c(
                vec![pc(2, 1), b.clone(), sum([prod([b.clone(), b]), cx])],
                1,
            ),
        )
    }

    /// k (c x - b)^2/(2 b c (b^2 + c^2 x^2)) >= 0 for every x.
    fn everywhere(&self) -> Certificate {
        let cx = self.c_value() * &sym(self.x);
        let form = self.gap_form(
            prod([self.k.clone(), PosExpr::Square(cx.clone() - &sym(self.b))]),
            ps(self.b),
            PosExpr::Square(cx),
        );
        let (n, x, p) = (self.name, self.x, self.peak_name);
        self.certificate(
            format!(
                "{n}({p}) - {n}({x}) = a square over a positive denominator: >= 0 for every {x}"
            ),
            false,
            &[],
            (&[], &[]),
            form,
        )
    }

    /// Right of the peak, x = b/c + t: k c^2 t^2/(2 b c (b^2 + (b + c t)^2)) > 0.
    fn above(&self) -> Certificate {
        let x = sym(self.b) / self.c_value() + &sym("t");
        let shifted = sum([ps(self.b), self.times_c(vec![ps("t")], 1)]);
        let form = self.gap_form(
            self.times_c(vec![self.k.clone(), ps("t"), ps("t")], 2),
            ps(self.b),
            prod([shifted.clone(), shifted]),
        );
        let (n, x_name, p) = (self.name, self.x, self.peak_name);
        self.certificate(
            format!("{n}({p}) - {n}({x_name}) > 0 right of the peak: {x_name} = {p} + t, t > 0"),
            true,
            &[(self.x, x)],
            (&["t"], &[]),
            form,
        )
    }

    /// Left of the peak, 0 <= x < b/c, i.e. b = c (x + t): k c^2 t^2/(2 B c (B^2 + c^2 x^2)) > 0
    /// with B = c (x + t).
    fn below(&self) -> Certificate {
        let big_b = self.times_c(vec![sum([ps(self.x), ps("t")])], 1);
        let form = self.gap_form(
            self.times_c(vec![self.k.clone(), ps("t"), ps("t")], 2),
            big_b,
            self.times_c(vec![ps(self.x), ps(self.x)], 2),
        );
        let b = self.c_value() * &(sym(self.x) + &sym("t"));
        let (n, x_name, p) = (self.name, self.x, self.peak_name);
        self.certificate(
            format!(
                "{n}({p}) - {n}({x_name}) > 0 left of the peak: 0 <= {x_name} < {p}, {p} = {x_name} + t, t > 0"
            ),
            true,
            &[(self.b, b)],
            (&["t"], &[self.x]),
            form,
        )
    }

    fn certificates(&self) -> Vec<Certificate> {
        vec![self.everywhere(), self.above(), self.below()]
    }
}

/// omega(a) of a general rod written through A (I = A^2 m M/(M + m)), scaled by `k`.
fn omega_peak(omega: RatFn, k: PosExpr) -> Peak {
    Peak {
        name: "omega",
        f: omega,
        x: "a",
        peak_name: "a*",
        b: "A",
        c: None,
        k,
        model: vec![("I", inertia_through_a_star())],
        positive: vec!["m", "M", "v0"],
    }
}

// ---------------------------------------------------------------------------------------------
// The uniform rod's threshold.

/// omega(a + t) - omega(a) > 0 for 0 <= a < a + t <= l when M = threshold m + q, q > 0, for
/// omega = scale m a v0/((M + m) l^2 + 3 m a^2) (scale 6 elastic, 3 sticking).
fn increasing_on_rod(paper: &Paper, omega: &RatFn, scale: i64, what: &str) -> Certificate {
    let (a, t, s) = (sym("a"), sym("t"), sym("s"));
    let expr = subs(omega, &[("a", a.clone() + &t)]) - omega;
    let l = sum([ps("a"), ps("t"), ps("s")]);
    let three_m = prod([pc(3, 1), ps("m")]);
    let slack = sum([
        prod([ps("t"), ps("t")]),
        prod([ps("s"), ps("s")]),
        prod([ps("a"), ps("t")]),
        prod([pc(2, 1), ps("a"), ps("s")]),
        prod([pc(2, 1), ps("t"), ps("s")]),
    ]);
    let denominator = |x: PosExpr| {
        sum([
            prod([sum([three_m.clone(), ps("q")]), l.clone(), l.clone()]),
            prod([three_m.clone(), x.clone(), x]),
        ])
    };
    let form = PosExpr::quotient(
        prod([
            pc(scale, 1),
            ps("m"),
            ps("v0"),
            ps("t"),
            sum([
                prod([three_m.clone(), slack]),
                prod([ps("q"), l.clone(), l.clone()]),
            ]),
        ]),
        prod([denominator(ps("a")), denominator(sum([ps("a"), ps("t")]))]),
    );
    positive(
        format!(
            "{what}: omega(a + t) - omega(a) > 0 for 0 <= a < a + t <= l (l = a + t + s, s >= 0) \
             when M = 2m + q, q > 0"
        ),
        expr,
        true,
        &[
            ("l", a + &t + &s),
            ("M", paper.threshold.value().clone() * &sym("m") + &sym("q")),
        ],
        &["m", "q", "t", "v0"],
        &["a", "s"],
        form,
    )
}

/// l^2 - a*^2 (uniform rod) for M <= 2m written as 2m = M + q, i.e. m = (M + q)/threshold:
/// it equals 2 q l^2/(3 (M + q)), >= 0 for q >= 0 and > 0 for q > 0 (`strict`).
fn room_at_the_end(paper: &Paper, strict: bool) -> Certificate {
    let expr = sq(&sym("l")) - &a_star_squared(&uniform_inertia());
    let m = (sym("M") + &sym("q")) / paper.threshold.clone();
    let form = PosExpr::quotient(
        prod([pc(2, 1), ps("q"), ps("l"), ps("l")]),
        prod([pc(3, 1), sum([ps("M"), ps("q")])]),
    );
    let (relation, q_sign, domain): (&str, &str, (&[&str], &[&str])) = if strict {
        ("> 0", "q > 0", (&["M", "l", "q"], &[]))
    } else {
        (">= 0", "q >= 0", (&["M", "l"], &["q"]))
    };
    positive(
        format!("l^2 - a*^2 {relation} when 2m = M + q, {q_sign} (uniform rod)"),
        expr,
        strict,
        &[("m", m.into())],
        domain.0,
        domain.1,
        form,
    )
}

/// `2 v0 (X - a^2)/(X + a^2)^2`: the slope of 2 v0 a/(X + a^2), which vanishes at a^2 = X.
fn slope_with_peak_at(x2: &RatFn) -> Formula {
    let a2 = Formula::sym("a").pow(2);
    Formula::int(2) * &Formula::sym("v0") * &(Formula::from(x2) - &a2)
        / &(Formula::from(x2) + &a2).pow(2)
}

/// d omega/da of the elastic uniform rod (generic solver) with M = `mass`.
fn uniform_slope(mass: &RatFn) -> RatFn {
    subs(&uniform_omega(), &[("M", mass.clone())]).derivative(Sym::new("a"))
}

/// The solver's slope at M = `mass` vanishes exactly at a^2 = `x2` (and changes sign there).
fn stationary_at(mass: &RatFn, mass_name: &str, x2: &RatFn) -> Certificate {
    Certificate::identity_at(
        format!(
            "at M = {mass_name}, d omega/da of the solver's omega (uniform rod) = \
             2 v0 ({x2} - a^2)/({x2} + a^2)^2: positive below, zero at, negative above a^2 = {x2}"
        ),
        Formula::named("omega'", uniform_slope(&sym("M"))),
        slope_with_peak_at(x2),
        &[("M", mass.clone())],
    )
}

// ---------------------------------------------------------------------------------------------
// The claims.

fn c19(_paper: &Paper) -> Claim {
    let (b, c, x) = (sym("b"), sym("c"), sym("x"));
    let f = x.clone() / (sq(&b) + &(sq(&c) * &sq(&x)));
    let peak = Peak {
        name: "f",
        f: f.clone(),
        x: "x",
        peak_name: "b/c",
        b: "b",
        c: Some("c"),
        k: pc(1, 1),
        model: vec![],
        positive: vec![],
    };
    let value = Certificate::identity_at(
        "f(b/c) = 1/(2bc)",
        Formula::named("f", f.clone()),
        Formula::int(1) / &(Formula::int(2) * &b * &c),
        &[("x", b.clone() / c.clone())],
    );
    let mut certs = vec![value];
    certs.extend(peak.certificates());
    Claim {
        id: "C19",
        location: "§optimum ¶1",
        group: Group::Optimum,
        statement: "For b, c > 0, f(x) = x/(b^2 + c^2 x^2) has its unique maximum on x > 0 at x = b/c, with value 1/(2bc)",
        formal: "For b, c > 0 and f(x) = x/(b^2 + c^2 x^2): f(b/c) = 1/(2bc); f(b/c) - f(x) = \
                 (c x - b)^2/(2bc(b^2 + c^2 x^2)) >= 0 for every real x; and f(b/c) - f(x) > 0 both for \
                 x = b/c + t and for 0 <= x = b/c - t (t > 0). So b/c is the unique maximiser on x >= 0, \
                 a fortiori on x > 0."
            .into(),
        reason: "f(b/c) - f(x) = (cx - b)^2/(2bc(b^2 + c^2x^2)), a square over a positive denominator, \
                 strictly positive off x = b/c"
            .into(),
        decision: Decision::Proved(certs),
    }
}

fn c20(paper: &Paper) -> Claim {
    let shape = peak_shape(Formula::named("a*^2", paper.a_star_squared.clone()));
    let rewritten = Certificate::identity(
        "Eq. (omega) as printed equals 2 v0 a/(a*^2 + a^2) with the printed a*^2 = (M + m) I/(m M)",
        paper.omega.clone(),
        shape,
    );
    let link = a_star_link(
        "a*^2 = (M + m) I/(m M)",
        &paper.a_star_squared,
        ("I", inertia_through_a_star()),
    );
    let peak = omega_peak(elastic_omega(sym("I")), prod([pc(2, 1), ps("v0")]));
    let mut certs = vec![rewritten, link];
    certs.extend(peak.certificates());
    Claim {
        id: "C20",
        location: "Eq. (maximal-a-general)",
        group: Group::Optimum,
        statement: "omega = 2 v0 a/(a*^2 + a^2), so the unconstrained maximum over a > 0 is at a* = sqrt((M+m)I/(mM))",
        formal: "For m, M, I, v0 > 0: the printed Eq. (omega) equals 2 v0 a/(a*^2 + a^2) with the printed \
                 a*^2 = (M + m) I/(m M). Writing I = A^2 m M/(M + m) with A > 0 (every I > 0 is reached; \
                 the printed a*^2 is then A^2), the solver's elastic omega satisfies omega(A) - omega(a) = \
                 v0 (a - A)^2/(A (A^2 + a^2)) >= 0, strictly for every a >= 0 other than A: the maximum \
                 over a > 0 is at a = a* and nowhere else (C19 with b = a*, c = 1)."
            .into(),
        reason: "with I written through A = a*, omega(a*) - omega(a) = v0 (a - a*)^2/(a* (a*^2 + a^2)) > 0 \
                 for a != a*"
            .into(),
        decision: Decision::Proved(certs),
    }
}

fn c21(paper: &Paper) -> Claim {
    let (big_m, l) = (sym("M"), sym("l"));
    let density = big_m.clone() / (k(2, 1) * &l);
    let integral = |title: &str, power: u32, expected: RatFn| {
        Certificate::Integral(crate::claims::certificate::Integral {
            title: title.into(),
            density: density.clone(),
            var: Sym::new("y"),
            power,
            lower: -l.clone(),
            upper: l.clone(),
            expected,
        })
    };
    Claim {
        id: "C21",
        location: "Eq. (inertia-homogeneous)",
        group: Group::Optimum,
        statement: "I = M(2l)^2/12 = Ml^2/3",
        formal: "A homogeneous thin rod of mass M on -l <= y <= l has the linear density M/(2l); its moment \
                 of inertia about the perpendicular axis through the centre is the integral of \
                 (M/(2l)) y^2 over [-l, l], which equals the printed M (2l)^2/12, and that is M l^2/3."
            .into(),
        reason: "the integral of (M/(2l)) y^2 over [-l, l] is M l^2/3 = M(2l)^2/12, and the density has mass M"
            .into(),
        decision: Decision::Proved(vec![
            integral("the density M/(2l) on [-l, l] has total mass M", 0, big_m.clone()),
            integral(
                "moment of inertia about the centre: integral of (M/(2l)) y^2 = the printed M (2l)^2/12",
                2,
                paper.uniform_inertia.value().clone(),
            ),
            Certificate::identity(
                "the printed M (2l)^2/12 equals M l^2/3",
                paper.uniform_inertia.clone(),
                Formula::from(big_m) * &Formula::from(l).pow(2) / &Formula::int(3),
            ),
        ]),
    }
}

fn c22(paper: &Paper) -> Claim {
    let shape = peak_shape(Formula::named("a*^2", paper.a_star_uniform_squared.clone()));
    Claim {
        id: "C22",
        location: "Eq. (maximal-a-homogeneous)",
        group: Group::Optimum,
        statement: "a* = sqrt((M+m)/(3m)) l",
        formal: "For the uniform rod (I = M l^2/3) with m, M, l, v0 > 0: the printed a*^2 = (M + m) l^2/(3m) \
                 is Eq. (maximal-a-general) with Eq. (inertia-homogeneous) substituted, and the solver's \
                 elastic omega is 2 v0 a/(a*^2 + a^2) with exactly this a*^2, so (C20) the maximiser over \
                 a > 0 is a* = sqrt((M + m)/(3m)) l (l > 0)."
            .into(),
        reason: "the printed a*^2 = (M + m) l^2/(3m) is (M + m) I/(m M) at I = M l^2/3, and the solver's omega \
                 is 2 v0 a/(a*^2 + a^2) with it"
            .into(),
        decision: Decision::Proved(vec![
            Certificate::identity_at(
                "the printed (M + m) I/(m M) at the printed I = M (2l)^2/12 equals the printed (M + m) l^2/(3m)",
                paper.a_star_squared.clone(),
                paper.a_star_uniform_squared.clone(),
                &[("I", paper.uniform_inertia.value().clone())],
            ),
            Certificate::identity(
                "the solver's elastic omega for I = M l^2/3 equals 2 v0 a/(a*^2 + a^2) with the printed \
                 a*^2 = (M + m) l^2/(3m)",
                Formula::named("omega", uniform_omega()),
                shape,
            ),
        ]),
    }
}

fn c23(paper: &Paper) -> Claim {
    // Independent derivation: a*^2 = I (M + m)/(m M) with I = M l^2/3.
    let expr = a_star_squared(&uniform_inertia()) - &(sym("l") * &sym("l"));
    let threshold_mass = paper.threshold.clone() * &sym("m") + &sym("q");
    Claim {
        id: "C23",
        location: "§optimum ¶2",
        group: Group::Optimum,
        statement: "M > 2m implies a* > l (unphysical)",
        formal: "Uniform rod (I = M l^2/3), m, l > 0: if M > 2m then a*^2 - l^2 > 0, i.e. the stationary \
                 point a* = sqrt((M + m)/(3m)) l lies beyond the end of the rod."
            .into(),
        reason: "with M = 2m + q (q > 0), a*^2 - l^2 = q l^2/(3m) > 0".into(),
        decision: Decision::Proved(vec![Certificate::Positive(crate::claims::certificate::Positive {
            title: "a*^2 - l^2 > 0 for M = 2m + q, q > 0".into(),
            expr,
            strict: true,
            substitutions: vec![(Sym::new("M"), threshold_mass.into())],
            positive: vec![Sym::new("m"), Sym::new("q"), Sym::new("l")],
            nonnegative: vec![],
            form: PosExpr::quotient(
                PosExpr::product([PosExpr::sym("q"), PosExpr::sym("l"), PosExpr::sym("l")]),
                PosExpr::product([PosExpr::constant(3, 1), PosExpr::sym("m")]),
            ),
        })]),
    }
}

fn c24(paper: &Paper) -> Claim {
    Claim {
        id: "C24",
        location: "§optimum ¶2",
        group: Group::Optimum,
        statement: "If M > 2m, omega is strictly increasing on [0,l], so the maximum is at a = l",
        formal: "Uniform rod (I = M l^2/3), m, v0, l > 0, M = 2m + q with q > 0, elastic omega from the \
                 generic solver: for all 0 <= a1 < a2 <= l (a2 = a1 + t, l = a1 + t + s, t > 0, s >= 0), \
                 omega(a2) - omega(a1) > 0. Hence the maximum over [0, l] is at a = l and only there."
            .into(),
        reason: "with M = 2m + q and l = a + t + s, omega(a + t) - omega(a) = 6 m v0 t (3m(t^2 + s^2 + at + \
                 2as + 2ts) + q l^2)/(positive) > 0"
            .into(),
        decision: Decision::Proved(vec![increasing_on_rod(
            paper,
            &uniform_omega(),
            6,
            "elastic omega (generic solver, uniform rod)",
        )]),
    }
}

fn c25(paper: &Paper) -> Claim {
    let a2 = a_star_squared(&uniform_inertia());
    let a2_positive = positive(
        "a*^2 = (M + m) l^2/(3m) > 0, so a* = sqrt(a*^2) > 0",
        a2,
        true,
        &[],
        &["m", "M", "l"],
        &[],
        PosExpr::quotient(
            prod([sum([ps("M"), ps("m")]), ps("l"), ps("l")]),
            prod([pc(3, 1), ps("m")]),
        ),
    );
    Claim {
        id: "C25",
        location: "§optimum ¶2",
        group: Group::Optimum,
        statement: "M <= 2m implies 0 < a* <= l",
        formal: "Uniform rod (I = M l^2/3), m, M, l > 0: a*^2 = (M + m) l^2/(3m) > 0, and if M <= 2m, \
                 written 2m = M + q with q >= 0, then l^2 - a*^2 >= 0; as a*, l > 0 this is 0 < a* <= l, \
                 so a* lies on the rod (it is the maximiser over [0, l] by C20)."
            .into(),
        reason: "with 2m = M + q (q >= 0), l^2 - a*^2 = 2 q l^2/(3(M + q)) >= 0, and a*^2 > 0".into(),
        decision: Decision::Proved(vec![a2_positive, room_at_the_end(paper, false)]),
    }
}

fn c26(paper: &Paper) -> Claim {
    let mass = paper.threshold.clone() * &sym("m");
    let l2 = sq(&sym("l"));
    Claim {
        id: "C26",
        location: "§optimum ¶2",
        group: Group::Optimum,
        statement: "M = 2m gives a* = l",
        formal: "Uniform rod, m, l, v0 > 0, M = 2m: the printed a*^2 = (M + m) l^2/(3m) equals l^2, so \
                 a* = l; independently, the solver's d omega/da is 2 v0 (l^2 - a^2)/(l^2 + a^2)^2, which \
                 vanishes on a > 0 only at a = l."
            .into(),
        reason: "at M = 2m the printed a*^2 is l^2, and the solver's slope 2 v0 (l^2 - a^2)/(l^2 + a^2)^2 \
                 vanishes at a = l"
            .into(),
        decision: Decision::Proved(vec![
            Certificate::identity_at(
                "the printed a*^2 = (M + m) l^2/(3m) at M = 2m equals l^2",
                paper.a_star_uniform_squared.clone(),
                l2.clone(),
                &[("M", mass.clone().into())],
            ),
            stationary_at(&mass, "2m", &l2),
        ]),
    }
}

fn c27(paper: &Paper) -> Claim {
    let omega = uniform_omega();
    let model = ("M", mass_through_a_star());
    let peak = Peak {
        model: vec![model.clone()],
        positive: vec!["m", "v0"],
        ..omega_peak(omega.clone(), prod([pc(2, 1), ps("v0")]))
    };
    // omega(a*) - omega(l) with l = A + t: the right-of-peak form at a = l.
    let at_end = subs(&omega, &[("a", sym("l"))]);
    let end_gap = positive(
        "omega(a*) - omega(l) > 0 when a* < l: l = A + t, t > 0",
        subs(&omega, &[("a", sym("A"))]) - &at_end,
        true,
        &compose(std::slice::from_ref(&model), &[("l", sym("A") + &sym("t"))]),
        &["m", "v0", "A", "t"],
        &[],
        PosExpr::quotient(
            prod([pc(2, 1), ps("v0"), ps("t"), ps("t")]),
            prod([
                pc(2, 1),
                ps("A"),
                sum([
                    prod([ps("A"), ps("A")]),
                    prod([sum([ps("A"), ps("t")]), sum([ps("A"), ps("t")])]),
                ]),
            ]),
        ),
    );
    let root = sqrt(&crate::field::q(2, 3));
    let witness = Certificate::witness(
        "M = m = l = v0 = 1: omega(sqrt(2/3)) = sqrt(3/2) > omega(1) = 6/5",
        at(&[
            ("m", rational(1, 1)),
            ("M", rational(1, 1)),
            ("l", rational(1, 1)),
            ("v0", rational(1, 1)),
            ("a", root),
        ]),
        omega,
        Relation::Gt,
        at_end,
    );
    let link = a_star_link(
        "a*^2 = (M + m) l^2/(3m)",
        &paper.a_star_uniform_squared,
        model,
    );
    let mut certs = vec![room_at_the_end(paper, true), link];
    certs.extend(peak.certificates());
    certs.extend([end_gap, witness]);
    Claim {
        id: "C27",
        location: "§optimum ¶2",
        group: Group::Optimum,
        statement: "M < 2m: the unique maximiser on [0,l] is a* < l, and omega(a*) > omega(l)",
        formal: "Uniform rod (I = M l^2/3), m, M, l, v0 > 0, elastic omega from the generic solver. If \
                 M < 2m (2m = M + q, q > 0) then a* < l. Writing M = 3 m A^2/l^2 - m with A > 0 (every \
                 M > 0 is reached; the printed a*^2 is then A^2), omega(A) - omega(a) >= 0 for every a, \
                 strictly for every a >= 0 other than A: A = a* is the unique maximiser on [0, l], and \
                 omega(a*) - omega(l) > 0 (l = A + t). Example: M = m, a* = sqrt(2/3) l."
            .into(),
        reason: "2m = M + q gives l^2 - a*^2 = 2ql^2/(3(M + q)) > 0, and omega(a*) - omega(a) = \
                 v0 (a - a*)^2/(a*(a*^2 + a^2)) > 0 for a != a*"
            .into(),
        decision: Decision::Proved(certs),
    }
}

fn c28(paper: &Paper) -> Claim {
    let m = sym("m");
    let target = k(2, 3) * &sq(&sym("l"));
    Claim {
        id: "C28",
        location: "§optimum ¶2",
        group: Group::Optimum,
        statement: "M = m gives a* = sqrt(2/3) l",
        formal: "Uniform rod, m, l, v0 > 0, M = m: the printed a*^2 = (M + m) l^2/(3m) equals 2 l^2/3, so \
                 a* = sqrt(2/3) l (l > 0); independently, the solver's d omega/da vanishes on a > 0 only \
                 at a^2 = 2 l^2/3."
            .into(),
        reason: "at M = m the printed a*^2 is 2 l^2/3, where the solver's slope vanishes".into(),
        decision: Decision::Proved(vec![
            Certificate::identity_at(
                "the printed a*^2 = (M + m) l^2/(3m) at M = m equals 2 l^2/3",
                paper.a_star_uniform_squared.clone(),
                target.clone(),
                &[("M", m.clone())],
            ),
            stationary_at(&m, "m", &target),
        ]),
    }
}

fn c29(paper: &Paper) -> Claim {
    let l2 = sq(&sym("l"));
    let third = l2.clone() / k(3, 1);
    let excess = positive(
        "a*^2 - l^2/3 = (M/m) l^2/3 > 0: a* > l/sqrt3 always, with relative excess M/m in a*^2",
        paper.a_star_uniform_squared.clone() - &third,
        true,
        &[],
        &["m", "M", "l"],
        &[],
        PosExpr::quotient(prod([ps("M"), ps("l"), ps("l")]), prod([pc(3, 1), ps("m")])),
    );
    Claim {
        id: "C29",
        location: "§optimum ¶2",
        group: Group::Optimum,
        statement: "M << m gives a* close to l/sqrt3",
        formal: "Uniform rod, m, l, v0 > 0: as M -> 0+ (M/m -> 0) the printed a*^2 tends to l^2/3, and the \
                 solver's d omega/da tends to 2 v0 (l^2/3 - a^2)/(l^2/3 + a^2)^2, whose zero is a = l/sqrt3. \
                 Precisely, a*^2 = (1 + M/m) l^2/3 > l^2/3: a* approaches l/sqrt3 from above and never \
                 reaches it (the paper's 'nearly as small as')."
            .into(),
        reason: "a*^2 = (1 + M/m) l^2/3 -> l^2/3 as M/m -> 0, from above".into(),
        decision: Decision::Proved(vec![
            Certificate::limit(
                "the printed a*^2 = (M + m) l^2/(3m) tends to l^2/3 as M -> 0+",
                paper.a_star_uniform_squared.clone(),
                "M",
                crate::field::ratfunc::Point::Zero,
                third.clone(),
            ),
            Certificate::limit(
                "the solver's d omega/da (uniform rod) tends to 2 v0 (l^2/3 - a^2)/(l^2/3 + a^2)^2 as M -> 0+",
                uniform_slope(&sym("M")),
                "M",
                crate::field::ratfunc::Point::Zero,
                slope_with_peak_at(&third),
            ),
            excess,
        ]),
    }
}

fn c30(paper: &Paper) -> Claim {
    let stuck = sticking(sym("I"));
    let halved = Certificate::identity(
        "sticking (composite body: CM y_c = m a/(M + m), I_c by parallel axes, angular momentum about y_c) \
         gives omega_inel = omega_el/2 for every a, with omega_el from the generic solver (e = 1)",
        Formula::named("omega_inel", stuck.omega.clone()),
        Formula::named("omega_el", elastic_omega(sym("I"))) / &Formula::int(2),
    );
    let link = a_star_link(
        "a*^2 = (M + m) I/(m M)",
        &paper.a_star_squared,
        ("I", inertia_through_a_star()),
    );
    let peak = omega_peak(stuck.omega, ps("v0"));
    let uniform_stuck = sticking(uniform_inertia()).omega;
    let mut certs = vec![halved, link];
    certs.extend(peak.certificates());
    certs.push(increasing_on_rod(
        paper,
        &uniform_stuck,
        3,
        "sticking omega (uniform rod)",
    ));
    Claim {
        id: "C30",
        location: "§optimum ¶2",
        group: Group::Inelastic,
        statement: "\"Exactly the same behaviour\" for a totally inelastic (sticking) collision",
        formal: "Behaviour = how omega depends on a: its maximiser and the threshold M = 2m. Sticking: the \
                 projectile stays at y = a; the pair is one rigid body with CM y_c = m a/(M + m) and \
                 I_c = I + M y_c^2 + m (a - y_c)^2; omega_inel = (angular momentum about y_c)/I_c. For all \
                 m, M, I, v0 > 0 and every a, omega_inel = omega_el/2, a positive multiple, so the \
                 maximiser and monotonicity are the same; checked directly: with I = A^2 m M/(M + m), \
                 omega_inel(A) - omega_inel(a) > 0 for a != A (same a*, hence the same threshold, a* = l \
                 at M = 2m, sqrt(2/3) l at M = m, l/sqrt3 as M -> 0), and on the uniform rod with M > 2m \
                 omega_inel increases strictly on [0, l]. omega itself is half the elastic value (and \
                 energy is lost), which the paper's 'behaviour' does not concern."
            .into(),
        reason: "omega_inel(a) = omega_el(a)/2 for every a: the same a* and threshold, only the scale halves"
            .into(),
        decision: Decision::Proved(certs),
    }
}

fn c31(_paper: &Paper) -> Claim {
    let inertia = sym("I");
    let stuck = sticking(inertia.clone());
    let p = free_rod(inertia.clone(), k(0, 1));
    let after = motion(&p);
    let without = Certificate::identity(
        "omega from the rod-centre equations with the rod's own I (momentum, Eq. (angular) about the \
         rod's centre, sticking v = V + omega a: the generic solver at e = 0) equals omega of the composite \
         body (CM y_c, I_c)",
        Formula::named("omega", after.omega.clone()),
        Formula::named("omega_c", stuck.omega.clone()),
    );
    let mu = Formula::named("mu", reduced_mass());
    let parallel_axes = Certificate::identity(
        "the composite's moment of inertia about y_c = m a/(M + m) is I_c = I + mu a^2, mu = m M/(M + m)",
        Formula::named("I_c", stuck.i_c.clone()),
        Formula::from(inertia) + &(mu * &Formula::sym("a").pow(2)),
    );
    let (omega, y_c) = (
        Formula::named("omega", after.omega.clone()),
        Formula::named("y_c", stuck.y_c.clone()),
    );
    let cm_moves_uniformly = Certificate::identity(
        "after the impact the rod point at y_c moves with V + omega y_c = V_c = m v0/(M + m): the stuck \
         pair's CM is y_c, not the rod's centre",
        Formula::named("V", after.rod_v.clone()) + &(omega.clone() * &y_c),
        Formula::named("V_c", stuck.v_c.clone()),
    );
    let v_c = Formula::named("V_c", stuck.v_c.clone());
    let energy = Certificate::identity(
        "kinetic energy after the impact (rod and projectile) = (M + m) V_c^2/2 + I_c omega^2/2: I_c is \
         the stuck pair's rotational inertia",
        Formula::named("K", kinetic_energy(&p, &after)),
        (Formula::sym("M") + &Formula::sym("m")) * &v_c.pow(2) / &Formula::int(2)
            + &(Formula::named("I_c", stuck.i_c) * &omega.pow(2) / &Formula::int(2)),
    );
    Claim {
        id: "C31",
        location: "§optimum ¶2",
        group: Group::Inelastic,
        statement: "The inelastic case needs the shifted CM and the modified I",
        formal: "Natural reading: finding omega after a sticking impact requires the composite's CM \
                 y_c = m a/(M + m) and its I_c. Refuted: the paper's own Eqs. (linear) and (angular) about \
                 the fixed point at the rod's centre, with the rod's own I, plus the sticking condition \
                 v = V + omega a in place of Eq. (kinetic), give the same omega as the composite body, for \
                 all m, M, I, v0 > 0 and every a. What is true: y_c and I_c (= I + mu a^2) describe the \
                 stuck pair as one rigid body after the impact: its CM is y_c moving at V_c = m v0/(M + m), \
                 and its kinetic energy is (M + m) V_c^2/2 + I_c omega^2/2."
            .into(),
        reason: "the rod-centre equations with the rod's own I and v = V + omega a give the composite body's \
                 omega exactly; y_c and I_c only describe the stuck pair afterwards"
            .into(),
        decision: Decision::Qualified {
            qualification: "y_c and I_c are needed only to describe the stuck pair as one rigid body after \
                            the impact (its CM y_c moving at V_c, its rotational energy I_c omega^2/2); omega \
                            itself needs only the sticking condition v = V + omega a in place of energy \
                            conservation"
                .into(),
            counterexample: vec![without],
            proof: vec![parallel_axes, cm_moves_uniformly, energy],
        },
    }
}

#[cfg(test)]
mod tests {
    use super::super::{Verdict, decide};
    use super::*;

    const RANGE: [(&str, Verdict); 13] = [
        ("C19", Verdict::Proved),
        ("C20", Verdict::Proved),
        ("C21", Verdict::Proved),
        ("C22", Verdict::Proved),
        ("C23", Verdict::Proved),
        ("C24", Verdict::Proved),
        ("C25", Verdict::Proved),
        ("C26", Verdict::Proved),
        ("C27", Verdict::Proved),
        ("C28", Verdict::Proved),
        ("C29", Verdict::Proved),
        ("C30", Verdict::Proved),
        ("C31", Verdict::Qualified),
    ];

    use super::super::test_support::verdict;

    /// The ids of the range whose verdict fails under `paper`.
    fn failing(paper: &Paper) -> Vec<&'static str> {
        RANGE
            .iter()
            .filter(|(id, _)| verdict(id, paper).is_err())
            .map(|(id, _)| *id)
            .collect()
    }

    #[test]
    fn verdicts_as_printed() {
        let paper = Paper::as_printed();
        for (id, expected) in RANGE {
            assert_eq!(verdict(id, &paper), Ok(expected), "{id}");
        }
    }

    #[test]
    fn registered_in_claims_order() {
        let ids: Vec<&str> = ENTRIES.iter().map(|e| e.id).collect();
        let expected: Vec<&str> = RANGE.iter().map(|(id, _)| *id).collect();
        assert_eq!(ids, expected);
    }

    #[test]
    fn a_wrong_threshold_is_caught() {
        let paper = Paper {
            threshold: k(3, 1).into(),
            ..Paper::as_printed()
        };
        assert_eq!(failing(&paper), ["C23", "C24", "C25", "C26", "C27", "C30"]);
    }

    #[test]
    fn a_wrong_general_optimum_is_caught() {
        let printed = Paper::as_printed();
        let paper = Paper {
            a_star_squared: printed.a_star_squared.clone() * &k(2, 1),
            ..printed
        };
        assert_eq!(failing(&paper), ["C20", "C22", "C30"]);
    }

    #[test]
    fn a_wrong_uniform_optimum_is_caught() {
        let printed = Paper::as_printed();
        // The natural slip: (M + m)/m instead of (M + m)/(3m).
        let paper = Paper {
            a_star_uniform_squared: printed.a_star_uniform_squared.clone() * &k(3, 1),
            ..printed
        };
        assert_eq!(failing(&paper), ["C22", "C26", "C27", "C28", "C29"]);
    }

    #[test]
    fn a_wrong_inertia_or_omega_is_caught() {
        let printed = Paper::as_printed();
        let paper = Paper {
            uniform_inertia: (sym("M") * &sym("l") * &sym("l") / k(12, 1)).into(),
            ..printed.clone()
        };
        assert_eq!(failing(&paper), ["C21", "C22"]);
        let paper = Paper {
            omega: printed.omega.clone() / k(2, 1),
            ..printed
        };
        assert_eq!(failing(&paper), ["C20"]);
    }

    /// Applies `edit` to the first certificate of the claim's (proof) list and re-checks.
    fn tampered(
        id: &str,
        edit: impl Fn(&mut Certificate),
    ) -> Result<Verdict, super::super::CheckError> {
        let mut claim = decide(id, &Paper::as_printed()).expect("registered").claim;
        match &mut claim.decision {
            Decision::Proved(c) | Decision::Refuted(c) => edit(&mut c[0]),
            Decision::Qualified { counterexample, .. } => edit(&mut counterexample[0]),
        }
        claim.check()
    }

    #[test]
    fn tampered_certificates_fail() {
        // C24: a form that is not the expression (scale 6 replaced by 3).
        let wrong_form = tampered("C24", |c| {
            if let Certificate::Positive(crate::claims::certificate::Positive { form, .. }) = c {
                *form = PosExpr::product([PosExpr::constant(1, 2), form.clone()]);
            }
        });
        assert!(wrong_form.is_err());
        // C25: l^2 - a*^2 is only >= 0 when M <= 2m; claiming > 0 must fail.
        let mut c25 = decide("C25", &Paper::as_printed()).unwrap().claim;
        if let Decision::Proved(certs) = &mut c25.decision
            && let Certificate::Positive(crate::claims::certificate::Positive { strict, .. }) =
                &mut certs[1]
        {
            *strict = true;
        }
        assert!(c25.check().is_err());
        // C27: the witness reversed (omega(a*) < omega(l)) must fail.
        let mut c27 = decide("C27", &Paper::as_printed()).unwrap().claim;
        if let Decision::Proved(certs) = &mut c27.decision
            && let Some(Certificate::Witness(crate::claims::certificate::Witness {
                relation, ..
            })) = certs.last_mut()
        {
            *relation = Relation::Lt;
        }
        assert!(c27.check().is_err());
        // C31: the identity against the composite body with the naive I + m a^2 must fail.
        let naive = tampered("C31", |c| {
            if let Certificate::Identity(crate::claims::certificate::Identity { rhs, .. }) = c {
                let i_naive = sym("I") + &(sym("m") * &sq(&sym("a")));
                *rhs = (sym("m") * &sym("v0") * &sym("a") / i_naive).into();
            }
        });
        assert!(naive.is_err());
    }

    #[test]
    fn a_wrong_peak_or_a_wrong_strictness_fails() {
        // f = x/(b^2 + c^2 x^2) does not peak at c/b: every peak certificate fails.
        let (b, c, x) = (sym("b"), sym("c"), sym("x"));
        let wrong = Peak {
            name: "f",
            f: x.clone() / (sq(&b) + &(sq(&c) * &sq(&x))),
            x: "x",
            peak_name: "c/b",
            b: "c",
            c: Some("b"),
            k: PosExpr::constant(1, 1),
            model: vec![],
            positive: vec![],
        };
        assert!(wrong.certificates().iter().all(|c| c.check().is_err()));
        // The gap is only >= 0 everywhere (it vanishes at the peak): claiming > 0 fails.
        let strict = tampered("C20", |c| {
            if let Certificate::Positive(crate::claims::certificate::Positive { strict, .. }) = c {
                *strict = true;
            }
        });
        assert!(strict.is_ok(), "C20's first certificate is an identity");
        let mut c20 = decide("C20", &Paper::as_printed()).unwrap().claim;
        if let Decision::Proved(certs) = &mut c20.decision
            && let Certificate::Positive(crate::claims::certificate::Positive { strict, .. }) =
                &mut certs[2]
        {
            *strict = true;
        }
        assert!(c20.check().is_err());
    }

    #[test]
    fn the_sticking_omega_is_not_the_elastic_one() {
        let stuck = sticking(sym("I"));
        let same = Certificate::identity("", stuck.omega, elastic_omega(sym("I")));
        assert!(same.check().is_err());
    }

    #[test]
    fn the_range_is_fast() {
        let paper = Paper::as_printed();
        let total: f64 = RANGE
            .iter()
            .map(|(id, _)| decide(id, &paper).unwrap().seconds)
            .sum();
        assert!(total < 2.0, "{total} s");
    }
}
