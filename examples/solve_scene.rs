//! Answer one scene with the library's front door: `cargo run --example solve_scene`.
//!
//! A disc of mass 1 and radius 1/10, spinning at 3 rad/s, slides at 2 m/s across and 1 m/s
//! along a free uniform rod (mass 3, half-length 1) and strikes it at a = 1/2 with e = 1/2 and
//! Coulomb friction mu = 1/5. Every number below is exact.

use rodimpact::prelude::*;

fn main() -> Result<(), Error> {
    let scene = Scene::builder(q(1, 1), q(3, 1))
        .a(q(1, 2))
        .v0(q(2, 1))
        .e(q(1, 2))
        .v0t(q(1, 1))
        .mu(q(1, 5))
        .disc(q(1, 10), q(3, 1))
        .build()?;
    let answer = Answer::of(&scene);
    let o = answer
        .impact
        .oblique
        .as_ref()
        .expect("an oblique scene is answered on both axes");
    println!("v = {}, vt = {} (the disc after)", o.after.v, o.after.vt);
    println!(
        "V = {}, Vt = {}, omega = {} (the rod after)",
        o.after.rod.v, o.after.rod.vt, o.after.rod.omega
    );
    println!("spin = {}", o.after.spin.as_ref().expect("a disc spins"));
    println!("J = {}, Jt = {}", answer.impulse, o.tangential_impulse);
    let contact = o.contact.expect("friction acts");
    println!(
        "contact: {}, mu* = {}",
        contact.kind(),
        answer.mu_star().expect("friction acts")
    );
    println!(
        "energy lost = {} (restitution {} + friction {})",
        o.energy.lost(),
        o.lost_restitution,
        o.lost_friction
    );
    println!("laws hold exactly: {}", answer.laws_hold());
    if let Some(best) = &answer.optimum {
        println!(
            "a*^2 = {}: a* = {} m",
            best.squared,
            QSqrt::sqrt_of(&best.squared)
        );
    }
    Ok(())
}
