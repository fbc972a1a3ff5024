//! The scene's `pose` op against an exact reference computed here: each world
//! coordinate c·x − s·y + tx (and s·x + c·y + ty) as an exact big-integer multiple of a
//! power of two, rounded to nearest, ties to even, by hand; strict convexity of the
//! rounded image by exact orientations; intersections by the linear algorithm on the
//! reference's world polygons. Covers exact touches one ulp apart after a turn, thin
//! shapes whose rounding breaks convexity, huge and tiny coordinates, overflow,
//! thousands of frames, translate after pose, edits of posed polygons, and random
//! sessions of every op compared reply by reply.

use num_bigint::BigInt;
use num_traits::{One, Signed, ToPrimitive, Zero};
use polysect::intersect::{ArrayIntersection, Linear};
use polysect::protocol::scene::{SceneOptions, SceneSession};
use polysect::{ConvexPolygon, Exact, Kernel, Orientation, Point};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use serde_json::{Value, json};
use std::collections::BTreeMap;
use std::io::Write as _;
use std::process::{Command, Stdio};

// ------------------------------------------------------------------ exact reference

/// `v = m · 2^e` exactly, `m` an integer.
fn parts(v: f64) -> (BigInt, i64) {
    let bits = v.to_bits();
    let neg = bits >> 63 == 1;
    let exp = ((bits >> 52) & 0x7ff) as i64;
    let frac = bits & ((1u64 << 52) - 1);
    let (m, e) = if exp == 0 {
        (frac, -1074)
    } else {
        (frac | (1u64 << 52), exp - 1075)
    };
    let m = BigInt::from(m);
    (if neg { -m } else { m }, e)
}

/// The exact sum of `terms` (each a product of doubles) as `n · 2^e`.
fn exact_sum(terms: &[(f64, f64, i32)]) -> (BigInt, i64) {
    let parts: Vec<(BigInt, i64)> = terms
        .iter()
        .map(|&(a, b, sign)| {
            let ((ma, ea), (mb, eb)) = (parts(a), parts(b));
            let m = ma * mb;
            (if sign < 0 { -m } else { m }, ea + eb)
        })
        .collect();
    let e = parts.iter().map(|p| p.1).min().expect("terms");
    let n = parts
        .into_iter()
        .fold(BigInt::zero(), |acc, (m, pe)| acc + (m << ((pe - e) as usize)));
    (n, e)
}

/// `n · 2^e` rounded to the nearest double, ties to even (exact zero is +0); `None`
/// when it overflows.
fn round(n: BigInt, e: i64) -> Option<f64> {
    if n.is_zero() {
        return Some(0.0);
    }
    let neg = n.is_negative();
    let mag = n.abs();
    let bits = mag.bits() as i64;
    let lsb = (e + bits - 53).max(-1074);
    let shift = lsb - e;
    let mut q = if shift > 0 {
        let q: BigInt = &mag >> (shift as usize);
        let rem: BigInt = &mag - (&q << (shift as usize));
        let half = BigInt::one() << ((shift - 1) as usize);
        let odd = (&q & BigInt::one()) == BigInt::one();
        if rem > half || (rem == half && odd) {
            q + 1
        } else {
            q
        }
    } else {
        &mag << ((-shift) as usize)
    }
    .to_u64()
    .expect("at most 2^53");
    let mut lsb = lsb;
    if q == 1u64 << 53 {
        q >>= 1;
        lsb += 1;
    }
    let value = if q < 1u64 << 52 {
        // Subnormal (lsb is -1074 here).
        f64::from_bits(q)
    } else {
        let biased = lsb + 52 + 1023;
        if biased > 2046 {
            return None;
        }
        f64::from_bits(((biased as u64) << 52) | (q - (1u64 << 52)))
    };
    Some(if neg { -value } else { value })
}

#[derive(Clone, Copy, Debug, PartialEq)]
struct RefPose {
    c: f64,
    s: f64,
    tx: f64,
    ty: f64,
}

impl RefPose {
    fn image(&self, p: Point) -> Option<Point> {
        let (n, e) = exact_sum(&[(self.c, p.x, 1), (self.s, p.y, -1), (self.tx, 1.0, 1)]);
        let x = round(n, e)?;
        let (n, e) = exact_sum(&[(self.s, p.x, 1), (self.c, p.y, 1), (self.ty, 1.0, 1)]);
        let y = round(n, e)?;
        Some(Point::new(x, y))
    }
}

/// Strictly convex, counter-clockwise, winding once, decided exactly.
fn strictly_convex(v: &[Point]) -> bool {
    let n = v.len();
    if n < 3 || v.iter().any(|p| !p.is_finite()) {
        return false;
    }
    let left = (0..n).all(|i| Exact.orient(v[i], v[(i + 1) % n], v[(i + 2) % n]) == Orientation::Ccw);
    let up = |a: Point, b: Point| b.y > a.y || (b.y == a.y && b.x > a.x);
    let windings = (0..n)
        .filter(|&i| !up(v[i], v[(i + 1) % n]) && up(v[(i + 1) % n], v[(i + 2) % n]))
        .count();
    left && windings == 1
}

/// The reference image of `shape`, if the pose is accepted.
fn placed(shape: &[Point], pose: &RefPose) -> Option<Vec<Point>> {
    let w: Option<Vec<Point>> = shape.iter().map(|&p| pose.image(p)).collect();
    w.filter(|w| strictly_convex(w))
}

fn intersects(p: &[Point], q: &[Point]) -> bool {
    let p = ConvexPolygon::from_ccw_unchecked(p.to_vec());
    let q = ConvexPolygon::from_ccw_unchecked(q.to_vec());
    Linear.intersects_with(Exact, &p, &q)
}

#[test]
fn the_reference_rounds_like_the_hardware_where_one_rounding_suffices() {
    // A single product or sum is rounded once by IEEE arithmetic: the reference agrees.
    let mut rng = SmallRng::seed_from_u64(1);
    for _ in 0..20_000 {
        let a = f64::from_bits(rng.random::<u64>() >> 2);
        let b = f64::from_bits(rng.random::<u64>() >> 2);
        let (n, e) = exact_sum(&[(a, b, 1)]);
        let want = a * b;
        assert_eq!(
            round(n, e).map(f64::to_bits),
            want.is_finite().then_some(want.to_bits())
        );
        let (n, e) = exact_sum(&[(a, 1.0, 1), (b, 1.0, -1)]);
        assert_eq!(
            round(n, e).map(f64::to_bits),
            Some((a - b).to_bits()),
            "{a} - {b}"
        );
    }
}

// ------------------------------------------------------------------ session helpers

fn session() -> SceneSession {
    SceneSession::new(SceneOptions::default())
}

fn ask(s: &mut SceneSession, line: Value) -> Value {
    let reply = s.answer_line(line.to_string().as_bytes());
    serde_json::from_str(&reply).unwrap_or_else(|e| panic!("{line}: reply {reply} is not JSON: {e}"))
}

fn is_ok(v: &Value) -> bool {
    v.get("error").is_none()
}

fn pts(v: &Value) -> Vec<Point> {
    v.as_array()
        .expect("points")
        .iter()
        .map(|p| Point::new(p[0].as_f64().unwrap(), p[1].as_f64().unwrap()))
        .collect()
}

fn arr(v: &[Point]) -> Value {
    Value::Array(v.iter().map(|p| json!([p.x, p.y])).collect())
}

fn pose_line(name: &str, p: &RefPose) -> Value {
    json!({"op": "pose", "name": name, "rotation": [p.c, p.s], "translation": [p.tx, p.ty]})
}

fn world(s: &mut SceneSession, name: &str) -> Vec<Point> {
    pts(&ask(s, json!({"op": "vertices", "name": name}))["points"])
}

fn polygon(rng: &mut SmallRng, k: usize, r: f64, cx: f64, cy: f64) -> Vec<Point> {
    loop {
        let mut angles: Vec<f64> = (0..k)
            .map(|_| rng.random_range(0.0..std::f64::consts::TAU))
            .collect();
        angles.sort_by(f64::total_cmp);
        let v: Vec<Point> = angles
            .iter()
            .map(|a| Point::new(cx + r * a.cos(), cy + r * a.sin()))
            .collect();
        if strictly_convex(&v) {
            return v;
        }
    }
}

fn angle_pose(rng: &mut SmallRng, spread: f64) -> RefPose {
    let t: f64 = rng.random_range(-10.0..10.0);
    RefPose {
        c: t.cos(),
        s: t.sin(),
        tx: rng.random_range(-spread..spread),
        ty: rng.random_range(-spread..spread),
    }
}

// ------------------------------------------------------------------ targeted tests

#[test]
fn posed_vertices_are_the_exactly_rounded_images() {
    let mut rng = SmallRng::seed_from_u64(38);
    let mut s = session();
    let mut refused = 0;
    for round_no in 0..300 {
        let name = format!("p{round_no}");
        let scale = [1.0, 1e-3, 1e6, 2f64.powi(600), 2f64.powi(-600)][round_no % 5];
        let k = rng.random_range(3..12);
        let cx = rng.random_range(-5.0..5.0) * scale;
        let shape = polygon(&mut rng, k, scale, cx, 0.0);
        assert!(is_ok(&ask(
            &mut s,
            json!({"op": "add", "name": name, "points": arr(&shape)})
        )));
        let mut pose = angle_pose(&mut rng, 10.0 * scale);
        if round_no % 7 == 0 {
            // Not a unit rotation: the map also scales.
            pose.c *= 3.0;
        }
        let reply = ask(&mut s, pose_line(&name, &pose));
        match placed(&shape, &pose) {
            Some(w) => {
                assert!(is_ok(&reply), "{reply}");
                let v = ask(&mut s, json!({"op": "vertices", "name": name}));
                assert_eq!(pts(&v["points"]), w, "pose {pose:?}");
                assert_eq!(pts(&v["shape"]), shape);
            }
            None => {
                refused += 1;
                assert!(!is_ok(&reply));
                let v = ask(&mut s, json!({"op": "vertices", "name": name}));
                assert_eq!(pts(&v["points"]), shape, "a refused pose changes nothing");
                assert!(v.get("shape").is_none(), "never posed");
            }
        }
    }
    assert!(refused < 50, "{refused} refusals");
}

#[test]
fn touches_one_ulp_apart_after_a_turn() {
    let mut rng = SmallRng::seed_from_u64(3801);
    for _ in 0..200 {
        let mut s = session();
        let shape = polygon(&mut rng, 7, 1.0, 0.0, 0.0);
        ask(&mut s, json!({"op": "add", "name": "b", "points": arr(&shape)}));
        let pose = angle_pose(&mut rng, 100.0);
        let Some(w) = placed(&shape, &pose) else { continue };
        assert!(is_ok(&ask(&mut s, pose_line("b", &pose))));
        // b's rightmost world vertex (the lowest of a tie).
        let right = *w
            .iter()
            .max_by(|p, q| p.x.total_cmp(&q.x).then(q.y.total_cmp(&p.y)))
            .unwrap();
        for (gap, expect) in [(right.x, true), (right.x.next_up(), false)] {
            let a = vec![
                Point::new(gap, right.y),
                Point::new(gap + 1.0, right.y - 1.0),
                Point::new(gap + 1.0, right.y + 1.0),
            ];
            ask(&mut s, json!({"op": "drop", "name": "a"}));
            assert!(is_ok(&ask(
                &mut s,
                json!({"op": "add", "name": "a", "points": arr(&a)})
            )));
            let got = ask(&mut s, json!({"op": "intersects", "a": "a", "b": "b"}));
            assert_eq!(got["intersects"], json!(expect), "{pose:?}");
            assert_eq!(intersects(&a, &w), expect);
            let pairs = ask(&mut s, json!({"op": "pairs"}));
            assert_eq!(
                pairs["pairs"],
                if expect { json!([["a", "b"]]) } else { json!([]) }
            );
        }
    }
}

#[test]
fn thin_shapes_whose_rounding_breaks_convexity_are_refused() {
    let mut rng = SmallRng::seed_from_u64(3802);
    let (mut refused, mut accepted) = (0, 0);
    for _ in 0..400 {
        // A sliver: the apex a few ulps off the base line.
        let x = rng.random_range(1.0..1e6);
        let apex = Point::new(x / 2.0, f64::EPSILON * x * rng.random_range(0.01..2.0));
        let shape = vec![Point::new(0.0, 0.0), Point::new(x, 0.0), apex];
        if !strictly_convex(&shape) {
            continue;
        }
        let mut s = session();
        ask(&mut s, json!({"op": "add", "name": "t", "points": arr(&shape)}));
        let pose = angle_pose(&mut rng, 1e7);
        let reply = ask(&mut s, pose_line("t", &pose));
        match placed(&shape, &pose) {
            Some(w) => {
                accepted += 1;
                assert!(is_ok(&reply));
                assert_eq!(world(&mut s, "t"), w);
            }
            None => {
                refused += 1;
                assert!(
                    reply["error"].as_str().unwrap().contains("pose refused"),
                    "{reply}"
                );
                assert_eq!(world(&mut s, "t"), shape);
            }
        }
    }
    assert!(
        refused > 20 && accepted > 20,
        "refused {refused}, accepted {accepted}"
    );
}

#[test]
fn huge_tiny_and_overflowing_poses() {
    let square = |h: f64| {
        vec![
            Point::new(0.0, 0.0),
            Point::new(h, 0.0),
            Point::new(h, h),
            Point::new(0.0, h),
        ]
    };
    let cases = [
        (
            square(2f64.powi(1000)),
            RefPose {
                c: 0.6,
                s: 0.8,
                tx: 0.0,
                ty: 0.0,
            },
        ),
        (
            square(2f64.powi(1020)),
            RefPose {
                c: 1.0,
                s: 1.0,
                tx: 0.0,
                ty: 0.0,
            },
        ), // overflows
        (
            square(f64::MAX / 2.0),
            RefPose {
                c: 1.0,
                s: 0.0,
                tx: f64::MAX,
                ty: 0.0,
            },
        ), // overflows
        (
            square(2f64.powi(-1000)),
            RefPose {
                c: 0.6,
                s: 0.8,
                tx: 0.0,
                ty: 0.0,
            },
        ),
        (
            square(2f64.powi(-1070)),
            RefPose {
                c: 0.6,
                s: 0.8,
                tx: 0.0,
                ty: 0.0,
            },
        ), // subnormal
        (
            square(1e-300),
            RefPose {
                c: 0.6,
                s: 0.8,
                tx: 1.0,
                ty: 0.0,
            },
        ), // collapses
        (
            square(1.0),
            RefPose {
                c: 2f64.powi(1000),
                s: 0.0,
                tx: 0.0,
                ty: 0.0,
            },
        ),
        (
            square(1.0),
            RefPose {
                c: 2f64.powi(-1070),
                s: 2f64.powi(-1072),
                tx: 0.0,
                ty: 0.0,
            },
        ),
    ];
    let mut kinds = (0, 0);
    for (shape, pose) in cases {
        let mut s = session();
        ask(&mut s, json!({"op": "add", "name": "q", "points": arr(&shape)}));
        let reply = ask(&mut s, pose_line("q", &pose));
        let overflow = shape.iter().any(|&p| pose.image(p).is_none());
        match placed(&shape, &pose) {
            Some(w) => {
                kinds.0 += 1;
                assert!(is_ok(&reply), "{pose:?}: {reply}");
                assert_eq!(world(&mut s, "q"), w);
            }
            None => {
                kinds.1 += 1;
                let msg = reply["error"]
                    .as_str()
                    .unwrap_or_else(|| panic!("{pose:?}: {reply}"));
                assert_eq!(msg.contains("finite range"), overflow, "{msg}");
                assert_eq!(world(&mut s, "q"), shape);
            }
        }
    }
    assert!(kinds.0 >= 4 && kinds.1 >= 2, "{kinds:?}");
}

#[test]
fn the_contract_s_fields_and_errors() {
    let mut s = session();
    let shape = vec![Point::new(0.0, 0.0), Point::new(2.0, 0.0), Point::new(0.0, 1.0)];
    ask(&mut s, json!({"op": "add", "name": "a", "points": arr(&shape)}));
    // Omitted fields: rotation [1, 0], translation [0, 0].
    assert!(is_ok(&ask(
        &mut s,
        json!({"op": "pose", "name": "a", "translation": [5, 0]})
    )));
    assert_eq!(world(&mut s, "a")[1], Point::new(7.0, 0.0));
    assert!(is_ok(&ask(
        &mut s,
        json!({"op": "pose", "name": "a", "rotation": [0, 1]})
    )));
    assert_eq!(world(&mut s, "a")[1], Point::new(0.0, 2.0));
    assert!(is_ok(&ask(&mut s, json!({"op": "pose", "name": "a"}))));
    let v = ask(&mut s, json!({"op": "vertices", "name": "a"}));
    assert_eq!(pts(&v["points"]), shape);
    assert_eq!(
        pts(&v["shape"]),
        shape,
        "posed with the identity still reports its shape"
    );
    // null is an error, not an omission; errors change nothing; the id is echoed.
    ask(&mut s, json!({"op": "pose", "name": "a", "translation": [1, 1]}));
    let before = ask(&mut s, json!({"op": "vertices", "name": "a"}));
    for bad in [
        json!({"id": 9, "op": "pose", "name": "a", "rotation": null}),
        json!({"id": 9, "op": "pose", "name": "a", "translation": null}),
        json!({"id": 9, "op": "pose", "name": "a", "rotation": [0, 0]}),
        json!({"id": 9, "op": "pose", "name": "a", "rotation": [1]}),
        json!({"id": 9, "op": "pose", "name": "zz"}),
        json!({"id": 9, "op": "pose"}),
    ] {
        let r = ask(&mut s, bad.clone());
        assert_eq!(r["id"], json!(9), "{bad}: {r}");
        assert!(!is_ok(&r), "{bad}: {r}");
        assert_eq!(ask(&mut s, json!({"op": "vertices", "name": "a"})), before);
    }
}

#[test]
fn thousands_of_frames_do_not_drift() {
    let mut rng = SmallRng::seed_from_u64(3803);
    let shape = polygon(&mut rng, 9, 3.0, 1.0, -2.0);
    let mut s = session();
    ask(&mut s, json!({"op": "add", "name": "a", "points": arr(&shape)}));
    let first = RefPose {
        c: 0.3f64.cos(),
        s: 0.3f64.sin(),
        tx: 17.25,
        ty: -4.5,
    };
    ask(&mut s, pose_line("a", &first));
    let want = placed(&shape, &first).expect("accepted");
    assert_eq!(world(&mut s, "a"), want);
    for frame in 0..4000 {
        let t = frame as f64 * 0.013;
        let pose = RefPose {
            c: t.cos(),
            s: t.sin(),
            tx: t.sin() * 50.0,
            ty: t,
        };
        assert!(is_ok(&ask(&mut s, pose_line("a", &pose))));
        if frame % 500 == 0 {
            assert_eq!(world(&mut s, "a"), placed(&shape, &pose).unwrap());
        }
        // Translations in between move the pose, which the next pose replaces.
        ask(&mut s, json!({"op": "translate", "name": "a", "by": [0.1, -0.1]}));
    }
    ask(&mut s, pose_line("a", &first));
    assert_eq!(
        world(&mut s, "a"),
        want,
        "absolute poses: the first frame again, bit for bit"
    );
    let v = ask(&mut s, json!({"op": "vertices", "name": "a"}));
    assert_eq!(pts(&v["shape"]), shape);
}

#[test]
fn translate_after_pose_moves_the_pose() {
    let mut rng = SmallRng::seed_from_u64(3804);
    for _ in 0..200 {
        let shape = polygon(&mut rng, 6, 1.0, 0.0, 0.0);
        let mut s = session();
        ask(&mut s, json!({"op": "add", "name": "a", "points": arr(&shape)}));
        let pose = angle_pose(&mut rng, 1e4);
        if placed(&shape, &pose).is_none() {
            continue;
        }
        ask(&mut s, pose_line("a", &pose));
        let (dx, dy) = (rng.random_range(-1e3..1e3), rng.random_range(-1e-3..1e-3));
        assert!(is_ok(&ask(
            &mut s,
            json!({"op": "translate", "name": "a", "by": [dx, dy]})
        )));
        let moved = RefPose {
            tx: pose.tx + dx,
            ty: pose.ty + dy,
            ..pose
        };
        assert_eq!(world(&mut s, "a"), placed(&shape, &moved).unwrap());
    }
    // Overflowing the translation is refused, changing nothing.
    let mut s = session();
    let shape = vec![Point::new(0.0, 0.0), Point::new(1.0, 0.0), Point::new(0.0, 1.0)];
    ask(&mut s, json!({"op": "add", "name": "a", "points": arr(&shape)}));
    ask(
        &mut s,
        json!({"op": "pose", "name": "a", "translation": [f64::MAX, 0.0]}),
    );
    let before = world(&mut s, "a");
    assert!(!is_ok(&ask(
        &mut s,
        json!({"op": "translate", "name": "a", "by": [f64::MAX, 0.0]})
    )));
    assert_eq!(world(&mut s, "a"), before);
}

#[test]
fn edits_of_posed_polygons_take_shape_coordinates() {
    let mut rng = SmallRng::seed_from_u64(3805);
    let (mut ok, mut refused) = (0, 0);
    for _ in 0..300 {
        let shape = polygon(&mut rng, 5, 1.0, 0.0, 0.0);
        let mut s = session();
        ask(&mut s, json!({"op": "add", "name": "a", "points": arr(&shape)}));
        let pose = angle_pose(&mut rng, 10.0);
        if placed(&shape, &pose).is_none() {
            continue;
        }
        ask(&mut s, pose_line("a", &pose));
        // Move vertex 2 to a random shape point, or insert after vertex 0.
        let p = Point::new(rng.random_range(-1.2..1.2), rng.random_range(-1.2..1.2));
        let mut edited = shape.clone();
        let reply = if rng.random_bool(0.5) {
            edited[2] = p;
            ask(
                &mut s,
                json!({"op": "move", "name": "a", "vertex": 2, "to": [p.x, p.y]}),
            )
        } else {
            edited.insert(1, p);
            ask(
                &mut s,
                json!({"op": "insert", "name": "a", "after": 0, "point": [p.x, p.y]}),
            )
        };
        let expect = strictly_convex(&edited).then(|| placed(&edited, &pose)).flatten();
        let v = ask(&mut s, json!({"op": "vertices", "name": "a"}));
        match expect {
            Some(w) => {
                ok += 1;
                assert!(is_ok(&reply), "{reply}");
                assert_eq!(pts(&v["points"]), w);
                assert_eq!(pts(&v["shape"]), edited);
            }
            None => {
                refused += 1;
                assert!(!is_ok(&reply));
                assert_eq!(pts(&v["shape"]), shape);
                assert_eq!(pts(&v["points"]), placed(&shape, &pose).unwrap());
            }
        }
    }
    assert!(ok > 20 && refused > 20, "{ok} accepted, {refused} refused");
}

#[test]
fn the_binary_answers_pose_lines() {
    let input = concat!(
        r#"{"op":"add","name":"a","points":[[0,0],[2,0],[2,2],[0,2]]}"#,
        "\n",
        r#"{"op":"add","name":"b","points":[[3,0],[4,0],[4,1]]}"#,
        "\n",
        r#"{"id":1,"op":"pose","name":"b","rotation":[-1,0],"translation":[6,0]}"#,
        "\n",
        r#"{"op":"intersects","a":"a","b":"b"}"#,
        "\n",
        r#"{"op":"vertices","name":"b"}"#,
        "\n",
        r#"{"op":"translate","name":"b","by":[0.5,0]}"#,
        "\n",
        r#"{"op":"pairs"}"#,
        "\n"
    );
    let mut child = Command::new(env!("CARGO_BIN_EXE_polysect"))
        .arg("scene")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .expect("run polysect");
    child.stdin.take().unwrap().write_all(input.as_bytes()).unwrap();
    let out = child.wait_with_output().unwrap();
    let lines: Vec<Value> = String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    // The reference: (x, y) ↦ (6 − x, −y).
    let pose = RefPose {
        c: -1.0,
        s: 0.0,
        tx: 6.0,
        ty: 0.0,
    };
    let shape = [Point::new(3.0, 0.0), Point::new(4.0, 0.0), Point::new(4.0, 1.0)];
    let w: Vec<Point> = shape.iter().map(|&p| pose.image(p).unwrap()).collect();
    assert_eq!(lines[2], json!({"id": 1, "ok": true}));
    assert_eq!(lines[3], json!({"intersects": true}));
    assert_eq!(
        lines[4],
        json!({"ids": [0, 1, 2], "points": arr(&w), "shape": arr(&shape)})
    );
    assert_eq!(lines[6], json!({"pairs": []}));
}

// ------------------------------------------------------------------ random sessions

#[derive(Clone, Debug)]
struct Model {
    /// (id, shape point) counter-clockwise.
    shape: Vec<(u64, Point)>,
    pose: Option<RefPose>,
    next_id: u64,
}

impl Model {
    fn points(&self) -> Vec<Point> {
        self.shape.iter().map(|v| v.1).collect()
    }

    fn world(&self) -> Vec<Point> {
        match &self.pose {
            Some(p) => placed(&self.points(), p).expect("kept convex"),
            None => self.points(),
        }
    }

    /// Accepts `shape` (ids, shape points) if it and its image are strictly convex.
    fn accept(&mut self, shape: Vec<(u64, Point)>) -> bool {
        let pts: Vec<Point> = shape.iter().map(|v| v.1).collect();
        let fine = strictly_convex(&pts) && self.pose.is_none_or(|p| placed(&pts, &p).is_some());
        if fine {
            self.shape = shape;
        }
        fine
    }

    fn vertices(&self) -> Value {
        let start = (0..self.shape.len()).min_by_key(|&i| self.shape[i].0).unwrap();
        let mut order: Vec<usize> = (0..self.shape.len())
            .map(|i| (start + i) % self.shape.len())
            .collect();
        order.truncate(self.shape.len());
        let w = self.world();
        let ids: Vec<u64> = order.iter().map(|&i| self.shape[i].0).collect();
        let points: Vec<Point> = order.iter().map(|&i| w[i]).collect();
        let mut v = json!({"ids": ids, "points": arr(&points)});
        if self.pose.is_some() {
            let shape: Vec<Point> = order.iter().map(|&i| self.shape[i].1).collect();
            v["shape"] = arr(&shape);
        }
        v
    }
}

#[test]
fn random_sessions_with_poses_match_the_reference() {
    let names = ["a", "b", "c", "d", "e"];
    for seed in 0..6u64 {
        let mut rng = SmallRng::seed_from_u64(0x5ce0_0038 + seed);
        let mut s = session();
        let mut model: BTreeMap<&str, Model> = BTreeMap::new();
        for step in 0..1500 {
            let name = names[rng.random_range(0..names.len())];
            let other = names[rng.random_range(0..names.len())];
            let op = rng.random_range(0..10);
            let context = format!("seed {seed} step {step} op {op} {name}");
            match (op, model.get(name).cloned()) {
                (_, None) => {
                    let k = rng.random_range(3..9);
                    let (r, cx) = (rng.random_range(0.5..3.0), rng.random_range(-4.0..4.0));
                    let pts = polygon(&mut rng, k, r, cx, 0.0);
                    let r = ask(&mut s, json!({"op": "add", "name": name, "points": arr(&pts)}));
                    assert!(is_ok(&r), "{context}: {r}");
                    let shape = pts.iter().enumerate().map(|(i, &p)| (i as u64, p)).collect();
                    model.insert(
                        name,
                        Model {
                            shape,
                            pose: None,
                            next_id: k as u64,
                        },
                    );
                }
                (0 | 1, Some(mut m)) => {
                    let pose = if rng.random_bool(0.2) {
                        // Quarter turns are exact: exact touches survive them.
                        let (c, s) =
                            [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)][rng.random_range(0..4)];
                        RefPose {
                            c,
                            s,
                            tx: rng.random_range(-4..=4) as f64,
                            ty: rng.random_range(-2..=2) as f64,
                        }
                    } else {
                        angle_pose(&mut rng, 4.0)
                    };
                    let r = ask(&mut s, pose_line(name, &pose));
                    let fine = placed(&m.points(), &pose).is_some();
                    assert_eq!(is_ok(&r), fine, "{context}: {r}");
                    if fine {
                        m.pose = Some(pose);
                        model.insert(name, m);
                    }
                }
                (2, Some(mut m)) => {
                    let (dx, dy) = (rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0));
                    let r = ask(&mut s, json!({"op": "translate", "name": name, "by": [dx, dy]}));
                    let fine = match m.pose {
                        Some(p) => {
                            let moved = RefPose {
                                tx: p.tx + dx,
                                ty: p.ty + dy,
                                ..p
                            };
                            let fine = placed(&m.points(), &moved).is_some();
                            if fine {
                                m.pose = Some(moved);
                            }
                            fine
                        }
                        None => {
                            let moved: Vec<(u64, Point)> = m
                                .shape
                                .iter()
                                .map(|&(i, p)| (i, Point::new(p.x + dx, p.y + dy)))
                                .collect();
                            m.accept(moved)
                        }
                    };
                    assert_eq!(is_ok(&r), fine, "{context}: {r}");
                    model.insert(name, m);
                }
                (3, Some(mut m)) => {
                    let i = rng.random_range(0..m.shape.len());
                    let id = m.shape[i].0;
                    let near = m.shape[i].1;
                    let to = Point::new(
                        near.x + rng.random_range(-0.3..0.3),
                        near.y + rng.random_range(-0.3..0.3),
                    );
                    let r = ask(
                        &mut s,
                        json!({"op": "move", "name": name, "vertex": id, "to": [to.x, to.y]}),
                    );
                    let mut shape = m.shape.clone();
                    shape[i].1 = to;
                    assert_eq!(is_ok(&r), m.accept(shape), "{context}: {r}");
                    model.insert(name, m);
                }
                (4, Some(mut m)) => {
                    let i = rng.random_range(0..m.shape.len());
                    let (a, b) = (m.shape[i].1, m.shape[(i + 1) % m.shape.len()].1);
                    let t: f64 = rng.random_range(0.0..1.0);
                    let out = rng.random_range(-0.05..0.3);
                    let p = Point::new(
                        a.x + t * (b.x - a.x) + out * (b.y - a.y),
                        a.y + t * (b.y - a.y) - out * (b.x - a.x),
                    );
                    let r = ask(
                        &mut s,
                        json!({"op": "insert", "name": name, "after": m.shape[i].0, "point": [p.x, p.y]}),
                    );
                    let mut shape = m.shape.clone();
                    shape.insert(i + 1, (m.next_id, p));
                    let fine = m.accept(shape);
                    assert_eq!(is_ok(&r), fine, "{context}: {r}");
                    if fine {
                        assert_eq!(r["vertex"], json!(m.next_id));
                        m.next_id += 1;
                    }
                    model.insert(name, m);
                }
                (5, Some(mut m)) => {
                    let i = rng.random_range(0..m.shape.len());
                    let id = m.shape[i].0;
                    let r = ask(&mut s, json!({"op": "remove", "name": name, "vertex": id}));
                    let mut shape = m.shape.clone();
                    shape.remove(i);
                    let fine = shape.len() >= 3 && m.accept(shape);
                    assert_eq!(is_ok(&r), fine, "{context}: {r}");
                    model.insert(name, m);
                }
                (6 | 7, Some(m)) => {
                    let r = ask(&mut s, json!({"op": "intersects", "a": name, "b": other}));
                    match model.get(other) {
                        Some(o) => {
                            assert_eq!(
                                r,
                                json!({"intersects": intersects(&m.world(), &o.world())}),
                                "{context} {other}"
                            )
                        }
                        None => assert!(!is_ok(&r)),
                    }
                }
                (8, Some(_)) => {
                    let r = ask(&mut s, json!({"op": "pairs"}));
                    let worlds: Vec<(&str, Vec<Point>)> =
                        model.iter().map(|(n, m)| (*n, m.world())).collect();
                    let mut want = Vec::new();
                    for (i, (na, wa)) in worlds.iter().enumerate() {
                        for (nb, wb) in &worlds[i + 1..] {
                            if intersects(wa, wb) {
                                want.push(json!([na, nb]));
                            }
                        }
                    }
                    assert_eq!(r, json!({"pairs": want}), "{context}");
                }
                (_, Some(m)) => {
                    let r = ask(&mut s, json!({"op": "vertices", "name": name}));
                    assert_eq!(r, m.vertices(), "{context}");
                }
            }
        }
        assert!(model.values().filter(|m| m.pose.is_some()).count() > 0);
    }
}
