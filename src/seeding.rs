//! How the crate seeds the generators of callers who pass none: every unseeded entry
//! point (one-off sampled queries such as [`LinkedIntersection::intersects`], a new
//! [`Scene`], the CLI without `--seed`) takes its generator from [`fresh_rng`], so this
//! module alone decides it (docs/design.md, "Randomness").
//!
//! The sampled tests are fast in expectation over their draws for every input fixed
//! before the draws; a generator whose seed is known lets anyone build inputs that
//! sample badly (answers stay exact, only the time suffers). With the `os-rng` feature
//! the seed comes from the operating system; without it (as on
//! `wasm32-unknown-unknown`) from a process-wide counter, which is the same in every
//! run. Reproducible runs pass their own seeded generator to the `*_seeded` / `*_rng`
//! entry points instead.
//!
//! [`LinkedIntersection::intersects`]: crate::intersect::LinkedIntersection::intersects
//! [`Scene`]: crate::store::Scene

use rand::SeedableRng;
use rand::rngs::SmallRng;

/// A generator for one query or one session, seeded from the thread-local generator
/// (itself seeded from the operating system): the sample is unknown to whoever chose
/// the input.
#[cfg(feature = "os-rng")]
pub fn fresh_rng() -> SmallRng {
    SmallRng::from_rng(&mut rand::rng())
}

/// A generator for one query or one session. Without the `os-rng` feature there is no
/// entropy source: the n-th unseeded generator of the process is seeded with n (0, 1,
/// 2, ...). Successive queries and scenes still draw different samples, but the
/// sequence is the same in every run, so whoever knows it can build slow inputs; pass a
/// seed drawn from a real entropy source where that matters.
#[cfg(not(feature = "os-rng"))]
pub fn fresh_rng() -> SmallRng {
    use std::sync::atomic::{AtomicU64, Ordering};
    static NEXT: AtomicU64 = AtomicU64::new(0);
    SmallRng::seed_from_u64(NEXT.fetch_add(1, Ordering::Relaxed))
}
