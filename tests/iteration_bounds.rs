//! Item: the thesis's iteration bounds (§4.2.1) per query, and CLM's counts (§3.3.2,
//! §4.3.1) as a [`Counts`] probe records them, on many random and adversarial inputs.
//!
//! - Barba: at most log2 P + log2 Q pruning iterations.
//! - Dobkin: at most 2·log2 P + 2·log2 Q (both chain pairs searched).
//! - Chazelle–Dobkin: the same two-chain-pairs bound as Dobkin.
//! - CLM: one to five LP calls, five and four chain walks on every disjoint pair whose
//!   samples are not the whole polygons, at most two walks before the two
//!   chain-against-chain LPs, samples of ⌈√n⌉ per polygon.
//!
//! `POLYSECT_BOUND_PAIRS` scales the number of random pairs per (family, size)
//! (default 6).

use polysect::ConvexPolygon;
use polysect::experiments::thesis::iteration_bound;
use polysect::generate::{self, Family, Relation};
use polysect::intersect::{
    Algorithm, ArrayIntersection, Barba, ChazelleDobkin, Clm, ClmWorkspace, Counts, Dobkin, Linear,
};
use polysect::intersect::{ArrayEngine, LinkedEngine};
use polysect::{Exact, LinkedPolygon, Point};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use std::f64::consts::TAU;

fn pairs_per_cell() -> usize {
    std::env::var("POLYSECT_BOUND_PAIRS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(6)
}

/// Random pairs of every generator family (steered both ways and unsteered) and
/// adversarial ones: tiny triangles near a big circle, nested polygons, very
/// unequal sizes.
fn inputs(rng: &mut SmallRng) -> Vec<(String, ConvexPolygon, ConvexPolygon)> {
    let mut out = Vec::new();
    for &family in Family::ALL {
        for n in [3, 4, 5, 7, 16, 100, 1000, 1 << 14] {
            for relation in [Relation::Any, Relation::Intersecting, Relation::Disjoint] {
                for _ in 0..pairs_per_cell() {
                    let (p, q) = generate::pair(family, n, relation, rng);
                    out.push((format!("{family} n={n} {relation:?}"), p, q));
                }
            }
        }
    }
    for log in [6, 12, 18] {
        let circle = generate::regular_polygon(1 << log, 1.0);
        for i in 0..12 {
            let t: f64 = rng.random_range(0.0..TAU);
            let r = 1.0 + [-1e-7, 1e-7, 0.0, 1e-3][i % 4];
            let (x, y) = (r * t.cos(), r * t.sin());
            let s = 1e-9;
            let tri = ConvexPolygon::new([[x, y], [x + s, y], [x, y + s]]).unwrap();
            out.push((format!("circle 2^{log} vs tiny triangle"), circle.clone(), tri));
        }
        let small = generate::regular_polygon(5, 0.5);
        out.push((
            format!("circle 2^{log} around a pentagon"),
            circle.clone(),
            small.clone(),
        ));
        let far = small.map(|v| Point::new(v.x + 3.0, v.y)).unwrap();
        out.push((format!("circle 2^{log} beside a pentagon"), circle, far));
    }
    out
}

#[test]
fn barba_and_dobkin_stay_within_the_thesis_bounds() {
    let mut rng = SmallRng::seed_from_u64(0xb00d5);
    let mut worst: Vec<(Algorithm, f64, String)> = Vec::new();
    let mut checked = 0;
    for (name, p, q) in inputs(&mut rng) {
        let truth = Linear.intersects(&p, &q);
        for (a, b) in [(&p, &q), (&q, &p)] {
            for alg in [Algorithm::Barba, Algorithm::Dobkin, Algorithm::ChazelleDobkin] {
                let mut counts = Counts::default();
                let answer = match alg {
                    Algorithm::Barba => Barba.intersects_probed(Exact, a, b, &mut counts),
                    Algorithm::Dobkin => Dobkin.intersects_probed(Exact, a, b, &mut counts),
                    _ => ChazelleDobkin.intersects_probed(Exact, a, b, &mut counts),
                };
                assert_eq!(answer, truth, "{alg} on {name}");
                let bound = iteration_bound(alg, a.len(), b.len()).unwrap();
                let slack = counts.iterations as f64 - bound;
                match worst.iter_mut().find(|w| w.0 == alg) {
                    Some(w) if w.1 >= slack => {}
                    Some(w) => *w = (alg, slack, format!("{name} ({}, {})", a.len(), b.len())),
                    None => worst.push((alg, slack, format!("{name} ({}, {})", a.len(), b.len()))),
                }
                checked += 1;
            }
        }
    }
    for (alg, slack, name) in &worst {
        println!("{alg}: iterations − bound at most {slack:.2} ({name})");
    }
    println!("{checked} queries checked");
    for (alg, slack, name) in &worst {
        assert!(*slack <= 0.0, "{alg} exceeds its bound by {slack:.2} on {name}");
    }
}

/// CLM's counts per query, kept apart: samples of ⌈√n⌉ draws (at least 3, at most the
/// polygon; repeats kept once; 12 when the first 12 draws of each decide an
/// intersection), a vertex inside the other sample's quadrilateral only on intersecting
/// pairs and then no LP but the prefixes', else the first LP on both samples, one LP
/// when the sample hulls meet, five LPs and four walks on every disjoint pair, the
/// summed work equal to its parts, and chains of expected length O(n / r) = O(√n)
/// (Chazelle–Liu–Magen, Theorem 2.1).
#[test]
fn clm_counts_are_recorded_apart_and_match_the_algorithm() {
    let mut rng = SmallRng::seed_from_u64(0x0c13);
    let mut ws = ClmWorkspace::default();
    let mut long_walks: Vec<(usize, f64)> = Vec::new();
    let mut checked = 0;
    for (name, p, q) in inputs(&mut rng) {
        let truth = Linear.intersects(&p, &q);
        let lp = LinkedPolygon::from_convex_shuffled(&p, &mut rng);
        let lq = LinkedPolygon::from_convex_shuffled(&q, &mut rng);
        let mut c = Counts::default();
        let answer = Clm.intersects_in(Exact, &lp, &lq, &mut rng, &mut ws, &mut c);
        assert_eq!(answer, truth, "clm on {name}");
        let expected = |n: usize| ((n as f64).sqrt().ceil() as usize).max(3).min(n);
        // Independent draws may repeat a vertex (about r²/2n = ½ repeats expected);
        // the sample keeps one copy. With independent draws on both sides (r ≤ n/16)
        // the first 12 of each are drawn first, and the rest only when their hulls are
        // disjoint: an intersecting query that one LP or the quadrilaterals decided may
        // have read only those.
        let independent = |n: usize| expected(n) * 16 <= n;
        let prefix_only = answer
            && c.lp_calls() <= 1
            && independent(p.len())
            && independent(q.len())
            && c.samples_p <= 12
            && c.samples_q <= 12;
        for (got, n) in [(c.samples_p, p.len()), (c.samples_q, q.len())] {
            let want = if prefix_only {
                expected(n).min(12)
            } else {
                expected(n)
            };
            assert!(got <= want && got + 8 >= want, "{name}: {got} of {n}");
        }
        assert!(c.inside <= 1, "{name}: {c:?}");
        if c.inside == 1 {
            assert!(truth, "{name}: a vertex inside on disjoint polygons");
            // Before any LP, or after the prefix LP found the prefixes' hulls disjoint.
            let prefixes = c.samples_p.min(12) + c.samples_q.min(12);
            assert!(
                c.walks.is_empty() && c.lps.iter().all(|l| l.constraints == prefixes) && c.lps.len() <= 1,
                "{name}: {c:?}"
            );
        } else {
            assert!((1..=5).contains(&c.lp_calls()), "{name}: {c:?}");
            // The prefix LP, or the LP on the whole samples.
            let prefixes = c.samples_p.min(12) + c.samples_q.min(12);
            assert!(
                [prefixes, c.samples()].contains(&c.lps[0].constraints),
                "{name}: {c:?}"
            );
        }
        assert!(c.walks.len() <= 4, "{name}: {c:?}");
        assert_eq!(
            c.iterations,
            c.lp_work() + c.chain_steps() as u64 + c.quad_tests,
            "{name}: the summed work is LP work plus chain steps plus points tested in quadrilaterals: {c:?}"
        );
        if c.lp_calls() == 1 {
            assert!(c.walks.is_empty(), "{name}: {c:?}");
        }
        let whole = c.samples_p == p.len() || c.samples_q == q.len();
        if !truth && !whole {
            assert_eq!(c.lp_calls(), 5, "{name}: {c:?}");
            assert_eq!(c.walks.len(), 4, "{name}: {c:?}");
        }
        for &w in &c.walks {
            assert!(w >= 2 && w <= p.len().max(q.len()) + 1, "{name}: walk of {w}");
        }
        let n = p.len().max(q.len());
        if n >= 4096 && !c.walks.is_empty() {
            let mean = c.chain_steps() as f64 / c.walks.len() as f64;
            long_walks.push((n, mean / (n as f64).sqrt()));
        }
        checked += 1;
    }
    let mean_ratio = long_walks.iter().map(|w| w.1).sum::<f64>() / long_walks.len() as f64;
    println!(
        "{checked} CLM queries; over {} queries with n ≥ 4096 and walks, mean vertices per walk = {mean_ratio:.2}·√n",
        long_walks.len()
    );
    assert!(long_walks.len() >= 20, "{}", long_walks.len());
    assert!(mean_ratio < 4.0, "chains longer than O(√n): {mean_ratio:.2}·√n");
}
