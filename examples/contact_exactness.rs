//! Exactness of contact answers beside parry2d-f64 on near-touching families: for each
//! family, how often parry's distance (disjoint pairs) or depth (overlapping pairs) is
//! more than 2 ulps from the exact value, and how often its touching/separated decision
//! is wrong (a positive distance for polygons that meet, or zero for polygons apart).
//! polysect's values are the exact ones, correctly rounded, by construction (checked
//! against a rational reference in tests/contact.rs).
//!
//! `cargo run --release --example contact_exactness` (numbers in docs/contact.md).

use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::{contact, distance};
use parry2d_f64::shape::ConvexPolygon as ParryPolygon;
use polysect::contact::{Contact, contact_with};
use polysect::generate::{Density, ellipse_polygon};
use polysect::{ConvexPolygon, Exact, Point};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

const SEED: u64 = 0xe4ac7;
const PAIRS: usize = 2000;

fn parry_polygon(p: &ConvexPolygon) -> ParryPolygon {
    let pts = p.vertices().iter().map(|v| Vector::new(v.x, v.y)).collect();
    ParryPolygon::from_convex_polyline_unmodified(pts).expect("a valid convex polygon")
}

/// Distance in ulps of `exact` between two values.
fn ulps(got: f64, exact: f64) -> f64 {
    let ulp = exact.abs().next_up() - exact.abs();
    (got - exact).abs() / ulp
}

#[derive(Default)]
struct Tally {
    apart: usize,
    meet: usize,
    distance_off: usize,
    depth_off: usize,
    said_meet_when_apart: usize,
    said_apart_when_meet: usize,
}

/// A random polygon, and a second one placed `k` ulps to the right of its rightmost
/// vertex (k < 0 overlaps, 0 touches, k > 0 leaves a gap), or on the line through one of
/// its edges, moved by `k` ulps along x.
fn family(rng: &mut SmallRng, on_edge: bool, k: i64) -> Option<(ConvexPolygon, ConvexPolygon)> {
    let n = rng.random_range(8..64);
    let p = ellipse_polygon(rng, n, &Density::Uniform, true);
    let v = p.vertices();
    let anchor = if on_edge {
        // A point on an edge, rounded: the edge's midpoint.
        let i = rng.random_range(0..v.len());
        let (a, b) = (v[i], v[(i + 1) % v.len()]);
        Point::new(0.5 * (a.x + b.x), 0.5 * (a.y + b.y))
    } else {
        *v.iter().max_by(|a, b| a.x.total_cmp(&b.x))?
    };
    let mut x = anchor.x;
    for _ in 0..k.unsigned_abs() {
        x = if k > 0 { x.next_up() } else { x.next_down() };
    }
    let s = rng.random_range(0.2..1.0);
    let q = ConvexPolygon::new([
        [x, anchor.y],
        [x + s, anchor.y - s],
        [x + 2.0 * s, anchor.y],
        [x + s, anchor.y + s],
    ])
    .ok()?;
    Some((p, q))
}

fn main() {
    let mut rng = SmallRng::seed_from_u64(SEED);
    let id = Pose::identity();
    println!(
        "family            pairs  apart  meet  dist>2ulp  depth>2ulp  parry:meet-when-apart  parry:apart-when-meet"
    );
    for (name, on_edge) in [("rightmost vertex", false), ("edge midpoint", true)] {
        let mut t = Tally::default();
        let mut pairs = 0;
        while pairs < PAIRS {
            let k = rng.random_range(-3..=3);
            let Some((p, q)) = family(&mut rng, on_edge, k) else {
                continue;
            };
            pairs += 1;
            let (pp, pq) = (parry_polygon(&p), parry_polygon(&q));
            let d = distance(&id, &pp, &id, &pq).expect("supported").distance;
            match contact_with(Exact, &p, &q) {
                Contact::Separated(s) => {
                    t.apart += 1;
                    let exact = s.distance.expect("finite");
                    if d == 0.0 {
                        t.said_meet_when_apart += 1;
                    }
                    if ulps(d, exact) > 2.0 {
                        t.distance_off += 1;
                    }
                }
                Contact::Overlapping(o) => {
                    t.meet += 1;
                    if d > 0.0 {
                        t.said_apart_when_meet += 1;
                    }
                    let exact = o.depth.expect("finite");
                    let parry_depth = contact(&id, &pp, &id, &pq, 0.0)
                        .expect("supported")
                        .map_or(0.0, |c| (-c.dist).max(0.0));
                    let off = if exact == 0.0 {
                        parry_depth != 0.0
                    } else {
                        ulps(parry_depth, exact) > 2.0
                    };
                    if off {
                        t.depth_off += 1;
                    }
                }
            }
        }
        println!(
            "{name:<17} {pairs:>5}  {:>5}  {:>4}  {:>9}  {:>10}  {:>21}  {:>21}",
            t.apart, t.meet, t.distance_off, t.depth_off, t.said_meet_when_apart, t.said_apart_when_meet
        );
    }
}
