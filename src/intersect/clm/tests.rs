use super::ordering::{OrderScratch, boundary_order};
use super::sampling::{below, fisher_yates, shuffle};
use super::{Clm, ClmWorkspace};
use crate::LinkedPolygon;
use crate::generate::{self, Family, Relation, pair};
use crate::intersect::{Derivation, LinkedIntersection, verify_linked};
use crate::kernel::{Exact, Fast, Point};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

/// Random samples (with repeats, in random order) of strictly convex polygons,
/// scaled by powers of two from 2^-1000 to 2^1000 and shifted by 2^40..2^52, come
/// out of `boundary_order` as the distinct sampled vertices in the polygon's
/// counter-clockwise order, from the lowest (then leftmost) one. At 2^1022 the
/// differences overflow and the keys are ruined: then either the same order or
/// `false` with the sample left as drawn. Under `Fast`, some order of the same
/// points (never a panic).
#[test]
fn boundary_order_is_the_cyclic_order_of_the_sample() {
    let mut rng = SmallRng::seed_from_u64(14);
    let mut scratch = OrderScratch::default();
    let (mut checked, mut refused) = (0, 0);
    for round in 0..600 {
        let family = [
            Family::Rotated,
            Family::Ellipse,
            Family::NonUniform,
            Family::OneUlpGap,
        ][round % 4];
        let n = rng.random_range(3..=400);
        let (poly, _) = pair(family, n, Relation::Any, &mut rng);
        let (scale, shift) = match round % 6 {
            0 => (1.0, 0.0),
            1 => (2f64.powi(1000), 0.0),
            2 => (2f64.powi(-1000), 0.0),
            3 => (1.0, 2f64.powi(rng.random_range(40..=52))),
            4 => (2f64.powi(1022), 0.0),
            _ => (2f64.powi(-500), 0.0),
        };
        let vertices: Vec<Point> = poly
            .vertices()
            .iter()
            .map(|v| Point::new(v.x * scale + shift, v.y * scale + shift))
            .collect();
        if crate::ConvexPolygon::new(vertices.iter().copied()).map(|p| p.len()) != Ok(vertices.len()) {
            continue; // the shift merged vertices: not a strictly convex polygon
        }
        let r = rng.random_range(1..=vertices.len() + 8);
        let mut positions: Vec<u32> = (0..r)
            .map(|_| rng.random_range(0..vertices.len() as u32))
            .collect();
        let mut points: Vec<Point> = positions.iter().map(|&i| vertices[i as usize]).collect();
        // The expected order: the sampled positions in the polygon's order, rotated
        // to start at the lowest (then leftmost) sampled point.
        let mut expected: Vec<u32> = positions.clone();
        expected.sort_unstable();
        expected.dedup();
        let start = (0..expected.len())
            .min_by(|&a, &b| {
                let (p, q) = (vertices[expected[a] as usize], vertices[expected[b] as usize]);
                p.y.total_cmp(&q.y).then(p.x.total_cmp(&q.x))
            })
            .unwrap();
        expected.rotate_left(start);
        let (mut fast_positions, mut fast_points) = (positions.clone(), points.clone());
        let drawn = positions.clone();
        if boundary_order(Exact, &mut positions, &mut points, &mut scratch) {
            assert_eq!(positions, expected, "round {round}");
            checked += 1;
        } else {
            assert!(
                round % 6 == 4,
                "refused at a scale whose keys are sound: round {round}"
            );
            assert_eq!(positions, drawn, "a refused sample is left as drawn");
            refused += 1;
        }
        for (&i, x) in positions.iter().zip(&points) {
            assert_eq!(*x, vertices[i as usize]);
        }
        boundary_order(Fast, &mut fast_positions, &mut fast_points, &mut scratch);
        fast_positions.sort_unstable();
        fast_positions.dedup();
        assert_eq!(fast_positions.len(), expected.len());
    }
    assert!(checked > 400, "{checked} checked, {refused} refused");
}

/// Intersecting pairs of the lattice families (exact touchings, one-ulp gaps,
/// nesting), as generated and scaled exactly to near f64::MAX and to subnormals:
/// every certified answer carries a certificate that `verify_linked` accepts, and
/// the LP's last step (a point beyond a chord, or a mixed pair of bounds) gives
/// the witness in some of them.
#[test]
fn last_step_witnesses_verify_on_touching_one_ulp_and_extreme_pairs() {
    let mut rng = SmallRng::seed_from_u64(0x57d1);
    let mut ws = ClmWorkspace::default();
    let families: Vec<Family> = Family::TOUCHING.iter().copied().chain([Family::Nested]).collect();
    let (mut straddles, mut mixed, mut checked) = (0, 0, 0);
    for i in 0..240 {
        let family = families[i % families.len()];
        let (p, q) = generate::pair(family, 30 + 7 * (i % 40), Relation::Intersecting, &mut rng);
        let largest = p
            .vertices()
            .iter()
            .chain(q.vertices())
            .map(|v| v.x.abs().max(v.y.abs()))
            .fold(0.0, f64::max);
        let up = 2f64.powi(1022 - largest.log2().ceil() as i32);
        for scale in [1.0, up, 2f64.powi(-1074)] {
            let f = |v: Point| Point::new(v.x * scale, v.y * scale);
            let (Ok(ps), Ok(qs)) = (p.map(f), q.map(f)) else {
                continue; // a scaling that merges vertices
            };
            let lp = LinkedPolygon::from_convex_shuffled(&ps, &mut rng);
            let lq = LinkedPolygon::from_convex_shuffled(&qs, &mut rng);
            for _ in 0..4 {
                let d = Clm.derive_in(Exact, &lp, &lq, &mut rng, &mut ws, &mut ());
                let Derivation::Certified(c) = d else {
                    panic!("{family} ×{scale:e} #{i}: no certificate under the exact kernel");
                };
                assert!(c.intersects(), "{family} ×{scale:e} #{i}: {c:?}");
                assert_eq!(verify_linked(&lp, &lq, &c), Ok(()), "{family} ×{scale:e} #{i}");
                straddles += usize::from(ws.lp.straddle().is_some());
                mixed += usize::from(ws.lp.mixed().is_some());
                checked += 1;
            }
        }
    }
    assert!(checked > 2000, "{checked}");
    assert!(straddles > 20 && mixed > 20, "{straddles} {mixed} of {checked}");
}

/// Intersecting Rotated pairs (the cost measurement's family) and the lattice
/// families at sizes where the samples outgrow the LP's prefix: every certificate
/// verifies, including those of queries whose samples the chain walk found meeting
/// (no LP witness: the sets are searched as convex polygons), which occur.
#[test]
fn walk_meets_are_certified_on_the_convex_sets() {
    let mut rng = SmallRng::seed_from_u64(0xc0a5);
    let mut ws = ClmWorkspace::default();
    let families = [
        Family::Rotated,
        Family::SharedEdge,
        Family::VertexOnEdge,
        Family::Nested,
    ];
    let (mut walked, mut checked) = (0, 0);
    for i in 0..160 {
        let family = families[i % families.len()];
        let (p, q) = generate::pair(family, 400 + 13 * i, Relation::Intersecting, &mut rng);
        let lp = LinkedPolygon::from_convex_shuffled(&p, &mut rng);
        let lq = LinkedPolygon::from_convex_shuffled(&q, &mut rng);
        for _ in 0..20 {
            let d = Clm.derive_in(Exact, &lp, &lq, &mut rng, &mut ws, &mut ());
            let Derivation::Certified(c) = d else {
                panic!("{family} #{i}: no certificate under the exact kernel");
            };
            assert!(c.intersects(), "{family} #{i}: {c:?}");
            assert_eq!(verify_linked(&lp, &lq, &c), Ok(()), "{family} #{i}");
            walked += usize::from(ws.lp.witness_points().is_empty());
            checked += 1;
        }
    }
    assert!(walked > 10, "{walked} of {checked}");
}

/// Intersecting Rotated pairs (the cost measurement's family) at sizes where the
/// 12-point prefixes decide: the LP's last step leaves many certified queries
/// without a witness, and nearly all of those are certified by a drawn vertex
/// inside the other sample's quadrilateral (`drawn_witness`); with the rounds
/// capped at 0 every such query goes on to the cone search and the chord walk
/// instead. Every certificate verifies either way, and the certified call leaves
/// the caller's generator where the plain call does.
#[test]
fn drawn_witnesses_verify_and_the_walk_takes_over_when_the_rounds_run_out() {
    for cap in [None, Some(0)] {
        let mut rng = SmallRng::seed_from_u64(0xd7a3);
        let (mut ws, mut plain_ws) = (ClmWorkspace::default(), ClmWorkspace::default());
        // Without the prefix test, which answers most of these queries before any
        // LP and so before the draws.
        let clm = super::ClmVariant {
            prefix_quads: false,
            ..super::ClmVariant::default()
        };
        ws.draws.rounds = cap;
        let mut checked = 0;
        for i in 0..24 {
            let (p, q) = generate::pair(
                Family::Rotated,
                1 << (8 + i % 5),
                Relation::Intersecting,
                &mut rng,
            );
            let lp = LinkedPolygon::from_convex_shuffled(&p, &mut rng);
            let lq = LinkedPolygon::from_convex_shuffled(&q, &mut rng);
            for _ in 0..40 {
                let mut plain_rng = rng.clone();
                let plain = clm.intersects_in(Exact, &lp, &lq, &mut plain_rng, &mut plain_ws, &mut ());
                let d = clm.derive_in(Exact, &lp, &lq, &mut rng, &mut ws, &mut ());
                // The draws come from the workspace's generator: the caller's is
                // where the plain call leaves it.
                assert!(plain && rng == plain_rng, "#{i} (cap {cap:?})");
                let Derivation::Certified(c) = d else {
                    panic!("#{i} (cap {cap:?}): no certificate under the exact kernel");
                };
                assert!(c.intersects(), "#{i} (cap {cap:?}): {c:?}");
                assert_eq!(verify_linked(&lp, &lq, &c), Ok(()), "#{i} (cap {cap:?})");
                checked += 1;
            }
        }
        let (found, walked) = (ws.draws.found, ws.draws.walked);
        match cap {
            None => assert!(
                found > 100 && walked * 10 < found,
                "{found} drawn, {walked} walked of {checked}"
            ),
            _ => assert!(
                found == 0 && walked > 100,
                "{found} drawn, {walked} walked of {checked}"
            ),
        }
    }
}

#[test]
fn below_is_in_range_and_uniform() {
    let mut rng = SmallRng::seed_from_u64(11);
    for n in [1u32, 2, 3, 7, 1000, u32::MAX] {
        for _ in 0..1000 {
            assert!(below(&mut rng, n) < n);
        }
    }
    // n = 3: a rejection threshold above zero (2^32 mod 3 = 1); each value ~1/3.
    let mut hits = [0u32; 3];
    for _ in 0..30_000 {
        hits[below(&mut rng, 3) as usize] += 1;
    }
    assert!(hits.iter().all(|&h| (9_400..10_600).contains(&h)), "{hits:?}");
}

#[test]
fn shuffle_keeps_positions_and_points_together() {
    let mut rng = SmallRng::seed_from_u64(12);
    let mut first = [0u32; 5];
    for _ in 0..2000 {
        let mut positions: Vec<u32> = (0..5).collect();
        let mut points: Vec<Point> = (0..5).map(|i| Point::new(i as f64, -(i as f64))).collect();
        shuffle(&mut positions, &mut points, &mut rng);
        for (&i, x) in positions.iter().zip(&points) {
            assert_eq!(*x, Point::new(i as f64, -(i as f64)));
        }
        let mut sorted = positions.clone();
        sorted.sort_unstable();
        assert_eq!(sorted, [0, 1, 2, 3, 4]);
        first[positions[0] as usize] += 1;
        // Positions alone.
        shuffle(&mut positions, &mut [], &mut rng);
        sorted.clone_from(&positions);
        sorted.sort_unstable();
        assert_eq!(sorted, [0, 1, 2, 3, 4]);
    }
    // Every position comes first about 2000/5 times.
    assert!(first.iter().all(|&h| (300..500).contains(&h)), "{first:?}");
}

#[test]
fn fisher_yates_draws_distinct_positions_and_restores_its_array() {
    let mut rng = SmallRng::seed_from_u64(3);
    let (mut perm, mut swaps, mut out) = (Vec::new(), Vec::new(), Vec::new());
    let mut hits = [0u32; 10];
    // A larger polygon first: its array serves the smaller one.
    fisher_yates(25, 5, &mut rng, &mut perm, &mut swaps, &mut out);
    for r in [0, 1, 3, 9, 10, 20] {
        for _ in 0..200 {
            out.clear();
            fisher_yates(10, r, &mut rng, &mut perm, &mut swaps, &mut out);
            assert_eq!(out.len(), r.min(10));
            let mut sorted = out.clone();
            sorted.sort_unstable();
            sorted.dedup();
            assert_eq!(sorted.len(), out.len(), "distinct: {out:?}");
            assert!(out.iter().all(|&i| i < 10));
            assert_eq!(perm, (0..perm.len() as u32).collect::<Vec<u32>>(), "restored");
            if r == 1 {
                hits[out[0] as usize] += 1;
            }
        }
    }
    // Every position is drawn (200 single draws over 10 positions).
    assert!(hits.iter().all(|&h| h > 0), "{hits:?}");
}
