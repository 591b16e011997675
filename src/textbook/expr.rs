//! Symbolic answers: a small expression grammar evaluated exactly into `c * sqrt(r)` with `c`
//! and `r` rational functions ([`RatFn`]).
//!
//! Grammar: `+ - * /`, `^` with an integer exponent, parentheses, `sqrt(...)`, numbers (as
//! [`crate::number::parse`] reads them) and the symbols `m M l L a d v0 e p I r` (`I` the rod's moment of inertia
//! about its centre, `r` its radius of gyration). There is no
//! implicit multiplication (`2m` is an error; write `2*m`). Inputs longer than [`MAX_LEN`]
//! characters or nested deeper than [`MAX_DEPTH`] are refused before any deep recursion, and
//! intermediate results are capped ([`MAX_DEGREE`], [`MAX_TERMS`], [`MAX_COEFF_BITS`]), and so is
//! the total work of the evaluation ([`MAX_WORK`]), so no input runs for long.

use super::spelling::nearest_symbol;
use super::surd_form::normal_form;
use crate::error::{Error, ErrorKind};
use crate::field::{Field, Poly, Q, RatFn};
use crate::number;
use num_traits::{One, Signed, Zero};

/// The longest accepted expression, in characters.
pub const MAX_LEN: usize = 10_000;
/// The deepest accepted nesting of parentheses, signs and powers.
pub const MAX_DEPTH: usize = 200;
/// The largest accepted |exponent| after `^`.
pub const MAX_EXPONENT: i64 = 64;
/// The largest total degree of any intermediate polynomial.
pub const MAX_DEGREE: u32 = 32;
/// The most terms of any intermediate polynomial.
pub const MAX_TERMS: usize = 2_000;
/// The largest numerator or denominator of any intermediate coefficient, in bits (about 20,000
/// decimal digits: the product of two numbers at the digit limit).
pub const MAX_COEFF_BITS: u64 = 66_440;
/// The most work one expression may cost: each operation on intermediate values `x` and `y`
/// is charged `size(x) * size(y)`, where a value's size counts the 64-bit words of every
/// coefficient of its polynomials. A count, not a clock, so a refusal does not depend on the
/// machine; textbook formulas cost a few hundred units.
pub const MAX_WORK: u64 = 4_000_000;
/// The most work all the expressions and identity decisions of one run may cost together
/// (every claim on the command line, or every problem of a file): ten expressions at
/// [`MAX_WORK`], about ten seconds at worst.
pub const MAX_RUN_WORK: u64 = 10 * MAX_WORK;

/// The work left for one run, charged by every expression parsed and every identity decided
/// (see [`MAX_RUN_WORK`]); the field being worked on when it runs out is named in the error.
///
/// # Examples
/// ```
/// use rodimpact::textbook::expr::{parse_within, Budget, MAX_RUN_WORK};
/// let mut budget = Budget::new(MAX_RUN_WORK);
/// parse_within("claim v", "m/(m+M)", &mut budget).unwrap();
/// assert!(budget.spent() > 0);
/// let mut tiny = Budget::new(1);
/// let err = parse_within("claim v", "m/(m+M)", &mut tiny).unwrap_err().to_string();
/// assert!(err.starts_with("claim v: the claims of this run together cost more than"), "{err}");
/// ```
#[derive(Debug, Clone)]
pub struct Budget {
    spent: u64,
    limit: u64,
}

impl Budget {
    /// A budget of `limit` work units.
    ///
    /// # Examples
    /// ```
    /// assert_eq!(rodimpact::textbook::expr::Budget::new(5).spent(), 0);
    /// ```
    pub fn new(limit: u64) -> Budget {
        Budget { spent: 0, limit }
    }

    /// The budget of one run: [`MAX_RUN_WORK`].
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::expr::Budget;
    /// assert_eq!(Budget::run().spent(), 0);
    /// ```
    pub fn run() -> Budget {
        Budget::new(MAX_RUN_WORK)
    }

    /// The work charged so far.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::expr::Budget;
    /// let mut b = Budget::new(10);
    /// b.charge("claim v", 4).unwrap();
    /// assert_eq!(b.spent(), 4);
    /// ```
    pub fn spent(&self) -> u64 {
        self.spent
    }

    /// Charges `units` of work done on `field`.
    ///
    /// # Errors
    /// `field: the claims of this run together cost more than ... (limit)` once the total
    /// passes the limit.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::expr::Budget;
    /// let mut b = Budget::new(10);
    /// assert!(b.charge("claim v", 10).is_ok());
    /// assert!(b.charge("claim V", 1).unwrap_err().to_string().starts_with("claim V: "));
    /// ```
    pub fn charge(&mut self, field: &str, units: u64) -> Result<(), Error> {
        self.spent = self.spent.saturating_add(units);
        if self.spent > self.limit {
            return Err(self.exhausted(field));
        }
        Ok(())
    }

    /// Runs the symbolic computation `f` (a solve, a*, omega_max, an identity) on what is left
    /// of the budget, charging the polynomial work it does (see
    /// [`metered`](crate::field::poly::metered)) as well as what `f` charges itself; a
    /// computation that would pass the limit is stopped and refused, naming `field`.
    ///
    /// # Errors
    /// `field: solving in symbols costs more than ... (limit)` when `f` would; `f`'s own errors.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::RatFn, textbook::expr::Budget};
    /// use num_traits::One;
    /// let x = RatFn::symbol("m") + RatFn::symbol("M");
    /// let power = |_: &mut Budget| Ok((0..40).fold(RatFn::one(), |p, _| p * x.clone()));
    /// let mut budget = Budget::run();
    /// assert!(budget.metered("M", power).is_ok());
    /// assert!(budget.spent() > 0);
    /// let err = Budget::new(100).metered("M", power).unwrap_err().to_string();
    /// assert!(err.starts_with("M: solving in symbols costs more than 100 work units"), "{err}");
    /// ```
    pub fn metered<T>(
        &mut self,
        field: &str,
        f: impl FnOnce(&mut Budget) -> Result<T, Error>,
    ) -> Result<T, Error> {
        let left = self.limit.saturating_sub(self.spent);
        match crate::field::poly::metered(left, || f(self)) {
            Ok((value, spent)) => {
                self.spent = self.spent.saturating_add(spent);
                if self.spent > self.limit {
                    return Err(self.too_costly(field));
                }
                value
            }
            Err(_) => {
                self.spent = self.limit.saturating_add(1);
                Err(self.too_costly(field))
            }
        }
    }

    fn too_costly(&self, field: &str) -> Error {
        Error::out_of_range(
            field,
            format!(
                "solving in symbols costs more than {} work units (limit); give this quantity a simpler formula or a number",
                self.limit
            ),
        )
    }

    fn exhausted(&self, field: &str) -> Error {
        Error::out_of_range(
            field,
            format!(
                "the claims of this run together cost more than {} work units (limit); check them in smaller runs",
                self.limit
            ),
        )
    }
}

/// The symbols an expression may use.
pub const SYMBOLS: [&str; 11] = ["m", "M", "l", "L", "a", "d", "v0", "e", "p", "I", "r"];

/// The symbols of an oblique scene, read in `formula`'s oblique flags: `v0t` (the projectile's
/// velocity along the rod), `mu` (friction), `rd` and `w` (the disc's radius and spin), `V0`,
/// `Vt0`, `omega0` (the rod's motion before the impact).
pub const OBLIQUE_SYMBOLS: [&str; 7] = ["v0t", "mu", "rd", "w", "V0", "Vt0", "omega0"];

/// An exact value `coeff * sqrt(radicand)`; rational when `radicand` is 1.
///
/// # Examples
/// ```
/// use rodimpact::textbook::expr::parse;
/// let r = parse("claim", "2*sqrt(m/3)").unwrap();
/// assert_eq!((r.coeff.to_string(), r.radicand.to_string()), ("2/3".into(), "3*m".into()));
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Radical {
    /// The rational factor.
    pub coeff: RatFn,
    /// The radicand (1 for a rational value).
    pub radicand: RatFn,
}

impl Radical {
    /// A rational value.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::expr::Radical;
    /// use rodimpact::field::RatFn;
    /// assert!(Radical::rational(RatFn::symbol("m")).is_rational());
    /// ```
    pub fn rational(coeff: RatFn) -> Radical {
        Radical {
            coeff,
            radicand: RatFn::one(),
        }
    }

    /// `coeff * sqrt(radicand)` in normal form: an integer free of squares under the root's
    /// constant, and even powers of the (positive) symbols brought out.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::expr::Radical;
    /// use rodimpact::field::{q, Field, RatFn};
    /// let l = RatFn::symbol("l");
    /// let r = Radical::normalized(RatFn::symbol("v0"), RatFn::from_rational(&q(3, 2)) / (l.clone() * &l));
    /// assert_eq!(r.to_string(), "(1/2*v0/l)*sqrt(6)");
    /// ```
    pub fn normalized(coeff: RatFn, radicand: RatFn) -> Radical {
        simplify(coeff, radicand)
    }

    /// Whether the value has no square root left.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::expr::parse;
    /// assert!(parse("x", "sqrt(4)").unwrap().is_rational());
    /// assert!(!parse("x", "sqrt(2)").unwrap().is_rational());
    /// ```
    pub fn is_rational(&self) -> bool {
        self.radicand.is_one() || self.coeff.is_zero()
    }

    /// Applies `f` to both parts (substitution); `None` when a denominator vanishes.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::expr::parse;
    /// use rodimpact::field::{RatFn, Sym};
    /// let r = parse("x", "m*sqrt(m)").unwrap();
    /// let s = r.map(|f| f.subs(Sym::new("m"), &RatFn::from(4))).unwrap();
    /// assert_eq!(s.coeff.to_string(), "8");
    /// ```
    pub fn map(&self, f: impl Fn(&RatFn) -> Option<RatFn>) -> Option<Radical> {
        Some(simplify(f(&self.coeff)?, f(&self.radicand)?))
    }

    /// Whether `sym` occurs.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::expr::parse;
    /// use rodimpact::field::Sym;
    /// assert!(parse("x", "sqrt(p)").unwrap().mentions(Sym::new("p")));
    /// ```
    pub fn mentions(&self, sym: crate::field::Sym) -> bool {
        self.coeff.symbols().contains(&sym) || self.radicand.symbols().contains(&sym)
    }

    /// The constant value as `(c, r)` meaning `c * sqrt(r)`, when no symbol is left.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::expr::parse;
    /// use rodimpact::field::q;
    /// assert_eq!(parse("x", "sqrt(8)/2").unwrap().constant(), Some((q(1, 1), q(2, 1))));
    /// ```
    pub fn constant(&self) -> Option<(Q, Q)> {
        Some((self.coeff.as_constant()?, self.radicand.as_constant()?))
    }
}

/// `coeff * sqrt(radicand)` in normal form ([`normal_form`]).
fn simplify(coeff: RatFn, radicand: RatFn) -> Radical {
    let (coeff, radicand) = normal_form(coeff, radicand);
    Radical { coeff, radicand }
}

impl std::fmt::Display for Radical {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.is_rational() {
            write!(f, "{}", self.coeff)
        } else if self.coeff.is_one() {
            write!(f, "sqrt({})", self.radicand)
        } else {
            write!(f, "({})*sqrt({})", self.coeff, self.radicand)
        }
    }
}

/// Parses and evaluates an expression; symbols stay symbols (`L` and `d` included: the caller
/// knows what they stand for in its scene).
///
/// # Errors
/// `field: ...` for a syntax error (with the position), an unknown symbol, a division by zero,
/// a sum of different square roots, nested roots, or a resource limit.
///
/// # Examples
/// ```
/// use rodimpact::textbook::expr::parse;
/// let r = parse("omega", "12*m*v0/((M+4*m)*L)").unwrap();
/// assert_eq!(r.to_string(), "12*m*v0/(L*M + 4*L*m)");
/// assert!(parse("omega", "2m").is_err());
/// assert!(parse("omega", &"(".repeat(100_000)).is_err());
/// ```
pub fn parse(field: &str, text: &str) -> Result<Radical, Error> {
    parse_within(field, text, &mut Budget::new(MAX_WORK))
}

/// [`parse`], charging the work to a run's `budget` as well as to the expression's own limit.
///
/// # Errors
/// Those of [`parse`], and an exhausted budget.
///
/// # Examples
/// ```
/// use rodimpact::textbook::expr::{parse_within, Budget};
/// let mut budget = Budget::run();
/// assert_eq!(parse_within("x", "2*m", &mut budget).unwrap().to_string(), "2*m");
/// ```
pub fn parse_within(field: &str, text: &str, budget: &mut Budget) -> Result<Radical, Error> {
    if text.chars().count() > MAX_LEN {
        return Err(invalid(
            field,
            format!("expression longer than {MAX_LEN} characters (limit)"),
        ));
    }
    let mut p = Parser {
        field,
        chars: text.chars().collect(),
        pos: 0,
        depth: 0,
        work: 0,
        budget,
    };
    let value = p.expr()?;
    p.skip_space();
    if p.pos < p.chars.len() {
        return Err(p.error("expected an operator"));
    }
    Ok(value)
}

fn invalid(field: &str, why: String) -> Error {
    Error::new(field, ErrorKind::Invalid(why))
}

struct Parser<'a> {
    field: &'a str,
    /// The run's budget, charged alongside [`Parser::work`].
    budget: &'a mut Budget,
    chars: Vec<char>,
    pos: usize,
    depth: usize,
    /// Work charged so far (see [`MAX_WORK`]).
    work: u64,
}

impl Parser<'_> {
    fn error(&self, why: &str) -> Error {
        let here = self.chars.get(self.pos);
        let found = match here {
            Some(c) => format!("'{}'", c.escape_debug()),
            None => "the end".to_string(),
        };
        // `4m`, `2(M+m)`, `(M+m)l`: a product written without its `*`.
        let before = self.pos.checked_sub(1).and_then(|k| self.chars.get(k));
        let implicit = matches!(before, Some(b) if b.is_ascii_alphanumeric() || *b == ')')
            && matches!(here, Some(c) if c.is_ascii_alphabetic() || *c == '(');
        let hint = if implicit {
            let left: String = self.chars[..self.pos]
                .iter()
                .rev()
                .take_while(|c| c.is_ascii_alphanumeric() || **c == '.' || **c == ')')
                .collect::<Vec<_>>()
                .into_iter()
                .rev()
                .collect();
            let right = here.map(|c| c.to_string()).unwrap_or_default();
            format!(": write {left}*{right}... (a product needs '*')")
        } else {
            String::new()
        };
        invalid(
            self.field,
            format!(
                "{why} at character {} (found {found}) in expression{hint}",
                self.pos + 1
            ),
        )
    }

    fn skip_space(&mut self) {
        while self.chars.get(self.pos).is_some_and(|c| c.is_whitespace()) {
            self.pos += 1;
        }
    }

    fn peek(&mut self) -> Option<char> {
        self.skip_space();
        self.chars.get(self.pos).copied()
    }

    fn enter(&mut self) -> Result<(), Error> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            Err(invalid(
                self.field,
                format!("expression nested deeper than {MAX_DEPTH} levels (limit)"),
            ))
        } else {
            Ok(())
        }
    }

    fn expr(&mut self) -> Result<Radical, Error> {
        let mut value = self.term()?;
        while let Some(op @ ('+' | '-')) = self.peek() {
            self.pos += 1;
            let rhs = self.term()?;
            let rhs = if op == '-' { neg(rhs) } else { rhs };
            self.charge(&value, &rhs)?;
            value = self.checked(add(value, rhs))?;
        }
        Ok(value)
    }

    fn term(&mut self) -> Result<Radical, Error> {
        let mut value = self.unary()?;
        while let Some(op @ ('*' | '/')) = self.peek() {
            self.pos += 1;
            let rhs = self.unary()?;
            self.charge(&value, &rhs)?;
            value = if op == '*' {
                self.checked(Ok(mul(value, rhs)))?
            } else {
                if rhs.coeff.is_zero() {
                    return Err(Error::new(self.field, ErrorKind::DivisionByZero));
                }
                self.checked(Ok(mul(value, inverse(rhs))))?
            };
        }
        Ok(value)
    }

    fn unary(&mut self) -> Result<Radical, Error> {
        match self.peek() {
            Some(op @ ('-' | '+')) => {
                self.pos += 1;
                self.enter()?;
                let value = self.unary()?;
                self.depth -= 1;
                Ok(if op == '-' { neg(value) } else { value })
            }
            _ => self.power(),
        }
    }

    fn power(&mut self) -> Result<Radical, Error> {
        let base = self.atom()?;
        if self.peek() != Some('^') {
            return Ok(base);
        }
        self.pos += 1;
        let n = self.exponent()?;
        if n < 0 && base.coeff.is_zero() {
            return Err(Error::new(self.field, ErrorKind::DivisionByZero));
        }
        let mut result = Radical::rational(RatFn::one());
        for _ in 0..n.unsigned_abs() {
            self.charge(&result, &base)?;
            result = self.checked(Ok(mul(result, base.clone())))?;
        }
        Ok(if n < 0 { inverse(result) } else { result })
    }

    /// An integer exponent: `2`, `-1`, `(-1)`.
    fn exponent(&mut self) -> Result<i64, Error> {
        let paren = self.peek() == Some('(');
        if paren {
            self.pos += 1;
        }
        let negative = self.peek() == Some('-');
        if negative {
            self.pos += 1;
        }
        self.skip_space();
        let start = self.pos;
        while self.chars.get(self.pos).is_some_and(char::is_ascii_digit) {
            self.pos += 1;
        }
        let digits: String = self.chars[start..self.pos].iter().collect();
        let n: i64 = match digits.parse::<i64>() {
            Ok(n) if n <= MAX_EXPONENT => n,
            Ok(_) | Err(_) if !digits.is_empty() => {
                return Err(invalid(
                    self.field,
                    format!("exponent beyond +-{MAX_EXPONENT} (limit)"),
                ));
            }
            _ => return Err(self.error("expected an integer exponent")),
        };
        if paren {
            if self.peek() != Some(')') {
                return Err(self.error("expected ')'"));
            }
            self.pos += 1;
        }
        Ok(if negative { -n } else { n })
    }

    fn atom(&mut self) -> Result<Radical, Error> {
        match self.peek() {
            Some('(') => {
                self.pos += 1;
                self.enter()?;
                let value = self.expr()?;
                if self.peek() != Some(')') {
                    return Err(self.error("expected ')'"));
                }
                self.pos += 1;
                self.depth -= 1;
                Ok(value)
            }
            Some(c) if c.is_ascii_digit() || c == '.' => self.number(),
            Some(c) if c.is_ascii_alphabetic() => self.name(),
            _ => Err(self.error("expected a number, a symbol or '('")),
        }
    }

    fn number(&mut self) -> Result<Radical, Error> {
        let start = self.pos;
        while self
            .chars
            .get(self.pos)
            .is_some_and(|c| c.is_ascii_digit() || *c == '.')
        {
            self.pos += 1;
        }
        // An exponent only when digits follow: `2e3`, `2e-3`; `2e` is 2 then the symbol e.
        if matches!(self.chars.get(self.pos), Some('e' | 'E')) {
            let mut k = self.pos + 1;
            if matches!(self.chars.get(k), Some('+' | '-')) {
                k += 1;
            }
            if self.chars.get(k).is_some_and(char::is_ascii_digit) {
                self.pos = k;
                while self.chars.get(self.pos).is_some_and(char::is_ascii_digit) {
                    self.pos += 1;
                }
            }
        }
        let text: String = self.chars[start..self.pos].iter().collect();
        let value = number::parse(&text).map_err(|kind| Error::new(self.field, kind))?;
        Ok(Radical::rational(RatFn::from_rational(&value)))
    }

    fn name(&mut self) -> Result<Radical, Error> {
        let start = self.pos;
        while self
            .chars
            .get(self.pos)
            .is_some_and(|c| c.is_ascii_alphanumeric() || *c == '_')
        {
            self.pos += 1;
        }
        let name: String = self.chars[start..self.pos].iter().collect();
        if name == "sqrt" {
            if self.peek() != Some('(') {
                return Err(self.error("expected '(' after sqrt"));
            }
            let arg = self.atom()?;
            return self.checked(sqrt(arg));
        }
        if SYMBOLS.contains(&name.as_str()) || OBLIQUE_SYMBOLS.contains(&name.as_str()) {
            Ok(Radical::rational(RatFn::symbol(&name)))
        } else {
            self.pos = start;
            let known: Vec<&'static str> =
                SYMBOLS.iter().chain(&OBLIQUE_SYMBOLS).copied().collect();
            let suggestion = nearest_symbol(&name, &known)
                .map(|s| format!("did you mean {s}? "))
                .unwrap_or_default();
            Err(invalid(
                self.field,
                format!(
                    "unknown symbol '{}' at character {} ({suggestion}symbols: m M l L a d v0 e p I r, oblique v0t mu rd w V0 Vt0 omega0, function sqrt)",
                    crate::echo::echo(&name),
                    start + 1
                ),
            ))
        }
    }

    /// Charges an operation on `x` and `y` against [`MAX_WORK`] before it is carried out.
    fn charge(&mut self, x: &Radical, y: &Radical) -> Result<(), Error> {
        let units = pair_cost(x, y);
        self.work = self.work.saturating_add(units);
        if self.work > MAX_WORK {
            return Err(invalid(
                self.field,
                format!("expression too costly to evaluate (work beyond {MAX_WORK} units, limit)"),
            ));
        }
        self.budget.charge(self.field, units)
    }

    fn checked(&self, value: Result<Radical, String>) -> Result<Radical, Error> {
        let value = value.map_err(|why| invalid(self.field, why))?;
        let polys = [
            value.coeff.num(),
            value.coeff.den(),
            value.radicand.num(),
            value.radicand.den(),
        ];
        if polys
            .iter()
            .any(|p| p.total_degree() > MAX_DEGREE || p.terms().count() > MAX_TERMS)
        {
            return Err(invalid(
                self.field,
                format!(
                    "expression too large (a polynomial beyond degree {MAX_DEGREE} or {MAX_TERMS} terms)"
                ),
            ));
        }
        let huge = |c: &Q| c.numer().bits() > MAX_COEFF_BITS || c.denom().bits() > MAX_COEFF_BITS;
        if polys.iter().any(|p| p.terms().any(|(_, c)| huge(c))) {
            return Err(invalid(
                self.field,
                format!("expression too large (a number beyond {MAX_COEFF_BITS} bits, limit)"),
            ));
        }
        Ok(value)
    }
}

/// The work of combining `x` and `y` term by term: every pair of coefficients of `w_i` and
/// `w_j` words costs `(w_i + w_j)^2` (a product, then a reduction by GCD, quadratic in the
/// size of the result), summed without enumerating the pairs.
fn pair_cost(x: &Radical, y: &Radical) -> u64 {
    let (tx, s1x, s2x) = moments(x);
    let (ty, s1y, s2y) = moments(y);
    tx.saturating_mul(s2y)
        .saturating_add(s1x.saturating_mul(s1y).saturating_mul(2))
        .saturating_add(ty.saturating_mul(s2x))
}

/// (terms, sum of words, sum of squared words) over the four polynomials of `x`.
fn moments(x: &Radical) -> (u64, u64, u64) {
    [
        x.coeff.num(),
        x.coeff.den(),
        x.radicand.num(),
        x.radicand.den(),
    ]
    .iter()
    .flat_map(|p| p.terms())
    .map(|(_, c)| c.numer().bits() / 64 + c.denom().bits() / 64 + 2)
    .fold((0, 0, 0), |(t, s1, s2), w| {
        (t + 1, s1.saturating_add(w), s2.saturating_add(w * w))
    })
}

/// The size of a value for [`MAX_WORK`]: the 64-bit words of every coefficient of its four
/// polynomials.
///
/// # Examples
/// ```
/// use rodimpact::textbook::expr::{parse, size};
/// assert_eq!(size(&parse("x", "m").unwrap()), 8); // m/1 and 1/1: two words a coefficient
/// ```
pub fn size(x: &Radical) -> u64 {
    size_of(&x.coeff).saturating_add(size_of(&x.radicand))
}

/// The size of a rational function: the 64-bit words of every coefficient of its numerator
/// and denominator.
///
/// # Examples
/// ```
/// use rodimpact::{field::RatFn, textbook::expr::size_of};
/// assert_eq!(size_of(&RatFn::symbol("m")), 4);
/// ```
pub fn size_of(f: &RatFn) -> u64 {
    words(f.num()).saturating_add(words(f.den()))
}

/// The 64-bit words of every coefficient of a polynomial (two at least for each).
///
/// # Examples
/// ```
/// use rodimpact::{field::RatFn, textbook::expr::words};
/// assert_eq!(words(RatFn::symbol("m").num()), 2);
/// ```
pub fn words(p: &Poly) -> u64 {
    p.words()
}

fn neg(x: Radical) -> Radical {
    Radical {
        coeff: -x.coeff,
        radicand: x.radicand,
    }
}

fn add(x: Radical, y: Radical) -> Result<Radical, String> {
    if x.coeff.is_zero() {
        Ok(y)
    } else if y.coeff.is_zero() {
        Ok(x)
    } else if x.radicand == y.radicand {
        Ok(simplify(x.coeff + &y.coeff, x.radicand))
    } else {
        Err("sums of different square roots are not supported".into())
    }
}

fn mul(x: Radical, y: Radical) -> Radical {
    if x.radicand == y.radicand {
        Radical::rational(x.coeff * &y.coeff * &x.radicand)
    } else {
        simplify(x.coeff * &y.coeff, x.radicand * &y.radicand)
    }
}

/// `1 / (c sqrt r) = (1 / (c r)) sqrt r`; the caller has excluded zero.
fn inverse(x: Radical) -> Radical {
    let denominator = x.coeff * &x.radicand;
    Radical {
        coeff: RatFn::one() / denominator,
        radicand: x.radicand,
    }
}

fn sqrt(x: Radical) -> Result<Radical, String> {
    if !x.is_rational() {
        return Err("nested square roots are not supported".into());
    }
    if let Some(c) = x.coeff.as_constant()
        && c.is_negative()
    {
        return Err(format!("square root of the negative number {c}"));
    }
    Ok(simplify(RatFn::one(), x.coeff))
}
