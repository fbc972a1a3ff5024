//! Mixed edit/query workloads on a scene: what the demo runs, the benchmark times and
//! the tests replay. A workload is a seeded stream; the stream of operations depends
//! only on the seed and the polygons' states, never on the strategy, so every strategy
//! sees the same operations.

use super::{PolygonId, Scene};
use crate::generate::{self, Family, Relation};
use crate::intersect::{ArrayIntersection, Linear};
use crate::kernel::{Kernel, Point};
use crate::polygon::LinkedPolygon;
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use std::time::{Duration, Instant};

/// A workload: how many operations, which fraction are edits, and the seed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WorkloadSpec {
    pub name: &'static str,
    pub steps: usize,
    pub edit_fraction: f64,
    pub seed: u64,
}

impl WorkloadSpec {
    /// The three standard mixes: edit-heavy (70% edits), balanced (30%), query-heavy (3%).
    pub fn standard(steps: usize, seed: u64) -> [WorkloadSpec; 3] {
        [
            WorkloadSpec {
                name: "edit-heavy",
                steps,
                edit_fraction: 0.7,
                seed,
            },
            WorkloadSpec {
                name: "balanced",
                steps,
                edit_fraction: 0.3,
                seed,
            },
            WorkloadSpec {
                name: "query-heavy",
                steps,
                edit_fraction: 0.03,
                seed,
            },
        ]
    }
}

/// What a workload run did and how long its queries took.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct WorkloadReport {
    pub queries: u64,
    pub hits: u64,
    pub edits: u64,
    pub refused_edits: u64,
    /// Time spent inside `Scene::intersects` (edits and verification excluded).
    pub query_time: Duration,
    /// Time spent inside the edit calls.
    pub edit_time: Duration,
    /// Answers checked against the exact reference, and how many differed.
    pub checked: u64,
    pub mismatches: u64,
}

impl WorkloadReport {
    pub fn queries_per_second(&self) -> f64 {
        self.queries as f64 / self.query_time.as_secs_f64().max(1e-12)
    }
}

/// A scene of `count` polygons, sizes log-uniform in 2^3..=2^max_log2, scattered over a
/// square of side `spread` so that some overlap. Deterministic in `seed`.
pub fn scattered_scene<K: Kernel>(
    kernel: K,
    count: usize,
    max_log2: u32,
    spread: f64,
    seed: u64,
) -> Scene<K> {
    let mut rng = SmallRng::seed_from_u64(seed);
    let mut scene = Scene::with_kernel(kernel);
    for _ in 0..count {
        let n = 1usize << rng.random_range(3..=max_log2.max(3));
        let (p, _) = generate::pair(Family::NonUniform, n, Relation::Any, &mut rng);
        let (dx, dy) = (
            rng.random_range(-spread..spread) / 2.0,
            rng.random_range(-spread..spread) / 2.0,
        );
        let moved = p.map(|v| Point::new(v.x + dx, v.y + dy)).unwrap_or(p);
        scene.insert(LinkedPolygon::from_convex_shuffled(&moved, &mut rng));
    }
    scene
}

/// Runs the workload on `scene`. With `verify`, every answer is compared with
/// [`Linear`] on the exact kernel (outside the timed part). `tick` is called after every
/// operation (for progress bars).
///
/// # Panics
/// On `wasm32-unknown-unknown`, which has no clock (`std::time::Instant`).
pub fn run<K: Kernel>(
    scene: &mut Scene<K>,
    spec: &WorkloadSpec,
    verify: bool,
    mut tick: impl FnMut(),
) -> WorkloadReport {
    let mut rng = SmallRng::seed_from_u64(spec.seed);
    let ids: Vec<PolygonId> = scene.ids().collect();
    let mut r = WorkloadReport::default();
    if ids.is_empty() {
        return r;
    }
    for _ in 0..spec.steps {
        let a = ids[rng.random_range(0..ids.len())];
        if rng.random_bool(spec.edit_fraction) {
            let start = Instant::now();
            let ok = random_edit(scene, a, &mut rng);
            r.edit_time += start.elapsed();
            r.edits += 1;
            if !ok {
                r.refused_edits += 1;
            }
        } else {
            let b = ids[rng.random_range(0..ids.len())];
            let start = Instant::now();
            let answer = scene.intersects(a, b).expect("workload ids stay live");
            r.query_time += start.elapsed();
            r.queries += 1;
            r.hits += answer as u64;
            if verify {
                let p = scene.polygon(a).expect("live").to_convex();
                let q = scene.polygon(b).expect("live").to_convex();
                r.checked += 1;
                if Linear.intersects(&p, &q) != answer {
                    r.mismatches += 1;
                }
            }
        }
        tick();
    }
    r
}

/// A random local edit, usually valid (a refused edit changes nothing): a vertex
/// scaled about the polygon's start vertex by up to ±2%, a point pushed just outside
/// an edge, or a removal (kept above 8 vertices). O(1).
fn random_edit<K: Kernel>(scene: &mut Scene<K>, id: PolygonId, rng: &mut SmallRng) -> bool {
    let Ok(poly) = scene.polygon(id) else { return false };
    let v = poly.random_vertex(rng);
    let (Ok(a), Ok(next)) = (poly.point(v), poly.next(v)) else {
        return false;
    };
    let Ok(b) = poly.point(next) else { return false };
    let Ok(c) = poly.point(poly.first()) else {
        return false;
    };
    let Ok(d) = poly.point(poly.prev(v).unwrap_or(v)) else {
        return false;
    };
    // An interior reference point: the midpoint of two vertices that are not neighbours
    // of each other is inside; the centre of the triangle (c, a, d) is a cheap stand-in.
    let (cx, cy) = ((a.x + c.x + d.x) / 3.0, (a.y + c.y + d.y) / 3.0);
    let len = poly.len();
    match rng.random_range(0..3) {
        0 => {
            let f = 1.0 + rng.random_range(-0.02..0.02);
            scene
                .move_vertex(id, v, Point::new(cx + (a.x - cx) * f, cy + (a.y - cy) * f))
                .is_ok()
        }
        1 => {
            let (mx, my) = ((a.x + b.x) / 2.0, (a.y + b.y) / 2.0);
            let f = 1.0 + rng.random_range(0.0..0.01);
            scene
                .insert_vertex(id, v, Point::new(cx + (mx - cx) * f, cy + (my - cy) * f))
                .is_ok()
        }
        _ if len > 8 => scene.remove_vertex(id, v).is_ok(),
        _ => false,
    }
}
