use crate::claims::dsl::*;
use crate::field::{Field, Q, RatFn};
use crate::impact::{Law, solve_contact};
use crate::model::parse_toml;

pub(super) const ENTRY: Entry = Entry {
    id: "X39",
    location: BEYOND,
    group: Group::Beyond,
    statement: "The law pymunk, Box2D 2.3 and Bullet converge to, lcp-newton (Newton's target on the final normal velocity and Coulomb's law on the final slip, in one phase), has one answer on the tilted rod landing on a rough floor (e = 1, mu = 1/3): the end sticks, and the rod gains exactly 1/10 of its 1 J, the work of the friction impulse; Newton's law followed through the slip reversal gains 197125/9435168 J",
    formalise,
    export: EXPORT,
};

// The claim for z3 and SymPy: the one-phase complementarity problem in the impulse's
// coefficients lam (along the floor's normal (0, 1)) and tau (along the tangent t = (-1, 0)),
// P = (-tau, lam). The rod (mass 1, I = 1/3) has its contact at r = (-3/5, -4/5) from its centre
// and moves at (1, -1) without spin: after P it moves at (1 - tau, -1 + lam) with
// omega = 3 (r x P) = 3 (-3 lam/5 - 4 tau/5); its end's normal velocity is un = vy - 3 omega/5,
// its slip ut = -(vx + 4 omega/5).
const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Nothing, ExportLaw::Restitution),
        &[
            Check::exists("the complementarity problem has a solution", "lam >= 0"),
            Check::holds(
                "its solution is unique: the end sticks",
                "lam = 11/10 and tau = -1/5 and ut = 0",
            ),
            Check::holds(
                "every solution gains exactly 1/10 J (the unique impulse as a lemma)",
                "(vx^2 + vy^2)/2 + w^2/6 = 11/10",
            )
            .using(&[1]),
        ],
    )
    .at(&[])
    .given(&[
        "vx = 1 - tau",
        "vy = -1 + lam",
        "w = 3*(-3*lam/5 - 4*tau/5)",
        "un = vy - 3*w/5",
        "ut = -(vx + 4*w/5)",
        // Newton's target on the final normal velocity (e = 1, approach at 1), complementary.
        "lam >= 0 and un >= 1 and lam*(un - 1) = 0",
        // Coulomb's law on the final slip, mu = 1/3.
        "-lam/3 <= tau and tau <= lam/3 and (ut > 0 => tau = -lam/3) and (ut < 0 => tau = lam/3)",
    ]),
);

/// The scene, as `examples/impacts/tilted-rod-rough-floor.toml` writes it.
const SCENE: &str = include_str!("../../../examples/impacts/tilted-rod-rough-floor.toml");

/// The rod's (vx, vy, omega) after the impulse lam n + tau t, from (1, -1, 0).
fn the_rod_after(lam: &RatFn, tau: &RatFn) -> [RatFn; 3] {
    let moment = k(-3, 5) * lam - &(k(4, 5) * tau);
    [k(1, 1) - tau, k(-1, 1) + lam, k(3, 1) * &moment]
}

/// The end's normal velocity and slip: (un, ut).
fn at_the_end([vx, vy, w]: &[RatFn; 3]) -> [RatFn; 2] {
    [vy.clone() - &(k(3, 5) * w), -(vx.clone() + &(k(4, 5) * w))]
}

fn energy([vx, vy, w]: &[RatFn; 3]) -> RatFn {
    (sq(vx) + &sq(vy)) / &k(2, 1) + &(sq(w) / &k(6, 1))
}

fn formalise(_paper: &Paper) -> Formalised {
    let mu = k(1, 3);
    // Sticking: un = 1 and ut = 0 at the end.
    let (lam, tau) = (k(11, 10), k(-1, 5));
    let after = the_rod_after(&lam, &tau);
    let [un, ut] = at_the_end(&after);
    // The two sliding modes, each with un = 1: the slip they leave contradicts their direction.
    let slide_forward = k(5, 4); // ut > 0 assumed, tau = -mu lam
    let [_, ut_forward] = at_the_end(&the_rod_after(
        &slide_forward,
        &-(mu.clone() * &slide_forward),
    ));
    let slide_back = k(25, 32); // ut < 0 assumed, tau = +mu lam
    let [_, ut_back] = at_the_end(&the_rod_after(&slide_back, &(mu.clone() * &slide_back)));
    let [_, ut_before] = at_the_end(&the_rod_after(&k(0, 1), &k(0, 1)));
    // The friction impulse's work: tau times the mean of the slip before and after (the normal
    // impulse does none: un goes from -1 to +1).
    let friction_work = tau.clone() * &((ut_before + &ut) / &k(2, 1));
    let gain = energy(&after) - &k(1, 1);
    let solver_gain = match parse_toml("X39", SCENE)
        .map_err(|e| e.to_string())
        .and_then(|system| solve_contact::<Q>(&system, Law::LcpNewton).map_err(|e| e.to_string()))
    {
        Ok(answer) => RatFn::from_rational(&answer.energy.change),
        Err(e) => panic!("X39: the scene has an lcp-newton answer, got {e}"),
    };
    proved(
        "A uniform rod (length 2, mass 1, I = 1/3), its axis at cos = 3/5, sin = 4/5 to the floor, \
         its lower end at (-3/5, 0) and its centre at (0, 4/5), moves at (1, -1) without spin \
         onto a rough floor (e = 1, mu = 1/3). lcp-newton: the impulse P = lam n + tau t (n = \
         (0, 1), t = (-1, 0)) with lam >= 0 complementary to u_n' - 1 >= 0 (Newton's target on \
         the final normal velocity) and tau within mu lam, opposing the final slip u_t' where it \
         is not zero. The certificates check that lam = 11/10, tau = -1/5 (|tau| = 6/30 < mu lam \
         = 11/30) give u_n' = 1 and u_t' = 0, that each sliding mode with u_n' = 1 leaves a slip \
         against its own direction (slide with u_t' > 0, tau = -lam/3: lam = 5/4 and u_t' = \
         -5/12; with u_t' < 0, tau = lam/3: lam = 25/32 and u_t' = 85/96), and that the energy \
         rises from 1 to 11/10; z3 decides from the conditions alone that the answer is unique \
         and gains exactly 1/10. The normal impulse does no work (u_n from -1 to +1); the \
         friction impulse does +1/10: it acts against the slip at the end (zero), not the slip \
         during the impact, which it pushes along. rodimpact's solver (impact --law lcp-newton) \
         gives the same change.",
        "the sticking impulse satisfies lcp-newton, both sliding modes contradict themselves, and the energy rises by exactly 1/10",
        vec![
            id(
                "the end leaves at the approach speed: un after",
                n("un", un),
                k(1, 1),
            ),
            id("the end sticks: ut after", n("ut", ut), k(0, 1)),
            id(
                "within the cone: mu lam - |tau| = 11/30 - 1/5",
                n("cone", mu.clone() * &lam + &tau),
                k(1, 6),
            ),
            id(
                "sliding with ut > 0 (tau = -lam/3, lam = 5/4) leaves ut < 0",
                n("ut_slide_forward", ut_forward),
                k(-5, 12),
            ),
            id(
                "sliding with ut < 0 (tau = lam/3, lam = 25/32) leaves ut > 0",
                n("ut_slide_back", ut_back),
                k(85, 96),
            ),
            id(
                "the friction impulse's work, tau (ut before + ut after)/2",
                n("W_t", friction_work),
                k(1, 10),
            ),
            id(
                "the energy change: (vx^2 + vy^2)/2 + w^2/6 - 1",
                n("dK", gain.clone()),
                k(1, 10),
            ),
            id(
                "rodimpact's lcp-newton on examples/impacts/tilted-rod-rough-floor.toml: the same change",
                n("dK_solver", solver_gain),
                gain,
            ),
        ],
    )
}
