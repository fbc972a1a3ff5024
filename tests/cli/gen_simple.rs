//! `polysect gen --simple`: pairs of random simple polygons (space partitioning
//! with uniform Δ or normal σ points as in docs/crossings.md's report, the star and the
//! angular sort) in the `crossings` input format, fed back to `polysect crossings`.

use polysect::SimplePolygon;
use serde_json::Value;

use crate::common::run;

fn lines(args: &[&str]) -> Vec<Value> {
    let (code, out, err) = run(args, b"");
    assert_eq!(code, 0, "{args:?}: {err}");
    out.lines().map(|l| serde_json::from_str(l).unwrap()).collect()
}

#[test]
fn every_method_and_distribution_feeds_crossings() {
    for method in ["space-partition", "star", "angular"] {
        for dist in [["--delta", "1000"], ["--sigma", "50"]] {
            let args = [
                "gen", "--simple", method, dist[0], dist[1], "--n", "40", "--count", "6", "--seed", "3",
            ];
            let pairs = lines(&args);
            assert_eq!(pairs.len(), 6);
            let mut input = String::new();
            for (i, line) in pairs.iter().enumerate() {
                assert_eq!(line["id"], i);
                assert_eq!(line["method"], method);
                assert!(line.get(&dist[0][2..]).is_some(), "{line}");
                for key in ["p", "q"] {
                    let pts: Vec<[f64; 2]> = serde_json::from_value(line[key].clone()).unwrap();
                    let poly = SimplePolygon::new(pts.clone()).unwrap();
                    // Real coordinates: no straight vertex is cleaned away.
                    assert_eq!(poly.len(), 40, "{method} {dist:?}");
                    assert!(poly.is_ccw(), "counter-clockwise by default");
                }
                input.push_str(&line.to_string());
                input.push('\n');
            }
            // Deterministic for a seed.
            assert_eq!(lines(&args), pairs);
            let answers = |algorithm: &str| {
                let (code, out, err) = run(&["crossings", "--algorithm", algorithm], input.as_bytes());
                assert_eq!(code, 0, "{err}");
                out.lines()
                    .map(|l| serde_json::from_str::<Value>(l).unwrap())
                    .collect::<Vec<_>>()
            };
            let sweep = answers("sweep");
            assert_eq!(sweep.len(), 6);
            assert!(sweep.iter().all(|a| a.get("points").is_some()), "{sweep:?}");
            assert_eq!(sweep, answers("brute"), "{method} {dist:?}");
        }
    }
}

#[test]
fn clockwise_order_and_default_distribution() {
    let pairs = lines(&[
        "gen", "--simple", "angular", "--n", "10", "--count", "2", "--order", "cw",
    ]);
    for line in &pairs {
        assert_eq!(line["delta"], 100.0, "uniform in [0, 100) by default");
        let pts: Vec<[f64; 2]> = serde_json::from_value(line["p"].clone()).unwrap();
        assert!(!SimplePolygon::new(pts.clone()).unwrap().is_ccw());
        assert!(
            pts.iter()
                .all(|p| (0.0..100.0).contains(&p[0]) && (0.0..100.0).contains(&p[1]))
        );
    }
}

#[test]
fn bad_parameters_are_usage_errors() {
    for args in [
        &["gen", "--simple", "angular", "--n", "2"][..],
        &["gen", "--simple", "star", "--sigma", "-1"],
        &["gen", "--simple", "star", "--delta", "0"],
        &["gen", "--simple", "star", "--delta", "5", "--sigma", "5"],
        &["gen", "--simple", "star", "--family", "ellipse"],
        &["gen", "--simple", "spiral"],
        &["gen", "--sigma", "5"],
    ] {
        let (code, out, err) = run(args, b"");
        assert_eq!(code, 2, "{args:?}: {out} {err}");
        assert!(out.is_empty(), "{args:?}");
        assert!(!err.is_empty(), "{args:?}");
    }
}
