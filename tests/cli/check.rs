//! The `polysect` binary per the CLI contract: JSON Lines in, one line out per line.

use crate::answers;
use crate::common::run;

const CASES: &str = r#"{"p": [[0,0],[2,0],[2,2],[0,2]], "q": [[2,2],[3,2],[3,3]]}
{"p": [[0,0],[2,0],[2,2],[0,2]], "q": [[2,1],[3,0],[3,2]]}
{"p": [[0,0],[2,0],[2,2],[0,2]], "q": [[2,0],[3,0],[3,2],[2,2]]}
{"p": [[0,0],[0,2],[2,2],[2,0]], "q": [[0.5,0.5],[1,0.5],[1,1]]}
{"p": [[0.5,0.5],[1,0.5],[1,1]], "q": [[0,0],[2,0],[2,2],[0,2]]}
{"p": [[0,0],[1,0],[1,1],[0,1]], "q": [[1.0000000000000002,0],[2,0],[2,1]]}
{"p": [[0,0],[1,0],[1,1],[0,1]], "q": [[1,0.5],[2,0],[2,1]]}
{"p": [[0,0],[1e-300,0],[1e-300,1e-300]], "q": [[2e-300,0],[3e-300,0],[3e-300,1e-300]]}
{"p": [[1125899906842624,1125899906842624],[1125899906842625,1125899906842624],[1125899906842625,1125899906842625]], "q": [[1125899906842625,1125899906842624],[1125899906842626,1125899906842624],[1125899906842626,1125899906842625]]}
{"p": [[1125899906842624,1125899906842624],[1125899906842625,1125899906842624],[1125899906842625,1125899906842625]], "q": [[1125899906842625.25,1125899906842624],[1125899906842626,1125899906842624],[1125899906842626,1125899906842625]]}
{"p": [[0,0],[1e300,0],[1e300,1e300]], "q": [[1e300,1e300],[2e300,1e300],[2e300,2e300]]}
"#;

const EXPECTED: [bool; 11] = [
    true, true, true, true, true, false, true, false, true, false, true,
];

#[test]
fn check_answers_touching_containment_gaps_and_extremes() {
    for precision in ["exact", "fast"] {
        for algorithm in ["auto", "linear", "barba", "dobkin"] {
            let got = answers(
                &["check", "--algorithm", algorithm, "--precision", precision],
                CASES,
            );
            assert_eq!(got.len(), EXPECTED.len());
            if precision == "exact" {
                for (i, (g, want)) in got.iter().zip(EXPECTED).enumerate() {
                    assert_eq!(g, &serde_json::json!({ "intersects": want }), "line {i}");
                }
            }
        }
    }
}

#[test]
fn scaled_by_2_pow_minus_1000_and_plus_1000() {
    for e in [-1000, 1000] {
        let s = 2f64.powi(e);
        let line = |dx: f64| {
            let p = [[0.0, 0.0], [s, 0.0], [s, s]];
            let q = [[dx * s, 0.0], [(dx + 1.0) * s, 0.0], [(dx + 1.0) * s, s]];
            format!("{}\n", serde_json::json!({ "p": p, "q": q }))
        };
        let got = answers(&["check"], &(line(1.0) + &line(1.5)));
        assert_eq!(
            got,
            vec![
                serde_json::json!({"intersects": true}),
                serde_json::json!({"intersects": false})
            ],
            "e = {e}"
        );
    }
}

#[test]
fn bad_lines_get_error_lines_and_the_run_goes_on() {
    let input = b"{\"p\": [[0,0],[1,0],[0,1]], \"q\": [[0,0],[1,0],[0,1]]}\n\nnot json\n{\"p\": [[0,0],[1,0],[0,1]]}\n{\"id\": 7, \"p\": [[0,0],[1,0]], \"q\": [[0,0],[1,0],[0,1]]}\n\xff\xfe\n{\"p\": [[0,0],[4,0],[4,4],[2,1],[0,4]], \"q\": [[0,0],[1,0],[0,1]]}\n{\"p\": [[0,0],[1,0],[0,1]], \"q\": [[0,0],[1,0],[0,1]]}";
    let (code, out, _) = run(&["check"], input);
    assert_eq!(code, 0);
    let lines: Vec<serde_json::Value> = out.lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    assert_eq!(lines.len(), 8, "{out}");
    assert_eq!(lines[0], serde_json::json!({"intersects": true}));
    for (i, l) in lines[1..7].iter().enumerate() {
        assert!(l["error"].is_string(), "line {}: {l}", i + 1);
    }
    assert_eq!(lines[4]["id"], 7);
    assert!(
        lines[4]["error"]
            .as_str()
            .unwrap()
            .contains("p: a polygon needs at least 3")
    );
    assert!(lines[6]["error"].as_str().unwrap().contains("vertex 3 is reflex"));
    // The last line has no newline and is still answered.
    assert_eq!(lines[7], serde_json::json!({"intersects": true}));
}

#[test]
fn unknown_names_are_usage_errors_listing_the_valid_ones() {
    let (code, _, err) = run(&["check", "--algorithm", "quick"], b"");
    assert_eq!(code, 2);
    assert!(err.contains("auto") && err.contains("linear"), "{err}");
    let (code, _, err) = run(&["check", "--precision", "double"], b"");
    assert_eq!(code, 2);
    assert!(err.contains("fast, exact"), "{err}");
    let (code, _, err) = run(&["check", "/no/such/file.jsonl"], b"");
    assert_eq!(code, 1);
    assert!(err.contains("cannot read"), "{err}");
}

#[test]
fn gen_output_feeds_check_and_expected_matches() {
    for family in ["rotated", "shared-edge", "one-ulp-gap", "nested"] {
        for order in ["ccw", "cw", "random"] {
            let (code, generated, err) = run(
                &[
                    "gen", "--family", family, "--n", "20", "--count", "30", "--order", order, "--seed", "3",
                ],
                b"",
            );
            assert_eq!(code, 0, "{err}");
            let got = answers(&["check"], &generated);
            for (line, answer) in generated.lines().zip(got) {
                let g: serde_json::Value = serde_json::from_str(line).unwrap();
                assert_eq!(answer["id"], g["id"]);
                assert_eq!(answer["intersects"], g["expected"], "{family} {order}: {line}");
            }
        }
    }
}

#[test]
fn demo_checks_every_answer_and_draws_the_scene() {
    let svg = std::env::temp_dir().join(format!("polysect-demo-test-{}.svg", std::process::id()));
    let svg_arg = svg.to_str().unwrap();
    let (code, out, err) = run(
        &[
            "demo",
            "--polygons",
            "12",
            "--max-log2",
            "9",
            "--steps",
            "150",
            "--svg",
            svg_arg,
        ],
        b"",
    );
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("polysect check"), "the demo says what else there is");
    let rows: Vec<&str> = out
        .lines()
        .filter(|l| l.contains("heavy") || l.starts_with("balanced"))
        .collect();
    assert!(rows.len() >= 12, "{out}");
    for row in rows.iter().filter(|r| r.contains('/')) {
        let agree = row.split_whitespace().last().unwrap();
        let (ok, all) = agree.split_once('/').unwrap();
        assert_eq!(ok, all, "{row}");
    }
    let picture = std::fs::read_to_string(&svg).unwrap();
    assert!(picture.matches("<polygon").count() >= 12);
    let _ = std::fs::remove_file(svg);
}

#[test]
fn render_draws_pairs_and_error_panels() {
    let out_file = std::env::temp_dir().join(format!("polysect-render-test-{}.svg", std::process::id()));
    let input = format!("{}not json\n", CASES);
    let (code, _, err) = run(&["render", "--out", out_file.to_str().unwrap()], input.as_bytes());
    assert_eq!(code, 0, "{err}");
    let picture = std::fs::read_to_string(&out_file).unwrap();
    assert_eq!(picture.matches("<polygon").count(), 2 * EXPECTED.len());
    assert!(picture.contains("error"));
    let _ = std::fs::remove_file(out_file);
}

#[test]
fn hostile_input_gets_an_error_line_each_and_never_a_crash() {
    let nested = format!("{}{}", "[".repeat(100_000), "]".repeat(100_000));
    let garbage = "x".repeat(2_000_000);
    let big_polygon: Vec<[f64; 2]> = (0..200_000)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / 200_000.0;
            [t.cos(), t.sin()]
        })
        .collect();
    let huge_valid =
        serde_json::json!({ "p": big_polygon, "q": [[0.5, 0.5], [2.0, 0.5], [2.0, 2.0]] }).to_string();
    let lines = [
        nested.as_str(),
        r#"{"p": [[0,0],[1,0],[0,1]], "q": [[0,0],[1,0],[0,"#, // truncated
        r#"{"p": [[0,0],[1,0],[0,1]], "q": [[0,0],[1,0],[0,1e999]]}"#,
        r#"{"p": [[0,0],[1,0],[0,1]], "q": [[0,0],[1,0],[0,-1e309]]}"#,
        garbage.as_str(),
        huge_valid.as_str(),
        r#"{"p": [[0,0],[1,0],[0,1]], "q": [[0,0],[1,0],[0,1]]}"#,
    ];
    let input = lines.join("\n");
    for algorithm in ["auto", "clm", "linear"] {
        let (code, out, err) = run(&["check", "--algorithm", algorithm], input.as_bytes());
        assert_eq!(code, 0, "{err}");
        let replies: Vec<serde_json::Value> = out.lines().map(|l| serde_json::from_str(l).unwrap()).collect();
        assert_eq!(replies.len(), lines.len());
        for (i, r) in replies[..5].iter().enumerate() {
            assert!(r["error"].is_string(), "{algorithm} line {i}: {r}");
        }
        assert_eq!(replies[5], serde_json::json!({"intersects": true}));
        assert_eq!(replies[6], serde_json::json!({"intersects": true}));
    }
    // The same hostile lines for crossings.
    let (code, out, _) = run(&["crossings"], input.as_bytes());
    assert_eq!(code, 0);
    assert_eq!(out.lines().count(), lines.len());
}
