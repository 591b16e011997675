//! Reading `engines/suite.csv`: each scene keeps its cells verbatim (they are echoed into the
//! output) and its numbers as exact rationals, converted to the engine's float only at set-up.

use std::fmt;

/// An exact rational `num/den` (den > 0), as written in the suite (`3`, `-1/2`, `999/1000`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ratio {
    pub num: i64,
    pub den: i64,
}

impl Ratio {
    /// Parses an integer or a fraction `p/q`; the suite's numbers are written that way.
    pub fn parse(text: &str) -> Result<Ratio, String> {
        let (num, den) = match text.split_once('/') {
            Some((p, q)) => (p.trim(), q.trim()),
            None => (text.trim(), "1"),
        };
        let num: i64 = num
            .parse()
            .map_err(|_| format!("'{text}' is not an integer or a fraction p/q"))?;
        let den: i64 = den
            .parse()
            .map_err(|_| format!("'{text}' is not an integer or a fraction p/q"))?;
        if den <= 0 {
            return Err(format!("'{text}': the denominator must be > 0"));
        }
        Ok(Ratio { num, den })
    }
}

impl fmt::Display for Ratio {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.den == 1 {
            write!(f, "{}", self.num)
        } else {
            write!(f, "{}/{}", self.num, self.den)
        }
    }
}

/// How the rod's moment of inertia about its centre follows from M and l (rodimpact's `--rod`).
#[derive(Clone, Copy, Debug)]
pub enum Rod {
    /// I = M l^2 / 3
    Uniform,
    /// I = M l^2
    Dumbbell,
    /// I = M r^2
    RadiusOfGyration(Ratio),
    /// I given directly
    Inertia(Ratio),
}

/// The oblique part of a scene (issue 20): the ball's slide along the rod and spin, friction,
/// and the rod's drift before the impact (the suite's rods never turn before it).
#[derive(Clone, Copy, Debug)]
pub struct Oblique {
    pub v0t: Ratio,
    pub mu: Ratio,
    pub radius: Ratio,
    pub spin: Ratio,
    pub rod_v: Ratio,
    pub rod_vt: Ratio,
}

/// One scene of the suite: the cells as written plus the parsed numbers.
#[derive(Clone, Debug)]
pub struct Scene {
    /// The cells of [`HEADER`], verbatim.
    pub cells: Vec<String>,
    pub m: Ratio,
    pub big_m: Ratio,
    pub l: Ratio,
    pub a: Ratio,
    pub v0: Ratio,
    pub rod: Rod,
    pub e: Ratio,
    /// Signed pivot position on the rod, or `None` for a free rod.
    pub pivot: Option<Ratio>,
    /// The oblique part, or `None` for a perpendicular frictionless impact.
    pub oblique: Option<Oblique>,
}

/// The header the suite must have, in this order.
pub const HEADER: &str =
    "id,class,m,M,l,a,v0,rod,e,pivot,v0t,mu,radius,spin,rod-v,rod-vt,rod-omega";
const COLUMNS: usize = 17;

fn parse_rod(text: &str) -> Result<Rod, String> {
    match text {
        "uniform" => Ok(Rod::Uniform),
        "dumbbell" => Ok(Rod::Dumbbell),
        _ => {
            if let Some(r) = text.strip_prefix("rg=") {
                Ok(Rod::RadiusOfGyration(Ratio::parse(r)?))
            } else if let Some(i) = text.strip_prefix("I=") {
                Ok(Rod::Inertia(Ratio::parse(i)?))
            } else {
                Err(format!(
                    "rod '{text}' is not uniform, dumbbell, rg=Q or I=Q"
                ))
            }
        }
    }
}

/// Reads the suite text; errors name the line and the column.
pub fn parse_suite(text: &str) -> Result<Vec<Scene>, String> {
    let mut lines = text.lines();
    let header = lines.next().ok_or("the suite is empty")?;
    if header.trim() != HEADER {
        return Err(format!("suite header must be '{HEADER}', got '{header}'"));
    }
    let mut scenes = Vec::new();
    for (index, line) in lines.enumerate() {
        let line_no = index + 2;
        if line.trim().is_empty() {
            continue;
        }
        let cells: Vec<String> = line.split(',').map(|c| c.trim().to_string()).collect();
        if cells.len() != COLUMNS {
            return Err(format!(
                "line {line_no}: expected {COLUMNS} cells, got {}",
                cells.len()
            ));
        }
        let number = |column: usize, name: &str| {
            Ratio::parse(&cells[column]).map_err(|e| format!("line {line_no}, column {name}: {e}"))
        };
        let scene = Scene {
            m: number(2, "m")?,
            big_m: number(3, "M")?,
            l: number(4, "l")?,
            a: number(5, "a")?,
            v0: number(6, "v0")?,
            rod: parse_rod(&cells[7]).map_err(|e| format!("line {line_no}, column rod: {e}"))?,
            e: number(8, "e")?,
            pivot: if cells[9].is_empty() {
                None
            } else {
                Some(number(9, "pivot")?)
            },
            oblique: if cells[10..].iter().all(|c| c.is_empty()) {
                None
            } else {
                if number(16, "rod-omega")?.num != 0 {
                    return Err(format!(
                        "line {line_no}: a rod turning before the impact is not set up"
                    ));
                }
                Some(Oblique {
                    v0t: number(10, "v0t")?,
                    mu: number(11, "mu")?,
                    radius: number(12, "radius")?,
                    spin: number(13, "spin")?,
                    rod_v: number(14, "rod-v")?,
                    rod_vt: number(15, "rod-vt")?,
                })
            },
            cells,
        };
        scenes.push(scene);
    }
    Ok(scenes)
}
