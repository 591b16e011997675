use crate::claims::dsl::*;
use crate::field::{Field, Q, RatFn};
use crate::impact::{Model, ModelOutcome, solve_several};
use crate::model::parse_toml;

pub(super) const ENTRY: Entry = Entry {
    id: "X38",
    location: BEYOND,
    group: Group::Beyond,
    statement: "Simultaneous Poisson impacts with Coulomb friction at two contacts can create kinetic energy: a uniform 1 x 3 box (mass 1) moving at (-1/2, -1/2) onto a plastic peg below it (e = 0) and an elastic peg beside it (e = 1), mu = 1/2 at both, has one Poisson answer, and it raises the energy from 1/4 to 7261587/25088000 (+15.8 %)",
    formalise,
    export: EXPORT,
};

// The claim for z3: the whole two-phase Poisson problem with Coulomb's law in each phase, in the
// box's velocities (vx, vy, w) after compression (c) and at the end (f). Contact 1, the peg
// below at (1/8, 0): normal (0, 1), tangent (-1, 0), arm r1 = (-3/8, -3/2) from the centre
// (1/2, 3/2). Contact 2, the peg beside at (0, 3/8): normal (1, 0), tangent (0, 1),
// r2 = (-1/2, -9/8). I = (1 + 9)/12 = 5/6. Compression impulses n, t; expansion p, q with
// p = e n + x (e = 0 at contact 1, 1 at contact 2).
const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Nothing, ExportLaw::Restitution),
        &[
            Check::exists(
                "the two-phase problem has a solution",
                "n1 >= 0 and n2 >= 0",
            ),
            Check::holds(
                "its solution is unique: the impulses found",
                "n1 = 83/280 and n2 = 141/280 and t1 = 83/560 and t2 = 141/560 and x1 = 0 and x2 = 0 and q1 = 0 and q2 = 141/560",
            ),
            Check::holds(
                "every solution raises the kinetic energy above 1/4 (the unique impulses as a lemma)",
                "(vxf^2 + vyf^2)/2 + 5*wf^2/12 > 1/4",
            )
            .using(&[1]),
            Check::holds(
                "to exactly 7261587/25088000",
                "(vxf^2 + vyf^2)/2 + 5*wf^2/12 = 7261587/25088000",
            )
            .using(&[1]),
        ],
    )
    .at(&[])
    .given(&[
        // Compression: the box after the impulses n, t.
        "vxc = -1/2 - t1 + n2",
        "vyc = -1/2 + n1 + t2",
        "wc = 6*(-3*n1/8 - 3*t1/2 + 9*n2/8 - t2/2)/5",
        "un1c = vyc - 3*wc/8",
        "ut1c = -vxc - 3*wc/2",
        "un2c = vxc + 9*wc/8",
        "ut2c = vyc - wc/2",
        "n1 >= 0 and un1c >= 0 and n1*un1c = 0",
        "n2 >= 0 and un2c >= 0 and n2*un2c = 0",
        "-n1/2 <= t1 and t1 <= n1/2 and (ut1c > 0 => t1 = -n1/2) and (ut1c < 0 => t1 = n1/2)",
        "-n2/2 <= t2 and t2 <= n2/2 and (ut2c > 0 => t2 = -n2/2) and (ut2c < 0 => t2 = n2/2)",
        // Expansion: p = e n + x, x >= 0 complementary to the normal velocity at the end.
        "p1 = x1",
        "p2 = n2 + x2",
        "vxf = vxc - q1 + p2",
        "vyf = vyc + p1 + q2",
        "wf = wc + 6*(-3*p1/8 - 3*q1/2 + 9*p2/8 - q2/2)/5",
        "un1f = vyf - 3*wf/8",
        "ut1f = -vxf - 3*wf/2",
        "un2f = vxf + 9*wf/8",
        "ut2f = vyf - wf/2",
        "x1 >= 0 and un1f >= 0 and x1*un1f = 0",
        "x2 >= 0 and un2f >= 0 and x2*un2f = 0",
        "-p1/2 <= q1 and q1 <= p1/2 and (ut1f > 0 => q1 = -p1/2) and (ut1f < 0 => q1 = p1/2)",
        "-p2/2 <= q2 and q2 <= p2/2 and (ut2f > 0 => q2 = -p2/2) and (ut2f < 0 => q2 = p2/2)",
    ]),
);

/// The scene, as `examples/impacts/two-contact-poisson-energy.toml` writes it.
const SCENE: &str = include_str!("../../../examples/impacts/two-contact-poisson-energy.toml");

/// The box's (vx, vy, w) after the impulses `(n1, t1, n2, t2)` on it, from (-1/2, -1/2, 0).
fn the_box_after(impulses: [&RatFn; 4]) -> [RatFn; 3] {
    let [n1, t1, n2, t2] = impulses;
    // Impulse (-t1, n1) at r1 = (-3/8, -3/2) and (n2, t2) at r2 = (-1/2, -9/8); I = 5/6.
    let torque = k(-3, 8) * n1 - &(k(-3, 2) * &(-t1.clone())) + &(k(-1, 2) * t2) - &(k(-9, 8) * n2);
    [k(-1, 2) - t1 + n2, k(-1, 2) + n1 + t2, torque * &k(6, 5)]
}

/// The normal and tangential velocities at the two pegs: (un1, ut1, un2, ut2).
fn at_the_pegs([vx, vy, w]: &[RatFn; 3]) -> [RatFn; 4] {
    [
        vy.clone() - &(k(3, 8) * w),
        -vx.clone() - &(k(3, 2) * w),
        vx.clone() + &(k(9, 8) * w),
        vy.clone() - &(w.clone() / &k(2, 1)),
    ]
}

fn energy([vx, vy, w]: &[RatFn; 3]) -> RatFn {
    (sq(vx) + &sq(vy)) / &k(2, 1) + &(k(5, 12) * &sq(w))
}

fn formalise(_paper: &Paper) -> Formalised {
    // The answer: compression (n, t), then expansion (p, q) = (e n + x, q) with x = 0.
    let (n1, n2) = (k(83, 280), k(141, 280));
    let (t1, t2) = (k(83, 560), k(141, 560));
    let (p1, p2, q1, q2) = (k(0, 1), n2.clone(), k(0, 1), k(141, 560));
    let compressed = the_box_after([&n1, &t1, &n2, &t2]);
    let [un1c, ut1c, un2c, ut2c] = at_the_pegs(&compressed);
    let total = |x: &RatFn, y: &RatFn| x.clone() + y;
    let end = the_box_after([
        &total(&n1, &p1),
        &total(&t1, &q1),
        &total(&n2, &p2),
        &total(&t2, &q2),
    ]);
    let [un1f, _, un2f, ut2f] = at_the_pegs(&end);
    let [_, ut1_before, _, _] =
        at_the_pegs(&the_box_after([&k(0, 1), &k(0, 1), &k(0, 1), &k(0, 1)]));
    let mean = |x: &RatFn, y: &RatFn| (x.clone() + y) / &k(2, 1);
    // Each impulse's work in a phase: the impulse times the mean of its velocity before and after.
    let friction_work = t1.clone() * &mean(&ut1_before, &ut1c);
    let restitution_work = p2.clone() * &mean(&k(0, 1), &un2f);
    let gain = energy(&end) - &k(1, 4);
    let solver_gain = match parse_toml("X38", SCENE)
        .map(|system| solve_several::<Q>(&system, &Model::SimultaneousPoisson))
    {
        Ok(ModelOutcome::Answered(answers)) if answers.len() == 1 => {
            RatFn::from_rational(&answers[0].ledger.energy.change)
        }
        other => panic!("X38: the scene has one Poisson answer, got {other:?}"),
    };
    proved(
        "A uniform box 1 wide and 3 high (mass 1, I = 5/6), its bottom-left corner at the origin, \
         moves at (-1/2, -1/2) without spin onto two fixed pegs: one under its bottom face at \
         (1/8, 0) (normal up, e = 0), one beside its left face at (0, 3/8) (normal +x, e = 1), \
         Coulomb friction mu = 1/2 at both; both approach at 1/2 and slide. Simultaneous Poisson \
         (Glocker and Pfeiffer), with Coulomb's law in each phase (the phase's tangential \
         impulse within mu times its normal impulse and opposing the slip at the phase's end): \
         compression gives each contact n_i >= 0 complementary to its normal velocity; \
         expansion adds e n_i + x_i, x_i >= 0 complementary to the final normal velocity. The \
         certificates check, in the box's own velocities, that the impulses n = (83/280, \
         141/280), t = mu n (both slips negative at the compression's end), then 141/280 at \
         the elastic peg with friction 141/560 (its slip negative at the end) and nothing at the \
         plastic one (which leaves at 2397/44800 > 0) satisfy every condition, and that the \
         energy rises by 989587/25088000. rodimpact's solver, which tries every mode of both \
         contacts in both phases, finds this answer and no other; z3 decides from the \
         conditions alone that it is the only one and that every solution gains energy. Where \
         the energy comes from (each impulse's work is the impulse times the mean of its \
         velocity before and after the phase): in the compression the friction at the lower peg \
         does positive work, +20999/627200, because that peg's slip reverses within the phase \
         and the phase's friction opposes the slip at its end; in the expansion the elastic \
         peg's normal impulse does +6938469/25088000, more than twice the -141/1120 its \
         compression impulse did.",
        "the one Poisson answer satisfies every condition of both phases and leaves the box with 989587/25088000 more kinetic energy",
        vec![
            id(
                "compression ends with both normal velocities 0 (contact 1)",
                n("un1c", un1c),
                k(0, 1),
            ),
            id("(contact 2)", n("un2c", un2c), k(0, 1)),
            id(
                "the slips at the compression's end are negative, so friction is +mu n (contact 1)",
                n("ut1c", ut1c),
                k(-27, 560),
            ),
            id("(contact 2)", n("ut2c", ut2c), k(-9, 560)),
            id(
                "the plastic peg leaves at the end (no extra impulse needed)",
                n("un1f", un1f),
                k(2397, 44800),
            ),
            id(
                "the elastic peg leaves at the end",
                n("un2f", un2f),
                k(49209, 44800),
            ),
            id(
                "the elastic peg's slip at the end is negative, so its expansion friction is +mu p",
                n("ut2f", ut2f),
                k(-321, 11200),
            ),
            id(
                "the work of the lower peg's friction in the compression, t1 (ut1 before + ut1c)/2, is positive",
                n("W_t1", friction_work),
                k(20999, 627200),
            ),
            id(
                "the work of the elastic peg's normal impulse in the expansion, p2 (un2c + un2f)/2",
                n("W_p2", restitution_work),
                k(6938469, 25088000),
            ),
            id(
                "the energy change: (vx^2 + vy^2)/2 + (5/12) w^2 - 1/4",
                n("dK", gain.clone()),
                k(989587, 25088000),
            ),
            id(
                "rodimpact's simultaneous-poisson on examples/impacts/two-contact-poisson-energy.toml: the same change",
                n("dK_solver", solver_gain),
                gain,
            ),
        ],
    )
}
