//! Warm starts across frames: each candidate pair of the last
//! [`intersecting_pairs`](super::Scene::intersecting_pairs) keeps what its test learnt,
//! so that a pair still separated this frame is proved so in O(1) on coherent motion.
//! This file knows linked polygons and the linear walk, never the scene.
//!
//! # What is kept
//! Per candidate pair of the last frame (keys and generations of both polygons), one
//! [`Warm`] state: the pair intersected, or was separated (no certificate kept yet), or a
//! *separating certificate by handles*: a vertex handle `from` of one polygon (the edge
//! is `from` → its current successor, so it is an edge whatever edits happened) and the
//! handle of the other polygon's vertex deepest on that edge's inner side. Nothing else:
//! memory is O(candidate pairs of the last frame), rebuilt at every frame by one merge of
//! two sorted lists (pairs no longer candidates, and pairs of removed polygons, are
//! dropped then; a removed polygon's handles and generation never match again, so until
//! then its entries are only dead weight, never used).
//!
//! # The check
//! Next frame, when both handles are still live ([`LinkedPolygon::position`] refuses a
//! removed vertex and a vertex of another polygon, as after a slot's reuse), the deepest
//! vertex is hill-climbed from the kept one along the links, comparing depths with the
//! kernel's exact `cross`: under pure translation it does not move, after a few vertex
//! edits it moves a few steps. A linear function along a strictly convex polygon is
//! unimodal with plateaus of at most two vertices, so a vertex no neighbour of which is
//! strictly deeper is the deepest of all. If it lies strictly outside the edge
//! (`orient` is clockwise), every vertex does: the pair is separated and
//! `Separated { from, to }` certifies it. Otherwise the planner's full test answers.
//! Each climb is capped at the polygon's size, so an inconsistent kernel cannot loop; a
//! capped climb falls back to the full test.
//!
//! # Filling the cache
//! A certificate by handles is found by the linear walk on the linked polygons
//! ([`separating_edge_at`]), which also answers the query: O(n + m). It is run instead of
//! the planner's test only for a pair that was a candidate *and separated* the frame
//! before (so the pair persists): incoherent motion (pairs new every frame) never pays
//! for it, and a pair that keeps intersecting keeps the planner's cheaper tests.
//!
//! # Precision
//! Under [`Exact`](crate::Exact) every step is an exact predicate on stored
//! coordinates: a warm answer is the exact answer. Under the fast kernel a warm answer
//! may be wrong exactly where the fast full test may be.

use crate::intersect::{Which, separating_edge_at};
use crate::kernel::{Kernel, Orientation, Point};
use crate::polygon::{LinkedPolygon, VertexId};

/// What the last frame learnt about one candidate pair.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Warm {
    /// The pair intersected: the planner's test answers again.
    Intersecting,
    /// The pair was separated, with no certificate kept: the linear walk answers and
    /// finds one.
    Separated,
    /// Separated by the edge `from` → successor of polygon `of` (P is the pair's first
    /// key); `deep` is the other polygon's vertex deepest on the edge's inner side.
    Certified {
        of: Which,
        from: VertexId,
        deep: VertexId,
    },
}

/// One pair of the last frame: keys (first < second), generations, state.
#[derive(Clone, Copy, Debug)]
struct Kept {
    keys: (u32, u32),
    generations: (u64, u64),
    warm: Warm,
}

instrument_pub! {
    /// Counters of the warm starts, for tests and benches.
    #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
    #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
    struct WarmStats {
        /// Pairs proved separated by their kept certificate.
        pub hits: u64,
        /// Kept certificates that no longer separate (or whose handles died): the planner's
        /// test answered.
        pub misses: u64,
        /// Linear walks run to find a certificate for a pair separated the frame before.
        pub fills: u64,
    }
}

/// The warm-start cache: the last frame's candidate pairs, sorted by keys.
#[derive(Clone, Debug, Default)]
pub(crate) struct WarmCache {
    kept: Vec<Kept>,
    pub(crate) stats: WarmStats,
}

impl WarmCache {
    /// The last frame's state of each of this frame's candidate `pairs` (sorted, keys
    /// first < second), `generation` giving each key's polygon generation. Consumes the
    /// kept pairs: [`keep`](Self::keep) stores this frame's. O(pairs + kept).
    pub(crate) fn take(
        &mut self,
        pairs: &[(usize, usize)],
        generation: impl Fn(usize) -> u64,
    ) -> Vec<Option<Warm>> {
        let kept = std::mem::take(&mut self.kept);
        let mut old = kept.iter().peekable();
        pairs
            .iter()
            .map(|&(a, b)| {
                let keys = (a as u32, b as u32);
                while old.next_if(|k| k.keys < keys).is_some() {}
                let k = old.next_if(|k| k.keys == keys)?;
                (k.generations == (generation(a), generation(b))).then_some(k.warm)
            })
            .collect()
    }

    /// Stores this frame's states (pairs sorted, as given to [`take`](Self::take)).
    pub(crate) fn keep(
        &mut self,
        pairs: &[(usize, usize)],
        states: impl Iterator<Item = Warm>,
        generation: impl Fn(usize) -> u64,
    ) {
        self.kept.clear();
        self.kept
            .extend(pairs.iter().zip(states).map(|(&(a, b), warm)| Kept {
                keys: (a as u32, b as u32),
                generations: (generation(a), generation(b)),
                warm,
            }));
    }

    /// Drops every kept pair (and its memory).
    pub(crate) fn clear(&mut self) {
        self.kept = Vec::new();
    }

    pub(crate) fn heap_bytes(&self) -> usize {
        self.kept.capacity() * std::mem::size_of::<Kept>()
    }
}

/// A separating edge found or confirmed: the certificate's points (the edge, counter-
/// clockwise, of polygon `of`) and the state to keep.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Separation {
    pub(crate) of: Which,
    pub(crate) from: Point,
    pub(crate) to: Point,
    pub(crate) warm: Warm,
}

/// Checks a kept certificate on the polygons as they are now (`p` is the pair's first
/// polygon): `Some` when it still separates them (with the climbed deepest vertex),
/// `None` when it does not or a handle died. O(1) plus the climb.
pub(crate) fn check<K: Kernel>(
    k: K,
    p: &LinkedPolygon,
    q: &LinkedPolygon,
    of: Which,
    from: VertexId,
    deep: VertexId,
) -> Option<Separation> {
    let (e, o) = match of {
        Which::P => (p, q),
        Which::Q => (q, p),
    };
    let s_pos = e.position(from).ok()?;
    let (s, t) = (e.point_at(s_pos), e.point_at(e.next_at(s_pos)));
    let j = climb(k, o, s, t, o.position(deep).ok()?)?;
    (k.orient(s, t, o.point_at(j)) == Orientation::Cw).then(|| Separation {
        of,
        from: s,
        to: t,
        warm: Warm::Certified {
            of,
            from,
            deep: o.id_at(j),
        },
    })
}

/// The position of the vertex of `o` deepest on the inner (left) side of the line
/// s → t, climbing from position `j`: `w` is deeper than `v` iff (t − s) × (w − v) > 0.
/// `None` when a climb runs past the polygon's size (an inconsistent kernel).
fn climb<K: Kernel>(k: K, o: &LinkedPolygon, s: Point, t: Point, mut j: usize) -> Option<usize> {
    let m = o.len();
    for step in [LinkedPolygon::next_at, LinkedPolygon::prev_at] {
        let mut moved = 0;
        loop {
            let n = step(o, j);
            if k.cross(s, t, o.point_at(j), o.point_at(n)) != Orientation::Ccw {
                break;
            }
            j = n;
            moved += 1;
            if moved > m {
                return None;
            }
        }
        // Moved forwards: the vertex behind is strictly shallower, so `j` is a local
        // (hence the global) maximum; no need to look backwards.
        if moved > 0 {
            break;
        }
    }
    Some(j)
}

/// The linear walk on the linked polygons, keeping what it finds: a separation with its
/// certificate by handles, or `None` when the polygons intersect. O(n + m).
pub(crate) fn fill<K: Kernel>(k: K, p: &LinkedPolygon, q: &LinkedPolygon) -> Option<Separation> {
    [(Which::P, p, q), (Which::Q, q, p)]
        .into_iter()
        .find_map(|(of, e, o)| {
            let (s, t, j) = separating_edge_at(k, e, o, &mut ())?;
            Some(Separation {
                of,
                from: e.point_at(s),
                to: e.point_at(t),
                warm: Warm::Certified {
                    of,
                    from: e.id_at(s),
                    deep: o.id_at(j),
                },
            })
        })
}
