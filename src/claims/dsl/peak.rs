//! The peak of k x/(b^2 + c^2 x^2).
//!
//! The optimum rests on one shape: omega(a) = k a/(b^2 + c^2 a^2) once the parameters are
//! written through a positive symbol `A` standing for a* (C19, C20, C27, C30). [`Peak`] turns a
//! function of that shape into three certificates: the gap to the peak is a square over a
//! positive denominator (>= 0 everywhere), and it is strictly positive on either side.

use super::*;
use crate::field::RatFn;

/// `model` with `domain` substituted into its values, followed by `domain`: the single
/// simultaneous substitution that applies `model` first and then `domain`.
pub(crate) fn compose<'a>(
    model: &[(&'a str, RatFn)],
    domain: &[(&'a str, RatFn)],
) -> Vec<(&'a str, RatFn)> {
    let mut all: Vec<(&str, RatFn)> = model.iter().map(|(s, v)| (*s, subs(v, domain))).collect();
    all.extend(domain.iter().cloned());
    all
}

/// A function `f` of the symbol `x` that, after the substitution `model`, has the shape
/// `k x/(b^2 + c^2 x^2)` with b, c > 0 (c = 1 when `c` is `None`).
pub(crate) struct Peak {
    /// The function's name in titles (`f`, `omega`).
    pub(crate) name: &'static str,
    /// The function, before the model substitution.
    pub(crate) f: RatFn,
    pub(crate) x: &'static str,
    /// The name of the peak in titles (`b/c`, `a*`).
    pub(crate) peak_name: &'static str,
    pub(crate) b: &'static str,
    pub(crate) c: Option<&'static str>,
    /// The factor k, visibly positive.
    pub(crate) k: PosExpr,
    /// Writes the parameters through b and c (empty when f already has the shape).
    pub(crate) model: Vec<(&'static str, RatFn)>,
    /// Symbols positive on the domain besides b, c, x and the slack t.
    pub(crate) positive: Vec<&'static str>,
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

    /// The three certificates: >= 0 everywhere, > 0 right of the peak, > 0 left of it.
    pub(crate) fn certificates(&self) -> Vec<Certificate> {
        vec![self.everywhere(), self.above(), self.below()]
    }
}

/// omega(a) of a general rod written through A (I = A^2 m M/(M + m)), scaled by `k`.
pub(crate) fn omega_peak(omega: RatFn, k: PosExpr) -> Peak {
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

#[cfg(test)]
mod tests {
    use super::*;

    /// f = x/(b^2 + c^2 x^2) peaks at b/c, not at c/b: every certificate of the wrong peak fails.
    #[test]
    fn a_wrong_peak_fails_every_certificate() {
        let (b, c, x) = (sym("b"), sym("c"), sym("x"));
        let f = x.clone() / (sq(&b) + &(sq(&c) * &sq(&x)));
        let peak = |b: &'static str, c: &'static str| Peak {
            name: "f",
            f: f.clone(),
            x: "x",
            peak_name: "b/c",
            b,
            c: Some(c),
            k: PosExpr::constant(1, 1),
            model: vec![],
            positive: vec![],
        };
        assert!(
            peak("b", "c")
                .certificates()
                .iter()
                .all(|c| c.check().is_ok())
        );
        assert!(
            peak("c", "b")
                .certificates()
                .iter()
                .all(|c| c.check().is_err())
        );
    }
}
