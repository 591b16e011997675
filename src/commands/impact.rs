//! `rodimpact impact`: any planar impact with one contact, under the three restitution laws.

use super::{Failure, parse_digits, print_out};
use clap::{Args, ValueEnum};
use rodimpact::batch::audit_impact;
use rodimpact::field::Q;
use rodimpact::model::{MAX_SCENE_BYTES, System, from_value, toml_value};
use rodimpact::report::{
    check_json, check_summary, check_table, impact_audit_json, impact_json, impact_text,
    models_json, models_text,
};
use rodimpact::solve::impact::{Law, solve_exact};
use rodimpact::solve::impact::{MAX_ORDERED, Model, ModelOutcome, orders, solve_several};
use rodimpact::textbook::SceneCheck;
use rodimpact::textbook::impact::{
    ImpactClaim, check_impact_claims, check_model_claims, read_impact_claims,
};
use rodimpact::{Error, ErrorKind};
use std::io::Read;
use std::path::PathBuf;

#[derive(Args, Debug)]
pub(crate) struct ImpactArgs {
    /// The scene: bodies, contacts and pins in TOML (docs/impacts.md; examples/impacts/).
    #[arg(
        value_name = "FILE.toml",
        required_unless_present = "batch",
        conflicts_with = "batch"
    )]
    pub(crate) file: Option<PathBuf>,
    /// Audit many scenes instead: one scene per line in JSON (a scene file's structure) with an
    /// engine's "claimed" bodies; one JSON line out per scene: the exact answers, the claim's
    /// relative errors, which law or model it matches, and a diagnosis. Exit 1 when a claim
    /// matches none.
    #[arg(long, value_name = "FILE.jsonl")]
    pub(crate) batch: Option<PathBuf>,
    /// With --batch: a claim matches an exact answer when every component is within this
    /// relative error [default: 1e-9].
    #[arg(long, value_name = "R", requires = "batch")]
    pub(crate) rtol: Option<String>,
    /// The restitution law: newton (kinematic), poisson (kinetic), energetic (Stronge), or all
    /// three side by side.
    #[arg(long, value_enum, default_value = "all")]
    pub(crate) law: LawChoice,
    /// How several contacts act together: simultaneous-newton, simultaneous-poisson,
    /// sequential (every order), sequential:2,1,3 (one order), pgs:K (K sweeps of projected
    /// Gauss-Seidel), or all (the simultaneous models, sequential in every order, pgs:1 and
    /// pgs:10). For a scene with several contacts only.
    #[arg(long, value_name = "MODEL")]
    pub(crate) model: Option<String>,
    /// Output format.
    #[arg(long, value_enum, default_value = "text")]
    pub(crate) format: ImpactFormat,
    /// Significant digits of the decimals (text: 6 by default; JSON: at least 30).
    #[arg(long, value_name = "N")]
    pub(crate) digits: Option<String>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum LawChoice {
    Newton,
    Poisson,
    Energetic,
    All,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum ImpactFormat {
    Text,
    Json,
}

pub(crate) fn run_impact(args: &ImpactArgs) -> Result<(), Failure> {
    if let Some(batch) = &args.batch {
        return run_batch(args, batch);
    }
    let file = args.file.as_ref().expect("clap requires FILE or --batch");
    let label = rodimpact::echo::echo_path(file);
    let mut bytes = Vec::new();
    std::fs::File::open(file)
        .and_then(|f| f.take(MAX_SCENE_BYTES as u64 + 1).read_to_end(&mut bytes))
        .map_err(|e| Error::io(label.clone(), "cannot read", e))?;
    let text = String::from_utf8(bytes)
        .map_err(|_| Error::new(label.clone(), ErrorKind::Invalid("not UTF-8 text".into())))?;
    let value = toml_value(&label, &text)?;
    let at_file = |e: Error| Error::new(format!("{label}: {}", e.field), e.kind);
    let system = from_value(&value).map_err(at_file)?;
    if system.contacts.len() > 1 {
        let claims = read_impact_claims(&value, &system).map_err(at_file)?;
        return run_models(args, &system, &label, &claims);
    }
    if args.model.is_some() {
        return Err(Error::new(
            "model",
            ErrorKind::Conflict(
                "one contact: the models of several contacts do not apply (the laws do: --law)"
                    .into(),
            ),
        )
        .into());
    }
    let claims = read_impact_claims(&value, &system).map_err(at_file)?;
    // A file's published answers need their laws answered whatever --law says.
    let laws: &[Law] = match args.law {
        _ if !claims.is_empty() => &Law::ALL,
        LawChoice::Newton => &[Law::Newton],
        LawChoice::Poisson => &[Law::Poisson],
        LawChoice::Energetic => &[Law::Energetic],
        LawChoice::All => &Law::ALL,
    };
    let answers = laws
        .iter()
        .map(|&law| {
            solve_exact(&system, law)
                .map_err(|e| Error::new(label.clone(), ErrorKind::Invalid(e.to_string())))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let checked = SceneCheck {
        symbolic: None,
        answers: check_impact_claims(&claims, &system, &answers).map_err(at_file)?,
    };
    match args.format {
        ImpactFormat::Json => {
            let digits = parse_digits(args.digits.as_deref(), 30)?;
            let mut json = impact_json(&system, &answers, digits);
            if !claims.is_empty() {
                json["claims"] = check_json(&checked);
            }
            print_out(&format!(
                "{}\n",
                serde_json::to_string_pretty(&json).expect("JSON of strings and bools")
            ));
        }
        ImpactFormat::Text => {
            let digits = parse_digits(args.digits.as_deref(), 6)?;
            let mut text = impact_text(&system, &answers, digits);
            if !claims.is_empty() {
                text.push_str(&format!(
                    "\nPublished answers (the file's claims, each under its source's law)\n{}  {}\n",
                    check_table(&checked),
                    check_summary(&checked)
                ));
            }
            print_out(&text);
        }
    }
    if checked.all_agree() {
        Ok(())
    } else {
        Err(Failure::Check)
    }
}

/// A scene with several contacts: every model asked for, side by side.
fn run_models(
    args: &ImpactArgs,
    system: &System,
    label: &str,
    claims: &[ImpactClaim],
) -> Result<(), Failure> {
    if args.law != LawChoice::All {
        return Err(Error::new(
            "law",
            ErrorKind::Conflict(
                "several contacts: their models (--model) say how the contacts act together".into(),
            ),
        )
        .into());
    }
    let models = parse_models(
        args.model.as_deref().unwrap_or("all"),
        system.contacts.len(),
    )?;
    let outcomes: Vec<(Model, ModelOutcome<Q>)> = models
        .into_iter()
        .map(|m| {
            let outcome = solve_several::<Q>(system, &m);
            (m, outcome)
        })
        .collect();
    let at_file = |e: Error| Error::new(format!("{label}: {}", e.field), e.kind);
    let checked = SceneCheck {
        symbolic: None,
        answers: check_model_claims(claims, system).map_err(at_file)?,
    };
    match args.format {
        ImpactFormat::Json => {
            let digits = parse_digits(args.digits.as_deref(), 30)?;
            let mut json = models_json(system, &outcomes, digits);
            if !claims.is_empty() {
                json["claims"] = check_json(&checked);
            }
            print_out(&format!(
                "{}\n",
                serde_json::to_string_pretty(&json).expect("JSON of strings and bools")
            ));
        }
        ImpactFormat::Text => {
            let digits = parse_digits(args.digits.as_deref(), 6)?;
            let mut text = models_text(system, &outcomes, digits);
            if !claims.is_empty() {
                text.push_str(&format!(
                    "\nPublished answers (the file's claims, each under its source's model)\n{}  {}\n",
                    check_table(&checked),
                    check_summary(&checked)
                ));
            }
            print_out(&text);
        }
    }
    if checked.all_agree() {
        Ok(())
    } else {
        Err(Failure::Check)
    }
}

/// The models `--model` names, for `n` contacts.
fn parse_models(text: &str, n: usize) -> Result<Vec<Model>, Error> {
    let bad = |why: String| Error::new("model", ErrorKind::Invalid(why));
    let every_order = || -> Result<Vec<Model>, Error> {
        if n > MAX_ORDERED {
            return Err(Error::out_of_range(
                "model",
                format!(
                    "sequential in every order takes at most {MAX_ORDERED} contacts ({n}! orders); give one order, sequential:1,2,..."
                ),
            ));
        }
        Ok(orders(n).into_iter().map(Model::Sequential).collect())
    };
    Ok(match text.trim() {
        "all" => {
            let mut all = vec![Model::SimultaneousNewton, Model::SimultaneousPoisson];
            if n <= MAX_ORDERED {
                all.extend(every_order()?);
            }
            all.extend([Model::Pgs(1), Model::Pgs(10)]);
            all
        }
        "sequential" => every_order()?,
        other => vec![Model::parse(other, n).map_err(|why| {
            bad(if other.contains(':') {
                why
            } else {
                format!(
                    "expected simultaneous-newton, simultaneous-poisson, sequential, sequential:ORDER, pgs:K or all, got '{}'",
                    rodimpact::echo::echo(other)
                )
            })
        })?],
    })
}

/// `impact --batch FILE.jsonl`: every line audited, one JSON line out each, a summary on stderr.
fn run_batch(args: &ImpactArgs, path: &std::path::Path) -> Result<(), Failure> {
    use std::io::{BufRead, Write};
    let label = rodimpact::echo::echo_path(path);
    let rtol = match &args.rtol {
        None => Q::new(1.into(), 1_000_000_000.into()),
        Some(text) => {
            let r = rodimpact::number::parse(text).map_err(|kind| Error::new("rtol", kind))?;
            if r < Q::from_integer(0.into()) {
                return Err(
                    Error::out_of_range("rtol", format!("must be >= 0, got {text}")).into(),
                );
            }
            r
        }
    };
    let file = std::fs::File::open(path).map_err(|e| Error::io(label.clone(), "cannot read", e))?;
    let mut reader = std::io::BufReader::new(file);
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    let (mut scenes, mut claimed) = (0usize, 0usize);
    let mut findings: std::collections::BTreeMap<String, Vec<String>> = Default::default();
    let mut matched: std::collections::BTreeMap<String, usize> = Default::default();
    let mut line = String::new();
    let mut number = 0;
    loop {
        line.clear();
        let read = (&mut reader)
            .take(MAX_SCENE_BYTES as u64 + 1)
            .read_line(&mut line)
            .map_err(|e| Error::io(label.clone(), "cannot read", e))?;
        if read == 0 {
            break;
        }
        number += 1;
        if line.len() > MAX_SCENE_BYTES {
            return Err(Error::out_of_range(
                format!("{label}: line {number}"),
                format!("longer than {MAX_SCENE_BYTES} bytes (limit)"),
            )
            .into());
        }
        if line.trim().is_empty() {
            continue;
        }
        let audit = audit_impact(line.trim_end(), number, &rtol)
            .map_err(|e| Error::new(format!("{label}: {}", e.field), e.kind))?;
        scenes += 1;
        if audit.claimed.is_some() {
            claimed += 1;
            for m in &audit.matches {
                *matched.entry(m.clone()).or_default() += 1;
            }
            for f in &audit.findings {
                findings
                    .entry((*f).into())
                    .or_default()
                    .push(audit.id.clone());
            }
        }
        let json = serde_json::to_string(&impact_audit_json(&audit)).expect("JSON of strings");
        if writeln!(out, "{json}").is_err() {
            return Err(Error::new(
                "stdout",
                ErrorKind::Invalid("cannot write standard output".into()),
            )
            .into());
        }
    }
    let mut summary = format!(
        "{scenes} scene{}, {claimed} with a claimed state\n",
        if scenes == 1 { "" } else { "s" }
    );
    if !matched.is_empty() {
        let list: Vec<String> = matched.iter().map(|(k, v)| format!("{k} {v}")).collect();
        summary.push_str(&format!(
            "claims matching each exact answer: {}\n",
            list.join(", ")
        ));
    }
    if findings.is_empty() {
        summary.push_str("every claim matches an exact answer\n");
    } else {
        summary.push_str("findings:\n");
        for (finding, ids) in &findings {
            let shown: Vec<&str> = ids.iter().take(5).map(String::as_str).collect();
            summary.push_str(&format!(
                "  {finding}: {} ({}{})\n",
                ids.len(),
                shown.join(", "),
                if ids.len() > 5 { ", ..." } else { "" }
            ));
        }
    }
    eprint!("{summary}");
    if findings.is_empty() {
        Ok(())
    } else {
        Err(Failure::Check)
    }
}
