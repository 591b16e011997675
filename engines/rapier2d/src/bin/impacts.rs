//! Runs the planar impact suite (`engines/impacts.jsonl`) in Rapier 2D 0.36.1 (`rapier2d-f64`),
//! one impact per scene, and writes `OUTDIR/rapier2d-0.36.1.jsonl`: each line the scene's own
//! JSON plus `"claimed"`, the velocity and spin of every moving body right after the impact
//! (floats as Rust `{:?}`, the shortest decimal that reads back to the same f64).
//!
//! Usage: `impacts SUITE.jsonl OUTDIR`
//!
//! The set-up is the one of `engines/python/impacts_common.py`:
//! * no gravity, no damping, sleeping off, dt = 1/1000, Rapier's default solver settings
//!   (4 solver iterations, 1 internal PGS and 1 stabilization iteration, default contact
//!   softness, prediction distance 0.02, warm starting);
//! * every moving body gets the scene's mass, centre of mass and inertia (collider mass
//!   properties); a rod is a capsule of the scene's length and radius 1/200, a box a cuboid, a
//!   disc a ball, a point mass a ball of radius 1/100 with its rotations locked;
//! * a floor or wall is a fixed cuboid (half extents 50 x 1) whose face is the scene's line,
//!   moved out by a rod's radius under a rod; a peg a fixed ball of radius 1/100; a pin a
//!   `RevoluteJoint` to a fixed body (contacts between them off);
//! * a disc or point at a contact with a rod is moved away along the normal by the rod's
//!   radius (a point also by its own), which changes no lever arm;
//! * e and mu: every collider uses the `Multiply` combine rule, moving colliders 1 and static
//!   ones e and mu (so the product is exactly e and mu), and a `modify_solver_contacts` hook
//!   sets every manifold's friction and restitution to the scene contact's e and mu (also for
//!   contacts between two moving bodies);
//! * start: each moving body where its free flight puts it 0.99 steps before the scene (a
//!   pinned one turned back about its pin);
//! * reading: stepped until, after a step with contact impulses, a step applies none (or less
//!   than 1/100 of the largest step impulse, then the state before it is read) and no contact
//!   of the scene approaches, at most 0.1 s; a pinned body's centre velocity is turned back by
//!   the angle it has turned since the scene, at the pose its velocity was solved at (Rapier's
//!   4 solver iterations are substeps that integrate the poses: the last substep's pose).

use std::collections::BTreeMap;
use std::fs;
use std::io::Write;
use std::path::Path;
use std::process::ExitCode;

use rapier2d_f64::prelude::*;

const RAPIER_VERSION: &str = "0.36.1";
const DT: f64 = 1.0 / 1000.0;
const ROD_RADIUS: f64 = 1.0 / 200.0;
const POINT_RADIUS: f64 = 1.0 / 100.0;
const PEG_RADIUS: f64 = 1.0 / 100.0;
const START_STEPS: f64 = 0.99;
const MAX_SECONDS: f64 = 0.1;
const TAIL_RATIO: f64 = 1.0 / 100.0;
const APPROACH_TOLERANCE: f64 = 1e-6;

// ---------------------------------------------------------------------------------------------
// A small JSON reader (the suite's lines: objects, arrays, strings, booleans; numbers are
// strings in the suite but are read too).
// ---------------------------------------------------------------------------------------------

#[derive(Debug, Clone)]
enum Json {
    Null,
    Bool(bool),
    Num(f64),
    Str(String),
    Arr(Vec<Json>),
    Obj(Vec<(String, Json)>),
}

impl Json {
    fn get(&self, key: &str) -> Option<&Json> {
        match self {
            Json::Obj(fields) => fields.iter().find(|(k, _)| k == key).map(|(_, v)| v),
            _ => None,
        }
    }
    fn str(&self) -> Option<&str> {
        match self {
            Json::Str(s) => Some(s),
            _ => None,
        }
    }
    fn arr(&self) -> &[Json] {
        match self {
            Json::Arr(items) => items,
            _ => &[],
        }
    }
}

struct Reader<'a> {
    text: &'a [u8],
    at: usize,
}

impl Reader<'_> {
    fn skip(&mut self) {
        while self.at < self.text.len() && (self.text[self.at] as char).is_whitespace() {
            self.at += 1;
        }
    }
    fn expect(&mut self, c: u8) -> Result<(), String> {
        self.skip();
        if self.text.get(self.at) == Some(&c) {
            self.at += 1;
            Ok(())
        } else {
            Err(format!("expected '{}' at byte {}", c as char, self.at))
        }
    }
    fn value(&mut self) -> Result<Json, String> {
        self.skip();
        match self.text.get(self.at) {
            Some(b'{') => {
                self.at += 1;
                let mut fields = Vec::new();
                self.skip();
                if self.text.get(self.at) == Some(&b'}') {
                    self.at += 1;
                    return Ok(Json::Obj(fields));
                }
                loop {
                    self.skip();
                    let key = match self.value()? {
                        Json::Str(s) => s,
                        _ => return Err(format!("a key must be a string at byte {}", self.at)),
                    };
                    self.expect(b':')?;
                    fields.push((key, self.value()?));
                    self.skip();
                    match self.text.get(self.at) {
                        Some(b',') => self.at += 1,
                        Some(b'}') => {
                            self.at += 1;
                            return Ok(Json::Obj(fields));
                        }
                        _ => return Err(format!("expected ',' or '}}' at byte {}", self.at)),
                    }
                }
            }
            Some(b'[') => {
                self.at += 1;
                let mut items = Vec::new();
                self.skip();
                if self.text.get(self.at) == Some(&b']') {
                    self.at += 1;
                    return Ok(Json::Arr(items));
                }
                loop {
                    items.push(self.value()?);
                    self.skip();
                    match self.text.get(self.at) {
                        Some(b',') => self.at += 1,
                        Some(b']') => {
                            self.at += 1;
                            return Ok(Json::Arr(items));
                        }
                        _ => return Err(format!("expected ',' or ']' at byte {}", self.at)),
                    }
                }
            }
            Some(b'"') => {
                self.at += 1;
                let mut out = String::new();
                loop {
                    match self.text.get(self.at) {
                        None => return Err("unterminated string".into()),
                        Some(b'"') => {
                            self.at += 1;
                            return Ok(Json::Str(out));
                        }
                        Some(b'\\') => {
                            let c = *self.text.get(self.at + 1).ok_or("bad escape")?;
                            self.at += 2;
                            match c {
                                b'n' => out.push('\n'),
                                b't' => out.push('\t'),
                                b'u' => {
                                    let hex = std::str::from_utf8(&self.text[self.at..self.at + 4])
                                        .map_err(|e| e.to_string())?;
                                    let code =
                                        u32::from_str_radix(hex, 16).map_err(|e| e.to_string())?;
                                    out.push(char::from_u32(code).unwrap_or('\u{fffd}'));
                                    self.at += 4;
                                }
                                other => out.push(other as char),
                            }
                        }
                        Some(_) => {
                            // copy one UTF-8 character
                            let rest = std::str::from_utf8(&self.text[self.at..])
                                .map_err(|e| e.to_string())?;
                            let ch = rest.chars().next().unwrap();
                            out.push(ch);
                            self.at += ch.len_utf8();
                        }
                    }
                }
            }
            Some(b't') if self.text[self.at..].starts_with(b"true") => {
                self.at += 4;
                Ok(Json::Bool(true))
            }
            Some(b'f') if self.text[self.at..].starts_with(b"false") => {
                self.at += 5;
                Ok(Json::Bool(false))
            }
            Some(b'n') if self.text[self.at..].starts_with(b"null") => {
                self.at += 4;
                Ok(Json::Null)
            }
            Some(_) => {
                let start = self.at;
                while self.at < self.text.len() && b"+-0123456789.eE".contains(&self.text[self.at])
                {
                    self.at += 1;
                }
                let text = std::str::from_utf8(&self.text[start..self.at]).unwrap();
                text.parse::<f64>()
                    .map(Json::Num)
                    .map_err(|_| format!("bad value at byte {start}"))
            }
            None => Err("unexpected end".into()),
        }
    }
}

fn parse_json(text: &str) -> Result<Json, String> {
    let mut r = Reader {
        text: text.as_bytes(),
        at: 0,
    };
    let v = r.value()?;
    r.skip();
    if r.at != r.text.len() {
        return Err(format!("trailing text at byte {}", r.at));
    }
    Ok(v)
}

/// An exact number of the scene file ("3/5", "0.9", "-2", "1.5e-3/7") as the nearest f64 of each
/// part, divided.
fn number(v: &Json) -> Result<f64, String> {
    match v {
        Json::Num(x) => Ok(*x),
        Json::Str(s) => {
            let mut parts = s.splitn(2, '/');
            let p: f64 = parts.next().unwrap().trim().parse().map_err(|_| format!("bad number {s:?}"))?;
            match parts.next() {
                Some(q) => Ok(p / q.trim().parse::<f64>().map_err(|_| format!("bad number {s:?}"))?),
                None => Ok(p),
            }
        }
        _ => Err(format!("not a number: {v:?}")),
    }
}

fn vec2(v: Option<&Json>, default: (f64, f64)) -> Result<(f64, f64), String> {
    match v {
        None => Ok(default),
        Some(v) => {
            let a = v.arr();
            if a.len() != 2 {
                return Err("a vector must have two entries".into());
            }
            Ok((number(&a[0])?, number(&a[1])?))
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The scene and its engine geometry
// ---------------------------------------------------------------------------------------------

#[derive(Clone, Copy, PartialEq, Debug)]
enum Shape {
    Rod(f64),        // length
    Box(f64, f64),   // width, height
    Disc(f64),       // radius
    Point,
    None,
}

struct Body {
    name: String,
    fixed: bool,
    shape: Shape,
    mass: f64,
    inertia: f64,
    position: (f64, f64),
    velocity: (f64, f64),
    omega: f64,
    angle: f64,
    pin: Option<(f64, f64)>,
    shift: (f64, f64),
}

impl Body {
    fn skin(&self) -> f64 {
        if let Shape::Rod(_) = self.shape {
            ROD_RADIUS
        } else {
            0.0
        }
    }
    fn rotates(&self) -> bool {
        self.inertia > 0.0
    }
}

struct Contact {
    a: usize,
    b: usize,
    point: (f64, f64),
    n: (f64, f64),
    e: f64,
    mu: f64,
}

enum Static {
    /// A point on the face and the outward unit normal.
    HalfPlane((f64, f64), (f64, f64)),
    /// Centre and radius.
    Circle((f64, f64), f64),
}

struct Scene {
    id: String,
    bodies: Vec<Body>,
    contacts: Vec<Contact>,
    statics: Vec<Static>,
    /// (tag, tag) -> (e, mu); a moving body's tag is its index, a static shape's 1000 + index.
    coefficients: BTreeMap<(u128, u128), (f64, f64)>,
}

fn key(t1: u128, t2: u128) -> (u128, u128) {
    (t1.min(t2), t1.max(t2))
}

impl Scene {
    fn parse(line: &Json) -> Result<Scene, String> {
        let id = line.get("id").and_then(Json::str).ok_or("a line needs an id")?.to_string();
        let mut bodies = Vec::new();
        for t in line.get("body").map(Json::arr).unwrap_or(&[]) {
            let name = t.get("name").and_then(Json::str).ok_or("a body needs a name")?.to_string();
            let fixed = matches!(t.get("fixed"), Some(Json::Bool(true)));
            let dim = |k: &str| t.get(k).map(number).transpose();
            let shape = match t.get("shape").and_then(Json::str) {
                Some("rod") => Shape::Rod(dim("length")?.ok_or("rod length")?),
                Some("box") => Shape::Box(dim("width")?.ok_or("box width")?, dim("height")?.ok_or("box height")?),
                Some("disc") => Shape::Disc(dim("radius")?.ok_or("disc radius")?),
                Some("point") => Shape::Point,
                None => Shape::None,
                Some(other) => return Err(format!("body {name}: shape {other} is not set up")),
            };
            let axis = vec2(t.get("axis"), (1.0, 0.0))?;
            let (mass, inertia) = if fixed {
                (0.0, 0.0)
            } else {
                let m = number(t.get("mass").ok_or("mass")?)?;
                let inertia = match t.get("inertia") {
                    Some(v) => number(v)?,
                    None => match shape {
                        Shape::Rod(l) => m * l * l / 12.0,
                        Shape::Box(w, h) => m * (w * w + h * h) / 12.0,
                        Shape::Disc(r) => m * r * r / 2.0,
                        Shape::Point => 0.0,
                        Shape::None => return Err(format!("body {name}: no inertia")),
                    },
                };
                (m, inertia)
            };
            bodies.push(Body {
                name,
                fixed,
                shape,
                mass,
                inertia,
                position: vec2(t.get("position"), (0.0, 0.0))?,
                velocity: vec2(t.get("velocity"), (0.0, 0.0))?,
                omega: t.get("omega").map(number).transpose()?.unwrap_or(0.0),
                angle: axis.1.atan2(axis.0),
                pin: None,
                shift: (0.0, 0.0),
            });
        }
        let index = |name: &str| {
            bodies
                .iter()
                .position(|b| b.name == name)
                .ok_or(format!("unknown body {name}"))
        };
        let mut pins = Vec::new();
        for p in line.get("pin").map(Json::arr).unwrap_or(&[]) {
            let b = index(p.get("body").and_then(Json::str).ok_or("pin body")?)?;
            pins.push((b, vec2(p.get("point"), (0.0, 0.0))?));
        }
        let mut contacts = Vec::new();
        for c in line.get("contact").map(Json::arr).unwrap_or(&[]) {
            let names = c.get("bodies").map(Json::arr).unwrap_or(&[]);
            let (a, b) = (
                index(names[0].str().ok_or("contact bodies")?)?,
                index(names[1].str().ok_or("contact bodies")?)?,
            );
            let n = vec2(c.get("normal"), (0.0, 0.0))?;
            let norm = n.0.hypot(n.1);
            contacts.push(Contact {
                a,
                b,
                point: vec2(c.get("point"), (0.0, 0.0))?,
                n: (n.0 / norm, n.1 / norm),
                e: c.get("e").map(number).transpose()?.unwrap_or(1.0),
                mu: c.get("mu").map(number).transpose()?.unwrap_or(0.0),
            });
        }
        for (b, q) in pins {
            bodies[b].pin = Some(q);
        }
        let mut scene = Scene {
            id,
            bodies,
            contacts,
            statics: Vec::new(),
            coefficients: BTreeMap::new(),
        };
        scene.place()?;
        Ok(scene)
    }

    fn set(&mut self, t1: u128, t2: u128, e: f64, mu: f64) -> Result<(), String> {
        let old = *self.coefficients.entry(key(t1, t2)).or_insert((e, mu));
        if old != (e, mu) {
            return Err(format!("{}: one pair of shapes with two coefficient sets", self.id));
        }
        Ok(())
    }

    fn shift(&mut self, b: usize, d: (f64, f64)) -> Result<(), String> {
        let old = self.bodies[b].shift;
        if old != (0.0, 0.0) && old != d {
            return Err(format!("{}: body {} would be moved twice", self.id, self.bodies[b].name));
        }
        self.bodies[b].shift = d;
        Ok(())
    }

    /// The engine geometry: static shapes and the moves of discs and points (as
    /// impacts_common.Scene._place).
    fn place(&mut self) -> Result<(), String> {
        let mut lines: Vec<(usize, [i64; 3], usize)> = Vec::new();
        for k in 0..self.contacts.len() {
            let (a, b, n, p, e, mu) = {
                let c = &self.contacts[k];
                (c.a, c.b, c.n, c.point, c.e, c.mu)
            };
            if self.bodies[a].fixed || self.bodies[b].fixed {
                let (moving, fixed) = if self.bodies[a].fixed { (b, a) } else { (a, b) };
                let into = if moving == a { n } else { (-n.0, -n.1) };
                if self.bodies[moving].shape == Shape::Point {
                    self.shift(moving, (POINT_RADIUS * into.0, POINT_RADIUS * into.1))?;
                }
                let s = self.bodies[moving].skin();
                let surface = (p.0 - s * into.0, p.1 - s * into.1);
                let index = match self.bodies[fixed].shape {
                    Shape::None => {
                        let offset = surface.0 * into.0 + surface.1 * into.1;
                        let q = |x: f64| (x * 1e12).round() as i64;
                        let k3 = [q(into.0), q(into.1), q(offset)];
                        match lines.iter().find(|(f, kk, _)| *f == fixed && *kk == k3) {
                            Some(&(_, _, i)) => i,
                            None => {
                                self.statics.push(Static::HalfPlane(surface, into));
                                lines.push((fixed, k3, self.statics.len() - 1));
                                self.statics.len() - 1
                            }
                        }
                    }
                    Shape::Point => {
                        let centre = (surface.0 - PEG_RADIUS * into.0, surface.1 - PEG_RADIUS * into.1);
                        self.statics.push(Static::Circle(centre, PEG_RADIUS));
                        self.statics.len() - 1
                    }
                    other => return Err(format!("{}: fixed body with shape {other:?}", self.id)),
                };
                self.set(moving as u128, 1000 + index as u128, e, mu)?;
                continue;
            }
            let mut done = false;
            for (x, y, sign) in [(a, b, 1.0), (b, a, -1.0)] {
                let shape = self.bodies[x].shape;
                if matches!(shape, Shape::Disc(_) | Shape::Point) {
                    let d = self.bodies[y].skin() + if shape == Shape::Point { POINT_RADIUS } else { 0.0 };
                    if d != 0.0 {
                        self.shift(x, (sign * d * n.0, sign * d * n.1))?;
                    }
                    done = true;
                    break;
                }
            }
            if !done {
                return Err(format!("{}: a contact between two bodies neither a disc nor a point", self.id));
            }
            self.set(a as u128, b as u128, e, mu)?;
        }
        Ok(())
    }

    /// The normal velocities of the scene's contacts from the given (vx, vy, omega) of each
    /// body (index order; fixed bodies ignored).
    fn normal_velocities(&self, state: &[(f64, f64, f64)]) -> Vec<f64> {
        self.contacts
            .iter()
            .map(|c| {
                let mut u = (0.0, 0.0);
                for (i, sign) in [(c.a, 1.0), (c.b, -1.0)] {
                    let b = &self.bodies[i];
                    if b.fixed {
                        continue;
                    }
                    let (vx, vy, w) = state[i];
                    let r = (c.point.0 - b.position.0, c.point.1 - b.position.1);
                    u.0 += sign * (vx - w * r.1);
                    u.1 += sign * (vy + w * r.0);
                }
                u.0 * c.n.0 + u.1 * c.n.1
            })
            .collect()
    }

    fn approaching(&self, state: &[(f64, f64, f64)]) -> bool {
        let before: Vec<(f64, f64, f64)> =
            self.bodies.iter().map(|b| (b.velocity.0, b.velocity.1, b.omega)).collect();
        let scale = self
            .normal_velocities(&before)
            .iter()
            .fold(1e-300_f64, |m, u| m.max(-u));
        self.normal_velocities(state)
            .iter()
            .any(|u| *u < -APPROACH_TOLERANCE * scale)
    }
}

// ---------------------------------------------------------------------------------------------
// Rapier
// ---------------------------------------------------------------------------------------------

struct Coefficients(BTreeMap<(u128, u128), (f64, f64)>);

impl PhysicsHooks for Coefficients {
    fn modify_solver_contacts(&self, context: &mut ContactModificationContext) {
        let t1 = context.colliders[context.collider1].user_data;
        let t2 = context.colliders[context.collider2].user_data;
        if let Some(&(e, mu)) = self.0.get(&key(t1, t2)) {
            if let Some(m) = context.rigid_mut() {
                *m.friction = mu;
                *m.restitution = e;
            }
        }
    }
}

fn rotate(a: f64, v: (f64, f64)) -> (f64, f64) {
    (a.cos() * v.0 - a.sin() * v.1, a.sin() * v.0 + a.cos() * v.1)
}

/// Runs one scene; returns each moving body's (vx, vy, omega) as read, the steps and how the
/// impact ended.
fn run(scene: &Scene) -> (Vec<(f64, f64, f64)>, usize, String) {
    let mut world = PhysicsWorld {
        gravity: Vector::ZERO,
        ..PhysicsWorld::default()
    };
    world.integration_parameters.dt = DT;
    let hooks = Coefficients(scene.coefficients.clone());
    let material = |builder: ColliderBuilder, e: f64, mu: f64, tag: u128| {
        builder
            .friction(mu)
            .friction_combine_rule(CoefficientCombineRule::Multiply)
            .restitution(e)
            .restitution_combine_rule(CoefficientCombineRule::Multiply)
            .user_data(tag)
            .active_hooks(ActiveHooks::MODIFY_SOLVER_CONTACTS)
    };
    let t0 = START_STEPS * DT;
    let ground = world.insert_body(RigidBodyBuilder::fixed());
    let mut handles = Vec::new();
    for (i, b) in scene.bodies.iter().enumerate() {
        if b.fixed {
            handles.push(None);
            continue;
        }
        let mut x = (b.position.0 + b.shift.0, b.position.1 + b.shift.1);
        match b.pin {
            Some(q) => {
                let r = rotate(-b.omega * t0, (x.0 - q.0, x.1 - q.1));
                x = (q.0 + r.0, q.1 + r.1);
            }
            None => x = (x.0 - b.velocity.0 * t0, x.1 - b.velocity.1 * t0),
        }
        let angle = b.angle - b.omega * t0;
        let mut builder = RigidBodyBuilder::dynamic()
            .can_sleep(false)
            .translation(Vector::new(x.0, x.1))
            .rotation(angle)
            .linvel(Vector::new(b.velocity.0, b.velocity.1))
            .angvel(if b.rotates() { b.omega } else { 0.0 });
        if !b.rotates() {
            builder = builder.lock_rotations();
        }
        let shape = match b.shape {
            Shape::Rod(l) => ColliderBuilder::capsule_x(l / 2.0, ROD_RADIUS),
            Shape::Box(w, h) => ColliderBuilder::cuboid(w / 2.0, h / 2.0),
            Shape::Disc(r) => ColliderBuilder::ball(r),
            Shape::Point => ColliderBuilder::ball(POINT_RADIUS),
            Shape::None => panic!("a moving body without a shape"),
        };
        let collider = material(shape, 1.0, 1.0, i as u128)
            .mass_properties(MassProperties::new(Vector::ZERO, b.mass, b.inertia));
        let (handle, _) = world.insert(builder, collider);
        if let Some(q) = b.pin {
            let local = rotate(-angle, (q.0 - x.0, q.1 - x.1));
            let joint = RevoluteJointBuilder::new()
                .local_anchor1(Vector::new(q.0, q.1))
                .local_anchor2(Vector::new(local.0, local.1))
                .contacts_enabled(false);
            world.impulse_joints.insert(ground, handle, joint, true);
        }
        handles.push(Some(handle));
    }
    for (k, st) in scene.statics.iter().enumerate() {
        let (e, mu) = scene
            .coefficients
            .iter()
            .find(|(kk, _)| kk.1 == 1000 + k as u128)
            .map(|(_, v)| *v)
            .unwrap();
        let collider = match *st {
            Static::HalfPlane(p, n) => {
                let centre = (p.0 - n.0, p.1 - n.1); // the cuboid's half height is 1
                ColliderBuilder::cuboid(50.0, 1.0)
                    .translation(Vector::new(centre.0, centre.1))
                    .rotation(n.1.atan2(n.0) - std::f64::consts::FRAC_PI_2)
            }
            Static::Circle(c, r) => ColliderBuilder::ball(r).translation(Vector::new(c.0, c.1)),
        };
        world.insert_collider(material(collider, e, mu, 1000 + k as u128), Some(ground));
    }

    let snapshot = |world: &PhysicsWorld, angles: &[f64]| -> Vec<(f64, f64, f64)> {
        scene
            .bodies
            .iter()
            .enumerate()
            .map(|(i, b)| match handles[i] {
                None => (0.0, 0.0, 0.0),
                Some(h) => {
                    let body = &world.bodies[h];
                    let v = body.linvel();
                    let mut v = (v.x, v.y);
                    if b.pin.is_some() {
                        v = rotate(-(angles[i] - b.angle), v);
                    }
                    (v.0, v.1, body.angvel())
                }
            })
            .collect()
    };
    let angles_now = |world: &PhysicsWorld| -> Vec<f64> {
        handles
            .iter()
            .map(|h| h.map_or(0.0, |h| world.bodies[h].rotation().angle()))
            .collect()
    };

    let max_steps = START_STEPS.ceil() as usize + (MAX_SECONDS / DT).round() as usize;
    let mut peak: f64 = 0.0;
    let mut before = snapshot(&world, &angles_now(&world));
    for k in 1..=max_steps {
        let angles_before = angles_now(&world);
        world.step_with_events(&hooks, &());
        // Rapier 0.36 runs its solver iterations as substeps, each integrating the poses, so
        // the velocities after a step were solved at the pose of its last substep.
        let substeps = world.integration_parameters.num_solver_iterations as f64;
        let solved_at: Vec<f64> = angles_before
            .iter()
            .zip(angles_now(&world))
            .map(|(a, b)| a + (b - a) * (substeps - 1.0) / substeps)
            .collect();
        let impulse: f64 = world
            .narrow_phase
            .contact_pairs()
            .map(|pair| pair.total_impulse_magnitude())
            .sum();
        let now = snapshot(&world, &solved_at);
        if peak > 0.0 && impulse <= TAIL_RATIO * peak {
            let (state, how) = if impulse == 0.0 { (now.clone(), "ended") } else { (before.clone(), "tail") };
            if !scene.approaching(&state) {
                return (state, k, how.to_string());
            }
        }
        peak = peak.max(impulse);
        before = now;
    }
    let how = if scene.approaching(&before) {
        "contacts still approach at the end"
    } else {
        "still in contact at the end"
    };
    (before, max_steps, how.to_string())
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().collect();
    if args.len() != 3 {
        eprintln!("usage: impacts SUITE.jsonl OUTDIR");
        return ExitCode::from(2);
    }
    let text = match fs::read_to_string(&args[1]) {
        Ok(t) => t,
        Err(e) => {
            eprintln!("error: {}: {e}", args[1]);
            return ExitCode::from(2);
        }
    };
    let engine = format!("rapier2d-f64 {RAPIER_VERSION}");
    let mut out = String::new();
    let mut count = 0;
    for raw in text.lines().filter(|l| !l.trim().is_empty()) {
        let scene = match parse_json(raw).and_then(|line| Scene::parse(&line)) {
            Ok(s) => s,
            Err(message) => {
                eprintln!("error: {message}");
                return ExitCode::from(2);
            }
        };
        let (state, steps, how) = run(&scene);
        eprintln!("{}: {steps} steps ({how})", scene.id);
        let bodies: Vec<String> = scene
            .bodies
            .iter()
            .zip(&state)
            .filter(|(b, _)| !b.fixed)
            .map(|(b, s)| {
                format!(
                    "\"{}\": {{\"velocity\": [\"{:?}\", \"{:?}\"], \"omega\": \"{:?}\"}}",
                    b.name, s.0, s.1, s.2
                )
            })
            .collect();
        let trimmed = raw.trim_end();
        let head = trimmed.strip_suffix('}').expect("a line is an object");
        out.push_str(&format!(
            "{head}, \"claimed\": {{\"engine\": \"{engine}\", \"bodies\": {{{}}}}}}}\n",
            bodies.join(", ")
        ));
        count += 1;
    }
    let path = Path::new(&args[2]).join(format!("rapier2d-{RAPIER_VERSION}.jsonl"));
    match fs::File::create(&path).and_then(|mut f| f.write_all(out.as_bytes())) {
        Ok(()) => {
            eprintln!("rapier2d-f64 {RAPIER_VERSION}: {count} scenes -> {}", path.display());
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: {}: {e}", path.display());
            ExitCode::from(2)
        }
    }
}
