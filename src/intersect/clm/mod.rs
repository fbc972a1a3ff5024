//! [`Clm`]: the Chazelle–Liu–Magen expected-O(√n) test on linked polygons (thesis 3.3.2).
//!
//! # Algorithm
//! 1. Sample r_P ≈ c·√n vertices R_P of P and r_Q ≈ c·√m vertices R_Q of Q uniformly,
//!    in O(r): independent draws when r ≤ n/16 (no distinctness marks: one cache miss
//!    less per draw), else distinct ([`LinkedPolygon::sample_positions`]), and the whole
//!    polygon when r ≥ n. CH(R_P) ⊆ P, CH(R_Q) ⊆ Q.
//! 2. Run the LP ([`separating_line`]) on R_P and R_Q. If the hulls intersect, so do P
//!    and Q. Otherwise we get a line L with R_P on its closed right side, R_Q on its
//!    closed left side, and tangent vertices p ∈ R_P, q ∈ R_Q on L.
//! 3. Chains: C_P is the run of P's vertices strictly on Q's side of L, walked from p
//!    along the direction in which p's neighbour lies strictly beyond L, **including the
//!    first vertex back on the near side at both ends** (p itself at one end). Then
//!    CH(C_P) ⊇ P ∩ H where H is Q's closed side of L: the boundary of P leaves H on
//!    the two closing edges, which are edges of the chain. If neither neighbour of p is
//!    strictly beyond L, P touches H at most along L near p and C_P = (prev p, p, next p).
//!    C_Q likewise for Q on P's side. By convexity these runs are contiguous, so the walk
//!    finds all of them; their expected length is O(n / r) (Chazelle–Liu–Magen,
//!    Theorem 2.1).
//! 4. A common point x of P and Q lies on one side of L: if on Q's closed side, x ∈
//!    P ∩ H ⊆ CH(C_P) and x ∈ Q; otherwise x ∈ CH(C_Q) and x ∈ P. So P ∩ Q ≠ ∅ iff
//!    P ∩ CH(C_Q) ≠ ∅ or Q ∩ CH(C_P) ≠ ∅ (the converse holds as CH(C_P) ⊆ P).
//! 5. P against CH(C_Q): the LP on R_P and C_Q; intersecting hulls mean P ∩ Q ≠ ∅. Else
//!    its line L′ gives the chain C′_P of P beyond L′ (step 3 again), and P ∩ CH(C_Q) ≠ ∅
//!    iff CH(C′_P) ∩ CH(C_Q) ≠ ∅, one more LP. Q against CH(C_P) symmetrically.
//!    Both chains are convex and come in boundary order, so this last LP is a
//!    galloping walk along them ([`separate_chains`], exact, from C′_P's first vertex
//!    and C_Q's tangent vertex on L′), the LP only when the walk gives no answer.
//!    With [`ClmVariant::sample_walk`] (the default) the LPs of steps 2 and 5 on a
//!    sample are such walks too: the samples are put in boundary order first
//!    (`boundary_order`: sorted by `f64` angle keys whose order is proved exact when
//!    they are two or more apart, `orient` only on near-ties), after an LP on the
//!    first 12 points of each (intersecting samples usually show there, before any
//!    ordering). With independent draws on both sides those 12 + 12 are drawn and read
//!    first, and the rest of the samples only when their hulls are disjoint, so an
//!    intersecting query decided there reads 24 random vertices instead of 2⌈c·√n⌉
//!    (docs/results.md has the times).
//!    Before that LP, with [`ClmVariant::prefix_quads`] (the default): each prefix
//!    gives a quadrilateral of its own points (`Quad::spread`: the chord between its
//!    lowest and highest x and the point farthest from that chord on each side, by
//!    `f64` distances, a guide only), which lies inside its polygon; a prefix point of
//!    the other polygon in it (`prefix_inside`: `f64` signs first, three or four exact
//!    orientations for a point they put inside) is a vertex inside, so the polygons
//!    intersect and the query ends, certified, without any LP: most intersecting
//!    queries on crossing pairs end there (docs/certificates.md has the share).
//!    When the prefix LP then finds the prefixes' hulls disjoint, the next 12 points
//!    of each sample are tried in the same quadrilaterals before the samples are put
//!    in order. Both tests cost O(1) (at most 24 points each), so the bounds below
//!    are unchanged; on disjoint polygons they never answer, and cost a small share of
//!    the query that falls with n (docs/results.md).
//!    Order of work: chain walks run two at a time in lockstep, so that their cache
//!    misses (each step is a dependent load at a random arena position) overlap, and
//!    each LP runs as soon as the chain it needs is walked (either sample-against-chain
//!    LP can end the query); the second chain its line calls for then takes the freed
//!    walking slot (see `walk_and_decide`).
//!
//! The LPs never read the arenas: each sample's points are read once right after the
//! draw, in one pass of independent reads whose cache misses overlap, and each walk
//! records the points it reads for its side tests, so every LP runs on contiguous
//! copies (16 bytes per point of workspace), however often a set is used.
//!
//! The LPs' random order comes from CLM (thesis 3.3.5, [`LpOrder::Caller`]): samples
//! drawn independently are in random order already, chains are shuffled once when
//! walked (Fisher–Yates with Lemire's bounded draws from 32 random bits), and the LP
//! keeps the order given. With [`ClmVariant::sample_walk`] (the default) the samples
//! are put in boundary order and the LPs become walks, so chains are not shuffled: the
//! LPs left (the 12-point prefix LP on samples, random already, and the fallbacks)
//! shuffle their points themselves where needed. [`ClmVariant`] also runs the LP's own
//! shuffle and the thesis's Fisher–Yates sampling (3.3.1), for comparison.
//!
//! At most five LPs on O(r + n/r) points each, so the expected time is O(√n) for
//! r = Θ(√n). The constant c = [`Clm::SAMPLE_FACTOR`] was chosen by measurement
//! (docs/sublinear.md, `benches/clm.rs`).
//!
//! # Certificate
//! The certified call records what decided (a vertex inside, or an LP) and every
//! separating line it found (nothing in the plain call: the recording is chosen at
//! compile time).
//! * **Disjoint.** Each LP line touches an input point of each set; if both are
//!   extreme in their whole polygons (each neighbour checked, four predicates), the
//!   line supports both polygons and an edge at its tangent vertices separates. The
//!   lines are tried from the last; the chain LPs' lines almost always qualify.
//! * **Intersecting.** A query the prefixes' quadrilaterals answered has its
//!   certificate already: the vertex inside (most intersecting queries on crossing
//!   pairs). Otherwise the LP that found the hulls
//!   intersecting reports a witness (at most nine
//!   points: the violating point, the one or two points that bounded its 1D problem,
//!   the previous optimum's tangent points, and a₀, b₀ and the bounding pair, which
//!   restrict separators to the LP's half-circle of directions). When the LP ran on
//!   the two samples (nearly always the 12-point prefixes), its last step names a
//!   point z beyond a chord of the other polygon's sample (the violating point p and
//!   the two points of the other set it failed on, or, for a mixed pair, the other
//!   set's bound y beyond p and p's own bound): z is tested in the quadrilateral of
//!   that sample on that chord (the sample vertex farthest beyond it on each side,
//!   one pass of `f64` distances), then the rest of z's sample in the same
//!   quadrilateral, then the chord's sample in the quadrilateral of z's sample
//!   (below) unless the prefix test tried that one already: sample vertices already
//!   read, no draw. Every quadrilateral test computes its signs in `f64` first and
//!   tests exactly only a point they put inside. Then the drawn vertices below, and
//!   only then the last step's five points, in O(1): when the violating point p
//!   failed on two points of the other set, one on each side of it in x′, the
//!   segment from p to its set's frame point meets their triangle with the other
//!   frame point ([`LpWorkspace::straddle`](crate::lp::LpWorkspace::straddle): p or that point
//!   inside, else two chords); when it failed on one point y of the other set and one
//!   of its own, y usually lies in the triangle of p, that point and the previous
//!   optimum's tangent point of p's set (or p's frame point)
//!   ([`LpWorkspace::mixed`](crate::lp::LpWorkspace::mixed)). A point of one set in
//!   the hull of the other's is a vertex inside. The **drawn vertices**
//!   (`drawn_witness`): each sample gives a quadrilateral of its own vertices, hence
//!   inside its polygon (the two above where the last step named a chord; else the
//!   chord between its lowest and highest x, and the sample
//!   vertex farthest from that chord's line on each side, by `f64` distances over at
//!   most about 16 of its points: a guide only); then rounds of one uniform vertex
//!   draw on each polygon (`below`, as the samples are drawn), each tested against the
//!   other polygon's quadrilateral with three orientations (a fourth checks the
//!   triangle it lands in), so a drawn vertex inside is a vertex inside. The samples'
//!   hulls meet, and on crossing polygons such as the generators' intersecting pairs a
//!   fair part of each boundary lies in the other's quadrilateral, so a few rounds
//!   usually suffice (nearly all of these queries on Rotated pairs end here;
//!   docs/certificates.md); after `DRAW_ROUNDS` (16) rounds the query goes on below.
//!   The step costs O(1) (at most 16 rounds, 24 sample tests and three passes over
//!   about 16 points), so the expected bound is unchanged; it replaces the cone
//!   search and the chord walk below in nearly every query that needed them, which
//!   cost a multiple of the plain query (docs/certificates.md). Else
//!   the points the LP examined (a few dozen) are searched without building a hull
//!   ([`cone_witness`](witness::cone_witness)): before the violating point
//!   x the LP's line separated them, so seen from x its own set spans less than a
//!   half-turn, and a point of the other set in that cone lies in the triangle of x
//!   and the cone's two extreme points (one or two orientations per point, three for a
//!   candidate); then x itself in a triangle of the other set's points, found the same
//!   way. Else two of the points form crossing chords (from the last step, else from
//!   the cone, else from the whole witness): P's chord is resolved by a walk along P
//!   started from the sample or chain vertex nearest Q's chord's line on either side,
//!   so it stays within one gap between those vertices (expected O(n/r + r), i.e.
//!   O(√n) like the test itself, but far more than an intersecting query that stopped
//!   after a few dozen points); an end of the edge it finds usually lies in the
//!   triangle of Q's chord and Q's sample vertex farthest from it on that side (a
//!   vertex inside, no second walk), else Q's chord is resolved by a walk too.
//!   Where a walk along two ordered sets ([`separate_chains`]) found their hulls
//!   meeting, no LP ran and there is no LP witness: both sets list the vertices of
//!   strictly convex polygons (a sample in boundary order, a chain in walk order), so
//!   Barba's certified search on the two (O(log r)) gives a vertex of one inside the
//!   other or two crossing edges, which are chords, resolved as above (the LP is
//!   rerun only for sets of fewer than three points); when the sets are the two
//!   samples, drawn vertices are tried first as above, with each quadrilateral built
//!   on its polygon's crossing edge. So the certified query draws the plain one's
//!   samples, except after an LP rerun for a witness (such small sets, or a meet found
//!   by the chain-against-chain walk); the drawn vertices come from the workspace's
//!   own generator (SplitMix64, stirred with the query's first sample positions), so
//!   the caller's generator ends where the plain call leaves it.
//! * Otherwise (an inconsistent kernel) only the answer, completed on the walked arrays.
//!
//! # Complexity
//! Expected O((c + 1/c)·(√n + √m)) for polygons of n and m vertices, over the random
//! samples and the LP's random orders, for **every** input (no assumption on the
//! polygons). Polygons with at most r vertices are used whole: one LP decides.
//! The worst case (an absurdly unlucky sample) is O(n + m) walks and quadratic LP time.
//! A [`Probe`] receives one iteration per unit of work: each point an LP examines
//! (bounding scan, incremental loop, one-dimensional steps, certification) and each
//! chain vertex walked; and, apart, the sample sizes, each LP call (constraints, points
//! examined) and each chain walk (vertices), which [`Counts`](super::Counts) records.
//!
//! # Degeneracies
//! Closed sets throughout: the LP reports touching hulls as intersecting and only
//! returns lines that separate with closed sides, and the chains include the closing
//! vertices on the near side, so shared vertices, vertices on edges, shared or
//! overlapping edges and containment are all intersections. The answer never depends
//! on the random draw; tests/clm.rs runs many seeds per pair.
//!
//! # Precision
//! Every decision is a predicate on input points (`orient` for sides and chain walks,
//! the LP's `orient`/`cross`/`dot`): exact under [`Exact`](crate::Exact), so it equals
//! [`Linear`](super::Linear) on every input. Under [`Fast`](crate::Fast) chain walks are
//! capped at n steps, so the test always terminates.

mod certify;
mod lp_call;
mod ordering;
mod quads;
mod query;
mod sampling;
mod walks;
mod witness;

use super::engine::{LinkedEngine, linked_entry_points};
use super::linked::LinkedIntersection;
use super::{Derivation, Probe, Which};
use crate::kernel::{Kernel, Point};
use crate::lp::{Bitangent, LpWorkspace};
use crate::polygon::{LinkedPolygon, SampleWorkspace};
use certify::certify;
use ordering::OrderScratch;
use quads::Quad;
use query::clm;
use rand::{Rng, RngCore};

/// The Chazelle–Liu–Magen sublinear test with the default sample factor
/// `Clm::SAMPLE_FACTOR` (1); see the module docs.
///
/// ```
/// use polysect::{ConvexPolygon, LinkedPolygon};
/// use polysect::generate::regular_polygon;
/// use polysect::intersect::{Clm, ClmWorkspace, LinkedIntersection};
/// use rand::{SeedableRng, rngs::SmallRng};
/// let mut rng = SmallRng::seed_from_u64(7);
/// let big = regular_polygon(4096, 1.0);
/// let p = LinkedPolygon::from_convex_shuffled(&big, &mut rng);
/// let far = big.map(|v| polysect::Point::new(v.x + 3.0, v.y))?;
/// let q = LinkedPolygon::from_convex_shuffled(&far, &mut rng);
/// let mut ws = ClmWorkspace::default();
/// assert!(!Clm.intersects_with_workspace(polysect::Exact, &p, &q, &mut rng, &mut ws));
/// // A triangle sharing the vertex (1, 0): touching is intersection.
/// let q = LinkedPolygon::from_points([[1.0, 0.0], [2.0, -1.0], [2.0, 1.0]])?;
/// assert!(Clm.intersects_with_workspace(polysect::Exact, &p, &q, &mut rng, &mut ws));
/// # Ok::<(), polysect::PolygonError>(())
/// ```
#[derive(Clone, Copy, Debug, Default)]
pub struct Clm;

impl Clm {
    instrument_pub! {
        /// The sample size is ⌈c·√n⌉ vertices per polygon of n vertices, with this c.
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        const SAMPLE_FACTOR: f64 = 1.0;
    }
}

/// The same test with an explicit sample factor c (samples of ⌈c·√n⌉ vertices), for
/// experiments that tune c.
#[derive(Clone, Copy, Debug)]
pub struct ClmWithFactor(pub f64);

/// How [`ClmVariant`] draws its samples.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Sampling {
    /// Ours (the default): independent uniform draws when r ≤ n/16, else distinct
    /// positions by rejection with marks (see the module docs, step 1).
    #[default]
    Independent,
    /// The thesis's (its 3.3.1): r distinct positions by a partial Fisher–Yates shuffle
    /// of the positions 0..n. The thesis swaps the arena's nodes themselves; here an
    /// index array in the workspace is shuffled and restored after the draw, so the
    /// arena is untouched (n · 4 bytes of workspace, one extra random access per draw).
    FisherYates,
}

/// Who puts the LP's constraints in random order in [`ClmVariant`].
// Only the research variants (`instrument`) choose `Lp`.
#[cfg_attr(not(feature = "instrument"), allow(dead_code))]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum LpOrder {
    /// Every LP shuffles all its points (Seidel's algorithm as written).
    Lp,
    /// The default, from the thesis (its 3.3.5): the caller randomises. Independent
    /// samples come in random order and are not shuffled again (distinct samples and
    /// whole polygons, listed in arena order, are shuffled once); each chain is
    /// shuffled once when walked; the LP keeps the order given
    /// ([`LpWorkspace::keep_order`]), taking A's and B's points alternately. Seidel's
    /// bound still holds: the first i points are a uniformly random subset of ⌈i/2⌉
    /// of A and ⌊i/2⌋ of B, and the i-th is uniform among its set's part, so it is one
    /// of the (at most two, barring ties) points the optimum is tight on in its set
    /// with probability O(1/i). Measured faster than [`LpOrder::Lp`] (docs/results.md):
    /// no random swaps per point and per LP, and a sample shared by two LPs or a chain
    /// shared by two is randomised once. With [`ClmVariant::sample_walk`] on (the
    /// default) chains are not shuffled, since no walk needs a random order; this
    /// choice then matters only for the LPs that still run.
    #[default]
    Caller,
}

/// The test with every implementation choice explicit: the sample factor and the
/// thesis's variants of sampling and of the LP's randomisation, for experiments that
/// compare them (`polysect bench sqrt`, docs/thesis.md). Every variant gives the same
/// answers; only the time changes.
#[derive(Clone, Copy, Debug)]
pub struct ClmVariant {
    /// Samples of ⌈factor·√n⌉ vertices.
    pub factor: f64,
    /// How the samples are drawn.
    pub sampling: Sampling,
    /// Who randomises the LPs' order.
    pub lp_order: LpOrder,
    /// Whether the two chain-against-chain LPs (step 5's second LP) are decided by
    /// [`separate_chains`](crate::lp::separate_chains), a walk along both chains in their order, instead of the LP
    /// (the default; the LP still runs when the walk gives no answer, and for the
    /// witness of a certified query whose chains intersect).
    pub chain_walk: bool,
    /// Whether the samples are put in boundary order (sorted by
    /// angle about their lowest point, exactly) so that the three LPs on a sample — the
    /// samples against each other and each against the other polygon's first chain —
    /// are [`separate_chains`](crate::lp::separate_chains) walks too (the default). Then no LP input is in random
    /// order: chains are not shuffled, and an LP that still runs (a walk without an
    /// answer, a certified query's witness) shuffles its points itself.
    pub sample_walk: bool,
    /// Whether, with [`sample_walk`](Self::sample_walk), the prefixes' quadrilaterals
    /// are tried first (the default): a prefix vertex of one polygon in a quadrilateral
    /// of the other's prefix answers an intersecting query before the prefix LP, and
    /// the next points of the samples are tried in the same quadrilaterals before the
    /// samples are put in order. Each test certifies its answer (a vertex inside).
    pub prefix_quads: bool,
}

impl Default for ClmVariant {
    fn default() -> Self {
        ClmVariant {
            factor: Clm::SAMPLE_FACTOR,
            sampling: Sampling::default(),
            lp_order: LpOrder::default(),
            chain_walk: true,
            sample_walk: true,
            prefix_quads: true,
        }
    }
}

/// Reusable scratch memory for [`Clm`]: sample marks and the sample, chain and LP buffers.
#[derive(Clone, Debug, Default)]
pub struct ClmWorkspace {
    sample: SampleWorkspace,
    rp: Vec<u32>,
    rq: Vec<u32>,
    cp: Vec<u32>,
    cq: Vec<u32>,
    chain: Vec<u32>,
    chain2: Vec<u32>,
    lp: LpWorkspace,
    /// The points of the samples, in the order of `rp` and `rq`, read from the arenas
    /// once (the LPs read them again and again).
    rp_points: Vec<Point>,
    rq_points: Vec<Point>,
    /// The points of the chains, in the order of `cp`, `cq`, `chain`, `chain2`,
    /// recorded by the walks as they read them.
    chain_points: [Vec<Point>; 4],
    /// C_P and C_Q (positions and points) in walk order, before the shuffle, for
    /// [`separate_chains`] ([`ClmVariant::chain_walk`]).
    ordered: [(Vec<u32>, Vec<Point>); 2],
    walked: u64,
    /// Sample points tested in the other sample's quadrilaterals (`prefix_inside`).
    tested: u64,
    /// Scratch of [`boundary_order`].
    order: OrderScratch,
    /// The index array of [`Sampling::FisherYates`] (the identity between draws) and
    /// the swaps of one draw, to restore it.
    perm: Vec<u32>,
    swaps: Vec<u32>,
    /// What the last certified query found, for its certificate.
    trace: Trace,
    /// The certified query's drawn witnesses (`drawn_witness`): the samples' hulls and
    /// the counts.
    draws: Draws,
}

/// Counts of [`drawn_witness`]: how many queries a drawn vertex certified and how many
/// went on (to the cone search and the chord walk), (for tests) a cap on the rounds,
/// and the generator of the draws.
#[derive(Clone, Debug, Default)]
struct Draws {
    found: u64,
    walked: u64,
    rounds: Option<u32>,
    generator: SplitMix,
}

/// SplitMix64, the drawn witnesses' random generator: it lives in the workspace, so
/// the certified call draws from the caller's generator exactly what the plain call
/// draws (the same samples, the same answers, the same state after the query).
#[derive(Clone, Copy, Debug, Default)]
struct SplitMix(u64);

impl RngCore for SplitMix {
    #[inline]
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    #[inline]
    fn next_u32(&mut self) -> u32 {
        (self.next_u64() >> 32) as u32
    }

    fn fill_bytes(&mut self, dst: &mut [u8]) {
        for chunk in dst.chunks_mut(8) {
            let bytes = self.next_u64().to_le_bytes();
            chunk.copy_from_slice(&bytes[..chunk.len()]);
        }
    }
}

/// The point sets an LP of [`clm`] ran on: samples, first chains, second chains.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Set {
    Rp,
    Rq,
    Cp,
    Cq,
    Chain,
    Chain2,
}

impl Set {
    /// The polygon the set's positions belong to.
    fn of(self) -> Which {
        match self {
            Set::Rp | Set::Cp | Set::Chain => Which::P,
            Set::Rq | Set::Cq | Set::Chain2 => Which::Q,
        }
    }
}

/// What a certified query recorded: the LP that found intersecting hulls (its
/// witness is in the LP workspace), or every separating line with the sets it
/// separates (A on its right, B on its left).
#[derive(Clone, Debug, Default)]
struct Trace {
    /// A sample vertex the prefix test ([`prefix_inside`]) found inside the other
    /// polygon (which polygon it is a vertex of, the point): the certificate itself.
    inside: Option<(Which, Point)>,
    meet: Option<(Set, Set)>,
    /// The prefixes' quadrilaterals (P's, Q's) that the prefix test tried, when the
    /// prefix LP found the prefixes' hulls intersecting.
    spread: Option<(Quad, Quad)>,
    lines: Vec<(Bitangent, Set, Set)>,
}

impl ClmWorkspace {
    instrument_pub! {
        /// The LP statistics accumulated by queries using this workspace: work counter and
        /// recomputations after failed certification (see [`LpWorkspace`]).
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn lp_stats(&self) -> &LpWorkspace {
            &self.lp
        }
    }

    instrument_pub! {
        /// Chain vertices collected by queries using this workspace (each one a step along
        /// the linked list).
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn walked(&self) -> u64 {
            self.walked
        }
    }
}

impl LinkedIntersection for Clm {
    const NAME: &'static str = "clm";
    type Workspace = ClmWorkspace;

    linked_entry_points!();
}

impl LinkedEngine for Clm {
    #[inline]
    fn intersects_in<K: Kernel, R: Rng + ?Sized, P: Probe>(
        &self,
        kernel: K,
        p: &LinkedPolygon,
        q: &LinkedPolygon,
        rng: &mut R,
        workspace: &mut ClmWorkspace,
        probe: &mut P,
    ) -> bool {
        ClmWithFactor(Clm::SAMPLE_FACTOR).intersects_in(kernel, p, q, rng, workspace, probe)
    }

    #[inline]
    fn derive_in<K: Kernel, R: Rng + ?Sized, P: Probe>(
        &self,
        kernel: K,
        p: &LinkedPolygon,
        q: &LinkedPolygon,
        rng: &mut R,
        workspace: &mut ClmWorkspace,
        probe: &mut P,
    ) -> Derivation {
        ClmWithFactor(Clm::SAMPLE_FACTOR).derive_in(kernel, p, q, rng, workspace, probe)
    }
}

impl LinkedIntersection for ClmWithFactor {
    const NAME: &'static str = "clm";
    type Workspace = ClmWorkspace;

    linked_entry_points!();
}

impl LinkedEngine for ClmWithFactor {
    #[inline]
    fn intersects_in<K: Kernel, R: Rng + ?Sized, P: Probe>(
        &self,
        kernel: K,
        p: &LinkedPolygon,
        q: &LinkedPolygon,
        rng: &mut R,
        workspace: &mut ClmWorkspace,
        probe: &mut P,
    ) -> bool {
        let v = ClmVariant {
            factor: self.0,
            ..ClmVariant::default()
        };
        v.intersects_in(kernel, p, q, rng, workspace, probe)
    }

    #[inline]
    fn derive_in<K: Kernel, R: Rng + ?Sized, P: Probe>(
        &self,
        kernel: K,
        p: &LinkedPolygon,
        q: &LinkedPolygon,
        rng: &mut R,
        workspace: &mut ClmWorkspace,
        probe: &mut P,
    ) -> Derivation {
        let v = ClmVariant {
            factor: self.0,
            ..ClmVariant::default()
        };
        v.derive_in(kernel, p, q, rng, workspace, probe)
    }
}

impl LinkedIntersection for ClmVariant {
    const NAME: &'static str = "clm";
    type Workspace = ClmWorkspace;

    linked_entry_points!();
}

impl LinkedEngine for ClmVariant {
    fn intersects_in<K: Kernel, R: Rng + ?Sized, P: Probe>(
        &self,
        k: K,
        p: &LinkedPolygon,
        q: &LinkedPolygon,
        rng: &mut R,
        ws: &mut ClmWorkspace,
        probe: &mut P,
    ) -> bool {
        let work_before = ws.lp.work + ws.walked + ws.tested;
        let answer = clm::<K, R, P, false>(k, *self, p, q, rng, ws, probe);
        for _ in work_before..ws.lp.work + ws.walked + ws.tested {
            probe.iteration();
        }
        answer
    }

    /// See the module docs' "Certificate" section.
    fn derive_in<K: Kernel, R: Rng + ?Sized, P: Probe>(
        &self,
        k: K,
        p: &LinkedPolygon,
        q: &LinkedPolygon,
        rng: &mut R,
        ws: &mut ClmWorkspace,
        probe: &mut P,
    ) -> Derivation {
        let work_before = ws.lp.work + ws.walked + ws.tested;
        let answer = clm::<K, R, P, true>(k, *self, p, q, rng, ws, probe);
        for _ in work_before..ws.lp.work + ws.walked + ws.tested {
            probe.iteration();
        }
        // The drawn witnesses' generator: the workspace's, stirred with this query's
        // first sample positions, so the caller's generator serves the plain draws only.
        let stir = |r: &[u32]| u64::from(r.first().copied().unwrap_or(0));
        let mut draws = SplitMix(ws.draws.generator.0 ^ (stir(&ws.rp) << 32 | stir(&ws.rq)));
        let certificate = certify(k, answer, p, q, ws, &mut draws);
        ws.draws.generator = draws;
        certificate.map_or(Derivation::Answer(answer), Derivation::Certified)
    }
}

#[cfg(test)]
mod tests;
