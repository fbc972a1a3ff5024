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
//! | [`Barba`] | arrays | O(log n + log m) | inner triangle of P against the edge hull of three edges of Q; halves one of them per step; uses one degree-4 predicate |
//! | [`Dobkin`] | arrays | O(log n + log m) | top/bottom by binary search, then left chain against right chain twice by slope comparisons; orient/cross only |
//! | [`ChazelleDobkin`] | arrays | O(log n + log m) | pivot, pencil of tangents, the two L chains halved by middle-edge slopes in a projective frame |
//! | [`Clm`] | linked | expected O(√n + √m) | Chazelle–Liu–Magen: samples, a 2D LP, chains ([`crate::lp`]) |
//! | [`Convert`] | linked | O(n + m) + array test | walk the lists into arrays, then an array algorithm |
//! | [`LinearLinked`] | linked | O(n + m) | `Linear`'s rotating pointers along the links, no conversion; the store's route for small polygons |
//!
//! Each algorithm is a unit struct implementing [`ArrayIntersection`] and is listed
//! once in [`Algorithm`], which the CLI, tests and benches iterate over. Tests on
//! [`LinkedPolygon`](crate::LinkedPolygon)s implement [`LinkedIntersection`]; through
//! [`Algorithm::run`] they take array polygons, which are linked in a shuffled arena
//! order (as the thesis's experiments do) with a generator seeded from the operating
//! system, or the caller's generator ([`Algorithm::run_rng`]) for reproducible runs.

//! # Certificates
//! Every test also has a certified call ([`ArrayIntersection::certified_with`],
//! [`LinkedIntersection::certified_with`], [`Algorithm::certified`]) that returns a
//! [`Certificate`] of its answer, derived from what the algorithm found
//! ([`ArrayIntersection::derive_probed`], each algorithm's module docs) and completed
//! by a slower search where that gives only the answer ([`Fallback`]). [`verify`]
//! checks any certificate exactly in O(n + m), independently of every algorithm:
//! run it when in doubt. docs/certificates.md has the details and the measured cost.

mod barba;
mod certificate;
mod chazelle_dobkin;
mod clm;
#[cfg(feature = "instrument")]
mod counts;
mod dobkin;
mod fallback;
mod kept;
mod linear;
mod linear_linked;
mod linked;
#[cfg(feature = "instrument")]
mod trace;

pub(crate) use crate::seeding::fresh_rng;
pub use barba::Barba;
#[cfg(feature = "instrument")]
pub use barba::BarbaVariant;
pub use certificate::{Certificate, CertificateError, Derivation, Which, verify, verify_linked};
pub use chazelle_dobkin::ChazelleDobkin;
pub use clm::{Clm, ClmWorkspace};
#[cfg(feature = "instrument")]
pub use clm::{ClmVariant, ClmWithFactor, LpOrder, Sampling};
#[cfg(feature = "instrument")]
pub use counts::{Counts, CountsSummary, LpCall};
pub use dobkin::Dobkin;
#[cfg(feature = "instrument")]
pub use dobkin::DobkinVariant;
pub use fallback::{exact_certificate, proven, proven_linked};
pub use kept::{Kept, Span};
pub use linear::{Linear, brute_force};
pub use linear_linked::LinearLinked;
pub(crate) use linear_linked::separating_edge_at;
pub use linked::{Convert, ConvertWorkspace, LinkedIntersection};
#[cfg(feature = "instrument")]
pub use trace::{Mark, Role, Shape, Trace, TraceStep, Tracer, trace, trace_rng};

use crate::kernel::{Exact, Fast, Kernel, Point, Precision};
use crate::lp::{ArenaPoints, LpError, Separation};
use crate::polygon::ConvexPolygon;
use rand::Rng;
use std::fmt;
use std::str::FromStr;

/// Receives one call per pruning iteration of an algorithm, for experiments
/// (the thesis's iteration counts). The unit type `()` ignores them and compiles away.
pub trait Probe {
    /// One pruning iteration (for CLM: one unit of work, see its module docs).
    #[inline]
    fn iteration(&mut self) {}

    /// Called when a certified call could not derive its certificate from what the
    /// algorithm found and completed the answer with a slower search (see
    /// [`Derivation`]); tests count these.
    #[inline]
    fn fallback(&mut self, _kind: Fallback) {}

    /// [`Clm`] drew its samples `p` and `q` (once per query).
    #[inline]
    fn samples(&mut self, _p: &ArenaPoints<'_>, _q: &ArenaPoints<'_>) {}

    /// [`Clm`] ran one LP on the point sets `a` and `b` (its constraints), which
    /// examined `work` points (violation tests, one-dimensional steps, certification)
    /// and returned `result`.
    #[inline]
    fn lp_call(
        &mut self,
        _a: &ArenaPoints<'_>,
        _b: &ArenaPoints<'_>,
        _work: u64,
        _result: &Result<Separation, LpError>,
    ) {
    }

    /// [`Clm`] walked one chain (a step per vertex collected).
    #[inline]
    fn chain_walk(&mut self, _chain: &ArenaPoints<'_>) {}

    /// [`Clm`] tested `tested` sample points (one unit of work each) in quadrilaterals
    /// of the other polygon's sample vertices, which lie inside that polygon.
    /// `inside`: the vertex it found in one, its polygon, and that quadrilateral
    /// (counter-clockwise; a corner repeats where it has only three); then the
    /// polygons intersect and the query ends there.
    #[inline]
    fn sample_quads(&mut self, _tested: u64, _inside: Option<(Which, Point, [Point; 4])>) {}

    /// One pruning step of [`Barba`], [`Dobkin`] or [`ChazelleDobkin`] is about to
    /// decide: what the algorithm keeps at this point ([`Kept`]). [`Tracer`] records
    /// these as a [`Trace`].
    #[inline]
    fn kept(&mut self, _kept: Kept<'_>) {}
}

/// How a certified call completed an answer its algorithm did not certify.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Fallback {
    /// An O(log n + log m) search that certifies the answer under the exact kernel:
    /// Dobkin's separation for "disjoint", Barba's witness for "intersecting".
    Search,
    /// [`exact_certificate`], O(n + m): the search contradicted the answer, which only
    /// an inconsistent kernel makes possible.
    Reference,
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

    /// The algorithm's run with what it can prove from its own findings: a certificate,
    /// or only the answer (docs/certificates.md says which exits give which).
    fn derive_probed<K: Kernel, P: Probe>(
        &self,
        kernel: K,
        p: &ConvexPolygon,
        q: &ConvexPolygon,
        probe: &mut P,
    ) -> Derivation;

    /// The answer with a [`Certificate`] that proves it: the algorithm's own
    /// ([`derive_probed`](Self::derive_probed)), completed where it gave only the answer
    /// ([`Fallback`]). Reports each pruning iteration and each fallback to `probe`. The
    /// answer is [`Certificate::intersects`], the same as
    /// [`intersects_probed`](Self::intersects_probed)'s.
    ///
    /// # Complexity
    /// That of the algorithm, plus O(log n + log m) where a derivation needs a search.
    ///
    /// # Precision
    /// Under [`Exact`] the certificate always passes [`verify`]. Under an inconsistent
    /// kernel ([`Fast`] near degeneracies) it may not; where the completing search
    /// contradicts the answer, [`exact_certificate`] supplies the certificate (and then
    /// the certified answer can differ from the plain call's, and be right).
    #[inline]
    fn certified_probed<K: Kernel, P: Probe>(
        &self,
        kernel: K,
        p: &ConvexPolygon,
        q: &ConvexPolygon,
        probe: &mut P,
    ) -> Certificate {
        let derivation = self.derive_probed(kernel, p, q, probe);
        fallback::complete(kernel, p.vertices(), q.vertices(), derivation, probe)
    }

    /// [`certified_probed`](Self::certified_probed) without a probe.
    #[inline]
    fn certified_with<K: Kernel>(&self, kernel: K, p: &ConvexPolygon, q: &ConvexPolygon) -> Certificate {
        self.certified_probed(kernel, p, q, &mut ())
    }

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

    /// The tests on sorted arrays: the reference and the O(log n) algorithms.
    pub const ARRAY: &'static [Algorithm] = &[
        Algorithm::Linear,
        Algorithm::Barba,
        Algorithm::Dobkin,
        Algorithm::ChazelleDobkin,
    ];

    /// The tests on linked polygons (through [`Algorithm::run`] they link array inputs in
    /// a shuffled arena order first, which costs O(n) per call).
    pub const LINKED: &'static [Algorithm] = &[Algorithm::Clm, Algorithm::Convert];

    /// The O(log n) tests on sorted arrays (the thesis's experiment 2 checks that
    /// their iteration counts grow like log n).
    pub const LOGARITHMIC: &'static [Algorithm] =
        &[Algorithm::Barba, Algorithm::Dobkin, Algorithm::ChazelleDobkin];

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

    /// The fastest algorithm on array polygons, what `--algorithm auto` runs.
    pub fn fastest_array() -> Algorithm {
        Algorithm::Barba
    }

    /// Runs the algorithm on two array polygons with the kernel named by `precision`,
    /// returning the answer and the number of pruning iterations. The linked-polygon
    /// tests draw from a generator seeded from the operating system (without the
    /// `os-rng` feature, from a counter; docs/design.md, "Randomness").
    pub fn run(self, precision: Precision, p: &ConvexPolygon, q: &ConvexPolygon) -> (bool, u64) {
        self.run_rng(precision, p, q, &mut fresh_rng())
    }

    /// [`run`](Self::run) drawing from `rng` (the shuffled arena order and the samples
    /// of the linked-polygon tests; the array tests draw nothing): a seeded `rng` makes
    /// the run reproducible.
    pub fn run_rng<R: Rng + ?Sized>(
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

    /// Runs the algorithm with a kernel chosen at compile time, returning the answer and
    /// the number of pruning iterations.
    pub fn run_with<K: Kernel>(self, k: K, p: &ConvexPolygon, q: &ConvexPolygon) -> (bool, u64) {
        self.run_with_rng(k, p, q, &mut fresh_rng())
    }

    /// [`run_with`](Self::run_with) drawing from `rng`.
    pub fn run_with_rng<K: Kernel, R: Rng + ?Sized>(
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

    /// The answer alone, with a kernel chosen at compile time.
    pub fn intersects_with<K: Kernel>(self, k: K, p: &ConvexPolygon, q: &ConvexPolygon) -> bool {
        self.run_with(k, p, q).0
    }

    /// The answer alone.
    pub fn intersects(self, precision: Precision, p: &ConvexPolygon, q: &ConvexPolygon) -> bool {
        self.run(precision, p, q).0
    }

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
    pub fn run_certified(
        self,
        precision: Precision,
        p: &ConvexPolygon,
        q: &ConvexPolygon,
    ) -> (Certificate, u64) {
        self.run_certified_rng(precision, p, q, &mut fresh_rng())
    }

    /// [`run_certified`](Self::run_certified) drawing from `rng`, as
    /// [`run_rng`](Self::run_rng).
    pub fn run_certified_rng<R: Rng + ?Sized>(
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

    /// [`run_certified`](Self::run_certified) with a kernel chosen at compile time.
    pub fn run_certified_with<K: Kernel>(
        self,
        k: K,
        p: &ConvexPolygon,
        q: &ConvexPolygon,
    ) -> (Certificate, u64) {
        self.run_certified_with_rng(k, p, q, &mut fresh_rng())
    }

    /// [`run_certified_with`](Self::run_certified_with) drawing from `rng`.
    pub fn run_certified_with_rng<K: Kernel, R: Rng + ?Sized>(
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
fn run_linked<L: LinkedIntersection, K: Kernel, R: Rng + ?Sized, P: Probe>(
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
fn run_linked_certified<L: LinkedIntersection, K: Kernel, R: Rng + ?Sized, P: Probe>(
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
