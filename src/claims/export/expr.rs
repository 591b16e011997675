//! The statement language of the exports: real expressions and propositions over named real
//! unknowns, written in the familiar infix syntax (`omega = 2*m*a*v0/(I + m*a^2)`,
//! `0 <= a <= l`, `v < 0 or V > 0`), parsed once and written out as SMT-LIB 2 or SymPy.
//!
//! Expressions: integers, names (`v0`, `omega_1`), `+ - * /`, `^` with a natural exponent,
//! parentheses. Propositions: comparisons `= != < <= > >=` (chained: `0 <= a <= l`), `not`,
//! `and`, `or`, `=>`, tightest first, and parentheses. Statements are written in the claim
//! files, so a parse error is a programming error, reported with the text.

use crate::claims::certificate::Relation;
use std::collections::BTreeSet;
use std::fmt;

/// A real expression.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Expr {
    /// A natural number.
    Int(u64),
    /// A named real.
    Name(String),
    /// `-x`.
    Neg(Box<Expr>),
    /// `x + y`.
    Add(Box<Expr>, Box<Expr>),
    /// `x - y`.
    Sub(Box<Expr>, Box<Expr>),
    /// `x * y`.
    Mul(Box<Expr>, Box<Expr>),
    /// `x / y`.
    Div(Box<Expr>, Box<Expr>),
    /// `x ^ n`.
    Pow(Box<Expr>, u32),
}

/// A proposition about real expressions.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Prop {
    /// `x op y`.
    Relation(Relation, Expr, Expr),
    /// `not p`.
    Not(Box<Prop>),
    /// `p and q and ...`.
    And(Vec<Prop>),
    /// `p or q or ...`.
    Or(Vec<Prop>),
    /// `p => q`.
    Implies(Box<Prop>, Box<Prop>),
}

/// Why a statement does not parse: the text and the reason.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ParseError {
    /// The statement.
    pub text: String,
    /// What is wrong, at which token.
    pub reason: String,
}

impl fmt::Display for ParseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "cannot parse {:?}: {}", self.text, self.reason)
    }
}

#[derive(Debug, Clone, PartialEq, Eq)]
enum Token {
    Int(u64),
    Name(String),
    Op(&'static str),
}

const OPERATORS: [&str; 14] = [
    "=>", "!=", "<=", ">=", "=", "<", ">", "+", "-", "*", "/", "^", "(", ")",
];

fn tokens(text: &str) -> Result<Vec<Token>, String> {
    let mut out = Vec::new();
    let mut rest = text;
    while let Some(c) = rest.chars().next() {
        if c.is_whitespace() {
            rest = &rest[c.len_utf8()..];
        } else if c.is_ascii_digit() {
            let end = rest
                .find(|c: char| !c.is_ascii_digit())
                .unwrap_or(rest.len());
            let n = rest[..end]
                .parse()
                .map_err(|_| format!("number {} too large", &rest[..end]))?;
            out.push(Token::Int(n));
            rest = &rest[end..];
        } else if c.is_ascii_alphabetic() || c == '_' {
            let end = rest
                .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                .unwrap_or(rest.len());
            out.push(Token::Name(rest[..end].to_string()));
            rest = &rest[end..];
        } else if let Some(op) = OPERATORS.iter().find(|op| rest.starts_with(**op)) {
            out.push(Token::Op(op));
            rest = &rest[op.len()..];
        } else {
            return Err(format!("unexpected character {c:?}"));
        }
    }
    Ok(out)
}

struct Parser {
    tokens: Vec<Token>,
    at: usize,
}

impl Parser {
    fn peek(&self) -> Option<&Token> {
        self.tokens.get(self.at)
    }

    fn eat_op(&mut self, op: &str) -> bool {
        if matches!(self.peek(), Some(Token::Op(o)) if *o == op) {
            self.at += 1;
            true
        } else {
            false
        }
    }

    fn eat_word(&mut self, word: &str) -> bool {
        if matches!(self.peek(), Some(Token::Name(n)) if n == word) {
            self.at += 1;
            true
        } else {
            false
        }
    }

    fn expect_op(&mut self, op: &str) -> Result<(), String> {
        if self.eat_op(op) {
            Ok(())
        } else {
            Err(format!("expected {op:?} at token {}", self.at + 1))
        }
    }

    fn implication(&mut self) -> Result<Prop, String> {
        let lhs = self.disjunction()?;
        if self.eat_op("=>") {
            let rhs = self.implication()?;
            return Ok(Prop::Implies(Box::new(lhs), Box::new(rhs)));
        }
        Ok(lhs)
    }

    fn disjunction(&mut self) -> Result<Prop, String> {
        let mut terms = vec![self.conjunction()?];
        while self.eat_word("or") {
            terms.push(self.conjunction()?);
        }
        Ok(if terms.len() == 1 {
            terms.remove(0)
        } else {
            Prop::Or(terms)
        })
    }

    fn conjunction(&mut self) -> Result<Prop, String> {
        let mut terms = vec![self.negation()?];
        while self.eat_word("and") {
            terms.push(self.negation()?);
        }
        Ok(if terms.len() == 1 {
            terms.remove(0)
        } else {
            Prop::And(terms)
        })
    }

    fn negation(&mut self) -> Result<Prop, String> {
        if self.eat_word("not") {
            return Ok(Prop::Not(Box::new(self.negation()?)));
        }
        // A parenthesis opens either a proposition or an expression: try the proposition.
        if self.peek() == Some(&Token::Op("(")) {
            let start = self.at;
            self.at += 1;
            if let Ok(p) = self.implication()
                && self.eat_op(")")
                && !self.at_comparison()
            {
                return Ok(p);
            }
            self.at = start;
        }
        self.comparison()
    }

    fn at_comparison(&self) -> bool {
        matches!(self.peek(), Some(Token::Op(op)) if comparison(op).is_some())
    }

    fn comparison(&mut self) -> Result<Prop, String> {
        let mut left = self.sum()?;
        let mut links = Vec::new();
        while let Some(Token::Op(op)) = self.peek() {
            let Some(cmp) = comparison(op) else { break };
            self.at += 1;
            let right = self.sum()?;
            links.push(Prop::Relation(cmp, left, right.clone()));
            left = right;
        }
        match links.len() {
            0 => Err(format!("expected a comparison at token {}", self.at + 1)),
            1 => Ok(links.remove(0)),
            _ => Ok(Prop::And(links)),
        }
    }

    fn sum(&mut self) -> Result<Expr, String> {
        let mut acc = self.product()?;
        loop {
            if self.eat_op("+") {
                acc = Expr::Add(Box::new(acc), Box::new(self.product()?));
            } else if self.eat_op("-") {
                acc = Expr::Sub(Box::new(acc), Box::new(self.product()?));
            } else {
                return Ok(acc);
            }
        }
    }

    fn product(&mut self) -> Result<Expr, String> {
        let mut acc = self.unary()?;
        loop {
            if self.eat_op("*") {
                acc = Expr::Mul(Box::new(acc), Box::new(self.unary()?));
            } else if self.eat_op("/") {
                acc = Expr::Div(Box::new(acc), Box::new(self.unary()?));
            } else {
                return Ok(acc);
            }
        }
    }

    fn unary(&mut self) -> Result<Expr, String> {
        if self.eat_op("-") {
            return Ok(Expr::Neg(Box::new(self.unary()?)));
        }
        self.power()
    }

    fn power(&mut self) -> Result<Expr, String> {
        let base = self.atom()?;
        if self.eat_op("^") {
            return match self.peek() {
                Some(Token::Int(n)) if (1..=16).contains(n) => {
                    let n = *n as u32;
                    self.at += 1;
                    Ok(Expr::Pow(Box::new(base), n))
                }
                _ => Err(format!(
                    "expected an exponent 1..16 at token {}",
                    self.at + 1
                )),
            };
        }
        Ok(base)
    }

    fn atom(&mut self) -> Result<Expr, String> {
        match self.peek().cloned() {
            Some(Token::Int(n)) => {
                self.at += 1;
                Ok(Expr::Int(n))
            }
            Some(Token::Name(name)) if !["and", "or", "not"].contains(&name.as_str()) => {
                self.at += 1;
                Ok(Expr::Name(name))
            }
            Some(Token::Op("(")) => {
                self.at += 1;
                let e = self.sum()?;
                self.expect_op(")")?;
                Ok(e)
            }
            _ => Err(format!(
                "expected a number, a name or '(' at token {}",
                self.at + 1
            )),
        }
    }
}

fn comparison(op: &str) -> Option<Relation> {
    Some(match op {
        "=" => Relation::Eq,
        "!=" => Relation::Ne,
        "<" => Relation::Lt,
        "<=" => Relation::Le,
        ">" => Relation::Gt,
        ">=" => Relation::Ge,
        _ => return None,
    })
}

/// Parses a proposition.
///
/// # Errors
/// [`ParseError`] naming the text and the token where it goes wrong.
///
/// # Examples
/// ```
/// use rodimpact::claims::export::{parse, Prop};
/// let p = parse("0 <= a <= l and not v = 0").unwrap();
/// assert!(matches!(p, Prop::And(ref terms) if terms.len() == 2));
/// assert!(parse("a <").is_err());
/// ```
pub fn parse(text: &str) -> Result<Prop, ParseError> {
    let fail = |reason: String| ParseError {
        text: text.to_string(),
        reason,
    };
    let mut parser = Parser {
        tokens: tokens(text).map_err(fail)?,
        at: 0,
    };
    let prop = parser.implication().map_err(fail)?;
    if parser.at != parser.tokens.len() {
        return Err(fail(format!("unexpected token {}", parser.at + 1)));
    }
    Ok(prop)
}

impl Expr {
    fn names(&self, out: &mut BTreeSet<String>) {
        match self {
            Expr::Int(_) => {}
            Expr::Name(n) => {
                out.insert(n.clone());
            }
            Expr::Neg(x) | Expr::Pow(x, _) => x.names(out),
            Expr::Add(x, y) | Expr::Sub(x, y) | Expr::Mul(x, y) | Expr::Div(x, y) => {
                x.names(out);
                y.names(out);
            }
        }
    }
}

impl Prop {
    /// Every name the proposition uses, in order.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::export::parse;
    /// let names: Vec<String> = parse("v < 0 or V*a > 1").unwrap().names().into_iter().collect();
    /// assert_eq!(names, ["V", "a", "v"]);
    /// ```
    pub fn names(&self) -> BTreeSet<String> {
        let mut out = BTreeSet::new();
        self.collect_names(&mut out);
        out
    }

    fn collect_names(&self, out: &mut BTreeSet<String>) {
        match self {
            Prop::Relation(_, x, y) => {
                x.names(out);
                y.names(out);
            }
            Prop::Not(p) => p.collect_names(out),
            Prop::And(ps) | Prop::Or(ps) => ps.iter().for_each(|p| p.collect_names(out)),
            Prop::Implies(p, q) => {
                p.collect_names(out);
                q.collect_names(out);
            }
        }
    }

    /// Whether the proposition is built from equations with `and`/`or` only (an identity a
    /// computer-algebra system decides by cancelling).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::export::parse;
    /// assert!(parse("v = 0 and (V = 1 or V = 2)").unwrap().is_equational());
    /// assert!(!parse("v < 0").unwrap().is_equational());
    /// ```
    pub fn is_equational(&self) -> bool {
        match self {
            Prop::Relation(op, _, _) => *op == Relation::Eq,
            Prop::And(ps) | Prop::Or(ps) => ps.iter().all(Prop::is_equational),
            Prop::Not(_) | Prop::Implies(..) => false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn name(n: &str) -> Expr {
        Expr::Name(n.into())
    }

    #[test]
    fn precedence_and_associativity() {
        let Prop::Relation(Relation::Eq, lhs, rhs) = parse("x = a - b - c*d^2/e").unwrap() else {
            panic!("a comparison")
        };
        assert_eq!(lhs, name("x"));
        let cd2 = Expr::Mul(
            Box::new(name("c")),
            Box::new(Expr::Pow(Box::new(name("d")), 2)),
        );
        let expected = Expr::Sub(
            Box::new(Expr::Sub(Box::new(name("a")), Box::new(name("b")))),
            Box::new(Expr::Div(Box::new(cd2), Box::new(name("e")))),
        );
        assert_eq!(rhs, expected);
    }

    #[test]
    fn logic_binds_not_and_or_implies_in_that_order() {
        let p = parse("x > 0 => not y = 0 and z < 1 or w = 2").unwrap();
        let Prop::Implies(hyp, concl) = p else {
            panic!("an implication")
        };
        assert!(matches!(*hyp, Prop::Relation(Relation::Gt, _, _)));
        let Prop::Or(terms) = *concl else {
            panic!("a disjunction")
        };
        assert!(matches!(&terms[0], Prop::And(t) if matches!(t[0], Prop::Not(_))));
    }

    #[test]
    fn parentheses_group_propositions_and_expressions() {
        assert!(matches!(
            parse("(x > 0 or y > 0) and z = 1").unwrap(),
            Prop::And(_)
        ));
        assert!(matches!(
            parse("(x + 1)*2 > y").unwrap(),
            Prop::Relation(Relation::Gt, Expr::Mul(..), _)
        ));
    }

    #[test]
    fn malformed_statements_are_refused_with_the_reason() {
        for bad in [
            "x",
            "x = ",
            "x = (y",
            "x ^ y = 1",
            "x = y)",
            "x # y",
            "x ^ 0 = 1",
        ] {
            assert!(parse(bad).is_err(), "{bad}");
        }
        assert!(
            parse("x = 1 1")
                .unwrap_err()
                .reason
                .contains("unexpected token")
        );
    }
}
