use super::ordering::{OrderScratch, boundary_order};
use super::sampling::{below, fisher_yates, shuffle};
use super::{Clm, ClmWorkspace};
use crate::LinkedPolygon;
use crate::generate::{self, Family, Relation, pair};
use crate::intersect::LinkedEngine;
use crate::intersect::clm::witness::{
    Cone, Radon, WitnessVertex, cone_witness, end_in_triangle, in_triangles, resolve_linked_chords,
    straddle_certificate, witness_certificate,
};
use crate::intersect::{Certificate, Derivation, Which, verify_linked};
use crate::kernel::{Exact, Fast, Point, SegmentContact, segment_contact};
use crate::lp::WitnessPoint;
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

// The witness code (witness.rs).

/// A witness point at (x, y) of polygon `of`, at arena position `pos`.
fn w(x: f64, y: f64, of: Which, pos: usize) -> WitnessVertex {
    WitnessVertex {
        point: Point::new(x, y),
        of,
        pos: Some(pos),
    }
}

fn positions_in_order(lp: &LinkedPolygon) -> Vec<usize> {
    let mut at = lp.position(lp.first()).unwrap();
    (0..lp.len())
        .map(|_| {
            let here = at;
            at = lp.next_at(at);
            here
        })
        .collect()
}

/// Chords of crossing polygons resolved by walks on linked polygons, with the walks'
/// starts chosen by `f64` distances: at ordinary scale, where those distances
/// overflow (2^1000: every one is infinite or NaN) and where they underflow to zero
/// (2^-1000), so that the exact check and the fallback to the chord's own end are
/// used. Every certificate found verifies, and chords that meet always give one.
#[test]
fn linked_chords_resolve_at_every_scale() {
    use crate::generate::{Family, Relation, map_pair, pair};
    use rand::SeedableRng;
    let mut rng = rand::rngs::SmallRng::seed_from_u64(0x11c4);
    let scales = [1.0, 2f64.powi(1000), 2f64.powi(-1000)];
    let mut resolved = [0; 3];
    for round in 0..6 {
        let base = pair(Family::Rotated, 40 + 7 * round, Relation::Intersecting, &mut rng);
        for (&scale, resolved) in scales.iter().zip(&mut resolved) {
            let Some((p, q)) = map_pair(&base, |v| Point::new(v.x * scale, v.y * scale)) else {
                continue;
            };
            let lp = LinkedPolygon::from_convex_shuffled(&p, &mut rng);
            let lq = LinkedPolygon::from_convex_shuffled(&q, &mut rng);
            let (op, oq) = (positions_in_order(&lp), positions_in_order(&lq));
            // Every fifth vertex serves as a walk's possible start.
            let starts = |lp: &LinkedPolygon, o: &[usize]| -> (Vec<u32>, Vec<Point>) {
                o.iter().step_by(5).map(|&i| (i as u32, lp.point_at(i))).unzip()
            };
            let (sp, sq) = (starts(&lp, &op), starts(&lq, &oq));
            for i in (0..op.len()).step_by(2) {
                for j in (0..oq.len()).step_by(2) {
                    let a = (op[i], op[(i + 7) % op.len()]);
                    let b = (oq[j], oq[(j + 9) % oq.len()]);
                    let meets = segment_contact(
                        Exact,
                        lp.point_at(a.0),
                        lp.point_at(a.1),
                        lq.point_at(b.0),
                        lq.point_at(b.1),
                    )
                    .meets();
                    let c = resolve_linked_chords(Exact, &lp, a, (&sp.0, &sp.1), &lq, b, (&sq.0, &sq.1));
                    assert_eq!(c.is_some(), meets, "scale {scale}, chords {a:?} {b:?}");
                    if let Some(c) = c {
                        assert_eq!(verify_linked(&lp, &lq, &c), Ok(()), "scale {scale}: {c:?}");
                        *resolved += 1;
                    }
                }
            }
        }
    }
    assert!(
        resolved.iter().all(|&r| r > 20),
        "chords resolved per scale: {resolved:?}"
    );
}

/// The LP's witness points: a vertex inside (on a vertex, on an edge, strictly
/// inside), repeats, and crossing segments with no vertex inside.
#[test]
fn witness_points_give_a_vertex_inside_or_chords() {
    let (p, q) = (Which::P, Which::Q);
    // A point of P on an edge of Q's triangle (touching), repeated.
    let pts = [
        w(1., 0., p, 0),
        w(1., 0., p, 0),
        w(5., 5., p, 1),
        w(0., 0., q, 2),
        w(2., 0., q, 3),
        w(0., 2., q, 4),
    ];
    match witness_certificate(Exact, pts.into_iter()) {
        Radon::Inside(Certificate::VertexInside { of, point }) => {
            assert_eq!((of, point), (Which::P, Point::new(1., 0.)));
        }
        _ => panic!("expected a vertex inside"),
    }
    // A vertex of Q strictly inside P's triangle, P's points listed after Q's.
    let pts = [
        w(1., 1., q, 0),
        w(9., 9., q, 1),
        w(0., 0., p, 2),
        w(4., 0., p, 3),
        w(0., 4., p, 4),
    ];
    assert!(matches!(
        witness_certificate(Exact, pts.into_iter()),
        Radon::Inside(Certificate::VertexInside { of: Which::Q, .. })
    ));
    // Two crossing segments, no vertex inside: the chords with their positions.
    let pts = [
        w(-1., 0., p, 7),
        w(1., 0., p, 8),
        w(0., -1., q, 5),
        w(0., 1., q, 6),
    ];
    match witness_certificate(Exact, pts.into_iter()) {
        Radon::Chords(a, b) => {
            let (mut a, mut b) = (a.map(Option::unwrap), b.map(Option::unwrap));
            a.sort_unstable();
            b.sort_unstable();
            assert_eq!((a, b), ([7, 8], [5, 6]));
        }
        _ => panic!("expected crossing chords"),
    }
    // Apart: nothing.
    let pts = [w(0., 0., p, 0), w(1., 0., p, 1), w(5., 5., q, 2), w(6., 5., q, 3)];
    assert!(matches!(
        witness_certificate(Exact, pts.into_iter()),
        Radon::Nothing
    ));
    // A one-ulp gap between a vertex of P and Q's edge: no contact.
    let below = -f64::from_bits(1);
    let pts = [
        w(1., below, p, 0),
        w(1., -3., p, 1),
        w(0., 0., q, 2),
        w(2., 0., q, 3),
        w(1., 2., q, 4),
    ];
    assert!(matches!(
        witness_certificate(Exact, pts.into_iter()),
        Radon::Nothing
    ));
}

#[test]
fn last_step_witnesses_give_a_vertex_inside_or_chords() {
    let (p, q) = (Which::P, Which::Q);
    let tri = [w(0., 0., q, 0), w(4., 0., q, 1), w(0., 4., q, 2)];
    // x on the triangle's edge (touching): a vertex inside.
    match straddle_certificate(Exact, [w(2., 2., p, 5), w(9., 9., p, 6)], tri) {
        Radon::Inside(Certificate::VertexInside { of, point }) => {
            assert_eq!((of, point), (Which::P, Point::new(2., 2.)));
        }
        _ => panic!("expected a vertex inside"),
    }
    // x one ulp beyond that edge: the segment from x crosses the triangle's edges.
    let beyond = 2f64 + f64::EPSILON * 2.0;
    match straddle_certificate(Exact, [w(beyond, 2., p, 5), w(-1., 1., p, 6)], tri) {
        Radon::Chords(a, b) => {
            assert_eq!(a, [Some(5), Some(6)]);
            assert!(b.iter().all(Option::is_some));
        }
        _ => panic!("expected crossing chords"),
    }
    // y₀ equal to a bound: segment against segment, touching at a vertex.
    let seg = [w(0., 0., q, 0), w(4., 0., q, 1), w(4., 0., q, 1)];
    match straddle_certificate(Exact, [w(2., 0., p, 5), w(2., 3., p, 6)], seg) {
        Radon::Inside(Certificate::VertexInside { of, point }) => {
            assert_eq!((of, point), (Which::P, Point::new(2., 0.)));
        }
        _ => panic!("expected a vertex inside"),
    }
    // ... and crossing properly; extreme coordinates are carried exactly.
    let big = f64::MAX / 4.0;
    let seg = [w(-big, 0., q, 0), w(big, 0., q, 1), w(big, 0., q, 1)];
    assert!(matches!(
        straddle_certificate(Exact, [w(0., big, p, 5), w(1., -big, p, 6)], seg),
        Radon::Chords(..)
    ));
    // The mixed case: y in a triangle of the other polygon, boundary included, and
    // not one ulp outside it; degenerate triangles are skipped.
    let tiny = f64::from_bits(1);
    let tri = [w(0., 0., p, 0), w(4. * tiny, 0., p, 1), w(0., 4. * tiny, p, 2)];
    let line = [w(0., 0., p, 0), w(1., 1., p, 1), w(2., 2., p, 2)];
    assert_eq!(
        in_triangles(Exact, w(2. * tiny, 2. * tiny, q, 9), &[line, tri]),
        Some(Certificate::VertexInside {
            of: Which::Q,
            point: Point::new(2. * tiny, 2. * tiny)
        })
    );
    assert_eq!(
        in_triangles(Exact, w(3. * tiny, 2. * tiny, q, 9), &[line, tri]),
        None
    );
    // A repeated vertex (the LP's bound equal to its previous tangent point) is
    // skipped by comparing points, even for y at that vertex; the next triangle
    // still counts, here with y one ulp inside its hypotenuse's end.
    let repeated = [w(0., 0., p, 0), w(4. * tiny, 0., p, 1), w(4. * tiny, 0., p, 1)];
    assert_eq!(in_triangles(Exact, w(4. * tiny, 0., q, 9), &[repeated]), None);
    assert_eq!(
        in_triangles(Exact, w(3. * tiny, tiny, q, 9), &[repeated, tri]),
        Some(Certificate::VertexInside {
            of: Which::Q,
            point: Point::new(3. * tiny, tiny)
        })
    );
    assert_eq!(
        in_triangles(Exact, w(3. * tiny, 2. * tiny, q, 9), &[repeated, tri]),
        None
    );
}

/// The cone search on hand-made examined sets (A's points, then B's, the violating
/// point x of A last): a point of B in the cone's triangle (inside, and exactly on
/// its side), none when it is one ulp outside, x in a triangle of B's points, and
/// two crossing segments when B's hull only crosses the triangle.
#[test]
fn cone_witness_finds_points_in_the_triangle_or_crossing_segments() {
    let a = |x: f64, y: f64, i: usize| WitnessPoint {
        point: Point::new(x, y),
        in_b: false,
        index: Some(i),
    };
    let b = |x: f64, y: f64, i: usize| WitnessPoint {
        point: Point::new(x, y),
        in_b: true,
        index: Some(i),
    };
    let x = a(0.0, 2.0, 3);
    let own = [a(-2.0, 0.0, 0), a(2.0, 0.0, 1), a(0.0, -1.0, 2)];
    let of = |in_b: bool| if in_b { Which::Q } else { Which::P };
    let run = |others: &[WitnessPoint], chords: bool| {
        let pts: Vec<WitnessPoint> = own.iter().chain(others).chain([&x]).copied().collect();
        cone_witness(Exact, x, || pts.clone().into_iter(), of, chords)
    };
    let inside = |c: Cone| match c {
        Cone::Inside(Certificate::VertexInside { of, point }) => Some((of, point)),
        _ => None,
    };
    // Strictly inside, and on the side x → (2, 0) (the line x + y = 2).
    assert_eq!(
        inside(run(&[b(5.0, 5.0, 0), b(0.0, 1.0, 1)], false)),
        Some((Which::Q, Point::new(0.0, 1.0)))
    );
    assert_eq!(
        inside(run(&[b(5.0, 5.0, 0), b(1.0, 1.0, 1)], false)),
        Some((Which::Q, Point::new(1.0, 1.0)))
    );
    // One ulp beyond that side: not inside, and no segment asked for.
    let up = f64::from_bits(1f64.to_bits() + 1);
    assert!(matches!(
        run(&[b(5.0, 5.0, 0), b(1.0, up, 1)], false),
        Cone::Nothing
    ));
    // x in the triangle of B's points, none of which is in the cone's triangle.
    assert_eq!(
        inside(run(&[b(-1.0, 1.9, 0), b(1.0, 1.9, 1), b(0.0, 3.0, 2)], false)),
        Some((Which::P, Point::new(0.0, 2.0)))
    );
    // B's segment y = 1.5 crosses the triangle: two crossing segments.
    match run(&[b(-1.0, 1.5, 0), b(1.0, 1.5, 1)], true) {
        Cone::Chords([s, e], [u, v]) => {
            assert_eq!(s, x);
            assert!(!s.in_b && !e.in_b && u.in_b && v.in_b);
            assert_eq!(
                segment_contact(Exact, s.point, e.point, u.point, v.point),
                SegmentContact::Crossing
            );
        }
        _ => panic!("no crossing segments"),
    }
    // x's own set seen as one point (repeated): no cone, and B's point on the segment
    // from x to it is not taken for inside; x itself in B's triangle still is.
    let single = [a(2.0, 0.0, 0), a(2.0, 0.0, 1)];
    let run1 = |others: &[WitnessPoint]| {
        let pts: Vec<WitnessPoint> = single.iter().chain(others).chain([&x]).copied().collect();
        cone_witness(Exact, x, || pts.clone().into_iter(), of, false)
    };
    assert!(matches!(run1(&[b(1.0, 1.0, 0), b(5.0, 5.0, 1)]), Cone::Nothing));
    assert_eq!(
        inside(run1(&[b(-1.0, 1.9, 0), b(1.0, 1.9, 1), b(0.0, 3.0, 2)])),
        Some((Which::P, Point::new(0.0, 2.0)))
    );
}

/// An end of an edge crossing a chord in the triangle of the chord and the farthest
/// point on its side: strictly inside, exactly on a side, and none when the only
/// point on that side makes a triangle that misses it by one ulp.
#[test]
fn end_in_triangle_is_exact() {
    let pt = Point::new;
    let (s, t) = (pt(0.0, 0.0), pt(4.0, 0.0));
    let edge = (pt(2.0, -0.5), pt(2.5, 0.5));
    assert_eq!(
        end_in_triangle(Exact, edge, (s, t), &[pt(1.0, 1.0), pt(2.0, 3.0), pt(9.0, -9.0)]),
        Some(pt(2.0, -0.5))
    );
    // Only a point above the chord: the end above it.
    let w = pt(2.5, 3.0);
    assert_eq!(end_in_triangle(Exact, edge, (s, t), &[w]), Some(pt(2.5, 0.5)));
    // On the side s–w of the triangle s, t, w with w = (5, 1): (2.5, 0.5) is on it.
    assert_eq!(
        end_in_triangle(Exact, edge, (s, t), &[pt(5.0, 1.0)]),
        Some(pt(2.5, 0.5))
    );
    // One ulp above that side: outside.
    let above = pt(2.5, f64::from_bits(0.5f64.to_bits() + 1));
    assert_eq!(
        end_in_triangle(Exact, (edge.0, above), (s, t), &[pt(5.0, 1.0)]),
        None
    );
    assert_eq!(end_in_triangle(Exact, edge, (s, t), &[]), None);
    // 32 points: every other one is tried first. Near the chord's line (heights
    // 2^-40 above it), none of those makes a triangle holding the end (2.5, 0.5),
    // but the one between them (index 1) does: found by the pass over all.
    let low = 2f64.powi(-40);
    let mut many: Vec<Point> = (0..32).map(|i| pt(f64::from(i) * 0.1, low)).collect();
    many[1] = pt(2.5, 3.0);
    assert_eq!(end_in_triangle(Exact, edge, (s, t), &many), Some(pt(2.5, 0.5)));
    // The same point at index 2 is among the first tried; one ulp outside the
    // triangle s, t, (5, 1) the end is outside with every point tried.
    many.swap(1, 2);
    assert_eq!(end_in_triangle(Exact, edge, (s, t), &many), Some(pt(2.5, 0.5)));
    many[2] = pt(5.0, 1.0);
    assert_eq!(end_in_triangle(Exact, edge, (s, t), &many), Some(pt(2.5, 0.5)));
    assert_eq!(end_in_triangle(Exact, (edge.0, above), (s, t), &many), None);
}
