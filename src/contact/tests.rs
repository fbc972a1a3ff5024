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
