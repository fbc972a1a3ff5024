//! `separating_line` against an exact brute force on small point sets in every relative
//! position: random, on a coarse grid (many collinear triples, duplicates and exact
//! touchings), all points on one line, single points, vertical and horizontal gaps, and
//! the same sets scaled by 2^±1000 and shifted by 2^40..2^52.

use crate::hulls::hulls_intersect;
use polysect::kernel::Kernel;
use polysect::lp::{LpError, LpWorkspace, Separation, separating_line};
use polysect::{Exact, Fast, Orientation, Point};
use rand::rngs::SmallRng;
use rand::seq::SliceRandom;
use rand::{Rng, SeedableRng};

const SEED: u64 = 0x5e1de1;

/// Checks a returned bitangent exactly: a line through two distinct points, A on the
/// closed right, B on the closed left, both tangent points on it.
fn check_bitangent(a: &[Point], b: &[Point], sep: &Separation) -> Result<(), String> {
    let Separation::Separated(t) = sep else {
        return Ok(());
    };
    let k = Exact;
    if t.start == t.end {
        return Err("degenerate line".into());
    }
    if let Some(x) = a
        .iter()
        .find(|&&x| k.orient(t.start, t.end, x) == Orientation::Ccw)
    {
        return Err(format!("A point {x:?} left of the line"));
    }
    if let Some(x) = b
        .iter()
        .find(|&&x| k.orient(t.start, t.end, x) == Orientation::Cw)
    {
        return Err(format!("B point {x:?} right of the line"));
    }
    if k.orient(t.start, t.end, a[t.a]) != Orientation::Collinear {
        return Err("A tangent not on the line".into());
    }
    if k.orient(t.start, t.end, b[t.b]) != Orientation::Collinear {
        return Err("B tangent not on the line".into());
    }
    Ok(())
}

#[derive(Clone, Copy, Debug)]
enum Shape {
    Grid,
    Float,
    Line,
}

fn random_set(rng: &mut SmallRng, shape: Shape, n: usize, offset: Point) -> Vec<Point> {
    let dir = Point::new(rng.random_range(-2..=2) as f64, rng.random_range(-2..=2) as f64);
    (0..n)
        .map(|_| match shape {
            Shape::Grid => Point::new(
                offset.x + rng.random_range(0..=3) as f64,
                offset.y + rng.random_range(0..=3) as f64,
            ),
            Shape::Float => Point::new(
                offset.x + rng.random::<f64>() * 3.0,
                offset.y + rng.random::<f64>() * 3.0,
            ),
            Shape::Line => {
                let t = rng.random_range(0..=4) as f64;
                Point::new(offset.x + t * dir.x, offset.y + t * dir.y)
            }
        })
        .collect()
}

/// A pair of sets with B placed in one of many relative positions around A (including
/// overlapping, exactly adjacent, vertical and horizontal gaps).
fn random_pair(rng: &mut SmallRng) -> (Vec<Point>, Vec<Point>) {
    if rng.random_range(0..4) == 0 {
        return shared_line_pair(rng);
    }
    let shapes = [Shape::Grid, Shape::Grid, Shape::Float, Shape::Line];
    let (sa, sb) = (shapes[rng.random_range(0..4)], shapes[rng.random_range(0..4)]);
    let (na, nb) = (rng.random_range(1..=7), rng.random_range(1..=7));
    let a = random_set(rng, sa, na, Point::new(0.0, 0.0));
    let off = Point::new(rng.random_range(-2..=2) as f64, rng.random_range(-2..=2) as f64);
    let b = random_set(rng, sb, nb, off);
    (a, b)
}

/// Both sets with several points on one common line (so the bitangent often contains
/// two or more points of one set and one of the other), plus a few points off the line,
/// each set mostly on its own side.
fn shared_line_pair(rng: &mut SmallRng) -> (Vec<Point>, Vec<Point>) {
    let dirs = [(1, 0), (0, 1), (1, 1), (1, -1), (2, 1), (-1, 3)];
    let (dx, dy) = dirs[rng.random_range(0..dirs.len())];
    let (dx, dy) = (dx as f64, dy as f64);
    let on = |t: i32| Point::new(t as f64 * dx, t as f64 * dy);
    let off = |t: i32, side: f64| Point::new(t as f64 * dx - side * dy, t as f64 * dy + side * dx);
    let split = rng.random_range(-1..=3);
    let mut a: Vec<Point> = (0..rng.random_range(1..=3))
        .map(|_| on(rng.random_range(-3..=split)))
        .collect();
    let mut b: Vec<Point> = (0..rng.random_range(1..=3))
        .map(|_| on(rng.random_range(split.min(2)..=6)))
        .collect();
    for _ in 0..rng.random_range(0..=3) {
        let side = if rng.random_range(0..6) == 0 { 1.0 } else { -1.0 };
        a.push(off(
            rng.random_range(-4..=4),
            side * rng.random_range(1..=2) as f64,
        ));
    }
    for _ in 0..rng.random_range(0..=3) {
        let side = if rng.random_range(0..6) == 0 { -1.0 } else { 1.0 };
        b.push(off(
            rng.random_range(0..=8),
            side * rng.random_range(1..=2) as f64,
        ));
    }
    if rng.random_bool(0.5) { (a, b) } else { (b, a) }
}

struct Tally {
    cases: usize,
    separated: usize,
    fast_wrong: usize,
}

fn check_pair(a: &[Point], b: &[Point], rng: &mut SmallRng, ws: &mut LpWorkspace, tally: &mut Tally) {
    let truth = hulls_intersect(a, b);
    // Several random orders per pair, both argument orders.
    for _ in 0..3 {
        let got = separating_line(Exact, a, b, rng, ws).unwrap();
        assert_eq!(
            matches!(got, Separation::Intersecting),
            truth,
            "exact verdict differs\nA = {a:?}\nB = {b:?}\ngot {got:?}"
        );
        check_bitangent(a, b, &got).unwrap_or_else(|e| panic!("{e}\nA = {a:?}\nB = {b:?}\n{got:?}"));
        let swapped = separating_line(Exact, b, a, rng, ws).unwrap();
        assert_eq!(
            matches!(swapped, Separation::Intersecting),
            truth,
            "swapped\nA = {a:?}\nB = {b:?}"
        );
        check_bitangent(b, a, &swapped).unwrap();
        assert_eq!(
            ws.redone, 0,
            "exact result failed certification\nA = {a:?}\nB = {b:?}"
        );
        let fast = separating_line(Fast, a, b, rng, ws).unwrap();
        ws.redone = 0;
        if matches!(fast, Separation::Intersecting) != truth {
            tally.fast_wrong += 1;
        }
    }
    tally.cases += 1;
    tally.separated += usize::from(!truth);
}

#[test]
fn random_small_sets_agree_with_brute_force() {
    let mut rng = SmallRng::seed_from_u64(SEED);
    let mut ws = LpWorkspace::new();
    let mut tally = Tally {
        cases: 0,
        separated: 0,
        fast_wrong: 0,
    };
    for _ in 0..20_000 {
        let (a, b) = random_pair(&mut rng);
        check_pair(&a, &b, &mut rng, &mut ws, &mut tally);
    }
    assert_eq!(ws.redone, 0, "exact results must certify themselves");
    println!(
        "lp: {} pairs, {} separable, fast kernel wrong {} of {} calls",
        tally.cases,
        tally.separated,
        tally.fast_wrong,
        3 * tally.cases
    );
    // Both verdicts must be well represented for the test to mean something.
    assert!(tally.separated > tally.cases / 5 && tally.separated < tally.cases * 4 / 5);
}

#[test]
fn hand_picked_relative_positions() {
    let p = |x: f64, y: f64| Point::new(x, y);
    let sq = vec![p(0., 0.), p(1., 0.), p(1., 1.), p(0., 1.)];
    let cases: Vec<(Vec<Point>, bool)> = vec![
        (vec![p(2., 0.), p(3., 1.)], false),              // right, vertical gap
        (vec![p(-2., 0.), p(-3., 1.)], false),            // left
        (vec![p(0., 2.), p(1., 3.)], false),              // above, horizontal gap
        (vec![p(0., -2.), p(1., -3.)], false),            // below
        (vec![p(1., 0.5), p(2., 0.5)], true),             // touches an edge
        (vec![p(1., 1.)], true),                          // a shared vertex
        (vec![p(1.5, 1.5)], false),                       // a single point apart
        (vec![p(0.5, 0.5)], true),                        // a single point inside
        (vec![p(1., 2.), p(1., 3.)], false),              // collinear with an edge, apart
        (vec![p(1., 1.), p(1., 3.)], true),               // collinear, touching
        (vec![p(-1., -1.), p(5., -1.), p(2., 5.)], true), // containment
        (vec![p(1., 0.), p(1., 1.), p(2., 0.), p(2., 1.)], true), // shared edge
    ];
    let mut rng = SmallRng::seed_from_u64(SEED + 1);
    let mut ws = LpWorkspace::new();
    for (b, want) in cases {
        assert_eq!(hulls_intersect(&sq, &b), want, "oracle on {b:?}");
        for _ in 0..20 {
            let got = separating_line(Exact, &sq, &b, &mut rng, &mut ws).unwrap();
            assert_eq!(matches!(got, Separation::Intersecting), want, "{b:?}: {got:?}");
            check_bitangent(&sq, &b, &got).unwrap();
        }
    }
    // Single points only, in every direction, and duplicates within a set.
    for (dx, dy) in [(1., 0.), (-1., 0.), (0., 1.), (0., -1.), (1., 1.), (0., 0.)] {
        let a = vec![p(0., 0.), p(0., 0.)];
        let b = vec![p(dx, dy)];
        let got = separating_line(Exact, &a, &b, &mut rng, &mut ws).unwrap();
        assert_eq!(matches!(got, Separation::Intersecting), dx == 0. && dy == 0.);
        check_bitangent(&a, &b, &got).unwrap();
    }
    let empty: Vec<Point> = Vec::new();
    assert_eq!(
        separating_line(Exact, &empty, &sq, &mut rng, &mut ws),
        Err(LpError::EmptySet)
    );
}

/// Scaling by a power of two and exact integer shifts change no predicate: the exact
/// verdict must not move, at 2^±1000 and at offsets 2^40..2^52.
#[test]
fn extremes_keep_the_exact_verdict() {
    let mut rng = SmallRng::seed_from_u64(SEED + 2);
    let mut ws = LpWorkspace::new();
    let mut fast_wrong = 0;
    let mut calls = 0;
    for _ in 0..3000 {
        let (a, b) = random_pair(&mut rng);
        if a.iter()
            .chain(&b)
            .any(|q| q.x.fract() != 0.0 || q.y.fract() != 0.0)
        {
            continue; // only exactly representable transforms below
        }
        let truth = hulls_intersect(&a, &b);
        let scale = [
            2f64.powi(1000),
            2f64.powi(-1000),
            2f64.powi(600),
            2f64.powi(-1060),
        ][rng.random_range(0..4)];
        let shift = 2f64.powi(rng.random_range(40..=52));
        let maps: [&dyn Fn(Point) -> Point; 3] = [
            &|q: Point| Point::new(q.x * scale, q.y * scale),
            &|q: Point| Point::new(q.x + shift, q.y - shift),
            &|q: Point| Point::new((q.x + shift) * scale, q.y * scale),
        ];
        for f in maps {
            let (fa, fb): (Vec<Point>, Vec<Point>) = (
                a.iter().map(|&q| f(q)).collect(),
                b.iter().map(|&q| f(q)).collect(),
            );
            if fa.iter().chain(&fb).any(|q| !q.is_finite()) {
                continue;
            }
            let got = separating_line(Exact, &fa, &fb, &mut rng, &mut ws).unwrap();
            assert_eq!(
                matches!(got, Separation::Intersecting),
                truth,
                "A = {fa:?}\nB = {fb:?}"
            );
            check_bitangent(&fa, &fb, &got).unwrap();
            calls += 1;
            if matches!(
                separating_line(Fast, &fa, &fb, &mut rng, &mut ws).unwrap(),
                Separation::Intersecting
            ) != truth
            {
                fast_wrong += 1;
            }
        }
    }
    println!("lp extremes: fast kernel wrong {fast_wrong} of {calls}");
    assert!(calls > 1000);
}

/// Larger random sets (up to a few thousand points): exact verdict against the hulls'
/// brute force on a subset is too slow, so compare with a second exact route — the
/// polygon reference `Linear` on the convex hulls.
#[test]
fn large_sets_agree_with_hull_reference() {
    use polysect::intersect::{ArrayIntersection, Linear};
    use polysect::polygon::convex_hull;
    let mut rng = SmallRng::seed_from_u64(SEED + 3);
    let mut ws = LpWorkspace::new();
    let mut checked = 0;
    for round in 0..300 {
        let n = 1 << rng.random_range(3..=11);
        let r = 1.0 + rng.random::<f64>();
        let gen_disc = |rng: &mut SmallRng, c: Point| -> Vec<Point> {
            (0..n)
                .map(|_| {
                    let t = rng.random::<f64>() * std::f64::consts::TAU;
                    let s = rng.random::<f64>().sqrt();
                    Point::new(c.x + s * t.cos(), c.y + s * t.sin())
                })
                .collect()
        };
        let a = gen_disc(&mut rng, Point::new(0.0, 0.0));
        let t = rng.random::<f64>() * std::f64::consts::TAU;
        let b = gen_disc(&mut rng, Point::new(r * t.cos() * 1.2, r * t.sin() * 1.2));
        let (Ok(ha), Ok(hb)) = (convex_hull(&a), convex_hull(&b)) else {
            continue;
        };
        let truth = Linear.intersects(&ha, &hb);
        let got = separating_line(Exact, &a, &b, &mut rng, &mut ws).unwrap();
        assert_eq!(matches!(got, Separation::Intersecting), truth, "round {round}");
        check_bitangent(&a, &b, &got).unwrap();
        checked += 1;
    }
    assert!(checked > 250);
    let _ = Fast.orient(Point::new(0., 0.), Point::new(1., 0.), Point::new(0., 1.));
}

/// The caller-ordered variant (the LP keeps the given order, thesis 3.3.5) gives the
/// same exact verdicts and valid bitangents, on inputs in random and in sorted order
/// (its worst case for the work, never for the answer).
#[test]
fn kept_order_agrees_with_brute_force() {
    let mut rng = SmallRng::seed_from_u64(SEED + 7);
    let mut ws = LpWorkspace::new();
    ws.keep_order(true);
    let mut tally = Tally {
        cases: 0,
        separated: 0,
        fast_wrong: 0,
    };
    for i in 0..5_000 {
        let (mut a, mut b) = random_pair(&mut rng);
        if i % 2 == 0 {
            a.sort_by(|u, v| u.x.total_cmp(&v.x));
            b.sort_by(|u, v| u.y.total_cmp(&v.y));
        }
        check_pair(&a, &b, &mut rng, &mut ws, &mut tally);
    }
    assert_eq!(ws.redone, 0, "exact results must certify themselves");
    assert!(tally.separated > tally.cases / 5 && tally.separated < tally.cases * 4 / 5);
}

/// The one-dimensional step tests each earlier point against the line through the
/// violating point and the tightest bound so far, and classifies only the violators:
/// sets with many points exactly on a common line (ties between bounds, the partner
/// of the other set preferred) and points one ulp to either side of it (the filter's
/// undecided calls, and bounds tighter or looser by one ulp), at an offset of 2^30
/// where an ulp is a visible step, in random and kept order, against the brute force.
#[test]
fn one_ulp_off_the_shared_line_agrees_with_brute_force() {
    let mut rng = SmallRng::seed_from_u64(SEED + 11);
    let mut ws = LpWorkspace::new();
    let mut tally = Tally {
        cases: 0,
        separated: 0,
        fast_wrong: 0,
    };
    let base = 2f64.powi(30);
    for i in 0..4_000 {
        ws.keep_order(i % 2 == 0);
        // The line y = base + s·(x − base) for a small integer slope s, exact at integers.
        let s = rng.random_range(-2..=2) as f64;
        let on = |x: f64| Point::new(base + x, base + s * x);
        let nudge = |q: Point, up: bool| Point::new(q.x, if up { q.y.next_up() } else { q.y.next_down() });
        let split = rng.random_range(-2..=2) as f64;
        let (mut a, mut b) = (Vec::new(), Vec::new());
        for _ in 0..rng.random_range(1..=6) {
            a.push(on(rng.random_range(-6..=0) as f64 + split));
        }
        for _ in 0..rng.random_range(1..=6) {
            b.push(on(rng.random_range(0..=6) as f64 - split.min(0.0)));
        }
        // A mostly below the line, B mostly above, by one ulp or by a unit; now and
        // then a point on the wrong side.
        for _ in 0..rng.random_range(0..=5) {
            let q = on(rng.random_range(-8..=8) as f64);
            let wrong = rng.random_range(0..8) == 0;
            a.push(if rng.random_bool(0.5) {
                nudge(q, wrong)
            } else {
                Point::new(q.x, q.y + if wrong { 1.0 } else { -1.0 })
            });
        }
        for _ in 0..rng.random_range(0..=5) {
            let q = on(rng.random_range(-8..=8) as f64);
            let wrong = rng.random_range(0..8) == 0;
            b.push(if rng.random_bool(0.5) {
                nudge(q, !wrong)
            } else {
                Point::new(q.x, q.y + if wrong { -1.0 } else { 1.0 })
            });
        }
        a.shuffle(&mut rng);
        b.shuffle(&mut rng);
        check_pair(&a, &b, &mut rng, &mut ws, &mut tally);
    }
    assert_eq!(ws.redone, 0, "exact results must certify themselves");
    println!(
        "lp one-ulp: {} pairs, {} separable, fast kernel wrong {} of {} calls",
        tally.cases,
        tally.separated,
        tally.fast_wrong,
        3 * tally.cases
    );
    assert!(tally.separated > tally.cases / 10 && tally.separated < tally.cases * 9 / 10);
}
