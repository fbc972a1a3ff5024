use super::dyadic::*;
use super::interval::*;
use super::out_of_line::*;
use super::semi_static::*;
use super::static_filter::*;
use super::*;
use crate::kernel::sealed::Predicates as _;
use crate::kernel::{
    CrossPoly, CrossProductsPoly, DotPoly, Fast, Kernel, Orientation, Point, Polynomial, Ring, Sign,
};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

/// The exact sign of a degree-4 call, by big integers.
fn exact_products(factors: [[Point; 4]; 4]) -> Sign {
    sign_slow(&CrossProductsPoly(factors))
}

/// The factors of `line_meet_side`'s polynomial for the lines ab, cd and ef.
fn line_meet_factors([a, b, c, d, e, f]: [Point; 6]) -> [[Point; 4]; 4] {
    [[a, b, c, d], [e, f, e, a], [a, c, c, d], [e, f, a, b]]
}

/// A point on (or, rounded, next to) the crossing of the lines ab and cd.
fn crossing(a: Point, b: Point, c: Point, d: Point) -> Point {
    let den = (b.x - a.x) * (d.y - c.y) - (b.y - a.y) * (d.x - c.x);
    let num = (c.x - a.x) * (d.y - c.y) - (c.y - a.y) * (d.x - c.x);
    let t = num / den;
    Point::new(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y))
}

/// `x` moved by `k` ulps.
fn ulps(x: f64, k: i32) -> f64 {
    let mut x = x;
    for _ in 0..k.unsigned_abs() {
        x = if k > 0 { x.next_up() } else { x.next_down() };
    }
    x
}

/// The static filter of `cross_products_sign` never claims a wrong sign, and the
/// whole predicate is exact: random points, nearly parallel lines, a third line
/// through (or one ulp off) the crossing, Chazelle–Dobkin's slope comparisons on grids
/// and on reals, at magnitudes from 2^-600 to 2^600, against big-integer evaluation.
#[test]
fn cross_products_filter_never_claims_a_wrong_sign() {
    let mut rng = SmallRng::seed_from_u64(0x11ee);
    let mut decided = 0;
    for i in 0..40_000 {
        let scale = [
            1.0,
            1e-60,
            1e60,
            1e-140,
            2f64.powi(600),
            2f64.powi(-600),
            2f64.powi(40),
        ][(i / 4) % 7];
        let grid = i % 8 >= 6;
        let mut r = || {
            let (x, y): (f64, f64) = if grid {
                (rng.random_range(-4..=4) as f64, rng.random_range(-4..=4) as f64)
            } else {
                (rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0))
            };
            Point::new(x * scale, y * scale)
        };
        let factors = if i % 2 == 0 {
            // line_meet_side's polynomial.
            let (a, b, c, e) = (r(), r(), r(), r());
            let mut d = r();
            if i % 3 == 0 {
                d = Point::new(c.x + (b.x - a.x) * 1.5, c.y + (b.y - a.y) * 1.5 + scale * 1e-12);
            }
            let x = crossing(a, b, c, d);
            let f = match i % 5 {
                0 => x,
                1 => Point::new(x.x.next_up(), x.y),
                _ => r(),
            };
            line_meet_factors([a, b, c, d, e, f])
        } else {
            // Chazelle–Dobkin's slope comparison with pivot a and direction c1 − c0.
            let (a, c0, c1, u1, u2, v1, v2) = (r(), r(), r(), r(), r(), r(), r());
            [[u1, u2, c0, c1], [a, v1, a, v2], [v2, v1, c0, c1], [a, u1, a, u2]]
        };
        if factors.iter().flatten().any(|p| !p.is_finite()) {
            continue;
        }
        let want = exact_products(factors);
        if let Some(sign) = cross_products_filtered(&factors) {
            decided += 1;
            assert_eq!(sign, want, "{factors:?}");
        }
        assert_eq!(Exact.cross_products_sign(factors), want, "{factors:?}");
    }
    assert!(decided > 15_000, "the filter decides too little: {decided}");
}

/// Every static filter on inputs whose computed value lies within a factor of four
/// of the filter's bound, on both sides: nearly collinear triples, nearly parallel
/// segments, nearly perpendicular ones, a third line nearly through a crossing, each
/// perturbed by up to 60 ulps at offsets up to 2^52. Whenever a filter decides, it
/// is right; both outcomes occur close to the bound, so the bound itself is tested.
#[test]
fn filters_at_their_bound() {
    let mut rng = SmallRng::seed_from_u64(0xb0_0d);
    // [decided, undecided] within a factor of 4 of the bound, per filter.
    let mut near = [[0usize; 2]; 4];
    let mut note = |f: usize, value: f64, bound: f64, decided: bool| {
        if bound.is_finite() && value.abs() > bound / 4.0 && value.abs() < bound * 4.0 {
            near[f][usize::from(!decided)] += 1;
        }
    };
    for i in 0..30_000 {
        let off = 2f64.powi([0, 20, 40, 52][i % 4]);
        let t: f64 = rng.random_range(-2.0..2.0);
        let k = rng.random_range(-60..=60);
        let mut r = || {
            Point::new(
                off + rng.random_range(-1.0..1.0),
                off + rng.random_range(-1.0..1.0),
            )
        };
        let (a, b) = (r(), r());
        // c on the line ab (rounded), moved by k ulps.
        let on = Point::new(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y));
        let c = Point::new(on.x, ulps(on.y, k));
        let left = (a.x - c.x) * (b.y - c.y);
        let right = (a.y - c.y) * (b.x - c.x);
        let got = orient_filtered(a, b, c);
        note(
            0,
            left - right,
            two_products_bound(left, (left - right).abs()),
            got.is_some(),
        );
        if let Some(s) = got {
            assert_eq!(s, sign_slow(&OrientPoly(a, b, c)), "orient {a:?} {b:?} {c:?}");
        }
        // cd nearly parallel to ab.
        let d = Point::new(c.x + (b.x - a.x), ulps(c.y + (b.y - a.y), k / 2));
        let left = (b.x - a.x) * (d.y - c.y);
        let right = (b.y - a.y) * (d.x - c.x);
        let got = cross_filtered(a, b, c, d);
        note(
            1,
            left - right,
            two_products_bound(left, (left - right).abs()),
            got.is_some(),
        );
        if let Some(s) = got {
            assert_eq!(
                s,
                sign_slow(&CrossPoly(a, b, c, d)),
                "cross {a:?} {b:?} {c:?} {d:?}"
            );
        }
        // cd nearly perpendicular to ab.
        let d = Point::new(c.x - (b.y - a.y), ulps(c.y + (b.x - a.x), k / 2));
        let left = (b.x - a.x) * (d.x - c.x);
        let right = (b.y - a.y) * (d.y - c.y);
        let got = dot_filtered(a, b, c, d);
        note(
            2,
            left + right,
            two_products_bound(left, (left + right).abs()),
            got.is_some(),
        );
        if let Some(s) = got {
            assert_eq!(s, sign_slow(&DotPoly(a, b, c, d)), "dot {a:?} {b:?} {c:?} {d:?}");
        }
        // A third line through the crossing of ab and a random cd, moved by k ulps.
        let (c, d, e) = (r(), r(), r());
        let x = crossing(a, b, c, d);
        let f = Point::new(ulps(x.x, k), x.y);
        if !f.is_finite() {
            continue;
        }
        let factors = line_meet_factors([a, b, c, d, e, f]);
        let (s, bound, valid) = cross_products_bounded(&factors);
        let got = cross_products_filtered(&factors);
        note(3, s, if valid { bound } else { f64::INFINITY }, got.is_some());
        if let Some(s) = got {
            assert_eq!(s, exact_products(factors), "{factors:?}");
        }
    }
    for (f, [decided, undecided]) in near.into_iter().enumerate() {
        assert!(
            decided > 50 && undecided > 50,
            "filter {f}: {decided} decided, {undecided} not, near the bound"
        );
    }
}

/// The out-of-line layers, each on inputs that reach it, against big integers:
/// structural zeros, rescaling (2^±600, near `f64::MAX`, subnormals), the adaptive
/// predicate on rescaled near-degenerate input, exact differences for `cross` and
/// `dot`, and the big-integer fallback for inputs spanning more than 2^1022.
#[test]
fn fallback_layers_match_big_integers() {
    let p = Point::new;
    let big = 1e300;
    let tiny = 1e-300;
    // Structural zeros, at any magnitude.
    for s in [1.0, big, tiny, 5e-324, f64::MAX] {
        let (a, b, c) = (p(s, -s), p(-s, 0.0), p(0.0, s));
        assert_eq!(orient_slow(a, a, c), Sign::Zero);
        assert_eq!(orient_slow(a, b, b), Sign::Zero);
        assert_eq!(orient_slow(c, b, c), Sign::Zero);
        assert_eq!(cross_slow(a, a, b, c), Sign::Zero);
        assert_eq!(cross_slow(a, b, a, b), Sign::Zero);
        assert_eq!(cross_slow(a, b, b, a), Sign::Zero);
        assert_eq!(dot_slow(a, b, c, c), Sign::Zero);
        assert_eq!(
            cross_products_slow([[a, a, b, c], [a, b, b, c], [a, b, c, a], [c, c, a, b]]),
            Sign::Zero
        );
    }
    let mut rng = SmallRng::seed_from_u64(0xfa11);
    for i in 0..20_000 {
        // Magnitudes that overflow or underflow the first filter, and scale 1.
        let e = [600, -600, 1000, 1023, -1000, -1060, 0][i % 7];
        let s = 2f64.powi(e / 2) * 2f64.powi(e - e / 2);
        let grid = i % 3 == 0;
        let mut r = || {
            let (x, y): (f64, f64) = if grid {
                (rng.random_range(-3..=3) as f64, rng.random_range(-3..=3) as f64)
            } else {
                (rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0))
            };
            p(x * s, y * s)
        };
        let (a, b, mut c, d) = (r(), r(), r(), r());
        if i % 5 == 0 {
            // Exactly collinear or parallel on the grid, nearly so on reals.
            c = p(a.x + (b.x - a.x) * 0.5, a.y + (b.y - a.y) * 0.5);
        }
        let d_par = p(c.x + (b.x - a.x), c.y + (b.y - a.y));
        if [a, b, c, d, d_par].iter().any(|q| !q.is_finite()) {
            continue;
        }
        assert_eq!(
            orient_slow(a, b, c),
            sign_slow(&OrientPoly(a, b, c)),
            "{a:?} {b:?} {c:?}"
        );
        assert_eq!(Exact.orient(a, b, c), sign_slow(&OrientPoly(a, b, c)).into());
        for d in [d, d_par] {
            assert_eq!(
                cross_slow(a, b, c, d),
                sign_slow(&CrossPoly(a, b, c, d)),
                "{a:?} {b:?} {c:?} {d:?}"
            );
            assert_eq!(
                dot_slow(a, b, c, d),
                sign_slow(&DotPoly(a, b, c, d)),
                "{a:?} {b:?} {c:?} {d:?}"
            );
        }
        let factors = line_meet_factors([a, b, c, d, r(), c]);
        if factors.iter().flatten().all(|q| q.is_finite()) {
            assert_eq!(cross_products_slow(factors), exact_products(factors));
        }
    }
    // Every coordinate at its own magnitude, from subnormal to near f64::MAX: the
    // scaled differences underflow, the coordinates cannot be rescaled exactly.
    for i in 0..20_000 {
        let mut c = || {
            let e = rng.random_range(-1074..1020);
            rng.random_range(-1.0..1.0) * 2f64.powi(e / 2) * 2f64.powi(e - e / 2)
        };
        let (a, b, d) = (p(c(), c()), p(c(), c()), p(c(), c()));
        let t = [0.5, 0.25, 2.0][i % 3];
        let mid = p(a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t);
        let c = if i % 2 == 0 { mid } else { p(c(), c()) };
        if [a, b, c, d, mid].iter().any(|q| !q.is_finite()) {
            continue;
        }
        assert_eq!(
            orient_slow(a, b, c),
            sign_slow(&OrientPoly(a, b, c)),
            "{a:?} {b:?} {c:?}"
        );
        assert_eq!(cross_slow(a, b, c, d), sign_slow(&CrossPoly(a, b, c, d)));
        assert_eq!(dot_slow(a, b, c, d), sign_slow(&DotPoly(a, b, c, d)));
        let factors = line_meet_factors([a, b, c, d, mid, c]);
        assert_eq!(
            cross_products_slow(factors),
            exact_products(factors),
            "{factors:?}"
        );
    }
    // Inputs spanning more than 2^1022 in one call cannot be rescaled: big integers.
    let (a, b) = (p(0.0, 0.0), p(big, tiny));
    assert!(Rescaled::new([a, b, p(2.0 * big, 2.0 * tiny)]).is_none());
    assert_eq!(
        Exact.orient(a, b, p(2.0 * big, 2.0 * tiny)),
        Orientation::Collinear
    );
    assert_eq!(
        Exact.orient(a, b, p(2.0 * big, (2.0 * tiny).next_up())),
        Orientation::Ccw
    );
    assert_eq!(
        Exact.cross(a, b, b, p(2.0 * big, 2.0 * tiny)),
        Orientation::Collinear
    );
    assert_eq!(Exact.dot(a, b, p(0.0, 0.0), p(-tiny, big)), Sign::Zero);
    assert_eq!(
        Exact.dot(a, b, p(0.0, 0.0), p(-tiny, big.next_up())),
        Sign::Positive
    );
}

/// Rescaling is exact, puts the largest magnitude in [1, 2), and refuses what it
/// cannot scale exactly.
#[test]
fn rescaling_is_exact() {
    let p = Point::new;
    for (pts, adaptive) in [
        ([p(3.0, -0.5), p(0.0, 1e-100)], true),
        ([p(f64::MAX, -f64::MAX), p(1e300, 0.0)], true),
        ([p(5e-324, 0.0), p(-1e-310, 3e-320)], true),
        ([p(2f64.powi(600), 1.0), p(0.0, 0.0)], false),
        ([p(1e300, 0.0), p(1e-6, 0.0)], false),
        ([p(1e300, 0.0), p(1e200, 0.0)], true),
    ] {
        let r = Rescaled::new(pts).expect("scalable");
        assert_eq!(r.adaptive, adaptive, "{pts:?}");
        let hi = r
            .points
            .iter()
            .fold(0.0f64, |m, q| m.max(q.x.abs()).max(q.y.abs()));
        assert!((1.0..2.0).contains(&hi), "{pts:?} -> {:?}", r.points);
        // Undo the scaling: the inputs come back bit for bit.
        let k = exponent(pts.iter().fold(0.0f64, |m, q| m.max(q.x.abs()).max(q.y.abs())));
        let back = |v: f64| v * 2f64.powi(k / 2) * 2f64.powi(k - k / 2);
        for (q, s) in pts.iter().zip(r.points) {
            assert_eq!((back(s.x), back(s.y)), (q.x, q.y), "{pts:?}");
        }
    }
    assert!(Rescaled::new([p(0.0, 0.0), p(-0.0, 0.0)]).is_none());
    assert!(Rescaled::new([p(1e300, 0.0), p(1e-300, 0.0)]).is_none());
    assert_eq!(exponent(5e-324), -1074);
    assert_eq!(exponent(f64::MAX), 1023);
    assert_eq!(exponent(1.0), 0);
    assert_eq!(exponent(0.75), -1);
}

/// Every predicate gives the same answer when all its inputs are multiplied by the
/// same power of two, from subnormal to near `f64::MAX`, on nearly degenerate input.
#[test]
fn predicates_are_invariant_under_power_of_two_scaling() {
    let mut rng = SmallRng::seed_from_u64(0x5ca1e);
    for _ in 0..2_000 {
        let mut r = || Point::new(rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0));
        let (a, b, e) = (r(), r(), r());
        let on = Point::new(a.x + 0.3 * (b.x - a.x), a.y + 0.3 * (b.y - a.y));
        let c = Point::new(on.x, on.y.next_up());
        let d = Point::new(c.x + (b.x - a.x), c.y + (b.y - a.y));
        let f = crossing(a, b, c, r());
        let want = (
            Exact.orient(a, b, c),
            Exact.cross(a, b, c, d),
            Exact.dot(a, b, c, d),
            Exact.cross_products_sign(line_meet_factors([a, b, c, r(), e, f])),
        );
        assert_eq!(want.0, sign_slow(&OrientPoly(a, b, c)).into());
        for k in [-1070, -1022, -600, -300, 300, 600, 1000, 1023] {
            let s = |q: Point| {
                Point::new(
                    q.x * 2f64.powi(k / 2) * 2f64.powi(k - k / 2),
                    q.y * 2f64.powi(k / 2) * 2f64.powi(k - k / 2),
                )
            };
            let (sa, sb, sc, sd) = (s(a), s(b), s(c), s(d));
            // Only exact scalings keep the polynomial's sign (subnormal results may round).
            let exact = |q: Point, sq: Point| {
                let u = |v: f64| v * 2f64.powi(-k / 2) * 2f64.powi(-k - (-k) / 2);
                u(sq.x) == q.x && u(sq.y) == q.y && sq.is_finite()
            };
            if !(exact(a, sa) && exact(b, sb) && exact(c, sc) && exact(d, sd)) {
                continue;
            }
            assert_eq!(Exact.orient(sa, sb, sc), want.0, "2^{k}");
            assert_eq!(Exact.cross(sa, sb, sc, sd), want.1, "2^{k}");
            assert_eq!(Exact.dot(sa, sb, sc, sd), want.2, "2^{k}");
        }
    }
}

fn exact_orient(a: Point, b: Point, c: Point) -> Orientation {
    sign_slow(&OrientPoly(a, b, c)).into()
}

#[test]
fn decompose_is_exact() {
    for x in [
        0.0,
        -0.0,
        1.0,
        -1.5,
        f64::MAX,
        f64::MIN_POSITIVE,
        5e-324,
        -5e-324,
        1e300,
        0.1,
    ] {
        let (m, e) = decompose(x);
        assert_eq!(
            (m as f64) * 2f64.powi(e as i32 / 2) * 2f64.powi(e as i32 - e as i32 / 2),
            x
        );
    }
}

#[test]
fn range_limits_are_powers_of_two() {
    assert_eq!(ADAPTIVE_MIN, 2f64.powi(-400));
    assert_eq!(ADAPTIVE_MAX, 2f64.powi(400));
}

#[test]
fn orient_matches_exact_fallback_near_collinear_and_at_extremes() {
    let mut rng = SmallRng::seed_from_u64(0x5eed_0001);
    let scales = [
        1.0,
        2f64.powi(-1000),
        2f64.powi(960),
        2f64.powi(-1070),
        2f64.powi(500),
    ];
    let mut fast_wrong = 0;
    for i in 0..20_000 {
        let s = scales[i % scales.len()];
        // Points on a line y = t·x with a one-ulp perturbation, at a large offset.
        let off = if i % 2 == 0 { 0.0 } else { 2f64.powi(40) };
        let t: f64 = rng.random_range(-2.0..2.0);
        let xs: [f64; 3] = [rng.random(), rng.random(), rng.random()];
        let mut p: Vec<Point> = xs
            .iter()
            .map(|&x| Point::new((x + off) * s, (t * x + off) * s))
            .collect();
        if rng.random_bool(0.5) {
            p[2].y = p[2].y.next_up();
        }
        let want = exact_orient(p[0], p[1], p[2]);
        assert_eq!(Exact.orient(p[0], p[1], p[2]), want, "{p:?}");
        assert_eq!(Exact.orient(p[1], p[0], p[2]), want.reverse());
        if Fast.orient(p[0], p[1], p[2]) != want {
            fast_wrong += 1;
        }
    }
    // The fast kernel is measurably wrong on this family; the exact one never is.
    println!("fast kernel wrong on near-collinear triples: {fast_wrong} of 20000");
    assert!(
        fast_wrong > 100,
        "expected the fast kernel to fail often, got {fast_wrong}"
    );
}

#[test]
fn orient_on_subnormals_and_mixed_magnitudes() {
    let tiny = 5e-324;
    let a = Point::new(0.0, 0.0);
    let b = Point::new(tiny, tiny);
    let c = Point::new(2.0 * tiny, 2.0 * tiny);
    assert_eq!(Exact.orient(a, b, c), Orientation::Collinear);
    let c2 = Point::new(2.0 * tiny, 3.0 * tiny);
    assert_eq!(Exact.orient(a, b, c2), Orientation::Ccw);
    // The fast kernel underflows to zero here.
    assert_eq!(Fast.orient(a, b, c2), Orientation::Collinear);
    let big = f64::MAX;
    let p = Point::new(-big, -big);
    let q = Point::new(big, big);
    let r = Point::new(0.0, 0.0);
    assert_eq!(Exact.orient(p, q, r), Orientation::Collinear);
    assert_eq!(Exact.orient(p, q, Point::new(0.0, tiny)), Orientation::Ccw);
    assert_eq!(Exact.orient(p, q, Point::new(tiny, 0.0)), Orientation::Cw);
}

#[test]
fn interval_filter_never_claims_a_wrong_sign() {
    let mut rng = SmallRng::seed_from_u64(7);
    for i in 0..5_000 {
        let e: i32 = rng.random_range(-1070..1000);
        let s = 2f64.powi(e);
        let mut pts: Vec<Point> = (0..4)
            .map(|_| Point::new(rng.random::<f64>() * s, rng.random::<f64>() * s))
            .collect();
        if i % 3 == 0 {
            // Exactly parallel directions, then nudged by one ulp half of the time.
            pts[3] = Point::new(pts[2].x + (pts[1].x - pts[0].x), pts[2].y + (pts[1].y - pts[0].y));
            if i % 2 == 0 {
                pts[3].y = pts[3].y.next_up();
            }
        }
        let poly = super::super::CrossPoly(pts[0], pts[1], pts[2], pts[3]);
        let exact = poly.eval::<Dyadic>().certain_sign();
        if let Some(s) = poly.eval::<Interval>().certain_sign() {
            assert_eq!(Some(s), exact);
        }
        assert_eq!(Some(Exact.sign(&poly)), exact);
        assert_eq!(
            Some(Exact.cross(pts[0], pts[1], pts[2], pts[3])),
            exact.map(Orientation::from)
        );
        let dot = super::super::DotPoly(pts[0], pts[1], pts[2], pts[3]);
        assert_eq!(
            Some(Exact.dot(pts[0], pts[1], pts[2], pts[3])),
            dot.eval::<Dyadic>().certain_sign()
        );
    }
}

/// The area sign is exact where a plain float sum overflows, underflows or cancels.
#[test]
fn area_sign_is_exact() {
    let p = Point::new;
    let arrow = [p(0., 0.), p(4., 0.), p(4., 4.), p(2., 1.), p(0., 4.)];
    for k in [0, 600, -600, 1021, -1070, -1074] {
        let s = |q: Point| {
            Point::new(
                q.x * 2f64.powi(k / 2) * 2f64.powi(k - k / 2),
                q.y * 2f64.powi(k / 2) * 2f64.powi(k - k / 2),
            )
        };
        let scaled: Vec<Point> = arrow.iter().map(|&q| s(q)).collect();
        if scaled.iter().zip(&arrow).any(|(a, b)| a.x == 0.0 && b.x != 0.0) {
            continue;
        }
        assert_eq!(area_sign(&scaled), Sign::Positive, "2^{k}");
        let mut rev = scaled.clone();
        rev.reverse();
        assert_eq!(area_sign(&rev), Sign::Negative, "2^{k}");
    }
    // A figure eight with equal lobes: area exactly zero.
    let eight = [p(0., 0.), p(1., 1.), p(2., 0.), p(2., 1.), p(1., 0.), p(0., 1.)];
    assert_eq!(area_sign(&eight), Sign::Zero);
    // Cancellation far from the origin: a tiny triangle at 2^60 (the float sum of
    // products of 2^60-sized coordinates loses it entirely).
    let o = 2f64.powi(60);
    let tri = [p(o, o), p(o + 256.0, o), p(o, o + 256.0)];
    assert_eq!(area_sign(&tri), Sign::Positive);
    assert_eq!(area_sign(&[tri[0], tri[2], tri[1]]), Sign::Negative);
    // Mixed magnitudes that cannot be rescaled: the big-integer sum.
    let mixed = [p(0., 0.), p(1e300, 0.), p(1e300, 1e-300), p(0., 1e-300)];
    assert_eq!(area_sign(&mixed), Sign::Positive);
    assert_eq!(area_sign(&mixed[..2]), Sign::Zero);
    // Random polygons: against the exact sum.
    let mut rng = SmallRng::seed_from_u64(0xa4ea);
    for _ in 0..300 {
        let n = rng.random_range(3..40);
        let e = rng.random_range(-1000..1000);
        let pts: Vec<Point> = (0..n)
            .map(|_| {
                p(
                    rng.random_range(-1.0..1.0) * 2f64.powi(e),
                    rng.random_range(-1.0..1.0) * 2f64.powi(e),
                )
            })
            .collect();
        let f = Dyadic::from_f64;
        let exact = (0..n)
            .map(|i| {
                let (a, b) = (pts[i], pts[(i + 1) % n]);
                f(a.x) * f(b.y) - f(a.y) * f(b.x)
            })
            .fold(f(0.0), |acc, t| acc + t)
            .certain_sign()
            .unwrap();
        assert_eq!(area_sign(&pts), exact);
    }
}

/// Differences next to `f64::MAX` beside subnormal ones: the largest difference needs
/// the two-factor scaling down by 2^1023, which must also scale the subnormal ones
/// (found by the fuzz driver: a wrong Chazelle–Dobkin answer and invalid hulls).
#[test]
fn subnormal_differences_beside_f64_max() {
    let p = Point::new;
    let pts = [
        p(-f64::MAX, -5e-324),
        p(1125899906842647.5, -0.0),
        p(1125899906842613.8, 1125899906842602.0),
        p(0.9999999999999999, 1125899906842653.8),
        p(-f64::MAX, 1e-300),
        p(-f64::MAX, 1125899906842634.3),
        p(-80.0, -7.052634219591294e113),
        p(119.0, -80.0),
        p(f64::MAX, 5e-324),
    ];
    let n = pts.len();
    for &a in &pts {
        for &b in &pts {
            for &c in &pts {
                assert_eq!(Exact.orient(a, b, c), exact_orient(a, b, c), "{a:?} {b:?} {c:?}");
                for &d in &pts {
                    let cross: Orientation = sign_slow(&CrossPoly(a, b, c, d)).into();
                    assert_eq!(Exact.cross(a, b, c, d), cross, "{a:?} {b:?} {c:?} {d:?}");
                    let dot = sign_slow(&DotPoly(a, b, c, d));
                    assert_eq!(Exact.dot(a, b, c, d), dot, "{a:?} {b:?} {c:?} {d:?}");
                }
            }
        }
    }
    let mut rng = SmallRng::seed_from_u64(0x5b_a11);
    for _ in 0..20_000 {
        let f: [[Point; 4]; 4] =
            std::array::from_fn(|_| std::array::from_fn(|_| pts[rng.random_range(0..n)]));
        assert_eq!(Exact.cross_products_sign(f), exact_products(f), "{f:?}");
    }
}

/// [`ExactWithin::new`] on boxes written `(min, max)`.
fn ew(boxes: [(Point, Point); 2]) -> ExactWithin {
    ExactWithin::new(boxes.map(|(lo, hi)| crate::BoundingBox::new(lo, hi)))
}

/// The box `(min, max)` of some points.
fn box_of(points: &[Point]) -> (Point, Point) {
    let (mut lo, mut hi) = (points[0], points[0]);
    for p in points {
        lo = Point::new(lo.x.min(p.x), lo.y.min(p.y));
        hi = Point::new(hi.x.max(p.x), hi.y.max(p.y));
    }
    (lo, hi)
}

/// The semi-static filter of [`ExactWithin`], with the box of each call's own points
/// (the tightest box, so the bound is as small as it gets): nearly collinear triples,
/// nearly parallel and nearly perpendicular segments, and a third line through (or a
/// few ulps off) a crossing, perturbed by up to 60 ulps at offsets up to 2^52 and
/// scaled by powers of two from 2^-1074 (subnormal) to 2^1000 (beyond the bounds'
/// ranges). Whenever the semi-static layer decides, it is right; both outcomes occur
/// within a factor of four of the bound; and the kernel as a whole always agrees with
/// big integers.
#[test]
fn semi_static_filter_at_its_bound() {
    let mut rng = SmallRng::seed_from_u64(0x5e_a1);
    // [decided, undecided] within a factor of 4 of the bound, per predicate.
    let mut near = [[0usize; 2]; 4];
    let mut decided_total = 0usize;
    let mut check = |f: usize, value: f64, bound: f64, got: Sign, want: Sign, what: &dyn Fn() -> String| {
        let decided = value > bound || value < -bound;
        if decided {
            decided_total += 1;
            assert_eq!(Sign::of(value), want, "semi-static {f}: {}", what());
        }
        assert_eq!(got, want, "kernel {f}: {}", what());
        if bound.is_finite() && value.abs() > bound / 4.0 && value.abs() < bound * 4.0 {
            near[f][usize::from(!decided)] += 1;
        }
    };
    let scales = [
        0, 0, 0, -1074, -1000, -600, -400, 250, 300, 505, 509, 511, 600, 1000,
    ];
    for i in 0..40_000 {
        let off = 2f64.powi([0, 20, 40, 52][i % 4]);
        let e = scales[(i / 4) % scales.len()];
        let (s1, s2) = (2f64.powi(e / 2), 2f64.powi(e - e / 2));
        let t: f64 = rng.random_range(-2.0..2.0);
        let k = rng.random_range(-60..=60);
        let mut r = || {
            Point::new(
                off + rng.random_range(-1.0..1.0),
                off + rng.random_range(-1.0..1.0),
            )
        };
        let (a, b) = (r(), r());
        let on = Point::new(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y));
        let c = Point::new(on.x, ulps(on.y, k));
        let d1 = Point::new(c.x + (b.x - a.x), ulps(c.y + (b.y - a.y), k / 2));
        let d2 = Point::new(c.x - (b.y - a.y), ulps(c.y + (b.x - a.x), k / 2));
        let (e2, c3, d3) = (r(), r(), r());
        let x = crossing(a, b, c3, d3);
        let f3 = Point::new(ulps(x.x, k), x.y);
        // Scaled by 2^e: exact unless it underflows, and then still a valid input.
        let sc = |p: Point| Point::new(p.x * s1 * s2, p.y * s1 * s2);
        let [a, b, c, d1, d2, e2, c3, d3, f3] = [a, b, c, d1, d2, e2, c3, d3, f3].map(sc);
        if [a, b, c, d1, d2, e2, c3, d3, f3].iter().any(|p| !p.is_finite()) {
            continue;
        }

        let k3 = ew([box_of(&[a, b]), box_of(&[c])]);
        let (l, r) = orient_products(a, b, c);
        let want = sign_slow(&OrientPoly(a, b, c));
        let got = k3.orient(a, b, c);
        check(0, l - r, k3.two, Sign::of(as_value_of(got)), want, &|| {
            format!("orient {a:?} {b:?} {c:?}")
        });
        assert_eq!(k3.orient_of(&a, &b, &c), got, "orient_of {a:?} {b:?} {c:?}");

        let k4 = ew([box_of(&[a, b]), box_of(&[c, d1])]);
        let (l, r) = cross_products(a, b, c, d1);
        let want = sign_slow(&CrossPoly(a, b, c, d1));
        let got = k4.cross(a, b, c, d1);
        check(1, l - r, k4.two, Sign::of(as_value_of(got)), want, &|| {
            format!("cross {a:?} {b:?} {c:?} {d1:?}")
        });

        let k4 = ew([box_of(&[a, b]), box_of(&[c, d2])]);
        let (l, r) = dot_products(a, b, c, d2);
        let want = sign_slow(&DotPoly(a, b, c, d2));
        check(2, l + r, k4.two, k4.dot(a, b, c, d2), want, &|| {
            format!("dot {a:?} {b:?} {c:?} {d2:?}")
        });

        let factors = line_meet_factors([a, b, c3, d3, e2, f3]);
        let k6 = ew([box_of(&[a, b, c3]), box_of(&[d3, e2, f3])]);
        let cr = |[ux, uy, vx, vy]: [f64; 4]| ux * vy - uy * vx;
        let [g0, g1, g2, g3] = factors.map(factor_differences);
        let s = cr(g0) * cr(g1) + cr(g2) * cr(g3);
        let want = exact_products(factors);
        check(3, s, k6.four, k6.cross_products_sign(factors), want, &|| {
            format!("{factors:?}")
        });
    }
    // The degree-4 bound is the loosest (P² for a product of four differences), so
    // fewer of its calls come near it.
    for (f, [decided, undecided]) in near.into_iter().enumerate() {
        let least = if f == 3 { 10 } else { 50 };
        assert!(
            decided > least && undecided > least,
            "predicate {f}: {decided} decided, {undecided} not, near the bound"
        );
    }
    assert!(
        decided_total > 40_000,
        "the semi-static filter decides too little: {decided_total}"
    );
}

fn as_value_of(o: Orientation) -> f64 {
    match o {
        Orientation::Cw => -1.0,
        Orientation::Collinear => 0.0,
        Orientation::Ccw => 1.0,
    }
}

/// The bounds' ranges: boxes whose side is too large or too small for a bound, or not
/// finite, give infinite bounds (every call goes to [`Exact`]); the default too.
#[test]
fn semi_static_bounds_and_their_ranges() {
    let p = Point::new;
    let unit = (p(0.0, 0.0), p(1.0, 1.0));
    let k = ew([unit, unit]);
    assert!(k.two > 0.0 && k.two < 1e-15 && k.four > 0.0 && k.four < 1e-13);
    // The side is the union's: a far box widens it.
    let far = ew([unit, (p(3.0, 0.0), p(4.0, 1.0))]);
    assert!(far.two > 15.0 * k.two && far.four > 200.0 * k.four);
    let d = ExactWithin::default();
    assert!(d.two == f64::INFINITY && d.four == f64::INFINITY);
    // A box that holds a non-finite point has a non-finite corner on that side.
    for bad in [f64::NAN, f64::INFINITY] {
        let b = ew([unit, (p(0.0, 0.0), p(bad, 1.0))]);
        assert!(b.two == f64::INFINITY && b.four == f64::INFINITY, "{bad}");
        let b = ew([(p(-bad, 0.0), p(1.0, 1.0)), unit]);
        assert!(b.two == f64::INFINITY && b.four == f64::INFINITY, "{bad}");
        let b = ew([unit, (p(0.0, -bad), p(1.0, bad))]);
        assert!(b.two == f64::INFINITY && b.four == f64::INFINITY, "{bad}");
    }
    // Side 2^510: P = 2^1020 is the last valid two-product bound; degree 4 stops at 2^125.
    let side = |s: f64| ew([(p(0.0, 0.0), p(s, s)), (p(0.0, 0.0), p(s, s))]);
    assert!(side(2f64.powi(510)).two.is_finite());
    assert_eq!(side(2f64.powi(510).next_up()).two, f64::INFINITY);
    assert!(side(2f64.powi(125)).four.is_finite());
    assert_eq!(side(2f64.powi(125).next_up()).four, f64::INFINITY);
    assert!(side(2f64.powi(-200)).four.is_finite());
    assert_eq!(side(2f64.powi(-200).next_down()).four, f64::INFINITY);
    // Subnormal and zero sides keep a valid (absolute) two-product bound.
    assert_eq!(side(5e-324).two, 2.0 * f64::MIN_POSITIVE);
    assert_eq!(side(0.0).two, 2.0 * f64::MIN_POSITIVE);
    // On a one-point box every orientation is collinear; the kernel still says so.
    let o = p(3.0, 3.0);
    let k = ew([(o, o), (o, o)]);
    assert_eq!(k.orient(o, o, o), Orientation::Collinear);
    // A huge and a tiny box together: the filter steps aside, the answer is exact.
    let (h, t) = (p(1e300, -1e300), p(1e-300, 3e-300));
    let k = ew([(h, h), (p(0.0, 0.0), t)]);
    assert_eq!(k.two, f64::INFINITY);
    assert_eq!(k.orient(h, t, p(0.0, 0.0)), Exact.orient(h, t, p(0.0, 0.0)));
}

/// The fixed rescaling of the out-of-line two-product path: nearly collinear,
/// nearly parallel and nearly perpendicular calls (up to 60 ulps off) and random ones
/// at scales whose products overflow (2^520 … 2^1020) or underflow (2^-520 … 2^-1074,
/// subnormal), with one difference far smaller than the others in some calls (it
/// underflows when scaled down). Whenever it decides, it is right, and it decides
/// most random calls at these scales.
#[test]
fn fixed_rescale_is_exact_where_it_decides() {
    let mut rng = SmallRng::seed_from_u64(0xf1_ed);
    let mut decided = 0;
    let scales = [520, 600, 900, 1000, 1020, -520, -600, -900, -1000, -1074];
    for i in 0..20_000 {
        let e = scales[i % scales.len()];
        let (s1, s2) = (2f64.powi(e / 2), 2f64.powi(e - e / 2));
        let k = rng.random_range(-60..=60);
        let t: f64 = rng.random_range(-2.0..2.0);
        let mut r = || Point::new(rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0));
        let (a, b) = (r(), r());
        let c = match i % 4 {
            0 => Point::new(a.x + t * (b.x - a.x), ulps(a.y + t * (b.y - a.y), k)),
            1 => Point::new(a.x + 1e-200, a.y),
            _ => r(),
        };
        let d = if i % 3 == 0 {
            Point::new(c.x - (b.y - a.y), ulps(c.y + (b.x - a.x), k))
        } else {
            Point::new(c.x + (b.x - a.x), ulps(c.y + (b.y - a.y), k))
        };
        let sc = |p: Point| Point::new(p.x * s1 * s2, p.y * s1 * s2);
        let [a, b, c, d] = [a, b, c, d].map(sc);
        if ![a, b, c, d].iter().all(|p| p.is_finite()) {
            continue;
        }
        let cases = [
            (
                [a.x - c.x, a.y - c.y, b.x - c.x, b.y - c.y],
                false,
                sign_slow(&OrientPoly(a, b, c)),
            ),
            (
                [b.x - a.x, b.y - a.y, d.x - c.x, d.y - c.y],
                false,
                sign_slow(&CrossPoly(a, b, c, d)),
            ),
            (
                [b.x - a.x, b.y - a.y, d.x - c.x, d.y - c.y],
                true,
                sign_slow(&DotPoly(a, b, c, d)),
            ),
        ];
        for (diffs, dot, want) in cases {
            if let Some(s) = fixed_rescale_sign(diffs, dot) {
                decided += 1;
                assert_eq!(s, want, "{a:?} {b:?} {c:?} {d:?} dot: {dot}");
            }
        }
        assert_eq!(Exact.orient(a, b, c), Orientation::from(cases[0].2));
        assert_eq!(Exact.cross(a, b, c, d), Orientation::from(cases[1].2));
        assert_eq!(Exact.dot(a, b, c, d), cases[2].2);
    }
    assert!(decided > 20_000, "decided {decided}");
}

/// [`ExactWithin`]'s degree-4 calls that its semi-static bound cannot decide go to the
/// static filter inline, which must refuse what it cannot vouch for. Here one factor's
/// products underflow to zero (2^-1100) while the other term is tiny but normal
/// (−2^-510): the computed value has the wrong sign and is far outside the bound
/// computed from the magnitudes, so only the filter's range check (every factor's
/// magnitude at least 2^-480) sends the call on to the exact layers. The boxes span
/// 2^300, beyond the semi-static bound's range.
#[test]
fn degree_four_inline_filter_refuses_underflow() {
    let p = Point::new;
    let o = p(0.0, 0.0);
    let (h, t) = (2f64.powi(300), 2f64.powi(-550));
    let (s1, s2) = (2f64.powi(-128), 2f64.powi(-127));
    let factors = [
        [o, p(h, 0.0), o, p(0.0, h)],
        [o, p(t, 0.0), o, p(0.0, t)],
        [o, p(s1, 0.0), o, p(0.0, -s2)],
        [o, p(s1, 0.0), o, p(0.0, s2)],
    ];
    // 2^600 · 2^-1100 − 2^-255 · 2^-255 > 0.
    assert_eq!(exact_products(factors), Sign::Positive);
    let b = (o, p(h, h));
    let k = ew([b, b]);
    assert_eq!(k.four, f64::INFINITY);
    assert_eq!(k.cross_products_sign(factors), Sign::Positive);
    assert_eq!(Exact.cross_products_sign(factors), Sign::Positive);
    // The fast kernel's value has the other sign.
    assert_eq!(super::super::Fast.cross_products_sign(factors), Sign::Negative);
}

/// [`Kernel::cross_of_short_edges`] under [`ExactWithin`]: short, nearly parallel
/// edges (perturbed by up to 60 ulps) inside boxes up to 2^40 times longer, at scales
/// from 2^-1074 to 2^1000 and beside `f64::MAX` (where differences overflow and the
/// bounds are infinite). Its answer is always the big integers' sign; the inline
/// static filter decides calls that the semi-static bound leaves open (the point of
/// the entry), and the [`ShortEdges`](crate::kernel::ShortEdges) wrapper answers
/// `cross` through it and everything else as the kernel it wraps.
#[test]
fn short_edges_cross_at_its_bound() {
    use crate::kernel::ShortEdges;
    let mut rng = SmallRng::seed_from_u64(0x5407_7ed9e);
    let scales = [0, 0, -1074, -1000, -600, 250, 600, 1000];
    let mut inline_decided = 0usize;
    let mut slow = 0usize;
    for i in 0..40_000 {
        let e = scales[i % scales.len()];
        let (s1, s2) = (2f64.powi(e / 2), 2f64.powi(e - e / 2));
        let span = 2f64.powi([0, 10, 20, 40][(i / 8) % 4]);
        let k = rng.random_range(-60..=60);
        let off = Point::new(rng.random_range(-span..span), rng.random_range(-span..span));
        let dir = Point::new(rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0));
        let a = off;
        let b = Point::new(a.x + dir.x, a.y + dir.y);
        let c = Point::new(rng.random_range(-span..span), rng.random_range(-span..span));
        let t: f64 = rng.random_range(0.5..2.0);
        let d = Point::new(c.x + t * dir.x, ulps(c.y + t * dir.y, k));
        let sc = |p: Point| Point::new(p.x * s1 * s2, p.y * s1 * s2);
        let corner = Point::new(span * s1 * s2, span * s1 * s2);
        let [a, b, c, d, corner] = [a, b, c, d, corner].map(sc);
        if [a, b, c, d, corner].iter().any(|p| !p.is_finite()) {
            continue;
        }
        let boxes = [(-corner, corner), box_of(&[a, b, c, d])];
        let kw = ew(boxes);
        let want = sign_slow(&CrossPoly(a, b, c, d));
        let got = kw.cross_of_short_edges(a, b, c, d);
        assert_eq!(Sign::of(as_value_of(got)), want, "{a:?} {b:?} {c:?} {d:?}");
        assert_eq!(got, kw.cross(a, b, c, d));
        assert_eq!(ShortEdges(kw).cross(a, b, c, d), got);
        assert_eq!(ShortEdges(kw).orient(a, b, c), kw.orient(a, b, c));
        let line = crate::kernel::DirectedLine::new(a, b);
        assert_eq!(ShortEdges(kw).orient_line(&line, c), kw.orient(a, b, c));
        assert_eq!(ShortEdges(kw).dot(a, b, c, d), kw.dot(a, b, c, d));
        let (l, r) = cross_products(a, b, c, d);
        let semi = l - r > kw.two || l - r < kw.neg_two;
        if !semi {
            if certain(l - r, l) {
                inline_decided += 1;
            } else {
                slow += 1;
            }
        }
    }
    // Beside f64::MAX the differences overflow: infinite bounds, and the inline
    // filter must refuse (an infinite product of an overflowed difference).
    let m = f64::MAX;
    let (a, b) = (Point::new(-m, 0.0), Point::new(m, 1e-300));
    let (c, d) = (Point::new(0.0, 0.0), Point::new(1e-300, 0.0));
    let kw = ew([(a, b), (c, d)]);
    assert_eq!(kw.two, f64::INFINITY);
    let want = sign_slow(&CrossPoly(a, b, c, d));
    assert_eq!(Sign::of(as_value_of(kw.cross_of_short_edges(a, b, c, d))), want);
    assert!(
        inline_decided > 5_000,
        "inline filter decided only {inline_decided}"
    );
    assert!(slow > 1_000, "too few calls left for the slow path: {slow}");
}

/// [`ExactWithin::for_differences`] ([`Kernel::within_differences`]) on the cross
/// products of two edges: short, nearly parallel edges (perturbed by up to 60 ulps)
/// up to 2^40 of their lengths apart, at scales from 2^-1074 to 2^1000 and beside
/// `f64::MAX`, with `w` the larger of the edges' computed differences (what
/// [`ConvexPolygon::edge_extent`](crate::ConvexPolygon::edge_extent) gives). The
/// answer is always the big integers' sign; the bound scaled to the edges decides many
/// calls, and far more than a bound scaled to the boxes would.
#[test]
fn edge_differences_bound_decides_edges() {
    let mut rng = SmallRng::seed_from_u64(0x0ed9_e005);
    let scales = [0, 0, -1074, -1000, -600, 250, 600, 1000];
    let (mut decided, mut boxes_decided, mut undecided) = (0usize, 0usize, 0usize);
    for i in 0..40_000 {
        let e = scales[i % scales.len()];
        let (s1, s2) = (2f64.powi(e / 2), 2f64.powi(e - e / 2));
        let span = 2f64.powi([0, 10, 20, 40][(i / 8) % 4]);
        let k = rng.random_range(-60..=60);
        let dir = Point::new(rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0));
        let a = Point::new(rng.random_range(-span..span), rng.random_range(-span..span));
        let b = Point::new(a.x + dir.x, a.y + dir.y);
        let c = Point::new(rng.random_range(-span..span), rng.random_range(-span..span));
        let t: f64 = rng.random_range(0.5..2.0);
        let d = Point::new(c.x + t * dir.x, ulps(c.y + t * dir.y, k));
        let sc = |p: Point| Point::new(p.x * s1 * s2, p.y * s1 * s2);
        let [a, b, c, d] = [a, b, c, d].map(sc);
        if [a, b, c, d].iter().any(|p| !p.is_finite()) {
            continue;
        }
        let w = [b.x - a.x, b.y - a.y, d.x - c.x, d.y - c.y]
            .into_iter()
            .fold(0.0f64, |w, x| w.max(x.abs()));
        let kw = Exact.within_differences(w);
        assert_eq!(kw, ExactWithin::for_differences(w));
        let want = sign_slow(&CrossPoly(a, b, c, d));
        let got = kw.cross(a, b, c, d);
        assert_eq!(
            Sign::of(as_value_of(got)),
            want,
            "{a:?} {b:?} {c:?} {d:?} w = {w:e}"
        );
        // A larger `w` is a promise too, and a weaker one.
        assert_eq!(ExactWithin::for_differences(2.0 * w).cross(a, b, c, d), got);
        let (l, r) = cross_products(a, b, c, d);
        if l - r > kw.two || l - r < kw.neg_two {
            decided += 1;
        } else {
            undecided += 1;
        }
        let kb = ew([box_of(&[a, b]), box_of(&[c, d])]);
        if l - r > kb.two || l - r < kb.neg_two {
            boxes_decided += 1;
        }
    }
    assert!(decided > 10_000, "the edges' bound decided only {decided}");
    assert!(undecided > 1_000, "too few calls left undecided: {undecided}");
    assert!(
        decided > 2 * boxes_decided,
        "edges' bound {decided}, boxes' bound {boxes_decided}"
    );
    // Beside f64::MAX: edges of length 2^1000 there (w² overflows: infinite bounds),
    // and an edge whose difference overflows (w infinite).
    let m = f64::MAX;
    let h = 2f64.powi(1000);
    let (a, b) = (Point::new(m - h, m - h), Point::new(m, m - h));
    let (c, d) = (Point::new(m - h, m), Point::new(m, m.next_down()));
    let kw = ExactWithin::for_differences(h);
    assert_eq!(kw.two, f64::INFINITY);
    let want = sign_slow(&CrossPoly(a, b, c, d));
    assert_eq!(Sign::of(as_value_of(kw.cross(a, b, c, d))), want);
    let (e, f) = (Point::new(-m, 0.0), Point::new(m, 1.0));
    let kw = ExactWithin::for_differences(f.x - e.x);
    assert_eq!(kw.two, f64::INFINITY);
    assert_eq!(
        Sign::of(as_value_of(kw.cross(e, f, a, b))),
        sign_slow(&CrossPoly(e, f, a, b))
    );
    // A promise that cannot hold gives infinite bounds.
    for w in [-1.0, f64::NAN, f64::INFINITY] {
        let kw = ExactWithin::for_differences(w);
        assert_eq!((kw.two, kw.four), (f64::INFINITY, f64::INFINITY), "{w}");
    }
}

/// Every pair of edges of two polygons, under [`Kernel::within_differences`] of their
/// larger [`edge_extent`](crate::ConvexPolygon::edge_extent): the big integers' sign,
/// at scales from 2^-1074 to 2^1000 (polygons of 96 vertices on an ellipse, 2^20 of
/// their size apart, so that their edges are short next to their boxes). Where the
/// edges' products stay normal and finite (scales 2^-300 to 2^480) the bound decides
/// nearly every call; elsewhere the bound is infinite or its products underflow, and
/// the exact layers answer.
#[test]
fn polygon_edges_cross_under_their_extent() {
    use crate::ConvexPolygon;
    let mut rng = SmallRng::seed_from_u64(0x0ed9_e006);
    let mut decided = 0usize;
    let mut calls = 0usize;
    for e in [0, -1074, -1000, -600, -300, 250, 480, 600, 1000] {
        let in_range = [0, -300, 250, 480].contains(&e);
        let (s1, s2) = (2f64.powi(e / 2), 2f64.powi(e - e / 2));
        let poly = |cx: f64, rng: &mut SmallRng| {
            let (rx, ry): (f64, f64) = (rng.random_range(1.0..4.0), rng.random_range(1.0..4.0));
            let turn: f64 = rng.random_range(0.0..1.0);
            let pts: Vec<Point> = (0..96)
                .map(|i| {
                    let t = std::f64::consts::TAU * (i as f64 + turn) / 96.0;
                    let p = Point::new(cx + 2f64.powi(20) * rx * t.cos(), 2f64.powi(20) * ry * t.sin());
                    Point::new(p.x * s1 * s2, p.y * s1 * s2)
                })
                .collect();
            ConvexPolygon::new(pts)
        };
        let (Ok(p), Ok(q)) = (poly(0.0, &mut rng), poly(2f64.powi(22), &mut rng)) else {
            continue;
        };
        let (pv, qv) = (p.vertices(), q.vertices());
        let next = |v: &[Point], i: usize| v[(i + 1) % v.len()];
        let largest = |v: &[Point]| {
            (0..v.len())
                .map(|i| {
                    let (a, b) = (v[i], next(v, i));
                    (b.x - a.x).abs().max((b.y - a.y).abs())
                })
                .fold(0.0f64, f64::max)
        };
        assert_eq!(p.edge_extent(), largest(pv));
        assert_eq!(q.edge_extent(), largest(qv));
        let kw = Exact.within_differences(p.edge_extent().max(q.edge_extent()));
        for i in 0..pv.len() {
            for j in 0..qv.len() {
                let (a, b, c, d) = (pv[i], next(pv, i), qv[j], next(qv, j));
                let got = kw.cross(a, b, c, d);
                assert_eq!(
                    Sign::of(as_value_of(got)),
                    sign_slow(&CrossPoly(a, b, c, d)),
                    "2^{e}: {a:?} {b:?} {c:?} {d:?}"
                );
                let (l, r) = cross_products(a, b, c, d);
                if in_range {
                    decided += usize::from(l - r > kw.two || l - r < kw.neg_two);
                    calls += 1;
                }
            }
        }
    }
    assert_eq!(calls, 4 * 96 * 96, "a polygon was refused");
    assert!(
        decided >= calls - calls / 100,
        "the edges' bound decided {decided} of {calls}"
    );
}

/// [`Kernel::cross_products_sign_of_short_edges`] under [`ExactWithin`]: Chazelle–Dobkin's
/// slope comparison of two short edges (the second a copy of the first moved by up to
/// 60 ulps, so that the slopes nearly agree) seen from a pivot, inside boxes up to
/// 2^40 times longer than the edges, at scales from 2^-1074 to 2^1000. Its answer is
/// always the big integers' sign; the edge-scaled bound decides calls that the
/// box-sized bound `B₄` leaves open (the point of the entry), is right whenever it
/// decides, and both outcomes occur within a factor of four of it.
#[test]
fn short_edges_cross_products_at_its_bound() {
    use crate::kernel::ShortEdges;
    let mut rng = SmallRng::seed_from_u64(0x5_10_9e);
    let scales = [0, 0, 0, -1074, -1000, -600, -300, 120, 250, 600, 1000];
    let (mut semi, mut edges, mut slow) = (0usize, 0usize, 0usize);
    let mut near = [0usize; 2];
    let (mut per_query, mut near_query) = (0usize, [0usize; 2]);
    for i in 0..40_000 {
        let e = scales[i % scales.len()];
        let (s1, s2) = (2f64.powi(e / 2), 2f64.powi(e - e / 2));
        let span = 2f64.powi([0, 10, 20, 40][(i / 16) % 4]);
        let k = rng.random_range(-60..=60);
        let mut r = || Point::new(rng.random_range(-span..span), rng.random_range(-span..span));
        let (a, c0, c1, u0) = (r(), r(), r(), r());
        let dir = Point::new(rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0));
        let u1 = Point::new(u0.x + dir.x, u0.y + dir.y);
        let shift = if i % 3 == 0 {
            Point::new(0.0, 0.0)
        } else {
            Point::new(rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0))
        };
        let v0 = Point::new(u0.x + shift.x, ulps(u0.y + shift.y, k));
        let v1 = Point::new(ulps(u1.x + shift.x, k / 2), u1.y + shift.y);
        let sc = |p: Point| Point::new(p.x * s1 * s2, p.y * s1 * s2);
        let corner = Point::new(span * s1 * s2, span * s1 * s2);
        let [a, c0, c1, u0, u1, v0, v1, corner] = [a, c0, c1, u0, u1, v0, v1, corner].map(sc);
        if [a, c0, c1, u0, u1, v0, v1, corner].iter().any(|p| !p.is_finite()) {
            continue;
        }
        let factors = [
            [u0, u1, c0, c1],
            [v0, v1, v0, a],
            [v0, v1, c0, c1],
            [u0, u1, a, u0],
        ];
        let kw = ew([(-corner, corner), box_of(&[a, c0, c1, u0, u1, v0, v1])]);
        let want = exact_products(factors);
        let got = kw.cross_products_sign_of_short_edges(factors);
        assert_eq!(got, want, "{factors:?}");
        assert_eq!(kw.cross_products_sign(factors), want, "{factors:?}");
        assert_eq!(ShortEdges(kw).cross_products_sign_of_short_edges(factors), want);
        assert_eq!(Exact.cross_products_sign_of_short_edges(factors), want);
        // The per-query bound for edges at most `extent` (both short directions' own
        // computed differences, so the call is on the contract's edge), applied once
        // and twice; and a larger promise, which must stay right.
        let extent = [u1.x - u0.x, u1.y - u0.y, v1.x - v0.x, v1.y - v0.y]
            .iter()
            .fold(0.0f64, |w, d| w.max(d.abs()));
        let ke = kw.within_short_edges(|| extent);
        assert!(ke.four <= kw.four || !kw.four.is_finite(), "{factors:?}");
        assert_eq!(ke.four.is_finite(), kw.four.is_finite(), "{factors:?}");
        assert_eq!(
            ke.cross_products_sign_of_short_edges(factors),
            want,
            "{factors:?}"
        );
        let twice = ke.within_short_edges(|| extent);
        assert_eq!(
            twice.cross_products_sign_of_short_edges(factors),
            want,
            "{factors:?}"
        );
        assert_eq!(
            kw.within_short_edges(|| extent * 3.0)
                .cross_products_sign_of_short_edges(factors),
            want
        );
        assert_eq!(kw.within_short_edges(|| -1.0).four.to_bits(), kw.four.to_bits());
        // The same tests as the kernel's, on the same computed values.
        let cr = |[ux, uy, vx, vy]: [f64; 4]| ux * vy - uy * vx;
        let m = |[ux, uy, _, _]: [f64; 4]| ux.abs().max(uy.abs());
        let d = factors.map(factor_differences);
        let s = cr(d[0]) * cr(d[1]) + cr(d[2]) * cr(d[3]);
        let bound = kw.short_edges_bound(m(d[0]) * m(d[1]) + m(d[2]) * m(d[3]));
        assert_eq!(bound.is_finite(), kw.four.is_finite(), "{factors:?}");
        if (s > ke.four || s < ke.neg_four) && !(s > kw.four || s < kw.neg_four) {
            per_query += 1;
            assert_eq!(Sign::of(s), want, "per-query edge bound: {factors:?}");
        }
        if ke.four.is_finite() && s.abs() > ke.four / 4.0 && s.abs() < ke.four * 4.0 {
            near_query[usize::from(s.abs() <= ke.four)] += 1;
        }
        if s > kw.four || s < kw.neg_four {
            semi += 1;
        } else if s > bound || s < -bound {
            edges += 1;
            assert_eq!(Sign::of(s), want, "edge-scaled bound: {factors:?}");
        } else {
            slow += 1;
        }
        if bound.is_finite() && s.abs() > bound / 4.0 && s.abs() < bound * 4.0 {
            near[usize::from(s.abs() <= bound)] += 1;
        }
    }
    assert!(
        edges > 5_000,
        "the edge-scaled bound decided only {edges} ({semi} by B₄)"
    );
    assert!(slow > 1_000, "too few calls left for the slow path: {slow}");
    assert!(near[0] > 50 && near[1] > 50, "near the bound: {near:?}");
    assert!(
        per_query > 5_000,
        "the per-query bound decided only {per_query} beyond B₄"
    );
    assert!(
        near_query[0] > 50 && near_query[1] > 50,
        "near the per-query bound: {near_query:?}"
    );
}
