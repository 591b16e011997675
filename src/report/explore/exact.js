"use strict";
// Exact arithmetic for the page: rationals on BigInt, square roots of rationals as surds
// c*sqrt(r) with r square-free, and their spelling as rodimpact spells them (field::notation):
// `sqrt(6)/3`, `2*sqrt(6)/5`, `5*sqrt(5)` in ASCII, `√6/3` in Unicode.

const Exact = (() => {
  const abs = (x) => (x < 0n ? -x : x);
  const gcd = (a, b) => {
    a = abs(a);
    b = abs(b);
    while (b) [a, b] = [b, a % b];
    return a;
  };

  class Q {
    constructor(n, d = 1n) {
      if (d === 0n) throw new RangeError("division by zero");
      if (d < 0n) {
        n = -n;
        d = -d;
      }
      const g = gcd(n, d) || 1n;
      this.n = n / g;
      this.d = d / g;
    }
    static of(n, d = 1) { return new Q(BigInt(n), BigInt(d)); }
    add(o) { return new Q(this.n * o.d + o.n * this.d, this.d * o.d); }
    sub(o) { return new Q(this.n * o.d - o.n * this.d, this.d * o.d); }
    mul(o) { return new Q(this.n * o.n, this.d * o.d); }
    div(o) { return new Q(this.n * o.d, this.d * o.n); }
    neg() { return new Q(-this.n, this.d); }
    abs() { return new Q(abs(this.n), this.d); }
    sign() { return this.n > 0n ? 1 : this.n < 0n ? -1 : 0; }
    cmp(o) { return this.sub(o).sign(); }
    isZero() { return this.n === 0n; }
    toNumber() { return Number(this.n) / Number(this.d); }
    /** `p/q` or `p`, as rodimpact prints a rational. */
    toString() { return this.d === 1n ? `${this.n}` : `${this.n}/${this.d}`; }
    /** Unicode spelling for people: `-3/2`, with a true minus sign. */
    pretty() { return this.toString().replace("-", "−"); }
    /** The value to `digits` significant digits, rounded half away from zero. */
    decimal(digits = 6) { return decimalOf(this.n, this.d, digits); }
  }

  // n/d (d > 0) to `digits` significant digits, as a plain decimal string.
  function decimalOf(n, d, digits) {
    if (n === 0n) return "0";
    const negative = n < 0n;
    n = abs(n);
    // Find the exponent: 10^k <= n/d < 10^(k+1).
    let k = n.toString().length - d.toString().length;
    const ten = (e) => 10n ** BigInt(e);
    const atLeast = (e) => (e >= 0 ? n >= d * ten(e) : n * ten(-e) >= d);
    if (!atLeast(k)) k -= 1;
    // Scaled integer with `digits` digits, rounded half up.
    const shift = digits - 1 - k;
    const num = shift >= 0 ? n * ten(shift) : n;
    const den = shift >= 0 ? d : d * ten(-shift);
    let q = num / den;
    if (2n * (num % den) >= den) q += 1n;
    let s = q.toString();
    const point = s.length - shift; // position of the decimal point in s
    // Rounding carried into a new digit (9.996 -> 10.00): drop the last zero.
    if (s.length > digits) s = s.slice(0, digits);
    let out;
    if (point <= 0) out = "0." + "0".repeat(-point) + s;
    else if (point >= s.length) out = s + "0".repeat(point - s.length);
    else out = s.slice(0, point) + "." + s.slice(point);
    return (negative ? "−" : "") + out;
  }

  const isqrt = (n) => {
    if (n < 2n) return n;
    // Newton's iteration from above (2^ceil(bits/2) >= sqrt(n)) decreases to the exact floor.
    let x = 1n << BigInt(Math.ceil(n.toString(2).length / 2));
    for (;;) {
      const y = (x + n / x) >> 1n;
      if (y >= x) return x;
      x = y;
    }
  };

  /** n = s^2 * r with r square-free (trial division to 10^5, then a square test). */
  function squareOut(n) {
    let s = 1n;
    let r = n;
    for (let p = 2n; p <= 100000n && p * p <= r; p += p === 2n ? 1n : 2n) {
      while (r % (p * p) === 0n) {
        r /= p * p;
        s *= p;
      }
    }
    const t = isqrt(r);
    if (t * t === r) return [s * t, 1n];
    return [s, r];
  }

  /** c * sqrt(r): r a square-free positive integer (1 for a rational), c rational. */
  class Surd {
    constructor(c, r) {
      this.c = c;
      this.r = r;
    }
    /** The square root of a rational x >= 0: sqrt(n/d) = sqrt(n d)/d. */
    static sqrt(x) {
      if (x.sign() < 0) throw new RangeError("square root of a negative number");
      const [s, r] = squareOut(x.n * x.d);
      return new Surd(new Q(s, x.d), r);
    }
    static rational(q) { return new Surd(q, 1n); }
    isRational() { return this.r === 1n || this.c.isZero(); }
    scale(q) { return new Surd(this.c.mul(q), this.r); }
    toNumber() { return this.c.toNumber() * Math.sqrt(Number(this.r)); }
    /** Compare with a rational exactly. */
    cmpQ(q) {
      // c sqrt(r) vs q: compare signs, then squares.
      const a = this.c.sign();
      const b = q.sign();
      if (a !== b) return a > b ? 1 : -1;
      const lhs = this.c.mul(this.c).mul(Q.of(this.r));
      const c = lhs.cmp(q.mul(q));
      return a >= 0 ? c : -c;
    }
    /** Spelled as rodimpact spells it: `ascii` (parses back) or Unicode. */
    spell(ascii) {
      if (this.isRational()) {
        const q = this.r === 1n ? this.c : Q.of(0);
        return ascii ? q.toString() : q.pretty();
      }
      const y = this.c;
      const num = abs(y.n);
      let term;
      if (ascii) term = num === 1n ? `sqrt(${this.r})` : `${num}*sqrt(${this.r})`;
      else term = `${num === 1n ? "" : num}√${this.r}`;
      const part = y.d === 1n ? term : `${term}/${y.d}`;
      return (y.sign() < 0 ? (ascii ? "-" : "−") : "") + part;
    }
    /** The value to `digits` significant digits (from an exact integer square root). */
    decimal(digits = 6) {
      if (this.isRational()) return this.c.decimal(digits);
      const scale = 10n ** 30n;
      const root = isqrt(this.r * scale * scale); // floor(sqrt(r) 10^30)
      return decimalOf(this.c.n * root, this.c.d * scale, digits);
    }
  }

  const MAX_DIGITS = 30;
  /**
   * An exact rational from what a student types: `3/2`, `1.5`, `-0.25`, `1.5e-3`, `2/0.5`.
   * Returns a Q, or throws an Error whose message says what is wrong.
   */
  function parse(text) {
    const t = text.trim();
    if (t === "") throw new Error("empty");
    const parts = t.split("/");
    if (parts.length > 2) throw new Error("at most one '/'");
    const one = (s) => {
      const m = /^([+-]?)(\d*)(?:\.(\d*))?(?:[eE]([+-]?\d{1,3}))?$/.exec(s.trim());
      if (!m || (m[2] === "" && (m[3] === undefined || m[3] === ""))) throw new Error(`'${s.trim()}' is not a number`);
      const digits = (m[2] + (m[3] || "")).replace(/^0+/, "");
      if (digits.length > MAX_DIGITS) throw new Error(`more than ${MAX_DIGITS} digits`);
      const exp = BigInt(m[4] || "0") - BigInt((m[3] || "").length);
      if (exp > 60n || exp < -60n) throw new Error("exponent beyond ±60");
      let n = BigInt(m[2] + (m[3] || "") || "0");
      if (m[1] === "-") n = -n;
      return exp >= 0n ? new Q(n * 10n ** exp) : new Q(n, 10n ** -exp);
    };
    const num = one(parts[0]);
    if (parts.length === 1) return num;
    const den = one(parts[1]);
    if (den.isZero()) throw new Error("division by zero");
    return num.div(den);
  }

  return { Q, Surd, parse, decimalOf };
})();
