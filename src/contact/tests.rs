//! The O(log) search against the linear walk, and the extreme-vertex search against a
//! scan, on many random inputs.

use super::{search, walk};
use crate::generate::{Density, ellipse_polygon, regular_polygon};
use crate::kernel::{Exact, Fast, Point};
use crate::polygon::ConvexPolygon;
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

fn shifted(p: &ConvexPolygon, dx: f64, dy: f64, start: usize) -> ConvexPolygon {
    p.map(|v| Point::new(v.x + dx, v.y + dy))
        .expect("a translation of a random polygon stays convex here")
        .starting_at(start % p.len())
}

#[test]
fn extreme_vertices_match_a_scan() {
    let mut rng = SmallRng::seed_from_u64(17);
    for _ in 0..300 {
        let n = rng.random_range(3..400);
        let p = ellipse_polygon(&mut rng, n, &Density::Uniform, true);
        let start = rng.random_range(0..p.len());
        let p = p.starting_at(start);
        let v = p.vertices();
        let a: f64 = rng.random_range(0.0..std::f64::consts::TAU);
        let u = (a.cos(), a.sin());
        let k = search::extreme(v, u);
        let best = v
            .iter()
            .map(|w| w.x * u.0 + w.y * u.1)
            .fold(f64::NEG_INFINITY, f64::max);
        let got = v[k].x * u.0 + v[k].y * u.1;
        assert!(got >= best - 1e-12, "extreme {k} of {n}: {got} < {best}");
    }
}

#[test]
fn the_search_finds_the_walks_nearest_feature() {
    let mut rng = SmallRng::seed_from_u64(18);
    let (mut found, mut total) = (0, 0);
    for case in 0..400 {
        let (n, m) = (rng.random_range(3..300), rng.random_range(3..300));
        let p = ellipse_polygon(&mut rng, n, &Density::Uniform, true);
        let q0 = ellipse_polygon(&mut rng, m, &Density::Uniform, true);
        let a: f64 = rng.random_range(0.0..std::f64::consts::TAU);
        let r = rng.random_range(2.1..6.0);
        let start = rng.random_range(0..q0.len());
        let q = shifted(&q0, r * a.cos(), r * a.sin(), start);
        let (pv, qv) = (p.vertices(), q.vertices());
        let Some(linear) = walk::nearest_feature(Exact, pv, qv) else {
            continue; // they meet
        };
        total += 1;
        let exact = super::construct::separation(pv, qv, linear).squared_distance;
        if let Some(f) = search::nearest_feature(Exact, pv, qv) {
            found += 1;
            assert_eq!(
                super::construct::separation(pv, qv, f).squared_distance,
                exact,
                "case {case}"
            );
        }
        // The fast kernel's search, when it certifies, certifies the same distance on
        // such well-separated input.
        if let Some(f) = search::nearest_feature(Fast, pv, qv) {
            assert_eq!(
                super::construct::separation(pv, qv, f).squared_distance,
                exact,
                "fast {case}"
            );
        }
    }
    assert!(total > 300, "{total} disjoint pairs");
    // The search proposes a certified feature on ordinary input (else the caller walks).
    assert!(found * 100 >= total * 98, "certified {found} of {total}");
}

#[test]
fn parallel_closest_edges_are_certified() {
    // Two regular polygons facing each other with parallel edges.
    let p = regular_polygon(64, 1.0);
    let q = shifted(&p, 2.5, 0.0, 7);
    let (pv, qv) = (p.vertices(), q.vertices());
    let linear = walk::nearest_feature(Exact, pv, qv).expect("apart");
    let exact = super::construct::separation(pv, qv, linear).squared_distance;
    let f = search::nearest_feature(Exact, pv, qv).expect("certified");
    assert_eq!(super::construct::separation(pv, qv, f).squared_distance, exact);
}

#[test]
fn depth_alone_equals_the_contacts_penetration() {
    let mut rng = SmallRng::seed_from_u64(19);
    let (mut meeting, mut apart) = (0, 0);
    for _ in 0..400 {
        let (n, m) = (rng.random_range(3..200), rng.random_range(3..200));
        let p = ellipse_polygon(&mut rng, n, &Density::Uniform, true);
        let q0 = ellipse_polygon(&mut rng, m, &Density::Uniform, true);
        let a: f64 = rng.random_range(0.0..std::f64::consts::TAU);
        let r = rng.random_range(0.0..3.0);
        let start = rng.random_range(0..q0.len());
        let q = shifted(&q0, r * a.cos(), r * a.sin(), start);
        match (super::contact(&p, &q), super::depth(&p, &q)) {
            (super::Contact::Overlapping(full), Some(d)) => {
                meeting += 1;
                assert_eq!(d.squared_depth, full.squared_depth);
                assert_eq!(d.depth, full.depth);
                assert_eq!(d.normal, full.normal);
            }
            (super::Contact::Separated(_), None) => apart += 1,
            (c, d) => panic!("contact says {} but depth says {d:?}", c.intersects()),
        }
    }
    assert!(meeting > 50 && apart > 50, "{meeting} meeting, {apart} apart");
}

/// The floating-point bounds of a squared depth contain the exact value, on random
/// D-edges across the moderate range, with exact zeros, near-collinear vertices and
/// tiny edges far from the origin.
#[test]
fn depth_bounds_contain_the_exact_squared_depth() {
    use super::construct;
    use crate::kernel::Rational;
    let mut rng = SmallRng::seed_from_u64(23);
    for case in 0..20000 {
        let scale = [1.0, 2f64.powi(-60), 2f64.powi(60), 1e-20, 7.0][case % 5];
        let pt = |rng: &mut SmallRng| {
            let (x, y): (f64, f64) = (rng.random_range(-4.0..4.0), rng.random_range(-4.0..4.0));
            if case % 3 == 0 {
                Point::new(x.round() * scale, y.round() * scale)
            } else {
                Point::new(x * scale, y * scale)
            }
        };
        let (a, b) = (pt(&mut rng), pt(&mut rng));
        let v = match case % 4 {
            // Within a few ulps of the edge's line.
            0 => {
                let t: f64 = rng.random_range(-1.0..2.0);
                let mut v = Point::new(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y));
                for _ in 0..rng.random_range(0..3) {
                    v.y = v.y.next_up();
                }
                v
            }
            // A tiny edge: b a few ulps from a.
            1 => {
                let v = pt(&mut rng);
                let b = Point::new(a.x.next_up().next_up(), a.y.next_down());
                if ![a, b, v]
                    .iter()
                    .all(|w| super::moderate(w.x) && super::moderate(w.y))
                {
                    continue;
                }
                let (lo, hi) = super::depth_bounds([a, b, v]);
                let exact = construct::squared_depth([a, b, v]);
                assert!(
                    Rational::from_f64(lo) <= exact && exact <= Rational::from_f64(hi),
                    "case {case}"
                );
                continue;
            }
            _ => pt(&mut rng),
        };
        if a == b
            || ![a, b, v]
                .iter()
                .all(|w| super::moderate(w.x) && super::moderate(w.y))
        {
            continue;
        }
        let (lo, hi) = super::depth_bounds([a, b, v]);
        let exact = construct::squared_depth([a, b, v]);
        assert!(
            Rational::from_f64(lo) <= exact && exact <= Rational::from_f64(hi),
            "case {case}: {lo:e} {hi:e} {a:?} {b:?} {v:?}"
        );
        assert!(lo <= hi);
    }
}
