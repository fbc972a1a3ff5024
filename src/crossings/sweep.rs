//! [`Sweep`]: the default crossings algorithm. It sorts the vertices once, counts
//! exactly how much work Žalik's lists would do, and runs [`ListSweep`] when that
//! is small and [`TreeSweep`] otherwise.
//!
//! # The choice
//! [`ListSweep`] tests each inserted edge against every edge of the other polygon
//! pierced at that moment: W = Σ r candidates, r the other list's length at each
//! insertion. A candidate costs a couple of comparisons on contiguous memory, or a
//! segment test when its y-range meets the new edge's; [`TreeSweep`] costs
//! O(log(n + m)) treap steps and orientation tests per vertex and tests no pair in
//! vain. With k = n + m vertices and L = ⌈log₂ k⌉, the budget of the lists is
//! B = [`LIST_BUDGET`] · k · L units, one unit per candidate and
//! [`PAIR_COST`](super::lists::PAIR_COST) per segment test, which is about what the
//! tree costs (measured: 35 to 90 units per vertex and level).
//!
//! W depends only on the order of the events, so one pass over the sorted vertices
//! counts it exactly in O(k) before any pair is tested. When W > B
//! the tree runs at once (zigzags, needle combs, every family whose lists grow with
//! n). Otherwise the lists run, counting their units, and give up for the tree as
//! soon as they exceed B (candidates whose y-ranges all overlap, as in needle combs
//! of moderate size). Either way the total is O((k + c) log k) for c reported
//! points: the lists never do more than B = O(k log k) units, and the tree is
//! O((k + c) log k) on every input.
//!
//! # Complexity
//! O((n + m + c) log(n + m)) time on every input (c reported points; expected over
//! the tree's pseudo-random priorities), O(n + m) memory plus the output.
//!
//! # Degeneracies and precision
//! Both sweeps report exactly the points of [`Brute`](super::Brute) under the exact
//! kernel (they test pairs with the same function; see the [module docs](super)).

use super::lists::{self, ListSweep, ListWorkspace};
use super::tree::{self, TreeSweep, TreeWorkspace};
use super::{CrossingOptions, Crossings, edge_pair_points, sort_dedup};
use crate::kernel::{Kernel, Point};
use crate::polygon::SimplePolygon;
use std::cmp::Ordering;

/// The default sweep; see the [module docs](self).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Sweep;

/// The lists' budget in units per vertex and tree level (see the [module docs](self)).
pub const LIST_BUDGET: u64 = 50;

/// Reusable scratch memory for [`Sweep::crossings_in`].
#[derive(Clone, Debug, Default)]
pub struct SweepWorkspace {
    events: Vec<(Point, u32)>,
    lists: ListWorkspace,
    tree: TreeWorkspace,
}

impl Crossings for Sweep {
    const NAME: &'static str = "sweep";

    fn crossings_with_options<K: Kernel>(
        &self,
        k: K,
        p: &SimplePolygon,
        q: &SimplePolygon,
        options: CrossingOptions,
    ) -> Vec<Point> {
        let mut out = Vec::new();
        self.crossings_in_with_options(k, p, q, options, &mut SweepWorkspace::default(), &mut out);
        out
    }
}

impl Sweep {
    /// Like [`Crossings::crossings_with`], reusing `ws` and writing into `out`
    /// (cleared first).
    pub fn crossings_in<K: Kernel>(
        &self,
        k: K,
        p: &SimplePolygon,
        q: &SimplePolygon,
        ws: &mut SweepWorkspace,
        out: &mut Vec<Point>,
    ) {
        self.crossings_in_with_options(k, p, q, CrossingOptions::default(), ws, out);
    }

    /// Like [`Crossings::crossings_with_options`], reusing `ws` and writing into `out`
    /// (cleared first).
    pub fn crossings_in_with_options<K: Kernel>(
        &self,
        k: K,
        p: &SimplePolygon,
        q: &SimplePolygon,
        options: CrossingOptions,
        ws: &mut SweepWorkspace,
        out: &mut Vec<Point>,
    ) {
        out.clear();
        sorted_events(p, q, &mut ws.events);
        let input = Input {
            p,
            q,
            events: &ws.events,
        };
        let budget = budget(p, q);
        let listed = within_budget(input, budget)
            && lists::run(input, &mut ws.lists, budget, |a, b, c, d| {
                edge_pair_points(k, a, b, c, d, options, out)
            })
            .is_some();
        if !listed {
            out.clear();
            tree::run(k, input, options, &mut ws.tree, out);
        }
        sort_dedup(out);
    }

    /// Which sweep [`Sweep`] ends up running on this pair: the name of [`ListSweep`]
    /// or of [`TreeSweep`] (it runs the lists within their budget to find out).
    pub fn choice(p: &SimplePolygon, q: &SimplePolygon) -> &'static str {
        let mut events = Vec::new();
        sorted_events(p, q, &mut events);
        let input = Input {
            p,
            q,
            events: &events,
        };
        let budget = budget(p, q);
        let listed = within_budget(input, budget)
            && lists::run(input, &mut ListWorkspace::default(), budget, |_, _, _, _| {}).is_some();
        if listed { ListSweep::NAME } else { TreeSweep::NAME }
    }
}

/// Whether the lists' candidates fit in `budget`: at once when 2·n·m does (W never
/// exceeds it), else by counting them.
fn within_budget(input: Input<'_>, budget: u64) -> bool {
    let (n, m) = (input.p.len() as u64, input.q.len() as u64);
    2 * n * m <= budget || list_work(input) <= budget
}

/// B = [`LIST_BUDGET`] · k · ⌈log₂ k⌉ for k = n + m.
fn budget(p: &SimplePolygon, q: &SimplePolygon) -> u64 {
    let k = (p.len() + q.len()) as u64;
    let levels = (64 - k.leading_zeros()) as u64;
    LIST_BUDGET * k * levels
}

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

/// The number of candidates [`ListSweep`] checks on this input: Σ r over the
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
