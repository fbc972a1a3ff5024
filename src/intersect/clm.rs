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
//!    (at 2^20, 1.2 instead of 55 µs; docs/results.md).
//!    Before that LP, with [`ClmVariant::prefix_quads`] (the default): each prefix
//!    gives a quadrilateral of its own points (`Quad::spread`: the chord between its
//!    lowest and highest x and the point farthest from that chord on each side, by
//!    `f64` distances, a guide only), which lies inside its polygon; a prefix point of
//!    the other polygon in it (`prefix_inside`: `f64` signs first, three or four exact
//!    orientations for a point they put inside) is a vertex inside, so the polygons
//!    intersect and the query ends, certified, without any LP: about 95% of the
//!    intersecting Rotated queries at 2^10–2^18 end there (docs/certificates.md).
//!    When the prefix LP then finds the prefixes' hulls disjoint, the next 12 points
//!    of each sample are tried in the same quadrilaterals before the samples are put
//!    in order. Both tests cost O(1) (at most 24 points each), so the bounds below
//!    are unchanged; on disjoint polygons they never answer, and cost about 2,500
//!    instructions per query (2.5K of 34K at 2^10, under 2% from 2^16).
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
//!   certificate already: the vertex inside (about 95% of the intersecting queries on
//!   the generators' crossing pairs). Otherwise the LP that found the hulls
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
//!   usually suffice (on Rotated pairs 97–99% of these queries end here, after
//!   about three rounds); after `DRAW_ROUNDS` (16) rounds the query goes on below.
//!   The step costs O(1) (at most 16 rounds, 24 sample tests and three passes over
//!   about 16 points), so the expected bound is unchanged; it replaces the cone
//!   search and the chord walk below in nearly every query that needed them, which
//!   at 2^16 cost about three times the plain query (docs/certificates.md). Else
//!   the points the LP examined (a few dozen) are searched without building a hull
//!   ([`cone_witness`](super::certificate::cone_witness)): before the violating point
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

use super::certificate::{
    Cone, Radon, WitnessVertex, cone_witness, from_support, in_triangles, resolve_linked_chords,
    straddle_certificate, supports_left, supports_right, witness_certificate,
};
use super::linked::LinkedIntersection;
use super::{ArrayIntersection, Barba};
use super::{Certificate, Derivation, Probe, Which};
use crate::kernel::{DirectedLine, Kernel, Orientation, Point};
use crate::lp::{
    ArenaPoints, Bitangent, LpError, LpWorkspace, Separation, WitnessPoint, separate_chains, separating_line,
};
use crate::polygon::{ConvexPolygon, LinkedPolygon, SampleWorkspace, box_of};
use rand::{Rng, RngCore};

/// The Chazelle–Liu–Magen sublinear test with the default sample factor
/// [`Clm::SAMPLE_FACTOR`]; see the module docs.
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
    /// The sample size is ⌈c·√n⌉ vertices per polygon of n vertices, with this c.
    pub const SAMPLE_FACTOR: f64 = 1.0;
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
    /// [`separate_chains`], a walk along both chains in their order, instead of the LP
    /// (the default; the LP still runs when the walk gives no answer, and for the
    /// witness of a certified query whose chains intersect).
    pub chain_walk: bool,
    /// Whether the samples are put in boundary order (sorted by
    /// angle about their lowest point, exactly) so that the three LPs on a sample — the
    /// samples against each other and each against the other polygon's first chain —
    /// are [`separate_chains`] walks too (the default). Then no LP input is in random
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
    /// The LP statistics accumulated by queries using this workspace: work counter and
    /// recomputations after failed certification (see [`LpWorkspace`]).
    pub fn lp_stats(&self) -> &LpWorkspace {
        &self.lp
    }

    /// Chain vertices collected by queries using this workspace (each one a step along
    /// the linked list).
    pub fn walked(&self) -> u64 {
        self.walked
    }
}

impl LinkedIntersection for Clm {
    const NAME: &'static str = "clm";
    type Workspace = ClmWorkspace;

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

/// The certificate of a certified query from its trace (module docs), or `None` when
/// the trace gives none in O(1) (then the caller walks the polygons). `rng` serves the
/// drawn witnesses ([`drawn_witness`]).
fn certify<K: Kernel, R: Rng + ?Sized>(
    k: K,
    answer: bool,
    p: &LinkedPolygon,
    q: &LinkedPolygon,
    ws: &mut ClmWorkspace,
    rng: &mut R,
) -> Option<Certificate> {
    let ClmWorkspace {
        rp,
        rq,
        cp,
        cq,
        chain,
        chain2,
        lp,
        rp_points,
        rq_points,
        chain_points,
        trace,
        draws,
        ..
    } = ws;
    let (lp, trace) = (&*lp, &*trace);
    let set = |s: Set| -> (&[u32], &LinkedPolygon) {
        let positions = match s {
            Set::Rp => &*rp,
            Set::Rq => &*rq,
            Set::Cp => &*cp,
            Set::Cq => &*cq,
            Set::Chain => &*chain,
            Set::Chain2 => &*chain2,
        };
        (positions, if s.of() == Which::P { p } else { q })
    };
    // The points at a set's positions, index for index.
    let points = |s: Set| -> &[Point] {
        match s {
            Set::Rp => rp_points,
            Set::Rq => rq_points,
            Set::Cp | Set::Cq | Set::Chain | Set::Chain2 => &chain_points[s.chain_index()],
        }
    };
    if answer {
        if let Some((of, point)) = trace.inside {
            return Some(Certificate::VertexInside { of, point });
        }
        // The LP's witness; else a vertex inside among the points it examined; else its
        // two crossing chords, resolved by walks from the nearest sample or chain vertex.
        let (a, b) = trace.meet?;
        if lp.witness_points().is_empty() {
            // The chain walk found the sets' hulls intersecting (`walk_or_lp`): both are
            // in boundary order, so they are convex polygons.
            let samples = (a, b) == (Set::Rp, Set::Rq) || (a, b) == (Set::Rq, Set::Rp);
            // Samples the walk found meeting are in boundary order already.
            let drawn = |[pc, qc]: [(Point, Point); 2], rng: &mut R| {
                let quads = (|| Quad::new(pc, rp_points), || Quad::new(qc, rq_points));
                draws.witness(k, (p, q), quads, rng)
            };
            return convex_sets_certificate(k, (p, q), (a, b), set, points, samples.then_some(drawn), rng);
        }
        // The sets are one of each polygon. Witness points keep their index in their
        // set until a pair of chords needs the arena positions (most queries end
        // before, with a vertex inside).
        let (a_of, b_of) = (a.of(), b.of());
        let vertex = |w: WitnessPoint| WitnessVertex {
            point: w.point,
            of: if w.in_b { b_of } else { a_of },
            pos: w.index,
        };
        // The LP's last step: its violating point beyond a chord of the other set (five
        // points), or a mixed pair of bounds (the other set's bound beyond a chord of
        // the violating point's set).
        let straddle = lp.straddle();
        let mixed = if straddle.is_none() { lp.mixed() } else { None };
        let samples = (a, b) == (Set::Rp, Set::Rq) || (a, b) == (Set::Rq, Set::Rp);
        if samples {
            // That point in the quadrilateral of the chord's sample on the chord (the
            // sample vertex farthest beyond it on either side): no pass but that one.
            let named = match (straddle, mixed) {
                (Some([x, _, b, c, _]), _) => Some((x, [b, c])),
                (None, Some([y, x, x1, _, _])) => Some((y, [x, x1])),
                _ => None,
            };
            // The prefix test's quadrilaterals, where it ran: their tests are done.
            let mut quads = trace.spread.map_or((None, None), |(a, b)| (Some(a), Some(b)));
            // (Tests turn the quadrilaterals off with a cap of 0 rounds.)
            if let Some((z, [u, v])) = named
                && draws.rounds != Some(0)
            {
                let (z, of) = ((vertex(z).of, z.point), vertex(u).of);
                if let Some(c) =
                    sample_quads(k, z, (of, (u.point, v.point)), (rp_points, rq_points), &mut quads)
                {
                    draws.found += 1;
                    return Some(c);
                }
            }
            // A drawn vertex of one polygon in the other sample's quadrilateral.
            let quads = (
                || quads.0.unwrap_or_else(|| Quad::spread(rp_points)),
                || quads.1.unwrap_or_else(|| Quad::spread(rq_points)),
            );
            if let Some(c) = draws.witness(k, (p, q), quads, rng) {
                return Some(c);
            }
        }
        // The last step's five points: a vertex inside or two chords.
        let mut chords = None;
        if let Some([x, x0, b, c, y0]) = straddle {
            match straddle_certificate(k, [vertex(x), vertex(x0)], [vertex(b), vertex(c), vertex(y0)]) {
                Radon::Inside(c) => return Some(c),
                Radon::Chords(pc, qc) => chords = Some((pc, qc)),
                Radon::Nothing => {}
            }
        } else if let Some([y, x, x1, t, x0]) = mixed {
            let (x, x1, t, x0) = (vertex(x), vertex(x1), vertex(t), vertex(x0));
            if let Some(c) = in_triangles(k, vertex(y), &[[x, x1, t], [x, x1, x0]]) {
                return Some(c);
            }
        }
        // The points the LP examined (which hold most of its witness): those of the
        // other set than the violating point in the cone it sees its own set in.
        if let Some(&x) = lp.witness_points().first() {
            match cone_witness(
                k,
                x,
                || lp.examined(),
                |in_b| if in_b { b_of } else { a_of },
                chords.is_none(),
            ) {
                Cone::Inside(c) => return Some(c),
                Cone::Chords(own, other) => {
                    let (own, other) = (own.map(|w| w.index), other.map(|w| w.index));
                    chords = Some(if vertex(x).of == Which::P {
                        (own, other)
                    } else {
                        (other, own)
                    });
                }
                _ => {}
            }
        }
        // Two crossing chords: from the last step, else from the cone, else from the
        // whole witness.
        let (pc, qc) = match chords {
            Some(c) => c,
            None => match witness_certificate(k, lp.witness_points().iter().map(|&w| vertex(w))) {
                Radon::Inside(c) => return Some(c),
                Radon::Chords(pc, qc) => (pc, qc),
                Radon::Nothing => return None,
            },
        };
        let (p_set, q_set) = if a_of == Which::P { (a, b) } else { (b, a) };
        // Before walking: a drawn vertex of one polygon in the other's sample hull.
        let starts = |s: Set| (set(s).0, points(s));
        // A chord's ends from indices in its set to arena positions.
        let ends = |s: Set, [i, j]: [Option<usize>; 2]| {
            let positions = set(s).0;
            Some((positions[i?] as usize, positions[j?] as usize))
        };
        return resolve_linked_chords(
            k,
            p,
            ends(p_set, pc)?,
            starts(p_set),
            q,
            ends(q_set, qc)?,
            starts(q_set),
        );
    }
    // The lines whose tangent vertices are extreme in the whole polygons separate them.
    trace.lines.iter().rev().find_map(|&(t, a, b)| {
        let ((a_pos, a_poly), (b_pos, b_poly)) = (set(a), set(b));
        let (ta, tb) = (a_pos[t.a] as usize, b_pos[t.b] as usize);
        let line = (t.start, t.end);
        if !supports_right(k, line, a_poly, ta) || !supports_left(k, line, b_poly, tb) {
            return None;
        }
        from_support(k, line, a_poly, ta, b_poly, tb).map(|c| c.relative_to(a.of()))
    })
}

/// The certificate of intersecting sets `a` and `b` (one of each polygon, given by
/// `set` and `points`) that the chain walk found meeting: each is in boundary order
/// (a sample put in order, or a chain in walk order, either way round), so it lists the
/// vertices of a strictly convex polygon, inside its own polygon. Barba's certified
/// search on the two, O(log r), gives a vertex of one inside the other (a vertex of its
/// polygon inside the other polygon) or two crossing edges, which are chords of the
/// polygons, resolved along them as the LP's chords are, unless `drawn` (given when
/// the sets are the two samples) finds a drawn vertex inside first. `None` for sets of
/// fewer than three points (the caller reran the LP for those) or if the search gives
/// no witness (only an inconsistent kernel).
#[inline(never)]
#[allow(clippy::too_many_arguments)]
fn convex_sets_certificate<'a, K: Kernel, R: Rng + ?Sized>(
    k: K,
    (p, q): (&LinkedPolygon, &LinkedPolygon),
    (a, b): (Set, Set),
    set: impl Fn(Set) -> (&'a [u32], &'a LinkedPolygon),
    points: impl Fn(Set) -> &'a [Point],
    drawn: Option<impl FnOnce([(Point, Point); 2], &mut R) -> Option<Certificate>>,
    rng: &mut R,
) -> Option<Certificate> {
    let polygon = |s: Set| -> Option<ConvexPolygon> {
        let v = points(s);
        if v.len() < 3 {
            return None;
        }
        // Strictly convex: the first three points give the orientation.
        let turn = k.orient(v[0], v[1], v[2]);
        if turn == Orientation::Collinear {
            return None;
        }
        let mut v = v.to_vec();
        if turn == Orientation::Cw {
            v.reverse();
        }
        Some(ConvexPolygon::from_ccw_unchecked(v))
    };
    let Derivation::Certified(c) = Barba.derive_probed(k, &polygon(a)?, &polygon(b)?, &mut ()) else {
        return None;
    };
    let (p_set, q_set) = if a.of() == Which::P { (a, b) } else { (b, a) };
    match c.relative_to(a.of()) {
        c @ Certificate::VertexInside { .. } => Some(c),
        Certificate::CrossingEdges { p: [u, v], q: [s, t] } => {
            // Before walking: a drawn vertex of one polygon in the other's sample hull.
            if let Some(c) = drawn.and_then(|drawn| drawn([(u, v), (s, t)], rng)) {
                return Some(c);
            }
            // The chords' ends at their arena positions.
            let at = |set_of: Set, x: Point| {
                let i = points(set_of).iter().position(|&y| y == x)?;
                Some(set(set_of).0[i] as usize)
            };
            let starts = |s: Set| (set(s).0, points(s));
            resolve_linked_chords(
                k,
                p,
                (at(p_set, u)?, at(p_set, v)?),
                starts(p_set),
                q,
                (at(q_set, s)?, at(q_set, t)?),
                starts(q_set),
            )
        }
        Certificate::Separated { .. } => None,
    }
}

/// How many rounds of draws (one vertex of each polygon per round) [`drawn_witness`]
/// tries before a chord is walked.
const DRAW_ROUNDS: u32 = 16;

impl Draws {
    /// [`drawn_witness`] against the quadrilaterals of the two samples (`samples`:
    /// R_P's points, R_Q's) on P's and Q's chord (`chords`, crossing). Counts the
    /// outcome.
    fn witness<K: Kernel, R: Rng + ?Sized>(
        &mut self,
        k: K,
        (p, q): (&LinkedPolygon, &LinkedPolygon),
        quads: (impl FnOnce() -> Quad, impl FnOnce() -> Quad),
        rng: &mut R,
    ) -> Option<Certificate> {
        let rounds = self.rounds.unwrap_or(DRAW_ROUNDS);
        let found = drawn_witness(k, (p, q), quads, rounds, rng);
        if found.is_some() {
            self.found += 1;
        } else {
            self.walked += 1;
        }
        found
    }
}

/// A quadrilateral of sample vertices of one polygon (so inside it): a chord a–b and
/// the sample vertices farthest from its line on its left and on its right, chosen by
/// distances computed in `f64` (a guide: [`Quad::contains`] checks exactly).
#[derive(Clone, Copy, Debug)]
struct Quad {
    chord: (Point, Point),
    left: Option<Point>,
    right: Option<Point>,
}

impl Quad {
    /// The quadrilateral on the chord between `sample`'s lowest and highest x among
    /// about 16 of its points (every ⌈len/16⌉-th); empty for an empty sample.
    fn spread(sample: &[Point]) -> Quad {
        let Some(first) = sample.first() else {
            return Quad {
                chord: (Point::new(0.0, 0.0), Point::new(0.0, 0.0)),
                left: None,
                right: None,
            };
        };
        // Indices and coordinates, not points, are carried through the loop.
        let (mut lo, mut hi, mut lo_x, mut hi_x) = (0, 0, first.x, first.x);
        let (stride, mut i) = (Quad::stride(sample), 0);
        while let Some(v) = sample.get(i) {
            if v.x < lo_x {
                (lo, lo_x) = (i, v.x);
            } else if v.x > hi_x {
                (hi, hi_x) = (i, v.x);
            }
            i += stride;
        }
        Quad::new((sample[lo], sample[hi]), sample)
    }

    /// The corners counter-clockwise: the chord's ends and the vertices right and left
    /// of it (a chord end repeats for a missing one).
    fn corners(&self) -> [Point; 4] {
        let (a, b) = self.chord;
        [a, self.right.unwrap_or(a), b, self.left.unwrap_or(b)]
    }

    /// The step through a sample that visits about 16 of its points.
    #[inline]
    fn stride(sample: &[Point]) -> usize {
        (sample.len() / 16).max(1)
    }

    /// The quadrilateral on `chord` with the farthest of about 16 of `sample`'s
    /// points (every ⌈len/16⌉-th) on each side.
    fn new((a, b): (Point, Point), sample: &[Point]) -> Quad {
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        let (mut left, mut right) = ((0.0, usize::MAX), (0.0, usize::MAX));
        let (stride, mut i) = (Quad::stride(sample), 0);
        while let Some(x) = sample.get(i) {
            let h = dx * (x.y - a.y) - dy * (x.x - a.x);
            if h > left.0 {
                left = (h, i);
            } else if h < right.0 {
                right = (h, i);
            }
            i += stride;
        }
        Quad {
            chord: (a, b),
            left: sample.get(left.1).copied(),
            right: sample.get(right.1).copied(),
        }
    }

    /// Whether `y` lies in the triangle of the chord and its vertex on y's side,
    /// boundary included (three orientations; a fourth checks that vertex's side when
    /// the answer is yes). A point on the chord's line is not looked at.
    /// Most points tested are outside: the same three signs are computed in `f64`
    /// first (a guide), and only a point they put inside is tested exactly. A point
    /// that rounding puts outside is missed, which only costs the caller another draw.
    #[inline]
    fn contains<K: Kernel>(&self, k: K, y: Point) -> bool {
        let (a, b) = self.chord;
        let turn = |u: Point, v: Point| (v.x - u.x) * (y.y - u.y) - (v.y - u.y) * (y.x - u.x);
        let h = turn(a, b);
        let guide = if h > 0.0 {
            self.left.is_some_and(|w| turn(b, w) >= 0.0 && turn(w, a) >= 0.0)
        } else if h < 0.0 {
            self.right.is_some_and(|w| turn(a, w) >= 0.0 && turn(w, b) >= 0.0)
        } else {
            false
        };
        guide && self.contains_exactly(k, y)
    }

    /// [`contains`](Self::contains)'s test, exact.
    #[inline(never)]
    fn contains_exactly<K: Kernel>(&self, k: K, y: Point) -> bool {
        let (a, b) = self.chord;
        match k.orient(a, b, y) {
            Orientation::Ccw => self.left.is_some_and(|w| {
                k.orient(b, w, y) != Orientation::Cw
                    && k.orient(w, a, y) != Orientation::Cw
                    && k.orient(a, b, w) == Orientation::Ccw
            }),
            Orientation::Cw => self.right.is_some_and(|w| {
                k.orient(a, w, y) != Orientation::Cw
                    && k.orient(w, b, y) != Orientation::Cw
                    && k.orient(a, b, w) == Orientation::Cw
            }),
            Orientation::Collinear => false,
        }
    }
}

/// A sample vertex of one polygon inside the other polygon, from the LP's last step:
/// `z` (of polygon `z.0`) beyond `chord` (two vertices of the other polygon `of`'s
/// sample) is tested in the quadrilateral of that sample on the chord, then the rest
/// of z's sample (already read: no draw, no arena read) in the same quadrilateral,
/// then the chord's sample in the quadrilateral of z's sample ([`Quad::spread`]),
/// unless `quads` (P's, Q's) holds that one already: then the prefix test
/// ([`prefix_inside`]) has done that test. Each sample is tested on its first
/// [`PREFIX`] points. Else `None`, with the two quadrilaterals (P's, Q's) in `quads`,
/// for the draws.
fn sample_quads<K: Kernel>(
    k: K,
    (z_of, z): (Which, Point),
    (of, chord): (Which, (Point, Point)),
    (rp, rq): (&[Point], &[Point]),
    quads: &mut (Option<Quad>, Option<Quad>),
) -> Option<Certificate> {
    let (chord_sample, own) = if of == Which::P { (rp, rq) } else { (rq, rp) };
    let quad = Quad::new(chord, chord_sample);
    if quad.contains(k, z) {
        return Some(Certificate::VertexInside { of: z_of, point: z });
    }
    if let Some(&y) = own.iter().take(PREFIX).find(|&&y| y != z && quad.contains(k, y)) {
        return Some(Certificate::VertexInside { of: z_of, point: y });
    }
    let tested = if of == Which::P { quads.1 } else { quads.0 };
    let own_quad = tested.unwrap_or_else(|| Quad::spread(own));
    if tested.is_none()
        && let Some(&y) = chord_sample
            .iter()
            .take(PREFIX)
            .find(|&&y| own_quad.contains(k, y))
    {
        return Some(Certificate::VertexInside { of, point: y });
    }
    *quads = if of == Which::P {
        (Some(quad), Some(own_quad))
    } else {
        (Some(own_quad), Some(quad))
    };
    None
}

/// A vertex of Q in P's quadrilateral (made by `quads.0`) or a vertex of P in Q's
/// (`quads.1`), sample vertices inside their polygon, so a vertex inside, from up to
/// `rounds` rounds of one uniform draw on each polygon (`below`, as the samples are
/// drawn), each tested in O(1); Q's quadrilateral is made only if the first draw
/// misses. Where the sample hulls cross, a fair part of each boundary usually lies in
/// the other's quadrilateral, so the expected number of rounds is O(1) on such pairs;
/// on others the rounds cost O(`rounds`) and the caller goes on.
fn drawn_witness<K: Kernel, R: Rng + ?Sized>(
    k: K,
    (p, q): (&LinkedPolygon, &LinkedPolygon),
    quads: (impl FnOnce() -> Quad, impl FnOnce() -> Quad),
    rounds: u32,
    rng: &mut R,
) -> Option<Certificate> {
    if rounds == 0 {
        return None;
    }
    let (n, m) = (p.len() as u32, q.len() as u32);
    let draw_q = |rng: &mut R| q.point_at(below(rng, m) as usize);
    let draw_p = |rng: &mut R| p.point_at(below(rng, n) as usize);
    let inside = |of, point| Some(Certificate::VertexInside { of, point });
    let qp = quads.0();
    let y = draw_q(rng);
    if qp.contains(k, y) {
        return inside(Which::Q, y);
    }
    let qq = quads.1();
    for round in 0..rounds {
        if round > 0 {
            let y = draw_q(rng);
            if qp.contains(k, y) {
                return inside(Which::Q, y);
            }
        }
        let x = draw_p(rng);
        if qq.contains(k, x) {
            return inside(Which::P, x);
        }
    }
    None
}

/// Appends `r` random vertex positions of `poly` to `out`: all of them when r ≥ n; r
/// independent uniform draws (with replacement) when r ≤ n/16, where repeats are rare
/// and skipping the distinctness marks saves a cache miss per draw on large polygons;
/// otherwise r distinct positions ([`LinkedPolygon::sample_positions`]). Repeats are
/// harmless: the LP accepts duplicate points, and the chain bounds of the analysis hold
/// for samples drawn with replacement.
fn sample<R: Rng + ?Sized>(
    poly: &LinkedPolygon,
    r: usize,
    rng: &mut R,
    marks: &mut SampleWorkspace,
    out: &mut Vec<u32>,
) {
    let n = poly.len();
    if r.saturating_mul(16) <= n {
        draw_below(rng, n as u32, r, out);
    } else {
        poly.sample_positions(r, rng, marks, out);
    }
}

/// Replaces `out` by the points of `poly` at `positions`, in order.
fn gather(poly: &LinkedPolygon, positions: &[u32], out: &mut Vec<Point>) {
    out.clear();
    out.extend(positions.iter().map(|&i| poly.point_at(i as usize)));
}

/// Scratch memory of [`boundary_order`]: the keyed entries, the bucket counts, the
/// entries in key order, and the sorted copy of the sample.
#[derive(Clone, Debug, Default)]
struct OrderScratch {
    entries: Vec<u64>,
    counts: Vec<u32>,
    sorted: Vec<u64>,
    positions: Vec<u32>,
    points: Vec<Point>,
}

/// Puts a sample of a strictly convex polygon's vertices (`positions` and `points`,
/// index for index) in counter-clockwise boundary order from its lowest point (the
/// leftmost of those), repeats dropped: the vertices of a convex polygon in cyclic
/// order, as [`separate_chains`] takes them. Every point lies in the half-turn [0, π)
/// of directions seen from the lowest point o, so "a before b" is `orient(o, a, b) =
/// Ccw`, and no two distinct vertices of a strictly convex polygon tie: under an exact
/// kernel the order is exact.
///
/// Each point gets a 32-bit key, an `f64` pseudo-angle about o scaled by 2³¹
/// ([`angle_key`]), and keys two or more apart are in the exact order (the error bound
/// is proved there). So the points are sorted by key alone (key and index in one
/// `u64`: one counting pass into r–2r buckets by the top bits, then an insertion sort
/// whose first step per entry is branchless, a minimum and a maximum with its
/// predecessor (most entries move by one place or none, and a loop exit there was
/// mispredicted about as often as it moved), and which falls back to a full sort after
/// 4r moves when the angles crowd), gathered in
/// that order, and only the runs of near-ties (consecutive keys at most one apart:
/// repeats, o's neighbours, angles within about 2⁻³¹) are sorted again with `orient`
/// ([`settle_near_ties`]), which also drops the repeats. Returns `false` when a
/// difference overflows (the keys are then unsound) or the near-ties need more than
/// 4r + 16 moves; the sample is then unchanged and the caller runs the LP.
fn boundary_order<K: Kernel>(
    k: K,
    positions: &mut Vec<u32>,
    points: &mut Vec<Point>,
    scratch: &mut OrderScratch,
) -> bool {
    let n = points.len();
    debug_assert_eq!(n, positions.len());
    let Some(&first) = points.first() else {
        return true;
    };
    // The lowest point, the leftmost of those (the first such in the sample): the lowest
    // height by four running minima (no branch to mispredict, no chain of dependent
    // comparisons), then the leftmost point at that height, on a branch that is rarely
    // taken. (One pass testing x first on ties compiled to a branch on x's order,
    // taken half the time.)
    let mut low = [first.y; 4];
    let mut quads = points.chunks_exact(4);
    for quad in &mut quads {
        for (low, x) in low.iter_mut().zip(quad) {
            if x.y < *low {
                *low = x.y;
            }
        }
    }
    for x in quads.remainder() {
        if x.y < low[0] {
            low[0] = x.y;
        }
    }
    let lowest = low.into_iter().fold(first.y, |m, y| if y < m { y } else { m });
    let mut o = first;
    let mut found = false;
    for &x in points.iter().filter(|x| x.y == lowest) {
        if !found || x.x < o.x {
            (o, found) = (x, true);
        }
    }
    let OrderScratch {
        entries,
        counts,
        sorted,
        positions: sorted_positions,
        points: sorted_points,
    } = scratch;
    // Each point's key above its index, counted in its bucket (the key's top bits) as
    // it is made; and the largest |dx| + dy (infinite if a difference overflowed).
    let bits = n.next_power_of_two().trailing_zeros().clamp(1, 24);
    let bucket = |entry: u64| (entry >> (64 - bits)) as usize;
    counts.clear();
    counts.resize(1 << bits, 0);
    let mut widest = 0.0f64;
    entries.clear();
    entries.resize(n, 0);
    for ((entry, &x), i) in entries.iter_mut().zip(points.iter()).zip(0u32..) {
        let (key, width) = angle_key(o, x);
        if width > widest {
            widest = width;
        }
        *entry = u64::from(key) << 32 | u64::from(i);
        counts[bucket(*entry)] += 1;
    }
    if widest == f64::INFINITY {
        return false;
    }
    // Counting sort on the keys' top bits, then insertion sort on the whole entries.
    let mut sum = 0;
    for count in counts.iter_mut() {
        (*count, sum) = (sum, sum + *count);
    }
    sorted.clear();
    sorted.resize(n, 0);
    for &entry in entries.iter() {
        let slot = &mut counts[bucket(entry)];
        sorted[*slot as usize] = entry;
        *slot += 1;
    }
    // Each insertion's first step is branchless (the entry and its predecessor as their
    // minimum and maximum): most entries move by at most one place, which a loop's exit
    // branch mispredicts about as often as it happens. Only an entry that moves further
    // loops, on a branch rarely taken.
    let mut moves = 0;
    for i in 1..n {
        let (prev, entry) = (sorted[i - 1], sorted[i]);
        let low = prev.min(entry);
        (sorted[i - 1], sorted[i]) = (low, prev.max(entry));
        moves += usize::from(entry < prev);
        if i >= 2 && sorted[i - 2] > low {
            let mut j = i - 1;
            while j > 0 && sorted[j - 1] > low {
                sorted[j] = sorted[j - 1];
                j -= 1;
            }
            sorted[j] = low;
            moves += i - 1 - j;
        }
        if moves > 4 * n {
            // Crowded buckets.
            sorted.sort_unstable();
            break;
        }
    }
    sorted_positions.clear();
    sorted_positions.extend(sorted.iter().map(|&e| positions[e as u32 as usize]));
    sorted_points.clear();
    sorted_points.extend(sorted.iter().map(|&e| points[e as u32 as usize]));
    // Every `orient` of the near-ties is on three points of the sample: rare enough
    // that the kernel's static filter does (no box to compute for a semi-static one).
    if !settle_near_ties(k, o, sorted, sorted_positions, sorted_points) {
        return false;
    }
    std::mem::swap(positions, sorted_positions);
    std::mem::swap(points, sorted_points);
    true
}

/// The key of `x` in [`boundary_order`] about the lowest point `o`, and |dx| + dy as
/// computed (infinite when a difference overflowed; the key is then unsound).
///
/// The key is ⌊2³¹·v⌋ (saturating; 0 for o itself, whose 0/0 is NaN) for the `f64`
/// value v of the pseudo-angle 1 − dx/(|dx| + dy), (dx, dy) = x − o: exactly, it lies in
/// [0, 2] and increases strictly with the angle of x − o in [0, π]. **Keys two or more
/// apart are in the exact order.** Proof: unless |dx| + dy overflows, dx and dy are
/// computed with relative error at most u = 2⁻⁵³ (exactly when subnormal), then
/// |dx| + dy (no cancellation: dy ≥ 0) and the quotient t = dx/(|dx| + dy) with relative
/// error u each (or absolute error 2⁻¹⁰⁷⁵ when subnormal); so the computed t is
/// t·(1 + δ) with |δ| < 4.1u, within 4.1u of t as |t| ≤ 1, and 1 − t rounds once more
/// (error ≤ u): the computed v is within 5.2u of the exact one. If key(b) ≥ key(a) + 2,
/// then with the computed values 2³¹·v(b) ≥ key(b) ≥ key(a) + 2 > 2³¹·v(a) + 1 (the
/// floor gives key ≤ 2³¹·v < key + 1; saturation at 2³² − 1 lowers only a key that
/// cannot be the smaller, and v ≥ 0 as |dx| ≤ |dx| + dy survives rounding), so the
/// exact values differ by more than 2⁻³¹ − 10.4u > 0 and the angle of a is smaller.
/// o comes before every other point, and its key 0 is the smallest: right as well.
#[inline]
fn angle_key(o: Point, x: Point) -> (u32, f64) {
    let (dx, dy) = (x.x - o.x, x.y - o.y);
    let width = dx.abs() + dy;
    let v = 1.0 - dx / width;
    ((v * 2_147_483_648.0) as u32, width)
}

/// The last step of [`boundary_order`], in place on the sample gathered in key order
/// (`sorted`, its entries, gives the keys): each run of near-ties (consecutive keys at
/// most one apart) is sorted by insertion with `orient` about `o`, and repeats (equal
/// points, which have equal keys and end up adjacent) are dropped. Keys two or more
/// apart are in the exact order ([`angle_key`]), so every point of a run is rightly
/// placed against every point outside it. `false` after 4r + 16 moves (the contents
/// are then scrambled).
fn settle_near_ties<K: Kernel>(
    k: K,
    o: Point,
    sorted: &[u64],
    positions: &mut Vec<u32>,
    points: &mut Vec<Point>,
) -> bool {
    let n = points.len();
    let before = |a: Point, b: Point| b != o && (a == o || k.orient(o, a, b) == Orientation::Ccw);
    let mut budget = 4 * n + 16;
    // The first index whose point repeats its predecessor's (n: none).
    let mut first_repeat = n;
    let near_tie = |w: &[u64]| (w[1] >> 32) - (w[0] >> 32) <= 1;
    // A near-tie's entries (key above index) differ by less than 2 · 2^32: a cheap
    // filter for the scan, which a pair two keys apart may also pass (checked next).
    let close = |(&a, &b): (&u64, &u64)| b - a < 2 << 32;
    let mut from = 0;
    while let Some(at) = sorted[from..]
        .iter()
        .zip(&sorted[from.min(n - 1) + 1..])
        .position(close)
    {
        let start = from + at;
        if !near_tie(&sorted[start..start + 2]) {
            from = start + 1;
            continue;
        }
        // The run start..end.
        let mut end = start + 2;
        while end < n && near_tie(&sorted[end - 1..=end]) {
            end += 1;
        }
        for i in start + 1..end {
            let (x, at) = (points[i], positions[i]);
            let mut j = i;
            while j > start && before(x, points[j - 1]) {
                if budget == 0 {
                    return false;
                }
                budget -= 1;
                points[j] = points[j - 1];
                positions[j] = positions[j - 1];
                j -= 1;
            }
            (points[j], positions[j]) = (x, at);
            if j > start && points[j - 1] == x {
                // Later insertions only move this pair right: no repeat lies before
                // the first one recorded.
                first_repeat = first_repeat.min(j);
            }
        }
        from = end;
    }
    if first_repeat < n {
        let mut len = first_repeat;
        for i in first_repeat..n {
            if points[i] != points[len - 1] {
                (points[len], positions[len]) = (points[i], positions[i]);
                len += 1;
            }
        }
        points.truncate(len);
        positions.truncate(len);
    }
    true
}

/// A uniform integer in `0..n` (`n > 0`) from 32 random bits, by Lemire's
/// multiply-and-reject method: one multiplication, and a division only in the rare
/// round that may need a rejection. (`Rng::random_range` does the same with more
/// bookkeeping; this runs for every sampled vertex and every chain vertex.)
#[inline]
fn below<R: Rng + ?Sized>(rng: &mut R, n: u32) -> u32 {
    below_from(rng.next_u32(), rng, n)
}

/// [`below`] with the first 32 random bits given (`bits`, uniform and independent of
/// `rng`'s further output); a rejection draws from `rng`.
#[inline]
fn below_from<R: Rng + ?Sized>(bits: u32, rng: &mut R, n: u32) -> u32 {
    let mut m = u64::from(bits) * u64::from(n);
    if (m as u32) < n {
        let threshold = n.wrapping_neg() % n;
        while (m as u32) < threshold {
            m = u64::from(rng.next_u32()) * u64::from(n);
        }
    }
    (m >> 32) as u32
}

/// Appends `count` independent uniform integers in `0..n` (`n > 0`) to `out`, two from
/// each 64-bit draw (its halves are independent uniform 32-bit words, as in
/// [`shuffle`]): half the generator's steps of [`below`] for each.
fn draw_below<R: Rng + ?Sized>(rng: &mut R, n: u32, count: usize, out: &mut Vec<u32>) {
    let start = out.len();
    out.resize(start + count, 0);
    let mut pairs = out[start..].chunks_exact_mut(2);
    for pair in &mut pairs {
        let bits = rng.next_u64();
        pair[0] = below_from(bits as u32, rng, n);
        pair[1] = below_from((bits >> 32) as u32, rng, n);
    }
    if let [last] = pairs.into_remainder() {
        *last = below(rng, n);
    }
}

/// Shuffles `positions` uniformly (Fisher–Yates), and `points` the same way when it is
/// not empty (then it has the same length). Each 64-bit draw serves two swaps (its
/// halves are independent uniform 32-bit words).
fn shuffle<R: Rng + ?Sized>(positions: &mut [u32], points: &mut [Point], rng: &mut R) {
    let with_points = !points.is_empty();
    debug_assert!(!with_points || points.len() == positions.len());
    let mut i = positions.len().saturating_sub(1);
    let mut swap = |i: usize, j: u32| {
        positions.swap(i, j as usize);
        if with_points {
            points.swap(i, j as usize);
        }
    };
    while i >= 2 {
        let bits = rng.next_u64();
        swap(i, below_from(bits as u32, rng, i as u32 + 1));
        swap(i - 1, below_from((bits >> 32) as u32, rng, i as u32));
        i -= 2;
    }
    if i == 1 {
        swap(1, below(rng, 2));
    }
}

/// Appends min(r, n) distinct random positions of a polygon of `n` vertices to `out`
/// by a partial Fisher–Yates shuffle of `perm` (the identity before and after: the
/// swaps are undone in reverse order). [`Sampling::FisherYates`].
fn fisher_yates<R: Rng + ?Sized>(
    n: usize,
    r: usize,
    rng: &mut R,
    perm: &mut Vec<u32>,
    swaps: &mut Vec<u32>,
    out: &mut Vec<u32>,
) {
    // The identity on 0..len, of which 0..n is the identity on 0..n: one array serves
    // polygons of every size, built once for the largest.
    if perm.len() < n {
        perm.clear();
        perm.extend(0..n as u32);
    }
    let perm = &mut perm[..n];
    swaps.clear();
    for last in (n - r.min(n)..n).rev() {
        let j = rng.random_range(0..=last);
        perm.swap(j, last);
        swaps.push(j as u32);
        out.push(perm[last]);
    }
    for (last, &j) in (n - swaps.len()..n).zip(swaps.iter().rev()) {
        perm.swap(j as usize, last);
    }
}

/// With the samples in boundary order ([`ClmVariant::sample_walk`]), the points of each
/// sample that a first LP tries before they are put in order.
const PREFIX: usize = 12;

/// How many points of each sample after its prefix are tested in the prefixes'
/// quadrilaterals when the prefix LP finds the prefixes' hulls disjoint.
const NEXT: usize = 12;

/// The first [`PREFIX`] entries of a sample's points or positions (fewer if it has
/// fewer).
fn prefix_of<T>(sample: &[T]) -> &[T] {
    &sample[..PREFIX.min(sample.len())]
}

/// The points of `polygon` at `positions`, as LPs and probe reports take them.
fn arena<'a>(polygon: &'a LinkedPolygon, positions: &'a [u32]) -> ArenaPoints<'a> {
    ArenaPoints { polygon, positions }
}

/// The [`NEXT`] points of a sample after its prefix (fewer if it has fewer).
fn next_points(sample: &[Point]) -> &[Point] {
    &sample[PREFIX.min(sample.len())..(PREFIX + NEXT).min(sample.len())]
}

/// A point of `a` (points of P's sample) in `qb` (a quadrilateral of Q's sample,
/// [`Quad::spread`]), or of `b` (Q's) in `qa` (P's), taken alternately: how many points
/// were tested, and the point found with the polygon it is a vertex of. Each
/// quadrilateral has sample vertices for corners, so it lies inside its polygon and a
/// point in it is a vertex inside, an intersection with its certificate. O(|a| + |b|);
/// each test computes `f64` signs, then (only for a point they put inside) exact
/// orientations ([`Quad::contains`]). A miss (a point rounding puts outside, or on the
/// chord's line) only leaves the query to the LP.
#[inline(never)]
fn prefix_inside<K: Kernel>(
    k: K,
    (a, qa): (&[Point], &Quad),
    (b, qb): (&[Point], &Quad),
) -> (u64, Option<(Which, Point)>) {
    for i in 0..a.len().max(b.len()) {
        if let Some(&y) = b.get(i)
            && qa.contains(k, y)
        {
            return (2 * i as u64 + 1, Some((Which::Q, y)));
        }
        if let Some(&x) = a.get(i)
            && qb.contains(k, x)
        {
            return (2 * i as u64 + 2, Some((Which::P, x)));
        }
    }
    ((a.len() + b.len()) as u64, None)
}

/// ⌈c·√n⌉, at least 3.
fn sample_size(c: f64, n: usize) -> usize {
    let r = (c * (n as f64).sqrt()).ceil();
    if r.is_finite() && r >= 3.0 { r as usize } else { 3 }
}

/// [`separating_line`] on the gathered points of two sets (the points at their arena
/// positions, index for index), reporting the call to `probe` (constraints and work).
fn counted_lp<K: Kernel, R: Rng + ?Sized, P: Probe>(
    k: K,
    (a, a_points): (&ArenaPoints<'_>, &[Point]),
    (b, b_points): (&ArenaPoints<'_>, &[Point]),
    rng: &mut R,
    lp: &mut LpWorkspace,
    probe: &mut P,
) -> Result<Separation, LpError> {
    counted_lp_after(k, (a, a_points), (b, b_points), 0, rng, lp, probe)
}

/// [`counted_lp`], reporting `spent` more work (done on the same decision before).
fn counted_lp_after<K: Kernel, R: Rng + ?Sized, P: Probe>(
    k: K,
    (a, a_points): (&ArenaPoints<'_>, &[Point]),
    (b, b_points): (&ArenaPoints<'_>, &[Point]),
    spent: u64,
    rng: &mut R,
    lp: &mut LpWorkspace,
    probe: &mut P,
) -> Result<Separation, LpError> {
    debug_assert!(a_points.len() == a.positions.len() && b_points.len() == b.positions.len());
    let before = lp.work - spent;
    // The LP asks its predicates of these points only: the exact kernel's semi-static
    // filter, with one bound from their boxes, certifies them with two comparisons
    // (one pass over the points, which the LP reads anyway).
    let k = k.within([box_of(a_points), box_of(b_points)]);
    let result = separating_line(k, a_points, b_points, rng, lp);
    probe.lp_call(a, b, lp.work - before, &result);
    result
}

/// The separation of two sets whose points come in boundary order (samples put in
/// order by [`boundary_order`], chains in walk order) by [`separate_chains`] from the
/// indices `start`, reported to `probe` as an LP call on the two sets; the LP (which
/// then shuffles the points itself) when the walk gives no answer, and for a certified
/// query whose intersecting sets have fewer than three points (the LP records the
/// witness; larger sets are convex polygons, which `certify` searches instead). `spent`
/// is work done on the same decision before, reported with it.
#[allow(clippy::too_many_arguments)]
fn walk_or_lp<K: Kernel, R: Rng + ?Sized, P: Probe, const CERT: bool>(
    k: K,
    (a, a_points): (&ArenaPoints<'_>, &[Point]),
    (b, b_points): (&ArenaPoints<'_>, &[Point]),
    start: [usize; 2],
    spent: u64,
    rng: &mut R,
    lp: &mut LpWorkspace,
    probe: &mut P,
) -> Result<Separation, LpError> {
    let before = lp.work - spent;
    match separate_chains(k, a_points, b_points, start, &mut lp.work) {
        // A certified query reruns the LP for its witness only where the sets are too
        // small to be convex polygons; otherwise the certificate is searched on the two
        // convex polygons the sets are (`certify`), and no LP witness is left to read.
        Some(Separation::Intersecting) if CERT && a_points.len() >= 3 && b_points.len() >= 3 => {
            lp.forget_witness();
            let result = Separation::Intersecting;
            probe.lp_call(a, b, lp.work - before, &Ok(result));
            return Ok(result);
        }
        Some(Separation::Intersecting) if CERT => {}
        Some(result) => {
            probe.lp_call(a, b, lp.work - before, &Ok(result));
            return Ok(result);
        }
        None => {}
    }
    counted_lp_after(k, (a, a_points), (b, b_points), lp.work - before, rng, lp, probe)
}

/// [`prefix_inside`] on the parts `part` of the two samples (P's points, Q's) and
/// `quads` (P's, Q's): counts the points tested as work and reports them to `probe`.
/// When a point lies inside, also reports the samples and then `prefix_lp` (the work
/// and result of an LP on the prefixes that ran before, not reported yet) first and,
/// with `CERT`, records the certificate; then true, the answer (intersecting).
#[allow(clippy::too_many_arguments)]
fn quads_answer<K: Kernel, P: Probe, const CERT: bool>(
    k: K,
    (p, q): (&LinkedPolygon, &LinkedPolygon),
    part: fn(&[Point]) -> &[Point],
    quads: &(Quad, Quad),
    prefix_lp: Option<(u64, Result<Separation, LpError>)>,
    ws: &mut ClmWorkspace,
    probe: &mut P,
) -> bool {
    let (a, b) = (part(&ws.rp_points), part(&ws.rq_points));
    let (tested, found) = prefix_inside(k, (a, &quads.0), (b, &quads.1));
    ws.tested += tested;
    let Some((of, point)) = found else {
        probe.sample_quads(tested, None);
        return false;
    };
    probe.samples(&arena(p, &ws.rp), &arena(q, &ws.rq));
    if let Some((work, result)) = prefix_lp {
        let (pa, pb) = (arena(p, prefix_of(&ws.rp)), arena(q, prefix_of(&ws.rq)));
        probe.lp_call(&pa, &pb, work, &result);
    }
    let quad = if of == Which::P { &quads.1 } else { &quads.0 };
    probe.sample_quads(tested, Some((of, point, quad.corners())));
    if CERT {
        ws.trace.inside = Some((of, point));
    }
    true
}

/// The test; with `CERT` it also records in `ws.trace` what its certificate needs.
fn clm<K: Kernel, R: Rng + ?Sized, P: Probe, const CERT: bool>(
    k: K,
    v: ClmVariant,
    p: &LinkedPolygon,
    q: &LinkedPolygon,
    rng: &mut R,
    ws: &mut ClmWorkspace,
    probe: &mut P,
) -> bool {
    if CERT {
        ws.trace.inside = None;
        ws.trace.meet = None;
        ws.trace.spread = None;
        ws.trace.lines.clear();
    }
    ws.lp.record_witness(CERT);
    // With the samples in boundary order nothing is in random order: the LPs that
    // still run shuffle their points themselves.
    let caller_random = v.lp_order == LpOrder::Caller && !v.sample_walk;
    ws.lp.keep_order(caller_random);
    ws.rp.clear();
    ws.rq.clear();
    let (rp_len, rq_len) = (sample_size(v.factor, p.len()), sample_size(v.factor, q.len()));
    // Independent draws on both sides (see `sample`), of which the prefix LP below
    // uses the first PREFIX.
    let independent = v.sampling == Sampling::Independent
        && rp_len.saturating_mul(16) <= p.len()
        && rq_len.saturating_mul(16) <= q.len();
    // With the prefix LP, independent samples are drawn in two parts: the prefixes
    // first, the rest only if the prefixes' hulls are disjoint (most intersecting
    // queries end there without reading the rest).
    let prefix_first = v.sample_walk && independent;
    let (first_p, first_q) = if prefix_first {
        (PREFIX.min(rp_len), PREFIX.min(rq_len))
    } else {
        (rp_len, rq_len)
    };
    match v.sampling {
        Sampling::Independent => {
            sample(p, first_p, rng, &mut ws.sample, &mut ws.rp);
            sample(q, first_q, rng, &mut ws.sample, &mut ws.rq);
            if caller_random {
                // Only independent draws come in random order.
                for (r, poly) in [(&mut ws.rp, p), (&mut ws.rq, q)] {
                    if r.len().saturating_mul(16) > poly.len() {
                        shuffle(r, &mut [], rng);
                    }
                }
            }
        }
        Sampling::FisherYates => {
            fisher_yates(p.len(), rp_len, rng, &mut ws.perm, &mut ws.swaps, &mut ws.rp);
            fisher_yates(q.len(), rq_len, rng, &mut ws.perm, &mut ws.swaps, &mut ws.rq);
        }
    }
    // One pass of independent reads per sample (their cache misses overlap), so the
    // LPs that use a sample read contiguous memory.
    gather(p, &ws.rp, &mut ws.rp_points);
    gather(q, &ws.rq, &mut ws.rq_points);
    // Intersecting samples usually show within a few dozen points: an LP on a short
    // prefix of each sample answers most intersecting queries before the samples are
    // put in order (a prefix of a random sample is a random sample).
    let mut spent = 0;
    let prefix_lp = v.sample_walk && (rp_len > PREFIX || rq_len > PREFIX);
    // The prefixes' quadrilaterals (P's, Q's).
    let prefix_quads = (prefix_lp && v.prefix_quads).then(|| {
        let (a, b) = (prefix_of(&ws.rp_points), prefix_of(&ws.rq_points));
        (Quad::spread(a), Quad::spread(b))
    });
    // The prefix LP's work and result, once it ran.
    let mut prefix_lp_ran = None;
    if prefix_lp {
        let before = ws.lp.work;
        // A prefix vertex of one polygon in a quadrilateral of the other prefix's
        // points answers most intersecting queries before any LP.
        if let Some(quads) = &prefix_quads
            && quads_answer::<K, P, CERT>(k, (p, q), prefix_of, quads, None, ws, probe)
        {
            return true;
        }
        let (a, b) = (prefix_of(&ws.rp_points), prefix_of(&ws.rq_points));
        // Distinct samples come in arena order: the LP shuffles them.
        let random = v.sampling == Sampling::FisherYates || independent;
        ws.lp.keep_order(random);
        let meet = separating_line(k.within([box_of(a), box_of(b)]), a, b, rng, &mut ws.lp);
        ws.lp.keep_order(caller_random);
        spent = ws.lp.work - before;
        prefix_lp_ran = Some((spent, meet));
        if meet == Ok(Separation::Intersecting) {
            let (rp, rq) = (arena(p, &ws.rp), arena(q, &ws.rq));
            probe.samples(&rp, &rq);
            probe.lp_call(&rp, &rq, spent, &meet);
            if CERT {
                // The witness's indices are the prefixes', the samples' own.
                ws.trace.meet = Some((Set::Rp, Set::Rq));
                ws.trace.spread = prefix_quads;
            }
            return true;
        }
    }
    if prefix_first {
        // The rest of the samples, read in one more pass of independent reads.
        for (poly, r, positions, points) in [
            (p, rp_len, &mut ws.rp, &mut ws.rp_points),
            (q, rq_len, &mut ws.rq, &mut ws.rq_points),
        ] {
            let drawn = positions.len();
            draw_below(rng, poly.len() as u32, r - drawn, positions);
            points.extend(positions[drawn..].iter().map(|&i| poly.point_at(i as usize)));
        }
        // The next points of each sample in the prefixes' quadrilaterals: about half
        // of the intersecting queries whose prefix hulls are disjoint end here, before
        // the samples are put in order.
        if let Some(quads) = &prefix_quads
            && quads_answer::<K, P, CERT>(k, (p, q), next_points, quads, prefix_lp_ran, ws, probe)
        {
            return true;
        }
    }
    // Both samples in boundary order, or neither: then the LPs decide.
    let ordered = v.sample_walk
        && boundary_order(k, &mut ws.rp, &mut ws.rp_points, &mut ws.order)
        && boundary_order(k, &mut ws.rq, &mut ws.rq_points, &mut ws.order);
    let rp = ArenaPoints {
        polygon: p,
        positions: &ws.rp,
    };
    let rq = ArenaPoints {
        polygon: q,
        positions: &ws.rq,
    };
    probe.samples(&rp, &rq);
    let first_lp = if ordered {
        walk_or_lp::<K, R, P, CERT>(
            k,
            (&rp, &ws.rp_points),
            (&rq, &ws.rq_points),
            [0, 0],
            spent,
            rng,
            &mut ws.lp,
            probe,
        )
    } else {
        counted_lp_after(
            k,
            (&rp, &ws.rp_points),
            (&rq, &ws.rq_points),
            spent,
            rng,
            &mut ws.lp,
            probe,
        )
    };
    let t = match first_lp {
        Ok(Separation::Separated(t)) => t,
        // Samples are never empty (polygons have ≥ 3 vertices), so only a real
        // intersection of the sample hulls gets here.
        _ => {
            if CERT {
                ws.trace.meet = Some((Set::Rp, Set::Rq));
            }
            return true;
        }
    };
    if CERT {
        ws.trace.lines.push((t, Set::Rp, Set::Rq));
    }
    if ws.rp.len() == p.len() && ws.rq.len() == q.len() {
        return false; // the LP saw both polygons whole
    }
    let (tp, tq) = (ws.rp[t.a] as usize, ws.rq[t.b] as usize);
    // P lies on the right of the line, Q on the left: P's far side is the left.
    let first = [
        Walk::new(p, t.start, t.end, Orientation::Ccw, tp),
        Walk::new(q, t.start, t.end, Orientation::Cw, tq),
    ];
    // The chains are walked into buffers taken out of the workspace for the schedule
    // and put back after it, whatever it answers.
    let mut chains = Chains(
        [
            std::mem::take(&mut ws.cp),
            std::mem::take(&mut ws.cq),
            std::mem::take(&mut ws.chain),
            std::mem::take(&mut ws.chain2),
        ],
        std::mem::take(&mut ws.chain_points),
    );
    let order = ChainOrder {
        shuffle: caller_random,
        walk: v.chain_walk,
        samples: ordered.then_some([t.a, t.b]),
    };
    let answer = walk_and_decide::<K, R, P, CERT>(k, p, q, first, &mut chains, order, rng, ws, probe);
    let Chains([cp, cq, chain, chain2], points) = chains;
    (ws.cp, ws.cq, ws.chain, ws.chain2) = (cp, cq, chain, chain2);
    ws.chain_points = points;
    answer
}

/// How [`walk_and_decide`] treats walked chains: shuffled for the LP
/// ([`LpOrder::Caller`]), and whether the chain-against-chain LPs are walks
/// ([`ClmVariant::chain_walk`]; then C′_P and C′_Q stay in walk order, and C_P and C_Q
/// are copied in walk order before their shuffle).
#[derive(Clone, Copy)]
struct ChainOrder {
    shuffle: bool,
    walk: bool,
    /// With the samples in boundary order ([`ClmVariant::sample_walk`]), the indices of
    /// the first line's tangent vertices in R_P and R_Q: the sample-against-chain LPs
    /// are walks from there and the chain's first vertex.
    samples: Option<[usize; 2]>,
}

/// The four chain buffers (positions, and the points at them), indexed by
/// [`Set::chain_index`].
struct Chains([Vec<u32>; 4], [Vec<Point>; 4]);

impl Chains {
    #[inline]
    fn get(&self, s: Set) -> &[u32] {
        &self.0[s.chain_index()]
    }

    #[inline]
    fn points(&self, s: Set) -> &[Point] {
        &self.1[s.chain_index()]
    }

    /// Both buffers of a chain, taken out to be written by a walk.
    #[inline]
    fn take(&mut self, s: Set) -> (Vec<u32>, Vec<Point>) {
        let i = s.chain_index();
        (std::mem::take(&mut self.0[i]), std::mem::take(&mut self.1[i]))
    }

    /// Puts back the buffers of a finished walk.
    #[inline]
    fn put(&mut self, s: Set, (positions, points): (Vec<u32>, Vec<Point>)) {
        let i = s.chain_index();
        (self.0[i], self.1[i]) = (positions, points);
    }

    /// Both buffers of a chain in place.
    #[inline]
    fn buffers(&mut self, s: Set) -> (&mut Vec<u32>, &mut Vec<Point>) {
        let i = s.chain_index();
        (&mut self.0[i], &mut self.1[i])
    }
}

impl Set {
    /// The buffer of a chain set in [`Chains`] (samples have none).
    #[inline]
    fn chain_index(self) -> usize {
        match self {
            Set::Cp => 0,
            Set::Cq => 1,
            Set::Chain => 2,
            Set::Chain2 => 3,
            Set::Rp | Set::Rq => unreachable!("samples are not walked"),
        }
    }
}

/// A walk in progress in one of the lockstep slots: the chain set it fills, and that
/// set's buffers (positions and points), taken out of [`Chains`] while it walks.
struct Active<'a> {
    set: Set,
    walk: Walk<'a>,
    cursor: Cursor,
    buffers: (Vec<u32>, Vec<Point>),
}

impl<'a> Active<'a> {
    /// Starts `walk` into the buffers of `set`.
    fn start<K: Kernel>(k: K, set: Set, walk: Walk<'a>, chains: &mut Chains) -> Self {
        let mut buffers = chains.take(set);
        let cursor = walk.start(k, &mut buffers);
        Active {
            set,
            walk,
            cursor,
            buffers,
        }
    }
}

/// Steps 3–5 of the module docs after the first LP, as a schedule of chain walks kept
/// two at a time in lockstep, so that their cache misses (each step is a dependent
/// load at a random arena position) overlap for the whole query rather than only
/// while both walks of a pair last. `first` are the walks of C_P and C_Q. When a walk
/// ends, the LP that needed it runs at once (an intersection there ends the query),
/// and the walk that LP's line calls for takes the freed slot:
/// * C_Q done: LP(R_P, C_Q); its line starts C′_P.
/// * C_P done: LP(R_Q, C_P); its line starts C′_Q.
/// * C′_P done: LP(C′_P, C_Q). C′_Q done: LP(C′_Q, C_P).
///
/// The answer is the disjunction of the four LPs' verdicts, so the order in which
/// walks end does not change it. A sample that is its whole polygon has decided its
/// sub-test already: its second chain is not walked. With `order.shuffle` each chain
/// is shuffled when walked ([`LpOrder::Caller`]); with `order.walk` the last two LPs are
/// [`separate_chains`] on the chains in walk order, started from C′'s first vertex (the
/// tangent vertex it was walked from) and the far chain's tangent vertex on the line
/// that started C′ (see [`chain_against_chain`]).
#[allow(clippy::too_many_arguments)]
fn walk_and_decide<K: Kernel, R: Rng + ?Sized, P: Probe, const CERT: bool>(
    k: K,
    p: &LinkedPolygon,
    q: &LinkedPolygon,
    first: [Walk<'_>; 2],
    chains: &mut Chains,
    order: ChainOrder,
    rng: &mut R,
    ws: &mut ClmWorkspace,
    probe: &mut P,
) -> bool {
    let ClmWorkspace {
        rp,
        rq,
        rp_points,
        rq_points,
        lp,
        walked,
        trace,
        ordered,
        ..
    } = ws;
    // Per polygon (P, Q): its first chain's tangent vertex on the line of the
    // sample-against-chain LP, where the chain-against-chain walk starts: its position
    // when the chain is shuffled, else its index in the chain.
    let mut far_tangent = [0usize; 2];
    let p_open = rp.len() < p.len();
    let q_open = rq.len() < q.len();
    let mut slots: [Option<Active<'_>>; 2] = [None, None];
    for (slot, (walk, set)) in slots.iter_mut().zip(first.into_iter().zip([Set::Cp, Set::Cq])) {
        *slot = Some(Active::start(k, set, walk, chains));
    }
    // At the top of this loop at least one slot walks: the loop returns when none does.
    loop {
        // Step every active walk until one of them ends.
        lockstep(k, &mut slots);
        for slot in &mut slots {
            let Some(Active { set, buffers, .. }) = slot.take_if(|a| a.cursor.done) else {
                continue;
            };
            chains.put(set, buffers);
            let len = chains.get(set).len();
            probe.chain_walk(&ArenaPoints {
                polygon: if set.of() == Which::P { p } else { q },
                positions: chains.get(set),
            });
            *walked += len as u64;
            let side = usize::from(set.of() == Which::Q);
            let second = matches!(set, Set::Chain | Set::Chain2);
            if order.walk && order.shuffle && !second {
                let (positions, points) = &mut ordered[side];
                positions.clone_from(&chains.0[set.chain_index()]);
                points.clone_from(&chains.1[set.chain_index()]);
            }
            if order.walk && second {
                let far = if set == Set::Chain { Set::Cq } else { Set::Cp };
                let far_side = usize::from(far.of() == Which::Q);
                let before = lp.work;
                let walked = if order.shuffle {
                    chain_against_chain(k, set, far, chains, &ordered[far_side], far_tangent[far_side], lp)
                } else {
                    let start = [0, far_tangent[far_side]];
                    separate_chains(k, chains.points(set), chains.points(far), start, &mut lp.work)
                };
                match walked {
                    Some(Separation::Separated(line)) => {
                        report_lp(
                            p,
                            q,
                            (set, far),
                            chains,
                            lp.work - before,
                            Separation::Separated(line),
                            probe,
                        );
                        if CERT {
                            trace.lines.push((line, set, far));
                        }
                        continue;
                    }
                    Some(Separation::Intersecting) if !CERT => {
                        report_lp(
                            p,
                            q,
                            (set, far),
                            chains,
                            lp.work - before,
                            Separation::Intersecting,
                            probe,
                        );
                        return true;
                    }
                    // No answer, or a certified query's intersection (the LP records the
                    // witness): the LP decides.
                    _ => {}
                }
            }
            if order.shuffle {
                let (positions, points) = chains.buffers(set);
                shuffle(positions, points, rng);
            }
            // The LP this chain completes: (near set, its polygon, far chain, its polygon).
            let (near, far) = match set {
                Set::Cq => (Set::Rp, Set::Cq),
                Set::Cp => (Set::Rq, Set::Cp),
                Set::Chain => (Set::Chain, Set::Cq),
                _ => (Set::Chain2, Set::Cp),
            };
            let polygon = |s: Set| if s.of() == Which::P { p } else { q };
            let (near_positions, near_points) = match near {
                Set::Rp => (&rp[..], &rp_points[..]),
                Set::Rq => (&rq[..], &rq_points[..]),
                s => (chains.get(s), chains.points(s)),
            };
            let a = ArenaPoints {
                polygon: polygon(near),
                positions: near_positions,
            };
            let b = ArenaPoints {
                polygon: polygon(far),
                positions: chains.get(far),
            };
            let result = match (near, order.samples) {
                (Set::Rp | Set::Rq, Some(tangents)) => {
                    let start = [tangents[usize::from(near == Set::Rq)], 0];
                    walk_or_lp::<K, R, P, CERT>(
                        k,
                        (&a, near_points),
                        (&b, chains.points(far)),
                        start,
                        0,
                        rng,
                        lp,
                        probe,
                    )
                }
                _ => counted_lp(k, (&a, near_points), (&b, chains.points(far)), rng, lp, probe),
            };
            let Ok(Separation::Separated(line)) = result else {
                if CERT {
                    trace.meet = Some((near, far));
                }
                return true;
            };
            if CERT {
                trace.lines.push((line, near, far));
            }
            if matches!(near, Set::Rp | Set::Rq) {
                far_tangent[usize::from(far.of() == Which::Q)] = if order.shuffle {
                    chains.get(far)[line.b] as usize
                } else {
                    line.b
                };
            }
            // After a first chain, the second chain of the other polygon, beyond the line
            // (the near set is on its right: its far side is the left).
            let next = match near {
                Set::Rp if p_open => Some((Set::Chain, p, rp[line.a])),
                Set::Rq if q_open => Some((Set::Chain2, q, rq[line.a])),
                _ => None,
            };
            if let Some((set, poly, t)) = next {
                let walk = Walk::new(poly, line.start, line.end, Orientation::Ccw, t as usize);
                *slot = Some(Active::start(k, set, walk, chains));
            }
        }
        if slots.iter().all(Option::is_none) {
            return false;
        }
    }
}

/// [`separate_chains`] on the second chain `near` (C′_P or C′_Q, in walk order: its
/// first vertex is the tangent vertex it was walked from) and the first chain `far` of
/// the other polygon in walk order (`ordered`: its positions and points), started at
/// the far chain's vertex at position `tangent`. The answer's index into `far` is into
/// its (shuffled) buffer in `chains`, as the LP's would be. `None` when the walk gives
/// no answer.
fn chain_against_chain<K: Kernel>(
    k: K,
    near: Set,
    far: Set,
    chains: &Chains,
    (positions, points): &(Vec<u32>, Vec<Point>),
    tangent: usize,
    lp: &mut LpWorkspace,
) -> Option<Separation> {
    let j = positions.iter().position(|&x| x as usize == tangent).unwrap_or(0);
    match separate_chains(k, chains.points(near), points, [0, j], &mut lp.work)? {
        Separation::Separated(line) => {
            let at = positions[line.b];
            let b = chains.get(far).iter().position(|&x| x == at)?;
            Some(Separation::Separated(Bitangent { b, ..line }))
        }
        Separation::Intersecting => Some(Separation::Intersecting),
    }
}

/// Reports to `probe` a chain-against-chain separation decided without the LP, as an
/// LP call on the two chains.
fn report_lp<P: Probe>(
    p: &LinkedPolygon,
    q: &LinkedPolygon,
    (a, b): (Set, Set),
    chains: &Chains,
    work: u64,
    result: Separation,
    probe: &mut P,
) {
    let set = |s: Set| ArenaPoints {
        polygon: if s.of() == Which::P { p } else { q },
        positions: chains.get(s),
    };
    probe.lp_call(&set(a), &set(b), work, &Ok(result));
}

/// One chain walk (see [`walk_and_decide`]): from the tangent vertex at position `t` of
/// `poly`, along the side where the neighbour lies strictly on the `far` side of the
/// directed line (s, e).
#[derive(Clone, Copy)]
struct Walk<'a> {
    poly: &'a LinkedPolygon,
    /// The line, directed so that the far side is its left (reversed when `far` is the
    /// right: `orient(e, s, x) = −orient(s, e, x)`, exactly under an exact kernel), its
    /// direction computed once for all the walk's side tests.
    line: DirectedLine,
    t: usize,
}

impl<'a> Walk<'a> {
    fn new(poly: &'a LinkedPolygon, s: Point, e: Point, far: Orientation, t: usize) -> Self {
        let line = if far == Orientation::Cw {
            DirectedLine::new(e, s)
        } else {
            debug_assert_eq!(far, Orientation::Ccw);
            DirectedLine::new(s, e)
        };
        Walk { poly, line, t }
    }
}

/// The state of a walk in progress.
struct Cursor {
    v: usize,
    forward: bool,
    steps_left: usize,
    done: bool,
}

impl Walk<'_> {
    #[inline(always)]
    fn is_far<K: Kernel>(&self, k: K, x: Point) -> bool {
        k.orient_line(&self.line, x) == Orientation::Ccw
    }

    /// Starts the walk, writing its first vertices and their points to `out`.
    fn start<K: Kernel>(&self, k: K, (out, points): &mut (Vec<u32>, Vec<Point>)) -> Cursor {
        out.clear();
        points.clear();
        let done = Cursor {
            v: 0,
            forward: true,
            steps_left: 0,
            done: true,
        };
        let (poly, t) = (self.poly, self.t);
        let (next, prev) = (poly.next_at(t), poly.prev_at(t));
        let (next_point, prev_point) = (poly.point_at(next), poly.point_at(prev));
        let forward = if self.is_far(k, next_point) {
            true
        } else if self.is_far(k, prev_point) {
            false
        } else {
            out.extend([prev as u32, t as u32, next as u32]);
            points.extend([prev_point, poly.point_at(t), next_point]);
            return done;
        };
        out.push(t as u32);
        points.push(poly.point_at(t));
        Cursor {
            v: if forward { next } else { prev },
            forward,
            // At most n − 1 further vertices; the cap also bounds walks under an
            // inconsistent kernel.
            steps_left: poly.len() - 1,
            done: false,
        }
    }

    /// One step from the vertex at `v`: records it and its point in `pos` and `point`,
    /// and returns the next vertex, or `None` if `v` closes the chain (it is not
    /// strictly beyond the line) or the next vertex is the start (the walk went
    /// around).
    #[inline(always)]
    fn step<K: Kernel>(
        &self,
        k: K,
        v: usize,
        forward: bool,
        pos: &mut u32,
        point: &mut Point,
    ) -> Option<usize> {
        let x = self.poly.point_at(v);
        (*pos, *point) = (v as u32, x);
        if !self.is_far(k, x) {
            return None;
        }
        let next = if forward {
            self.poly.next_at(v)
        } else {
            self.poly.prev_at(v)
        };
        (next != self.t).then_some(next)
    }
}

/// How many steps of each walk [`lockstep`] takes between two checks of its buffers'
/// room.
const CHUNK: usize = 64;

/// Makes room for `m` more vertices in a walk's buffers, returning the slices to write
/// them to (the buffers are cut back to what was written by [`close`]).
#[inline(always)]
fn open((positions, points): &mut (Vec<u32>, Vec<Point>), m: usize) -> (&mut [u32], &mut [Point]) {
    let len = positions.len();
    positions.resize(len + m, 0);
    points.resize(len + m, Point::new(0.0, 0.0));
    (&mut positions[len..], &mut points[len..])
}

/// After `steps` steps of a chunk that [`open`] made room for `m` of: the buffers keep
/// the vertices written, and the cursor moves to `next` (`None`: the chain is closed)
/// or ends at the step cap.
#[inline(always)]
fn close(
    (positions, points): &mut (Vec<u32>, Vec<Point>),
    c: &mut Cursor,
    m: usize,
    steps: usize,
    next: Option<usize>,
) {
    let len = positions.len() - (m - steps);
    positions.truncate(len);
    points.truncate(len);
    c.steps_left -= steps;
    match next {
        Some(v) if c.steps_left > 0 => c.v = v,
        _ => c.done = true,
    }
}

/// Steps the active walks in lockstep (one step of each per round) until one of them
/// ends: their cache misses overlap. The steps run in chunks written to slices, with
/// each walk's state in locals, so that a step is a load, a side test and two stores.
fn lockstep<K: Kernel>(k: K, slots: &mut [Option<Active<'_>>; 2]) {
    match slots {
        [Some(a), Some(b)] => {
            while !a.cursor.done && !b.cursor.done {
                let m = CHUNK.min(a.cursor.steps_left).min(b.cursor.steps_left);
                let (wa, wb) = (a.walk, b.walk);
                let (fa, fb) = (a.cursor.forward, b.cursor.forward);
                let (mut va, mut vb) = (Some(a.cursor.v), Some(b.cursor.v));
                let ((pa, xa), (pb, xb)) = (open(&mut a.buffers, m), open(&mut b.buffers, m));
                let mut steps = 0;
                let slots_a = pa.iter_mut().zip(xa.iter_mut());
                for ((pa, xa), (pb, xb)) in slots_a.zip(pb.iter_mut().zip(xb.iter_mut())) {
                    let (Some(u), Some(w)) = (va, vb) else {
                        break;
                    };
                    va = wa.step(k, u, fa, pa, xa);
                    vb = wb.step(k, w, fb, pb, xb);
                    steps += 1;
                }
                close(&mut a.buffers, &mut a.cursor, m, steps, va);
                close(&mut b.buffers, &mut b.cursor, m, steps, vb);
            }
        }
        [Some(a), None] | [None, Some(a)] => {
            while !a.cursor.done {
                let m = CHUNK.min(a.cursor.steps_left);
                let (w, forward) = (a.walk, a.cursor.forward);
                let mut v = Some(a.cursor.v);
                let (positions, points) = open(&mut a.buffers, m);
                let mut steps = 0;
                for (pos, point) in positions.iter_mut().zip(points.iter_mut()) {
                    let Some(u) = v else {
                        break;
                    };
                    v = w.step(k, u, forward, pos, point);
                    steps += 1;
                }
                close(&mut a.buffers, &mut a.cursor, m, steps, v);
            }
        }
        [None, None] => {}
    }
}

#[cfg(test)]
mod tests {
    use super::{Clm, ClmWorkspace, OrderScratch, below, boundary_order, fisher_yates, shuffle};
    use crate::LinkedPolygon;
    use crate::generate::{self, Family, Relation, pair};
    use crate::intersect::{Derivation, LinkedIntersection, verify_linked};
    use crate::kernel::{Exact, Fast, Point};
    use rand::rngs::SmallRng;
    use rand::{Rng, SeedableRng};

    /// Random samples (with repeats, in random order) of strictly convex polygons,
    /// scaled by powers of two from 2^-1000 to 2^1000 and shifted by 2^40..2^52, come
    /// out of `boundary_order` as the distinct sampled vertices in the polygon's
    /// counter-clockwise order, from the lowest (then leftmost) one. At 2^1022 the
    /// differences overflow and the keys are ruined: then either the same order or
    /// `false` with the sample left as drawn. Under `Fast`, some order of the same
    /// points (never a panic).
    #[test]
    fn boundary_order_is_the_cyclic_order_of_the_sample() {
        let mut rng = SmallRng::seed_from_u64(14);
        let mut scratch = OrderScratch::default();
        let (mut checked, mut refused) = (0, 0);
        for round in 0..600 {
            let family = [
                Family::Rotated,
                Family::Ellipse,
                Family::NonUniform,
                Family::OneUlpGap,
            ][round % 4];
            let n = rng.random_range(3..=400);
            let (poly, _) = pair(family, n, Relation::Any, &mut rng);
            let (scale, shift) = match round % 6 {
                0 => (1.0, 0.0),
                1 => (2f64.powi(1000), 0.0),
                2 => (2f64.powi(-1000), 0.0),
                3 => (1.0, 2f64.powi(rng.random_range(40..=52))),
                4 => (2f64.powi(1022), 0.0),
                _ => (2f64.powi(-500), 0.0),
            };
            let vertices: Vec<Point> = poly
                .vertices()
                .iter()
                .map(|v| Point::new(v.x * scale + shift, v.y * scale + shift))
                .collect();
            if crate::ConvexPolygon::new(vertices.iter().copied()).map(|p| p.len()) != Ok(vertices.len()) {
                continue; // the shift merged vertices: not a strictly convex polygon
            }
            let r = rng.random_range(1..=vertices.len() + 8);
            let mut positions: Vec<u32> = (0..r)
                .map(|_| rng.random_range(0..vertices.len() as u32))
                .collect();
            let mut points: Vec<Point> = positions.iter().map(|&i| vertices[i as usize]).collect();
            // The expected order: the sampled positions in the polygon's order, rotated
            // to start at the lowest (then leftmost) sampled point.
            let mut expected: Vec<u32> = positions.clone();
            expected.sort_unstable();
            expected.dedup();
            let start = (0..expected.len())
                .min_by(|&a, &b| {
                    let (p, q) = (vertices[expected[a] as usize], vertices[expected[b] as usize]);
                    p.y.total_cmp(&q.y).then(p.x.total_cmp(&q.x))
                })
                .unwrap();
            expected.rotate_left(start);
            let (mut fast_positions, mut fast_points) = (positions.clone(), points.clone());
            let drawn = positions.clone();
            if boundary_order(Exact, &mut positions, &mut points, &mut scratch) {
                assert_eq!(positions, expected, "round {round}");
                checked += 1;
            } else {
                assert!(
                    round % 6 == 4,
                    "refused at a scale whose keys are sound: round {round}"
                );
                assert_eq!(positions, drawn, "a refused sample is left as drawn");
                refused += 1;
            }
            for (&i, x) in positions.iter().zip(&points) {
                assert_eq!(*x, vertices[i as usize]);
            }
            boundary_order(Fast, &mut fast_positions, &mut fast_points, &mut scratch);
            fast_positions.sort_unstable();
            fast_positions.dedup();
            assert_eq!(fast_positions.len(), expected.len());
        }
        assert!(checked > 400, "{checked} checked, {refused} refused");
    }

    /// Intersecting pairs of the lattice families (exact touchings, one-ulp gaps,
    /// nesting), as generated and scaled exactly to near f64::MAX and to subnormals:
    /// every certified answer carries a certificate that `verify_linked` accepts, and
    /// the LP's last step (a point beyond a chord, or a mixed pair of bounds) gives
    /// the witness in some of them.
    #[test]
    fn last_step_witnesses_verify_on_touching_one_ulp_and_extreme_pairs() {
        let mut rng = SmallRng::seed_from_u64(0x57d1);
        let mut ws = ClmWorkspace::default();
        let families: Vec<Family> = Family::TOUCHING.iter().copied().chain([Family::Nested]).collect();
        let (mut straddles, mut mixed, mut checked) = (0, 0, 0);
        for i in 0..240 {
            let family = families[i % families.len()];
            let (p, q) = generate::pair(family, 30 + 7 * (i % 40), Relation::Intersecting, &mut rng);
            let largest = p
                .vertices()
                .iter()
                .chain(q.vertices())
                .map(|v| v.x.abs().max(v.y.abs()))
                .fold(0.0, f64::max);
            let up = 2f64.powi(1022 - largest.log2().ceil() as i32);
            for scale in [1.0, up, 2f64.powi(-1074)] {
                let f = |v: Point| Point::new(v.x * scale, v.y * scale);
                let (Ok(ps), Ok(qs)) = (p.map(f), q.map(f)) else {
                    continue; // a scaling that merges vertices
                };
                let lp = LinkedPolygon::from_convex_shuffled(&ps, &mut rng);
                let lq = LinkedPolygon::from_convex_shuffled(&qs, &mut rng);
                for _ in 0..4 {
                    let d = Clm.derive_in(Exact, &lp, &lq, &mut rng, &mut ws, &mut ());
                    let Derivation::Certified(c) = d else {
                        panic!("{family} ×{scale:e} #{i}: no certificate under the exact kernel");
                    };
                    assert!(c.intersects(), "{family} ×{scale:e} #{i}: {c:?}");
                    assert_eq!(verify_linked(&lp, &lq, &c), Ok(()), "{family} ×{scale:e} #{i}");
                    straddles += usize::from(ws.lp.straddle().is_some());
                    mixed += usize::from(ws.lp.mixed().is_some());
                    checked += 1;
                }
            }
        }
        assert!(checked > 2000, "{checked}");
        assert!(straddles > 20 && mixed > 20, "{straddles} {mixed} of {checked}");
    }

    /// Intersecting Rotated pairs (the cost measurement's family) and the lattice
    /// families at sizes where the samples outgrow the LP's prefix: every certificate
    /// verifies, including those of queries whose samples the chain walk found meeting
    /// (no LP witness: the sets are searched as convex polygons), which occur.
    #[test]
    fn walk_meets_are_certified_on_the_convex_sets() {
        let mut rng = SmallRng::seed_from_u64(0xc0a5);
        let mut ws = ClmWorkspace::default();
        let families = [
            Family::Rotated,
            Family::SharedEdge,
            Family::VertexOnEdge,
            Family::Nested,
        ];
        let (mut walked, mut checked) = (0, 0);
        for i in 0..160 {
            let family = families[i % families.len()];
            let (p, q) = generate::pair(family, 400 + 13 * i, Relation::Intersecting, &mut rng);
            let lp = LinkedPolygon::from_convex_shuffled(&p, &mut rng);
            let lq = LinkedPolygon::from_convex_shuffled(&q, &mut rng);
            for _ in 0..20 {
                let d = Clm.derive_in(Exact, &lp, &lq, &mut rng, &mut ws, &mut ());
                let Derivation::Certified(c) = d else {
                    panic!("{family} #{i}: no certificate under the exact kernel");
                };
                assert!(c.intersects(), "{family} #{i}: {c:?}");
                assert_eq!(verify_linked(&lp, &lq, &c), Ok(()), "{family} #{i}");
                walked += usize::from(ws.lp.witness_points().is_empty());
                checked += 1;
            }
        }
        assert!(walked > 10, "{walked} of {checked}");
    }

    /// Intersecting Rotated pairs (the cost measurement's family) at sizes where the
    /// 12-point prefixes decide: the LP's last step leaves many certified queries
    /// without a witness, and nearly all of those are certified by a drawn vertex
    /// inside the other sample's quadrilateral (`drawn_witness`); with the rounds
    /// capped at 0 every such query goes on to the cone search and the chord walk
    /// instead. Every certificate verifies either way, and the certified call leaves
    /// the caller's generator where the plain call does.
    #[test]
    fn drawn_witnesses_verify_and_the_walk_takes_over_when_the_rounds_run_out() {
        for cap in [None, Some(0)] {
            let mut rng = SmallRng::seed_from_u64(0xd7a3);
            let (mut ws, mut plain_ws) = (ClmWorkspace::default(), ClmWorkspace::default());
            // Without the prefix test, which answers most of these queries before any
            // LP and so before the draws.
            let clm = super::ClmVariant {
                prefix_quads: false,
                ..super::ClmVariant::default()
            };
            ws.draws.rounds = cap;
            let mut checked = 0;
            for i in 0..24 {
                let (p, q) = generate::pair(
                    Family::Rotated,
                    1 << (8 + i % 5),
                    Relation::Intersecting,
                    &mut rng,
                );
                let lp = LinkedPolygon::from_convex_shuffled(&p, &mut rng);
                let lq = LinkedPolygon::from_convex_shuffled(&q, &mut rng);
                for _ in 0..40 {
                    let mut plain_rng = rng.clone();
                    let plain = clm.intersects_in(Exact, &lp, &lq, &mut plain_rng, &mut plain_ws, &mut ());
                    let d = clm.derive_in(Exact, &lp, &lq, &mut rng, &mut ws, &mut ());
                    // The draws come from the workspace's generator: the caller's is
                    // where the plain call leaves it.
                    assert!(plain && rng == plain_rng, "#{i} (cap {cap:?})");
                    let Derivation::Certified(c) = d else {
                        panic!("#{i} (cap {cap:?}): no certificate under the exact kernel");
                    };
                    assert!(c.intersects(), "#{i} (cap {cap:?}): {c:?}");
                    assert_eq!(verify_linked(&lp, &lq, &c), Ok(()), "#{i} (cap {cap:?})");
                    checked += 1;
                }
            }
            let (found, walked) = (ws.draws.found, ws.draws.walked);
            match cap {
                None => assert!(
                    found > 100 && walked * 10 < found,
                    "{found} drawn, {walked} walked of {checked}"
                ),
                _ => assert!(
                    found == 0 && walked > 100,
                    "{found} drawn, {walked} walked of {checked}"
                ),
            }
        }
    }

    #[test]
    fn below_is_in_range_and_uniform() {
        let mut rng = SmallRng::seed_from_u64(11);
        for n in [1u32, 2, 3, 7, 1000, u32::MAX] {
            for _ in 0..1000 {
                assert!(below(&mut rng, n) < n);
            }
        }
        // n = 3: a rejection threshold above zero (2^32 mod 3 = 1); each value ~1/3.
        let mut hits = [0u32; 3];
        for _ in 0..30_000 {
            hits[below(&mut rng, 3) as usize] += 1;
        }
        assert!(hits.iter().all(|&h| (9_400..10_600).contains(&h)), "{hits:?}");
    }

    #[test]
    fn shuffle_keeps_positions_and_points_together() {
        let mut rng = SmallRng::seed_from_u64(12);
        let mut first = [0u32; 5];
        for _ in 0..2000 {
            let mut positions: Vec<u32> = (0..5).collect();
            let mut points: Vec<Point> = (0..5).map(|i| Point::new(i as f64, -(i as f64))).collect();
            shuffle(&mut positions, &mut points, &mut rng);
            for (&i, x) in positions.iter().zip(&points) {
                assert_eq!(*x, Point::new(i as f64, -(i as f64)));
            }
            let mut sorted = positions.clone();
            sorted.sort_unstable();
            assert_eq!(sorted, [0, 1, 2, 3, 4]);
            first[positions[0] as usize] += 1;
            // Positions alone.
            shuffle(&mut positions, &mut [], &mut rng);
            sorted.clone_from(&positions);
            sorted.sort_unstable();
            assert_eq!(sorted, [0, 1, 2, 3, 4]);
        }
        // Every position comes first about 2000/5 times.
        assert!(first.iter().all(|&h| (300..500).contains(&h)), "{first:?}");
    }

    #[test]
    fn fisher_yates_draws_distinct_positions_and_restores_its_array() {
        let mut rng = SmallRng::seed_from_u64(3);
        let (mut perm, mut swaps, mut out) = (Vec::new(), Vec::new(), Vec::new());
        let mut hits = [0u32; 10];
        // A larger polygon first: its array serves the smaller one.
        fisher_yates(25, 5, &mut rng, &mut perm, &mut swaps, &mut out);
        for r in [0, 1, 3, 9, 10, 20] {
            for _ in 0..200 {
                out.clear();
                fisher_yates(10, r, &mut rng, &mut perm, &mut swaps, &mut out);
                assert_eq!(out.len(), r.min(10));
                let mut sorted = out.clone();
                sorted.sort_unstable();
                sorted.dedup();
                assert_eq!(sorted.len(), out.len(), "distinct: {out:?}");
                assert!(out.iter().all(|&i| i < 10));
                assert_eq!(perm, (0..perm.len() as u32).collect::<Vec<u32>>(), "restored");
                if r == 1 {
                    hits[out[0] as usize] += 1;
                }
            }
        }
        // Every position is drawn (200 single draws over 10 positions).
        assert!(hits.iter().all(|&h| h > 0), "{hits:?}");
    }
}
