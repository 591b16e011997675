//! The tilted-rod page's computations: a uniform rod (mass 1, length 2) tilted at theta above a
//! rough floor, its lower end landing while it falls at 1 and slides sideways, answered by the
//! general one-contact solver under Newton's, Poisson's and Stronge's laws, with Routh's path
//! and the energy change decided exactly; and where each law creates energy over a grid.

use super::explore_api::read_number;
use super::{exact, field_error};
use crate::field::{Field, Q, QSqrt, q};
use crate::impact::{Law, contact_matrix, contact_path, solve_exact};
use crate::model::{System, from_value};
use crate::report::{law_heading, law_name};
use num_traits::{Signed, Zero};
use serde_json::{Value, json};

/// The most scenes one `tilted_map` answers (a 40 x 40 grid).
const MAX_MAP_CELLS: usize = 1600;

/// The scene's inputs, exact.
struct Tilt {
    tan_half: Q,
    slip: Q,
    mu: Q,
    e: Q,
}

impl Tilt {
    /// Reads `tan_half` (0 < t < 1: the tilt theta in (0, 90) degrees, tan(theta/2) = t), `slip`
    /// (any), `mu` (>= 0) and `e` (0 <= e <= 1); the error of the first wrong field.
    fn read(request: &Value) -> Result<Tilt, Value> {
        let field = |key: &str, check: &dyn Fn(&Q) -> Option<&'static str>| {
            read_number(request, key, check)
                .map_err(|why| field_error(key, format!("{key}: {why}")))
        };
        let (zero, one) = (Q::zero(), Q::from_i64(1));
        Ok(Tilt {
            tan_half: field("tan_half", &|t| {
                (*t <= zero || *t >= one)
                    .then_some("must lie in 0 < tan(θ/2) < 1 (a tilt between 0 and 90 degrees)")
            })?,
            slip: field("slip", &|_| None)?,
            mu: field("mu", &|m| (*m < zero).then_some("must be ≥ 0"))?,
            e: field("e", &|e| {
                (*e < zero || *e > one).then_some("must lie in 0 ≤ e ≤ 1")
            })?,
        })
    }

    /// cos theta and sin theta, rational: (1 - t^2)/(1 + t^2) and 2t/(1 + t^2).
    fn axis(&self) -> [Q; 2] {
        let t2 = self.tan_half.clone() * &self.tan_half;
        let d = Q::from_i64(1) + &t2;
        [
            (Q::from_i64(1) - &t2) / &d,
            Q::from_i64(2) * &self.tan_half / &d,
        ]
    }

    /// The scene as `rodimpact impact` reads it.
    fn toml(&self) -> String {
        let [cos, sin] = self.axis();
        format!(
            "# A uniform rod (mass 1, length 2) tilted at tan(theta/2) = {t} above a rough floor y = 0,\n\
             # its lower end landing while it falls at 1 and slides at {slip}, not spinning.\n\
             title = \"A tilted rod on a rough floor (tan(theta/2) = {t}, slip {slip}, mu = {mu}, e = {e})\"\n\n\
             [[body]]\nname = \"rod\"\nmass = \"1\"\nshape = \"rod\"\nlength = \"2\"\n\
             axis = [\"{cos}\", \"{sin}\"]\nposition = [\"0\", \"{sin}\"]\nvelocity = [\"{slip}\", \"-1\"]\nomega = \"0\"\n\n\
             [[body]]\nname = \"floor\"\nfixed = true\n\n\
             [[contact]]\nbodies = [\"rod\", \"floor\"]\npoint = [\"{minus_cos}\", \"0\"]\nnormal = [\"0\", \"1\"]\n\
             e = \"{e}\"\nmu = \"{mu}\"\n",
            t = self.tan_half,
            slip = self.slip,
            mu = self.mu,
            e = self.e,
            minus_cos = -cos.clone(),
        )
    }

    /// The scene as the solver takes it: [`Tilt::toml`]'s scene in its JSON form (the same
    /// structure, read without a TOML parser, which the page's module does without).
    fn system(&self) -> System {
        let [cos, sin] = self.axis();
        let text = |x: &Q| json!(x.to_string());
        from_value(&json!({
            "body": [
                {
                    "name": "rod", "mass": "1", "shape": "rod", "length": "2",
                    "axis": [text(&cos), text(&sin)], "position": ["0", text(&sin)],
                    "velocity": [text(&self.slip), "-1"], "omega": "0",
                },
                { "name": "floor", "fixed": true },
            ],
            "contact": [{
                "bodies": ["rod", "floor"], "point": [text(&-cos.clone()), "0"], "normal": ["0", "1"],
                "e": text(&self.e), "mu": text(&self.mu),
            }],
        }))
        .expect("a tilted rod with checked inputs is a valid scene")
    }
}

/// `tilted`: the scene (`scene`: cos, sin, degrees, the contact velocity `u0`, `W`, `mu_stick`,
/// the energy before, the floor's `tangent`, the `toml` to check it from a terminal), the
/// inputs read (`input`), the end of compression `lam_c`, Routh's `path` (breakpoints up to the
/// last law's end) and one object per law in `laws` (its end `lam` and `tau`, `phases`,
/// `u_after`, the rod after, the energy after and its change, `energy_gain` decided exactly,
/// `energy_percent`, the `work` split). Every number is an exact value ([`exact`]).
///
/// # Examples
/// The default scene (tan(theta/2) = 1/2: cos = 3/5, sin = 4/5; slip 1, mu = 1/3, e = 1): Newton's
/// law creates 197125/9435168 of energy; Poisson's and Stronge's lose.
/// ```
/// use serde_json::json;
/// let answer = rodimpact::app::pages::tilted(&json!({"tan_half": "1/2", "slip": "1", "mu": "1/3", "e": "1"}));
/// let newton = &answer["laws"][0];
/// assert_eq!(newton["energy_change"]["text"], "197125/9435168");
/// assert_eq!(newton["energy_gain"], true);
/// assert_eq!(answer["laws"][1]["energy_gain"], false);
/// assert_eq!(answer["lam_c"]["text"], "25/64");
/// assert_eq!(answer["path"][1]["lam"]["text"], "75/181");
/// let wrong = rodimpact::app::pages::tilted(&json!({"tan_half": "1/2", "slip": "1", "mu": "-1", "e": "1"}));
/// assert_eq!(wrong["error"]["message"], "mu: must be ≥ 0");
/// ```
pub fn tilted(request: &Value) -> Value {
    let tilt = match Tilt::read(request) {
        Ok(t) => t,
        Err(e) => return e,
    };
    let system = tilt.system();
    let [cos, sin] = tilt.axis();
    let lift = |x: &Q| QSqrt::rational(x.clone());
    let (w, u0) = contact_matrix::<Q>(&system);
    let mu_stick = (!w.tt.is_zero()).then(|| w.nt.abs() / &w.tt);
    let answers: Vec<_> = Law::ALL
        .into_iter()
        .map(|law| (law, solve_exact(&system, law)))
        .collect();
    let mut energy_before = None;
    let laws: Vec<Value> = answers
        .iter()
        .map(|(law, answer)| {
            let head = json!({
                "law": law.name(),
                "name": law_name(*law),
                "kind": unicode_rule(law_heading(*law)),
            });
            match answer {
                Err(e) => merge(head, json!({ "error": e.to_string() })),
                Ok(a) => {
                    energy_before = Some(a.energy.before.clone());
                    let rod = &a.bodies[0];
                    let percent =
                        a.energy.change.clone() / &a.energy.before * &QSqrt::from_i64(100);
                    merge(
                        head,
                        json!({
                            "lam": exact(&a.lam),
                            "tau": exact(&a.tau),
                            "phases": a.phases.iter().map(|p| json!({
                                "mode": p.mode.name(), "from": exact(&p.from), "to": exact(&p.to),
                            })).collect::<Vec<_>>(),
                            "u_after": [exact(&a.contact_after[0]), exact(&a.contact_after[1])],
                            "rod": {
                                "vx": exact(&rod.velocity.x),
                                "vy": exact(&rod.velocity.y),
                                "omega": exact(&rod.omega),
                            },
                            "energy_after": exact(&a.energy.after),
                            "energy_change": exact(&a.energy.change),
                            "energy_gain": a.energy.gain(),
                            "energy_percent": exact(&percent),
                            "work": {
                                "compression": exact(&a.work[0]),
                                "restitution": exact(&a.work[1]),
                                "friction": exact(&a.work[2]),
                            },
                        }),
                    )
                }
            }
        })
        .collect();
    // The path up to the last law's end (the same path under every law).
    let last = answers
        .iter()
        .filter_map(|(_, a)| a.as_ref().ok().map(|a| a.lam.clone()))
        .max_by(QSqrt::cmp_exact);
    let path: Vec<Value> = last
        .and_then(|upto| contact_path::<QSqrt>(&system, &upto).ok())
        .unwrap_or_default()
        .iter()
        .map(|p| {
            json!({
                "lam": exact(&p.lam), "u_n": exact(&p.u[0]), "u_t": exact(&p.u[1]),
                "tau": exact(&p.tau), "mode": p.mode.name(),
            })
        })
        .collect();
    let lam_c = answers
        .iter()
        .find_map(|(_, a)| a.as_ref().ok().map(|a| exact(&a.lam_c)));
    json!({
        "input": {
            "tan_half": exact(&lift(&tilt.tan_half)),
            "slip": exact(&lift(&tilt.slip)),
            "mu": exact(&lift(&tilt.mu)),
            "e": exact(&lift(&tilt.e)),
        },
        "scene": {
            "cos": exact(&lift(&cos)),
            "sin": exact(&lift(&sin)),
            "degrees": sin.nearest_f64().atan2(cos.nearest_f64()).to_degrees(),
            "u0": [exact(&lift(&u0[0])), exact(&lift(&u0[1]))],
            "W": { "nn": exact(&lift(&w.nn)), "nt": exact(&lift(&w.nt)), "tt": exact(&lift(&w.tt)) },
            "mu_stick": mu_stick.map(|m| exact(&lift(&m))),
            "energy_before": energy_before.as_ref().map(exact),
            // The floor's tangent t (the normal n = (0, 1) turned a quarter turn counterclockwise):
            // u_t > 0 when the rod's end slides towards -x.
            "tangent": [exact(&lift(&q(-1, 1))), exact(&QSqrt::zero())],
            "toml": tilt.toml(),
        },
        "lam_c": lam_c,
        "path": path,
        "laws": laws,
    })
}

/// `a` with `b`'s keys added.
fn merge(mut a: Value, b: Value) -> Value {
    if let (Some(a), Value::Object(b)) = (a.as_object_mut(), b) {
        a.extend(b);
    }
    a
}

/// A law's rule for people: the true minus sign, `e²`, `×`.
fn unicode_rule(heading: &str) -> String {
    let rule = heading
        .split_once(" (")
        .map_or(heading, |(_, rule)| rule.trim_end_matches(')'));
    rule.replace("-e", "−e")
        .replace("e^2", "e²")
        .replace(" x ", " × ")
}

/// `tilted_map`: where each law creates energy over a grid of scenes at the request's `mu` and
/// `e`: rows follow `slips`, columns `tan_halves`; per law (`newton`, `poisson`, `energetic`)
/// a grid of `true` (gains), `false`, or `null` (no answer); `degrees` per column. At most
/// 1,600 cells.
///
/// # Examples
/// ```
/// use serde_json::json;
/// let map = rodimpact::app::pages::tilted_map(&json!({
///     "mu": "1/3", "e": "1", "tan_halves": ["1/2", "1/40"], "slips": ["1", "0"]
/// }));
/// assert_eq!(map["newton"], json!([[true, false], [false, false]]));
/// assert_eq!(map["poisson"], json!([[false, false], [false, false]]));
/// ```
pub fn tilted_map(request: &Value) -> Value {
    let texts = |key: &str| -> Vec<String> {
        request[key]
            .as_array()
            .map(|a| {
                a.iter()
                    .map(|v| v.as_str().unwrap_or_default().to_string())
                    .collect()
            })
            .unwrap_or_default()
    };
    let (angles, slips) = (texts("tan_halves"), texts("slips"));
    // Checked multiplication: usize is 32 bits in the pages' WebAssembly module, where
    // 65,536 x 65,536 wrapped to 0 and passed.
    if angles
        .len()
        .checked_mul(slips.len())
        .is_none_or(|cells| cells > MAX_MAP_CELLS)
    {
        return field_error(
            "tan_halves",
            format!(
                "the map takes at most {MAX_MAP_CELLS} scenes, got {} x {}",
                slips.len(),
                angles.len()
            ),
        );
    }
    let mut grids = [(); 3].map(|()| Vec::with_capacity(slips.len()));
    let mut degrees = Vec::new();
    for (row, slip) in slips.iter().enumerate() {
        let mut rows = [(); 3].map(|()| Vec::with_capacity(angles.len()));
        for angle in &angles {
            let tilt = match Tilt::read(&json!({
                "tan_half": angle, "slip": slip, "mu": request["mu"], "e": request["e"],
            })) {
                Ok(t) => t,
                Err(e) => return e,
            };
            if row == 0 {
                let [cos, sin] = tilt.axis();
                degrees.push(sin.nearest_f64().atan2(cos.nearest_f64()).to_degrees());
            }
            let system = tilt.system();
            for (grid, law) in rows.iter_mut().zip(Law::ALL) {
                grid.push(
                    solve_exact(&system, law).map_or(Value::Null, |a| json!(a.energy.gain())),
                );
            }
        }
        for (grid, row) in grids.iter_mut().zip(rows) {
            grid.push(row);
        }
    }
    let [newton, poisson, energetic] = grids;
    json!({ "newton": newton, "poisson": poisson, "energetic": energetic, "degrees": degrees })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The page's scene file is the example's own scene: the same answer under every law.
    #[test]
    fn the_default_scene_is_the_example_file() {
        let text = std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/examples/impacts/tilted-rod-rough-floor.toml"
        ))
        .expect("the example exists");
        let example = crate::model::parse_toml("example", &text).expect("valid");
        let tilt = Tilt::read(&json!({"tan_half": "1/2", "slip": "1", "mu": "1/3", "e": "1"}))
            .expect("valid");
        // The file the page shows solves as the scene it computes.
        let shown = crate::model::parse_toml("shown", &tilt.toml()).expect("valid");
        for law in Law::ALL {
            assert_eq!(solve_exact(&tilt.system(), law), solve_exact(&example, law));
            assert_eq!(solve_exact(&shown, law), solve_exact(&example, law));
        }
    }
}
