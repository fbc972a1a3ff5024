//! LinkedPolygon: uniform sampling (chi-square with a bound a biased sampler fails),
//! edit churn under the invariant checker.

use polysect::generate::regular_polygon;
use polysect::polygon::SampleWorkspace;
use polysect::{EditError, LinkedPolygon, Point};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

const SEED: u64 = 0x05a1_19e5;

/// Pearson's statistic for observed counts against equal expected counts.
fn chi_square(counts: &[u64]) -> f64 {
    let total: u64 = counts.iter().sum();
    let expected = total as f64 / counts.len() as f64;
    counts
        .iter()
        .map(|&c| (c as f64 - expected).powi(2) / expected)
        .sum()
}

/// For 49 degrees of freedom the 99.999th percentile of chi-square is about 103.
const CHI2_BOUND_49: f64 = 103.0;

fn thinned_polygon(rng: &mut SmallRng) -> LinkedPolygon {
    // 200 vertices, then 150 random removals: sampling must be uniform over the 50 left.
    let mut p = LinkedPolygon::from_convex_shuffled(&regular_polygon(200, 1.0), rng);
    for _ in 0..150 {
        let v = p.random_vertex(rng);
        p.remove(v).unwrap();
    }
    p.debug_validate().unwrap();
    assert_eq!(p.len(), 50);
    p
}

fn index_of(p: &LinkedPolygon) -> std::collections::HashMap<polysect::VertexId, usize> {
    p.iter().enumerate().map(|(i, (id, _))| (id, i)).collect()
}

#[test]
fn single_samples_are_uniform_after_removals() {
    let mut rng = SmallRng::seed_from_u64(SEED);
    let p = thinned_polygon(&mut rng);
    let index = index_of(&p);
    let mut counts = vec![0u64; 50];
    for _ in 0..200_000 {
        counts[index[&p.random_vertex(&mut rng)]] += 1;
    }
    let chi2 = chi_square(&counts);
    assert!(chi2 < CHI2_BOUND_49, "chi-square {chi2}");

    // The bound has power: the classic sparse-arena sampler (draw a slot of a 200-slot
    // arena with 150 holes, take the next live slot) fails it.
    let mut slots: Vec<usize> = (0..200).collect();
    for i in (1..200).rev() {
        slots.swap(i, rng.random_range(0..=i));
    }
    let mut live: Vec<usize> = slots[..50].to_vec();
    live.sort();
    let mut biased = vec![0u64; 50];
    for _ in 0..200_000 {
        let r = rng.random_range(0..200);
        let k = live.iter().position(|&s| s >= r).unwrap_or(0);
        biased[k] += 1;
    }
    let chi2_biased = chi_square(&biased);
    assert!(
        chi2_biased > CHI2_BOUND_49,
        "biased sampler passed: {chi2_biased}"
    );
}

#[test]
fn distinct_samples_are_uniform_subsets() {
    let mut rng = SmallRng::seed_from_u64(SEED + 1);
    let p = thinned_polygon(&mut rng);
    let index = index_of(&p);
    let mut ws = SampleWorkspace::default();
    for k in [5usize, 30] {
        let mut counts = vec![0u64; 50];
        let mut out = Vec::new();
        let rounds = 40_000;
        for _ in 0..rounds {
            out.clear();
            p.sample_positions(k, &mut rng, &mut ws, &mut out);
            let mut seen = std::collections::HashSet::new();
            for &pos in &out {
                assert!(seen.insert(pos), "duplicate in sample");
                counts[index[&p.id_at(pos as usize)]] += 1;
            }
        }
        // Inclusion counts: each vertex with probability k/50; scale Pearson's statistic by
        // 1/(1 − k/50), the variance of a Bernoulli inclusion relative to a Poisson count.
        let chi2 = chi_square(&counts) / (1.0 - k as f64 / 50.0);
        assert!(chi2 < CHI2_BOUND_49, "k = {k}: chi-square {chi2}");
    }
}

#[test]
fn edit_churn_keeps_every_invariant() {
    let mut rng = SmallRng::seed_from_u64(SEED + 2);
    let mut p = LinkedPolygon::from_convex_shuffled(&regular_polygon(64, 1.0), &mut rng);
    let (mut inserted, mut removed, mut moved, mut refused) = (0, 0, 0, 0);
    for step in 0..20_000 {
        let v = p.random_vertex(&mut rng);
        let before = p.to_convex();
        let result = match rng.random_range(0..3) {
            0 => {
                // A point near the edge midpoint, pushed outwards by a random amount.
                let (a, b) = (p.point(v).unwrap(), p.point(p.next(v).unwrap()).unwrap());
                let (mx, my) = ((a.x + b.x) / 2.0, (a.y + b.y) / 2.0);
                let push = rng.random_range(-0.01..0.02);
                p.insert_after(v, Point::new(mx * (1.0 + push), my * (1.0 + push)))
                    .map(|_| inserted += 1)
            }
            1 if p.len() > 16 => p.remove(v).map(|_| removed += 1),
            _ => {
                let a = p.point(v).unwrap();
                let f = 1.0 + rng.random_range(-0.01..0.01);
                p.move_vertex(v, Point::new(a.x * f, a.y * f)).map(|_| moved += 1)
            }
        };
        if let Err(e) = result {
            assert!(
                matches!(
                    e,
                    EditError::WouldBreakConvexity { .. } | EditError::TooFewVertices
                ),
                "{e}"
            );
            assert_eq!(p.to_convex(), before, "a refused edit changed the polygon");
            refused += 1;
        }
        if step % 97 == 0 {
            p.debug_validate().unwrap_or_else(|e| panic!("step {step}: {e}"));
        }
    }
    p.debug_validate().unwrap();
    assert!(
        inserted > 100 && removed > 100 && moved > 100 && refused > 100,
        "{inserted} {removed} {moved} {refused}"
    );
}

/// The reference for a translation: round every vertex, then ask the validating
/// constructor whether the rounded list, as given, is already a strictly convex
/// counter-clockwise polygon (nothing cleaned, nothing reordered).
fn translated_reference(p: &LinkedPolygon, dx: f64, dy: f64) -> Option<Vec<Point>> {
    let moved: Vec<Point> = p.iter().map(|(_, v)| Point::new(v.x + dx, v.y + dy)).collect();
    match polysect::ConvexPolygon::new(moved.iter().copied()) {
        Ok(c) if c.vertices() == moved.as_slice() => Some(moved),
        _ => None,
    }
}

#[test]
fn translations_round_each_coordinate_and_are_refused_exactly_when_convexity_breaks() {
    let mut rng = SmallRng::seed_from_u64(SEED ^ 0x7a);
    let (mut accepted, mut refused) = (0, 0);
    for round in 0..3_000 {
        let n = rng.random_range(3..40);
        // Polygons from subnormal to huge scales: translations round their turns flat
        // or leave them alone.
        let exponent = match rng.random_range(0..3) {
            0 => rng.random_range(-1070..-1000),
            1 => rng.random_range(-60..60),
            _ => rng.random_range(900..1000),
        };
        let scale = 2f64.powi(exponent);
        let base = polysect::generate::regular_polygon(n, 1.0);
        let Ok(poly) = base.map(|v| Point::new(v.x * scale, v.y * scale)) else {
            continue;
        };
        let mut p = LinkedPolygon::from_convex_shuffled(&poly, &mut rng);
        let big = [1e-310, 1.0, 2f64.powi(30), 2f64.powi(52), 2f64.powi(1000), 1e308][rng.random_range(0..6)];
        let (dx, dy) = (
            big * rng.random_range(-1.0..1.0),
            big * rng.random_range(-1.0..1.0),
        );
        let ids: Vec<_> = p.iter().map(|(id, _)| id).collect();
        let before: Vec<Point> = p.iter().map(|(_, v)| v).collect();
        let want = translated_reference(&p, dx, dy);
        let overflow = before.iter().any(|v| !Point::new(v.x + dx, v.y + dy).is_finite());
        match p.translate(dx, dy) {
            Ok(()) => {
                let got: Vec<Point> = p.iter().map(|(_, v)| v).collect();
                assert_eq!(
                    Some(got),
                    want,
                    "round {round}: accepted a translation the reference refuses"
                );
                assert_eq!(
                    p.iter().map(|(id, _)| id).collect::<Vec<_>>(),
                    ids,
                    "handles survive"
                );
                p.debug_validate().unwrap();
                accepted += 1;
            }
            Err(e) => {
                assert!(
                    want.is_none() || overflow,
                    "round {round}: refused ({e}) a valid translation"
                );
                if overflow {
                    assert!(matches!(e, EditError::NonFinite { .. }), "{e}");
                }
                assert_eq!(p.iter().map(|(_, v)| v).collect::<Vec<_>>(), before, "unchanged");
                refused += 1;
            }
        }
    }
    assert!(
        accepted > 500 && refused > 500,
        "both outcomes exercised: {accepted} accepted, {refused} refused"
    );
    let mut t = LinkedPolygon::from_points([[0., 0.], [1., 0.], [0., 1.]]).unwrap();
    for bad in [(f64::NAN, 0.0), (0.0, f64::INFINITY)] {
        assert!(matches!(
            t.translate(bad.0, bad.1),
            Err(EditError::NonFinite { .. })
        ));
    }
    t.translate(f64::MAX, 0.0).unwrap_err();
    t.translate(0.0, 0.0).unwrap();
}

/// Translations that round nothing (coordinates and offsets on a common binary grid)
/// skip the boundary walk; they must still give exactly the reference's polygon.
#[test]
fn exact_translations_move_rigidly() {
    let mut rng = SmallRng::seed_from_u64(SEED ^ 0x7b);
    let grid = 2f64.powi(-20);
    for _ in 0..500 {
        let n = rng.random_range(3..200);
        let base = polysect::generate::regular_polygon(n, 1000.0);
        let Ok(poly) = base.map(|v| Point::new((v.x / grid).round() * grid, (v.y / grid).round() * grid))
        else {
            continue;
        };
        let mut p = LinkedPolygon::from_convex_shuffled(&poly, &mut rng);
        for _ in 0..20 {
            let (dx, dy) = (
                (rng.random_range(-50.0..50.0) / grid).round() * grid,
                (rng.random_range(-50.0..50.0) / grid).round() * grid,
            );
            let want = translated_reference(&p, dx, dy).expect("an exact translation is valid");
            p.translate(dx, dy).expect("accepted");
            assert_eq!(p.iter().map(|(_, v)| v).collect::<Vec<_>>(), want);
        }
        p.debug_validate().unwrap();
    }
}
