//! The query planner's cost model, strategies and counters. The rule itself is in the
//! module docs of [`store`](super); `Scene` applies it. This file knows the routes
//! (`route.rs`, which it times) and nothing of the scene.

use super::route::{QueryWorkspace, barba_test, linear_array_test, linear_test, sampled_test};
use crate::generate::{self, Family, Relation};
use crate::kernel::Kernel;
use crate::polygon::{ConvexPolygon, LinkedPolygon};
use rand::SeedableRng;
use rand::rngs::SmallRng;
use std::time::Instant;

/// How a scene answers `intersects` for polygons without valid snapshots.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Strategy {
    /// Always the sampled sublinear test on the linked polygons (snapshots are still
    /// used when both happen to be valid).
    Sampled,
    /// Convert both polygons to arrays for every query and throw the arrays away.
    Convert,
    /// Convert on first use and keep the snapshot until the next edit.
    Cached,
    /// Decide per query from sizes, the measured costs of each route and the queries
    /// since the last edit (the rule in the [module docs](super)).
    #[default]
    Planner,
}

impl Strategy {
    /// Every strategy, for comparisons.
    pub const ALL: [Strategy; 4] = [
        Strategy::Sampled,
        Strategy::Convert,
        Strategy::Cached,
        Strategy::Planner,
    ];

    /// The strategy's name, as the CLI and the benches print it.
    pub fn name(self) -> &'static str {
        match self {
            Strategy::Sampled => "sampled",
            Strategy::Convert => "convert",
            Strategy::Cached => "cached",
            Strategy::Planner => "planner",
        }
    }
}

/// The smallest size in the cost tables is 2^`MIN_LOG2` vertices.
const MIN_LOG2: u32 = 2;
/// The tables hold sizes 2^2 ..= 2^18; larger sizes are extrapolated.
pub const COST_SIZES: usize = 17;

/// Estimated costs, in nanoseconds, that drive the planner: one table per route,
/// entry i for polygons of 2^(i + 2) vertices (2^2 ..= 2^18), measured by
/// [`CostModel::calibrate`]. Between entries costs are interpolated linearly in the
/// size; beyond the largest, extrapolated along the last segment's power law. Walks
/// along the links (conversion, the linear test) are measured on arenas in boundary
/// order and on shuffled arenas, and a polygon is priced between the two by its
/// arena's disorder (inserts and removals since it was built in order).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct CostModel {
    /// Converting one linked polygon of that size to an array, shuffled arena.
    pub(crate) convert_ns: [f64; COST_SIZES],
    /// The same, arena in boundary order.
    pub(crate) convert_ordered_ns: [f64; COST_SIZES],
    /// The sampled test (Chazelle–Liu–Magen) on two linked polygons of that size
    /// (shuffled arenas; its reads are random anyway).
    pub(crate) sampled_ns: [f64; COST_SIZES],
    /// The linear test walking two linked polygons of that size
    /// ([`LinearLinked`](crate::intersect::LinearLinked)), shuffled arenas.
    pub(crate) linear_ns: [f64; COST_SIZES],
    /// The same, arenas in boundary order.
    pub(crate) linear_ordered_ns: [f64; COST_SIZES],
    /// The array test on two snapshots of that size: [`Linear`](crate::intersect::Linear)
    /// up to `array_linear_max` vertices, Barba–Langerman above.
    pub(crate) array_ns: [f64; COST_SIZES],
    /// The largest size at which the linear array test beats Barba–Langerman; a pair
    /// of snapshots with at most twice this many vertices in all is tested linearly.
    pub(crate) array_linear_max: usize,
    /// Summary, at 2^18 vertices: conversion per vertex (shuffled arena).
    pub(crate) convert_ns_per_vertex: f64,
    /// Summary: the median over the sizes of the sampled test's time per √n.
    pub(crate) sampled_ns_per_sqrt_n: f64,
    /// The largest size at which two fresh polygons (arenas in boundary order) are
    /// converted on their first query (converting both costs less than what snapshots
    /// save that query); 0 if none.
    pub(crate) crossover: usize,
}

/// What the cost model needs to know of a linked polygon: its size and how far its
/// arena is from boundary order (0 in order, 1 shuffled).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct ArenaProfile {
    /// Number of vertices.
    pub vertices: usize,
    /// How far the arena is from boundary order: 0 in order, 1 shuffled.
    pub disorder: f64,
}

impl ArenaProfile {
    /// The polygon's size and arena disorder. O(1).
    pub(crate) fn of(polygon: &LinkedPolygon) -> ArenaProfile {
        ArenaProfile {
            vertices: polygon.len(),
            disorder: polygon.arena_disorder(),
        }
    }

    /// An arena in boundary order.
    pub(crate) fn ordered(vertices: usize) -> ArenaProfile {
        ArenaProfile {
            vertices,
            disorder: 0.0,
        }
    }
}

impl Default for CostModel {
    /// `polysect calibrate` on the project's 2-core reference machine while other jobs
    /// ran: the least of five runs entry by entry, made non-decreasing (docs/store.md).
    fn default() -> Self {
        CostModel::from_tables(DEFAULT_TABLES)
    }
}

type Table = [f64; COST_SIZES];

/// The tables of the default model, in the order of [`CostModel::from_tables`].
const DEFAULT_TABLES: [Table; 6] = [
    [
        18.9, 24.1, 39.9, 72.4, 152.9, 324.5, 1150.2, 3125.5, 42785.0, 86472.0, 2.398e+05, 5.335e+05,
        1.077e+06, 2.900e+06, 7.742e+06, 1.849e+07, 4.807e+07,
    ],
    [
        14.8, 15.4, 17.7, 20.5, 27.7, 45.7, 187.7, 560.9, 1146.6, 2291.1, 4505.9, 8876.1, 17769.1, 35755.1,
        1.014e+05, 2.115e+05, 4.699e+05,
    ],
    [
        529.5, 643.7, 690.3, 781.4, 985.9, 1240.9, 1574.4, 1955.7, 2932.2, 3170.5, 4815.1, 4875.4, 6567.2,
        7744.0, 10045.0, 13745.5, 24251.0,
    ],
    [
        42.5, 87.1, 204.0, 551.2, 1136.0, 2277.5, 4771.4, 10551.2, 70315.4, 87000.8, 2.719e+05, 6.532e+05,
        1.221e+06, 3.127e+06, 7.290e+06, 2.624e+07, 7.496e+07,
    ],
    [
        34.7, 74.6, 173.6, 495.0, 1030.5, 2035.2, 3967.8, 8144.6, 17299.0, 33179.0, 63960.6, 1.312e+05,
        3.402e+05, 7.798e+05, 1.042e+06, 6.753e+06, 1.151e+07,
    ],
    [
        23.7, 57.5, 81.2, 108.7, 142.0, 156.2, 177.7, 213.3, 213.3, 217.1, 217.1, 217.1, 217.1, 217.1, 217.1,
        217.1, 217.1,
    ],
];

/// The size of table entry `i`.
fn size_of(i: usize) -> usize {
    1 << (i as u32 + MIN_LOG2)
}

/// Looks `n` up in `table`: linear interpolation in n between the entries of the
/// neighbouring powers of two (no logarithm on the planner's path), the first entry
/// below the smallest size, and beyond the largest the last segment's power law.
fn lookup(table: &Table, n: usize) -> f64 {
    let n = n.max(1);
    let k = n.ilog2();
    if k < MIN_LOG2 {
        return table[0];
    }
    let i = (k - MIN_LOG2) as usize;
    if i + 1 < COST_SIZES {
        let f = (n - (1 << k)) as f64 / (1u64 << k) as f64;
        return table[i] + f * (table[i + 1] - table[i]);
    }
    let (a, b) = (table[COST_SIZES - 2].max(1e-3), table[COST_SIZES - 1].max(1e-3));
    let top = size_of(COST_SIZES - 1) as f64;
    b * (n as f64 / top).powf((b / a).log2())
}

impl CostModel {
    /// The polygon sizes (vertices) the tables are indexed by: entry i of every table is
    /// for `sizes()[i]` = 2^(i + 2) vertices.
    pub fn sizes() -> [usize; COST_SIZES] {
        std::array::from_fn(size_of)
    }

    /// What the model makes the planner do, in one or two plain sentences (what
    /// `polysect calibrate` prints on standard error beside the JSON).
    pub fn summary(&self) -> String {
        let first = if self.crossover == 0 {
            "No polygon is converted to an array on its first query".to_string()
        } else {
            format!(
                "Polygons of at most {} vertices are converted to arrays on their first query",
                self.crossover
            )
        };
        format!(
            "{first}; larger ones once their sampled queries since the last edit have cost as \
             much as converting them ({:.1} ns per vertex to convert, {:.1} ns times the square \
             root of the size per sampled query).",
            self.convert_ns_per_vertex, self.sampled_ns_per_sqrt_n
        )
    }

    /// The model's tables, in the order [`from_tables`](Self::from_tables) takes them:
    /// a model built from them prices every query as this one does, except that the
    /// linear array test's range (`array_linear_max`, measured by calibration) is 0.
    pub fn tables(&self) -> [[f64; COST_SIZES]; 6] {
        [
            self.convert_ns,
            self.convert_ordered_ns,
            self.sampled_ns,
            self.linear_ns,
            self.linear_ordered_ns,
            self.array_ns,
        ]
    }

    /// A model from its tables, in this order: conversion (shuffled, ordered), sampled,
    /// linear walk (shuffled, ordered), array test; `array_linear_max` is 0 (Barba–Langerman
    /// at every size), the summaries and the crossover are derived.
    pub fn from_tables(tables: [[f64; COST_SIZES]; 6]) -> CostModel {
        let [
            convert_ns,
            convert_ordered_ns,
            sampled_ns,
            linear_ns,
            linear_ordered_ns,
            array_ns,
        ] = tables;
        let mut model = CostModel {
            convert_ns,
            convert_ordered_ns,
            sampled_ns,
            linear_ns,
            linear_ordered_ns,
            array_ns,
            array_linear_max: 0,
            convert_ns_per_vertex: 0.0,
            sampled_ns_per_sqrt_n: 0.0,
            crossover: 0,
        };
        model.derive_summaries();
        model
    }

    fn derive_summaries(&mut self) {
        let last = COST_SIZES - 1;
        self.convert_ns_per_vertex = self.convert_ns[last] / size_of(last) as f64;
        let mut per_sqrt: Vec<f64> = (0..COST_SIZES)
            .map(|i| self.sampled_ns[i] / (size_of(i) as f64).sqrt())
            .collect();
        self.sampled_ns_per_sqrt_n = median(&mut per_sqrt);
        self.crossover = (0..COST_SIZES)
            .map(size_of)
            .take_while(|&n| {
                let a = ArenaProfile::ordered(n);
                2.0 * self.convert_cost(a) <= self.saving(a, a)
            })
            .last()
            .unwrap_or(0);
    }

    /// Between the ordered and the shuffled table by the arena's disorder.
    fn walk(ordered: &Table, shuffled: &Table, a: ArenaProfile) -> f64 {
        let (o, s) = (lookup(ordered, a.vertices), lookup(shuffled, a.vertices));
        o + a.disorder.clamp(0.0, 1.0) * (s - o).max(0.0)
    }

    /// Estimated cost of converting the polygon.
    pub(crate) fn convert_cost(&self, a: ArenaProfile) -> f64 {
        Self::walk(&self.convert_ordered_ns, &self.convert_ns, a)
    }

    /// Estimated cost of the sampled test on the two polygons (governed by the larger).
    pub(crate) fn sampled_cost(&self, a: ArenaProfile, b: ArenaProfile) -> f64 {
        lookup(&self.sampled_ns, a.vertices.max(b.vertices))
    }

    /// Estimated cost of the linear test walking the two polygons.
    pub(crate) fn linear_cost(&self, a: ArenaProfile, b: ArenaProfile) -> f64 {
        0.5 * (Self::walk(&self.linear_ordered_ns, &self.linear_ns, a)
            + Self::walk(&self.linear_ordered_ns, &self.linear_ns, b))
    }

    /// Whether a pair of snapshots of `n` and `m` vertices is tested linearly rather
    /// than by Barba–Langerman.
    pub(crate) fn array_is_linear(&self, n: usize, m: usize) -> bool {
        n + m <= 2 * self.array_linear_max
    }

    /// Estimated cost of the array test on snapshots of `n` and `m` vertices.
    pub(crate) fn array_cost(&self, n: usize, m: usize) -> f64 {
        if self.array_is_linear(n, m) {
            lookup(&self.array_ns, (n + m) / 2)
        } else {
            lookup(&self.array_ns, n.max(m))
        }
    }

    /// Whether the linear walk is the cheaper test on the two linked polygons
    /// (otherwise the sampled test).
    pub(crate) fn prefers_linear(&self, a: ArenaProfile, b: ArenaProfile) -> bool {
        self.linear_cost(a, b) <= self.sampled_cost(a, b)
    }

    /// Estimated cost of the cheaper test on the two linked polygons.
    pub(crate) fn linked_cost(&self, a: ArenaProfile, b: ArenaProfile) -> f64 {
        self.linear_cost(a, b).min(self.sampled_cost(a, b))
    }

    /// What snapshots of both polygons save one query between them: the cheaper linked
    /// test less the array test (never negative).
    pub(crate) fn saving(&self, a: ArenaProfile, b: ArenaProfile) -> f64 {
        (self.linked_cost(a, b) - self.array_cost(a.vertices, b.vertices)).max(0.0)
    }

    /// Measures the model on this machine, for sizes 2^2 ..= 2^18, on generated polygons
    /// linked in boundary order and in shuffled arenas (as after a long edit history),
    /// half of the pairs intersecting and half disjoint. At each size the polygons are
    /// drawn from a pool of about 2^18 vertices in all, so that large sizes are measured
    /// out of cache, as in a scene. Two passes over all sizes, seconds apart, each figure
    /// the best of five short rounds (large sizes: one cold run), and the better pass kept
    /// entry by entry, so a burst of other work on the machine spoils at most one pass;
    /// then each table is smoothed (median of three neighbours) and made non-decreasing
    /// in the size. Takes about ten seconds.
    ///
    /// # Panics
    /// On `wasm32-unknown-unknown`, which has no clock (`std::time::Instant`).
    pub fn calibrate<K: Kernel>(kernel: K) -> CostModel {
        let mut rng = SmallRng::seed_from_u64(0xca1b);
        let mut tables = [[f64::INFINITY; COST_SIZES]; 7];
        let mut ws = QueryWorkspace::default();
        for _pass in 0..2 {
            for i in 0..COST_SIZES {
                let row = measure_size(kernel, size_of(i), &mut rng, &mut ws);
                for (table, value) in tables.iter_mut().zip(row) {
                    table[i] = table[i].min(value);
                }
            }
        }
        for table in &mut tables {
            monotone(table);
        }
        let [
            convert,
            convert_ordered,
            sampled,
            linear,
            linear_ordered,
            barba,
            linear_array,
        ] = tables;
        let mut model =
            CostModel::from_tables([convert, convert_ordered, sampled, linear, linear_ordered, barba]);
        model.set_array_tables(&barba, &linear_array);
        model
    }

    /// The array table is the cheaper of the two array tests at each size, and
    /// `array_linear_max` the last size of the initial run where the linear one wins.
    fn set_array_tables(&mut self, barba: &Table, linear: &Table) {
        self.array_linear_max = (0..COST_SIZES)
            .take_while(|&i| linear[i] < barba[i])
            .last()
            .map_or(0, size_of);
        for i in 0..COST_SIZES {
            self.array_ns[i] = if size_of(i) <= self.array_linear_max {
                linear[i]
            } else {
                barba[i]
            };
        }
        self.derive_summaries();
    }
}

/// Times the routes at size n: conversion (per polygon; shuffled, then ordered arenas),
/// sampled, linear on linked polygons (shuffled, ordered), Barba–Langerman and linear on
/// arrays (per pair).
fn measure_size<K: Kernel>(kernel: K, n: usize, rng: &mut SmallRng, ws: &mut QueryWorkspace) -> [f64; 7] {
    let count = ((1usize << 17) / n).clamp(2, 128);
    let arrays: Vec<(ConvexPolygon, ConvexPolygon)> = (0..count)
        .map(|j| {
            let relation = if j % 2 == 0 {
                Relation::Disjoint
            } else {
                Relation::Intersecting
            };
            generate::pair(Family::NonUniform, n, relation, rng)
        })
        .collect();
    let shuffled: Vec<(LinkedPolygon, LinkedPolygon)> = arrays
        .iter()
        .map(|(p, q)| {
            (
                LinkedPolygon::from_convex_shuffled(p, rng),
                LinkedPolygon::from_convex_shuffled(q, rng),
            )
        })
        .collect();
    let ordered: Vec<(LinkedPolygon, LinkedPolygon)> = arrays
        .iter()
        .map(|(p, q)| (LinkedPolygon::from_convex(p), LinkedPolygon::from_convex(q)))
        .collect();
    let per_pair = |t: f64| t / count as f64;
    let convert = |pairs: &[(LinkedPolygon, LinkedPolygon)]| {
        per_pair(best_time(|| {
            for (p, q) in pairs {
                std::hint::black_box(p.to_convex());
                std::hint::black_box(q.to_convex());
            }
        })) / 2.0
    };
    let linear = |pairs: &[(LinkedPolygon, LinkedPolygon)]| {
        per_pair(best_time(|| {
            for (p, q) in pairs {
                std::hint::black_box(linear_test(kernel, p, q));
            }
        }))
    };
    let sampled = per_pair(best_time(|| {
        for (p, q) in &shuffled {
            std::hint::black_box(sampled_test(kernel, p, q, ws, rng));
        }
    }));
    let barba = per_pair(best_time(|| {
        for (p, q) in &arrays {
            std::hint::black_box(barba_test(kernel, p, q));
        }
    }));
    let linear_array = per_pair(best_time(|| {
        for (p, q) in &arrays {
            std::hint::black_box(linear_array_test(kernel, p, q));
        }
    }));
    [
        convert(&shuffled),
        convert(&ordered),
        sampled,
        linear(&shuffled),
        linear(&ordered),
        barba,
        linear_array,
    ]
}

/// Makes a measured table non-decreasing in the size, as every route's cost is, without
/// letting one disturbed measurement move the others: each inner entry becomes the
/// median of itself and its two neighbours (an isolated spike or dip is dropped), then
/// each entry is raised to every earlier one.
fn monotone(table: &mut Table) {
    let measured = *table;
    for i in 1..COST_SIZES - 1 {
        let mut three = [measured[i - 1], measured[i], measured[i + 1]];
        three.sort_by(f64::total_cmp);
        table[i] = three[1];
    }
    for i in 1..COST_SIZES {
        table[i] = table[i].max(table[i - 1]);
    }
}

/// Times `f` in nanoseconds: once (which also warms the caches); if that took under
/// 5 ms, five more rounds of repetitions filling about 0.3 ms each, and the
/// best per-repetition time. Large sizes are thus measured once, cold, as a scene meets
/// them, and calibration stays within a few seconds.
fn best_time(mut f: impl FnMut()) -> f64 {
    let start = Instant::now();
    f();
    let once = start.elapsed().as_nanos().max(1) as f64;
    if once >= 5e6 {
        return once;
    }
    let reps = ((3e5 / once) as usize).clamp(1, 1000);
    (0..5)
        .map(|_| {
            let start = Instant::now();
            for _ in 0..reps {
                f();
            }
            start.elapsed().as_nanos() as f64 / reps as f64
        })
        .fold(f64::INFINITY, f64::min)
}

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// A polygon's planner account since its last edit: what answering without a snapshot
/// has cost so far, and the history of queries between edits.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Account {
    /// What the missing snapshot of this polygon has cost the queries since its last
    /// edit (the saving a snapshot would have brought them), in nanoseconds.
    rent_ns: f64,
    /// Queries (past the bounding boxes) since the last edit.
    queries_since_edit: u32,
    /// Moving average of the number of queries between two edits (infinite until the
    /// first edit: no history, convert once the cost so far reaches the conversion's).
    queries_per_edit: f64,
}

impl Default for Account {
    fn default() -> Self {
        Account {
            rent_ns: 0.0,
            queries_since_edit: 0,
            queries_per_edit: f64::INFINITY,
        }
    }
}

impl Account {
    /// An edit: the snapshot is gone, the cost so far starts again at 0, the history learns how many
    /// queries came between the last two edits.
    pub(crate) fn edited(&mut self) {
        self.rent_ns = 0.0;
        let q = self.queries_since_edit as f64;
        self.queries_per_edit = if self.queries_per_edit.is_finite() {
            0.5 * self.queries_per_edit + 0.5 * q
        } else {
            q
        };
        self.queries_since_edit = 0;
    }

    /// A query past the bounding boxes.
    pub(crate) fn queried(&mut self) {
        self.queries_since_edit = self.queries_since_edit.saturating_add(1);
    }

    /// A query answered without this polygon's snapshot, which cost it `saving_ns` more.
    pub(crate) fn pay(&mut self, saving_ns: f64) {
        self.rent_ns += saving_ns;
    }

    /// Whether to convert now. `known_ns` is what a snapshot of this polygon saves the
    /// `known` queries being planned now (one query, or a batch's), `cost_ns` the
    /// conversion.
    ///
    /// Convert at once when the queries at hand alone pay for the conversion; otherwise
    /// convert once the extra cost since the last edit plus their saving reaches the
    /// conversion's cost, unless the queries expected before the next edit (the average between
    /// edits so far, less those already seen; as many again as already seen once past
    /// the average) would not pay for it.
    pub(crate) fn should_convert(&self, cost_ns: f64, known_ns: f64, known: u32) -> bool {
        if known_ns >= cost_ns {
            return true;
        }
        if self.rent_ns + known_ns < cost_ns {
            return false;
        }
        let seen = self.queries_since_edit as f64;
        let expected_more = if self.queries_per_edit > seen {
            self.queries_per_edit - seen
        } else {
            seen
        };
        known_ns + expected_more * (known_ns / known.max(1) as f64) >= cost_ns
    }
}

/// What the planner did, for the demo table and the tests.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PlannerStats {
    /// Queries answered `false` by the bounding boxes alone.
    pub box_rejects: u64,
    /// Queries answered by an array test on two valid snapshots.
    pub array_tests: u64,
    /// Queries answered by the sampled test on linked polygons.
    pub sampled_tests: u64,
    /// Queries answered by the linear test walking both linked polygons.
    pub linear_tests: u64,
    /// Snapshots built (and kept).
    pub conversions: u64,
    /// Arrays built for one query and dropped (strategy `Convert`).
    pub throwaway_conversions: u64,
    /// Snapshots dropped by an edit.
    pub invalidations: u64,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_label_the_tables_and_the_summary_reads_plainly() {
        let sizes = CostModel::sizes();
        assert_eq!((sizes[0], sizes[COST_SIZES - 1]), (4, 1 << 18));
        assert!(sizes.windows(2).all(|w| w[1] == 2 * w[0]));
        let mut model = CostModel {
            crossover: 64,
            ..CostModel::default()
        };
        let text = model.summary();
        assert!(
            text.starts_with("Polygons of at most 64 vertices are converted"),
            "{text}"
        );
        model.crossover = 0;
        let text = model.summary();
        assert!(text.starts_with("No polygon is converted"), "{text}");
        assert!(!text.contains("at most 0"), "{text}");
    }
}
