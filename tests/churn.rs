//! Long random edit churn on a LinkedPolygon (and, in tests/store.rs, on a scene), with queries interleaved:
//! the invariant checker runs throughout, the arena stays bounded, answers equal the
//! exact reference.

use polysect::generate::regular_polygon;
use polysect::intersect::{Algorithm, ArrayIntersection, Linear};
use polysect::{LinkedPolygon, Point, Precision};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

/// One random edit of the polygon, kept near the unit circle so it neither collapses
/// nor grows without bound: inserts push a point just outside an edge, moves rescale a
/// vertex towards radius 1, removals keep at least 64 vertices.
/// Returns whether the edit was accepted.
fn churn_step(p: &mut LinkedPolygon, rng: &mut SmallRng, target: usize) -> bool {
    let v = p.random_vertex(rng);
    let a = p.point(v).unwrap();
    let grow = p.len() < target;
    match rng.random_range(0..3) {
        0 if grow || rng.random_bool(0.5) => {
            let b = p.point(p.next(v).unwrap()).unwrap();
            let (mx, my) = ((a.x + b.x) / 2.0, (a.y + b.y) / 2.0);
            let r = (mx * mx + my * my).sqrt();
            let f = 1.0 + rng.random_range(0.0..1.0) * (1.0 / r - 1.0).max(0.0);
            p.insert_after(v, Point::new(mx * f, my * f)).is_ok()
        }
        1 if p.len() > 64 => p.remove(v).is_ok(),
        _ => {
            let r = (a.x * a.x + a.y * a.y).sqrt();
            let f = 1.0 + rng.random_range(-0.5..0.5) * (1.0 - r).abs();
            p.move_vertex(v, Point::new(a.x * f, a.y * f)).is_ok()
        }
    }
}

#[test]
fn a_million_edits_on_one_polygon() {
    let mut rng = SmallRng::seed_from_u64(0xc4u64);
    let mut p = LinkedPolygon::from_convex_shuffled(&regular_polygon(512, 1.0), &mut rng);
    let q = regular_polygon(64, 0.2)
        .map(|v| Point::new(v.x + 1.05, v.y))
        .unwrap();
    let mut max_len = p.len();
    let (mut queries, mut accepted) = (0, 0);
    for step in 0..1_000_000u32 {
        accepted += churn_step(&mut p, &mut rng, 1024) as u32;
        max_len = max_len.max(p.len());
        if step % 2_000 == 0 {
            let a = p.to_convex();
            let truth = Linear.intersects(&a, &q);
            for &alg in Algorithm::ALL {
                assert_eq!(
                    alg.intersects(Precision::Exact, &a, &q),
                    truth,
                    "{alg} at step {step}"
                );
            }
            queries += 1;
        }
        if step % 50_000 == 0 {
            p.debug_validate().unwrap_or_else(|e| panic!("step {step}: {e}"));
        }
    }
    p.debug_validate().unwrap();
    assert!(queries >= 500);
    assert!(
        accepted > 300_000,
        "only {accepted} of a million edits were accepted"
    );
    println!("{accepted} of 1,000,000 edits accepted, {queries} query rounds, at most {max_len} vertices");
    // Dense storage: the arena is sized by the largest polygon, not by the edit count.
    assert!(
        p.capacity() <= 2 * max_len.next_power_of_two(),
        "capacity {} for at most {max_len} vertices",
        p.capacity()
    );
}
