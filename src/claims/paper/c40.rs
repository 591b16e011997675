use crate::claims::dsl::*;
use crate::field::ratfunc::Point;

pub(super) const ENTRY: Entry = Entry {
    id: "C40",
    location: "Eq. (inertia-general)",
    group: Group::Inhomogeneous,
    statement: "I = M r_G^2; hidden: r_G <= l, with equality only when all the mass is at the ends",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Unstated(
    "r_G <= l rests on an integral over the mass density (and equality on a limit of densities), not a statement about finitely many reals",
);

fn formalise(_paper: &Paper) -> Formalised {
    // A symmetric polynomial density c0 + c2 y^2 + c4 y^4 (c_i >= 0).
    let poly = [("c0", 0), ("c2", 2), ("c4", 4)];
    let lambda = density(&poly);
    let (mass, inertia) = (symmetric_moment(&poly, 0), symmetric_moment(&poly, 2));
    let l2 = sq(&sym("l"));
    let (l, h) = (sym("l"), sym("h"));
    // Uniform density c on the two end segments of width h.
    let end_mass = sym("c") * &h;
    let end_inertia =
        sym("c") * &(l2.clone() * &h - &(l.clone() * &sq(&h)) + &(pow(&h, 3) / k(3, 1)));
    let right = (l.clone() - &h, l.clone());
    let left = (-l.clone(), h.clone() - &l);
    let end_rg2 = end_inertia.clone() / end_mass.clone();
    Formalised {
        formal: "For any mass distribution dm on [-l, l] of total mass M > 0, r_G is defined by I = M r_G^2 \
                 with I = integral y^2 dm; then M l^2 - I = integral (l^2 - y^2) dm >= 0, and since \
                 l^2 - y^2 > 0 on (-l, l), equality holds iff all the mass sits at y = +-l (the ideal \
                 dumbbell). This measure argument is stated, not machine-checked in general; the \
                 certificates check it for two families: the polynomial densities c0 + c2 y^2 + c4 y^4 \
                 (c_i >= 0), where r_G^2 <= (5/7) l^2, and a uniform density on the end segments of \
                 width h in (0, l], where l^2 - r_G^2 = l h - h^2/3 > 0 tends to 0 as h -> 0 (the \
                 dumbbell, which the point masses M/2 at +-l attain)."
            .into(),
        reason: "M l^2 - I = integral (l^2 - y^2) dm >= 0, zero only for mass at y = +-l; checked exactly for a polynomial family and for end-loaded rods tending to the dumbbell".into(),
        decision: Decision::Proved(vec![
            integral(
                "polynomial density c0 + c2 y^2 + c4 y^4: mass M",
                lambda.clone(),
                0,
                whole_rod(),
                mass.clone(),
            ),
            integral(
                "polynomial density: moment of inertia I about the centre",
                lambda.clone(),
                2,
                whole_rod(),
                inertia.clone(),
            ),
            integral(
                "polynomial density: integral of (l^2 - y^2) dm equals M l^2 - I",
                lambda * &(l2.clone() - &sq(&sym("y"))),
                0,
                whole_rod(),
                l2.clone() * &mass - &inertia,
            ),
            positive("polynomial density (c_i >= 0): (5/7) l^2 M - I >= 0, i.e. M l^2 - I >= (2/7) M l^2 > 0, so r_G^2 <= (5/7) l^2 < l^2", k(5, 7) * &l2 * &mass - &inertia, false, &[], &["l"], &["c0", "c2", "c4"], sum([
                    prod([pc(16, 21), ps("c0"), ps("l"), ps("l"), ps("l")]),
                    prod([pc(8, 105), ps("c2"), ps("l"), ps("l"), ps("l"), ps("l"), ps("l")]),
                ])),
            integral(
                "end-loaded rod (density c on [l - h, l]): mass of the right segment",
                sym("c"),
                0,
                right.clone(),
                end_mass.clone(),
            ),
            integral(
                "end-loaded rod (density c on [-l, -l + h]): mass of the left segment",
                sym("c"),
                0,
                left.clone(),
                end_mass,
            ),
            integral(
                "end-loaded rod: moment of inertia of the right segment",
                sym("c"),
                2,
                right,
                end_inertia.clone(),
            ),
            integral(
                "end-loaded rod: moment of inertia of the left segment",
                sym("c"),
                2,
                left,
                end_inertia,
            ),
            positive("end-loaded rod, 0 < h <= l: l^2 - r_G^2 = l h - h^2/3 > 0 (l = h + s, s >= 0)", l2.clone() - &end_rg2, true, &[("l", h.clone() + &sym("s"))], &["c", "h"], &["s"], sum([prod([pc(2, 3), ps("h"), ps("h")]), prod([ps("h"), ps("s")])])),
            Certificate::limit(
                "end-loaded rod: r_G^2 -> l^2 as the end segments shrink (h -> 0+), the dumbbell limit",
                end_rg2,
                "h",
                Point::Zero,
                l2.clone(),
            ),
            Certificate::identity_at(
                "dumbbell (point masses M/2 at y = -l and y = l): I = sum of (M/2) y^2 equals M r_G^2 with r_G = l",
                f("M") / &Formula::int(2) * &(-f("l")).pow(2) + &(f("M") / &Formula::int(2) * &f("l").pow(2)),
                f("M") * &f("r_G").pow(2),
                &[("r_G", l)],
            ),
        ]),
    }
}
