//! The input both sweeps share: the two polygons and their vertices sorted once as
//! events, and the exact count of the work [`ListSweep`](super::ListSweep) would do on
//! it, from which [`Sweep`](super::Sweep) chooses.
//!
//! # Complexity
//! Sorting the events is O(k log k) for k = n + m vertices; [`list_work`] is one O(k)
//! pass over them.
//!
//! # Degeneracies and precision
//! Equal points (a zero of either sign included) get equal keys and are grouped as one
//! event; every comparison is exact (lexicographic order of f64 coordinates).

use super::sort_dedup;
use crate::kernel::Point;
use crate::polygon::SimplePolygon;
use std::cmp::Ordering;

/// The two polygons and their sorted vertices: the input of both sweeps.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Input<'a> {
    pub p: &'a SimplePolygon,
    pub q: &'a SimplePolygon,
    /// The vertices of P (ids 0..n) and of Q (ids n..n+m), see [`sorted_events`].
    pub events: &'a [(Point, u32)],
}

/// Sorts the vertices, lets `run` append points for them, and returns the points
/// sorted and deduplicated: a whole query for a sweep without a workspace.
pub(crate) fn standalone(
    p: &SimplePolygon,
    q: &SimplePolygon,
    run: impl FnOnce(Input<'_>, &mut Vec<Point>),
) -> Vec<Point> {
    let mut events = Vec::new();
    sorted_events(p, q, &mut events);
    let mut out = Vec::new();
    run(
        Input {
            p,
            q,
            events: &events,
        },
        &mut out,
    );
    sort_dedup(&mut out);
    out
}

/// The vertices of P (ids 0..n) and of Q (ids n..n+m) sorted lexicographically
/// (x, then y): the events of both sweeps.
pub(crate) fn sorted_events(p: &SimplePolygon, q: &SimplePolygon, events: &mut Vec<(Point, u32)>) {
    let n = p.len();
    events.clear();
    events.extend(p.vertices().iter().enumerate().map(|(i, &v)| (v, i as u32)));
    events.extend(q.vertices().iter().enumerate().map(|(i, &v)| (v, (n + i) as u32)));
    // Equal points get equal keys whatever the sign of a zero: lexicographic order.
    events.sort_unstable_by_key(|&(v, _)| super::lex_key(Point::new(v.x + 0.0, v.y + 0.0)));
}

/// The number of candidates [`ListSweep`](super::ListSweep) checks on this input: Σ r over the
/// insertions, r the length of the other polygon's list at that moment. O(n + m).
pub(crate) fn list_work(input: Input<'_>) -> u64 {
    let Input { p, q, events } = input;
    let polys = [p.vertices(), q.vertices()];
    let n = polys[0].len();
    let mut len = [0u64; 2];
    let mut work = 0u64;
    let total = events.len();
    let mut i = 0;
    while i < total {
        let here = events[i].0;
        let mut j = i + 1;
        while j < total && events[j].0 == here {
            j += 1;
        }
        let mut ending = [0u64; 2];
        for &(_, id) in &events[i..j] {
            let id = id as usize;
            let (s, w) = if id < n { (0, id) } else { (1, id - n) };
            let v = polys[s];
            let m = v.len();
            for other in [v[(w + m - 1) % m], v[(w + 1) % m]] {
                match here.lex_cmp(other) {
                    Ordering::Less => {
                        work += len[1 - s];
                        len[s] += 1;
                    }
                    Ordering::Greater => ending[s] += 1,
                    Ordering::Equal => {}
                }
            }
        }
        len[0] = len[0].saturating_sub(ending[0]);
        len[1] = len[1].saturating_sub(ending[1]);
        i = j;
    }
    work
}
