//! The shape constructors (`ConvexPolygon::rectangle`, `oriented_rectangle`, `regular`,
//! `circle`, `hull_of` and their `LinkedPolygon` twins): every invalid parameter is a
//! `BadParameter` naming it; every polygon produced is strictly convex (checked exactly)
//! with the vertex count asked for, at every scale from subnormal to near `f64::MAX`;
//! the vertices are where the definition puts them (up to the rounding of a sine, a
//! cosine, a product and a sum); the circle's vertex count is the least that meets the
//! tolerance, checked against the gap formula computed another way.

use polysect::polygon::convex_hull;
use polysect::{ConvexPolygon, LinkedPolygon, Point, PolygonError};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use std::f64::consts::{PI, TAU};

const SEED: u64 = 0x5_4a9e;

/// Values no finite parameter accepts.
const NOT_FINITE: [f64; 3] = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY];
/// Values no size accepts: the non-finite ones, zero of either sign, negatives.
const NOT_POSITIVE: [f64; 8] = [
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    0.0,
    -0.0,
    -1.0,
    -f64::MIN_POSITIVE,
    -f64::MAX,
];

/// Asserts that `result` is a `BadParameter` naming `parameter`, and that its message
/// says so.
fn assert_bad<T: std::fmt::Debug>(result: Result<T, PolygonError>, parameter: &str, context: &str) {
    match result {
        Err(e @ PolygonError::BadParameter { .. }) => {
            let PolygonError::BadParameter {
                parameter: got,
                ref reason,
            } = e
            else {
                unreachable!()
            };
            assert_eq!(got, parameter, "{context}: wrong parameter named ({reason})");
            assert!(!reason.is_empty(), "{context}: empty reason");
            assert!(
                e.to_string().contains(&format!("`{parameter}`")),
                "{context}: message {e} does not name {parameter}"
            );
        }
        other => panic!("{context}: expected BadParameter for {parameter}, got {other:?}"),
    }
}

fn valid(p: &ConvexPolygon, expected: usize, context: &str) {
    p.debug_validate().unwrap_or_else(|e| panic!("{context}: {e}"));
    assert_eq!(p.len(), expected, "{context}: vertex count");
}

#[test]
fn rectangle_refuses_every_invalid_parameter() {
    for bad in NOT_FINITE {
        for (min, max, name) in [
            ([bad, 0.0], [1.0, 1.0], "min"),
            ([0.0, bad], [1.0, 1.0], "min"),
            ([0.0, 0.0], [bad, 1.0], "max"),
            ([0.0, 0.0], [1.0, bad], "max"),
        ] {
            assert_bad(
                ConvexPolygon::rectangle(min, max),
                name,
                &format!("{min:?} {max:?}"),
            );
            assert_bad(
                LinkedPolygon::rectangle(min, max),
                name,
                &format!("linked {min:?} {max:?}"),
            );
        }
    }
    // Zero width, zero height, a point, reversed corners in either coordinate or both.
    for (min, max) in [
        ([0.0, 0.0], [0.0, 1.0]),
        ([0.0, 0.0], [1.0, 0.0]),
        ([2.0, 3.0], [2.0, 3.0]),
        ([1.0, 0.0], [0.0, 1.0]),
        ([0.0, 1.0], [1.0, 0.0]),
        ([1.0, 1.0], [0.0, 0.0]),
        ([-0.0, 0.0], [0.0, 1.0]),
    ] {
        assert_bad(
            ConvexPolygon::rectangle(min, max),
            "max",
            &format!("{min:?} {max:?}"),
        );
    }
}

#[test]
fn rectangle_is_exact_at_every_scale() {
    let mut rng = SmallRng::seed_from_u64(SEED);
    for _ in 0..2000 {
        let e = rng.random_range(-320..=300);
        let scale = 10f64.powi(e);
        let lo = Point::new(
            rng.random_range(-1.0..1.0) * scale,
            rng.random_range(-1.0..1.0) * scale,
        );
        let hi = Point::new(
            lo.x + rng.random_range(0.0..2.0) * scale,
            lo.y + rng.random_range(0.0..2.0) * scale,
        );
        let r = ConvexPolygon::rectangle(lo, hi);
        if hi.x > lo.x && hi.y > lo.y {
            let r = r.unwrap_or_else(|e| panic!("{lo} {hi}: {e}"));
            valid(&r, 4, &format!("{lo} {hi}"));
            assert_eq!(
                r.vertices(),
                [lo, Point::new(hi.x, lo.y), hi, Point::new(lo.x, hi.y)]
            );
            assert_eq!((r.bounding_box().min, r.bounding_box().max), (lo, hi));
        } else {
            // The sum rounded back onto the corner (subnormal and huge scales).
            assert_bad(r, "max", &format!("{lo} {hi}"));
        }
    }
    // The extremes of f64: the whole finite plane is a rectangle.
    let whole = ConvexPolygon::rectangle([-f64::MAX, -f64::MAX], [f64::MAX, f64::MAX]).unwrap();
    valid(&whole, 4, "the whole plane");
    let tiny = ConvexPolygon::rectangle([0.0, 0.0], [f64::from_bits(1), f64::from_bits(1)]).unwrap();
    valid(&tiny, 4, "one subnormal step");
}

#[test]
fn oriented_rectangle_refuses_every_invalid_parameter() {
    for bad in NOT_FINITE {
        assert_bad(
            ConvexPolygon::oriented_rectangle([bad, 0.0], [1.0, 1.0], 0.0),
            "centre",
            "x",
        );
        assert_bad(
            ConvexPolygon::oriented_rectangle([0.0, bad], [1.0, 1.0], 0.0),
            "centre",
            "y",
        );
        assert_bad(
            ConvexPolygon::oriented_rectangle([0.0, 0.0], [1.0, 1.0], bad),
            "angle",
            "angle",
        );
        assert_bad(
            LinkedPolygon::oriented_rectangle([0.0, 0.0], [1.0, 1.0], bad),
            "angle",
            "linked",
        );
    }
    for bad in NOT_POSITIVE {
        assert_bad(
            ConvexPolygon::oriented_rectangle([0.0, 0.0], [bad, 1.0], 0.0),
            "half_extents",
            "w",
        );
        assert_bad(
            ConvexPolygon::oriented_rectangle([0.0, 0.0], [1.0, bad], 0.0),
            "half_extents",
            "h",
        );
    }
    // Corners beyond f64::MAX.
    assert_bad(
        ConvexPolygon::oriented_rectangle([f64::MAX, 0.0], [f64::MAX, 1.0], 0.0),
        "half_extents",
        "overflow",
    );
    assert_bad(
        ConvexPolygon::oriented_rectangle([0.0, 0.0], [f64::MAX, f64::MAX], 0.5),
        "half_extents",
        "overflow on turning",
    );
    // Too small for its position: all four corners round onto the centre, or two pairs
    // onto each other.
    assert_bad(
        ConvexPolygon::oriented_rectangle([1e20, 1e20], [1.0, 1.0], 0.3),
        "half_extents",
        "collapse",
    );
    assert_bad(
        ConvexPolygon::oriented_rectangle([1e20, 1e20], [1e6, 1.0], 0.0),
        "half_extents",
        "sliver",
    );
}

/// `p − c` turned by `−angle`.
fn unturn(p: Point, c: Point, angle: f64) -> Point {
    let (s, co) = angle.sin_cos();
    let (dx, dy) = (p.x - c.x, p.y - c.y);
    Point::new(co * dx + s * dy, -s * dx + co * dy)
}

#[test]
fn oriented_rectangle_is_strictly_convex_and_where_it_should_be() {
    let mut rng = SmallRng::seed_from_u64(SEED + 1);
    let mut built = 0;
    for round in 0..4000 {
        let size = 10f64.powi(rng.random_range(-300..=300));
        // The centre sometimes far out relative to the size (where rounding may collapse).
        let offset =
            (size * 10f64.powi(rng.random_range(-3..=if round % 4 == 0 { 20 } else { 3 }))).min(1e307);
        let c = Point::new(
            rng.random_range(-1.0..1.0) * offset,
            rng.random_range(-1.0..1.0) * offset,
        );
        let (w, h) = (
            rng.random_range(0.01..1.0) * size,
            rng.random_range(0.01..1.0) * size,
        );
        let angle = rng.random_range(-10.0..10.0);
        let context = format!("centre {c} half extents {w} {h} angle {angle}");
        match ConvexPolygon::oriented_rectangle(c, [w, h], angle) {
            Ok(r) => {
                built += 1;
                valid(&r, 4, &context);
                // Rounding of the corners, then of the check's own arithmetic.
                let err = 8.0 * f64::EPSILON * (c.x.abs().max(c.y.abs()) + w + h);
                for (v, (a, b)) in
                    r.vertices()
                        .iter()
                        .zip([(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)])
                {
                    let u = unturn(*v, c, angle);
                    assert!(
                        (u.x - a * w).abs() <= err && (u.y - b * h).abs() <= err,
                        "{context}: corner {v} unturned {u}"
                    );
                }
                assert!(r.contains_point(c), "{context}: centre outside");
            }
            Err(e) => {
                // Only when the size is small against the centre.
                assert!(offset > size * 1e6, "{context}: refused at a moderate scale: {e}");
                assert_bad(Err::<(), _>(e), "half_extents", &context);
            }
        }
    }
    assert!(built > 3000, "only {built} rectangles built");
}

#[test]
fn regular_refuses_every_invalid_parameter() {
    for n in 0..3 {
        assert_bad(
            ConvexPolygon::regular([0.0, 0.0], 1.0, n, 0.0),
            "n",
            &format!("n = {n}"),
        );
        assert_bad(
            LinkedPolygon::regular([0.0, 0.0], 1.0, n, 0.0),
            "n",
            &format!("linked n = {n}"),
        );
    }
    for bad in NOT_FINITE {
        assert_bad(ConvexPolygon::regular([bad, 0.0], 1.0, 5, 0.0), "centre", "x");
        assert_bad(ConvexPolygon::regular([0.0, bad], 1.0, 5, 0.0), "centre", "y");
        assert_bad(ConvexPolygon::regular([0.0, 0.0], 1.0, 5, bad), "phase", "phase");
    }
    for bad in NOT_POSITIVE {
        assert_bad(
            ConvexPolygon::regular([0.0, 0.0], bad, 5, 0.0),
            "radius",
            "radius",
        );
    }
    // Overflowing vertices.
    assert_bad(
        ConvexPolygon::regular([f64::MAX, 0.0], f64::MAX, 5, 0.0),
        "n",
        "overflow",
    );
    // Far more vertices than f64 separates: refused before allocating them.
    assert_bad(
        ConvexPolygon::regular([0.0, 0.0], 1.0, usize::MAX, 0.0),
        "n",
        "usize::MAX",
    );
    assert_bad(ConvexPolygon::regular([0.0, 0.0], 1.0, 1 << 40, 0.0), "n", "2^40");
    // Vertices rounding onto one another near a far centre.
    assert_bad(
        ConvexPolygon::regular([1e20, -1e20], 1.0, 8, 0.0),
        "n",
        "far centre",
    );
    assert_bad(
        ConvexPolygon::regular([1e6, 0.0], 1e-6, 1000, 0.0),
        "n",
        "turns lost",
    );
    // The smallest radius: coordinates −1, 0 or 1 times the smallest subnormal, a 3 × 3
    // grid holding no strictly convex 12-gon.
    assert_bad(
        ConvexPolygon::regular([0.0, 0.0], f64::from_bits(1), 12, 0.0),
        "n",
        "subnormal",
    );
}

#[test]
fn regular_is_strictly_convex_with_n_vertices_at_every_scale() {
    let mut rng = SmallRng::seed_from_u64(SEED + 2);
    let mut built = 0;
    let mut refused = 0;
    for round in 0..3000 {
        let r = 10f64.powi(rng.random_range(-300..=306)) * rng.random_range(1.0..1.5);
        let offset = (r * 10f64.powi(rng.random_range(-3..=if round % 3 == 0 { 18 } else { 2 }))).min(1e307);
        let c = Point::new(
            rng.random_range(-1.0..1.0) * offset,
            rng.random_range(-1.0..1.0) * offset,
        );
        let n = match rng.random_range(0..4) {
            0 => rng.random_range(3..10),
            1 => rng.random_range(10..100),
            2 => rng.random_range(100..2000),
            _ => 1 << rng.random_range(2..15),
        };
        let phase = rng.random_range(-TAU..TAU);
        let context = format!("centre {c} radius {r} n {n} phase {phase}");
        match ConvexPolygon::regular(c, r, n, phase) {
            Ok(p) => {
                built += 1;
                valid(&p, n, &context);
                // The coordinates' rounding, and the angle's (of magnitude up to |phase| + 2π).
                let err = 8.0 * f64::EPSILON * (c.x.abs().max(c.y.abs()) + r)
                    + 4.0 * f64::EPSILON * r * (phase.abs() + TAU);
                for (i, v) in p.vertices().iter().enumerate() {
                    let a = phase + TAU * i as f64 / n as f64;
                    let ideal = Point::new(c.x + r * a.cos(), c.y + r * a.sin());
                    assert!(
                        (v.x - ideal.x).abs() <= err && (v.y - ideal.y).abs() <= err,
                        "{context}: vertex {i} at {v}, ideal {ideal}"
                    );
                }
                let linked = LinkedPolygon::regular(c, r, n, phase).unwrap();
                let points: Vec<Point> = linked.iter().map(|(_, q)| q).collect();
                assert_eq!(points, p.vertices(), "{context}: the linked twin differs");
            }
            Err(e) => {
                refused += 1;
                // At a centre within 100 radii and a count of a few thousand f64 has
                // room to spare, except where the radius is subnormal.
                assert!(
                    offset > r * 1e6 || r < 1e-290,
                    "{context}: refused at a moderate scale: {e}"
                );
                assert_bad(Err::<(), _>(e), "n", &context);
            }
        }
    }
    assert!(built > 2000 && refused > 50, "built {built}, refused {refused}");
}

/// The largest distance from the circle of radius `r` to its inscribed regular n-gon,
/// `r·(1 − cos(π/n))`, directly (valid where the subtraction loses nothing that matters).
fn gap(r: f64, n: usize) -> f64 {
    r * (1.0 - (PI / n as f64).cos())
}

#[test]
fn circle_has_the_fewest_vertices_that_meet_the_tolerance() {
    let mut rng = SmallRng::seed_from_u64(SEED + 3);
    for _ in 0..3000 {
        let r = 10f64.powi(rng.random_range(-200..=200)) * rng.random_range(1.0..10.0);
        // Relative tolerances from 1e-7 (about 8,000 vertices) up to beyond the triangle's.
        let tolerance = r * 10f64.powf(rng.random_range(-7.0..0.5));
        let c = Point::new(rng.random_range(-3.0..3.0) * r, rng.random_range(-3.0..3.0) * r);
        let context = format!("centre {c} radius {r} tolerance {tolerance}");
        let p = ConvexPolygon::circle(c, r, tolerance).unwrap_or_else(|e| panic!("{context}: {e}"));
        let n = p.len();
        p.debug_validate().unwrap_or_else(|e| panic!("{context}: {e}"));
        // Within the tolerance (up to rounding), and one vertex fewer would not be.
        assert!(
            gap(r, n) <= tolerance * (1.0 + 1e-6),
            "{context}: {n} vertices leave {}",
            gap(r, n)
        );
        if n > 3 {
            assert!(
                gap(r, n - 1) > tolerance * (1.0 - 1e-6),
                "{context}: {} vertices would do ({})",
                n - 1,
                gap(r, n - 1)
            );
        }
        // It is the regular polygon of that count from angle 0, inside the circle.
        assert_eq!(p, ConvexPolygon::regular(c, r, n, 0.0).unwrap(), "{context}");
        for v in p.vertices() {
            assert!(
                v.distance(c) <= r * (1.0 + 1e-12),
                "{context}: {v} outside the circle"
            );
        }
    }
}

#[test]
fn circle_refuses_every_invalid_parameter() {
    for bad in NOT_FINITE {
        assert_bad(ConvexPolygon::circle([bad, 0.0], 1.0, 0.1), "centre", "x");
        assert_bad(ConvexPolygon::circle([0.0, bad], 1.0, 0.1), "centre", "y");
    }
    for bad in NOT_POSITIVE {
        assert_bad(ConvexPolygon::circle([0.0, 0.0], bad, 0.1), "radius", "radius");
        assert_bad(
            ConvexPolygon::circle([0.0, 0.0], 1.0, bad),
            "tolerance",
            "tolerance",
        );
        assert_bad(LinkedPolygon::circle([0.0, 0.0], 1.0, bad), "tolerance", "linked");
    }
    // Finer than f64 resolves on the circle: refused, not allocated.
    for tolerance in [f64::from_bits(1), 1e-300, 1e-40, 1e-20] {
        assert_bad(
            ConvexPolygon::circle([0.0, 0.0], 1.0, tolerance),
            "tolerance",
            &format!("{tolerance}"),
        );
    }
    // A coarse tolerance is a triangle, however coarse.
    for tolerance in [0.5, 1.0, 1e300, f64::MAX] {
        assert_eq!(
            ConvexPolygon::circle([0.0, 0.0], 1.0, tolerance).unwrap().len(),
            3
        );
    }
}

#[test]
fn hull_of_is_the_hull_and_refuses_what_the_hull_refuses() {
    let mut rng = SmallRng::seed_from_u64(SEED + 4);
    for _ in 0..500 {
        let k = rng.random_range(3..60);
        let pts: Vec<Point> = (0..k)
            .map(|_| Point::new(rng.random_range(-8..8) as f64, rng.random_range(-8..8) as f64))
            .collect();
        let ours = ConvexPolygon::hull_of(pts.iter().copied());
        let reference = convex_hull(&pts);
        assert_eq!(ours, reference, "{pts:?}");
        if let Ok(h) = ours {
            h.debug_validate().unwrap();
            assert!(pts.iter().all(|&p| h.contains_point(p)));
            let linked = LinkedPolygon::hull_of(pts.iter().copied()).unwrap();
            assert_eq!(linked.len(), h.len());
        }
    }
    assert!(matches!(
        ConvexPolygon::hull_of([[0.0, 0.0], [1.0, f64::NAN], [2.0, 0.0]]),
        Err(PolygonError::NonFinite { index: 1, .. })
    ));
    assert!(matches!(
        ConvexPolygon::hull_of([[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]]),
        Err(PolygonError::AllCollinear)
    ));
    assert!(matches!(
        ConvexPolygon::hull_of([[1.0, 1.0], [1.0, 1.0], [2.0, 2.0]]),
        Err(PolygonError::TooFewVertices { distinct: 2 })
    ));
    assert!(matches!(
        ConvexPolygon::hull_of(Vec::<Point>::new()),
        Err(PolygonError::TooFewVertices { distinct: 0 })
    ));
}

/// Numbers in error messages print in their shortest round-trip form (`-1e308`, not the
/// 309 digits of its decimal expansion), so a message stays readable at any scale.
#[test]
fn error_messages_print_numbers_shortest() {
    let err = ConvexPolygon::regular((0.0, 0.0), -1e308, 5, 0.0)
        .unwrap_err()
        .to_string();
    assert!(err.contains("-1e308"), "{err}");
    assert!(err.len() < 120, "{err}");
    let err = ConvexPolygon::circle((0.0, 0.0), 1.0, -5e-324)
        .unwrap_err()
        .to_string();
    assert!(err.contains("-5e-324"), "{err}");
    let err = polysect::generate::try_regular_polygon(5, -1e300)
        .unwrap_err()
        .to_string();
    assert!(err.contains("-1e300"), "{err}");
}
