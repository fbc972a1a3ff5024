//! Crossing points of simple polygons: the sweep against the brute-force reference
//! on random and degenerate pairs, an independent oracle for the points that are
//! input vertices, the error bound of constructed crossings, and invalid input.

use polysect::crossings::{Brute, CrossingAlgorithm, Crossings, Sweep, SweepWorkspace, crossing_point};
use polysect::generate::simple::{PointDistribution, SimpleMethod, random_simple_polygon};
use polysect::kernel::{Polynomial, Ring, SegmentContact, point_on_segment, segment_contact};
use polysect::{Exact, Fast, Kernel, Point, Precision, Sign, SimplePolygon, SimplePolygonError};
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

/// Sweep and brute force under the exact kernel, required equal; returns the points.
fn agree(a: &SimplePolygon, b: &SimplePolygon) -> Vec<Point> {
    let sweep = Sweep.crossings(a, b);
    let brute = Brute.crossings(a, b);
    assert_eq!(
        sweep,
        brute,
        "sweep != brute for\nP = {:?}\nQ = {:?}",
        a.vertices(),
        b.vertices()
    );
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

/// The sign of (p̃ − a)·den − num·d ∓ B·den for one coordinate, where the exact
/// crossing is a + (num/den)·d: its sign tells on which side of the exact value ± B
/// the constructed coordinate lies.
struct Deviation {
    got: f64,
    a: Point,
    b: Point,
    c: Point,
    e: Point,
    bound: f64,
    y: bool,
}

impl Polynomial for Deviation {
    fn eval<R: Ring>(&self) -> R {
        let f = R::from_f64;
        let (a, b, c, e) = (self.a, self.b, self.c, self.e);
        let (dx, dy) = (f(b.x) - f(a.x), f(b.y) - f(a.y));
        let (ex, ey) = (f(e.x) - f(c.x), f(e.y) - f(c.y));
        let (wx, wy) = (f(c.x) - f(a.x), f(c.y) - f(a.y));
        let den = dx.clone() * ey.clone() - dy.clone() * ex.clone();
        let num = wx * ey - wy * ex;
        let (a0, d) = if self.y { (a.y, dy) } else { (a.x, dx) };
        (f(self.got) - f(a0)) * den.clone() - num * d - f(self.bound) * den
    }
}

/// The documented bound, doubled for the terms left out of the first-order analysis.
fn documented_bound(a: Point, b: Point, c: Point, e: Point, got: Point) -> f64 {
    let u = f64::EPSILON / 2.0;
    let len = |a: Point, b: Point| ((b.x - a.x).powi(2) + (b.y - a.y).powi(2)).sqrt();
    let (l1, l2) = (len(a, b).min(len(c, e)), len(a, b).max(len(c, e)));
    let den = ((b.x - a.x) * (e.y - c.y) - (b.y - a.y) * (e.x - c.x)).abs();
    let kappa = len(a, b) * len(c, e) / den;
    2.0 * u * (3.0 * kappa * (3.0 * l1 + l2) + 3.0 * l1 + 2.0 * got.x.abs().max(got.y.abs()))
}

fn within_bound(a: Point, b: Point, c: Point, e: Point) -> bool {
    let got = crossing_point(a, b, c, e);
    let bound = documented_bound(a, b, c, e, got);
    [false, true].into_iter().all(|y| {
        let coord = if y { got.y } else { got.x };
        let den = Exact.cross(a, b, c, e);
        let s = |bound: f64| {
            let sg = Exact.sign(&Deviation {
                got: coord,
                a,
                b,
                c,
                e,
                bound,
                y,
            });
            if den == polysect::Orientation::Cw {
                sg.reverse()
            } else {
                sg
            }
        };
        // (got − exact)·den ≤ B·den and ≥ −B·den (den > 0 after the sign flip).
        s(bound) != Sign::Positive && s(-bound) != Sign::Negative
    })
}

#[test]
fn constructed_crossings_stay_within_the_documented_bound() {
    let mut rng = SmallRng::seed_from_u64(SEED_BOUND);
    let mut tested = 0;
    let pt = |rng: &mut SmallRng, r: f64| p(rng.random_range(-r..r), rng.random_range(-r..r));
    while tested < 3000 {
        let (a, b, c, e) = (
            pt(&mut rng, 1e3),
            pt(&mut rng, 1e3),
            pt(&mut rng, 1e3),
            pt(&mut rng, 1e3),
        );
        // Every third pair nearly parallel: e − c is b − a turned by a tiny angle.
        let (c, e) = if tested % 3 == 0 {
            let mid = p((a.x + b.x) / 2.0, (a.y + b.y) / 2.0);
            let eps = 10f64.powi(-rng.random_range(3..12));
            let (dx, dy) = (b.x - a.x, b.y - a.y);
            (
                p(mid.x - dx - eps * dy, mid.y - dy + eps * dx),
                p(mid.x + dx + eps * dy, mid.y + dy - eps * dx),
            )
        } else {
            (c, e)
        };
        if segment_contact(Exact, a, b, c, e) != SegmentContact::Crossing {
            continue;
        }
        tested += 1;
        assert!(within_bound(a, b, c, e), "{a:?} {b:?} {c:?} {e:?}");
        assert!(within_bound(c, e, a, b));
    }
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
