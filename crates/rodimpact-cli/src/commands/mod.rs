//! The subcommands: each file parses its flags and calls the library; this module holds what
//! they share (scene flags, number lists, the failure kinds that become exit codes).

pub(crate) mod batch;
pub(crate) mod check;
pub(crate) mod claims;
pub(crate) mod explore;
pub(crate) mod formula;
pub(crate) mod handout;
pub(crate) mod impact;
pub(crate) mod plot;
pub(crate) mod scenes;
pub(crate) mod simulate;
pub(crate) mod solve;
pub(crate) mod stability;
pub(crate) mod table;

use clap::Args;
use rodimpact::Error;
use rodimpact::scene::{SceneInput, flag_help, parse_field};

/// Scene flags shared by the commands that take one scene. Numbers are exact: "2", "0.25",
/// "3/7", "1.5e-3", "75/9.8", and may carry a unit ("100 g", "120cm", "36 km/h"), converted
/// exactly to SI.
#[derive(Args, Debug)]
pub(crate) struct SceneFlags {
    #[arg(long = "m", value_name = "Q", allow_hyphen_values = true, help = const { flag_help("m") })]
    pub(crate) m: Option<String>,
    #[arg(long = "M", value_name = "Q", allow_hyphen_values = true, help = const { flag_help("M") })]
    pub(crate) rod_mass: Option<String>,
    #[arg(long = "l", value_name = "Q", allow_hyphen_values = true, help = const { flag_help("l") })]
    pub(crate) l: Option<String>,
    #[arg(long, value_name = "Q", allow_hyphen_values = true, help = const { flag_help("length") })]
    pub(crate) length: Option<String>,
    #[arg(long = "a", value_name = "Q", allow_hyphen_values = true, help = const { flag_help("a") })]
    pub(crate) a: Option<String>,
    #[arg(long, value_name = "Q", allow_hyphen_values = true, help = const { flag_help("from-end") })]
    pub(crate) from_end: Option<String>,
    #[arg(long, value_name = "Q", allow_hyphen_values = true, help = const { flag_help("v0") })]
    pub(crate) v0: Option<String>,
    #[arg(long, value_name = "KIND", help = const { flag_help("rod") })]
    pub(crate) rod: Option<String>,
    #[arg(long, value_name = "Q", allow_hyphen_values = true, group = "law", help = const { flag_help("e") })]
    pub(crate) e: Option<String>,
    /// Elastic impact, e = 1 (the default).
    #[arg(long, group = "law")]
    pub(crate) elastic: bool,
    /// Totally inelastic impact, e = 0: the projectile sticks to the rod.
    #[arg(long, group = "law")]
    pub(crate) inelastic: bool,
    #[arg(long, value_name = "Q", allow_hyphen_values = true, help = const { flag_help("pivot") })]
    pub(crate) pivot: Option<String>,
}

impl SceneFlags {
    pub(crate) fn input(&self) -> SceneInput {
        let e = if self.elastic {
            Some("1".to_string())
        } else if self.inelastic {
            Some("0".to_string())
        } else {
            self.e.clone()
        };
        SceneInput {
            m: self.m.clone(),
            rod_mass: self.rod_mass.clone(),
            l: self.l.clone(),
            length: self.length.clone(),
            a: self.a.clone(),
            from_end: self.from_end.clone(),
            v0: self.v0.clone(),
            rod: self.rod.clone(),
            e,
            pivot: self.pivot.clone(),
            ..SceneInput::default()
        }
    }
}

/// The oblique and frictional scene flags of `solve` and `check` (docs/conventions.md,
/// "Oblique and frictional impacts").
#[derive(Args, Debug, Default)]
pub(crate) struct ObliqueFlags {
    #[arg(long, value_name = "Q", allow_hyphen_values = true, help = const { flag_help("v0t") })]
    pub(crate) v0t: Option<String>,
    #[arg(long, value_name = "Q", allow_hyphen_values = true, help = const { flag_help("mu") })]
    pub(crate) mu: Option<String>,
    #[arg(long, value_name = "Q", allow_hyphen_values = true, help = const { flag_help("radius") })]
    pub(crate) radius: Option<String>,
    #[arg(long, value_name = "Q", allow_hyphen_values = true, help = const { flag_help("spin") })]
    pub(crate) spin: Option<String>,
    #[arg(long, value_name = "Q", allow_hyphen_values = true, help = const { flag_help("rod-v") })]
    pub(crate) rod_v: Option<String>,
    #[arg(long, value_name = "Q", allow_hyphen_values = true, help = const { flag_help("rod-vt") })]
    pub(crate) rod_vt: Option<String>,
    #[arg(long, value_name = "Q", allow_hyphen_values = true, help = const { flag_help("rod-omega") })]
    pub(crate) rod_omega: Option<String>,
}

impl ObliqueFlags {
    /// The scene `flags` give, with these oblique inputs added.
    pub(crate) fn input(&self, flags: &SceneFlags) -> SceneInput {
        SceneInput {
            v0t: self.v0t.clone(),
            mu: self.mu.clone(),
            radius: self.radius.clone(),
            spin: self.spin.clone(),
            rod_v: self.rod_v.clone(),
            rod_vt: self.rod_vt.clone(),
            rod_omega: self.rod_omega.clone(),
            ..flags.input()
        }
    }
}

/// How a command ended, mapped to the process exit code.
pub(crate) enum Failure {
    /// Bad input: exit 2 with one line on stderr.
    Input(Error),
    /// A check failed: exit 1 (the report was already printed).
    Check,
}

impl From<Error> for Failure {
    fn from(e: Error) -> Self {
        Failure::Input(e)
    }
}

/// The format names every command takes, with their aliases: `md` is `markdown`, `tex` is
/// `latex`, `txt` is `text`, `htm` is `html`.
const FORMAT_NAMES: [(&str, &str); 10] = [
    ("text", "text"),
    ("txt", "text"),
    ("markdown", "markdown"),
    ("md", "markdown"),
    ("latex", "latex"),
    ("tex", "latex"),
    ("json", "json"),
    ("csv", "csv"),
    ("html", "html"),
    ("htm", "html"),
];

/// The canonical name of the format `text` (an alias taken, case ignored) when it is one of
/// `allowed` (canonical names); else the error naming `field` and what it takes.
pub(crate) fn format_choice(
    field: &str,
    text: &str,
    allowed: &[&'static str],
) -> Result<&'static str, Error> {
    let wanted = text.trim().to_ascii_lowercase();
    FORMAT_NAMES
        .iter()
        .find(|(name, canonical)| *name == wanted && allowed.contains(canonical))
        .map(|(_, canonical)| *canonical)
        .ok_or_else(|| {
            let (last, first) = allowed.split_last().expect("a command takes some format");
            Error::new(
                field,
                rodimpact::ErrorKind::Invalid(format!(
                    "expected {} or {last}, got '{}'",
                    first.join(", "),
                    rodimpact::echo::echo(text)
                )),
            )
        })
}

pub(crate) use rodimpact::report::parse_digits;

/// The most mass ratios one `--ratios` list may hold.
pub(crate) const MAX_RATIOS: usize = 1_000;

/// A comma-separated list of positive mass ratios (at most [`MAX_RATIOS`], counted before any
/// is parsed).
pub(crate) fn parse_ratios(field: &str, list: &str) -> Result<Vec<rodimpact::field::Q>, Error> {
    if list.split(',').nth(MAX_RATIOS).is_some() {
        return Err(Error::out_of_range(
            field,
            format!("more than {MAX_RATIOS} ratios (limit)"),
        ));
    }
    list.split(',')
        .map(|text| {
            let x = parse_field(field, text)?;
            if x > rodimpact::field::Q::from_integer(0.into()) {
                Ok(x)
            } else {
                Err(Error::out_of_range(
                    field,
                    format!("mass ratios must be > 0, got {x}"),
                ))
            }
        })
        .collect()
}

/// Writes `text` to standard output. When the reader has gone (`rodimpact paper | head`, a
/// broken pipe), the program ends quietly (exit 0); any other failure (a full disk, `/dev/full`)
/// ends it with exit 2 and one line, so a lost report never passes for success.
pub(crate) fn print_out(text: &str) {
    use std::io::Write;
    let mut stdout = std::io::stdout().lock();
    if let Err(why) = stdout
        .write_all(text.as_bytes())
        .and_then(|()| stdout.flush())
    {
        stdout_failed(&why);
    }
}

/// The `--summary-json` file of an audit, opened before the audit runs so that a path that
/// cannot be written is refused at once, not after every line was audited.
pub(crate) struct SummaryFile(Option<(rodimpact::io::AtomicFile, String)>);

impl SummaryFile {
    /// Opens `path` (nothing without one).
    pub(crate) fn open(path: Option<&std::path::Path>) -> Result<SummaryFile, Error> {
        path.map(|p| {
            rodimpact::io::AtomicFile::create("summary-json", p)
                .map(|file| (file, rodimpact::echo::echo_path(p)))
        })
        .transpose()
        .map(SummaryFile)
    }

    /// Writes `json`, pretty-printed, all or nothing.
    pub(crate) fn write(self, json: &serde_json::Value) -> Result<(), Error> {
        use std::io::Write;
        let Some((mut file, label)) = self.0 else {
            return Ok(());
        };
        let text = serde_json::to_string_pretty(json).expect("JSON of numbers and strings");
        writeln!(file, "{text}")
            .map_err(|why| Error::io("summary-json", format!("cannot write {label}"), why))?;
        file.commit()
    }
}

/// Ends the program after a write to standard output failed: quietly for a broken pipe (the
/// reader has all it wanted), otherwise with `error: out: cannot write standard output: <reason>`
/// and exit 2.
pub(crate) fn stdout_failed(why: &std::io::Error) -> ! {
    if why.kind() == std::io::ErrorKind::BrokenPipe {
        std::process::exit(0);
    }
    let error = Error::io(
        "out",
        "cannot write standard output",
        std::io::Error::new(why.kind(), why.to_string()),
    );
    print_err(&format!("error: {error}\n"));
    std::process::exit(2)
}

/// Writes `text` to standard error. A failure there cannot be reported anywhere, so it is
/// ignored (never a panic): the exit code still tells.
pub(crate) fn print_err(text: &str) {
    use std::io::Write;
    let _ = std::io::stderr().lock().write_all(text.as_bytes());
}
