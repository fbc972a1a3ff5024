//! Traces (`polysect::intersect::trace`): on every generator family (random, touching,
//! one-ulp gaps, nested) and on the fuzz driver's arbitrary-coordinate hulls, under the
//! exact kernel, a trace of each algorithm ends in the same answer and certificate as
//! the certified call without a tracer (CLM and Convert from generators in the same
//! state), the certificate verifies, and the steps are what the algorithm reports:
//! kept vertices only shrink, each step's pruned vertices were kept by the previous
//! one, and the last step carries the answer.
//!
//! `POLYSECT_TRACE_PAIRS` scales the number of pairs per family (default 100).

use polysect::generate::{self, Family, Relation};
use polysect::intersect::{Algorithm, Role, Shape, Span, Trace, trace_rng, verify};
use polysect::{ConvexPolygon, Exact};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

fn pairs_per_family() -> usize {
    std::env::var("POLYSECT_TRACE_PAIRS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(100)
}

fn flags(spans: &[Span], n: usize) -> Vec<bool> {
    let mut f = vec![false; n];
    for s in spans {
        for i in s.indices(n) {
            f[i] = true;
        }
    }
    f
}

/// Checks one pair with every algorithm; returns the number of steps recorded.
fn check(p: &ConvexPolygon, q: &ConvexPolygon, seed: u64, what: &str) -> usize {
    let mut steps = 0;
    for &algorithm in Algorithm::ALL {
        let t: Trace = trace_rng(algorithm, Exact, p, q, &mut SmallRng::seed_from_u64(seed));
        let (plain, _) = algorithm.run_certified_with_rng(Exact, p, q, &mut SmallRng::seed_from_u64(seed));
        assert_eq!(
            t.certificate, plain,
            "{algorithm} {what}: trace and certified call differ"
        );
        assert_eq!(verify(p, q, &t.certificate), Ok(()), "{algorithm} {what}");
        let last = t.steps.last().expect("a last step");
        assert_eq!(last.answer, Some(plain.intersects()), "{algorithm} {what}");
        assert!(t.steps[..t.steps.len() - 1].iter().all(|s| s.answer.is_none()));
        // Kept sets shrink; pruned vertices were kept before and are not now.
        let sizes = [p.len(), q.len()];
        let mut before = [vec![true; sizes[0]], vec![true; sizes[1]]];
        for (k, step) in t.steps.iter().enumerate() {
            if step.kept[0].is_empty() && step.kept[1].is_empty() {
                continue; // CLM's steps, fallbacks and the last step keep no ranges
            }
            for side in 0..2 {
                let now = flags(&step.kept[side], sizes[side]);
                let pruned = flags(&step.pruned[side], sizes[side]);
                for i in 0..sizes[side] {
                    assert!(
                        !now[i] || before[side][i],
                        "{algorithm} {what} step {k}: kept grew"
                    );
                    assert_eq!(
                        pruned[i],
                        before[side][i] && !now[i],
                        "{algorithm} {what} step {k}"
                    );
                }
                before[side] = now;
            }
        }
        let reports = t.steps.len() - 1;
        match algorithm {
            // Nothing but a note where a fallback completed the certificate.
            Algorithm::Linear | Algorithm::Convert => assert!(
                t.steps
                    .iter()
                    .all(|s| s.kept.iter().all(Vec::is_empty) && s.answer.is_some() != s.marks.is_empty()),
                "{algorithm} {what}"
            ),
            // The sample and its first LP at least.
            Algorithm::Clm => {
                assert!(reports >= 2, "{algorithm} {what}");
                assert!(
                    t.steps[0].marks.iter().all(|m| m.role == Role::Sample),
                    "{algorithm} {what}"
                );
            }
            _ => {}
        }
        steps += reports;
    }
    steps
}

#[test]
fn traces_end_in_the_certified_answer_on_every_family() {
    let mut rng = SmallRng::seed_from_u64(0x7ace_0001);
    let mut steps = 0;
    for &family in Family::ALL {
        for i in 0..pairs_per_family() {
            let n = (2f64.powf(rng.random_range(1.585..9.0)) as usize).max(3);
            let relation = [Relation::Intersecting, Relation::Disjoint, Relation::Any][i % 3];
            let (p, q) = generate::pair(family, n, relation, &mut rng);
            steps += check(&p, &q, rng.random(), &format!("{family} n={n} {relation:?} #{i}"));
        }
    }
    assert!(steps > 0);
}

/// (The fuzz decoder is built with the `protocol` feature.)
#[cfg(feature = "protocol")]
#[test]
fn traces_end_in_the_certified_answer_on_arbitrary_hulls() {
    use polysect::fuzzing::Decoder;
    use polysect::polygon::convex_hull;
    // The fuzz driver's inputs: random bytes decoded into points, their hulls.
    let mut tested = 0;
    for seed in 0..pairs_per_family() as u64 * 20 {
        let mut rng = SmallRng::seed_from_u64(0x7ace_0002 + seed);
        let len = rng.random_range(0..=300);
        let bytes: Vec<u8> = (0..len).map(|_| rng.random()).collect();
        let mut d = Decoder::new(&bytes);
        let (a, b) = (d.points(16), d.points(16));
        let (Ok(p), Ok(q)) = (convex_hull(&a), convex_hull(&b)) else {
            continue;
        };
        check(&p, &q, seed, &format!("bytes seed {seed}"));
        tested += 1;
    }
    assert!(tested > 10, "only {tested} pairs reached the checks");
}

#[test]
fn logarithmic_traces_prune_and_draw_their_state() {
    // Two large disjoint polygons: every logarithmic algorithm reports steps that prune.
    let p = generate::regular_polygon(4096, 1.0);
    let q = p.map(|v| polysect::Point::new(v.x + 1.43, v.y + 1.42)).unwrap();
    for &algorithm in Algorithm::LOGARITHMIC {
        let t = trace_rng(algorithm, Exact, &p, &q, &mut SmallRng::seed_from_u64(1));
        assert!(!t.intersects());
        let pruned: usize = t
            .steps
            .iter()
            .flat_map(|s| s.pruned.iter().flatten())
            .map(|s| s.len)
            .sum();
        let texts: Vec<&str> = t.steps.iter().map(|s| s.text.as_str()).collect();
        assert!(
            pruned > 4096,
            "{algorithm}: only {pruned} vertices pruned: {texts:#?}"
        );
        assert!(
            t.steps.len() > 3 && t.steps.len() < 80,
            "{algorithm}: {} steps",
            t.steps.len()
        );
        let expected = match algorithm {
            Algorithm::Barba => Role::Triangle,
            Algorithm::Dobkin => Role::Bound,
            _ => Role::Pencil,
        };
        assert!(
            t.steps[0].marks.iter().any(|m| m.role == expected),
            "{algorithm}: no {expected:?} mark"
        );
        let last = t.steps.last().unwrap();
        assert!(
            last.marks
                .iter()
                .any(|m| m.role == Role::Separator && matches!(m.shape, Shape::Line(..))),
            "{algorithm}: the last step draws no separating line"
        );
    }
    // CLM: samples, LPs with their lines, walks.
    let t = trace_rng(Algorithm::Clm, Exact, &p, &q, &mut SmallRng::seed_from_u64(2));
    assert!(
        t.steps
            .iter()
            .any(|s| s.marks.iter().any(|m| m.role == Role::Separator))
    );
    assert!(
        t.steps
            .iter()
            .any(|s| s.marks.iter().any(|m| m.role == Role::Chain))
    );
}
