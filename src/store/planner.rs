//! The query planner's cost model, strategies and counters. The rule itself is in the
//! module docs of [`store`](super); `Scene` applies it. This file knows the routes
//! (`route.rs`, which it times) and nothing of the scene.

use super::route::{QueryWorkspace, array_test, sampled_test};
use crate::generate::{self, Family, Relation};
use crate::kernel::Kernel;
use crate::polygon::LinkedPolygon;
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
    /// Decide per query from sizes, the crossover and the queries since the last edit.
    #[default]
    Planner,
}

impl Strategy {
    pub const ALL: [Strategy; 4] = [
        Strategy::Sampled,
        Strategy::Convert,
        Strategy::Cached,
        Strategy::Planner,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Strategy::Sampled => "sampled",
            Strategy::Convert => "convert",
            Strategy::Cached => "cached",
            Strategy::Planner => "planner",
        }
    }
}

/// Estimated costs, in nanoseconds, that drive the planner.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct CostModel {
    /// Walking a linked polygon into an array, per vertex.
    pub convert_ns_per_vertex: f64,
    /// One sampled query, per √n of the larger polygon.
    pub sampled_ns_per_sqrt_n: f64,
    /// The size below which converting both polygons plus an array test beats one
    /// sampled query (measured on disjoint pairs). Reported for users choosing a fixed
    /// strategy; the planner's rule needs only the two cost constants, which imply it.
    pub crossover: usize,
}

impl Default for CostModel {
    /// Measured with `polysect calibrate` on the project's 2-core reference machine
    /// (two runs: 126–137 ns per vertex, 694–702 ns·√n, crossover 4096; docs/store.md).
    fn default() -> Self {
        CostModel {
            convert_ns_per_vertex: 130.0,
            sampled_ns_per_sqrt_n: 700.0,
            crossover: 4096,
        }
    }
}

impl CostModel {
    /// Estimated cost of converting an n-vertex polygon.
    pub fn convert_cost(&self, n: usize) -> f64 {
        self.convert_ns_per_vertex * n as f64
    }

    /// Estimated cost of one sampled query involving an n-vertex polygon.
    pub fn sampled_cost(&self, n: usize) -> f64 {
        self.sampled_ns_per_sqrt_n * (n as f64).sqrt()
    }

    /// Estimated cost of answering a query on polygons of `n` and `m` vertices without
    /// both snapshots, less the array test that would replace it: what snapshots of both
    /// save that query.
    pub fn saving(&self, n: usize, m: usize) -> f64 {
        self.sampled_cost(n.max(m))
    }

    /// Measures the model on this machine on generated polygons in shuffled arenas:
    /// conversion time per vertex at the largest size (2^18, where the walk misses the
    /// caches, as it does for the large polygons the rule is about), sampled time per √n
    /// (median over 2^4..2^18), and the crossover as the smallest size at which one sampled
    /// query is cheaper than converting both polygons plus an array test. Takes a few
    /// seconds.
    pub fn calibrate<K: Kernel>(kernel: K) -> CostModel {
        let mut rng = SmallRng::seed_from_u64(0xca1b);
        let sizes: Vec<usize> = (4..=18).step_by(2).map(|e| 1usize << e).collect();
        let mut convert_per_vertex = Vec::new();
        let mut sampled_per_sqrt = Vec::new();
        let mut crossover = None;
        let mut ws = QueryWorkspace::default();
        for &n in &sizes {
            let pairs: Vec<(LinkedPolygon, LinkedPolygon)> = (0..8)
                .map(|_| {
                    let (p, q) = generate::pair(Family::NonUniform, n, Relation::Disjoint, &mut rng);
                    (
                        LinkedPolygon::from_convex_shuffled(&p, &mut rng),
                        LinkedPolygon::from_convex_shuffled(&q, &mut rng),
                    )
                })
                .collect();
            let reps = ((1 << 18) / n.max(64)).max(2);
            let t_convert = time_per(reps, || {
                for (p, q) in &pairs {
                    let (a, b) = (p.to_convex(), q.to_convex());
                    std::hint::black_box(array_test(kernel, &a, &b));
                }
            }) / pairs.len() as f64;
            let t_sampled = time_per(reps, || {
                for (p, q) in &pairs {
                    std::hint::black_box(sampled_test(kernel, p, q, &mut ws, &mut rng));
                }
            }) / pairs.len() as f64;
            convert_per_vertex.push(t_convert / (2 * n) as f64);
            sampled_per_sqrt.push(t_sampled / (n as f64).sqrt());
            if crossover.is_none() && t_sampled < t_convert {
                crossover = Some(n);
            }
        }
        CostModel {
            convert_ns_per_vertex: *convert_per_vertex.last().expect("sizes are measured"),
            sampled_ns_per_sqrt_n: median(&mut sampled_per_sqrt),
            crossover: crossover.unwrap_or(usize::MAX),
        }
    }
}

fn time_per(reps: usize, mut f: impl FnMut()) -> f64 {
    f(); // warm the caches
    let start = Instant::now();
    for _ in 0..reps {
        f();
    }
    start.elapsed().as_nanos() as f64 / reps as f64
}

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// A polygon's planner account since its last edit: the ski-rental rent and the history
/// of queries between edits.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Account {
    /// What the missing snapshot of this polygon has cost the queries since its last
    /// edit (the saving a snapshot would have brought them), in nanoseconds.
    rent_ns: f64,
    /// Queries (past the bounding boxes) since the last edit.
    queries_since_edit: u32,
    /// Moving average of the number of queries between two edits (infinite until the
    /// first edit: no history, plain ski rental).
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
    /// An edit: the snapshot is gone, the rent starts again, the history learns how many
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

    /// A query answered without this polygon's snapshot: rent of `saving_ns`.
    pub(crate) fn pay(&mut self, saving_ns: f64) {
        self.rent_ns += saving_ns;
    }

    /// Whether to convert now. `known_ns` is what a snapshot of this polygon saves the
    /// `known` queries being planned now (one query, or a batch's), `cost_ns` the
    /// conversion.
    ///
    /// Ski rental, with the queries at hand counted: buy at once when they alone pay for
    /// it; otherwise buy once the rent since the last edit plus their saving reaches the
    /// price, unless the queries expected before the next edit (the average between
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
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct PlannerStats {
    /// Queries answered `false` by the bounding boxes alone.
    pub box_rejects: u64,
    /// Queries answered by an array test on two valid snapshots.
    pub array_tests: u64,
    /// Queries answered by the sampled test on linked polygons.
    pub sampled_tests: u64,
    /// Snapshots built (and kept).
    pub conversions: u64,
    /// Arrays built for one query and dropped (strategy `Convert`).
    pub throwaway_conversions: u64,
    /// Snapshots dropped by an edit.
    pub invalidations: u64,
}
