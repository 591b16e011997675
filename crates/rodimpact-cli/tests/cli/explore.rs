//! `rodimpact explore`: the interactive page, written whole, self-contained and small, with
//! rodimpact's exact answers for its reference scenes embedded (the page checks its own
//! arithmetic against them when it opens; `.ci/browser/run` drives it in headless Chromium).

use crate::common;

use common::rodimpact;

fn page() -> String {
    let (code, stdout, stderr) = rodimpact(&["explore"]);
    assert_eq!(code, 0, "{stderr}");
    stdout
}

#[test]
fn a_small_page_that_asks_nothing_of_the_network() {
    let page = page();
    assert!(page.starts_with("<!DOCTYPE html>"));
    assert!(page.len() < 3_000_000, "{} bytes", page.len());
    assert!(!page.contains("{{"), "a template slot left unfilled");
    for needle in [
        " src=",
        "<link",
        "@import",
        "url(",
        "https://",
        "<iframe",
        "fetch(",
        "XMLHttpRequest",
    ] {
        assert!(!page.contains(needle), "{needle}");
    }
    // The only http:// is the SVG namespace the script creates elements in.
    assert_eq!(page.matches("http://").count(), 1);
    assert!(page.contains("\"http://www.w3.org/2000/svg\""));
    // Every control is labelled: a <label for=ID> or an aria-label on the input itself.
    for id in [
        "ratio",
        "a",
        "e",
        "rg",
        "pivot",
        "guess",
        "time",
        "ratio-slider",
        "a-slider",
        "e-slider",
    ] {
        let tag_start = page
            .find(&format!("<input id=\"{id}\""))
            .unwrap_or_else(|| panic!("{id}"));
        let tag = &page[tag_start..tag_start + page[tag_start..].find('>').unwrap()];
        assert!(
            page.contains(&format!("<label for=\"{id}\"")) || tag.contains("aria-label="),
            "{id} has no label"
        );
    }
}

/// The embedded answers are rodimpact's: the default scene (M = m, a = l/2, elastic, uniform
/// rod) has a*^2 = (M + m) l^2/(3 m) = 2/3 l^2, a* = sqrt(6)/3 l, omega = 2 a/(a*^2 + a^2) =
/// 12/11 v0/l; the heavy rod M = 3m struck elastically at the end has a*^2 = 4/3 l^2, a* =
/// 2 sqrt(3)/3 l beyond the end, and omega_max = omega(l) = 2 l/(4/3 + 1) = 6/7 v0/l; the pivoted rod
/// (p = l/4, M = 3m/2, e = 1/2) has its pivot impulse -11/7 m v0.
#[test]
fn the_reference_answers_are_rodimpacts() {
    let page = page();
    let start = page
        .find("<script type=\"application/json\" id=\"reference\">")
        .unwrap();
    let json = &page[start..];
    let json = &json[json.find('>').unwrap() + 1..json.find("</script>").unwrap()];
    let reference: serde_json::Value = serde_json::from_str(json).unwrap();
    let first = &reference[0];
    assert_eq!(first["input"]["M"], "1");
    assert_eq!(first["a_star"], "sqrt(6)/3");
    assert_eq!(first["omega"], "12/11");
    let heavy = reference
        .as_array()
        .unwrap()
        .iter()
        .find(|r| r["input"]["M"] == "3")
        .unwrap();
    assert_eq!(heavy["a_star"], "2*sqrt(3)/3");
    assert_eq!(heavy["omega_max"], "6/7");
    let pivot = reference
        .as_array()
        .unwrap()
        .iter()
        .find(|r| r["input"]["pivot"] == "1/4")
        .unwrap();
    assert_eq!(pivot["pivot_impulse"], "-11/7");
    // Struck exactly at a* (X19's scene: M = m, elastic): v = V = m v0/(M + m) = 1/2 and
    // omega a* = v0, so omega = 1/a* = sqrt(6)/2, and no energy is lost.
    let at = |a: &str| {
        reference
            .as_array()
            .unwrap()
            .iter()
            .find(|r| r["input"]["a"] == a)
            .unwrap()
    };
    let x19 = at("a*");
    assert_eq!(
        [&x19["v"], &x19["V"], &x19["omega"], &x19["energy_lost"]],
        ["1/2", "1/2", "sqrt(6)/2", "0"]
    );
    // On a pivot at p = -l (uniform rod, M = m, e = 1/3) struck at p + a*: I_p = I + M p^2 =
    // 4/3, a* = sqrt(I_p/m) = 2 sqrt(3)/3; J = (1 + e)/(1 + a*^2/I_p) = 2/3, v = 1 - J = 1/3,
    // omega = J a*/I_p = sqrt(3)/3, V = -omega p = sqrt(3)/3, and the pivot's impulse
    // M V - J = -2/3 + sqrt(3)/3: a number of Q(sqrt 3), as rodimpact spells it.
    let pivoted = at("p+a*");
    assert_eq!(
        [
            &pivoted["v"],
            &pivoted["V"],
            &pivoted["omega"],
            &pivoted["pivot_impulse"]
        ],
        ["1/3", "sqrt(3)/3", "sqrt(3)/3", "-2/3 + sqrt(3)/3"]
    );
    assert_eq!(
        reference.as_array().unwrap().len(),
        rodimpact::app::pages::REFERENCE_SCENES.len()
    );
}

#[test]
fn out_writes_the_page_whole_and_refuses_a_bad_path() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("explore.html");
    let (code, stdout, _) = rodimpact(&["explore", "--out", file.to_str().unwrap()]);
    assert_eq!(code, 0);
    assert!(stdout.is_empty());
    assert_eq!(std::fs::read_to_string(&file).unwrap(), page());
    let missing = dir.path().join("none/explore.html");
    let (code, _, err) = rodimpact(&["explore", "--out", missing.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(
        err.starts_with("error: out:") && err.trim_end().lines().count() == 1,
        "{err}"
    );
    let (code, _, _) = rodimpact(&["explore", "--bogus"]);
    assert_eq!(code, 2);
}

/// NEWCOMER M4: the page opens in predict-first mode and its introduction asks the question
/// without answering it (the browser run checks that the answer is then hidden on screen).
#[test]
fn the_page_opens_asking_not_answering() {
    let page = page();
    assert!(page.contains(r#"<input type="checkbox" id="predict" checked>"#));
    assert!(
        page.contains(r#"<div id="guess-box">"#),
        "the guess is offered at once"
    );
    let header = &page[page.find("<header>").unwrap()..page.find("</header>").unwrap()];
    assert!(
        header.contains("Where should it\nhit to make the rod spin fastest?"),
        "{header}"
    );
    for answer in ["interior point", "a</i>*", "2<i>m</i>", "√"] {
        assert!(
            !header.contains(answer),
            "the introduction gives away {answer:?}"
        );
    }
}

/// The preset the page opens on, as `explore` wrote it (the link's keys, after `#`).
fn preset(args: &[&str]) -> String {
    let mut all = vec!["explore"];
    all.extend_from_slice(args);
    let (code, page, stderr) = rodimpact(&all);
    assert_eq!(code, 0, "{stderr}");
    let start = "<script type=\"application/json\" id=\"preset\">";
    let json = &page[page.find(start).expect("the preset") + start.len()..];
    serde_json::from_str(&json[..json.find("</script>").unwrap()]).unwrap()
}

/// NEWCOMER m10: a teacher presets the page with solve's own flags, in the page's units
/// (m = l = v0 = 1: the ratios), and "predict first" and the view of the motion with their own.
#[test]
fn flags_preset_the_page_in_its_units() {
    assert_eq!(preset(&[]), "", "nothing given, nothing preset");
    assert_eq!(
        preset(&[
            "--M",
            "1/2",
            "--a",
            "1",
            "--e",
            "1/2",
            "--rod",
            "dumbbell",
            "--pivot",
            "-1",
            "--no-predict",
            "--frame",
            "lab",
        ]),
        "M=1/2&a=1&e=1/2&rod=dumbbell&pivot=-1&predict=0&frame=lab"
    );
    // Units and lengths, read exactly as solve reads them: M/m = 0.3 kg/100 g = 3; a rod 2 m
    // long has l = 1 m, so a = l - 1/2 = 1/2, r_G = 50 cm = l/2 and p = -0.5 = -l/2.
    assert_eq!(
        preset(&[
            "--m",
            "100 g",
            "--M",
            "0.3kg",
            "--length",
            "2",
            "--from-end",
            "1/2",
            "--rod",
            "rg=50 cm",
            "--pivot",
            "-0.5",
        ]),
        "M=3&a=1/2&rod=rg=1/2&pivot=-1/2"
    );
    // m defaults to 1 and M to m; l scales a; a moment of inertia with a rational r_G is taken.
    assert_eq!(preset(&["--m", "2"]), "M=1");
    assert_eq!(preset(&["--l", "2", "--a", "-1"]), "a=-1/2");
    assert_eq!(preset(&["--M", "2", "--rod", "I=1/2"]), "M=2&rod=rg=1/2");
    assert_eq!(preset(&["--inelastic", "--predict"]), "e=0&predict=1");
    assert_eq!(
        preset(&["--predict", "--no-predict"]),
        "predict=0",
        "the last wins"
    );
    // a* itself, as the page's a field takes it (NEWCOMER capability 2), and from a pivot.
    assert_eq!(preset(&["--a", "a*"]), "a=a*");
    assert_eq!(
        preset(&["--a", "p - a*", "--pivot", "-1"]),
        "a=p-a*&pivot=-1"
    );
    // The oblique tab, opened by solve's oblique flags, in the page's units (v0 = 2: v0t/v0 = 1;
    // l = 2: r/l = 1/10, spin l/v0 = 3).
    assert_eq!(
        preset(&["--v0t", "1", "--mu", "1/4"]),
        "tab=oblique&v0t=1&mu=1/4"
    );
    assert_eq!(
        preset(&[
            "--v0", "2", "--l", "2", "--v0t", "2", "--mu", "0.5", "--radius", "0.2", "--spin", "3"
        ]),
        "tab=oblique&v0t=1&mu=1/2&radius=1/10&spin=3"
    );
}

/// What the page cannot open on is refused, naming the flag.
#[test]
fn a_star_and_oblique_presets_refuse_what_the_page_cannot_show() {
    for (args, message) in [
        (
            &["--a", "p+a*"][..],
            "error: a: 'p+a*' and 'p-a*' are measured from a pivot: give --pivot\n",
        ),
        (
            &["--v0t", "1", "--rod-omega", "1/2"][..],
            "error: rod-omega: the page's oblique tab takes a rod at rest (--v0t, --mu, --radius and --spin)\n",
        ),
    ] {
        crate::common::assert_refused(&[&["explore"][..], args].concat(), message);
    }
}

/// A bad preset is refused as solve refuses it: one line naming the flag, exit 2, no page.
#[test]
fn a_bad_preset_is_one_line_naming_its_flag() {
    for (args, message) in [
        (&["--M", "-1"][..], "error: M: must be > 0, got -1"),
        (
            &["--a", "2"],
            "error: a: must lie on the rod, |a| <= l = 1, got 2",
        ),
        (
            &["--e", "3/2"],
            "error: e: coefficient of restitution must lie in [0, 1], got 3/2",
        ),
        (
            &["--rod", "steel"],
            "error: rod: expected uniform, dumbbell, rg=<radius> or I=<inertia>, got 'steel'",
        ),
        (
            &["--pivot", "2"],
            "error: pivot: must lie on the rod, |pivot| <= l = 1, got 2",
        ),
        (&["--m", "1/0"], "error: m: division by zero"),
        (
            &["--a", "1", "--from-end", "0"],
            "error: from-end: give either --a or --from-end, not both",
        ),
        (
            &["--rod", "I=1/2"],
            "error: rod: the page takes uniform, dumbbell or rg=<radius>; this moment of inertia \
             gives r_G = sqrt(2)/2 l, not a fraction",
        ),
        (
            &["--M", "1e40"],
            "error: M: the page takes at most 30 digits above and below the fraction bar, got \
             1000000000000000000000000000000000000000...",
        ),
        (
            &["--frame", "sideways"],
            "error: invalid value 'sideways' for '--frame <VIEW>' [possible values: \
             centre-of-mass, lab] (try --help)",
        ),
    ] {
        let mut all = vec!["explore"];
        all.extend_from_slice(args);
        let (code, stdout, stderr) = rodimpact(&all);
        assert_eq!(code, 2, "{args:?}");
        assert!(stdout.is_empty(), "{args:?}: no page");
        assert_eq!(stderr.trim_end(), message, "{args:?}");
    }
    // The same flags, the same messages as solve's.
    let (_, _, solve) = rodimpact(&["solve", "--m", "1", "--M", "1", "--pivot", "2"]);
    let (_, _, explore) = rodimpact(&["explore", "--pivot", "2"]);
    assert_eq!(solve, explore);
}

/// The second page: `--scene tilted-rod`, preset by `--tilt`, `--slip`, `--mu` and `--e` (read
/// exactly, as the page reads them); the paper's flags refused there, and its flags refused on the
/// paper's page, each in one line naming the flag.
#[test]
fn the_tilted_rod_page_and_its_flags() {
    let (code, page, err) = rodimpact(&[
        "explore",
        "--scene",
        "tilted-rod",
        "--tilt",
        "1/4",
        "--slip",
        "-0.5",
        "--mu",
        "0.5",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(page.starts_with("<!DOCTYPE html>") && page.contains("Routh"));
    assert!(page.contains(
        "<script type=\"application/json\" id=\"preset\">\"tan_half=1/4&slip=-1/2&mu=1/2\"</script>"
    ));
    for (args, message) in [
        (
            vec!["--scene", "tilted-rod", "--M", "2"],
            "error: M: not a setting of the tilted-rod page, which takes --tilt, --slip, --mu and --e\n",
        ),
        (
            vec!["--scene", "tilted-rod", "--frame", "lab"],
            "error: frame: not a setting of the tilted-rod page, which takes --tilt, --slip, --mu and --e\n",
        ),
        (
            vec!["--scene", "tilted-rod", "--tilt", "1"],
            "error: tilt: must lie in 0 < tan(θ/2) < 1 (a tilt between 0 and 90 degrees)\n",
        ),
        (
            vec!["--scene", "tilted-rod", "--mu", "-1"],
            "error: mu: must be ≥ 0\n",
        ),
        (
            vec!["--slip", "1"],
            "error: slip: a setting of the tilted-rod page (--scene tilted-rod)\n",
        ),
        // Not a number, said as such (RELIABILITY H15: it was "exponent beyond ±60", the 'e'
        // of "alert" read as an exponent); a real exponent past the page's limit still refused.
        (
            vec![
                "--scene",
                "tilted-rod",
                "--tilt",
                "</script><script>alert(1)</script>",
            ],
            "error: tilt: not a number: more than one '/' in \"</script><script>alert(1)</script>\"\n",
        ),
        (
            vec!["--scene", "tilted-rod", "--tilt", "abc"],
            "error: tilt: not a number: unexpected character 'a' at position 1 in \"abc\"\n",
        ),
        (
            vec!["--scene", "tilted-rod", "--tilt", "1e-61"],
            "error: tilt: exponent beyond ±60\n",
        ),
    ] {
        crate::common::assert_refused(&[&["explore"][..], &args[..]].concat(), message);
    }
}

/// Both pages compute with the library compiled to WebAssembly, inlined: no arithmetic of their
/// own (the BigInt rationals and the JavaScript physics are gone) and no request beyond the page.
#[test]
fn the_pages_carry_the_library_not_a_copy_of_the_physics() {
    for args in [vec!["explore"], vec!["explore", "--scene", "tilted-rod"]] {
        let (code, page, err) = rodimpact(&args);
        assert_eq!(code, 0, "{err}");
        let module = page
            .split("<script type=\"application/octet-stream\" id=\"rodimpact-wasm\">")
            .nth(1)
            .and_then(|rest| rest.split("</script>").next())
            .expect("the module is inlined");
        assert!(
            module.len() > 100_000
                && module
                    .bytes()
                    .all(|b| b.is_ascii_alphanumeric() || b"+/=".contains(&b))
        );
        for copy in ["BigInt", "const Physics", "const Exact", "fetch("] {
            assert!(!page.contains(copy), "{args:?}: {copy}");
        }
        assert!(page.contains("rodimpactPage(function (api) {"));
        assert!(page.len() < 1_000_000, "{} bytes", page.len());
    }
}
