//! `--certificate` through the binary: `polysect check --certificate` and `polysect
//! scene --certificate` print the contract's certificates, and every printed one is
//! checked with the library's exact `verify` against the polygons as cleaned, on hostile
//! inputs (touching, one-ulp gaps, collinear and repeated input vertices, clockwise
//! input, −0.0, subnormal and near-`f64::MAX` coordinates), for every algorithm,
//! strategy and precision. Printed coordinates must be, bit for bit, vertices of the
//! cleaned polygons. Corrupted printed certificates are rejected.

use crate::answers;
use crate::common::run;
use polysect::intersect::{Certificate, CertificateError, Which, brute_force, verify};
use polysect::{ConvexPolygon, Point};
use serde_json::Value;

fn points(v: &Value) -> Vec<Point> {
    v.as_array()
        .expect("a point list")
        .iter()
        .map(|p| Point::new(p[0].as_f64().unwrap(), p[1].as_f64().unwrap()))
        .collect()
}

/// The certificate of a reply, read with the library's serde form (independent of the
/// protocol's printer).
fn certificate_of(reply: &Value) -> Certificate {
    let c = reply
        .get("certificate")
        .unwrap_or_else(|| panic!("no certificate in {reply}"));
    serde_json::from_value(c.clone()).unwrap_or_else(|e| panic!("{e}: {c}"))
}

/// Every coordinate of the certificate, with the polygon it must be a vertex of.
fn named_points(c: &Certificate) -> Vec<(Which, Point)> {
    match *c {
        Certificate::Separated { of, from, to } => vec![(of, from), (of, to)],
        Certificate::VertexInside { of, point } => vec![(of, point)],
        Certificate::CrossingEdges { p, q } => vec![
            (Which::P, p[0]),
            (Which::P, p[1]),
            (Which::Q, q[0]),
            (Which::Q, q[1]),
        ],
    }
}

/// The checks every printed certificate must pass: `verify` accepts it, its answer is
/// the printed one and the exact reference's, and its points are the cleaned polygons'
/// vertices bit for bit.
fn check_printed(reply: &Value, p: &ConvexPolygon, q: &ConvexPolygon, context: &str) -> Certificate {
    let c = certificate_of(reply);
    assert_eq!(verify(p, q, &c), Ok(()), "{context}: {reply}");
    assert_eq!(
        reply["intersects"].as_bool(),
        Some(c.intersects()),
        "{context}: {reply}"
    );
    assert_eq!(
        c.intersects(),
        brute_force(polysect::Exact, p, q),
        "{context}: {reply}"
    );
    for (of, x) in named_points(&c) {
        let poly = if of == Which::P { p } else { q };
        let bits = (x.x.to_bits(), x.y.to_bits());
        assert!(
            poly.vertices()
                .iter()
                .any(|v| (v.x.to_bits(), v.y.to_bits()) == bits),
            "{context}: {x:?} is not bit for bit a vertex of cleaned {of}: {reply}"
        );
    }
    c
}

const MAX: f64 = f64::MAX;

/// Hostile pairs: (p, q) as JSON point lists.
fn hostile_pairs() -> Vec<(String, String)> {
    let mut v: Vec<(String, String)> = [
        // Touching at a vertex, on an edge, along an edge; containment both ways.
        ("[[0,0],[2,0],[2,2],[0,2]]", "[[2,2],[3,2],[3,3]]"),
        ("[[0,0],[2,0],[2,2],[0,2]]", "[[2,1],[3,0],[3,2]]"),
        ("[[0,0],[2,0],[2,2],[0,2]]", "[[2,0],[3,0],[3,2],[2,2]]"),
        ("[[0,0],[0,2],[2,2],[2,0]]", "[[0.5,0.5],[1,0.5],[1,1]]"),
        ("[[0.5,0.5],[1,0.5],[1,1]]", "[[0,0],[2,0],[2,2],[0,2]]"),
        // Crossing without a vertex inside (a star of two triangles).
        ("[[0,1],[3,1],[1.5,4]]", "[[0,3],[1.5,0],[3,3]]"),
        // One-ulp gaps and one-ulp overlaps.
        ("[[0,0],[1,0],[1,1],[0,1]]", "[[1.0000000000000002,0],[2,0],[2,1]]"),
        ("[[0,0],[1,0],[1,1],[0,1]]", "[[0.9999999999999999,0.5],[2,0],[2,1]]"),
        // 2^50 + 1 against a quarter past it: exact in f64, lost by a naive determinant.
        (
            "[[1125899906842624,1125899906842624],[1125899906842625,1125899906842624],[1125899906842625,1125899906842625]]",
            "[[1125899906842625.25,1125899906842624],[1125899906842626,1125899906842624],[1125899906842626,1125899906842625]]",
        ),
        (
            "[[1125899906842624,1125899906842624],[1125899906842625,1125899906842624],[1125899906842625,1125899906842625]]",
            "[[1125899906842625,1125899906842624],[1125899906842626,1125899906842624],[1125899906842626,1125899906842625]]",
        ),
        // Tiny: 1e-300 and subnormals (5e-324 is the smallest positive f64).
        ("[[0,0],[1e-300,0],[1e-300,1e-300]]", "[[2e-300,0],[3e-300,0],[3e-300,1e-300]]"),
        ("[[0,0],[5e-324,0],[5e-324,5e-324]]", "[[1e-323,0],[1.5e-323,0],[1.5e-323,5e-324]]"),
        ("[[0,0],[5e-324,0],[5e-324,5e-324]]", "[[5e-324,0],[1.5e-323,0],[1.5e-323,5e-324]]"),
        // −0.0 beside 0.0: the same point.
        ("[[-0.0,-0.0],[1,0],[0,1]]", "[[0,0],[-1,0],[0,-1]]"),
        // Collinear middle vertices and repeats, cleaned away: P's input point (1, 0)
        // is not a vertex of P as cleaned, though Q touches P exactly there.
        ("[[0,0],[1,0],[2,0],[2,2],[0,2]]", "[[1,0],[2,-1],[0,-1]]"),
        ("[[0,0],[0,0],[1,0],[2,0],[2,0],[2,2],[0,2],[0,0]]", "[[1,0],[1,0],[0.5,-1],[1.5,-1],[1,0]]"),
        // Clockwise input with a repeated closing vertex.
        ("[[0,0],[0,2],[2,2],[2,0],[0,0]]", "[[2,1],[3,1],[3,2],[2,1]]"),
        ("[[0,0],[0,2],[2,2],[2,0],[0,0]]", "[[3,1],[2.5,2],[4,2]]"),
    ]
    .iter()
    .map(|(p, q)| (p.to_string(), q.to_string()))
    .collect();
    // Near f64::MAX: every coordinate representable, every difference overflowing.
    let m = format!("{MAX:?}");
    let h = format!("{:?}", MAX / 2.0);
    v.push((
        format!("[[-{m},0],[{m},0],[0,{m}]]"),
        format!("[[0,{m}],[-{m},{m}],[-{m},{h}]]"),
    ));
    v.push((
        format!("[[-{m},-{m}],[{m},-{m}],[{m},{m}]]"),
        format!("[[-{m},-{h}],[{h},{m}],[-{m},{m}]]"),
    ));
    v.push((
        format!("[[-{m},-{m}],[{m},-{m}],[{m},{m}]]"),
        format!("[[-{m},-{m}],[{h},{m}],[-{m},{m}]]"),
    ));
    v
}

fn pair_input(pairs: &[(String, String)]) -> String {
    pairs
        .iter()
        .enumerate()
        .map(|(i, (p, q))| format!("{{\"id\": {i}, \"p\": {p}, \"q\": {q}}}\n"))
        .collect()
}

fn cleaned(list: &str) -> ConvexPolygon {
    let v: Value = serde_json::from_str(list).unwrap();
    ConvexPolygon::new(points(&v)).unwrap_or_else(|e| panic!("{list}: {e}"))
}

#[test]
fn check_certificates_verify_for_every_algorithm_and_precision() {
    let pairs = hostile_pairs();
    let input = pair_input(&pairs);
    let mut kinds = std::collections::HashSet::new();
    for precision in ["exact", "fast"] {
        for algorithm in [
            "auto",
            "linear",
            "barba",
            "dobkin",
            "chazelle-dobkin",
            "clm",
            "convert",
        ] {
            let args = [
                "check",
                "--certificate",
                "--algorithm",
                algorithm,
                "--precision",
                precision,
                "--seed",
                "5",
            ];
            let replies = answers(&args, &input);
            assert_eq!(replies.len(), pairs.len());
            for (i, ((p, q), reply)) in pairs.iter().zip(&replies).enumerate() {
                assert_eq!(reply["id"], i, "{reply}");
                let context = format!("{algorithm} {precision} line {i}");
                let c = check_printed(reply, &cleaned(p), &cleaned(q), &context);
                kinds.insert(std::mem::discriminant(&c));
            }
        }
    }
    assert_eq!(kinds.len(), 3, "every kind of certificate was printed");
}

#[test]
fn check_certificate_format_and_bad_lines() {
    let input = "{\"p\": [[0,0],[2,0],[2,2],[0,2]], \"q\": [[3,0],[4,0],[4,1]]}\n\
                 {\"id\": \"x\", \"p\": [[0,0],[2,0],[2,2],[0,2]], \"q\": [[2,2],[3,2],[3,3]]}\n\
                 {\"p\": [[0,0],[1,1],[2,2]], \"q\": [[0,0],[1,0],[0,1]]}\n\
                 {\"p\": [[0,0],[2,0],[0,2]], \"q\": [[0,2],[2,0],[2,2]]}\n";
    let (code, out, err) = run(
        &["check", "--certificate", "--algorithm", "linear"],
        input.as_bytes(),
    );
    assert_eq!(code, 0, "{err}");
    let out: Vec<&str> = out.lines().collect();
    assert_eq!(
        out[0],
        r#"{"intersects": false, "certificate": {"separating_edge": {"of": "p", "from": [2.0,0.0], "to": [2.0,2.0]}}}"#
    );
    assert!(
        out[1].starts_with(r#"{"id": "x", "intersects": true, "certificate": {"#),
        "{}",
        out[1]
    );
    assert!(out[2].starts_with(r#"{"error": "line 3: p: "#), "{}", out[2]);
    assert!(!out[2].contains("certificate"));
    // Sharing an edge, walked in opposite directions: any of the three kinds may prove it.
    let shared: Value = serde_json::from_str(out[3]).unwrap();
    check_printed(
        &shared,
        &cleaned("[[0,0],[2,0],[0,2]]"),
        &cleaned("[[0,2],[2,0],[2,2]]"),
        "shared edge",
    );
    // Without the option, no certificate.
    let (_, plain, _) = run(&["check"], input.as_bytes());
    assert!(!plain.contains("certificate"));
}

/// A scene session whose every query is followed by `vertices` of both polygons, so
/// the certificate can be checked against the polygons as they were when it was given.
fn scene_script(
    names: &[(&str, String)],
    edits: &[String],
    rounds: usize,
) -> (String, Vec<(usize, String, String)>) {
    let mut input = String::new();
    let mut queries = Vec::new();
    let mut line = 0;
    let mut push = |input: &mut String, text: String| {
        input.push_str(&text);
        input.push('\n');
        line += 1;
        line - 1
    };
    for (name, pts) in names {
        push(
            &mut input,
            format!(r#"{{"op": "add", "name": "{name}", "points": {pts}}}"#),
        );
    }
    for round in 0..rounds {
        if let Some(edit) = edits.get(round) {
            push(&mut input, edit.clone());
        }
        for (a, _) in names {
            for (b, _) in names {
                let at = push(
                    &mut input,
                    format!(r#"{{"op": "intersects", "a": "{a}", "b": "{b}"}}"#),
                );
                push(&mut input, format!(r#"{{"op": "vertices", "name": "{a}"}}"#));
                push(&mut input, format!(r#"{{"op": "vertices", "name": "{b}"}}"#));
                queries.push((at, a.to_string(), b.to_string()));
            }
        }
    }
    (input, queries)
}

#[test]
fn scene_certificates_verify_for_every_strategy_and_precision() {
    let m = format!("{MAX:?}");
    let names: Vec<(&str, String)> = vec![
        // Collinear middles and repeats (ids 1, 4 and 7 are cleaned away).
        (
            "square",
            "[[0,0],[1,0],[2,0],[2,0],[2,2],[0,2],[0,1],[0,0]]".into(),
        ),
        // Clockwise; touches the square at (2, 1).
        ("tri", "[[2,1],[3,2],[3,0]]".into()),
        // One ulp right of the square's edge x = 2.
        ("gap", "[[2.0000000000000004,0],[3,-1],[3,0.5]]".into()),
        // Far away: its box rejects every other polygon.
        ("far", "[[100,100],[101,100],[100,101]]".into()),
        ("tiny", "[[0,0],[5e-324,0],[5e-324,5e-324]]".into()),
        ("huge", format!("[[-{m},-{m}],[{m},-{m}],[{m},{m}]]")),
    ];
    let edits = vec![
        r#"{"op": "translate", "name": "tri", "by": [4.440892098500626e-16, 0]}"#.to_string(),
        r#"{"op": "insert", "name": "square", "after": 2, "point": [2.5, 1]}"#.to_string(),
        r#"{"op": "move", "name": "gap", "vertex": 0, "to": [2.5, 0.5]}"#.to_string(),
        r#"{"op": "translate", "name": "far", "by": [-98, -98]}"#.to_string(),
    ];
    // Enough rounds that the planner and the cached strategy query snapshots too.
    let (input, queries) = scene_script(&names, &edits, 12);
    let mut kinds = std::collections::HashSet::new();
    for precision in ["exact", "fast"] {
        for strategy in ["planner", "sampled", "convert", "cached"] {
            let args = [
                "scene",
                "--certificate",
                "--strategy",
                strategy,
                "--precision",
                precision,
                "--seed",
                "3",
            ];
            let replies = answers(&args, &input);
            for (at, a, b) in &queries {
                assert!(replies[*at].get("error").is_none(), "{}", replies[*at]);
                let poly = |r: &Value| ConvexPolygon::new(points(&r["points"])).unwrap();
                let (p, q) = (poly(&replies[at + 1]), poly(&replies[at + 2]));
                let context = format!("{strategy} {precision} line {} {a} {b}", at + 1);
                let c = check_printed(&replies[*at], &p, &q, &context);
                kinds.insert(std::mem::discriminant(&c));
            }
        }
    }
    assert_eq!(kinds.len(), 3, "every kind of certificate was printed");
}

#[test]
fn corrupted_printed_certificates_are_rejected() {
    // P the square, Q a triangle one unit to its right: P's edge x = 2 separates.
    let input = "{\"p\": [[0,0],[2,0],[2,2],[0,2]], \"q\": [[3,0],[4,0],[4,1]]}\n\
                 {\"p\": [[0,0],[2,0],[2,2],[0,2]], \"q\": [[1,1],[3,1],[3,3]]}\n";
    let replies = answers(&["check", "--certificate", "--algorithm", "linear"], input);
    let p = cleaned("[[0,0],[2,0],[2,2],[0,2]]");
    let q = cleaned("[[3,0],[4,0],[4,1]]");
    let sep = check_printed(&replies[0], &p, &q, "separated");
    let pt = Point::new;
    let Certificate::Separated { of, from, to } = sep else {
        panic!("{sep:?}")
    };
    assert_eq!((of, from, to), (Which::P, pt(2.0, 0.0), pt(2.0, 2.0)));
    let rejected = |c: Certificate| verify(&p, &q, &c).expect_err("a corrupted certificate");
    // Wrong side: the edge walked clockwise, and a consecutive edge Q is not beyond.
    assert!(matches!(
        rejected(Certificate::Separated {
            of,
            from: to,
            to: from
        }),
        CertificateError::Clockwise { .. }
    ));
    assert!(matches!(
        rejected(Certificate::Separated {
            of,
            from: pt(2.0, 2.0),
            to: pt(0.0, 2.0)
        }),
        CertificateError::NotSeparating { .. }
    ));
    // The right line, but named on the wrong polygon.
    assert!(matches!(
        rejected(Certificate::Separated {
            of: Which::Q,
            from,
            to
        }),
        CertificateError::NotAVertex { .. }
    ));
    // Non-consecutive vertices (a diagonal).
    assert!(matches!(
        rejected(Certificate::Separated {
            of,
            from: pt(0.0, 0.0),
            to: pt(2.0, 2.0)
        }),
        CertificateError::NotAnEdge { .. }
    ));
    // A vertex nudged by one ulp.
    let nudged = pt(2.0, f64::from_bits(2.0f64.to_bits() + 1));
    assert!(matches!(
        rejected(Certificate::Separated { of, from, to: nudged }),
        CertificateError::NotAVertex { .. }
    ));

    // Intersecting: Q's vertex (1, 1) lies in P.
    let q2 = cleaned("[[1,1],[3,1],[3,3]]");
    let inside = check_printed(&replies[1], &p, &q2, "inside");
    assert!(inside.intersects());
    let rejected = |c: Certificate| verify(&p, &q2, &c).expect_err("a corrupted certificate");
    // A point outside: Q's vertex (3, 3) is not in P.
    assert!(matches!(
        rejected(Certificate::VertexInside {
            of: Which::Q,
            point: pt(3.0, 3.0)
        }),
        CertificateError::Outside { .. }
    ));
    // A point inside P that is not a vertex of Q.
    assert!(matches!(
        rejected(Certificate::VertexInside {
            of: Which::Q,
            point: pt(1.5, 1.5)
        }),
        CertificateError::NotAVertex { .. }
    ));
    // Edges that do not meet, and edges that are not consecutive.
    assert!(matches!(
        rejected(Certificate::CrossingEdges {
            p: [pt(0.0, 0.0), pt(2.0, 0.0)],
            q: [pt(3.0, 1.0), pt(3.0, 3.0)]
        }),
        CertificateError::EdgesDisjoint { .. }
    ));
    assert!(matches!(
        rejected(Certificate::CrossingEdges {
            p: [pt(0.0, 0.0), pt(2.0, 2.0)],
            q: [pt(1.0, 1.0), pt(3.0, 1.0)]
        }),
        CertificateError::NotAnEdge { .. }
    ));
}
