use super::events::{Input, standalone};
use super::status::Status;
use super::{CrossingOptions, Crossings, edge_pair_points};
use crate::kernel::{Exact, Kernel, Orientation, Point};
use crate::polygon::SimplePolygon;
use std::cmp::Ordering;

/// [`TreeSweep`]: a red–blue sweep over the vertices only, with one ordered status
/// holding the pierced edges of both polygons, O((n + m + k) log(n + m)) on every input.
///
/// # Why it works
/// The edges of one simple polygon never cross each other, so along any vertical
/// line the order of P's pierced edges never changes while they are pierced, and
/// the same holds for Q's (the idea of Mantler and Snoeyink's red–blue sweep). Only
/// a P edge and a Q edge can change order, and only where they meet. The status is
/// one sequence of the pierced edges of both polygons in which:
///
/// 1. the edges of each polygon are in their true bottom-to-top order;
/// 2. every pair of a P edge and a Q edge that has not been reported yet is in the
///    order they had when the later of the two was inserted.
///
/// So a pair that is out of order (listed below, lying above) has met since, and
/// reporting it is output. Crossing points are never events and never compared:
/// the sweep stops at the n + m vertices only, sorted lexicographically (x, then y),
/// and repairs the order lazily, where it needs it: around the current vertex v.
///
/// # One event
/// Each pierced edge s = (a, b) (a < v ≤ b lexicographically) is classified against
/// v by one exact orientation test: **below** v, **through** v (collinear; then v
/// lies on s) or **above** v.
///
/// 1. *Below against the rest.* Along P's edges the classes are sorted (below,
///    then through, then above), and so along Q's. Let x be the first P edge that is
///    not below and y the last Q edge that is below. If x is listed before y, every
///    P edge between them is not below and every Q edge between them is below, and
///    each pair (P edge listed before Q edge) in that stretch is out of order: it has
///    met. The stretch is reported pair by pair and rewritten as its Q edges
///    followed by its P edges, each polygon's order kept. (Or the same with the
///    colours exchanged; both cannot happen at once.) The work is proportional to
///    the pairs reported, plus O(log n) to find x and y.
/// 2. *Through against above*, the same way.
/// 3. Now the status is: below v, through v, above v. Every pair of a P edge and a Q
///    edge through v, counting the edges that start at v, meets at v and is reported.
///    The edges that end at v are removed; the edges that continue past v and those
///    that start at v are put back in the order of their directions (an exact
///    cross-product sign; collinear P and Q edges overlap and may go either way).
///
/// Every pair that meets is reported: a pair that meets at a vertex of either is
/// reported there in step 3 (both are pierced and go through it; this covers
/// touchings and the first point of every overlap), and a pair that crosses
/// properly at a point c that is no vertex is out of order at the next vertex where
/// one of them ends (one goes through it, the other does not), and steps 1 and 2
/// find every such pair. A reported pair always meets, so a pair is reported at
/// most a constant number of times (an overlap at both its ends).
///
/// # Complexity
/// O((n + m) log(n + m)) expected for the sort and the status operations (a treap,
/// `status.rs`), plus O(k log(n + m)) for the k reported pairs: k is at
/// most eight times the number of reported points (a point is shared by at most four
/// pairs, and a pair is reported at most twice). No pair of edges is ever tested
/// in vain. Memory O(n + m). The bound holds for every input, including edges that
/// all span one x-range, many vertices on one vertical line and long overlaps.
///
/// # Degeneracies
/// A vertical edge is pierced between its lower and its upper end (the events are
/// sorted by x, then y) and goes through every vertex on it, so it meets what
/// crosses it there in step 3 or is repaired at its upper end. Edges of P and Q on
/// one line overlap from the later of their lower ends: both go through that
/// vertex (step 3 reports them), keep one order while they overlap (they are in the
/// same class at every vertex), and go through the end of the overlap too. Any
/// number of vertices may share an x. A P vertex on a Q vertex is one event with
/// up to four edges through it.
///
/// # Precision
/// The sweep's own decisions (classification against a vertex, the order of
/// directions) are exact orientation signs on input points, taken with [`Exact`]
/// whatever the caller's kernel: a status ordered by inconsistent signs would have
/// no complexity bound. The caller's kernel decides only, through
/// [`segment_contact`](crate::kernel::segment_contact), how each reported pair meets.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct TreeSweep;

/// How a pierced edge lies against the current vertex.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Class {
    Below,
    Through,
    Above,
}

/// Reusable scratch memory for [`TreeSweep`].
#[derive(Clone, Debug, Default)]
pub struct TreeWorkspace {
    status: Status,
    /// Lexicographically smaller and larger end of each edge (P's edges, then Q's).
    lo: Vec<Point>,
    hi: Vec<Point>,
    region: Vec<u32>,
    scratch: Vec<u32>,
    starts: Vec<u32>,
}

impl Crossings for TreeSweep {
    const NAME: &'static str = "tree-sweep";

    fn crossings_with_options<K: Kernel>(
        &self,
        k: K,
        p: &SimplePolygon,
        q: &SimplePolygon,
        options: CrossingOptions,
    ) -> Vec<Point> {
        standalone(p, q, |input, out| {
            run(k, input, options, &mut TreeWorkspace::default(), out)
        })
    }
}

/// Runs the sweep over `events` (the vertices of P then Q, sorted), appending the
/// points of every reported pair to `out` (unsorted, with repeats).
pub(crate) fn run<K: Kernel>(
    k: K,
    input: Input<'_>,
    options: CrossingOptions,
    ws: &mut TreeWorkspace,
    out: &mut Vec<Point>,
) {
    let Input { p, q, events } = input;
    let polys = [p.vertices(), q.vertices()];
    let n = polys[0].len();
    ws.lo.clear();
    ws.hi.clear();
    for v in polys {
        for i in 0..v.len() {
            let (a, b) = (v[i], v[(i + 1) % v.len()]);
            let (lo, hi) = if a.lex_cmp(b).is_le() { (a, b) } else { (b, a) };
            ws.lo.push(lo);
            ws.hi.push(hi);
        }
    }
    ws.status.reset(n + polys[1].len(), n);
    let mut sweep = State {
        k,
        polys,
        n,
        options,
        ws,
        out,
    };
    let total = events.len();
    let mut i = 0;
    while i < total {
        let here = events[i].0;
        let mut j = i + 1;
        while j < total && events[j].0 == here {
            j += 1;
        }
        sweep.ws.starts.clear();
        for &(_, id) in &events[i..j] {
            let id = id as usize;
            let (s, w) = if id < n { (0, id) } else { (1, id - n) };
            let len = polys[s].len();
            for e in [(w + len - 1) % len, w] {
                let eid = (e + s * n) as u32;
                // (A validated polygon has no edge of length zero; skip one anyway.)
                if sweep.ws.lo[eid as usize] == here && sweep.ws.hi[eid as usize] != here {
                    sweep.ws.starts.push(eid);
                }
            }
        }
        sweep.event(here);
        i = j;
    }
}

/// One run of the sweep: the input, the options and the workspace.
struct State<'a, K: Kernel> {
    k: K,
    polys: [&'a [Point]; 2],
    n: usize,
    options: CrossingOptions,
    ws: &'a mut TreeWorkspace,
    out: &'a mut Vec<Point>,
}

impl<K: Kernel> State<'_, K> {
    #[inline]
    fn class(&self, id: u32, v: Point) -> Class {
        let (lo, hi) = (self.ws.lo[id as usize], self.ws.hi[id as usize]);
        if hi == v {
            return Class::Through;
        }
        match Exact.orient(lo, hi, v) {
            Orientation::Ccw => Class::Below,
            Orientation::Cw => Class::Above,
            Orientation::Collinear => Class::Through,
        }
    }

    /// Reports the pair of edges `a` and `b` (one of each polygon, either order).
    fn report(&mut self, a: u32, b: u32) {
        let (pe, qe) = if (a as usize) < self.n {
            (a as usize, b as usize - self.n)
        } else {
            (b as usize, a as usize - self.n)
        };
        let (p, q) = (self.polys[0], self.polys[1]);
        edge_pair_points(
            self.k,
            p[pe],
            p[(pe + 1) % p.len()],
            q[qe],
            q[(qe + 1) % q.len()],
            self.options,
            self.out,
        );
    }

    fn event(&mut self, v: Point) {
        // Steps 1 and 2: separate below / through / above, repairing where needed.
        let (mut from, mut to) = (0, 0);
        if self.ws.status.len() > 0 {
            let mut b = self.boundaries(v);
            if let Some((lo, hi, x)) = self.inversion(b.0) {
                self.repair(lo, hi, x);
                b = self.boundaries(v);
            }
            if let Some((lo, hi, x)) = self.inversion(b.1) {
                self.repair(lo, hi, x);
                b = self.boundaries(v);
            }
            from = b.0[0].min(b.0[1]);
            to = b.1[0].min(b.1[1]).max(from);
        }
        if from == to && self.ws.starts.is_empty() {
            return;
        }
        // Step 3: the edges through v form the stretch from..to.
        let mut through = std::mem::take(&mut self.ws.region);
        through.clear();
        self.ws.status.cut(from, to, &mut through);
        let starts = std::mem::take(&mut self.ws.starts);
        // Every P–Q pair through v meets at v.
        for (i, &a) in through.iter().chain(&starts).enumerate() {
            for &b in through.iter().chain(&starts).skip(i + 1) {
                if self.ws.status.color(a) != self.ws.status.color(b) {
                    self.report(a, b);
                }
            }
        }
        // Put back what continues past v, with what starts at v, by direction.
        through.retain(|&id| self.ws.hi[id as usize] != v);
        through.extend_from_slice(&starts);
        let (lo, hi) = (&self.ws.lo, &self.ws.hi);
        let status = &self.ws.status;
        through.sort_by(|&a, &b| {
            let (a_, b_) = (a as usize, b as usize);
            match Exact.cross(lo[a_], hi[a_], lo[b_], hi[b_]) {
                Orientation::Ccw => Ordering::Less,
                Orientation::Cw => Ordering::Greater,
                Orientation::Collinear => status.color(a).cmp(&status.color(b)).then(a.cmp(&b)),
            }
        });
        self.ws.status.paste(&through);
        self.ws.region = through;
        self.ws.starts = starts;
    }

    /// For each colour, the position of its first edge that is not below v and of its
    /// first edge above v (the length of the status when there is none).
    fn boundaries(&self, v: Point) -> ([usize; 2], [usize; 2]) {
        let status = &self.ws.status;
        let len = status.len();
        let (mut not_below, mut above) = ([len; 2], [len; 2]);
        for c in 0..2 {
            if let Some((id, at)) = status.first_where(c, |id| self.class(id, v) != Class::Below) {
                not_below[c] = at;
                above[c] = if self.class(id, v) == Class::Above {
                    at
                } else {
                    status
                        .first_where(c, |id| self.class(id, v) == Class::Above)
                        .map_or(len, |(_, at)| at)
                };
            }
        }
        (not_below, above)
    }

    /// Given the first "high" position of each colour along a monotone split of the
    /// classes (not below, or above), the stretch from the first high edge of one
    /// colour to the last low edge of the other when they are listed in that order:
    /// `(start, end, colour of the high edges)`.
    fn inversion(&self, first_high: [usize; 2]) -> Option<(usize, usize, usize)> {
        // Only the colour whose first high edge comes first can have a low edge of the
        // other colour after it.
        let x = (first_high[1] < first_high[0]) as usize;
        let y = 1 - x;
        if first_high[x] >= first_high[y] {
            return None;
        }
        let last_low = self.ws.status.last_before(y, first_high[y])?;
        (last_low > first_high[x]).then_some((first_high[x], last_low + 1, x))
    }

    /// Rewrites positions `lo..hi` (edges of colour x that are high, edges of the other
    /// colour that are low, interleaved) as the low ones followed by the high ones,
    /// reporting every pair of a high edge listed before a low one.
    fn repair(&mut self, lo: usize, hi: usize, x: usize) {
        let mut region = std::mem::take(&mut self.ws.region);
        let mut lows = std::mem::take(&mut self.ws.scratch);
        region.clear();
        lows.clear();
        self.ws.status.cut(lo, hi, &mut region);
        // From the end: each high edge meets every low edge listed after it.
        for &id in region.iter().rev() {
            if self.ws.status.color(id) == x {
                for &l in lows.iter() {
                    self.report(id, l);
                }
            } else {
                lows.push(id);
            }
        }
        lows.reverse();
        lows.extend(region.iter().copied().filter(|&id| self.ws.status.color(id) == x));
        self.ws.status.paste(&lows);
        self.ws.region = region;
        self.ws.scratch = lows;
    }
}
