use super::events::{Input, sorted_events, standalone};
use super::{CrossingOptions, Crossings, edge_pair_points};
use crate::kernel::{Kernel, Point};
use crate::polygon::SimplePolygon;
use std::cmp::Ordering;

/// [`ListSweep`]: Žalik's sweep line with two lists of pierced edges (as in the report of docs/crossings.md).
///
/// # Algorithm
/// The n + m vertices of both polygons are the events, sorted lexicographically:
/// by x, then by y (so a vertical edge starts at its lower end and no two
/// neighbours of a vertex tie with it). Each polygon has a list of its edges
/// currently pierced by the sweep line. At a vertex v with neighbours u (previous)
/// and w (next) in its polygon:
///
/// * rule A: u > v and w > v (both edges start here): insert both edges;
/// * rule B: u < v and w < v (both edges end here): remove both;
/// * rules C and D: one neighbour before v, one after: insert the edge that starts
///   here, remove the one that ends here;
/// * rule V (a neighbour on the same vertical line): covered by the y tie-break,
///   which makes the lower end the start, so it is rule A, B, C or D.
///
/// Each inserted edge is tested against every edge in the **other** polygon's list
/// (the polygons are simple, so an edge never meets a non-adjacent edge of its own
/// polygon). All vertices at one point (at most one per polygon) form one event
/// group: every insertion of the group happens before any removal. Since the points
/// of a segment are lexicographically between its ends, two edges that meet have
/// overlapping closed event ranges, and the one inserted later finds the other
/// still listed, including when they only touch at the event point. That is what
/// makes touchings, vertex-on-vertex contacts and overlaps come out complete.
///
/// The lists are vectors with a position index per edge: insertion appends,
/// removal swaps the last entry in (O(1), where the report's linked lists take O(r)).
/// Each entry keeps its edge's y-range in a column of its own, and a candidate
/// whose y-range misses the new edge's is skipped with two comparisons on 16
/// contiguous bytes (x-ranges overlap by construction).
///
/// # Complexity
/// O((n + m) log(n + m)) to sort plus O(W) candidate checks, W = Σ r, r being the
/// length of the other polygon's list at each insertion; worst case O(n·m) (every
/// edge of P spanning the x-range of every edge of Q: zigzags, combs of long
/// needles). On the report's random polygons r is a small fraction of n. Memory
/// O(n + m). W depends only on the order of the vertices: [`Sweep`](super::Sweep)
/// counts it in O(n + m) before testing any pair, to choose between this and
/// [`TreeSweep`](super::TreeSweep) (with `instrument`, `ListSweep::work` reports W with the number of
/// pair tests).
///
/// # Degeneracies and precision
/// As for the module: predicates come from the caller's kernel, touchings and
/// overlaps are reported as input vertices, crossings are constructed by
/// [`crossing_point`](super::crossing_point). Under the exact kernel the result is
/// identical to [`Brute`](super::Brute)'s.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct ListSweep;

/// One polygon's list of pierced edges, stored by columns so that the scan over
/// y-ranges (the hot loop) reads 16 bytes per entry.
#[derive(Clone, Debug, Default)]
struct List {
    /// (lowest y, highest y) of each listed edge.
    ys: Vec<(f64, f64)>,
    /// The endpoints, in polygon order.
    segs: Vec<(Point, Point)>,
    /// The edge index.
    edges: Vec<u32>,
}

impl List {
    fn clear(&mut self) {
        self.ys.clear();
        self.segs.clear();
        self.edges.clear();
    }

    fn push(&mut self, edge: u32, a: Point, b: Point, ys: (f64, f64)) {
        self.ys.push(ys);
        self.segs.push((a, b));
        self.edges.push(edge);
    }

    /// Removes entry `at` by moving the last entry there; returns the moved edge.
    fn swap_remove(&mut self, at: usize) -> Option<u32> {
        self.ys.swap_remove(at);
        self.segs.swap_remove(at);
        self.edges.swap_remove(at);
        self.edges.get(at).copied()
    }
}

/// Reusable scratch memory for [`ListSweep`].
#[derive(Clone, Debug, Default)]
pub struct ListWorkspace {
    lists: [List; 2],
    pos: [Vec<u32>; 2],
    /// Pass every candidate on, without the y-range check (the crossings report's sweep).
    every_candidate: bool,
}

impl Crossings for ListSweep {
    const NAME: &'static str = "list-sweep";

    fn crossings_with_options<K: Kernel>(
        &self,
        k: K,
        p: &SimplePolygon,
        q: &SimplePolygon,
        options: CrossingOptions,
    ) -> Vec<Point> {
        standalone(p, q, |input, out| {
            run(input, &mut ListWorkspace::default(), u64::MAX, |a, b, c, d| {
                edge_pair_points(k, a, b, c, d, options, out)
            });
        })
    }
}

/// The cost of a candidate whose y-range meets the new edge's (a segment test), in
/// units of a skipped candidate.
pub(crate) const PAIR_COST: u64 = 8;

/// Runs the sweep over the sorted vertices, calling `pair` on every pair of a P edge
/// and a Q edge whose y-ranges overlap while both are listed (each edge in its
/// polygon's direction, P's first). Gives up, returning `None`, as soon as its work
/// exceeds `budget`: one unit per candidate checked and [`PAIR_COST`] per candidate
/// passed to `pair`; otherwise returns the work done.
pub(crate) fn run(
    input: Input<'_>,
    ws: &mut ListWorkspace,
    budget: u64,
    mut pair: impl FnMut(Point, Point, Point, Point),
) -> Option<u64> {
    let mut spent = 0u64;
    let filter = !ws.every_candidate;
    let Input { p, q, events } = input;
    let polys = [p.vertices(), q.vertices()];
    let n = polys[0].len();
    for ((list, pos), v) in ws.lists.iter_mut().zip(&mut ws.pos).zip(polys) {
        list.clear();
        pos.clear();
        pos.resize(v.len(), u32::MAX);
    }
    let locate = |id: u32| -> (usize, usize) {
        let id = id as usize;
        if id < n { (0, id) } else { (1, id - n) }
    };
    let total = events.len();
    let mut i = 0;
    while i < total {
        let here = events[i].0;
        let mut j = i + 1;
        while j < total && events[j].0 == here {
            j += 1;
        }
        // Insertions of the whole group first (rules A, C, D: edges starting here).
        for &(_, id) in &events[i..j] {
            let (s, w) = locate(id);
            let v = polys[s];
            let len = v.len();
            for e in [(w + len - 1) % len, w] {
                let (a, b) = (v[e], v[(e + 1) % len]);
                let other = if e == w { b } else { a };
                if here.lex_cmp(other) != Ordering::Less {
                    continue;
                }
                let (ylo, yhi) = (a.y.min(b.y), a.y.max(b.y));
                let other_list = &ws.lists[1 - s];
                spent += other_list.ys.len() as u64;
                for (at, &(lo, hi)) in other_list.ys.iter().enumerate() {
                    if filter && (lo > yhi || hi < ylo) {
                        continue;
                    }
                    spent += PAIR_COST;
                    let (c, d) = other_list.segs[at];
                    if s == 0 {
                        pair(a, b, c, d);
                    } else {
                        pair(c, d, a, b);
                    }
                }
                if spent > budget {
                    return None;
                }
                ws.pos[s][e] = ws.lists[s].edges.len() as u32;
                ws.lists[s].push(e as u32, a, b, (ylo, yhi));
            }
        }
        // Then the removals (rules B, C, D: edges ending here).
        for &(_, id) in &events[i..j] {
            let (s, w) = locate(id);
            let v = polys[s];
            let len = v.len();
            for e in [(w + len - 1) % len, w] {
                let other = if e == w { v[(e + 1) % len] } else { v[e] };
                if here.lex_cmp(other) != Ordering::Greater {
                    continue;
                }
                let at = ws.pos[s][e] as usize;
                if at == u32::MAX as usize {
                    continue; // never inserted (only if the polygon was not validated)
                }
                if let Some(moved) = ws.lists[s].swap_remove(at) {
                    ws.pos[s][moved as usize] = at as u32;
                }
                ws.pos[s][e] = u32::MAX;
            }
        }
        i = j;
    }
    Some(spent)
}

instrument_pub! {
    /// How much work [`ListSweep`] does on a pair of polygons.
    #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
    #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
    struct ListWork {
        /// Candidates checked: Σ r over the insertions, r the other list's length.
        pub candidates: u64,
        /// Candidates whose y-range meets the inserted edge's: the pairs tested.
        pub tests: u64,
    }
}

/// The lists as the crossings report runs them: `pair` is called on every candidate (each edge
/// of the other polygon listed when an edge is inserted, P's edge first), with no
/// y-range check. For `polysect bench crossings`.
#[cfg(feature = "cli")]
pub(crate) fn every_candidate(
    p: &SimplePolygon,
    q: &SimplePolygon,
    events: &mut Vec<(Point, u32)>,
    ws: &mut ListWorkspace,
    pair: impl FnMut(Point, Point, Point, Point),
) {
    sorted_events(p, q, events);
    let input = Input { p, q, events };
    ws.every_candidate = true;
    run(input, ws, u64::MAX, pair);
    ws.every_candidate = false;
}

impl ListSweep {
    instrument_pub! {
        /// Counts the candidates and the pair tests of the sweep on `p` and `q`, testing
        /// no pair.
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn work(p: &SimplePolygon, q: &SimplePolygon) -> ListWork {
            let mut events = Vec::new();
            sorted_events(p, q, &mut events);
            let input = Input {
                p,
                q,
                events: &events,
            };
            let mut tests = 0;
            run(input, &mut ListWorkspace::default(), u64::MAX, |_, _, _, _| {
                tests += 1
            });
            ListWork {
                candidates: super::events::list_work(input),
                tests,
            }
        }
    }
}
