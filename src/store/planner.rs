//! The query planner's cost model, strategies and counters. The rule itself is in the
//! module docs of [`store`](super); `Scene` applies it.

use crate::generate::{self, Family, Relation};
use crate::intersect::Algorithm;
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
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
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
        let mut ws = super::scene::QueryWorkspace::default();
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
                    std::hint::black_box(Algorithm::fastest_array().intersects_with(kernel, &a, &b));
                }
            }) / pairs.len() as f64;
            let t_sampled = time_per(reps, || {
                for (p, q) in &pairs {
                    std::hint::black_box(super::scene::sampled_test(kernel, p, q, &mut ws, &mut rng));
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
    /// Snapshots built (and kept).
    pub conversions: u64,
    /// Arrays built for one query and dropped (strategy `Convert`).
    pub throwaway_conversions: u64,
    /// Snapshots dropped by an edit.
    pub invalidations: u64,
}

/// Runs the fastest array algorithm with the scene's kernel.
pub(crate) fn array_test<K: Kernel>(kernel: K, p: &ConvexPolygon, q: &ConvexPolygon) -> bool {
    Algorithm::fastest_array().intersects_with(kernel, p, q)
}
