use super::events::{Input, list_work, sorted_events};
use super::lists::{self, ListSweep, ListWorkspace};
use super::tree::{self, TreeSweep, TreeWorkspace};
use super::{CrossingOptions, Crossings, edge_pair_points, sort_dedup};
use crate::kernel::{Kernel, Point};
use crate::polygon::SimplePolygon;

/// [`Sweep`]: the default crossings algorithm. It sorts the vertices once, counts
/// exactly how much work Žalik's lists would do, and runs [`ListSweep`] when that
/// is small and [`TreeSweep`] otherwise.
///
/// # The choice
/// [`ListSweep`] tests each inserted edge against every edge of the other polygon
/// pierced at that moment: W = Σ r candidates, r the other list's length at each
/// insertion. A candidate costs a couple of comparisons on contiguous memory, or a
/// segment test when its y-range meets the new edge's; [`TreeSweep`] costs
/// O(log(n + m)) treap steps and orientation tests per vertex and tests no pair in
/// vain. With k = n + m vertices and L = ⌈log₂ k⌉, the budget of the lists is
/// B = `LIST_BUDGET` · k · L units, one unit per candidate and
/// `PAIR_COST` per segment test, which is about what the
/// tree costs (docs/results.md, "Crossings").
///
/// W depends only on the order of the events, so one pass over the sorted vertices
/// counts it exactly in O(k) before any pair is tested. When W > B
/// the tree runs at once (zigzags, needle combs, every family whose lists grow with
/// n). Otherwise the lists run, counting their units, and give up for the tree as
/// soon as they exceed B (candidates whose y-ranges all overlap, as in needle combs
/// of moderate size). Either way the total is O((k + c) log k) for c reported
/// points: the lists never do more than B = O(k log k) units, and the tree is
/// O((k + c) log k) on every input.
///
/// # Complexity
/// O((n + m + c) log(n + m)) time on every input (c reported points; expected over
/// the tree's pseudo-random priorities), O(n + m) memory plus the output.
///
/// # Degeneracies and precision
/// Both sweeps report exactly the points of [`Brute`](super::Brute) under the exact
/// kernel (they test pairs with the same function; see the [module docs](super)).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Sweep;

/// The lists' budget in units per vertex and tree level (see [`Sweep`]).
pub(crate) const LIST_BUDGET: u64 = 50;

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
