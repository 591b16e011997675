"use strict";
// The impact, exactly, in units m = l = v0 = 1 (the page's sliders are ratios): a projectile of
// mass 1 and speed 1 strikes a rod of mass M, half-length 1, moment of inertia I = k M about
// its centre (k = 1/3 uniform, 1 dumbbell, (r_G/l)^2), at a from the centre, with restitution e;
// the rod free, or on a fixed pivot at p along it. Signs as in rodimpact's docs/conventions.md:
// omega > 0 when the struck point moves forward for a > 0 (a > p on a pivot).
//
// Both cases share one shape: with the lever arm x (x = a free, x = a - p on a pivot) and
// A = I (M + m)/(m M) (free) or A = I_p/m (pivot, I_p = I + M p^2),
//   J = (1 + e) v0 / (1/m + x^2/I_eff),  omega = (1 + e) v0 x/(A + x^2),
// largest over the arm at x = sqrt(A) = a*, where omega_max = (1 + e) v0/(2 a*).

const Physics = (() => {
  const { Q, Quad } = Exact;
  const one = Q.of(1);
  const two = Q.of(2);
  const half = Q.of(1, 2);

  /** The moment of inertia's factor k (I = k M l^2) for a rod kind. */
  function inertiaFactor(kind, rg) {
    if (kind === "uniform") return Q.of(1, 3);
    if (kind === "dumbbell") return one;
    return rg.mul(rg);
  }

  /**
   * A = a*^2: (M + m) I/(m M) for a free rod, I_p/m = I + M p^2 on a pivot at p (Q values; the
   * optimum lever arm is sqrt(A), from the centre or from the pivot).
   */
  function aStarSquared(M, k, p) {
    const I = k.mul(M);
    return p === null ? I.mul(M.add(one)).div(M) : I.add(M.mul(p).mul(p));
  }

  /**
   * The exact answer for a scene { M, e, k, pivot } (Q values; pivot null for a free rod) struck
   * at a (a Q, or a Quad such as a*). Returns every quantity the page shows: the velocities,
   * impulses and energies as Quads (rational unless a is irrational), a* as a Quad, and the
   * optimum's rationals.
   */
  function solve(scene) {
    const { M, e, k } = scene;
    const a = Quad.from(scene.a);
    const p = scene.pivot;
    const I = k.mul(M);
    const pivoted = p !== null;
    const Ieff = pivoted ? I.add(M.mul(p).mul(p)) : I; // about the pivot, or the centre
    const x = pivoted ? a.sub(p) : a;
    // 1/m + (1/M for a free rod) + x^2/I_eff
    let k_n = x.mul(x).div(Ieff).add(one);
    if (!pivoted) k_n = k_n.add(one.div(M));
    const J = Quad.from(one.add(e)).div(k_n);
    const omega = J.mul(x).div(Ieff);
    const v = Quad.from(one).sub(J);
    const V = pivoted ? omega.mul(p).neg() : J.div(M); // the centre's velocity
    const pivotImpulse = pivoted ? V.mul(M).sub(J) : null;
    const K0 = Quad.from(half);
    const projectile = v.mul(v).mul(half);
    const translation = V.mul(V).mul(M).mul(half);
    const rotation = omega.mul(omega).mul(I).mul(half); // about the centre
    const lost = K0.sub(projectile).sub(translation).sub(rotation);
    // The optimum over the arm on the struck side.
    const A = aStarSquared(M, k, p);
    const side = x.sign() < 0 ? -1 : 1;
    const arm = pivoted ? (side > 0 ? one.sub(p) : one.add(p)) : one;
    const aStar = Quad.sqrt(A);
    const inside = A.cmp(arm.mul(arm)) <= 0;
    const omegaAt = (lever) => one.add(e).mul(lever).div(A.add(lever.mul(lever)));
    const omegaEnd = omegaAt(arm); // magnitude at the end of the arm
    // omega_max = (1 + e)/(2 sqrt(A)) = (1 + e) sqrt(A)/(2 A), or the end's when a* is beyond it.
    const omegaMax = inside ? aStar.mul(one.add(e).div(two.mul(A))) : Quad.from(omegaEnd);
    return {
      pivoted, I, Ieff, x, J, v, V, omega, pivotImpulse, K0, projectile, translation, rotation, lost,
      A, aStar, arm, side, inside, omegaEnd, omegaMax,
      // Struck exactly at a* (x^2 = A: the lever arm is a*).
      atAStar: x.mul(x).cmp(A) === 0,
      // The threshold mass ratio below which a* lies on the rod (free rod): M/m < 1/k - 1.
      threshold: pivoted ? null : one.div(k).sub(one),
    };
  }

  /**
   * The motion after the impact, in floats for the animation: positions at time t (t < 0: the
   * approach), whether the puck is stuck to the rod, and the time of the second impact, if the
   * projectile meets the rod again within `horizon` (l/v0 units), found by scanning and
   * bisection. At e = 0 the puck sticks (the paper's sticking collision): puck and rod turn as
   * one body at omega, about the pivot or about their common centre of mass, which moves on at
   * m v0/(M + m); otherwise each moves freely (the puck straight on at v).
   */
  function motion(scene, out, horizon = 12) {
    const a = scene.a.toNumber();
    const p = out.pivoted ? scene.pivot.toNumber() : 0;
    const v = out.v.toNumber();
    const V = out.V.toNumber();
    const w = out.omega.toNumber();
    const stuck = scene.e.isZero();
    const M = scene.M.toNumber();
    // The point about which a stuck pair turns: the pivot, or their centre of mass (moving).
    const hub = out.pivoted ? [0, p] : [0, a / (1 + M)];
    const hubSpeed = out.pivoted ? 0 : 1 / (1 + M);
    // (0, y) turned counter-clockwise by phi.
    const turned = (y, phi) => [-y * Math.sin(phi), y * Math.cos(phi)];
    const at = (t) => {
      if (t <= 0) return { ball: [t, a], centre: [0, 0], phi: 0 };
      const phi = -w * t; // counter-clockwise angle of the rod
      if (stuck || out.pivoted) {
        const [hx, hy] = [hub[0] + hubSpeed * t, hub[1]];
        const rim = (y) => { const [x, z] = turned(y - hub[1], phi); return [hx + x, hy + z]; };
        return { ball: stuck ? rim(a) : [v * t, a], centre: rim(0), phi };
      }
      return { ball: [v * t, a], centre: [V * t, 0], phi };
    };
    // Signed distance of the ball from the rod's line, and where along the rod it is.
    const relative = (t) => {
      const s = at(t);
      const dx = s.ball[0] - s.centre[0];
      const dy = s.ball[1] - s.centre[1];
      const normal = dx * Math.cos(s.phi) + dy * Math.sin(s.phi);
      const along = -dx * Math.sin(s.phi) + dy * Math.cos(s.phi);
      return { normal, along };
    };
    const touches = (r) => Math.abs(r.along) <= 1;
    let second = null;
    if (stuck) return { at, second, stuck };
    const dt = 1e-3;
    let before = relative(dt);
    for (let t = 2 * dt; t <= horizon; t += dt) {
      const now = relative(t);
      const crossed = (before.normal < 0) !== (now.normal < 0);
      if (crossed && (touches(now) || touches(before))) {
        let lo = t - dt;
        let hi = t;
        for (let i = 0; i < 60; i++) {
          const mid = (lo + hi) / 2;
          if ((relative(mid).normal < 0) === (before.normal < 0)) lo = mid;
          else hi = mid;
        }
        if (touches(relative(hi))) {
          second = hi;
          break;
        }
      }
      before = now;
    }
    return { at, second, stuck };
  }

  return { inertiaFactor, aStarSquared, solve, motion };
})();
