//! Contact geometry against an exact reference written here: O(n·m) brute force in
//! big-integer rationals (intersection by every vertex and edge pair, distance by every
//! vertex–edge pair, depth by every edge's deepest opposite vertex, overlap by exact
//! Sutherland–Hodgman clipping), and correct rounding checked by bisection over the
//! doubles. Families: random, integer grids (shared edges, vertex on edge, touching),
//! containment both ways, one-ulp gaps, parallel closest edges, scaled by 2^±1000 and
//! into subnormals, huge coordinates whose distance or area overflows; both kernels,
//! arrays and linked polygons. Every family is small in count and size: the reference
//! is quadratic and its numbers grow with the scale.

use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};
use polysect::contact::{Contact, contact_linked_with, contact_with, depth_with, distance_with};
use polysect::polygon::convex_hull;
use polysect::{ConvexPolygon, Exact, Fast, LinkedPolygon, Point};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use std::cmp::Ordering;

const SEED: u64 = 0x00c0_17ac;

/// The reference's own rational: `n / d`, `d > 0`.
#[derive(Clone, Debug)]
struct Q {
    n: BigInt,
    d: BigInt,
}

impl Q {
    fn f(x: f64) -> Q {
        assert!(x.is_finite());
        let bits = x.to_bits();
        let neg = bits >> 63 == 1;
        let exp = ((bits >> 52) & 0x7ff) as i64;
        let frac = (bits & ((1u64 << 52) - 1)) as i64;
        let (m, e) = if exp == 0 {
            (frac, -1074)
        } else {
            (frac | 1 << 52, exp - 1075)
        };
        let m = BigInt::from(if neg { -m } else { m });
        if e >= 0 {
            Q {
                n: m << e as usize,
                d: BigInt::one(),
            }
        } else {
            Q {
                n: m,
                d: BigInt::one() << (-e) as usize,
            }
        }
    }
    fn int(k: i64) -> Q {
        Q {
            n: BigInt::from(k),
            d: BigInt::one(),
        }
    }
    fn from_lib(r: &polysect::kernel::Rational) -> Q {
        let (n, d) = r.parts();
        Q {
            n: n.clone(),
            d: d.clone(),
        }
    }
    fn add(&self, o: &Q) -> Q {
        Q {
            n: &self.n * &o.d + &o.n * &self.d,
            d: &self.d * &o.d,
        }
    }
    fn sub(&self, o: &Q) -> Q {
        Q {
            n: &self.n * &o.d - &o.n * &self.d,
            d: &self.d * &o.d,
        }
    }
    fn mul(&self, o: &Q) -> Q {
        Q {
            n: &self.n * &o.n,
            d: &self.d * &o.d,
        }
    }
    fn div(&self, o: &Q) -> Q {
        let (n, d) = (&self.n * &o.d, &self.d * &o.n);
        if d.is_negative() {
            Q { n: -n, d: -d }
        } else {
            Q { n, d }
        }
    }
    fn sign(&self) -> i32 {
        if self.n.is_zero() {
            0
        } else if self.n.is_positive() {
            1
        } else {
            -1
        }
    }
    fn cmp(&self, o: &Q) -> Ordering {
        (&self.n * &o.d).cmp(&(&o.n * &self.d))
    }
    fn eq(&self, o: &Q) -> bool {
        self.cmp(o) == Ordering::Equal
    }
}

type P2 = [Q; 2];

fn pq(p: Point) -> P2 {
    [Q::f(p.x), Q::f(p.y)]
}
fn sub(a: &P2, b: &P2) -> P2 {
    [a[0].sub(&b[0]), a[1].sub(&b[1])]
}
fn cross(u: &P2, v: &P2) -> Q {
    u[0].mul(&v[1]).sub(&u[1].mul(&v[0]))
}
fn dot(u: &P2, v: &P2) -> Q {
    u[0].mul(&v[0]).add(&u[1].mul(&v[1]))
}
fn orient(a: &P2, b: &P2, c: &P2) -> i32 {
    cross(&sub(b, a), &sub(c, a)).sign()
}
fn same(a: &P2, b: &P2) -> bool {
    a[0].eq(&b[0]) && a[1].eq(&b[1])
}

/// The double nearest `x`, ties to even, by bisection over the doubles' bit patterns.
fn round_ref(x: &Q) -> f64 {
    if x.sign() < 0 {
        let neg = Q {
            n: -x.n.clone(),
            d: x.d.clone(),
        };
        return -round_ref(&neg);
    }
    let max = Q::f(f64::MAX);
    let limit = max.add(&Q::f(2f64.powi(970)));
    match x.cmp(&limit) {
        Ordering::Less => {}
        _ => return f64::INFINITY,
    }
    let (mut lo, mut hi) = (0u64, f64::MAX.to_bits());
    // Largest double ≤ x.
    while lo < hi {
        let mid = lo + (hi - lo).div_ceil(2);
        if Q::f(f64::from_bits(mid)).cmp(x) != Ordering::Greater {
            lo = mid
        } else {
            hi = mid - 1
        }
    }
    let f = f64::from_bits(lo);
    if f == f64::MAX {
        return f;
    }
    let g = f.next_up();
    let mid = Q::f(f).add(&Q::f(g)).mul(&Q {
        n: BigInt::one(),
        d: BigInt::from(2),
    });
    match x.cmp(&mid) {
        Ordering::Less => f,
        Ordering::Greater => g,
        Ordering::Equal => {
            if lo % 2 == 0 {
                f
            } else {
                g
            }
        }
    }
}

/// The double nearest √x (x ≥ 0), ties to even, by bisection.
fn sqrt_ref(x: &Q) -> f64 {
    assert!(x.sign() >= 0);
    let sq = |f: f64| Q::f(f).mul(&Q::f(f));
    let (mut lo, mut hi) = (0u64, f64::MAX.to_bits());
    while lo < hi {
        let mid = lo + (hi - lo).div_ceil(2);
        if sq(f64::from_bits(mid)).cmp(x) != Ordering::Greater {
            lo = mid
        } else {
            hi = mid - 1
        }
    }
    let f = f64::from_bits(lo);
    let g_q = if f == f64::MAX {
        Q::f(f64::MAX).add(&Q::f(2f64.powi(971)))
    } else {
        Q::f(f.next_up())
    };
    let half = Q {
        n: BigInt::one(),
        d: BigInt::from(2),
    };
    let mid = Q::f(f).add(&g_q).mul(&half);
    let mid2 = mid.mul(&mid);
    let up = match x.cmp(&mid2) {
        Ordering::Less => false,
        Ordering::Greater => true,
        Ordering::Equal => lo % 2 == 1,
    };
    if !up {
        f
    } else if f == f64::MAX {
        f64::INFINITY
    } else {
        f.next_up()
    }
}

fn finite(x: f64) -> Option<f64> {
    x.is_finite().then_some(x)
}

struct Poly {
    v: Vec<P2>,
}

impl Poly {
    fn of(p: &ConvexPolygon) -> Poly {
        Poly {
            v: p.vertices().iter().map(|&x| pq(x)).collect(),
        }
    }
    fn edges(&self) -> impl Iterator<Item = (&P2, &P2)> {
        let n = self.v.len();
        (0..n).map(move |i| (&self.v[i], &self.v[(i + 1) % n]))
    }
    fn contains(&self, x: &P2) -> bool {
        self.edges().all(|(a, b)| orient(a, b, x) >= 0)
    }
}

fn on_segment(a: &P2, b: &P2, x: &P2) -> bool {
    orient(a, b, x) == 0 && dot(&sub(x, a), &sub(b, a)).sign() >= 0 && dot(&sub(x, b), &sub(a, b)).sign() >= 0
}

fn segments_meet(a: &P2, b: &P2, c: &P2, d: &P2) -> bool {
    let (o1, o2, o3, o4) = (orient(a, b, c), orient(a, b, d), orient(c, d, a), orient(c, d, b));
    (o1 * o2 < 0 && o3 * o4 < 0)
        || on_segment(a, b, c)
        || on_segment(a, b, d)
        || on_segment(c, d, a)
        || on_segment(c, d, b)
}

fn ref_intersects(p: &Poly, q: &Poly) -> bool {
    p.v.iter().any(|x| q.contains(x))
        || q.v.iter().any(|x| p.contains(x))
        || p.edges()
            .any(|(a, b)| q.edges().any(|(c, d)| segments_meet(a, b, c, d)))
}

/// Squared distance from x to segment a–b.
fn point_segment(a: &P2, b: &P2, x: &P2) -> Q {
    let e = sub(b, a);
    let w = sub(x, a);
    let t = dot(&w, &e);
    let l = dot(&e, &e);
    if t.sign() <= 0 {
        return dot(&w, &w);
    }
    if t.cmp(&l) != Ordering::Less {
        let u = sub(x, b);
        return dot(&u, &u);
    }
    let c = cross(&e, &w);
    c.mul(&c).div(&l)
}

fn min_q(values: impl Iterator<Item = Q>) -> Q {
    values
        .reduce(|a, b| if b.cmp(&a) == Ordering::Less { b } else { a })
        .expect("candidates")
}

fn ref_sq_distance(p: &Poly, q: &Poly) -> Q {
    let one = |x: &Poly, y: &Poly| {
        min_q(
            x.v.iter()
                .flat_map(|v| y.edges().map(move |(a, b)| point_segment(a, b, v))),
        )
    };
    let (a, b) = (one(p, q), one(q, p));
    if b.cmp(&a) == Ordering::Less { b } else { a }
}

/// Per edge of either polygon: the squared depth of the other's deepest vertex across
/// it, the edge's direction and whether it is Q's.
fn depth_candidates(p: &Poly, q: &Poly) -> Vec<(Q, P2, bool)> {
    let mut out = Vec::new();
    for (poly, other, of_q) in [(q, p, true), (p, q, false)] {
        for (a, b) in poly.edges() {
            let e = sub(b, a);
            let o = other
                .v
                .iter()
                .map(|v| cross(&e, &sub(v, a)))
                .reduce(|x, y| if y.cmp(&x) == Ordering::Greater { y } else { x })
                .expect("vertices");
            let l = dot(&e, &e);
            out.push((o.mul(&o).div(&l), e, of_q));
        }
    }
    out
}

/// The unit translation direction of Q for an edge direction `e` (Q's: the inward
/// normal; P's: the outward one), each component the correctly rounded ±√(c²/|e|²).
fn direction(e: &P2, of_q: bool) -> [f64; 2] {
    let l = dot(e, e);
    let c = if of_q {
        [
            Q {
                n: -e[1].n.clone(),
                d: e[1].d.clone(),
            },
            e[0].clone(),
        ]
    } else {
        [
            e[1].clone(),
            Q {
                n: -e[0].n.clone(),
                d: e[0].d.clone(),
            },
        ]
    };
    let comp = |c: &Q| {
        let m = sqrt_ref(&c.mul(c).div(&l));
        if c.sign() < 0 { -m } else { m }
    };
    [comp(&c[0]), comp(&c[1])]
}

/// P ∩ Q by clipping P with every edge of Q, exactly, then without repeats and
/// collinear vertices.
fn ref_overlap(p: &Poly, q: &Poly) -> Vec<P2> {
    let mut poly: Vec<P2> = p.v.clone();
    for (a, b) in q.edges() {
        let mut out = Vec::new();
        let k = poly.len();
        for i in 0..k {
            let (s, e) = (&poly[i], &poly[(i + 1) % k]);
            let (os, oe) = (orient(a, b, s), orient(a, b, e));
            if os >= 0 {
                out.push(s.clone());
            }
            if (os > 0 && oe < 0) || (os < 0 && oe > 0) {
                let r = sub(e, s);
                let t = cross(&sub(a, s), &sub(b, a)).div(&cross(&r, &sub(b, a)));
                out.push([s[0].add(&r[0].mul(&t)), s[1].add(&r[1].mul(&t))]);
            }
        }
        poly = out;
        if poly.is_empty() {
            return poly;
        }
    }
    // A touching point or segment: its distinct points' extremes.
    if twice_area(&poly).sign() == 0 {
        let mut pts = poly;
        pts.sort_by(|a, b| a[0].cmp(&b[0]).then_with(|| a[1].cmp(&b[1])));
        pts.dedup_by(|a, b| same(a, b));
        if pts.len() > 2 {
            let last = pts.pop().expect("points");
            pts.truncate(1);
            pts.push(last);
        }
        return pts;
    }
    // Drop repeats, then collinear vertices, until none is left.
    loop {
        let k = poly.len();
        if k < 2 {
            return poly;
        }
        if let Some(i) = (0..k).find(|&i| same(&poly[i], &poly[(i + 1) % k])) {
            poly.remove(i);
            continue;
        }
        if k < 3 {
            return poly;
        }
        if let Some(i) = (0..k).find(|&i| orient(&poly[(i + k - 1) % k], &poly[i], &poly[(i + 1) % k]) == 0) {
            poly.remove(i);
            continue;
        }
        return poly;
    }
}

fn twice_area(v: &[P2]) -> Q {
    let k = v.len();
    if k < 3 {
        return Q::int(0);
    }
    (0..k)
        .map(|i| cross(&v[i], &v[(i + 1) % k]))
        .fold(Q::int(0), |a, b| a.add(&b))
}

fn same_cycle(a: &[P2], b: &[P2]) -> bool {
    if a.len() != b.len() {
        return false;
    }
    if a.is_empty() {
        return true;
    }
    (0..b.len()).any(|s| (0..a.len()).all(|i| same(&a[i], &b[(i + s) % b.len()])))
}

/// The contract's rounded overlap from the exact one: round, drop repeats, start at the
/// lowest then leftmost.
fn rounded_overlap(v: &[P2]) -> Vec<Point> {
    let mut out: Vec<Point> = Vec::new();
    for x in v {
        let r = Point::new(round_ref(&x[0]), round_ref(&x[1]));
        if !out.contains(&r) {
            out.push(r);
        }
    }
    if let Some(s) =
        (0..out.len()).min_by(|&i, &k| out[i].y.total_cmp(&out[k].y).then(out[i].x.total_cmp(&out[k].x)))
    {
        out.rotate_left(s);
    }
    out
}

/// Checks the exact contact of `p` and `q` against the reference; returns whether they meet.
fn check_exact(p: &ConvexPolygon, q: &ConvexPolygon, what: &str) -> bool {
    let (rp, rq) = (Poly::of(p), Poly::of(q));
    let meets = ref_intersects(&rp, &rq);
    let got = contact_with(Exact, p, q);
    assert_eq!(
        got.intersects(),
        meets,
        "{what}: intersects\np = {p:?}\nq = {q:?}"
    );
    match &got {
        Contact::Separated(s) => {
            let d2 = ref_sq_distance(&rp, &rq);
            assert!(
                Q::from_lib(&s.squared_distance).eq(&d2),
                "{what}: squared distance"
            );
            assert_eq!(s.distance, finite(sqrt_ref(&d2)), "{what}: distance");
            let [a, b] = &s.closest_exact;
            let (a, b) = (
                [Q::from_lib(&a[0]), Q::from_lib(&a[1])],
                [Q::from_lib(&b[0]), Q::from_lib(&b[1])],
            );
            assert!(
                rp.contains(&a) && rq.contains(&b),
                "{what}: closest points lie on their polygons"
            );
            let d = sub(&a, &b);
            assert!(dot(&d, &d).eq(&d2), "{what}: the closest pair is at the distance");
            for (k, x) in [&a, &b].into_iter().enumerate() {
                assert_eq!(
                    s.closest[k],
                    Point::new(round_ref(&x[0]), round_ref(&x[1])),
                    "{what}: rounding"
                );
            }
        }
        Contact::Overlapping(o) => {
            let cands = depth_candidates(&rp, &rq);
            let best = min_q(cands.iter().map(|c| c.0.clone()));
            assert!(
                Q::from_lib(&o.squared_depth).eq(&best),
                "{what}: squared depth\np = {p:?}\nq = {q:?}"
            );
            assert_eq!(o.depth, finite(sqrt_ref(&best)), "{what}: depth");
            let unit = o.normal[0].hypot(o.normal[1]);
            assert!((unit - 1.0).abs() < 4.0 * f64::EPSILON, "{what}: unit normal");
            let tol = 2.0 * f64::EPSILON;
            assert!(
                cands.iter().filter(|c| c.0.eq(&best)).any(|(_, e, of_q)| {
                    let n = direction(e, *of_q);
                    (n[0] - o.normal[0]).abs() <= tol && (n[1] - o.normal[1]).abs() <= tol
                }),
                "{what}: the normal {:?} is no tied minimum's direction",
                o.normal
            );
            let region = ref_overlap(&rp, &rq);
            let exact: Vec<P2> = o
                .overlap_exact
                .iter()
                .map(|x| [Q::from_lib(&x[0]), Q::from_lib(&x[1])])
                .collect();
            assert!(
                same_cycle(&exact, &region),
                "{what}: overlap polygon\np = {p:?}\nq = {q:?}\n{:?}",
                o.overlap
            );
            assert_eq!(o.overlap, rounded_overlap(&region), "{what}: rounded overlap");
            let area2 = twice_area(&region);
            assert!(Q::from_lib(&o.twice_area).eq(&area2), "{what}: area");
            let half = Q {
                n: BigInt::one(),
                d: BigInt::from(2),
            };
            assert_eq!(
                o.area,
                finite(round_ref(&area2.mul(&half))),
                "{what}: rounded area"
            );
        }
    }
    // Linked polygons give the same contact.
    let (lp, lq) = (LinkedPolygon::from_convex(p), LinkedPolygon::from_convex(q));
    assert_eq!(contact_linked_with(Exact, &lp, &lq), got, "{what}: linked");
    // The lighter queries give the checked contact's values.
    match &got {
        Contact::Separated(s) => {
            let d = distance_with(Exact, p, q).expect("apart");
            assert_eq!(
                (d.distance, d.closest),
                (s.distance, s.closest),
                "{what}: distance_with"
            );
            // Bit for bit: `==` on doubles would let a −0 pass for +0.
            let bits = |c: &[Point; 2]| c.map(|v| (v.x.to_bits(), v.y.to_bits()));
            assert_eq!(bits(&d.closest), bits(&s.closest), "{what}: distance_with bits");
            assert!(
                depth_with(Exact, p, q).is_none(),
                "{what}: depth_with of a separated pair"
            );
        }
        Contact::Overlapping(o) => {
            let d = depth_with(Exact, p, q).expect("meeting");
            assert_eq!((d.depth, d.normal), (o.depth, o.normal), "{what}: depth_with");
            assert!(
                distance_with(Exact, p, q).is_none(),
                "{what}: distance_with of a meeting pair"
            );
        }
    }
    // The fast kernel never panics, and its constructions are exact roundings of
    // whatever it decided.
    let _ = contact_with(Fast, p, q);
    meets
}

fn random_polygon(rng: &mut SmallRng, k: usize, r: f64, c: Point) -> ConvexPolygon {
    loop {
        let pts: Vec<Point> = (0..k)
            .map(|_| Point::new(c.x + rng.random_range(-r..r), c.y + rng.random_range(-r..r)))
            .collect();
        if let Ok(h) = convex_hull(&pts) {
            return h;
        }
    }
}

fn grid_polygon(rng: &mut SmallRng, k: usize, size: i32, c: (i32, i32)) -> ConvexPolygon {
    loop {
        let pts: Vec<Point> = (0..k)
            .map(|_| {
                Point::new(
                    (c.0 + rng.random_range(0..=size)) as f64,
                    (c.1 + rng.random_range(0..=size)) as f64,
                )
            })
            .collect();
        if let Ok(h) = convex_hull(&pts) {
            return h;
        }
    }
}

fn scaled(p: &ConvexPolygon, s: f64) -> ConvexPolygon {
    p.map(|v| Point::new(v.x * s, v.y * s))
        .expect("power-of-two scaling is exact")
}

fn poly(v: &[[f64; 2]]) -> ConvexPolygon {
    ConvexPolygon::new(v.iter().copied()).expect("valid")
}

#[test]
fn random_pairs_match_the_reference() {
    let mut rng = SmallRng::seed_from_u64(SEED);
    let (mut met, mut apart) = (0, 0);
    for case in 0..300 {
        let k1 = rng.random_range(3..14);
        let k2 = rng.random_range(3..14);
        let p = random_polygon(&mut rng, k1, 10.0, Point::new(0.0, 0.0));
        let c = Point::new(rng.random_range(-22.0..22.0), rng.random_range(-22.0..22.0));
        let q = random_polygon(&mut rng, k2, 10.0, c);
        if check_exact(&p, &q, &format!("random {case}")) {
            met += 1
        } else {
            apart += 1
        }
        // Fast decisions agree on well-separated or well-overlapping random input.
        if let (Contact::Separated(a), Contact::Separated(b)) =
            (contact_with(Fast, &p, &q), contact_with(Exact, &p, &q))
        {
            assert_eq!(a.squared_distance, b.squared_distance);
        }
    }
    assert!(
        met > 50 && apart > 50,
        "both outcomes covered: {met} met, {apart} apart"
    );
}

#[test]
fn integer_grids_touch_share_edges_and_contain() {
    let mut rng = SmallRng::seed_from_u64(SEED + 1);
    let mut met = 0;
    for case in 0..400 {
        let (k1, k2) = (rng.random_range(3..8), rng.random_range(3..8));
        let shift = (rng.random_range(-6..=6), rng.random_range(-6..=6));
        let p = grid_polygon(&mut rng, k1, 6, (0, 0));
        let q = grid_polygon(&mut rng, k2, 6, shift);
        met += usize::from(check_exact(&p, &q, &format!("grid {case}")));
    }
    assert!(met > 100);
}

#[test]
fn scales_subnormals_and_overflow() {
    let mut rng = SmallRng::seed_from_u64(SEED + 2);
    for case in 0..40 {
        let (k1, k2) = (rng.random_range(3..7), rng.random_range(3..7));
        let shift = (rng.random_range(-8..=8), rng.random_range(-8..=8));
        let p = grid_polygon(&mut rng, k1, 8, (0, 0));
        let q = grid_polygon(&mut rng, k2, 8, shift);
        for s in [
            2f64.powi(1000),
            2f64.powi(-1000),
            2f64.powi(-1070),
            2f64.powi(1016),
        ] {
            check_exact(&scaled(&p, s), &scaled(&q, s), &format!("scaled {case} by {s:e}"));
        }
    }
    // Distance beyond the largest double: null.
    let p = poly(&[[-1.7e308, 0.0], [-1.6e308, 0.0], [-1.6e308, 1.0]]);
    let q = poly(&[[1.6e308, 0.0], [1.7e308, 0.0], [1.7e308, 1.0]]);
    check_exact(&p, &q, "overflowing distance");
    let Contact::Separated(s) = contact_with(Exact, &p, &q) else {
        panic!("apart")
    };
    assert_eq!(s.distance, None);
    // Area and depth beyond the largest double.
    let big = poly(&[[-1e308, -1e308], [1e308, -1e308], [1e308, 1e308], [-1e308, 1e308]]);
    let big2 = poly(&[
        [-9e307, -9e307],
        [1.5e308, -9e307],
        [1.5e308, 1.5e308],
        [-9e307, 1.5e308],
    ]);
    check_exact(&big, &big2, "overflowing area");
    let Contact::Overlapping(o) = contact_with(Exact, &big, &big2) else {
        panic!("meet")
    };
    assert_eq!(o.area, None);
}

#[test]
fn adversarial_near_touches_and_parallel_edges() {
    let one = 1.0f64;
    let cases: Vec<(ConvexPolygon, ConvexPolygon, bool)> = vec![
        // One-ulp gap, and touching.
        (
            poly(&[[0., 0.], [1., 0.], [1., 1.], [0., 1.]]),
            poly(&[[one.next_up(), 0.], [2., 0.], [2., 1.]]),
            false,
        ),
        (
            poly(&[[0., 0.], [1., 0.], [1., 1.], [0., 1.]]),
            poly(&[[1., 0.5], [2., 0.], [2., 1.]]),
            true,
        ),
        (
            poly(&[[0., 0.], [1., 0.], [1., 1.], [0., 1.]]),
            poly(&[[1., 1.], [2., 1.], [2., 2.]]),
            true,
        ),
        // Shared edge, and a shared edge portion.
        (
            poly(&[[0., 0.], [1., 0.], [1., 1.], [0., 1.]]),
            poly(&[[1., 0.], [2., 0.], [2., 1.], [1., 1.]]),
            true,
        ),
        (
            poly(&[[0., 0.], [1., 0.], [1., 1.], [0., 1.]]),
            poly(&[[1., 0.25], [2., 0.], [2., 2.], [1., 0.75]]),
            true,
        ),
        // Parallel closest edges, offset.
        (
            poly(&[[0., 0.], [3., 0.], [3., 1.], [0., 1.]]),
            poly(&[[1., 2.], [5., 2.], [5., 3.], [1., 3.]]),
            false,
        ),
        // Diagonal near touch: a vertex one ulp off the hypotenuse, both sides.
        (
            poly(&[[0., 0.], [1., 0.], [0., 1.]]),
            poly(&[[0.5, 0.5f64.next_up()], [2., 2.], [0.5, 2.]]),
            false,
        ),
        (
            poly(&[[0., 0.], [1., 0.], [0., 1.]]),
            poly(&[[0.5, 0.5f64.next_down()], [2., 2.], [0.5, 2.]]),
            true,
        ),
        // 0.1 + 0.9 exceeds 1 by 2^-55 in doubles: apart; 0.25 + 0.75 is 1: touching.
        (
            poly(&[[0., 0.], [1., 0.], [0., 1.]]),
            poly(&[[0.1, 0.9], [2., 2.], [0.5, 2.]]),
            false,
        ),
        (
            poly(&[[0., 0.], [1., 0.], [0., 1.]]),
            poly(&[[0.25, 0.75], [2., 2.], [0.5, 2.]]),
            true,
        ),
        // Containment both ways, and identical polygons.
        (
            poly(&[[0., 0.], [10., 0.], [10., 10.], [0., 10.]]),
            poly(&[[2., 3.], [4., 3.], [3., 7.]]),
            true,
        ),
        (
            poly(&[[2., 3.], [4., 3.], [3., 7.]]),
            poly(&[[0., 0.], [10., 0.], [10., 10.], [0., 10.]]),
            true,
        ),
        (
            poly(&[[0., 0.], [1., 0.], [0.3, 0.7]]),
            poly(&[[0., 0.], [1., 0.], [0.3, 0.7]]),
            true,
        ),
        // A tip that crosses an edge by less than an ulp: its two crossings round to one point.
        (
            poly(&[[0., 0.], [4., 0.], [0., 4.]]),
            poly(&[[1.999, 0.5], [2.001, 0.5], [2., 2. + 2f64.powi(-51)]]),
            true,
        ),
        // Tiny against huge.
        (
            poly(&[[-1e300, -1e300], [1e300, -1e300], [0., 1e300]]),
            poly(&[[5e-324, 0.], [1e-323, 0.], [5e-324, 5e-324]]),
            true,
        ),
        (
            poly(&[[0., 0.], [1e-300, 0.], [0., 1e-300]]),
            poly(&[[1e-300, 1e-300], [1e300, 1e-300], [1e-300, 1e300]]),
            false,
        ),
    ];
    for (k, (p, q, meets)) in cases.iter().enumerate() {
        assert_eq!(check_exact(p, q, &format!("case {k}")), *meets, "case {k}");
        assert_eq!(
            check_exact(q, p, &format!("case {k} swapped")),
            *meets,
            "case {k} swapped"
        );
    }
    // The tip's two crossings are one rounded point.
    let Contact::Overlapping(o) = contact_with(Exact, &cases[13].0, &cases[13].1) else {
        panic!("meet")
    };
    assert_eq!(o.overlap_exact.len(), 4);
    assert_eq!(
        o.overlap,
        [
            Point::new(1.999, 0.5),
            Point::new(2.001, 0.5),
            Point::new(2.0, 2.0)
        ]
    );
}

#[test]
fn touching_has_zero_depth_and_a_separating_normal() {
    let p = poly(&[[0., 0.], [1., 0.], [1., 1.], [0., 1.]]);
    let q = poly(&[[1., 0.5], [2., 0.], [2., 1.]]);
    let Contact::Overlapping(o) = contact_with(Exact, &p, &q) else {
        panic!("touching meets")
    };
    assert_eq!((o.depth, o.area), (Some(0.0), Some(0.0)));
    assert_eq!(o.overlap, [Point::new(1.0, 0.5)]);
    assert_eq!(o.normal, [1.0, 0.0]);
    let q = poly(&[[1., 0.], [2., 0.], [2., 1.], [1., 1.]]);
    let Contact::Overlapping(o) = contact_with(Exact, &p, &q) else {
        panic!("a shared edge meets")
    };
    assert_eq!(o.overlap, [Point::new(1.0, 0.0), Point::new(1.0, 1.0)]);
    assert_eq!(o.normal, [1.0, 0.0]);
}

/// The scene's contacts of all intersecting pairs: exactly the pairs the reference finds
/// meeting, each with the contact the checked function gives, on grid polygons that
/// touch, share edges and contain each other.
#[test]
fn scene_contacts_are_the_reference_pairs_with_their_contacts() {
    let mut rng = SmallRng::seed_from_u64(SEED + 7);
    let mut scene = polysect::store::Scene::new();
    let mut polygons = Vec::new();
    for _ in 0..60 {
        let k = rng.random_range(3..8);
        let c = (rng.random_range(-20..=20), rng.random_range(-20..=20));
        let p = grid_polygon(&mut rng, k, 6, c);
        let id = scene.insert(LinkedPolygon::from_convex(&p));
        polygons.push((id, p));
    }
    let mut want = Vec::new();
    for (i, (a, p)) in polygons.iter().enumerate() {
        for (b, q) in &polygons[i + 1..] {
            if ref_intersects(&Poly::of(p), &Poly::of(q)) {
                want.push(if a < b { (*a, *b) } else { (*b, *a) });
            }
        }
    }
    want.sort();
    let contacts = scene.contacts();
    let mut got: Vec<_> = contacts
        .iter()
        .map(|(a, b, _)| if a < b { (*a, *b) } else { (*b, *a) })
        .collect();
    got.sort();
    assert_eq!(got, want);
    assert!(want.len() > 20, "{} meeting pairs", want.len());
    let of = |id| &polygons.iter().find(|(k, _)| *k == id).expect("inserted").1;
    for (a, b, c) in &contacts {
        assert!(c.intersects());
        assert_eq!(c, &contact_with(Exact, of(*a), of(*b)), "{a} and {b}");
        check_exact(of(*a), of(*b), "scene pair");
    }
}

/// `Scene::distance` on the scene's polygons where they stand, posed ones included:
/// the reference's distance and a closest pair on the world polygons, `None` exactly
/// for the pairs the reference finds meeting, errors for removed handles.
#[test]
fn scene_distance_is_the_reference_distance_of_the_world_polygons() {
    use polysect::kernel::Pose;
    let mut rng = SmallRng::seed_from_u64(SEED + 8);
    let mut scene = polysect::store::Scene::new();
    let mut ids = Vec::new();
    for k in 0..40 {
        let n = rng.random_range(3..30);
        let c = Point::new(rng.random_range(-30.0..30.0), rng.random_range(-30.0..30.0));
        let p = random_polygon(&mut rng, n, 6.0, c);
        let id = scene.insert(LinkedPolygon::from_convex(&p));
        if k % 2 == 0 {
            // Rotations by exact and inexact angles, with a translation.
            let t: f64 = rng.random_range(0.0..std::f64::consts::TAU);
            let rotation = [[0.0, 1.0], [t.cos(), t.sin()]][k % 4 / 2];
            let pose = Pose::new(rotation, [rng.random_range(-5.0..5.0), 0.25]).expect("a pose");
            // A pose whose rounding breaks convexity is refused; the polygon stays.
            let _ = scene.set_pose(id, pose);
        }
        ids.push(id);
    }
    let (mut apart, mut meet) = (0, 0);
    for (i, &a) in ids.iter().enumerate() {
        for &b in &ids[i + 1..] {
            let (p, q) = (
                scene.polygon(a).expect("live").to_convex(),
                scene.polygon(b).expect("live").to_convex(),
            );
            let got = scene.distance(a, b).expect("live handles");
            let meets = check_exact(&p, &q, &format!("scene {a} and {b}"));
            assert_eq!(got.is_none(), meets, "{a} and {b}");
            match (got, contact_with(Exact, &p, &q)) {
                (Some(d), Contact::Separated(s)) => {
                    assert_eq!(
                        (d.distance, d.closest, d.feature),
                        (s.distance, s.closest, s.feature)
                    );
                    apart += 1;
                }
                (None, Contact::Overlapping(_)) => meet += 1,
                (got, want) => panic!("{a} and {b}: {got:?} against {want:?}"),
            }
        }
    }
    assert!(apart > 100 && meet > 10, "{apart} apart, {meet} meet");
    let gone = ids[1];
    scene.remove(gone).expect("live");
    assert!(scene.distance(ids[0], gone).is_err());
    assert!(scene.distance(gone, ids[0]).is_err());
}

/// Negative zeros in the input: every query prints +0 where the exact value is zero.
#[test]
fn negative_zero_inputs_give_positive_zero_closest_points() {
    let cases = [
        (
            poly(&[[-2.0, -1.0], [-0.0, -0.0], [-2.0, 1.0]]),
            poly(&[[1.0, -0.0], [3.0, -1.0], [3.0, 1.0]]),
        ),
        (
            poly(&[[-0.0, -1.0], [-0.0, 1.0], [-2.0, -0.0]]),
            poly(&[[1.0, -0.0], [3.0, -1.0], [3.0, 1.0]]),
        ),
        (
            poly(&[[-1.0, -0.0], [1.0, -0.0], [-0.0, 1.0]]),
            poly(&[[-0.0, -2.0], [-1.0, -3.0], [1.0, -3.0]]),
        ),
    ];
    for (k, (p, q)) in cases.iter().enumerate() {
        for (a, b) in [(p, q), (q, p)] {
            assert!(!check_exact(a, b, &format!("negative zeros {k}")));
            let d = distance_with(Exact, a, b).expect("apart");
            for c in d.closest {
                for x in [c.x, c.y] {
                    assert!(x != 0.0 || x.is_sign_positive(), "case {k}: {:?}", d.closest);
                }
            }
        }
    }
}
