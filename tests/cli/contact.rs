//! `polysect contact` and the scene's `contact` op, from outside, against the contract:
//! field names and order, the overlap's start and dropped repeats, `null` past the
//! largest double, errors and ids as in `check`.

use crate::common::run;

fn contact(input: &str, args: &[&str]) -> Vec<String> {
    let mut all = vec!["contact"];
    all.extend_from_slice(args);
    let (code, out, err) = run(&all, input.as_bytes());
    assert_eq!(code, 0, "exit code; stderr: {err}");
    out.lines().map(str::to_owned).collect()
}

#[test]
fn separated_pairs_give_distance_and_closest_points() {
    let out = contact(
        r#"{"id": 7, "p": [[0,0],[2,0],[2,2],[0,2]], "q": [[3,0],[4,0],[4,1]]}
{"p": [[0,0],[1,0],[0,1]], "q": [[2,2],[3,2],[2,3]]}
"#,
        &[],
    );
    assert_eq!(
        out[0],
        r#"{"id": 7, "intersects": false, "distance": 1.0, "closest": [[2.0,0.0],[3.0,0.0]]}"#
    );
    // √4.5 correctly rounded; the closest pair (0.5, 0.5)–(2, 2).
    assert_eq!(
        out[1],
        format!(
            r#"{{"intersects": false, "distance": {:?}, "closest": [[0.5,0.5],[2.0,2.0]]}}"#,
            4.5f64.sqrt()
        )
    );
}

#[test]
fn overlapping_pairs_give_depth_normal_overlap_and_area() {
    let out = contact(
        // Clockwise input, other start: the overlap starts at its lowest, then leftmost point.
        r#"{"p": [[0,2],[2,2],[2,0],[0,0]], "q": [[1,1],[3,1],[3,3],[1,3]]}
{"p": [[0,0],[4,0],[0,4]], "q": [[3,-1],[3,3],[-1,3]]}
"#,
        &[],
    );
    assert!(
        out[0].starts_with(r#"{"intersects": true, "depth": 1.0, "normal": ["#),
        "{}",
        out[0]
    );
    assert!(out[0].ends_with(r#", "overlap": [[1.0,1.0],[2.0,1.0],[2.0,2.0],[1.0,2.0]], "area": 1.0}"#));
    // The triangle x, y ≥ 0, x + y ≤ 4 against x ≤ 3, y ≤ 3, x + y ≥ 2: a hexagon of
    // area 8 − 2 − ½ − ½, starting at its lowest (then leftmost) point (2, 0). Moving q
    // by (1, 1) separates them: depth √2.
    assert_eq!(
        out[1],
        format!(
            r#"{{"intersects": true, "depth": {:?}, "normal": [{h:?},{h:?}], "overlap": [[2.0,0.0],[3.0,0.0],[3.0,1.0],[1.0,3.0],[0.0,3.0],[0.0,2.0]], "area": 5.0}}"#,
            2f64.sqrt(),
            h = 0.5f64.sqrt()
        )
    );
}

#[test]
fn touching_gives_one_or_two_points_and_zero_depth() {
    let out = contact(
        r#"{"p": [[0,0],[1,0],[1,1],[0,1]], "q": [[1,0.5],[2,0],[2,1]]}
{"p": [[0,0],[1,0],[1,1],[0,1]], "q": [[1,0],[2,0],[2,1],[1,1]]}
"#,
        &[],
    );
    assert_eq!(
        out[0],
        r#"{"intersects": true, "depth": 0.0, "normal": [1.0,0.0], "overlap": [[1.0,0.5]], "area": 0.0}"#
    );
    assert_eq!(
        out[1],
        r#"{"intersects": true, "depth": 0.0, "normal": [1.0,0.0], "overlap": [[1.0,0.0],[1.0,1.0]], "area": 0.0}"#
    );
}

#[test]
fn a_point_repeated_after_rounding_is_dropped() {
    // The tip (2, 2 + 2^-51) pokes out of x + y ≤ 4 by less than an ulp: the two
    // crossings both round to (2, 2).
    let out = contact(
        r#"{"p": [[0,0],[4,0],[0,4]], "q": [[1.999,0.5],[2.001,0.5],[2,2.0000000000000004]]}"#,
        &[],
    );
    assert!(
        out[0].contains(r#""overlap": [[1.999,0.5],[2.001,0.5],[2.0,2.0]]"#),
        "{}",
        out[0]
    );
}

#[test]
fn overflowing_values_are_null() {
    let out = contact(
        r#"{"p": [[-1.7e308,0],[-1.6e308,0],[-1.6e308,1]], "q": [[1.6e308,0],[1.7e308,0],[1.7e308,1]]}
{"p": [[-1e308,-1e308],[1e308,-1e308],[1e308,1e308],[-1e308,1e308]], "q": [[-9e307,-9e307],[1.5e308,-9e307],[1.5e308,1.5e308],[-9e307,1.5e308]]}
"#,
        &[],
    );
    assert_eq!(
        out[0],
        r#"{"intersects": false, "distance": null, "closest": [[-1.6e308,0.0],[1.6e308,0.0]]}"#
    );
    // The shortest escape is 1e308 + 9e307 = 1.9e308 > f64::MAX: null, as the area.
    assert!(
        out[1].starts_with(r#"{"intersects": true, "depth": null, "normal": "#),
        "{}",
        out[1]
    );
    assert!(out[1].ends_with(r#""area": null}"#), "{}", out[1]);
}

#[test]
fn errors_and_ids_as_in_check() {
    let out = contact(
        r#"{"id": "a", "p": [[0,0],[1,0]], "q": [[0,0],[1,0],[0,1]]}
not json
{"id": [1, 2], "p": [[0,0],[1,0],[0,1]], "q": [[5,0],[6,0],[5,1]]}
{"p": [[0,0],[1,0],[0,1]]}
"#,
        &[],
    );
    assert_eq!(out.len(), 4);
    assert!(
        out[0].starts_with(r#"{"id": "a", "error": "line 1: p: "#),
        "{}",
        out[0]
    );
    assert!(out[1].starts_with(r#"{"error": "line 2"#), "{}", out[1]);
    assert_eq!(
        out[2],
        r#"{"id": [1, 2], "intersects": false, "distance": 4.0, "closest": [[1.0,0.0],[5.0,0.0]]}"#
    );
    assert!(out[3].contains("missing field `q`"), "{}", out[3]);
}

#[test]
fn the_fast_kernel_answers_ordinary_input_alike() {
    let input = r#"{"p": [[0,0],[2,0],[2,2],[0,2]], "q": [[3,0],[4,0],[4,1]]}
{"p": [[0,2],[2,2],[2,0],[0,0]], "q": [[1,1],[3,1],[3,3],[1,3]]}
"#;
    assert_eq!(contact(input, &["--precision", "fast"]), contact(input, &[]));
}

#[test]
fn the_scene_answers_contact_on_its_polygons() {
    let (code, out, err) = run(
        &["scene"],
        br#"{"op": "add", "name": "a", "points": [[0,0],[2,0],[2,2],[0,2]]}
{"op": "add", "name": "b", "points": [[3,0],[4,0],[4,1]]}
{"id": 3, "op": "contact", "a": "a", "b": "b"}
{"op": "translate", "name": "b", "by": [-1.5, 0]}
{"op": "contact", "a": "a", "b": "b"}
{"op": "contact", "a": "a", "b": "c"}
{"op": "contact", "a": "a"}
"#,
    );
    assert_eq!(code, 0, "{err}");
    let out: Vec<&str> = out.lines().collect();
    assert_eq!(
        out[2],
        r#"{"id": 3, "intersects": false, "distance": 1.0, "closest": [[2.0,0.0],[3.0,0.0]]}"#
    );
    // b's hypotenuse y = x − 1.5 cuts the corner of a: moving b by (¼, −¼), a depth of
    // √⅛, separates them (moving it right needs ½).
    assert_eq!(
        out[4],
        format!(
            r#"{{"intersects": true, "depth": {:?}, "normal": [{h:?},{:?}], "overlap": [[1.5,0.0],[2.0,0.0],[2.0,0.5]], "area": 0.125}}"#,
            0.125f64.sqrt(),
            -(0.5f64.sqrt()),
            h = 0.5f64.sqrt()
        )
    );
    assert!(out[5].contains(r#"no polygon is named \"c\""#), "{}", out[5]);
    assert!(out[6].contains("needs the field `b`"), "{}", out[6]);
}

/// Generated `contact` lines for the fast path's byte-for-byte test: random pairs on
/// both sides of the walk/search threshold, near touches a few ulps either side of an
/// edge or a vertex, one-ulp gaps, parallel closest edges, negative zeros, messy
/// input (clockwise, repeated and collinear points, non-convex), scaled by 2^±1000 and
/// into subnormals, and coordinates whose distance overflows.
mod lines {
    use rand::rngs::SmallRng;
    use rand::{Rng, SeedableRng};

    pub type Poly = Vec<[f64; 2]>;

    fn json(v: &[[f64; 2]]) -> String {
        let pts: Vec<String> = v.iter().map(|[x, y]| format!("[{x:?},{y:?}]")).collect();
        format!("[{}]", pts.join(","))
    }

    pub fn line(p: &[[f64; 2]], q: &[[f64; 2]]) -> String {
        format!(r#"{{"p": {}, "q": {}}}"#, json(p), json(q))
    }

    fn ellipse(rng: &mut SmallRng, k: usize, c: [f64; 2], r: f64) -> Poly {
        let mut a: Vec<f64> = (0..k)
            .map(|_| rng.random_range(0.0..std::f64::consts::TAU))
            .collect();
        a.sort_by(f64::total_cmp);
        let (rx, ry) = (r * rng.random_range(0.3..1.0), r * rng.random_range(0.3..1.0));
        a.iter()
            .map(|t| [c[0] + rx * t.cos(), c[1] + ry * t.sin()])
            .collect()
    }

    fn ulps(x: f64, k: i32) -> f64 {
        let mut y = x;
        for _ in 0..k.unsigned_abs() {
            y = if k > 0 { y.next_up() } else { y.next_down() };
        }
        y
    }

    fn scaled(v: &[[f64; 2]], s: f64) -> Poly {
        v.iter().map(|[x, y]| [x * s, y * s]).collect()
    }

    /// The pairs, unscaled.
    fn base(rng: &mut SmallRng) -> Vec<(Poly, Poly)> {
        let mut out = Vec::new();
        for _ in 0..300 {
            let (k1, k2) = (rng.random_range(3..40), rng.random_range(3..40));
            let p = ellipse(rng, k1, [0.0, 0.0], 1.0);
            let d = rng.random_range(1.0..4.0);
            let t: f64 = rng.random_range(0.0..std::f64::consts::TAU);
            let q = ellipse(rng, k2, [d * t.cos(), d * t.sin()], 1.0);
            out.push((p, q));
        }
        // A vertex of q a few ulps either side of p's edge x + y = 1, of its corner
        // (1, 0), and a one-ulp gap beside an axis-parallel edge.
        for k in -3..=3 {
            for (x, y) in [(0.5, 0.5), (0.25, 0.75), (0.1, 0.9), (0.7, 0.3)] {
                let tri = vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
                out.push((tri.clone(), vec![[x, ulps(y, k)], [2.0, 2.0], [x, 2.0]]));
                out.push((tri, vec![[ulps(x, k), y], [3.0, y], [3.0, 3.0]]));
            }
            let sq = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
            out.push((sq.clone(), vec![[ulps(1.0, k), 0.5], [2.0, 0.0], [2.0, 1.0]]));
            out.push((
                sq.clone(),
                vec![[ulps(1.0, k), ulps(1.0, k)], [2.0, 1.5], [1.5, 2.0]],
            ));
            out.push((
                sq,
                vec![
                    [ulps(1.0, k), 0.25],
                    [2.0, 0.25],
                    [2.0, 0.75],
                    [ulps(1.0, k), 0.75],
                ],
            ));
        }
        // Parallel closest edges, offset.
        out.push((
            vec![[0.0, 0.0], [3.0, 0.0], [3.0, 1.0], [0.0, 1.0]],
            vec![[1.0, 2.0], [5.0, 2.0], [5.0, 3.0], [1.0, 3.0]],
        ));
        // Negative zeros at the closest vertices and on the closest edges.
        out.push((
            vec![[-2.0, -1.0], [-0.0, -0.0], [-2.0, 1.0]],
            vec![[1.0, -0.0], [3.0, -1.0], [3.0, 1.0]],
        ));
        out.push((
            vec![[-0.0, -1.0], [-0.0, 1.0], [-2.0, -0.0]],
            vec![[1.0, -0.0], [3.0, -1.0], [3.0, 1.0]],
        ));
        out.push((
            vec![[-1.0, -0.0], [1.0, -0.0], [-0.0, 1.0]],
            vec![[-0.0, -2.0], [-1.0, -3.0], [1.0, -3.0]],
        ));
        for _ in 0..60 {
            // Integer grids with every zero's sign random.
            let g = |rng: &mut SmallRng, c: i32| -> Poly {
                (0..rng.random_range(3..7))
                    .map(|_| {
                        let mut z = |o: i32| {
                            let v = (o + rng.random_range(-3..=3)) as f64;
                            if v == 0.0 && rng.random_bool(0.5) { -0.0 } else { v }
                        };
                        [z(0), z(c)]
                    })
                    .collect()
            };
            let c = rng.random_range(-8..=8);
            let (p, q) = (g(rng, 0), g(rng, c));
            out.push((p, q));
        }
        // Messy: clockwise, repeated points, collinear points, non-convex.
        out.push((
            vec![[0.0, 2.0], [2.0, 2.0], [2.0, 0.0], [0.0, 0.0]],
            vec![[3.0, 0.0], [3.0, 0.0], [4.0, 0.0], [5.0, 0.0], [4.0, 1.0]],
        ));
        out.push((
            vec![[0.0, 0.0], [2.0, 0.0], [1.0, 0.5], [2.0, 2.0], [0.0, 2.0]],
            vec![[3.0, 0.0], [4.0, 0.0], [4.0, 1.0]],
        ));
        out
    }

    /// Every pair of [`base`], and the same scaled by 2^1000, 2^-1000 and 2^-1070, and
    /// pairs whose distance overflows.
    pub fn all(seed: u64) -> Vec<(Poly, Poly)> {
        let mut rng = SmallRng::seed_from_u64(seed);
        let base = base(&mut rng);
        let mut out = base.clone();
        for s in [2f64.powi(1000), 2f64.powi(-1000), 2f64.powi(-1070)] {
            out.extend(base.iter().step_by(3).map(|(p, q)| (scaled(p, s), scaled(q, s))));
        }
        out.push((
            vec![[-1.7e308, 0.0], [-1.6e308, 0.0], [-1.6e308, 1.0]],
            vec![[1.6e308, 0.0], [1.7e308, 0.0], [1.7e308, 1.0]],
        ));
        out.push((
            vec![[-1.7e308, -1e308], [-1.6e308, -1e308], [-1.6e308, 1e308]],
            vec![[1.6e308, 1e-300], [1.7e308, -1e308], [1.7e308, 1e308]],
        ));
        out
    }
}

/// `polysect contact` (distance alone for pairs that do not meet) prints, byte for
/// byte, what the full contact of every pair printed: on generated lines of every
/// family, both precisions.
#[test]
fn the_distance_path_prints_the_full_contacts_reply_byte_for_byte() {
    use polysect::contact::contact_with;
    use polysect::protocol::contact::{contact, contact_with_kernel};
    use polysect::{Exact, Fast};
    let pairs = lines::all(0x00c0_4747);
    let input: String = pairs.iter().map(|(p, q)| lines::line(p, q) + "\n").collect();
    let (mut full, mut full_fast) = (Vec::new(), Vec::new());
    contact(input.as_bytes(), &mut full, |p, q| contact_with(Exact, p, q)).expect("in memory");
    contact(input.as_bytes(), &mut full_fast, |p, q| contact_with(Fast, p, q)).expect("in memory");
    let (full, full_fast) = (
        String::from_utf8(full).unwrap(),
        String::from_utf8(full_fast).unwrap(),
    );
    let mut lib = Vec::new();
    contact_with_kernel(Exact, input.as_bytes(), &mut lib).expect("in memory");
    assert_eq!(String::from_utf8(lib).unwrap(), full, "the library's fast path");
    let (code, out, err) = run(&["contact"], input.as_bytes());
    assert_eq!(code, 0, "{err}");
    let (code, out_fast, err) = run(&["contact", "--precision", "fast"], input.as_bytes());
    assert_eq!(code, 0, "{err}");
    for (k, ((got, want), line)) in out.lines().zip(full.lines()).zip(input.lines()).enumerate() {
        assert_eq!(got, want, "line {}: {line}", k + 1);
    }
    assert_eq!(out, full);
    assert_eq!(out_fast, full_fast);
    // Both outcomes, negative zeros and errors are covered.
    let apart = full
        .lines()
        .filter(|l| l.contains(r#""intersects": false"#))
        .count();
    let meet = full
        .lines()
        .filter(|l| l.contains(r#""intersects": true"#))
        .count();
    let errors = full.lines().filter(|l| l.contains(r#""error""#)).count();
    assert!(
        apart > 300 && meet > 100 && errors > 0,
        "{apart} apart, {meet} meet, {errors} errors"
    );
    assert!(input.contains("-0.0") && !full.contains("-0.0,") && !full.contains(",-0.0]"));
}

/// The scene's `contact` op (distance alone for pairs that do not meet) prints what the
/// full contact of the polygons where they stand prints, posed ones included.
#[test]
fn the_scenes_distance_path_prints_the_full_contacts_reply() {
    use polysect::contact::contact_with;
    use polysect::protocol::contact::contact_json;
    use polysect::{ConvexPolygon, Exact};
    let pairs = lines::all(0x00c0_4748);
    let mut script = String::new();
    let mut names = Vec::new();
    for (k, (p, q)) in pairs.iter().enumerate().step_by(2) {
        // Only pairs whose polygons the scene accepts.
        if ConvexPolygon::new(p.iter().copied()).is_err() || ConvexPolygon::new(q.iter().copied()).is_err() {
            continue;
        }
        let add = lines::line(p, q);
        let add = add.replacen(
            r#"{"p": "#,
            &format!(r#"{{"op": "add", "name": "p{k}", "points": "#),
            1,
        );
        let (p_add, q_pts) = add.split_once(r#", "q": "#).expect("two lists");
        script += &format!("{p_add}}}\n");
        script += &format!("{{\"op\": \"add\", \"name\": \"q{k}\", \"points\": {}\n", q_pts);
        if k % 4 == 0 {
            // A quarter turn about the origin and back by a translation: q stays near p.
            script +=
                &format!(r#"{{"op": "pose", "name": "q{k}", "rotation": [0, 1], "translation": [0.5, 0]}}"#);
            script.push('\n');
        }
        script += &format!(r#"{{"op": "contact", "a": "p{k}", "b": "q{k}"}}"#);
        script += &format!(
            "\n{{\"op\": \"vertices\", \"name\": \"p{k}\"}}\n{{\"op\": \"vertices\", \"name\": \"q{k}\"}}\n"
        );
        names.push(k);
    }
    let (code, out, err) = run(&["scene"], script.as_bytes());
    assert_eq!(code, 0, "{err}");
    let (mut apart, mut meet, mut checked) = (0, 0, 0);
    let replies: Vec<&str> = out.lines().collect();
    let world = |reply: &str| -> Option<ConvexPolygon> {
        let v: serde_json::Value = serde_json::from_str(reply).expect("JSON");
        let pts = v.get("points")?.as_array()?.iter().map(|p| {
            let p = p.as_array().expect("a point");
            [p[0].as_f64().expect("x"), p[1].as_f64().expect("y")]
        });
        ConvexPolygon::new(pts.collect::<Vec<_>>()).ok()
    };
    for (k, reply) in replies.iter().enumerate() {
        if !reply.contains(r#""intersects""#) {
            continue;
        }
        let (Some(p), Some(q)) = (world(replies[k + 1]), world(replies[k + 2])) else {
            continue;
        };
        let want = format!("{{{}}}", contact_json(&contact_with(Exact, &p, &q)));
        assert_eq!(*reply, want, "scene reply {k}");
        checked += 1;
        if reply.contains(r#""intersects": false"#) {
            apart += 1
        } else {
            meet += 1
        }
    }
    assert!(checked >= names.len() * 9 / 10, "{checked} of {}", names.len());
    assert!(apart > 100 && meet > 30, "{apart} apart, {meet} meet");
}
