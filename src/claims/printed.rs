//! The paper's formulas as printed: the data the claims compare with independent computations.

use super::Formula;

/// The formulas as the paper prints them: the data the claims compare with independent
/// computations. [`Paper::as_printed`] is the paper; tests mutate a field to check that the
/// verifier notices. Each is a [`Formula`], so certificates show it as printed.
#[derive(Debug, Clone, PartialEq)]
pub struct Paper {
    /// Eq. (v): `v = -(1 - m/M - m a^2/I)/D v0`.
    pub v: Formula,
    /// Eq. (V): `V = (2m/M)/D v0`.
    pub big_v: Formula,
    /// Eq. (omega): `omega = (2ma/I)/D v0`.
    pub omega: Formula,
    /// Eq. (maximal-a-general), squared: `a*^2 = (M + m) I/(m M)`.
    pub a_star_squared: Formula,
    /// Eq. (inertia-homogeneous): `I = M (2l)^2/12`.
    pub uniform_inertia: Formula,
    /// Eq. (maximal-a-homogeneous), squared: `a*^2 = (M + m) l^2/(3m)`.
    pub a_star_uniform_squared: Formula,
    /// The mass ratio M/m at which a* reaches the end of a uniform rod: 2.
    pub threshold: Formula,
    /// Eq. (impulse-linear): `I_lin = 2 m v0/(1 + m/M + 3 m a^2/(M l^2))`.
    pub impulse_linear: Formula,
    /// Eq. (maximal-a-gyration), squared: `a*^2 = (M + m) r_G^2/m`.
    pub a_star_gyration_squared: Formula,
}

impl Paper {
    /// The formulas exactly as printed in the paper (`D = 1 + m/M + m a^2/I` written out).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::Paper;
    /// let paper = Paper::as_printed();
    /// assert_eq!(paper.threshold.to_string(), "2");
    /// assert_eq!(paper.omega.to_string(), "(2*m*a/I)/(1 + m/M + m*a^2/I)*v0");
    /// assert_eq!(paper.omega.value().to_string(), "2*M*a*m*v0/(M*a^2*m + I*M + I*m)");
    /// ```
    pub fn as_printed() -> Paper {
        let f = Formula::sym;
        let (m, big_m, inertia, a, v0, l, r) =
            (f("m"), f("M"), f("I"), f("a"), f("v0"), f("l"), f("r_G"));
        let (one, two, three) = (Formula::int(1), Formula::int(2), Formula::int(3));
        let m_over_big_m = m.clone() / &big_m;
        let m_a2_over_i = m.clone() * &a.pow(2) / &inertia;
        let d = one.clone() + &m_over_big_m + &m_a2_over_i;
        Paper {
            v: -((one.clone() - &m_over_big_m - &m_a2_over_i) / &d * &v0),
            big_v: (two.clone() * &m / &big_m) / &d * &v0,
            omega: (two.clone() * &m * &a / &inertia) / &d * &v0,
            a_star_squared: (big_m.clone() + &m) * &inertia / &(m.clone() * &big_m),
            uniform_inertia: big_m.clone() * &(two.clone() * &l).pow(2) / &Formula::int(12),
            a_star_uniform_squared: (big_m.clone() + &m) / &(three.clone() * &m) * &l.pow(2),
            threshold: two.clone(),
            impulse_linear: two * &m * &v0
                / &(one + &m_over_big_m + &(three * &m * &a.pow(2) / &(big_m.clone() * &l.pow(2)))),
            a_star_gyration_squared: (big_m + &m) / &m * &r.pow(2),
        }
    }
}
