use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "X29",
    location: BEYOND,
    group: Group::Beyond,
    statement: "Galilean invariance: a rod sliding with (V0, Vt0) before the impact gives, relative to that frame, exactly the answer of the rod at rest struck with (v0 - V0, v0t - Vt0): the velocities shift by the frame's, omega, the disc's spin, both impulses and the contact do not change",
    formalise,
    export: EXPORT,
};

// The claim for z3 and SymPy: a rod drifting with (V0, Vt0) and a sticking contact; the
// impulses depend on the relative approach only and every velocity changes as at rest.
const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Free, ExportLaw::Restitution)
            .oblique(Friction::Stick)
            .moving(),
        &[
            Check::holds(
                "disc: the rod at rest's answer in the relative velocities (v0 - V0, v0t - Vt0): J, Jt and omega from the relative approach, each velocity shifted by the frame's",
                "J*(1/m + 1/M + a^2/I) = (1 + e)*(v0 - V0) and Jt*(3/m + 1/M) = v0t - Vt0 + w*rd and I*omega = a*J and v - V0 = v0 - V0 - J/m and vt - Vt0 = v0t - Vt0 - Jt/m and V - V0 = J/M and Vt - Vt0 = Jt/M and spin = w - 2*Jt/(m*rd)",
            )
            .given(&["rd > 0"]),
            Check::holds(
                "point (rd = 0): the rod at rest's answer in the relative velocities, k_t = 1/m + 1/M",
                "J*(1/m + 1/M + a^2/I) = (1 + e)*(v0 - V0) and Jt*(1/m + 1/M) = v0t - Vt0 and I*omega = a*J and v - V0 = v0 - V0 - J/m and vt - Vt0 = v0t - Vt0 - Jt/m and V - V0 = J/M and Vt - Vt0 = Jt/M",
            )
            .given(&["rd = 0"]),
            Check::fails(
                "reading: the rod's drift does not enter the impulse (J k_n = (1 + e) v0); refuted",
                "J*(1/m + 1/M + a^2/I) = (1 + e)*v0",
            )
            .given(&["rd = 0"]),
        ],
    )
    .partly("the sliding contact (the same invariance) is certified by rodimpact only: one scene per exported statement"),
);

fn formalise(_paper: &Paper) -> Formalised {
    let rod = oblique_rod();
    let rest = oblique(true);
    let moving = ObliqueParams {
        rod_before: RodMotion {
            v: sym("V0"),
            vt: sym("Vt0"),
            omega: int(0),
        },
        ..rest.clone()
    };
    let in_frame = [
        ("v0", sym("v0") - &sym("V0")),
        ("v0t", sym("v0t") - &sym("Vt0")),
    ];
    let mut certs = Vec::new();
    for contact in [Mode::Stick, Mode::Slide { forward: true }] {
        let there = oblique_solved(&rod, &moving, contact);
        let here = oblique_solved(&rod, &rest, contact);
        let spin = |o: &ObliqueOutcome<crate::field::RatFn>| o.after.spin.clone().expect("a disc");
        let rows = [
            ("v", there.after.v.clone(), "V0", here.after.v.clone()),
            ("vt", there.after.vt.clone(), "Vt0", here.after.vt.clone()),
            (
                "V",
                there.after.rod.v.clone(),
                "V0",
                here.after.rod.v.clone(),
            ),
            (
                "Vt",
                there.after.rod.vt.clone(),
                "Vt0",
                here.after.rod.vt.clone(),
            ),
            (
                "omega",
                there.after.rod.omega.clone(),
                "",
                here.after.rod.omega.clone(),
            ),
            ("spin", spin(&there), "", spin(&here)),
            ("J", there.impulse.clone(), "", here.impulse.clone()),
            (
                "Jt",
                there.tangential_impulse.clone(),
                "",
                here.tangential_impulse.clone(),
            ),
        ];
        for (name, moving_value, shift, rest_value) in rows {
            let lhs = if shift.is_empty() {
                n(name, moving_value)
            } else {
                n(name, moving_value) - &f(shift)
            };
            let what = if shift.is_empty() {
                format!("{name} (moving rod) = {name} (rod at rest, relative velocities)")
            } else {
                format!("{name} (moving rod) - {shift} = {name} (rod at rest, relative velocities)")
            };
            certs.push(Certificate::identity(
                format!("{}: {what}", case(contact)),
                lhs,
                n(&format!("{name}_rest"), subs(&rest_value, &in_frame)),
            ));
        }
    }
    proved(
        "Free rod (m, M, I > 0, any a, e), solid disc projectile (radius r, spin w, velocity (v0, v0t)), \
         friction mu_f; the rod's centre moves with (V0, Vt0) before the impact and does not turn. For the \
         sticking and the sliding contact, the solver's answer minus the frame velocity equals the \
         solver's answer for the rod at rest with the projectile at (v0 - V0, v0t - Vt0), identically; \
         omega, the spin and both impulses are equal. Stick or slide is decided by relative velocities \
         only, so the same case applies in both frames.",
        "the oblique solver commutes with a change of inertial frame, identically in every symbol",
        certs,
    )
}
