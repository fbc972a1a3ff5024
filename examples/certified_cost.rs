//! The cost of the certified calls beside the plain ones, for instruction counters:
//! `certified_cost ALGORITHM plain|certified intersecting|disjoint LOG2 QUERIES` runs
//! QUERIES queries of one kind on 32 Rotated pairs of 2^LOG2 vertices per polygon
//! (cycled, exact kernel). Count with e.g. `perf stat -e instructions` and subtract a
//! run with 0 queries (the setup): docs/certificates.md, "Cost". ALGORITHM is an
//! algorithm's name or one of Barba's variants (docs/thesis.md): `barba-halving` (first
//! triangle at first/middle/last), `barba-thirds` (= `barba`), and with the halving
//! triangle `barba-finish3` (finish on three edges of Q) and `barba-p-edges-first`;
//! `barba-thesis` has all three of the thesis's choices. `dobkin-lemmas` is Dobkin's
//! variant with every pruning rule by its own `if` (the thesis's Code 3.1 form),
//! `dobkin-compact` ours (= `dobkin`). `clm` runs CLM on the pairs as linked polygons
//! in shuffled arena order (one workspace, one seeded generator, as in the `clm` bench);
//! `clm-no-prefix` the same without the prefixes' quadrilaterals
//! (`ClmVariant::prefix_quads` off).
//!
//! The setup (generating the pairs with the exact kernel) costs far more than the
//! queries at large sizes, and under an instruction counter it runs for hours at 2^18.
//! `certified_cost write-pairs intersecting|disjoint LOG2 FILE`, run natively, generates
//! the same 32 pairs (same seed, same generator) and writes them to FILE with the
//! generator's position after them; a sixth argument `certified_cost ... QUERIES FILE`
//! reads them back instead of generating them (the file's relation and size must match
//! the arguments). The counted queries are the same either way: docs/certificates.md,
//! "Cost".

use polysect::generate::{self, Family, Relation};
use polysect::intersect::{
    Algorithm, ArrayIntersection, Barba, BarbaVariant, ChazelleDobkin, ClmVariant, ClmWorkspace, Dobkin,
    DobkinVariant, Linear, LinkedIntersection,
};
use polysect::{ConvexPolygon, Exact, LinkedPolygon, Point};
use rand::rngs::SmallRng;
use rand::{RngCore, SeedableRng};
use std::hint::black_box;

/// The generator's seed: the pairs, and CLM's shuffles and samples after them.
const SEED: u64 = 0xce47;
/// How many pairs are generated and cycled.
const PAIRS: usize = 32;
/// The pairs file's first bytes (format version 1).
const MAGIC: &[u8; 8] = b"PSCCPRS1";

/// The 32 Rotated pairs of 2^`log2` vertices per polygon with the answer `want`
/// (the exact reference decides), drawn from `rng`.
fn generate_pairs(log2: u32, want: bool, rng: &mut SmallRng) -> Vec<(ConvexPolygon, ConvexPolygon)> {
    let rel = if want {
        Relation::Intersecting
    } else {
        Relation::Disjoint
    };
    (0..PAIRS)
        .map(|_| {
            loop {
                let (p, q) = generate::pair(Family::Rotated, 1 << log2, rel, rng);
                if Linear.intersects(&p, &q) == want {
                    break (p, q);
                }
            }
        })
        .collect()
}

/// How many 64-bit outputs a generator seeded with [`SEED`] has drawn to reach
/// `after`'s state: found by stepping a fresh one until its next four outputs (the
/// whole 256-bit state of xoshiro256++) equal `after`'s.
fn steps_drawn(after: &SmallRng) -> u64 {
    let next4 = |r: &SmallRng| {
        let mut r = r.clone();
        [r.next_u64(), r.next_u64(), r.next_u64(), r.next_u64()]
    };
    let target = next4(after);
    let mut fresh = SmallRng::seed_from_u64(SEED);
    let mut steps = 0u64;
    while next4(&fresh) != target {
        fresh.next_u64();
        steps += 1;
    }
    steps
}

/// Writes the pairs and the generator's position after them: `MAGIC`, then
/// little-endian u64s: LOG2, the relation (1 intersecting, 0 disjoint), the steps
/// drawn, the number of pairs, and for each polygon its vertex count and its
/// coordinates' bits (x, y per vertex, counter-clockwise as generated).
fn write_pairs(path: &str, log2: u32, want: bool) -> std::io::Result<()> {
    let mut rng = SmallRng::seed_from_u64(SEED);
    let pairs = generate_pairs(log2, want, &mut rng);
    let steps = steps_drawn(&rng);
    let mut out = MAGIC.to_vec();
    let mut put = |v: u64| out.extend_from_slice(&v.to_le_bytes());
    for v in [u64::from(log2), u64::from(want), steps, PAIRS as u64] {
        put(v);
    }
    for (p, q) in &pairs {
        for poly in [p, q] {
            put(poly.len() as u64);
            for v in poly.vertices() {
                put(v.x.to_bits());
                put(v.y.to_bits());
            }
        }
    }
    std::fs::write(path, out)
}

/// Reads what [`write_pairs`] wrote for `log2` and `want`, and the generator at the
/// position it was in after generating them.
fn read_pairs(
    path: &str,
    log2: u32,
    want: bool,
) -> Result<(Vec<(ConvexPolygon, ConvexPolygon)>, SmallRng), String> {
    let bytes = std::fs::read(path).map_err(|e| format!("{path}: {e}"))?;
    let body = bytes
        .strip_prefix(MAGIC.as_slice())
        .ok_or_else(|| format!("{path}: not a pairs file"))?;
    let mut words = body
        .chunks_exact(8)
        .map(|c| u64::from_le_bytes(c.try_into().expect("8 bytes")));
    if body.len() % 8 != 0 {
        return Err(format!("{path}: truncated"));
    }
    let mut next = || words.next().ok_or_else(|| format!("{path}: truncated"));
    let (file_log2, file_want, steps, count) = (next()?, next()?, next()?, next()?);
    if file_log2 != u64::from(log2) || file_want != u64::from(want) || count != PAIRS as u64 {
        return Err(format!(
            "{path} holds {count} pairs of 2^{file_log2} vertices, {}; asked for 2^{log2}, {}",
            if file_want == 1 {
                "intersecting"
            } else {
                "disjoint"
            },
            if want { "intersecting" } else { "disjoint" },
        ));
    }
    let mut polygon = || -> Result<ConvexPolygon, String> {
        let n = usize::try_from(next()?).map_err(|e| e.to_string())?;
        let mut vertices = Vec::with_capacity(n.min(1 << 27));
        for _ in 0..n {
            let (x, y) = (f64::from_bits(next()?), f64::from_bits(next()?));
            vertices.push(Point::new(x, y));
        }
        let polygon = ConvexPolygon::from_ccw_unchecked(vertices);
        // As after generation: the exact reference's check computed it.
        polygon.edge_extent();
        Ok(polygon)
    };
    let mut pairs = Vec::with_capacity(PAIRS);
    for _ in 0..PAIRS {
        let p = polygon()?;
        let q = polygon()?;
        pairs.push((p, q));
    }
    if next().is_ok() {
        return Err(format!("{path}: trailing data"));
    }
    let mut rng = SmallRng::seed_from_u64(SEED);
    for _ in 0..steps {
        rng.next_u64();
    }
    Ok((pairs, rng))
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = "usage: certified_cost ALGORITHM plain|certified intersecting|disjoint LOG2 QUERIES [PAIRS_FILE]\n       certified_cost write-pairs intersecting|disjoint LOG2 PAIRS_FILE";
    if let [cmd, relation, log2, path] = args.as_slice()
        && cmd == "write-pairs"
    {
        let (Ok(log2), want) = (log2.parse::<u32>(), relation.as_str()) else {
            eprintln!("{usage}");
            std::process::exit(2)
        };
        let want = match want {
            "intersecting" => true,
            "disjoint" => false,
            _ => {
                eprintln!("{usage}");
                std::process::exit(2)
            }
        };
        if let Err(e) = write_pairs(path, log2, want) {
            eprintln!("{path}: {e}");
            std::process::exit(1)
        }
        return;
    }
    let (alg, mode, relation, log2, queries, pairs_file) = match args.as_slice() {
        [a, m, r, l, q] => (a, m, r, l, q, None),
        [a, m, r, l, q, f] => (a, m, r, l, q, Some(f)),
        _ => {
            eprintln!("{usage}");
            std::process::exit(2)
        }
    };
    // CLM without the prefixes' quadrilaterals (the code before they were added).
    let clm_variant = ClmVariant {
        prefix_quads: alg != "clm-no-prefix",
        ..ClmVariant::default()
    };
    let alg = if alg == "clm-no-prefix" {
        "clm"
    } else {
        alg.as_str()
    };
    let variant = match alg {
        "barba-thirds" => Some(0),
        "barba-finish3" => Some(1),
        "barba-p-edges-first" => Some(2),
        "barba-thesis" => Some(3),
        "barba-halving" => Some(4),
        "dobkin-compact" => Some(5),
        "dobkin-lemmas" => Some(6),
        _ => None,
    };
    let alg: Algorithm = if variant.is_some() {
        Algorithm::Barba
    } else {
        alg.parse().unwrap_or_else(|e| {
            eprintln!("{e}");
            std::process::exit(2)
        })
    };
    let want = match relation.as_str() {
        "intersecting" => true,
        "disjoint" => false,
        _ => {
            eprintln!("{usage}");
            std::process::exit(2)
        }
    };
    let (Ok(log2), Ok(queries)) = (log2.parse::<u32>(), queries.parse::<usize>()) else {
        eprintln!("{usage}");
        std::process::exit(2)
    };
    let certified = mode == "certified";
    let (pairs, mut rng) = match pairs_file {
        Some(path) => read_pairs(path, log2, want).unwrap_or_else(|e| {
            eprintln!("{e}");
            std::process::exit(1)
        }),
        None => {
            let mut rng = SmallRng::seed_from_u64(SEED);
            (generate_pairs(log2, want, &mut rng), rng)
        }
    };
    if alg == Algorithm::Clm {
        // CLM on linked polygons in shuffled arena order (as in the `clm` bench), one
        // workspace and one seeded generator for the whole run.
        let linked: Vec<(LinkedPolygon, LinkedPolygon)> = pairs
            .iter()
            .map(|(p, q)| {
                (
                    LinkedPolygon::from_convex_shuffled(p, &mut rng),
                    LinkedPolygon::from_convex_shuffled(q, &mut rng),
                )
            })
            .collect();
        let mut ws = ClmWorkspace::default();
        let mut hits = 0usize;
        for i in 0..queries {
            let (p, q) = &linked[i % linked.len()];
            let (p, q) = (black_box(p), black_box(q));
            let hit = if certified {
                clm_variant
                    .certified_with_workspace(Exact, p, q, &mut rng, &mut ws)
                    .intersects()
            } else {
                clm_variant.intersects_with_workspace(Exact, p, q, &mut rng, &mut ws)
            };
            hits += usize::from(hit == want);
        }
        assert_eq!(hits, queries, "a wrong answer");
        return;
    }
    let mut hits = 0usize;
    for i in 0..queries {
        let (p, q) = &pairs[i % pairs.len()];
        let (p, q) = (black_box(p), black_box(q));
        let hit = match (variant, certified) {
            (Some(0), false) => BarbaVariant::<true, 7, false>.intersects_with(Exact, p, q),
            (Some(0), true) => BarbaVariant::<true, 7, false>
                .certified_with(Exact, p, q)
                .intersects(),
            (Some(1), false) => BarbaVariant::<false, 4, false>.intersects_with(Exact, p, q),
            (Some(1), true) => BarbaVariant::<false, 4, false>
                .certified_with(Exact, p, q)
                .intersects(),
            (Some(2), false) => BarbaVariant::<false, 7, true>.intersects_with(Exact, p, q),
            (Some(2), true) => BarbaVariant::<false, 7, true>
                .certified_with(Exact, p, q)
                .intersects(),
            (Some(4), false) => BarbaVariant::<false, 7, false>.intersects_with(Exact, p, q),
            (Some(4), true) => BarbaVariant::<false, 7, false>
                .certified_with(Exact, p, q)
                .intersects(),
            (Some(5), false) => DobkinVariant::<false>.intersects_with(Exact, p, q),
            (Some(5), true) => DobkinVariant::<false>.certified_with(Exact, p, q).intersects(),
            (Some(6), false) => DobkinVariant::<true>.intersects_with(Exact, p, q),
            (Some(6), true) => DobkinVariant::<true>.certified_with(Exact, p, q).intersects(),
            (Some(_), false) => BarbaVariant::<true, 4, true>.intersects_with(Exact, p, q),
            (Some(_), true) => BarbaVariant::<true, 4, true>
                .certified_with(Exact, p, q)
                .intersects(),
            (None, _) => match (alg, certified) {
                (Algorithm::Barba, false) => Barba.intersects_with(Exact, p, q),
                (Algorithm::Barba, true) => Barba.certified_with(Exact, p, q).intersects(),
                (Algorithm::Dobkin, false) => Dobkin.intersects_with(Exact, p, q),
                (Algorithm::Dobkin, true) => Dobkin.certified_with(Exact, p, q).intersects(),
                (Algorithm::ChazelleDobkin, false) => ChazelleDobkin.intersects_with(Exact, p, q),
                (Algorithm::ChazelleDobkin, true) => ChazelleDobkin.certified_with(Exact, p, q).intersects(),
                (Algorithm::Linear, false) => Linear.intersects_with(Exact, p, q),
                (Algorithm::Linear, true) => Linear.certified_with(Exact, p, q).intersects(),
                (other, true) => other.certified_with(Exact, p, q).intersects(),
                (other, false) => other.intersects_with(Exact, p, q),
            },
        };
        hits += usize::from(hit == want);
    }
    assert_eq!(hits, queries, "a wrong answer");
}
