//! The seeded random-input driver: every fuzz harness in `polysect::fuzzing` on random
//! byte strings, a bounded number of times (`POLYSECT_FUZZ_ITERS`, default 20,000 per
//! harness). A failure prints the seed of the failing input; rerun with
//! `POLYSECT_FUZZ_SEED=<seed> POLYSECT_FUZZ_ITERS=1` to reproduce it alone.

use polysect::fuzzing;
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

fn iterations() -> u64 {
    std::env::var("POLYSECT_FUZZ_ITERS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(20_000)
}

/// Runs `harness` on random inputs; it returns whether an input reached the interesting
/// part, and at least `min_share` of the inputs must (so the driver cannot silently
/// test nothing).
fn drive(name: &str, max_len: usize, min_share: f64, harness: fn(&[u8]) -> bool) {
    let mut reached = 0;
    let base: u64 = std::env::var("POLYSECT_FUZZ_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(0xf022);
    for i in 0..iterations() {
        let seed = base.wrapping_add(i);
        let mut rng = SmallRng::seed_from_u64(seed);
        let len = rng.random_range(0..=max_len);
        let bytes: Vec<u8> = (0..len).map(|_| rng.random()).collect();
        match std::panic::catch_unwind(|| harness(&bytes)) {
            Ok(hit) => reached += hit as u64,
            Err(_) => panic!("{name}: input from seed {seed} failed: {bytes:?}"),
        }
    }
    let share = reached as f64 / iterations().max(1) as f64;
    println!("{name}: {reached} of {} inputs reached the checks", iterations());
    assert!(
        share >= min_share,
        "{name}: only {share:.3} of the inputs reached the checks"
    );
}

#[test]
fn fuzz_polygon_construction() {
    drive("polygon_construction", 200, 0.05, fuzzing::polygon_construction);
}

#[test]
fn fuzz_edit_sequences() {
    drive("edit_sequence", 400, 0.02, fuzzing::edit_sequence);
}

#[test]
fn fuzz_json_lines() {
    // Raw bytes, and mutations of a valid line (much more likely to reach the parser's depth).
    drive("json_line", 120, 0.0, fuzzing::json_line);
    const VALID: &[u8] = br#"{"id": 1, "p": [[0,0],[1e-300,0],[0,1]], "q": [[1,1],[2,1.5],[1,2]]}"#;
    drive("json_line (mutated)", 8, 0.02, |noise| {
        let mut line = VALID.to_vec();
        for pair in noise.chunks(2) {
            if let [at, byte] = pair {
                let i = *at as usize % line.len();
                line[i] = *byte;
            }
        }
        fuzzing::json_line(&line)
    });
}

#[test]
fn fuzz_scene_ops() {
    drive("scene_ops", 600, 0.3, fuzzing::scene_ops);
}

#[test]
fn fuzz_algorithms_agree() {
    drive("algorithms_agree", 600, 0.05, fuzzing::algorithms_agree);
}

#[test]
fn fuzz_crossings() {
    drive("crossings_agree", 500, 0.02, fuzzing::crossings_agree);
}
