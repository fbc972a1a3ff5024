//! Convex polygon intersection tests: "do P and Q share a point?"
//!
//! Polygons are closed sets: a shared vertex, a vertex on an edge, overlapping
//! collinear edges and containment all count as intersection. Every algorithm is
//! written once, generic over the [`Kernel`]; under [`Exact`] all of them give the
//! same answer on every valid input, which the test suite checks against
//! [`Linear`] and an O(n·m) brute force (`brute_force`, with `instrument`).
//!
//! | algorithm | input | time | notes |
//! |---|---|---|---|
//! | [`Linear`] | arrays | O(n + m) | separating-edge search with rotating pointers; the reference |
//! | [`Barba`] | arrays | O(log n + log m) | inner triangle of P against the edge hull of three edges of Q; halves one of them per step; uses one degree-4 predicate |
//! | [`Dobkin`] | arrays | O(log n + log m) | top/bottom by binary search, then left chain against right chain twice by slope comparisons; orient/cross only |
//! | [`ChazelleDobkin`] | arrays | O(log n + log m) | pivot, pencil of tangents, the two L chains halved by middle-edge slopes in a projective frame |
//! | [`Clm`] | linked | expected O(√n + √m) | Chazelle–Liu–Magen: samples, a 2D LP, chains |
//! | [`Convert`] | linked | O(n + m) + array test | walk the lists into arrays, then an array algorithm |
//! | [`LinearLinked`] | linked | O(n + m) | `Linear`'s rotating pointers along the links, no conversion; the store's route for small polygons |
//!
//! Each algorithm is a unit struct implementing [`ArrayIntersection`] and is listed
//! once in [`Algorithm`], which the CLI, tests and benches iterate over. Tests on
//! [`LinkedPolygon`](crate::LinkedPolygon)s implement [`LinkedIntersection`]; through
//! [`Algorithm`] they take array polygons, which are linked in a shuffled arena order
//! (as the thesis's experiments do) with a generator seeded from the operating system
//! (with `instrument`, `Algorithm::run_rng` takes the caller's generator, for
//! reproducible runs).

//! # Certificates
//! Every test also has a certified call ([`ArrayIntersection::certified_with`],
//! [`LinkedIntersection::certified_with`], [`Algorithm::certified`]) that returns a
//! [`Certificate`] of its answer, derived from what the algorithm found
//! (each algorithm's module docs) and completed by a slower search where that gives
//! only the answer. [`verify`]
//! checks any certificate exactly in O(n + m), independently of every algorithm:
//! run it when in doubt. docs/certificates.md has the details and the measured cost.

mod barba;
mod certificate;
mod chazelle_dobkin;
mod clm;
mod convert;
#[cfg(feature = "instrument")]
mod counts;
mod dobkin;
mod engine;
mod fallback;
mod kept;
mod linear;
mod linear_linked;
mod linked;
mod probe;
#[cfg(feature = "instrument")]
mod trace;

pub(crate) use crate::seeding::fresh_rng;
pub use barba::Barba;
#[cfg(feature = "instrument")]
pub use barba::BarbaVariant;
pub(crate) use barba::{
    certified_vertices as barba_certified_vertices, intersects_vertices as barba_vertices,
};
pub use certificate::{Certificate, CertificateError, Which, verify, verify_linked};
pub use chazelle_dobkin::ChazelleDobkin;
pub use clm::{Clm, ClmWorkspace};
#[cfg(feature = "instrument")]
pub use clm::{ClmVariant, ClmWithFactor, LpOrder, Sampling};
pub use convert::{Convert, ConvertWorkspace};
#[cfg(feature = "instrument")]
pub use counts::{Counts, CountsSummary, LpCall};
pub use dobkin::Dobkin;
#[cfg(feature = "instrument")]
pub use dobkin::DobkinVariant;
pub use fallback::{exact_certificate, verified_or_exact, verified_or_exact_linked};
pub use linear::Linear;
#[cfg(feature = "instrument")]
pub use linear::brute_force;
#[cfg(not(feature = "instrument"))]
#[allow(unused_imports)] // the fuzzing oracles (`protocol`) use it
pub(crate) use linear::brute_force;
pub use linear_linked::LinearLinked;
pub(crate) use linear_linked::separating_edge_at;
pub use linked::LinkedIntersection;
// The probes, the engines' probed entry points, derivations and what a pruning step
// keeps: the crate's own machinery, an API with `instrument` only.
#[cfg(feature = "instrument")]
pub use certificate::Derivation;
#[cfg(not(feature = "instrument"))]
pub(crate) use certificate::Derivation;
#[cfg(feature = "instrument")]
pub use engine::{ArrayEngine, LinkedEngine};
#[cfg(not(feature = "instrument"))]
pub(crate) use engine::{ArrayEngine, LinkedEngine};
#[cfg(feature = "instrument")]
pub use kept::{Kept, Span};
#[cfg(not(feature = "instrument"))]
pub(crate) use kept::{Kept, Span};
#[cfg(feature = "instrument")]
pub use probe::{Fallback, Iterations, Probe};
#[cfg(not(feature = "instrument"))]
pub(crate) use probe::{Fallback, Iterations, Probe};
#[cfg(feature = "instrument")]
pub use trace::{Mark, Role, Shape, Trace, TraceStep, Tracer, trace, trace_rng};

use crate::kernel::{Exact, Fast, Kernel, Precision};
use crate::polygon::ConvexPolygon;
use rand::Rng;
use std::fmt;
use std::str::FromStr;

/// An intersection test on two convex polygons stored as sorted arrays.
pub trait ArrayIntersection {
    /// The name used by the CLI's `--algorithm` and by benches.
    const NAME: &'static str;

    /// Whether `p` and `q` intersect, deciding predicates with `kernel`.
    fn intersects_with<K: Kernel>(&self, kernel: K, p: &ConvexPolygon, q: &ConvexPolygon) -> bool;

    /// Whether `p` and `q` intersect, with the exact kernel.
    #[inline]
    fn intersects(&self, p: &ConvexPolygon, q: &ConvexPolygon) -> bool {
        self.intersects_with(Exact, p, q)
    }

    /// The answer with a [`Certificate`] that proves it: the algorithm's own, completed
    /// by a search where the algorithm found only the answer (docs/certificates.md says
    /// which exits give which). The answer is [`Certificate::intersects`], the same as
    /// [`intersects_with`](Self::intersects_with)'s.
    ///
    /// # Complexity
    /// That of the algorithm, plus O(log n + log m) where a derivation needs a search.
    ///
    /// # Precision
    /// Under [`Exact`] the certificate always passes [`verify`]. Under an inconsistent
    /// kernel ([`Fast`] near degeneracies) it may not; where the completing search
    /// contradicts the answer, [`exact_certificate`] supplies the certificate (and then
    /// the certified answer can differ from the plain call's, and be right).
    fn certified_with<K: Kernel>(&self, kernel: K, p: &ConvexPolygon, q: &ConvexPolygon) -> Certificate;

    /// The answer with its certificate, with the exact kernel.
    #[inline]
    fn certified(&self, p: &ConvexPolygon, q: &ConvexPolygon) -> Certificate {
        self.certified_with(Exact, p, q)
    }
}

/// Every intersection algorithm, by name: what the CLI, the tests and the benches
/// iterate over.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Algorithm {
    /// [`Linear`]: the O(n + m) reference.
    Linear,
    /// [`Barba`]: Barba–Langerman's O(log n + log m) pruning.
    Barba,
    /// [`Dobkin`]: Dobkin–Souvaine's O(log n + log m) chain test.
    Dobkin,
    /// [`ChazelleDobkin`]: Chazelle–Dobkin's O(log n + log m) pencil test.
    ChazelleDobkin,
    /// [`Clm`]: the O(√n) sampled test on linked polygons.
    Clm,
    /// [`Convert`]: link to array in O(n), then an O(log n) test.
    Convert,
}

impl Algorithm {
    /// Every algorithm, in the order tables list them.
    pub const ALL: &'static [Algorithm] = &[
        Algorithm::Linear,
        Algorithm::Barba,
        Algorithm::Dobkin,
        Algorithm::ChazelleDobkin,
        Algorithm::Clm,
        Algorithm::Convert,
    ];

    instrument_pub! {
        /// The tests on sorted arrays: the reference and the O(log n) algorithms.
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        const ARRAY: &'static [Algorithm] = &[
            Algorithm::Linear,
            Algorithm::Barba,
            Algorithm::Dobkin,
            Algorithm::ChazelleDobkin,
        ];
    }

    instrument_pub! {
        /// The tests on linked polygons (through `Algorithm::run` they link array inputs in
        /// a shuffled arena order first, which costs O(n) per call).
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        const LINKED: &'static [Algorithm] = &[Algorithm::Clm, Algorithm::Convert];
    }

    instrument_pub! {
        /// The O(log n) tests on sorted arrays (the thesis's experiment 2 checks that
        /// their iteration counts grow like log n).
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        const LOGARITHMIC: &'static [Algorithm] =
            &[Algorithm::Barba, Algorithm::Dobkin, Algorithm::ChazelleDobkin];
    }

    /// The name used by the CLI's `--algorithm`, the benches and the CSVs.
    pub fn name(self) -> &'static str {
        match self {
            Algorithm::Linear => Linear::NAME,
            Algorithm::Barba => Barba::NAME,
            Algorithm::Dobkin => Dobkin::NAME,
            Algorithm::ChazelleDobkin => ChazelleDobkin::NAME,
            Algorithm::Clm => Clm::NAME,
            Algorithm::Convert => <Convert>::NAME,
        }
    }

    instrument_pub! {
        /// The fastest algorithm on array polygons, what `--algorithm auto` runs.
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn fastest_array() -> Algorithm {
            Algorithm::Barba
        }
    }

    instrument_pub! {
        /// Runs the algorithm on two array polygons with the kernel named by `precision`,
        /// returning the answer and the number of pruning iterations. The linked-polygon
        /// tests draw from a generator seeded from the operating system (without the
        /// `os-rng` feature, from a counter; docs/design.md, "Randomness").
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn run(self, precision: Precision, p: &ConvexPolygon, q: &ConvexPolygon) -> (bool, u64) {
            self.run_rng(precision, p, q, &mut fresh_rng())
        }
    }

    instrument_pub! {
        /// [`run`](Self::run) drawing from `rng` (the shuffled arena order and the samples
        /// of the linked-polygon tests; the array tests draw nothing): a seeded `rng` makes
        /// the run reproducible.
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn run_rng<R: Rng + ?Sized>(
            self,
            precision: Precision,
            p: &ConvexPolygon,
            q: &ConvexPolygon,
            rng: &mut R,
        ) -> (bool, u64) {
            match precision {
                Precision::Fast => self.run_with_rng(Fast, p, q, rng),
                Precision::Exact => self.run_with_rng(Exact, p, q, rng),
            }
        }
    }

    instrument_pub! {
        /// Runs the algorithm with a kernel chosen at compile time, returning the answer and
        /// the number of pruning iterations.
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn run_with<K: Kernel>(self, k: K, p: &ConvexPolygon, q: &ConvexPolygon) -> (bool, u64) {
            self.run_with_rng(k, p, q, &mut fresh_rng())
        }
    }

    instrument_pub! {
        /// [`run_with`](Self::run_with) drawing from `rng`.
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn run_with_rng<K: Kernel, R: Rng + ?Sized>(
            self,
            k: K,
            p: &ConvexPolygon,
            q: &ConvexPolygon,
            rng: &mut R,
        ) -> (bool, u64) {
            let mut it = Iterations::default();
            let answer = match self {
                Algorithm::Linear => Linear.intersects_probed(k, p, q, &mut it),
                Algorithm::Barba => Barba.intersects_probed(k, p, q, &mut it),
                Algorithm::Dobkin => Dobkin.intersects_probed(k, p, q, &mut it),
                Algorithm::ChazelleDobkin => ChazelleDobkin.intersects_probed(k, p, q, &mut it),
                Algorithm::Clm => run_linked(&Clm, k, p, q, rng, &mut it),
                Algorithm::Convert => run_linked(&<Convert>::default(), k, p, q, rng, &mut it),
            };
            (answer, it.0)
        }
    }

    /// The answer alone, with a kernel chosen at compile time.
    pub fn intersects_with<K: Kernel>(self, k: K, p: &ConvexPolygon, q: &ConvexPolygon) -> bool {
        self.run_with(k, p, q).0
    }

    /// The answer alone.
    pub fn intersects(self, precision: Precision, p: &ConvexPolygon, q: &ConvexPolygon) -> bool {
        self.run(precision, p, q).0
    }

    instrument_pub! {
        /// Runs the certified call of the algorithm with the kernel named by `precision`,
        /// returning the [`Certificate`] (whose [`intersects`](Certificate::intersects) is the
        /// answer) and the number of pruning iterations. Linked-polygon tests link the
        /// inputs as [`Algorithm::run`] does.
        ///
        /// ```
        /// use polysect::{ConvexPolygon, Precision};
        /// use polysect::intersect::{Algorithm, verify};
        /// let p = ConvexPolygon::new([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
        /// let q = ConvexPolygon::new([[2.0, 2.0], [3.0, 2.0], [3.0, 3.0]])?;
        /// for &alg in Algorithm::ALL {
        ///     let c = alg.certified(Precision::Exact, &p, &q);
        ///     assert!(c.intersects()); // the shared vertex (2, 2)
        ///     assert_eq!(verify(&p, &q, &c), Ok(()));
        /// }
        /// # Ok::<(), polysect::PolygonError>(())
        /// ```
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn run_certified(
            self,
            precision: Precision,
            p: &ConvexPolygon,
            q: &ConvexPolygon,
        ) -> (Certificate, u64) {
            self.run_certified_rng(precision, p, q, &mut fresh_rng())
        }
    }

    instrument_pub! {
        /// [`run_certified`](Self::run_certified) drawing from `rng`, as
        /// [`run_rng`](Self::run_rng).
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn run_certified_rng<R: Rng + ?Sized>(
            self,
            precision: Precision,
            p: &ConvexPolygon,
            q: &ConvexPolygon,
            rng: &mut R,
        ) -> (Certificate, u64) {
            match precision {
                Precision::Fast => self.run_certified_with_rng(Fast, p, q, rng),
                Precision::Exact => self.run_certified_with_rng(Exact, p, q, rng),
            }
        }
    }

    instrument_pub! {
        /// [`run_certified`](Self::run_certified) with a kernel chosen at compile time.
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn run_certified_with<K: Kernel>(
            self,
            k: K,
            p: &ConvexPolygon,
            q: &ConvexPolygon,
        ) -> (Certificate, u64) {
            self.run_certified_with_rng(k, p, q, &mut fresh_rng())
        }
    }

    instrument_pub! {
        /// [`run_certified_with`](Self::run_certified_with) drawing from `rng`.
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn run_certified_with_rng<K: Kernel, R: Rng + ?Sized>(
            self,
            k: K,
            p: &ConvexPolygon,
            q: &ConvexPolygon,
            rng: &mut R,
        ) -> (Certificate, u64) {
            let mut it = Iterations::default();
            let certificate = match self {
                Algorithm::Linear => Linear.certified_probed(k, p, q, &mut it),
                Algorithm::Barba => Barba.certified_probed(k, p, q, &mut it),
                Algorithm::Dobkin => Dobkin.certified_probed(k, p, q, &mut it),
                Algorithm::ChazelleDobkin => ChazelleDobkin.certified_probed(k, p, q, &mut it),
                Algorithm::Clm => run_linked_certified(&Clm, k, p, q, rng, &mut it),
                Algorithm::Convert => run_linked_certified(&<Convert>::default(), k, p, q, rng, &mut it),
            };
            (certificate, it.0)
        }
    }

    /// The certificate alone, with a kernel chosen at compile time.
    pub fn certified_with<K: Kernel>(self, k: K, p: &ConvexPolygon, q: &ConvexPolygon) -> Certificate {
        self.run_certified_with(k, p, q).0
    }

    /// The certificate alone, with the kernel named by `precision`.
    pub fn certified(self, precision: Precision, p: &ConvexPolygon, q: &ConvexPolygon) -> Certificate {
        self.run_certified(precision, p, q).0
    }
}

/// Links `p` and `q` in shuffled arena order and runs a linked-polygon test on them.
fn run_linked<L: LinkedEngine, K: Kernel, R: Rng + ?Sized, P: Probe>(
    alg: &L,
    k: K,
    p: &ConvexPolygon,
    q: &ConvexPolygon,
    rng: &mut R,
    probe: &mut P,
) -> bool {
    let lp = crate::polygon::LinkedPolygon::from_convex_shuffled(p, rng);
    let lq = crate::polygon::LinkedPolygon::from_convex_shuffled(q, rng);
    alg.intersects_in(k, &lp, &lq, rng, &mut L::Workspace::default(), probe)
}

/// [`run_linked`] with the certified call.
fn run_linked_certified<L: LinkedEngine, K: Kernel, R: Rng + ?Sized, P: Probe>(
    alg: &L,
    k: K,
    p: &ConvexPolygon,
    q: &ConvexPolygon,
    rng: &mut R,
    probe: &mut P,
) -> Certificate {
    let lp = crate::polygon::LinkedPolygon::from_convex_shuffled(p, rng);
    let lq = crate::polygon::LinkedPolygon::from_convex_shuffled(q, rng);
    alg.certified_in(k, &lp, &lq, rng, &mut L::Workspace::default(), probe)
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
