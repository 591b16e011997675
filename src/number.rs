//! TEMPORARY shim (replaced by the number branch).
use crate::error::ErrorKind;
use crate::field::Q;
/// limit
pub const MAX_DIGITS: usize = 10_000;
/// limit
pub const MAX_EXPONENT: u64 = 10_000;
/// parse
pub fn parse(text: &str) -> Result<Q, ErrorKind> {
    let t = text.trim();
    if t.is_empty() {
        return Err(ErrorKind::Empty);
    }
    if t.contains('/') {
        let (a, b) = t.split_once('/').unwrap();
        let a = parse(a)?;
        let b = parse(b)?;
        if b == Q::from_integer(0.into()) {
            return Err(ErrorKind::DivisionByZero);
        }
        return Ok(a / b);
    }
    if let Some((m, e)) = t.split_once(['e', 'E']) {
        let e: i32 = e.parse().map_err(|_| ErrorKind::Malformed(t.into()))?;
        if e.unsigned_abs() as u64 > MAX_EXPONENT {
            return Err(ErrorKind::ExponentTooLarge {
                limit: MAX_EXPONENT,
            });
        }
        let m = parse(m)?;
        let p = Q::from_integer(num_bigint::BigInt::from(10).pow(e.unsigned_abs()));
        return Ok(if e < 0 { m / p } else { m * p });
    }
    let (i, f) = t.split_once('.').unwrap_or((t, ""));
    let s = format!("{i}{f}");
    let n: num_bigint::BigInt = s.parse().map_err(|_| ErrorKind::Malformed(t.into()))?;
    Ok(Q::new(n, num_bigint::BigInt::from(10).pow(f.len() as u32)))
}
/// decimal
pub fn decimal(value: &Q, digits: usize) -> String {
    let _ = digits;
    format!("{:.20}", num_traits::ToPrimitive::to_f64(value).unwrap())
}
/// bounds
pub fn sqrt_bounds(x: &Q, digits: usize) -> (Q, Q) {
    let _ = digits;
    (x.clone(), x.clone())
}
/// surd
pub fn surd(x: &Q) -> String {
    format!("sqrt({x})")
}
/// dsqrt
pub fn decimal_sqrt(x: &Q, digits: usize) -> String {
    decimal(x, digits)
}
