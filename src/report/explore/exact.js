"use strict";
// Exact arithmetic for the page: rationals on BigInt, and numbers x + y*sqrt(r) with r
// square-free (a* and the values at a*), and their spelling as rodimpact spells them (field::notation):
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

  const ZERO = new Q(0n);

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

  /**
   * x + y*sqrt(r): x, y rational, r a square-free integer > 1 (r = 1 and y = 0 for a rational).
   * The page's one number type for answers: the optimum a* = sqrt(A) of a rational A, and every
   * value of a scene struck at a* (x^2 = A is rational again), lives in Q(sqrt r). Operations
   * take a Quad or a Q; two different radicands never meet (an error if they would).
   */
  class Quad {
    constructor(x, y = ZERO, r = 1n) {
      if (y.isZero() || r === 1n) {
        this.x = r === 1n ? x.add(y) : x;
        this.y = ZERO;
        this.r = 1n;
      } else {
        this.x = x;
        this.y = y;
        this.r = r;
      }
    }
    /** A Q (or a Quad, returned as it is) as a Quad. */
    static from(v) { return v instanceof Quad ? v : new Quad(v); }
    /** The square root of a rational x >= 0: sqrt(n/d) = sqrt(n d)/d, square factors out. */
    static sqrt(x) {
      if (x.sign() < 0) throw new RangeError("square root of a negative number");
      const [s, r] = squareOut(x.n * x.d);
      return r === 1n ? new Quad(new Q(s, x.d)) : new Quad(ZERO, new Q(s, x.d), r);
    }
    /** The radicand shared with `o`. */
    field(o) {
      if (this.r === 1n || this.r === o.r) return o.r;
      if (o.r === 1n) return this.r;
      throw new RangeError(`sqrt(${this.r}) and sqrt(${o.r}) in one expression`);
    }
    add(v) { const o = Quad.from(v); return new Quad(this.x.add(o.x), this.y.add(o.y), this.field(o)); }
    sub(v) { return this.add(Quad.from(v).neg()); }
    neg() { return new Quad(this.x.neg(), this.y.neg(), this.r); }
    mul(v) {
      const o = Quad.from(v);
      const r = this.field(o);
      const x = this.x.mul(o.x).add(this.y.mul(o.y).mul(new Q(r)));
      return new Quad(x, this.x.mul(o.y).add(this.y.mul(o.x)), r);
    }
    div(v) {
      // (x + y sqrt r)^-1 = (x - y sqrt r)/(x^2 - y^2 r); the denominator is 0 only for 0.
      const o = Quad.from(v);
      const r = this.field(o);
      const norm = o.x.mul(o.x).sub(o.y.mul(o.y).mul(new Q(r)));
      if (norm.isZero()) throw new RangeError("division by zero");
      return this.mul(new Quad(o.x.div(norm), o.y.neg().div(norm), r));
    }
    isZero() { return this.x.isZero() && this.y.isZero(); }
    isRational() { return this.y.isZero(); }
    /** The rational value (a programming error when there is a root). */
    rational() {
      if (!this.isRational()) throw new RangeError(`${this} is not rational`);
      return this.x;
    }
    /** -1, 0 or 1, exactly: when x and y sqrt r differ in sign, the larger square wins. */
    sign() {
      const a = this.x.sign();
      const b = this.y.sign();
      if (b === 0 || a === b) return a || b;
      if (a === 0) return b;
      return this.x.mul(this.x).cmp(this.y.mul(this.y).mul(new Q(this.r))) > 0 ? a : b;
    }
    cmp(v) { return this.sub(v).sign(); }
    abs() { return this.sign() < 0 ? this.neg() : this; }
    toNumber() { return this.x.toNumber() + this.y.toNumber() * Math.sqrt(Number(this.r)); }
    /** Spelled as rodimpact spells it (field::notation::surd): ASCII, which parses back. */
    toString() { return this.spell(true); }
    /** Spelled for people: `√6/3`, `−1 + 5√6/12`, true minus signs. */
    pretty() { return this.spell(false); }
    spell(ascii) {
      const minus = ascii ? "-" : "−";
      const rational = ascii ? this.x.toString() : this.x.pretty();
      if (this.isRational()) return rational;
      const y = this.y;
      const num = abs(y.n);
      const term = ascii ? (num === 1n ? `sqrt(${this.r})` : `${num}*sqrt(${this.r})`) : `${num === 1n ? "" : num}√${this.r}`;
      const part = y.d === 1n ? term : `${term}/${y.d}`;
      if (this.x.isZero()) return (y.sign() < 0 ? minus : "") + part;
      return `${rational} ${y.sign() < 0 ? minus : "+"} ${part}`;
    }
    /** The value to `digits` significant digits (sqrt r from an exact integer square root). */
    decimal(digits = 6) {
      if (this.isRational()) return this.x.decimal(digits);
      const scale = 10n ** 40n;
      const root = isqrt(this.r * scale * scale); // floor(sqrt(r) 10^40)
      const { x, y } = this;
      return decimalOf(x.n * y.d * scale + y.n * x.d * root, x.d * y.d * scale, digits);
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

  return { Q, Quad, parse, decimalOf };
})();
