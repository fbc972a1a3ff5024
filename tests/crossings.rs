//! Crossing points of simple polygons: the sweep against the brute-force reference
//! on random and degenerate pairs, an independent oracle for the points that are
//! input vertices, the error bound of constructed crossings, and invalid input.

use num_bigint::{BigInt, Sign as BigSign};
use num_traits::Zero;
use polysect::crossings::{
    Brute, CrossingAlgorithm, Crossings, ListSweep, Sweep, SweepWorkspace, TreeSweep, crossing_point,
};
use polysect::generate::simple::{PointDistribution, SimpleMethod, random_simple_polygon};
use polysect::kernel::{SegmentContact, point_on_segment, segment_contact};
use polysect::{Exact, Fast, Kernel, Point, Precision, SimplePolygon, SimplePolygonError};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

const SEED_RANDOM: u64 = 0x5eed_0003;
const SEED_GRID: u64 = 0x6e1d;
const SEED_BOUND: u64 = 0xb0b0;

fn poly(v: &[[f64; 2]]) -> SimplePolygon {
    SimplePolygon::new(v.iter().copied()).unwrap()
}

fn p(x: f64, y: f64) -> Point {
    Point::new(x, y)
}

/// The sweep (and each of the two sweeps it chooses between) and the brute force
/// under the exact kernel, required equal; returns the points.
fn agree(a: &SimplePolygon, b: &SimplePolygon) -> Vec<Point> {
    let sweep = Sweep.crossings(a, b);
    let brute = Brute.crossings(a, b);
    for (name, got) in [
        ("sweep", &sweep),
        ("list sweep", &ListSweep.crossings(a, b)),
        ("tree sweep", &TreeSweep.crossings(a, b)),
    ] {
        assert_eq!(
            got,
            &brute,
            "{name} != brute for\nP = {:?}\nQ = {:?}",
            a.vertices(),
            b.vertices()
        );
    }
    // Sorted, distinct, no negative zero.
    assert!(sweep.windows(2).all(|w| w[0].lex_cmp(w[1]).is_lt()));
    assert!(sweep.iter().all(|q| q.x.is_sign_positive() || q.x != 0.0));
    sweep
}

fn on_boundary(poly: &SimplePolygon, v: Point) -> bool {
    (0..poly.len()).any(|i| {
        let (a, b) = poly.edge(i);
        point_on_segment(Exact, a, b, v)
    })
}

/// An oracle independent of the pair routine: the reported input vertices are
/// exactly the vertices of either polygon that lie on the other's boundary, and the
/// other points are as many as the edge pairs that cross properly.
fn check_oracle(a: &SimplePolygon, b: &SimplePolygon, got: &[Point]) {
    let mut vertex_points: Vec<Point> = a
        .vertices()
        .iter()
        .filter(|&&v| on_boundary(b, v))
        .chain(b.vertices().iter().filter(|&&v| on_boundary(a, v)))
        .map(|v| p(v.x + 0.0, v.y + 0.0))
        .collect();
    vertex_points.sort_by(|x, y| x.lex_cmp(*y));
    vertex_points.dedup();
    let is_vertex = |q: &Point| vertex_points.binary_search_by(|v| v.lex_cmp(*q)).is_ok();
    let reported_vertices: Vec<Point> = got.iter().copied().filter(|q| is_vertex(q)).collect();
    assert_eq!(
        reported_vertices,
        vertex_points,
        "vertex points\nP = {:?}\nQ = {:?}",
        a.vertices(),
        b.vertices()
    );
    let crossings = (0..a.len())
        .flat_map(|i| (0..b.len()).map(move |j| (i, j)))
        .filter(|&(i, j)| {
            let (p1, p2) = a.edge(i);
            let (q1, q2) = b.edge(j);
            segment_contact(Exact, p1, p2, q1, q2) == SegmentContact::Crossing
        })
        .count();
    assert_eq!(got.len() - reported_vertices.len(), crossings);
}

#[test]
fn sweep_equals_brute_force_on_random_pairs() {
    let mut rng = SmallRng::seed_from_u64(SEED_RANDOM);
    let dists = [
        PointDistribution::Uniform { min: 0.0, max: 10.0 },
        PointDistribution::Uniform { min: 0.0, max: 500.0 },
        PointDistribution::Normal {
            mean: 0.0,
            sigma: 10.0,
        },
        PointDistribution::Normal {
            mean: 0.0,
            sigma: 100.0,
        },
    ];
    let mut ws = SweepWorkspace::default();
    let mut buf = Vec::new();
    let mut total_points = 0;
    // (pairs, smallest n, largest n): mostly small, a few up to 2,000 vertices.
    for (pairs, lo, hi) in [(3000, 3, 40), (150, 40, 400), (6, 1000, 2001)] {
        for i in 0..pairs {
            let method = SimpleMethod::ALL[i % 2];
            let dist = dists[rng.random_range(0..dists.len())];
            let n = rng.random_range(lo..hi);
            let m = rng.random_range(lo..hi);
            let a = random_simple_polygon(method, dist, n, &mut rng).unwrap();
            let b =
                random_simple_polygon(SimpleMethod::ALL[rng.random_range(0..2)], dist, m, &mut rng).unwrap();
            let got = agree(&a, &b);
            if hi <= 40 {
                check_oracle(&a, &b, &got);
                // Random real inputs are far from degenerate: the fast kernel agrees.
                assert_eq!(Sweep.crossings_with(Fast, &a, &b), got);
            }
            // Swapping the polygons or reversing one changes nothing.
            Sweep.crossings_in(Exact, &b.reversed(), &a, &mut ws, &mut buf);
            assert_eq!(buf.len(), got.len());
            total_points += got.len();
        }
    }
    assert!(total_points > 10_000, "{total_points}");
}

/// Two polygons on one small integer grid: equal x everywhere, vertical edges,
/// shared vertices, vertices on edges, collinear overlaps.
fn grid_pair(rng: &mut SmallRng) -> (SimplePolygon, SimplePolygon) {
    let size = rng.random_range(3..10u32);
    let cap = ((size * size) as usize / 2).clamp(4, 30);
    let dist = PointDistribution::Grid { size };
    let one = |rng: &mut SmallRng| {
        let n = rng.random_range(3..cap);
        let method = SimpleMethod::ALL[rng.random_range(0..2)];
        random_simple_polygon(method, dist, n, rng).unwrap()
    };
    (one(rng), one(rng))
}

#[test]
fn sweep_equals_brute_force_on_grid_pairs() {
    let mut rng = SmallRng::seed_from_u64(SEED_GRID);
    let (mut shared, mut overlaps, mut crossings) = (0, 0, 0);
    for _ in 0..3000 {
        let (a, b) = grid_pair(&mut rng);
        let got = agree(&a, &b);
        check_oracle(&a, &b, &got);
        shared += a.vertices().iter().filter(|v| b.vertices().contains(v)).count();
        overlaps += (0..a.len())
            .flat_map(|i| (0..b.len()).map(move |j| (i, j)))
            .filter(|&(i, j)| {
                let (p1, p2) = a.edge(i);
                let (q1, q2) = b.edge(j);
                segment_contact(Exact, p1, p2, q1, q2) == SegmentContact::Overlapping
            })
            .count();
        crossings += got.len();
        // The fast kernel never panics; on small integers it is exact too.
        assert_eq!(CrossingAlgorithm::Sweep.run(Precision::Fast, &a, &b), got);
    }
    // The family really is degenerate.
    assert!(
        shared > 1000 && overlaps > 1000 && crossings > 10_000,
        "{shared} {overlaps} {crossings}"
    );
}

#[test]
fn identical_reversed_translated_and_rotated_copies() {
    let mut rng = SmallRng::seed_from_u64(SEED_GRID + 1);
    for _ in 0..400 {
        let (a, _) = grid_pair(&mut rng);
        // Identical (and reversed): every vertex is an overlap end, nothing else.
        let mut verts = a.vertices().to_vec();
        verts.sort_by(|x, y| x.lex_cmp(*y));
        assert_eq!(agree(&a, &a), verts);
        assert_eq!(agree(&a, &a.reversed()), verts);
        // Translated by a lattice step, rotated by 90° about a lattice point, reflected.
        let dx = rng.random_range(-2..3) as f64;
        let dy = rng.random_range(-2..3) as f64;
        for b in [
            a.map(|v| p(v.x + dx, v.y + dy)).unwrap(),
            a.map(|v| p(4.0 - v.y, v.x)).unwrap(),
            a.map(|v| p(6.0 - v.x, v.y)).unwrap(),
        ] {
            let got = agree(&a, &b);
            check_oracle(&a, &b, &got);
        }
    }
}

#[test]
fn nested_and_disjoint_pairs_have_no_points() {
    let mut rng = SmallRng::seed_from_u64(SEED_RANDOM + 1);
    let dist = PointDistribution::Uniform { min: -1.0, max: 1.0 };
    let mut nested = 0;
    for _ in 0..300 {
        let n = rng.random_range(3..200);
        let a = random_simple_polygon(SimpleMethod::Star, dist, n, &mut rng).unwrap();
        // Far to the right (the x-ranges do not even overlap), and straight above
        // (the x-ranges overlap, the y-ranges do not).
        for b in [
            a.map(|v| p(v.x + 3.0, v.y)).unwrap(),
            a.map(|v| p(v.x, v.y + 2.5)).unwrap(),
        ] {
            assert!(agree(&a, &b).is_empty());
        }
        // Shrunk towards the centre of a star-shaped polygon: strictly inside.
        let inner = a.map(|v| p(v.x * 0.5, v.y * 0.5)).unwrap();
        // The centre (0, 0) is strictly inside when every angular gap is below π.
        let v = a.vertices();
        let contains_center = (0..v.len())
            .all(|i| Exact.orient(p(0., 0.), v[i], v[(i + 1) % v.len()]) == polysect::Orientation::Ccw);
        if contains_center {
            assert!(agree(&a, &inner).is_empty(), "{:?}", a.vertices());
            nested += 1;
        }
    }
    assert!(nested > 100, "{nested}");
}

#[test]
fn hand_made_degenerate_cases() {
    let square = poly(&[[0., 0.], [4., 0.], [4., 4.], [0., 4.]]);
    let cases: Vec<(SimplePolygon, Vec<Point>)> = vec![
        // Vertex on vertex (corner to corner).
        (poly(&[[4., 4.], [6., 4.], [6., 6.]]), vec![p(4., 4.)]),
        // Vertex on an edge, from outside.
        (poly(&[[4., 2.], [6., 0.], [6., 4.]]), vec![p(4., 2.)]),
        // Vertex on an edge, from above; and a vertex of the square on Q's edge.
        (poly(&[[2., 4.], [3., 5.], [1., 5.]]), vec![p(2., 4.)]),
        (poly(&[[3., 5.], [5., 3.], [6., 6.]]), vec![p(4., 4.)]),
        // Shared edge part (collinear overlap) with a crossing elsewhere.
        (
            poly(&[[1., 0.], [3., 0.], [3., 6.], [2., 2.]]),
            vec![p(1., 0.), p(2.5, 4.), p(3., 0.), p(3., 4.)],
        ),
        // An edge overlapping beyond both ends of the square's edge.
        (poly(&[[-1., 4.], [5., 4.], [2., 6.]]), vec![p(0., 4.), p(4., 4.)]),
        // Vertical edges along the square's vertical edges, on equal x.
        (poly(&[[0., 1.], [0., 3.], [-2., 2.]]), vec![p(0., 1.), p(0., 3.)]),
        (poly(&[[4., -1.], [4., 5.], [5., 2.]]), vec![p(4., 0.), p(4., 4.)]),
        // Proper crossings only.
        (
            poly(&[[-1., 1.], [5., 1.], [5., 3.], [-1., 3.]]),
            vec![p(0., 1.), p(0., 3.), p(4., 1.), p(4., 3.)],
        ),
        // Nested and disjoint.
        (poly(&[[1., 1.], [2., 1.], [1., 2.]]), vec![]),
        (poly(&[[5., 5.], [6., 5.], [5., 6.]]), vec![]),
    ];
    for (q, want) in cases {
        assert_eq!(agree(&square, &q), want, "{:?}", q.vertices());
        let mut back = agree(&q, &square);
        back.sort_by(|a, b| a.lex_cmp(*b));
        assert_eq!(back, want);
        check_oracle(&square, &q, &want);
    }
    // Two combs, one with vertical teeth and one with horizontal teeth: many events
    // share each x, and every tooth crosses every tooth.
    let mut vertical = vec![[0.0, 0.0]];
    for i in 0..10 {
        let x = 2.0 * i as f64;
        vertical.extend([[x + 1.0, 0.0], [x + 1.0, 20.0], [x + 2.0, 20.0], [x + 2.0, 0.0]]);
    }
    vertical.extend([[21.0, 0.0], [21.0, -1.0], [0.0, -1.0]]);
    let v = poly(&vertical);
    let h = v.map(|q| p(q.y + 0.5, q.x + 0.5)).unwrap();
    let got = agree(&v, &h);
    check_oracle(&v, &h, &got);
    // 20 vertical tooth edges (x = 1..20) each cross the 19 horizontal tooth edges
    // at y = 1.5..19.5 (the one at 20.5 passes above the vertical teeth).
    assert!(got.len() >= 20 * 19, "{}", got.len());
}

#[test]
fn extreme_scales_and_offsets() {
    let mut rng = SmallRng::seed_from_u64(SEED_GRID + 2);
    for _ in 0..300 {
        let (a, b) = grid_pair(&mut rng);
        let base = agree(&a, &b);
        for e in [-1000, -500, 500, 1000] {
            let s = 2f64.powi(e);
            let f = |v: Point| p(v.x * s, v.y * s);
            let (fa, fb) = (a.map(f).unwrap(), b.map(f).unwrap());
            let got = agree(&fa, &fb);
            // The fast kernel overflows or underflows here; it must still answer
            // with finite points and no panic.
            for alg in CrossingAlgorithm::ALL {
                assert!(alg.run(Precision::Fast, &fa, &fb).iter().all(|q| q.is_finite()));
            }
            // Scaling by a power of two is exact, and so is the construction's response to it.
            let scaled: Vec<Point> = base.iter().map(|&v| f(v)).collect();
            assert_eq!(got, scaled, "2^{e}");
        }
        let o = 2f64.powi(40);
        let f = |v: Point| p(v.x + o, v.y - o);
        let (fa, fb) = (a.map(f).unwrap(), b.map(f).unwrap());
        let got = agree(&fa, &fb);
        assert_eq!(got.len(), base.len());
        check_oracle(&fa, &fb, &got);
    }
}

/// A finite `f64` times 2^1074: an integer, exactly (every finite `f64` is a
/// multiple of 2^-1074). Independent of the library's own dyadic arithmetic.
fn fixed(x: f64) -> BigInt {
    let bits = x.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i64;
    let frac = (bits & ((1u64 << 52) - 1)) as i64;
    let (m, e) = if biased == 0 {
        (frac, 0)
    } else {
        (frac | (1 << 52), biased - 1)
    };
    let v = BigInt::from(m) << e as usize;
    if bits >> 63 == 1 { -v } else { v }
}

/// True when `got` is the exact coordinate `num / den` rounded to the nearest `f64`
/// (ties to even); `num / den` in units of 2^-1074.
fn rounds_to(num: &BigInt, den: &BigInt, got: f64) -> bool {
    let (num, den) = if den.sign() == BigSign::Minus {
        (-num, -den)
    } else {
        (num.clone(), den.clone())
    };
    // Midpoints below and above `got`, in units of 2^-1075.
    let lo = fixed(got.next_down()) + fixed(got);
    let hi = fixed(got) + fixed(got.next_up());
    let x2 = num << 1usize; // the exact value in units of 2^-1075, times den
    let even = got.to_bits() & 1 == 0;
    let above_lo = match x2.cmp(&(lo * &den)) {
        std::cmp::Ordering::Greater => true,
        std::cmp::Ordering::Equal => even,
        std::cmp::Ordering::Less => false,
    };
    let below_hi = match x2.cmp(&(hi * &den)) {
        std::cmp::Ordering::Less => true,
        std::cmp::Ordering::Equal => even,
        std::cmp::Ordering::Greater => false,
    };
    above_lo && below_hi
}

/// Checks `crossing_point` on segments a→b and c→e (which must not be parallel)
/// against the exact rational crossing, in every argument order.
fn assert_correctly_rounded(a: Point, b: Point, c: Point, e: Point) {
    let (ax, ay, bx, by) = (fixed(a.x), fixed(a.y), fixed(b.x), fixed(b.y));
    let (cx, cy, ex, ey) = (fixed(c.x), fixed(c.y), fixed(e.x), fixed(e.y));
    let (dx, dy) = (&bx - &ax, &by - &ay);
    let den = &dx * (&ey - &cy) - &dy * (&ex - &cx);
    assert!(!den.is_zero(), "parallel: {a:?} {b:?} {c:?} {e:?}");
    let num = (&cx - &ax) * (&ey - &cy) - (&cy - &ay) * (&ex - &cx);
    // x = a + (num / den)·d, in units of 2^-1074: (a·den + num·d) / den.
    let xn = &ax * &den + &num * &dx;
    let yn = &ay * &den + &num * &dy;
    for got in [
        crossing_point(a, b, c, e),
        crossing_point(b, a, c, e),
        crossing_point(e, c, a, b),
        crossing_point(c, e, b, a),
    ] {
        assert!(
            rounds_to(&xn, &den, got.x) && rounds_to(&yn, &den, got.y),
            "{got:?} is not the rounded crossing of {a:?} {b:?} {c:?} {e:?}"
        );
    }
}

/// Crossings of the needle, near-parallel, extreme-scale and tie families, and of
/// ordinary random segments, checked against exact rational arithmetic
/// (`POLYSECT_ROUNDING_CASES` per family, default 3,000).
#[test]
fn constructed_crossings_are_correctly_rounded() {
    use polysect::generate::hard::{HardFamily, hard_pair};
    let cases: usize = std::env::var("POLYSECT_ROUNDING_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(3000);
    let mut rng = SmallRng::seed_from_u64(SEED_BOUND);
    let pt = |rng: &mut SmallRng, r: f64| p(rng.random_range(-r..r), rng.random_range(-r..r));
    let crossing = |a, b, c, e| segment_contact(Exact, a, b, c, e) == SegmentContact::Crossing;
    // Ordinary segments.
    let mut tested = 0;
    while tested < cases {
        let (a, b, c, e) = (
            pt(&mut rng, 1e3),
            pt(&mut rng, 1e3),
            pt(&mut rng, 1e3),
            pt(&mut rng, 1e3),
        );
        if crossing(a, b, c, e) {
            assert_correctly_rounded(a, b, c, e);
            tested += 1;
        }
    }
    // Nearly parallel: e − c is b − a turned by an angle down to 10^-15.
    tested = 0;
    while tested < cases {
        let (a, b) = (pt(&mut rng, 1e3), pt(&mut rng, 1e3));
        let mid = p((a.x + b.x) / 2.0, (a.y + b.y) / 2.0);
        let eps = 10f64.powi(-rng.random_range(3..16));
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        let (c, e) = (
            p(mid.x - dx - eps * dy, mid.y - dy + eps * dx),
            p(mid.x + dx + eps * dy, mid.y + dy - eps * dx),
        );
        if crossing(a, b, c, e) {
            assert_correctly_rounded(a, b, c, e);
            tested += 1;
        }
    }
    // Needles: every crossing pair of two needle combs (angles near 10^-6).
    tested = 0;
    while tested < cases {
        let (pp, qq) = hard_pair(HardFamily::Needles, 60, &mut rng);
        for i in 0..pp.len() {
            for j in 0..qq.len() {
                let ((a, b), (c, e)) = (pp.edge(i), qq.edge(j));
                if crossing(a, b, c, e) {
                    assert_correctly_rounded(a, b, c, e);
                    tested += 1;
                }
            }
        }
    }
    // Extreme scales: ordinary and nearly parallel crossings scaled by 2^k, from the
    // subnormal range to near f64::MAX, and pairs mixing a tiny and a huge segment.
    tested = 0;
    while tested < cases {
        let (mut a, mut b, mut c, mut e) = (
            pt(&mut rng, 1.0),
            pt(&mut rng, 1.0),
            pt(&mut rng, 1.0),
            pt(&mut rng, 1.0),
        );
        let k = rng.random_range(-1070..1020);
        let s = |v: Point, k: i32| {
            p(
                v.x * 2f64.powi(k / 2) * 2f64.powi(k - k / 2),
                v.y * 2f64.powi(k / 2) * 2f64.powi(k - k / 2),
            )
        };
        if tested % 3 == 0 {
            // One segment near the origin at a tiny scale crossing a long one.
            let t = rng.random_range(-1070..-200);
            a = s(a, t);
            b = p(-a.x, -a.y);
            (c, e) = (s(c, k.max(-900)), s(e, k.max(-900)));
            c = p(-c.x.abs() - 1e-300, c.y);
            e = p(e.x.abs() + 1e-300, -c.y);
        } else {
            (a, b, c, e) = (s(a, k), s(b, k), s(c, k), s(e, k));
        }
        if [a, b, c, e].iter().all(|v| v.is_finite()) && crossing(a, b, c, e) {
            assert_correctly_rounded(a, b, c, e);
            tested += 1;
        }
    }
    // Exact ties: crossings exactly halfway between two neighbouring f64 values.
    for k in [-1074, -1022, -600, 0, 1, 52, 600, 970] {
        let one = 2f64.powi(k / 2) * 2f64.powi(k - k / 2);
        if one == 0.0 || !one.is_finite() {
            continue;
        }
        let next = one.next_up();
        // The segment from (next, -one) to (one, one) crosses y = 0 at the midpoint of
        // one and next: a tie, to the one whose last bit is 0.
        let (a, b) = (p(-one, 0.0), p(4.0 * one, 0.0));
        let (c, e) = (p(next, -one), p(one, one));
        if crossing(a, b, c, e) {
            assert_correctly_rounded(a, b, c, e);
            let even = if one.to_bits() & 1 == 0 { one } else { next };
            assert_eq!(crossing_point(a, b, c, e), p(even, 0.0));
        }
    }
}

/// Points reported by the algorithms on random and adversarial pairs are the rounded
/// exact crossings of their edge pairs, and independent of the polygons' order and
/// orientation.
#[test]
fn reported_crossings_are_correctly_rounded() {
    use polysect::generate::hard::{HardFamily, hard_pair};
    let mut rng = SmallRng::seed_from_u64(SEED_BOUND + 1);
    let mut checked = 0;
    for i in 0..60 {
        let (a, b) = if i % 2 == 0 {
            let dist = PointDistribution::Uniform { min: 0.0, max: 100.0 };
            (
                random_simple_polygon(SimpleMethod::SpacePartition, dist, 40, &mut rng).unwrap(),
                random_simple_polygon(SimpleMethod::SpacePartition, dist, 40, &mut rng).unwrap(),
            )
        } else {
            hard_pair(HardFamily::ALL[i % HardFamily::ALL.len()], 40, &mut rng)
        };
        let got = agree(&a, &b);
        assert_eq!(agree(&b.reversed(), &a), got);
        for i in 0..a.len() {
            for j in 0..b.len() {
                let ((p1, p2), (q1, q2)) = (a.edge(i), b.edge(j));
                if segment_contact(Exact, p1, p2, q1, q2) == SegmentContact::Crossing {
                    assert_correctly_rounded(p1, p2, q1, q2);
                    assert!(
                        got.binary_search_by(|v| v.lex_cmp(crossing_point(p1, p2, q1, q2)))
                            .is_ok()
                    );
                    checked += 1;
                }
            }
        }
    }
    assert!(checked > 500, "{checked}");
}

#[test]
fn touchings_and_overlap_ends_are_input_vertices_bit_for_bit() {
    // Coordinates without short binary expansions: recomputing any of these points
    // as an intersection of lines would round. `on` = 2a lies exactly on segment a–4a.
    let a = p(0.1, 0.7);
    let b = p(0.4, 2.8);
    let on = p(0.2, 1.4);
    assert_eq!(Exact.orient(a, b, on), polysect::Orientation::Collinear);
    let p_poly = SimplePolygon::new([a, b, p(-5.0, 2.0)]).unwrap();
    let q_poly = SimplePolygon::new([on, p(on.x + 1.0, on.y - 0.3), p(on.x + 2.0, on.y + 0.1)]).unwrap();
    assert_eq!(agree(&p_poly, &q_poly), vec![on]);
    // An overlap whose ends are one vertex of each polygon: b and 2a.
    let q_over = SimplePolygon::new([on, p(0.8, 5.6), p(3.0, 0.0)]).unwrap();
    assert_eq!(agree(&p_poly, &q_over), vec![on, b]);
    // Shared vertex with arbitrary bits.
    let q2 = SimplePolygon::new([b, p(b.x + 1.0, b.y - 0.3), p(b.x + 2.0, b.y + 0.1)]).unwrap();
    assert_eq!(agree(&p_poly, &q2), vec![b]);
}

#[test]
fn invalid_polygons_are_errors() {
    use SimplePolygonError::*;
    let bowtie = SimplePolygon::new([[0., 0.], [2., 2.], [2., 0.], [0., 2.]]);
    assert!(matches!(
        bowtie,
        Err(SelfIntersection {
            contact: SegmentContact::Crossing,
            ..
        })
    ));
    assert!(matches!(
        SimplePolygon::new([[0., 0.], [1., 0.]]),
        Err(TooFewVertices { distinct: 2 })
    ));
    assert!(matches!(
        SimplePolygon::new([[0., 0.], [1., 0.], [f64::NAN, 1.]]),
        Err(NonFinite { index: 2, .. })
    ));
    assert!(matches!(
        SimplePolygon::new([[0., 0.], [1., 1.], [3., 3.], [0., 0.]]),
        Err(ZeroArea)
    ));
    // Random vertex lists on a grid: every answer agrees with an all-pairs check.
    let mut rng = SmallRng::seed_from_u64(SEED_GRID + 3);
    let (mut ok, mut bad) = (0, 0);
    for _ in 0..2000 {
        let n = rng.random_range(3..12);
        let pts: Vec<[f64; 2]> = (0..n)
            .map(|_| [rng.random_range(0..6) as f64, rng.random_range(0..6) as f64])
            .collect();
        match SimplePolygon::new(pts.iter().copied()) {
            Ok(poly) => {
                ok += 1;
                let v = poly.vertices();
                let k = v.len();
                for i in 0..k {
                    for j in i + 2..k {
                        if i == 0 && j == k - 1 {
                            continue;
                        }
                        let (p1, p2) = poly.edge(i);
                        let (q1, q2) = poly.edge(j);
                        assert!(!segment_contact(Exact, p1, p2, q1, q2).meets(), "{pts:?}");
                    }
                }
            }
            Err(e) => {
                bad += 1;
                assert!(!e.to_string().is_empty());
            }
        }
    }
    assert!(ok > 50 && bad > 500, "{ok} {bad}");
}

const SEED_HARD: u64 = 0x4a4d_0019;

/// The adversarial families (zigzags, needle combs, vertical edges, edges on lines
/// through one point, collinear overlaps), transformed by exact maps (reversal,
/// swapping, power-of-two scaling, reflection), at sizes up to a few thousand.
#[test]
fn sweep_equals_brute_force_on_adversarial_families() {
    use polysect::generate::hard::{HardFamily, hard_pair};
    let mut rng = SmallRng::seed_from_u64(SEED_HARD);
    let mut total = 0;
    for &family in HardFamily::ALL {
        let mut points = 0;
        for n in [8, 9, 12, 20, 33, 64, 150, 400, 1500, 3000] {
            let reps = if n <= 64 { 12 } else { 2 };
            for _ in 0..reps {
                let (a, b) = hard_pair(family, n, &mut rng);
                let got = agree(&a, &b);
                if n <= 150 {
                    check_oracle(&a, &b, &got);
                }
                points += got.len();
                if n <= 400 {
                    // Exact maps: the same points, mapped.
                    let s = 2f64.powi(rng.random_range(-600..600));
                    let f = |v: Point| p(-v.x * s, v.y * s);
                    let (fa, fb) = (a.map(f).unwrap(), b.map(f).unwrap());
                    let mut want: Vec<Point> = got
                        .iter()
                        .map(|&v| f(v))
                        .map(|v| p(v.x + 0.0, v.y + 0.0))
                        .collect();
                    want.sort_by(|x, y| x.lex_cmp(*y));
                    assert_eq!(agree(&fb.reversed(), &fa), want, "{family} n = {n}");
                }
            }
        }
        assert!(points > 0 || family == HardFamily::StackedZigzag, "{family}");
        total += points;
    }
    assert!(total > 10_000, "{total}");
}

/// `Touching::Exclude` on grid and adversarial pairs: every algorithm reports the same
/// points, and they are exactly the proper crossings and the ends of overlaps, found
/// independently from the pairs' contacts.
#[test]
fn touching_exclude_reports_proper_crossings_and_overlap_ends() {
    use polysect::crossings::{CrossingOptions, Touching};
    use polysect::generate::hard::{HardFamily, hard_pair};
    let exclude = CrossingOptions {
        touching: Touching::Exclude,
    };
    let mut rng = SmallRng::seed_from_u64(SEED_HARD + 1);
    let (mut with_touchings, mut removed) = (0, 0);
    for i in 0..900 {
        let (a, b) = if i % 3 == 0 {
            hard_pair(
                HardFamily::ALL[i / 3 % HardFamily::ALL.len()],
                rng.random_range(8..80),
                &mut rng,
            )
        } else {
            grid_pair(&mut rng)
        };
        let got = Brute.crossings_with_options(Exact, &a, &b, exclude);
        for other in [
            Sweep.crossings_with_options(Exact, &a, &b, exclude),
            ListSweep.crossings_with_options(Exact, &a, &b, exclude),
            TreeSweep.crossings_with_options(Exact, &a, &b, exclude),
            CrossingAlgorithm::Sweep.run_with_options(Precision::Exact, &a, &b, exclude),
        ] {
            assert_eq!(other, got, "P = {:?}\nQ = {:?}", a.vertices(), b.vertices());
        }
        let mut want = Vec::new();
        for i in 0..a.len() {
            for j in 0..b.len() {
                let ((p1, p2), (q1, q2)) = (a.edge(i), b.edge(j));
                match segment_contact(Exact, p1, p2, q1, q2) {
                    SegmentContact::Crossing => want.push(crossing_point(p1, p2, q1, q2)),
                    SegmentContact::Overlapping => {
                        let mut ends = [p1, p2, q1, q2];
                        ends.sort_by(|x, y| x.lex_cmp(*y));
                        want.extend([ends[1], ends[2]].map(|v| p(v.x + 0.0, v.y + 0.0)));
                    }
                    _ => {}
                }
            }
        }
        want.sort_by(|x, y| x.lex_cmp(*y));
        want.dedup();
        assert_eq!(got, want);
        let all = agree(&a, &b);
        assert!(got.iter().all(|v| all.contains(v)));
        with_touchings += (all.len() > got.len()) as usize;
        removed += all.len() - got.len();
    }
    assert!(
        with_touchings > 300 && removed > 1000,
        "{with_touchings} {removed}"
    );
}
