//! Probes: what an algorithm reports while it runs, for experiments (the thesis's
//! iteration counts, work counts, step traces) and for the tests that count fallbacks.
//! The unit type `()` ignores every report and compiles away; the lean library's
//! queries all run with it. An API with the `instrument` feature only.

use super::{Kept, Which};
use crate::kernel::Point;
use crate::lp::{ArenaPoints, LpError, Separation};

/// Receives one call per pruning iteration of an algorithm, for experiments
/// (the thesis's iteration counts). The unit type `()` ignores them and compiles away.
pub trait Probe {
    /// One pruning iteration (for CLM: one unit of work, see its module docs).
    #[inline]
    fn iteration(&mut self) {}

    /// Called when a certified call could not derive its certificate from what the
    /// algorithm found and completed the answer with a slower search (see
    /// [`Derivation`](super::Derivation)); tests count these.
    #[inline]
    fn fallback(&mut self, _kind: Fallback) {}

    /// [`Clm`](super::Clm) drew its samples `p` and `q` (once per query).
    #[inline]
    fn samples(&mut self, _p: &ArenaPoints<'_>, _q: &ArenaPoints<'_>) {}

    /// [`Clm`](super::Clm) ran one LP on the point sets `a` and `b` (its constraints), which
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

    /// [`Clm`](super::Clm) walked one chain (a step per vertex collected).
    #[inline]
    fn chain_walk(&mut self, _chain: &ArenaPoints<'_>) {}

    /// [`Clm`](super::Clm) tested `tested` sample points (one unit of work each) in quadrilaterals
    /// of the other polygon's sample vertices, which lie inside that polygon.
    /// `inside`: the vertex it found in one, its polygon, and that quadrilateral
    /// (counter-clockwise; a corner repeats where it has only three); then the
    /// polygons intersect and the query ends there.
    #[inline]
    fn sample_quads(&mut self, _tested: u64, _inside: Option<(Which, Point, [Point; 4])>) {}

    /// One pruning step of [`Barba`](super::Barba), [`Dobkin`](super::Dobkin) or [`ChazelleDobkin`](super::ChazelleDobkin) is about to
    /// decide: what the algorithm keeps at this point ([`Kept`]). [`Tracer`](super::Tracer) records
    /// these as a [`Trace`](super::Trace).
    #[inline]
    fn kept(&mut self, _kept: Kept<'_>) {}
}

/// How a certified call completed an answer its algorithm did not certify.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Fallback {
    /// An O(log n + log m) search that certifies the answer under the exact kernel:
    /// Dobkin's separation for "disjoint", Barba's witness for "intersecting".
    Search,
    /// [`exact_certificate`](super::exact_certificate), O(n + m): the search contradicted the answer, which only
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
