//! Regression tests for what a newcomer meets on the command line: exit codes, range
//! checks and memory guards before any work, errors that name their path, help texts
//! that list the valid values, `check --verify-expected`, and `render` (pictures that
//! fill their panels, a legend, error panels, simple polygons with crossing points, the
//! limit warning, SVG only).

use crate::common::run;
use std::path::PathBuf;

fn temp(name: &str) -> PathBuf {
    std::env::temp_dir().join(format!("polysect-options-{}-{name}", std::process::id()))
}

/// Usage errors: exit 2, a message on standard error, nothing on standard output.
fn usage_error(args: &[&str]) -> String {
    let (code, out, err) = run(args, b"");
    assert_eq!(code, 2, "{args:?}: exit {code}, stderr {err}");
    assert!(out.is_empty(), "{args:?} wrote {out}");
    err
}

#[test]
fn demo_checks_its_options_before_any_work() {
    for args in [
        ["demo", "--polygons", "0"],
        ["demo", "--max-log2", "2"],
        ["demo", "--max-log2", "40"],
        ["demo", "--steps", "0"],
    ] {
        let err = usage_error(&args);
        assert!(err.contains(args[1]), "{err}");
    }
    // In range, but beyond the memory guard: refused with the estimate.
    let err = usage_error(&["demo", "--polygons", "4096", "--max-log2", "24"]);
    assert!(err.contains("would need about") && err.contains("GB"), "{err}");
    // A picture render cannot write is refused as usage, before the work.
    let err = usage_error(&["demo", "--svg", "scene.png"]);
    assert!(err.contains("SVG only") && err.contains("rsvg-convert"), "{err}");
}

#[test]
fn demo_exits_1_when_its_picture_cannot_be_written() {
    let (code, out, err) = run(&["demo", "--svg", "/nonexistent/x.svg", "--polygons", "3"], b"");
    assert_eq!(code, 1, "{out}{err}");
    assert!(err.contains("cannot write /nonexistent/x.svg"), "{err}");
    // It failed first, not after running every workload.
    assert!(!out.contains("planner"), "{out}");
}

#[test]
fn demo_draws_the_scene_of_its_table_with_a_legend() {
    let svg = temp("demo.svg");
    let (code, out, err) = run(
        &[
            "demo",
            "--polygons",
            "10",
            "--max-log2",
            "12",
            "--steps",
            "60",
            "--svg",
            svg.to_str().unwrap(),
        ],
        b"",
    );
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("below 1: the planner was faster"),
        "the ratios are explained: {out}"
    );
    assert!(!out.contains("NaN"), "{out}");
    // The planner's ratio is a median over repeated runs, with their spread.
    assert!(out.contains("the median of 21 runs"), "{out}");
    let ratios: Vec<&str> = out.lines().filter(|l| l.contains("planner = ")).collect();
    assert_eq!(ratios.len(), 3, "{out}");
    for line in ratios {
        assert!(
            line.contains("[middle half ") && line.contains(", all "),
            "{line}"
        );
    }
    let picture = std::fs::read_to_string(&svg).unwrap();
    assert_eq!(picture.matches("<polygon").count(), 10, "the table's 10 polygons");
    assert!(
        picture.contains("before its workloads: 10 polygons, 2^3 to 2^12"),
        "{picture}"
    );
    // The legend tells the colours apart by how many others a polygon meets.
    assert!(
        picture.contains("intersects more than ") && picture.contains("intersects none ("),
        "{picture}"
    );
    assert!(picture.contains("intersects 1 other (") || picture.contains("intersects 1 to "));
    // Polygons of up to 2^12 vertices are thinned for drawing, and say so.
    assert!(picture.contains("drawn with at most 720"));
    let _ = std::fs::remove_file(svg);
}

#[test]
fn gen_refuses_sizes_that_are_not_polygons_or_do_not_fit() {
    for n in ["0", "2", "100000000000"] {
        let err = usage_error(&["gen", "--n", n]);
        assert!(err.contains("3..=16777216") || err.contains("3 to"), "{n}: {err}");
    }
    let (code, out, _) = run(&["gen", "--n", "3", "--count", "2"], b"");
    assert_eq!(code, 0);
    for line in out.lines() {
        let v: serde_json::Value = serde_json::from_str(line).unwrap();
        assert_eq!(v["n"], 3);
        assert_eq!(v["p"].as_array().unwrap().len(), 3);
    }
}

#[test]
fn errors_name_the_path() {
    for args in [
        vec!["check", "/tmp"],
        vec!["crossings", "/tmp"],
        vec!["scene", "/tmp"],
        vec!["render", "/tmp", "--out", "/tmp/polysect-never.svg"],
    ] {
        let (code, _, err) = run(&args, b"");
        assert_eq!(code, 1, "{args:?}");
        assert!(err.contains("cannot read /tmp"), "{args:?}: {err}");
    }
    let (code, _, err) = run(
        &["bench", "--quick", "--no-progress", "--out", "/proc/nope", "sqrt"],
        b"",
    );
    assert_eq!(code, 1);
    assert!(err.contains("/proc/nope"), "{err}");
    let (code, _, err) = run(&["render", "--out", "/nonexistent/pairs.svg"], b"");
    assert_eq!(code, 1);
    assert!(err.contains("cannot write /nonexistent/pairs.svg"), "{err}");
}

/// Every option of every subcommand has a description (clap's short help puts it on
/// the option's line).
#[test]
fn every_option_is_described_and_lists_its_values() {
    let (_, top, _) = run(&["--help"], b"");
    assert!(top.contains("3 when `check --verify-expected`"), "{top}");
    for command in [
        "check",
        "scene",
        "crossings",
        "gen",
        "bench",
        "list",
        "demo",
        "render",
        "calibrate",
        "serve",
    ] {
        let (code, help, _) = run(&[command, "-h"], b"");
        assert_eq!(code, 0);
        let mut options = 0;
        for line in help.lines().skip_while(|l| !l.starts_with("Options:")).skip(1) {
            let spec = line.trim_start();
            if !spec.starts_with('-') {
                continue;
            }
            options += 1;
            let described = spec
                .split_once("  ")
                .is_some_and(|(_, text)| !text.trim().is_empty());
            assert!(described, "{command}: `{line}` has no description");
        }
        assert!(options >= 1, "{command}: {help}");
    }
    let (_, check, _) = run(&["check", "-h"], b"");
    for word in [
        "exact",
        "fast",
        "linear",
        "chazelle-dobkin",
        "Seed",
        "--verify-expected",
    ] {
        assert!(check.contains(word), "check -h lacks {word}");
    }
    // The families gen lists are the ones `list` knows.
    let (_, gen_help, _) = run(&["gen", "-h"], b"");
    let (_, list, _) = run(&["list"], b"");
    let families = list.lines().find(|l| l.starts_with("families:")).unwrap();
    for family in families["families:".len()..].split(',') {
        assert!(gen_help.contains(family.trim()), "gen -h lacks {family}");
    }
    let (_, crossings, _) = run(&["crossings", "--help"], b"");
    assert!(
        crossings.contains("shared edge gives its two endpoints"),
        "{crossings}"
    );
}

const GOOD_AND_BAD: &str = r#"{"expected": true, "p": [[0,0],[1,0],[0,1]], "q": [[1,0],[2,0],[2,1]]}
{"expected": true, "p": [[0,0],[1,0],[0,1]], "q": [[5,5],[6,5],[5,6]]}
"#;

#[test]
fn check_verify_expected_compares_with_gen() {
    let (code, generated, _) = run(
        &[
            "gen",
            "--family",
            "one-ulp-gap",
            "--count",
            "40",
            "--n",
            "12",
            "--seed",
            "9",
        ],
        b"",
    );
    assert_eq!(code, 0);
    let (code, out, err) = run(&["check", "--verify-expected"], generated.as_bytes());
    assert_eq!(code, 0, "{err}");
    assert!(
        err.contains("40 answer(s) compared") && err.contains("0 disagree"),
        "{err}"
    );
    for line in out.lines() {
        let v: serde_json::Value = serde_json::from_str(line).unwrap();
        assert_eq!(v["agrees"], true, "{line}");
    }
    // A wrong "expected" is found: exit 3, "agrees": false on its line.
    let (code, out, err) = run(&["check", "--verify-expected"], GOOD_AND_BAD.as_bytes());
    assert_eq!(code, 3, "{err}");
    assert!(err.contains("1 disagree"), "{err}");
    let lines: Vec<serde_json::Value> = out.lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    assert_eq!(lines[0], serde_json::json!({"intersects": true, "agrees": true}));
    assert_eq!(
        lines[1],
        serde_json::json!({"intersects": false, "agrees": false})
    );
    // Without "expected", or with a non-boolean one: an error line, not a crash.
    let input = "{\"p\": [[0,0],[1,0],[0,1]], \"q\": [[0,0],[1,0],[0,1]]}\n{\"expected\": \"yes\", \"p\": [[0,0],[1,0],[0,1]], \"q\": [[0,0],[1,0],[0,1]]}\n";
    let (code, out, _) = run(&["check", "--verify-expected"], input.as_bytes());
    assert_eq!(code, 0);
    let lines: Vec<serde_json::Value> = out.lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    assert!(
        lines[0]["error"]
            .as_str()
            .unwrap()
            .contains("missing field `expected`")
    );
    assert!(lines[1]["error"].as_str().unwrap().contains("true or false"));
    // Plain check ignores "expected", whatever its type.
    let (code, out, _) = run(&["check"], input.as_bytes());
    assert_eq!(code, 0);
    assert_eq!(
        out.lines().filter(|l| l.contains("\"intersects\": true")).count(),
        2
    );
}

// ---------- render ----------

/// The numbers of every `<polygon points="...">`, per polygon.
fn polygons(svg: &str) -> Vec<Vec<(f64, f64)>> {
    svg.split("<polygon points=\"")
        .skip(1)
        .map(|chunk| {
            chunk[..chunk.find('"').unwrap()]
                .split(' ')
                .map(|pair| {
                    let (x, y) = pair.split_once(',').unwrap();
                    (x.parse().unwrap(), y.parse().unwrap())
                })
                .collect()
        })
        .collect()
}

fn render(args: &[&str], input: &str) -> (i32, String, String) {
    // Tests run in parallel: every call writes a file of its own.
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let call = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let out = temp(&format!("render-{call}.svg"));
    let mut all = vec!["render", "--out", out.to_str().unwrap()];
    all.extend_from_slice(args);
    let (code, _, err) = run(&all, input.as_bytes());
    let svg = std::fs::read_to_string(&out).unwrap_or_default();
    let _ = std::fs::remove_file(&out);
    (code, svg, err)
}

#[test]
fn render_fills_each_panel_and_draws_a_legend() {
    let (_, generated, _) = run(&["gen", "--family", "nested", "--count", "8", "--n", "8"], b"");
    let (code, svg, err) = render(&[], &generated);
    assert_eq!(code, 0, "{err}");
    assert!(
        svg.contains(">p</text>") && svg.contains("q, intersecting p") && svg.contains("q, disjoint from p")
    );
    // Panels are 320 px wide in 4 columns: each pair spans its panel less a 14 px margin
    // in its larger dimension, centred in the other.
    let shapes = polygons(&svg);
    assert_eq!(shapes.len(), 16);
    for (i, pair) in shapes.chunks(2).enumerate() {
        let xs = pair.iter().flatten().map(|p| p.0);
        let (lo, hi) = xs.fold((f64::MAX, f64::MIN), |a, x| (a.0.min(x), a.1.max(x)));
        let left = (i % 4) as f64 * 320.0;
        let ys = pair.iter().flatten().map(|p| p.1);
        let (ylo, yhi) = ys.fold((f64::MAX, f64::MIN), |a, y| (a.0.min(y), a.1.max(y)));
        let span = (hi - lo).max(yhi - ylo);
        assert!((span - 292.0).abs() < 0.1, "pair {i}: span {span}");
        assert!(
            (lo - left - (320.0 - (hi - lo)) / 2.0).abs() < 0.1,
            "pair {i}: x {lo}..{hi}"
        );
    }
}

#[test]
fn render_error_panels_wrap_their_message_inside_the_panel() {
    let long = format!(
        "{{\"p\": [[0,0],[1,0],[0,1]], \"q\": [[0,0],[1,0],[0,{}]]}}\nnot json\n{{\"p\": [[0,0],[4,0],[4,4],[2,1],[0,4]], \"q\": [[0,0],[1,1],[1,0],[0,1]]}}\n",
        "1".repeat(400) + "e999"
    );
    let (code, svg, err) = render(&[], &long);
    assert_eq!(code, 0, "{err}");
    assert_eq!(svg.matches("fill=\"#fbeaea\"").count(), 3, "three error panels");
    // Every text element starts inside its panel and is short enough to end inside it
    // (13 px font, at most 0.66 em per character).
    for text in svg.split("<text x=\"").skip(1) {
        let x: f64 = text[..text.find('"').unwrap()].parse().unwrap();
        let content = text.split_once('>').unwrap().1.split('<').next().unwrap();
        let chars = content
            .replace("&lt;", "<")
            .replace("&gt;", ">")
            .replace("&amp;", "&")
            .chars()
            .count();
        let panel_right = ((x / 320.0).floor() + 1.0) * 320.0;
        assert!(
            x + chars as f64 * 13.0 * 0.66 <= panel_right + 1.0,
            "overflows: {content}"
        );
    }
    assert!(svg.contains("q: the boundary intersects itself"), "{svg}");
}

#[test]
fn render_draws_simple_polygons_with_their_crossing_points() {
    let input = r#"{"p": [[0,0],[4,0],[4,4],[2,1],[0,4]], "q": [[1,-1],[3,-1],[2,3]]}
{"p": [[0,0],[4,0],[4,4],[0,4]], "q": [[4,0],[6,0],[6,4],[4,4]]}
"#;
    let (code, svg, err) = render(&[], input);
    assert_eq!(code, 0, "{err}");
    assert!(svg.contains("line 1: 4 crossing points"), "{svg}");
    assert!(svg.contains("line 2: intersect"));
    assert_eq!(svg.matches("<circle").count(), 4 + 1, "4 marks and the legend's");
    // --crossings marks convex pairs too: the shared edge's two endpoints.
    let (code, svg, _) = render(&["--crossings"], input);
    assert_eq!(code, 0);
    assert!(svg.contains("line 2: 2 crossing points"), "{svg}");
    assert_eq!(svg.matches("<circle").count(), 6 + 1);
}

#[test]
fn render_warns_when_it_stops_at_its_limit() {
    let (_, generated, _) = run(&["gen", "--count", "5"], b"");
    let (code, svg, err) = render(&["--limit", "3"], &generated);
    assert_eq!(code, 0);
    assert_eq!(polygons(&svg).len(), 6);
    assert!(err.contains("stopped at its limit of 3 pairs"), "{err}");
    let (_, _, err) = render(&["--limit", "5"], &generated);
    assert!(!err.contains("limit"), "{err}");
    usage_error(&["render", "--limit", "0"]);
}

#[test]
fn render_writes_svg_only() {
    let png = temp("pairs.png");
    let err = usage_error(&["render", "--out", png.to_str().unwrap()]);
    assert!(err.contains("SVG only") && err.contains("rsvg-convert"), "{err}");
    assert!(!png.exists(), "nothing written");
    // "-" writes the SVG to standard output.
    let (code, out, _) = run(
        &["render", "--out", "-"],
        b"{\"p\": [[0,0],[1,0],[0,1]], \"q\": [[0,0],[1,0],[0,1]]}\n",
    );
    assert_eq!(code, 0);
    assert!(out.starts_with("<svg") && out.trim_end().ends_with("</svg>"));
    // A name without an extension (a device, a pipe) and .SVG are fine.
    for name in ["/dev/null", "-"] {
        let (code, _, err) = run(&["render", "--out", name], b"");
        assert_eq!(code, 0, "{name}: {err}");
    }
    let upper = temp("PAIRS.SVG");
    let (code, _, err) = run(&["render", "--out", upper.to_str().unwrap()], b"");
    assert_eq!(code, 0, "{err}");
    assert!(std::fs::read_to_string(&upper).unwrap().starts_with("<svg"));
    let _ = std::fs::remove_file(&upper);
}

/// `calibrate > costs.json` is JSON and nothing else, its tables labelled by size, and
/// it loads back as the `CostModel` that `Scene::set_costs` takes; the talk is on
/// standard error.
#[test]
fn calibrate_writes_only_json_on_stdout() {
    let (code, out, err) = run(&["calibrate"], b"");
    assert_eq!(code, 0, "{err}");
    let value: serde_json::Value = serde_json::from_str(&out).expect("stdout is one JSON value");
    let sizes: Vec<usize> = serde_json::from_value(value["sizes"].clone()).expect("sizes");
    assert_eq!(sizes, polysect::store::CostModel::sizes());
    let costs: polysect::store::CostModel = serde_json::from_str(&out).expect("a CostModel");
    assert!(costs.tables().iter().flatten().all(|c| c.is_finite() && *c > 0.0));
    let mut scene = polysect::store::Scene::new();
    scene.set_costs(costs);
    assert_eq!(scene.costs(), costs);
    assert!(err.contains(&costs.summary()), "{err}");
    assert!(err.contains("set_costs"), "{err}");
    assert!(!err.contains("at most 0 vertices"), "{err}");
}
