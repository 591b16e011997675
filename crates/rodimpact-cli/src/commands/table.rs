//! `rodimpact table`: the exact tables T1-T5 of the paper, and T6 beyond it.

use super::{Failure, parse_ratios, print_out};
use clap::Args;
use num_traits::{One, Signed};
use rodimpact::field::Q;
use rodimpact::io::write_atomic;
use rodimpact::report::{self, Format};
use rodimpact::scene::{Disc, RodInertia, parse_field, spin_without_disc};
use rodimpact::tables::{self, TableOptions};
use rodimpact::{Error, ErrorKind};
use std::path::PathBuf;

#[derive(Args, Debug)]
pub(crate) struct TableArgs {
    /// Mass ratios M/m for T1 and T5, comma separated [default: 1/100,1/10,1/2,1,3/2,2,3,10,100].
    #[arg(long, value_name = "Q,Q,...")]
    pub(crate) ratios: Option<String>,
    /// The mass ratio M/m of T2, T3 and T6 [default: 1].
    #[arg(long, value_name = "Q")]
    pub(crate) ratio: Option<String>,
    /// Mass distribution: uniform, dumbbell, rg=R (r_G = R l) or I=X (I = X M l^2), with
    /// 0 < R, X <= 1 (all tables but T4) [default: uniform].
    #[arg(long, value_name = "KIND")]
    pub(crate) rod: Option<String>,
    /// Coefficient of restitution for T1, T2, T5 and T6 [default: 1].
    #[arg(long, value_name = "Q", allow_hyphen_values = true)]
    pub(crate) e: Option<String>,
    /// A pivot at p (in units of l) for T1.
    #[arg(long, value_name = "Q", allow_hyphen_values = true)]
    pub(crate) pivot: Option<String>,
    /// The projectile's velocity along the rod for T6, in units of v0 [default: 1].
    #[arg(long, value_name = "Q", allow_hyphen_values = true)]
    pub(crate) v0t: Option<String>,
    /// T6's impact point, in units of l, |a| <= 1 [default: 1, the end].
    #[arg(long, value_name = "Q", allow_hyphen_values = true)]
    pub(crate) a: Option<String>,
    /// T6's projectile as a solid disc (I = m r^2/2) of this radius, in units of l.
    #[arg(long, value_name = "Q", allow_hyphen_values = true)]
    pub(crate) radius: Option<String>,
    /// The T6 disc's spin before the impact, counterclockwise seen from above, in units of
    /// v0/l (needs --radius) [default: 0].
    #[arg(long, value_name = "Q", allow_hyphen_values = true)]
    pub(crate) spin: Option<String>,
    /// Output format: md, latex or csv. CSV: one table is one file (a header line, exact
    /// strings and `_decimal` columns); several tables make one file with a leading `table`
    /// column (T1-T6) and the union of their columns, empty where a table has none.
    #[arg(long, value_name = "FORMAT", default_value = "md")]
    pub(crate) format: String,
    /// Only these tables, comma separated: T1-T5 (the paper's) and T6 (an oblique impact with
    /// friction, the contact as mu grows past its threshold) [default: T1-T5].
    #[arg(long, value_name = "T1,T2,...")]
    pub(crate) only: Option<String>,
    /// Write to FILE (atomically) instead of standard output.
    #[arg(long, value_name = "FILE")]
    pub(crate) out: Option<PathBuf>,
}

fn table_options(args: &TableArgs) -> Result<TableOptions, Error> {
    let mut opts = TableOptions::default();
    if let Some(list) = &args.ratios {
        opts.ratios = parse_ratios("ratios", list)?;
    }
    if let Some(r) = &args.ratio {
        opts.ratio = parse_ratios("ratio", r)?.remove(0);
    }
    if let Some(rod) = &args.rod {
        opts.rod = relative_rod(rod)?;
    }
    if let Some(e) = &args.e {
        opts.e = parse_field("e", e)?;
    }
    if let Some(p) = &args.pivot {
        opts.pivot = Some(parse_field("pivot", p)?);
    }
    if let Some(v0t) = &args.v0t {
        opts.v0t = parse_field("v0t", v0t)?;
    }
    if let Some(a) = &args.a {
        opts.a = parse_field("a", a)?;
    }
    let spin = args
        .spin
        .as_deref()
        .map(|s| parse_field("spin", s))
        .transpose()?;
    opts.disc = match (&args.radius, spin) {
        (Some(r), spin) => Some(Disc {
            radius: parse_field("radius", r)?,
            spin: spin.unwrap_or_default(),
        }),
        (None, Some(_)) => return Err(spin_without_disc()),
        (None, None) => None,
    };
    Ok(opts)
}

/// `--rod` in units of l and M l^2: `I=X` needs 0 < X <= 1 (the scene's own check would name
/// I in absolute units, which differ from one mass ratio to the next).
fn relative_rod(text: &str) -> Result<RodInertia, Error> {
    let rod = RodInertia::parse(text)?;
    if let RodInertia::Moment(x) = &rod
        && !(x.is_positive() && *x <= Q::one())
    {
        return Err(Error::out_of_range(
            "rod",
            format!("I=X means I = X M l^2 and needs 0 < X <= 1, got {x}"),
        ));
    }
    Ok(rod)
}

fn parse_format(text: &str) -> Result<Format, Error> {
    Format::parse(text).ok_or_else(|| {
        Error::new(
            "format",
            ErrorKind::Invalid(format!(
                "expected md, latex or csv, got '{}'",
                rodimpact::echo::echo(text)
            )),
        )
    })
}

/// Which tables each table-specific flag changes (the `--help` of each flag says the same).
const USES: [(&str, &[&str]); 9] = [
    ("ratios", &["T1", "T5"]),
    ("ratio", &["T2", "T3", "T6"]),
    ("rod", &["T1", "T2", "T3", "T5", "T6"]),
    ("e", &["T1", "T2", "T5", "T6"]),
    ("pivot", &["T1"]),
    ("v0t", &["T6"]),
    ("a", &["T6"]),
    ("radius", &["T6"]),
    ("spin", &["T6"]),
];

/// Refuses, by name, a flag that changes none of the tables asked for (`--only T6 --pivot 0`
/// printed T6 unchanged, as `plot` refuses flags that change nothing in its figure). Ids that
/// are not tables are left to `tables::tables`, which names them.
fn refuse_unused(args: &TableArgs) -> Result<(), Error> {
    let given = [
        args.ratios.is_some(),
        args.ratio.is_some(),
        args.rod.is_some(),
        args.e.is_some(),
        args.pivot.is_some(),
        args.v0t.is_some(),
        args.a.is_some(),
        args.radius.is_some(),
        args.spin.is_some(),
    ];
    let wanted: Vec<String> = match &args.only {
        Some(only) => only
            .split(',')
            .map(|t| t.trim().to_ascii_uppercase())
            .collect(),
        None => tables::TABLE_IDS.iter().map(|t| t.to_string()).collect(),
    };
    if wanted
        .iter()
        .any(|w| !tables::ALL_TABLE_IDS.contains(&w.as_str()))
    {
        return Ok(());
    }
    for ((flag, uses), given) in USES.iter().zip(given) {
        if given && !uses.iter().any(|t| wanted.iter().any(|w| w == t)) {
            let asked = match &args.only {
                Some(only) => format!("--only {}", rodimpact::echo::echo(only)),
                None => "the default T1-T5".to_string(),
            };
            return Err(Error::new(
                *flag,
                ErrorKind::Conflict(format!(
                    "changes only {}, which {asked} leaves out; leave --{flag} out",
                    uses.join(", ")
                )),
            ));
        }
    }
    Ok(())
}

pub(crate) fn run_table(args: &TableArgs) -> Result<(), Failure> {
    let format = parse_format(&args.format)?;
    let opts = table_options(args)?;
    refuse_unused(args)?;
    let tables = match &args.only {
        Some(only) => tables::tables(&only.split(',').collect::<Vec<_>>(), &opts)?,
        None => tables::all_tables(&opts)?,
    };
    let text = report::render_document(&tables, format);
    match &args.out {
        Some(path) => write_atomic("out", path, &text)?,
        None => print_out(&text),
    }
    Ok(())
}
