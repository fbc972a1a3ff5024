//! Convex polygon intersection tests: "do P and Q share a point?"
//!
//! Polygons are closed sets: a shared vertex, a vertex on an edge, overlapping
//! collinear edges and containment all count as intersection. Every algorithm is
//! written once, generic over the [`Kernel`]; under [`Exact`] all of them give the
//! same answer on every valid input, which the test suite checks against
//! [`Linear`] and [`brute_force`].
//!
//! | algorithm | input | time | notes |
//! |---|---|---|---|
//! | [`Linear`] | arrays | O(n + m) | separating-edge search with rotating pointers; the reference |
//! | [`brute_force`] | arrays | O(n·m) | every edge pair plus containment; the oracle for `Linear` |
//!
//! Each algorithm is a unit struct implementing [`ArrayIntersection`] and is listed
//! once in [`Algorithm`], which the CLI, tests and benches iterate over.

mod linear;

pub use linear::{Linear, brute_force};

use crate::kernel::{Exact, Fast, Kernel, Precision};
use crate::polygon::ConvexPolygon;
use std::fmt;
use std::str::FromStr;

/// Receives one call per pruning iteration of an algorithm, for experiments
/// (the thesis's iteration counts). The unit type `()` ignores them and compiles away.
pub trait Probe {
    #[inline]
    fn iteration(&mut self) {}
}

impl Probe for () {}

/// Counts iterations.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Iterations(pub u64);

impl Probe for Iterations {
    #[inline]
    fn iteration(&mut self) {
        self.0 += 1;
    }
}

/// An intersection test on two convex polygons stored as sorted arrays.
pub trait ArrayIntersection {
    /// The name used by the CLI's `--algorithm` and by benches.
    const NAME: &'static str;

    /// Whether `p` and `q` intersect, reporting each pruning iteration to `probe`.
    fn intersects_probed<K: Kernel, P: Probe>(
        &self,
        kernel: K,
        p: &ConvexPolygon,
        q: &ConvexPolygon,
        probe: &mut P,
    ) -> bool;

    /// Whether `p` and `q` intersect, deciding predicates with `kernel`.
    #[inline]
    fn intersects_with<K: Kernel>(&self, kernel: K, p: &ConvexPolygon, q: &ConvexPolygon) -> bool {
        self.intersects_probed(kernel, p, q, &mut ())
    }

    /// Whether `p` and `q` intersect, with the exact kernel.
    #[inline]
    fn intersects(&self, p: &ConvexPolygon, q: &ConvexPolygon) -> bool {
        self.intersects_with(Exact, p, q)
    }
}

/// Every intersection algorithm, by name: what the CLI, the tests and the benches
/// iterate over.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Algorithm {
    Linear,
}

impl Algorithm {
    /// Every algorithm, in the order tables list them.
    pub const ALL: &'static [Algorithm] = &[Algorithm::Linear];

    pub fn name(self) -> &'static str {
        match self {
            Algorithm::Linear => Linear::NAME,
        }
    }

    /// The fastest algorithm on array polygons, what `--algorithm auto` runs.
    pub fn fastest_array() -> Algorithm {
        Algorithm::Linear
    }

    /// Runs the algorithm on two array polygons with the kernel named by `precision`,
    /// returning the answer and the number of pruning iterations.
    pub fn run(self, precision: Precision, p: &ConvexPolygon, q: &ConvexPolygon) -> (bool, u64) {
        match precision {
            Precision::Fast => self.run_with(Fast, p, q),
            Precision::Exact => self.run_with(Exact, p, q),
        }
    }

    /// Runs the algorithm with a kernel chosen at compile time, returning the answer and
    /// the number of pruning iterations.
    pub fn run_with<K: Kernel>(self, k: K, p: &ConvexPolygon, q: &ConvexPolygon) -> (bool, u64) {
        let mut it = Iterations::default();
        let answer = match self {
            Algorithm::Linear => Linear.intersects_probed(k, p, q, &mut it),
        };
        (answer, it.0)
    }

    /// The answer alone, with a kernel chosen at compile time.
    pub fn intersects_with<K: Kernel>(self, k: K, p: &ConvexPolygon, q: &ConvexPolygon) -> bool {
        self.run_with(k, p, q).0
    }

    /// The answer alone.
    pub fn intersects(self, precision: Precision, p: &ConvexPolygon, q: &ConvexPolygon) -> bool {
        self.run(precision, p, q).0
    }
}

impl fmt::Display for Algorithm {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Algorithm {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Algorithm::ALL
            .iter()
            .copied()
            .find(|a| a.name() == s)
            .ok_or_else(|| {
                let names: Vec<&str> = Algorithm::ALL.iter().map(|a| a.name()).collect();
                format!("unknown algorithm '{s}' (valid: {})", names.join(", "))
            })
    }
}
