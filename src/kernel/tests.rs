#[test]
fn point_measures_stay_finite_at_the_extremes() {
    let big = Point::new(1e300, 1e300);
    assert_eq!(big.length(), 1e300 * 2f64.sqrt());
    let tiny = Point::new(3e-320, 4e-320);
    assert!((tiny.length() - 5e-320).abs() <= 1e-323);
    assert_eq!(Point::new(-2.0, 0.0).distance(Point::new(2.0, 3.0)), 5.0);
    // Counter-clockwise is positive, as for `orient`.
    assert!(Point::new(1.0, 0.0).cross(Point::new(0.0, 1.0)) > 0.0);
}

use super::*;
use crate::kernel::sealed::Predicates as _;

#[test]
fn display_is_short_for_every_magnitude() {
    assert_eq!(Point::new(4.5, 2.0).to_string(), "(4.5, 2)");
    assert_eq!(
        Point::new(f64::MAX, -5e-324).to_string(),
        "(1.7976931348623157e308, -5e-324)"
    );
    assert_eq!(Point::new(1e16, 1e-5).to_string(), "(1e16, 0.00001)");
    assert_eq!(Point::new(f64::NAN, f64::NEG_INFINITY).to_string(), "(NaN, -inf)");
    assert_eq!(format!("{:.2}", Point::new(1.0 / 3.0, 2.0)), "(0.33, 2.00)");
    for v in [0.1, 1e300, 3e-320, 123456.789, -0.0] {
        let s = Point::new(v, v).to_string();
        let x: f64 = s[1..s.find(',').unwrap()].parse().unwrap();
        assert_eq!(x.to_bits(), v.to_bits(), "{s}");
    }
}

#[test]
fn cross_and_dot_signs() {
    let o = Point::new(0.0, 0.0);
    let x = Point::new(1.0, 0.0);
    let y = Point::new(0.0, 1.0);
    for k in [Precision::Fast, Precision::Exact] {
        let (c, d) = match k {
            Precision::Fast => (Fast.cross(o, x, o, y), Fast.dot(o, x, o, y)),
            Precision::Exact => (Exact.cross(o, x, o, y), Exact.dot(o, x, o, y)),
        };
        assert_eq!(c, Orientation::Ccw);
        assert_eq!(d, Sign::Zero);
    }
    assert_eq!(Exact.cross(o, y, o, x), Orientation::Cw);
    assert_eq!(Exact.cross(o, x, y, Point::new(2.0, 1.0)), Orientation::Collinear);
    assert_eq!(Exact.dot(o, x, x, o), Sign::Negative);
}

#[test]
fn orient_line_agrees_with_orient() {
    use rand::rngs::SmallRng;
    use rand::{Rng, SeedableRng};
    let mut rng = SmallRng::seed_from_u64(5);
    for _ in 0..20_000 {
        // Nearly collinear triples at various offsets and scales, some exactly on
        // the line, some repeating a point.
        let scale = f64::powi(2.0, rng.random_range(-30..30));
        let off = Point::new(rng.random_range(-1e3..1e3), rng.random_range(-1e3..1e3)) * scale;
        let a = off + Point::new(rng.random::<f64>(), rng.random::<f64>()) * scale;
        let d = Point::new(rng.random::<f64>() - 0.5, rng.random::<f64>() - 0.5) * scale;
        let b = a + d;
        let t = f64::from(rng.random_range(-4..8)) * 0.5;
        let mut c = a + d * t;
        if rng.random_bool(0.5) {
            c.y += c.y * f64::EPSILON * f64::from(rng.random_range(-1..=1));
        }
        let line = DirectedLine::new(a, b);
        let want = Exact.orient(a, b, c);
        assert_eq!(Exact.orient_line(&line, c), want, "{a} {b} {c}");
        let boxed = |p: Point, q: Point, r: Point| {
            let lo = Point::new(p.x.min(q.x).min(r.x), p.y.min(q.y).min(r.y));
            let hi = Point::new(p.x.max(q.x).max(r.x), p.y.max(q.y).max(r.y));
            BoundingBox::new(lo, hi)
        };
        let k = Exact.within([boxed(a, b, c), boxed(a, b, c)]);
        assert_eq!(k.orient_line(&line, c), want, "{a} {b} {c}");
        assert_eq!(Fast.orient_line(&line, c), Fast.orient(a, b, c));
    }
}

#[test]
fn line_meet_side_signs() {
    let p = |x: f64, y: f64| Point::new(x, y);
    // Lines y = 0 and x = 1 meet at (1, 0).
    let (l1, l2) = ((p(0., 0.), p(2., 0.)), (p(1., -1.), p(1., 3.)));
    for (ef, want) in [
        ((p(0., 1.), p(3., 1.)), Orientation::Cw),
        ((p(3., -1.), p(0., -1.)), Orientation::Cw),
        ((p(0., -1.), p(3., -1.)), Orientation::Ccw),
        ((p(0., -1.), p(2., 1.)), Orientation::Collinear),
    ] {
        assert_eq!(line_meet_side(Exact, l1, l2, ef), want);
        assert_eq!(line_meet_side(Exact, l2, l1, ef), want);
        assert_eq!(line_meet_side(Fast, (l1.1, l1.0), l2, ef), want);
    }
    assert_eq!(
        line_meet_side(Exact, l1, (p(0., 1.), p(1., 1.)), l2),
        Orientation::Collinear
    );
}

#[test]
fn precision_names_round_trip() {
    for p in Precision::ALL {
        assert_eq!(p.name().parse::<Precision>(), Ok(p));
    }
    assert!("double".parse::<Precision>().unwrap_err().contains("fast, exact"));
}
