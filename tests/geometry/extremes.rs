//! Every algorithm (array and linked) × both kernels at the extremes of f64: coordinates near f64::MAX and
//! f64::MIN_POSITIVE, subnormals, unit-size polygons offset by 2^52, 2^22-vertex polygons
//! and triangles against them. Under the exact kernel every algorithm must equal the
//! reference; under the fast kernel nothing may panic (wrong answers are counted).

use polysect::generate::{self, Family, Relation, map_pair};
use polysect::intersect::{
    Algorithm, ArrayIntersection, Clm, ClmWorkspace, Convert, ConvertWorkspace, Linear, LinkedIntersection,
    brute_force,
};
use polysect::{ConvexPolygon, Exact, Fast, LinkedPolygon, Point, Precision};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

type Pair = (ConvexPolygon, ConvexPolygon);

fn check_all(pair: &Pair, what: &str, fast_wrong: &mut usize, total: &mut usize) {
    let mut rng = SmallRng::seed_from_u64(pair.0.len() as u64 ^ (pair.1.len() as u64) << 32);
    let linked = (
        LinkedPolygon::from_convex_shuffled(&pair.0, &mut rng),
        LinkedPolygon::from_convex_shuffled(&pair.1, &mut rng),
    );
    check_all_linked(
        (&pair.0, &pair.1),
        (&linked.0, &linked.1),
        what,
        fast_wrong,
        total,
    );
}

/// Every array algorithm on `pair`, and the linked algorithms on `linked` (the same
/// polygons linked in a shuffled arena order, built once by the caller: linking is O(n)).
fn check_all_linked(
    pair: (&ConvexPolygon, &ConvexPolygon),
    linked: (&LinkedPolygon, &LinkedPolygon),
    what: &str,
    fast_wrong: &mut usize,
    total: &mut usize,
) {
    let (p, q) = pair;
    let (lp, lq) = linked;
    // The reference itself (its fast kernel is measured in tests/geometry/reference.rs).
    let truth = Linear.intersects(p, q);
    for &algorithm in Algorithm::LOGARITHMIC {
        assert_eq!(
            algorithm.intersects(Precision::Exact, p, q),
            truth,
            "{algorithm} exact: {what}"
        );
        assert_eq!(
            algorithm.intersects(Precision::Exact, q, p),
            truth,
            "{algorithm} exact swapped: {what}"
        );
        *total += 1;
        if algorithm.intersects(Precision::Fast, p, q) != truth {
            *fast_wrong += 1;
        }
    }
    let mut rng = SmallRng::seed_from_u64(0x11c);
    let (mut clm_ws, mut convert_ws) = (ClmWorkspace::default(), ConvertWorkspace::default());
    for _ in 0..3 {
        assert_eq!(
            Clm.intersects_with_workspace(Exact, lp, lq, &mut rng, &mut clm_ws),
            truth,
            "clm exact: {what}"
        );
        assert_eq!(
            Clm.intersects_with_workspace(Exact, lq, lp, &mut rng, &mut clm_ws),
            truth,
            "clm exact swapped: {what}"
        );
        *total += 1;
        if Clm.intersects_with_workspace(Fast, lp, lq, &mut rng, &mut clm_ws) != truth {
            *fast_wrong += 1;
        }
    }
    // Convert walks both lists (seconds at 2^22 in a shuffled arena): big inputs run it
    // once per test, in the pairs of two big polygons.
    if lp.len().min(lq.len()) < 1 << 20 && lp.len().max(lq.len()) >= 1 << 20 {
        return;
    }
    let convert = <Convert>::default();
    assert_eq!(
        convert.intersects_with_workspace(Exact, lp, lq, &mut rng, &mut convert_ws),
        truth,
        "convert: {what}"
    );
    *total += 1;
    if convert.intersects_with_workspace(Fast, lp, lq, &mut rng, &mut convert_ws) != truth {
        *fast_wrong += 1;
    }
}

/// Touching and one-step-apart pairs on integer coordinates (below 2^36), which the maps
/// below carry into extreme ranges exactly.
fn lattice_pairs(rng: &mut SmallRng, count: usize) -> Vec<Pair> {
    const LATTICE: [Family; 4] = [
        Family::SharedVertex,
        Family::VertexOnEdge,
        Family::SharedEdge,
        Family::OverlappingEdges,
    ];
    (0..count)
        .map(|i| {
            let family = LATTICE[i % LATTICE.len()];
            let relation = if i % 2 == 0 {
                Relation::Intersecting
            } else {
                Relation::Disjoint
            };
            generate::pair(family, 3 + i % 40, relation, rng)
        })
        .collect()
}

#[test]
fn near_max_min_positive_and_subnormal() {
    let mut rng = SmallRng::seed_from_u64(0xe7);
    let (mut wrong, mut total) = (0, 0);
    for base in lattice_pairs(&mut rng, 200) {
        let truth = brute_force(Exact, &base.0, &base.1);
        // The largest power of two that keeps every coordinate finite: up near f64::MAX.
        let largest = base
            .0
            .vertices()
            .iter()
            .chain(base.1.vertices())
            .map(|v| v.x.abs().max(v.y.abs()))
            .fold(0.0, f64::max);
        let up = 2f64.powi(1022 - largest.log2().ceil() as i32);
        let scales = [
            ("near f64::MAX", up),
            ("2^-1022", 2f64.powi(-1022)),
            ("subnormal 2^-1074", 2f64.powi(-1074)),
        ];
        for (name, s) in scales {
            let Some(pair) = map_pair(&base, |p| Point::new(p.x * s, p.y * s)) else {
                continue;
            };
            if s == up {
                assert!(largest * s > 2f64.powi(1021), "reaches near f64::MAX");
            }
            check_all(&pair, name, &mut wrong, &mut total);
            assert_eq!(
                Linear.intersects(&pair.0, &pair.1),
                truth,
                "scaling by {name} changed the answer"
            );
        }
    }
    println!("fast kernel wrong at the extremes of the exponent range: {wrong}/{total}");
}

#[test]
fn unit_polygons_offset_by_2_pow_52() {
    let mut rng = SmallRng::seed_from_u64(0x52);
    let (mut wrong, mut total) = (0, 0);
    let o = 2f64.powi(52);
    for base in lattice_pairs(&mut rng, 200) {
        let truth = brute_force(Exact, &base.0, &base.1);
        // Integer coordinates below 2^51 stay exact next to 2^52 (spacing 1 or ½ there).
        if let Some(pair) = map_pair(&base, |p| Point::new(p.x + o, p.y - o)) {
            check_all(&pair, "offset 2^52", &mut wrong, &mut total);
            assert_eq!(Linear.intersects(&pair.0, &pair.1), truth);
        }
    }
    // Random unit-size polygons at 2^52: rounding makes them lattice polygons of spacing 1.
    for _ in 0..100 {
        let (p, q) = generate::pair(Family::Rotated, 12, Relation::Any, &mut rng);
        let big = |c: &ConvexPolygon| c.map(|v| Point::new(o + (v.x * 8.0).round(), o + (v.y * 8.0).round()));
        if let (Ok(p), Ok(q)) = (big(&p), big(&q)) {
            let pair = (p, q);
            assert_eq!(
                Linear.intersects(&pair.0, &pair.1),
                brute_force(Exact, &pair.0, &pair.1)
            );
            check_all(&pair, "random at 2^52", &mut wrong, &mut total);
        }
    }
    println!("fast kernel wrong at offset 2^52: {wrong}/{total}");
}

#[test]
fn polygons_of_2_pow_22_vertices_and_triangles_against_them() {
    let big = generate::regular_polygon(1 << 22, 1.0);
    let mut rng = SmallRng::seed_from_u64(0x22);
    let big_linked = LinkedPolygon::from_convex_shuffled(&big, &mut rng);
    let (mut wrong, mut total) = (0, 0);
    for (dx, what) in [(1.9, "two 2^22-gons overlapping"), (2.1, "two 2^22-gons apart")] {
        let other = big.map(|v| Point::new(v.x + dx, v.y)).unwrap();
        let other_linked = LinkedPolygon::from_convex_shuffled(&other, &mut rng);
        check_all_linked(
            (&big, &other),
            (&big_linked, &other_linked),
            what,
            &mut wrong,
            &mut total,
        );
    }
    for i in 0..16 {
        let t: f64 = rng.random_range(0.0..std::f64::consts::TAU);
        // Triangles hugging the circle from outside, across it, and just inside.
        let r = [1.0 + 1e-9, 1.0, 1.0 - 1e-12, 1.001][i % 4];
        let (x, y) = (r * t.cos(), r * t.sin());
        let (dx, dy) = (t.cos() * 1e-6, t.sin() * 1e-6);
        let tri =
            ConvexPolygon::new([[x, y], [x + dx - dy, y + dy + dx], [x + dx + dy, y + dy - dx]]).unwrap();
        let tri_linked = LinkedPolygon::from_convex(&tri);
        check_all_linked(
            (&big, &tri),
            (&big_linked, &tri_linked),
            "triangle against a 2^22-gon",
            &mut wrong,
            &mut total,
        );
    }
    println!("fast kernel wrong on 2^22-vertex polygons: {wrong}/{total}");
}
