//! `polysect contact` and the scene's `contact` op, from outside, against the contract:
//! field names and order, the overlap's start and dropped repeats, `null` past the
//! largest double, errors and ids as in `check`.

mod common;

use common::run;

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
