//! [`Kept`] and [`Span`]: what an array algorithm keeps when one of its pruning steps is
//! about to decide, the argument of [`Probe::kept`](super::Probe::kept). The plain
//! calls' no-op probe never reads it; with the `instrument` feature the trace recorder
//! (`Tracer`) turns these reports into a step-by-step trace.

// Only the trace recorder reads these reports; without `instrument` they are built
// for the unit probe, which ignores them (and the optimizer removes them).
#![cfg_attr(not(feature = "instrument"), allow(dead_code))]

use crate::kernel::Point;

/// `len` consecutive vertices of a polygon from array index `start`, wrapping past the
/// last vertex. The hooks may give a `start` of n or more, meaning `start` modulo n
/// (so that the plain calls compute no remainder for them); traces (`instrument`) hold starts
/// below n.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Span {
    /// Array index of the first vertex (modulo the polygon's size).
    pub start: usize,
    /// Number of vertices.
    pub len: usize,
}

impl Span {
    /// The span of `len` vertices from `start`.
    #[inline]
    pub const fn new(start: usize, len: usize) -> Span {
        Span { start, len }
    }

    /// The array indices of the span in a polygon of `n` vertices (at most `n`).
    pub fn indices(self, n: usize) -> impl Iterator<Item = usize> {
        (0..self.len.min(n)).map(move |i| (self.start + i) % n.max(1))
    }
}

/// What an array algorithm keeps when one of its steps is about to decide
/// ([`Probe::kept`](super::Probe::kept)). Index ranges are into the polygons' vertex arrays.
#[derive(Clone, Copy, Debug)]
pub enum Kept<'a> {
    /// Barba–Langerman's main loop: P' (vertices `p` of P) and Q' (vertices `q` of
    /// Q). T_P is P''s vertices at positions `tp`; T_Q's edges start at Q''s positions
    /// 0, (len − 2)/2 and len − 2. Invariant: P and Q intersect if and only if CH(P')
    /// and CH(Q') do.
    Barba {
        /// P'.
        p: Span,
        /// T_P's vertices, as positions in P' (0, len/3, 2·len/3 on the first step and
        /// along chains that started there, else 0, (len − 1)/2, len − 1).
        tp: [usize; 3],
        /// Q'.
        q: Span,
    },
    /// Barba–Langerman's finish: P' against Q''s vertices `q` (at most six, array
    /// indices into Q; two when Q' shrank to a chord).
    BarbaSmall {
        /// P'.
        p: Span,
        /// T_P's vertices, as positions in P'.
        tp: [usize; 3],
        /// Q''s vertices.
        q: &'a [usize],
    },
    /// Dobkin–Souvaine: one chain-pair search, the part `l` of the left chain of the
    /// polygon `left` against the part `r` of the right chain of `right`, both within
    /// the common y-interval `heights` (low, high).
    Dobkin {
        /// The polygon of the left chain.
        left: &'a [Point],
        /// The left chain's part in play, top to bottom.
        l: Span,
        /// The polygon of the right chain.
        right: &'a [Point],
        /// The right chain's part in play, bottom to top.
        r: Span,
        /// The common y-interval: low, high.
        heights: [f64; 2],
    },
    /// Chazelle–Dobkin: the chains F (vertices `f` of P) and G (vertices `g` of Q)
    /// still in play; `pivot` is P's vertex 0, `tangents` the pencil's tangent points
    /// on Q (q_L, q_R) and `window` the directions from the pivot bounding the window.
    ChazelleDobkin {
        /// F, a chain of P.
        f: Span,
        /// G, a chain of Q.
        g: Span,
        /// P's vertex 0.
        pivot: Point,
        /// The pencil's tangent points on Q.
        tangents: [Point; 2],
        /// Points on the window's two bounding directions from the pivot.
        window: [Point; 2],
    },
}
