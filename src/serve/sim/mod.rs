//! The simulation behind the live page: convex polygons moving in a box, held in a real
//! [`Scene`], turning, bouncing off the walls and off each other.
//!
//! # One frame
//! 1. **Update**: each body's angle and position advance by its angular velocity and
//!    velocity times the speed, and [`Scene::set_pose`] places its shape there
//!    absolutely (the shape stays in its own frame, so nothing drifts; O(log n) per
//!    polygon when the store can prove the rounded image convex, else O(n)); a body whose
//!    box would leave the box through a wall has that velocity component flipped first.
//!    A pose the store refuses (its rounded image not strictly convex, rare) leaves the
//!    body where it was and reverses its motion, so the next frame goes back towards an
//!    accepted pose.
//! 2. **Broad phase**: [`Scene::candidate_pairs`], the pairs whose boxes overlap (timed
//!    on its own and reported as the candidate count).
//! 3. **Narrow phase**: [`Scene::candidate_pairs_certified`], the store's own answer
//!    with a certificate per candidate pair (an intersection witness, or the separating
//!    edge of a pair found disjoint), planned per pair (sampled, converted, cached) as
//!    the chosen strategy says. It flushes the already-flushed broad phase once more;
//!    that repeat is counted in this phase.
//! 4. **Response**: each disjoint candidate's separating edge is kept (no second
//!    query). Each intersecting pair takes
//!    its contact normal from the separating edge of its last disjoint frame
//!    ([`separation_normal`]), or, when it has none (it was never seen disjoint with
//!    overlapping boxes), from the library's penetration normal ([`penetration_normal`]); a
//!    pair whose points at the contact approach along its normal gets one impulse
//!    there, which changes velocities and angular velocities ([`physics`]: restitution
//!    1, masses the areas, inertias the second moments about the pivots).
//!
//! # Shapes, poses and world points
//! Every shape coordinate (generated vertices, edit targets mapped into the shape) is a
//! multiple of [`GRID`] = 2^-36 of magnitude below 2^12. A body's world polygon is its
//! shape under its pose, each world coordinate the exact value rounded once
//! ([`Pose::apply`]): it depends on the shape and the pose only, never on the history
//! of frames. The page gets the shapes once per scene, one pose per polygon per frame,
//! and (up to [`MAX_WORLD_POINTS`] vertices in all) every world point the store holds,
//! so it draws and reports the store's own coordinates, bit for bit. The browser test
//! relies on it: it checks the page's pairs against the exact reference on the page's
//! own coordinates. An edit's target is a world point (the pointer), mapped into the
//! shape through the inverse of the body's pose and snapped to the grid: the vertex
//! lands within rounding of the pointer.
//!
//! # Bounds
//! At most [`MAX_POLYGONS`] polygons of [`MIN_VERTICES`]..=[`MAX_VERTICES`] vertices,
//! [`MAX_TOTAL_VERTICES`] in all (checked for a new scene and for every insertion);
//! speed in 0..=[`MAX_SPEED`]; each polygon hands out at most [`MAX_VERTEX_IDS`] vertex
//! ids. The map from wire ids to vertices holds the live vertices only (a removed
//! vertex's id leaves it), so a session's memory is bounded by its live scene whatever
//! its history of edits.

use super::contact::{penetration_normal, separation_normal};
use crate::intersect::{Algorithm, Certificate, Trace, trace_rng};
use crate::kernel::{Exact, Fast, Point, Pose, Precision};
use crate::polygon::{ConvexPolygon, LinkedPolygon, VertexId, convex_hull};
use crate::store::{PlannerStats, PolygonId, Scene, SceneError, Strategy};
use physics::{Motion, clamp_speed, impulse, mass_and_inertia};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use std::collections::HashMap;
use std::f64::consts::{PI, TAU};
use std::time::Instant;

/// The box the polygons move in: `[0, WORLD[0]] × [0, WORLD[1]]`.
pub const WORLD: [f64; 2] = [1200.0, 800.0];
/// Every coordinate is a multiple of this (2^-36); see the module docs.
pub const GRID: f64 = 1.0 / (1u64 << 36) as f64;
/// Edit targets must lie in `[AREA_MIN, AREA_MAX]` on both axes (per axis: the box and
/// half its size on each side).
pub const AREA_MIN: [f64; 2] = [-0.5 * WORLD[0], -0.5 * WORLD[1]];
/// See [`AREA_MIN`].
pub const AREA_MAX: [f64; 2] = [1.5 * WORLD[0], 1.5 * WORLD[1]];
/// The most polygons in a scene.
pub const MAX_POLYGONS: usize = 1000;
/// The fewest vertices per polygon.
pub const MIN_VERTICES: usize = 3;
/// The most vertices per polygon.
pub const MAX_VERTICES: usize = 65_536;
/// The most vertices in a scene.
pub const MAX_TOTAL_VERTICES: usize = 1 << 21;
/// The largest speed setting.
pub const MAX_SPEED: f64 = 5.0;
/// The most vertex ids one polygon hands out (insertions take new ids).
pub const MAX_VERTEX_IDS: usize = 1 << 20;
/// Step-through traces polygons of at most this many vertices (the reply carries every
/// vertex, and each step its marks).
pub const MAX_TRACE_VERTICES: usize = 4096;
/// Distance per frame at speed 1, in box units (the box is 1200 wide).
const BASE_SPEED: f64 = 1.6;
/// The largest velocity after collisions, in box units per frame at speed 1.
const MAX_VELOCITY: f64 = 4.0 * BASE_SPEED;
/// The largest distance a polygon moves in one frame, whatever the speed.
const MAX_STEP: f64 = 20.0;
/// The largest starting turn rate, radians per frame at speed 1.
const BASE_OMEGA: f64 = 0.02;
/// The largest turn rate after collisions, radians per frame at speed 1.
const MAX_OMEGA: f64 = 0.06;
/// The largest angle a polygon turns in one frame, whatever the speed.
const MAX_TURN: f64 = 0.2;
/// Frames carry every world point while the scene has at most this many vertices (above,
/// the page draws the shapes under the poses).
pub const MAX_WORLD_POINTS: usize = 1 << 16;

/// Rounds to the nearest multiple of [`GRID`] (exact: scaling by a power of two).
pub fn snap(x: f64) -> f64 {
    (x / GRID).round() * GRID
}

/// What the page controls.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    /// Number of polygons.
    pub polygons: usize,
    /// Vertices per polygon.
    pub vertices: usize,
    /// Seed of the scene's shapes, positions and velocities.
    pub seed: u64,
    /// How the store answers a pair.
    pub strategy: Strategy,
    /// The kernel of the store's queries.
    pub precision: Precision,
    /// Multiplies every velocity.
    pub speed: f64,
    /// Whether frames leave the polygons in place.
    pub paused: bool,
}

impl Default for Settings {
    /// The scene the page starts with: enough polygons, big enough and fast enough, to
    /// collide within the first second.
    fn default() -> Self {
        Settings {
            polygons: 36,
            vertices: 16,
            seed: 1,
            strategy: Strategy::Planner,
            precision: Precision::Exact,
            speed: 1.0,
            paused: false,
        }
    }
}

impl Settings {
    /// Checks the bounds of the module docs.
    ///
    /// # Errors
    /// A message naming the field and its allowed range.
    pub fn validate(&self) -> Result<(), String> {
        if !(1..=MAX_POLYGONS).contains(&self.polygons) {
            return Err(format!(
                "polygons must be between 1 and {MAX_POLYGONS}, not {}",
                self.polygons
            ));
        }
        if !(MIN_VERTICES..=MAX_VERTICES).contains(&self.vertices) {
            return Err(format!(
                "vertices must be between {MIN_VERTICES} and {MAX_VERTICES}, not {}",
                self.vertices
            ));
        }
        if self.polygons * self.vertices > MAX_TOTAL_VERTICES {
            return Err(format!(
                "{} polygons of {} vertices exceed the limit of {MAX_TOTAL_VERTICES} vertices in all",
                self.polygons, self.vertices
            ));
        }
        if !(0.0..=MAX_SPEED).contains(&self.speed) {
            return Err(format!(
                "speed must be between 0 and {MAX_SPEED}, not {:?}",
                self.speed
            ));
        }
        Ok(())
    }
}

/// The store, on the kernel the precision names.
#[derive(Debug)]
enum Store {
    Exact(Scene<Exact>),
    Fast(Scene<Fast>),
}

/// Runs `$body` with `$s` bound to the scene, whatever its kernel.
macro_rules! on_scene {
    ($store:expr, $s:ident => $body:expr) => {
        match $store {
            Store::Exact($s) => $body,
            Store::Fast($s) => $body,
        }
    };
}

// After the macro: it is in scope only below its definition.
mod edits;
pub mod physics;
use edits::VertexIds;

impl Store {
    fn new(precision: Precision, strategy: Strategy) -> Store {
        let mut store = match precision {
            Precision::Exact => Store::Exact(Scene::new()),
            Precision::Fast => Store::Fast(Scene::with_kernel(Fast)),
        };
        on_scene!(&mut store, s => s.set_strategy(strategy));
        store
    }
}

#[derive(Debug)]
struct Body {
    id: PolygonId,
    /// The pose the store holds: world polygon = shape under it.
    pose: Pose,
    /// The angle (radians, in [−π, π]) and translation the pose is made of.
    angle: f64,
    position: [f64; 2],
    /// Box units per frame at speed 1.
    velocity: [f64; 2],
    /// Radians per frame at speed 1, counter-clockwise.
    omega: f64,
    /// The shape's area.
    mass: f64,
    /// The shape's second moment of area about its origin (the pivot).
    inertia: f64,
    /// Wire vertex id → vertex handle, live vertices only.
    ids: VertexIds,
}

impl Body {
    fn motion(&self) -> Motion {
        Motion {
            velocity: self.velocity,
            omega: self.omega,
            mass: self.mass,
            inertia: self.inertia,
            pivot: self.position,
        }
    }
}

/// Milliseconds spent in each part of a frame on the server.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize)]
pub struct Timing {
    /// Moving the polygons.
    pub update_ms: f64,
    /// The broad phase (candidate pairs).
    pub broad_ms: f64,
    /// The narrow phase (every candidate pair answered with its certificate).
    pub narrow_ms: f64,
    /// Contact normals and bounces.
    pub response_ms: f64,
}

/// What one frame changed, for the page.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Frame {
    /// The scene's number.
    pub scene: u64,
    /// Frames advanced since the scene started.
    pub frame: u64,
    /// Whether the polygons moved (false while paused).
    pub advanced: bool,
    /// Per polygon `c, s, tx, ty`: world point = (c·x − s·y + tx, s·x + c·y + ty) of
    /// each shape point, rounded.
    pub poses: Vec<f64>,
    /// Whether a binary message with every world point follows (at most
    /// [`MAX_WORLD_POINTS`] vertices in all).
    pub world: bool,
    /// Intersecting pairs of polygon indices `[i, j]`, `i < j`, sorted.
    pub pairs: Vec<[usize; 2]>,
    /// The contact normal of each pair, from `i` towards `j` (null when degenerate).
    pub normals: Vec<Option<[f64; 2]>>,
    /// Pairs whose boxes overlap.
    pub candidates: usize,
    /// Queries the store answered in this frame (box rejects included).
    pub queries: u64,
    /// Server time per part of the frame.
    pub timing: Timing,
    /// What the planner did in this frame.
    pub stats: PlannerStats,
    /// What the planner did since the scene (or the precision) was set.
    pub totals: PlannerStats,
}

/// An accepted edit, as the page applies it: points are shape coordinates.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Edit {
    /// The polygon's index.
    pub polygon: usize,
    /// `move`, `insert` or `remove`.
    pub kind: &'static str,
    /// The wire id of the vertex moved, inserted or removed.
    pub vertex: u32,
    /// For an insertion: the wire id of the vertex it follows.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub after: Option<u32>,
    /// For a move or an insertion: the vertex's new shape point.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub point: Option<[f64; 2]>,
}

/// Why an edit did not happen.
#[derive(Clone, Debug, PartialEq)]
pub enum EditFailure {
    /// The request names nothing valid (polygon index, vertex id) or a point outside
    /// the area.
    Invalid(String),
    /// The store refused it; the text is the error's `Display`.
    Refused(String),
}

/// The simulation of one page.
#[derive(Debug)]
pub struct Simulation {
    settings: Settings,
    store: Store,
    bodies: Vec<Body>,
    index: HashMap<PolygonId, usize>,
    scene: u64,
    frame: u64,
    /// Per candidate pair `[i, j]`, `i < j`: the contact normal from `i` to `j` given by
    /// the separating edge of the last frame that found the pair disjoint.
    separators: HashMap<[usize; 2], [f64; 2]>,
    /// Vertices in all polygons (at most [`MAX_TOTAL_VERTICES`], edits included).
    vertices: usize,
}

impl Simulation {
    /// A new scene from `settings`, numbered `scene`.
    ///
    /// # Errors
    /// The settings are out of bounds ([`Settings::validate`]).
    pub fn new(settings: Settings, scene: u64) -> Result<Simulation, String> {
        settings.validate()?;
        let mut sim = Simulation {
            settings,
            store: Store::new(settings.precision, settings.strategy),
            bodies: Vec::new(),
            index: HashMap::new(),
            scene,
            frame: 0,
            separators: HashMap::new(),
            vertices: 0,
        };
        let mut rng = SmallRng::seed_from_u64(settings.seed);
        for (points, position, velocity, omega) in generate(&settings, &mut rng) {
            let shape = match LinkedPolygon::from_points(points.iter().copied()) {
                Ok(p) => p,
                // Snapping made some vertices collinear: keep their hull (still on the grid).
                Err(_) => LinkedPolygon::from_convex(&convex_hull(&points).map_err(|e| e.to_string())?),
            };
            let ids = VertexIds::new(shape.iter().map(|(v, _)| v));
            let (mass, inertia) = mass_and_inertia(shape.iter().map(|(_, p)| p));
            sim.vertices += shape.len();
            // Angle 0 and a translation on the grid: every world coordinate is a sum of
            // two grid numbers below 2^12, exact, so the first pose cannot be refused.
            let pose = Pose::new([1.0, 0.0], position).map_err(|e| e.to_string())?;
            let id = on_scene!(&mut sim.store, s => {
                let id = s.insert(shape);
                s.set_pose(id, pose).map(|()| id)
            })
            .map_err(|e| e.to_string())?;
            sim.index.insert(id, sim.bodies.len());
            sim.bodies.push(Body {
                id,
                pose,
                angle: 0.0,
                position,
                velocity,
                omega,
                mass,
                inertia,
                ids,
            });
        }
        Ok(sim)
    }

    /// The settings in force.
    pub fn settings(&self) -> Settings {
        self.settings
    }

    /// The scene's number.
    pub fn scene(&self) -> u64 {
        self.scene
    }

    /// Frames advanced since the scene started.
    pub fn frame_number(&self) -> u64 {
        self.frame
    }

    /// Number of polygons.
    pub fn len(&self) -> usize {
        self.bodies.len()
    }

    /// Whether the scene has no polygons.
    pub fn is_empty(&self) -> bool {
        self.bodies.is_empty()
    }

    /// Changes what can change in place: strategy, speed, pause, and the precision (the
    /// shapes move into a scene on the other kernel, handles and poses unchanged;
    /// the planner's counters start again).
    ///
    /// # Errors
    /// The speed is out of bounds.
    pub fn adjust(
        &mut self,
        strategy: Strategy,
        precision: Precision,
        speed: f64,
        paused: bool,
    ) -> Result<(), String> {
        Settings {
            speed,
            ..self.settings
        }
        .validate()?;
        if precision != self.settings.precision {
            let mut store = Store::new(precision, strategy);
            self.index.clear();
            for (i, body) in self.bodies.iter_mut().enumerate() {
                let shape = on_scene!(&mut self.store, s => {
                    // A twin keeps the polygon's identity, so the wire ids' handles stay
                    // valid (a clone would be another polygon).
                    let shape = s.shape(body.id).map(|p| p.translated_twin(&[]));
                    s.remove(body.id).and(shape)
                })
                .map_err(|e| e.to_string())?;
                // The same shape under the same pose: accepted before, accepted again.
                body.id = on_scene!(&mut store, s => {
                    let id = s.insert(shape);
                    s.set_pose(id, body.pose).map(|()| id)
                })
                .map_err(|e| e.to_string())?;
                self.index.insert(body.id, i);
            }
            self.store = store;
        }
        on_scene!(&mut self.store, s => s.set_strategy(strategy));
        self.settings.strategy = strategy;
        self.settings.precision = precision;
        self.settings.speed = speed;
        self.settings.paused = paused;
        Ok(())
    }

    /// Every polygon's shape vertices (counter-clockwise, wire ids 0, 1, ... in that
    /// order for a new scene), as `x, y` pairs, with the count per polygon.
    pub fn base_vertices(&self) -> (Vec<usize>, Vec<f64>) {
        let mut sizes = Vec::with_capacity(self.bodies.len());
        let mut coords = Vec::new();
        for body in &self.bodies {
            let shape = on_scene!(&self.store, s => s.shape(body.id)).expect("live polygon");
            sizes.push(shape.len());
            coords.extend(shape.iter().flat_map(|(_, p)| [p.x, p.y]));
        }
        (sizes, coords)
    }

    /// Every polygon's world vertices, in the order of [`base_vertices`](Self::base_vertices)
    /// (vertex k of the world polygon is the image of the shape's vertex k).
    pub fn current_vertices(&self) -> Vec<Vec<Point>> {
        self.bodies.iter().map(|b| self.world_of(b)).collect()
    }

    fn world_of(&self, body: &Body) -> Vec<Point> {
        on_scene!(&self.store, s => {
            let (shape, world) = (s.shape(body.id).expect("live polygon"), s.polygon(body.id).expect("live polygon"));
            shape.iter().map(|(v, _)| world.point(v).expect("a twin has the shape's handles")).collect()
        })
    }

    /// Every world point, `x, y` pairs polygon after polygon, in the order of
    /// [`base_vertices`](Self::base_vertices). O(total vertices).
    pub fn world_coordinates(&self) -> Vec<f64> {
        let mut out = Vec::with_capacity(2 * self.vertices);
        for body in &self.bodies {
            out.extend(self.world_of(body).into_iter().flat_map(|p| [p.x, p.y]));
        }
        out
    }

    /// The total kinetic energy (linear and rotational, [`physics`]), for the tests.
    pub fn energy(&self) -> f64 {
        self.bodies.iter().map(|b| b.motion().energy()).sum()
    }

    /// Each body's angle (radians) and turn rate (radians per frame at speed 1).
    pub fn turning(&self) -> Vec<(f64, f64)> {
        self.bodies.iter().map(|b| (b.angle, b.omega)).collect()
    }

    /// The store's intersecting pairs as polygon indices, sorted (no timing, no motion).
    pub fn store_pairs(&mut self) -> Vec<[usize; 2]> {
        let pairs = on_scene!(&mut self.store, s => s.intersecting_pairs());
        self.index_pairs(&pairs)
    }

    fn index_pairs(&self, pairs: &[(PolygonId, PolygonId)]) -> Vec<[usize; 2]> {
        let mut out: Vec<[usize; 2]> = pairs
            .iter()
            .map(|(a, b)| {
                let (i, j) = (self.index[a], self.index[b]);
                [i.min(j), i.max(j)]
            })
            .collect();
        out.sort_unstable();
        out
    }

    /// One frame: moves the polygons (unless `advance` is false), asks the store for the
    /// intersecting pairs and bounces the pairs that approach.
    pub fn frame(&mut self, advance: bool) -> Frame {
        let t0 = Instant::now();
        if advance {
            self.update();
            self.frame += 1;
        }
        let t1 = Instant::now();
        let before = on_scene!(&self.store, s => s.stats());
        let candidates = on_scene!(&mut self.store, s => s.candidate_pairs());
        let t2 = Instant::now();
        let answered = on_scene!(&mut self.store, s => s.candidate_pairs_certified());
        let (found, apart): (Vec<_>, Vec<_>) = answered
            .into_iter()
            .filter_map(|(a, b, c)| Some((a, b, c.ok()?)))
            .partition(|(_, _, c)| c.intersects());
        let hits = self.index_certified(found);
        let pairs: Vec<[usize; 2]> = hits.iter().map(|h| h.0).collect();
        let t3 = Instant::now();
        let after = on_scene!(&self.store, s => s.stats());
        let normals = self.respond(&self.index_certified(apart), &hits, advance);
        let t4 = Instant::now();
        let stats = stats_delta(after, before);
        let ms = |a: Instant, b: Instant| (b - a).as_secs_f64() * 1e3;
        Frame {
            scene: self.scene,
            frame: self.frame,
            advanced: advance,
            poses: self
                .bodies
                .iter()
                .flat_map(|b| {
                    let ([c, s], [tx, ty]) = (b.pose.rotation(), b.pose.translation());
                    [c, s, tx, ty]
                })
                .collect(),
            world: self.vertices <= MAX_WORLD_POINTS,
            pairs,
            normals,
            candidates: candidates.len(),
            queries: stats.box_rejects + stats.array_tests + stats.sampled_tests,
            timing: Timing {
                update_ms: ms(t0, t1),
                broad_ms: ms(t1, t2),
                narrow_ms: ms(t2, t3),
                response_ms: ms(t3, t4),
            },
            stats,
            totals: after,
        }
    }

    fn update(&mut self) {
        let speed = self.settings.speed;
        for body in &mut self.bodies {
            let bbox = on_scene!(&self.store, s => s.bounding_box(body.id)).expect("live polygon");
            let mut d = [0.0; 2];
            for axis in 0..2 {
                let (lo, hi) = match axis {
                    0 => (bbox.min.x, bbox.max.x),
                    _ => (bbox.min.y, bbox.max.y),
                };
                let v = &mut body.velocity[axis];
                let step = (*v * speed).clamp(-MAX_STEP, MAX_STEP);
                if (lo + step < 0.0 && *v < 0.0) || (hi + step > WORLD[axis] && *v > 0.0) {
                    *v = -*v;
                }
                d[axis] = *v * speed;
            }
            let len = d[0].hypot(d[1]);
            if len > MAX_STEP {
                d = [d[0] * MAX_STEP / len, d[1] * MAX_STEP / len];
            }
            let turn = (body.omega * speed).clamp(-MAX_TURN, MAX_TURN);
            if d == [0.0, 0.0] && turn == 0.0 {
                continue;
            }
            // Kept in [−π, π] so that the angle never grows with the frames.
            let angle = (body.angle + turn + PI).rem_euclid(TAU) - PI;
            let position = [body.position[0] + d[0], body.position[1] + d[1]];
            let placed = Pose::from_angle(angle, position)
                .map_err(|e| e.to_string())
                .and_then(|pose| {
                    on_scene!(&mut self.store, s => s.set_pose(body.id, pose))
                        .map(|()| pose)
                        .map_err(|e| e.to_string())
                });
            match placed {
                Ok(pose) => (body.pose, body.angle, body.position) = (pose, angle, position),
                // Refused (the rounded image not strictly convex): stay, and go back
                // towards the accepted pose next frame (energy unchanged).
                Err(_) => {
                    body.velocity = [-body.velocity[0], -body.velocity[1]];
                    body.omega = -body.omega;
                }
            }
        }
    }

    /// Certified store pairs as sorted index pairs `[i, j]`, `i < j`,
    /// each certificate turned so that its P is polygon `i`.
    fn index_certified(
        &self,
        found: Vec<(PolygonId, PolygonId, Certificate)>,
    ) -> Vec<([usize; 2], Certificate)> {
        let mut out: Vec<([usize; 2], Certificate)> = found
            .into_iter()
            .map(|(a, b, c)| {
                let (i, j) = (self.index[&a], self.index[&b]);
                if i < j { ([i, j], c) } else { ([j, i], c.swapped()) }
            })
            .collect();
        out.sort_unstable_by_key(|h| h.0);
        out
    }

    /// Contact normals for the intersecting pairs `hits` (module docs, "Contact
    /// normals"); when the frame advanced, the impulse of every pair approaching along
    /// its normal at the contact. Records the separating edge of every candidate pair found
    /// disjoint (`apart`, with the certificates the narrow phase gave), for its next
    /// contact.
    fn respond(
        &mut self,
        apart: &[([usize; 2], Certificate)],
        hits: &[([usize; 2], Certificate)],
        bounce: bool,
    ) -> Vec<Option<[f64; 2]>> {
        let mut separators = HashMap::with_capacity(apart.len() + hits.len());
        for (pair, certificate) in apart {
            if let Some(n) = separation_normal(certificate) {
                separators.insert(*pair, n);
            }
        }
        let mut walked: HashMap<usize, Vec<Point>> = HashMap::new();
        let mut normals = Vec::with_capacity(hits.len());
        for (pair, _) in hits {
            let [i, j] = *pair;
            let n = match self.separators.get(pair) {
                Some(&n) => {
                    separators.insert(*pair, n);
                    Some(n)
                }
                None => {
                    for k in [i, j] {
                        walked.entry(k).or_insert_with(|| {
                            let polygon = on_scene!(&self.store, s => s.polygon(self.bodies[k].id))
                                .expect("live polygon");
                            polygon.iter().map(|(_, p)| p).collect()
                        });
                    }
                    penetration_normal(&walked[&i], &walked[&j])
                }
            };
            normals.push(n);
            if let (true, Some(n)) = (bounce, n) {
                let (a, b) = (&self.bodies[i], &self.bodies[j]);
                let contact = on_scene!(&self.store, s => {
                    let (p, q) = (s.bounding_box(a.id).expect("live polygon"), s.bounding_box(b.id).expect("live polygon"));
                    // The centre of the boxes' overlap (they overlap: the pair is a
                    // candidate), an O(1) estimate of where the two meet.
                    [
                        0.5 * (p.min.x.max(q.min.x) + p.max.x.min(q.max.x)),
                        0.5 * (p.min.y.max(q.min.y) + p.max.y.min(q.max.y)),
                    ]
                });
                if let Some(((va, wa), (vb, wb))) = impulse(&a.motion(), &b.motion(), contact, n) {
                    for (k, v, w) in [(i, va, wa), (j, vb, wb)] {
                        self.bodies[k].velocity = clamp_speed(v, MAX_VELOCITY);
                        self.bodies[k].omega = w.clamp(-MAX_OMEGA, MAX_OMEGA);
                    }
                }
            }
        }
        self.separators = separators;
        normals
    }

    /// A trace of `algorithm` on polygons `a` (as P) and `b` (as Q) at their current
    /// positions, under the scene's precision, with the two polygons' vertices.
    /// Randomised algorithms draw from a generator seeded by the frame number.
    ///
    /// # Errors
    /// An index out of range, `a == b`, or a polygon of more than
    /// [`MAX_TRACE_VERTICES`] vertices.
    pub fn trace(
        &self,
        a: usize,
        b: usize,
        algorithm: Algorithm,
    ) -> Result<(Vec<Point>, Vec<Point>, Trace), String> {
        if a == b {
            return Err(format!("a trace needs two different polygons (both are {a})"));
        }
        let polygon = |i: usize| -> Result<ConvexPolygon, String> {
            let body = self
                .bodies
                .get(i)
                .ok_or_else(|| format!("no polygon {i} (there are {})", self.bodies.len()))?;
            let linked = on_scene!(&self.store, s => s.polygon(body.id)).map_err(|e| e.to_string())?;
            if linked.len() > MAX_TRACE_VERTICES {
                return Err(format!(
                    "polygon {i} has {} vertices; step-through traces at most {MAX_TRACE_VERTICES}",
                    linked.len()
                ));
            }
            ConvexPolygon::new(linked.iter().map(|(_, p)| p)).map_err(|e| e.to_string())
        };
        let (p, q) = (polygon(a)?, polygon(b)?);
        let mut rng = SmallRng::seed_from_u64(self.frame);
        let t = match self.settings.precision {
            Precision::Exact => trace_rng(algorithm, Exact, &p, &q, &mut rng),
            Precision::Fast => trace_rng(algorithm, Fast, &p, &q, &mut rng),
        };
        Ok((p.vertices().to_vec(), q.vertices().to_vec(), t))
    }

    /// Checks that every world vertex is the image of its shape vertex (in `base`, the
    /// shapes as [`base_vertices`](Self::base_vertices) gave them) under the body's pose,
    /// that the shapes lie on the grid, and the store's own invariants.
    ///
    /// # Errors
    /// The first violation found, described.
    pub fn debug_validate(&self, base: &[f64]) -> Result<(), String> {
        on_scene!(&self.store, s => s.debug_validate())?;
        let mut k = 0;
        for (i, body) in self.bodies.iter().enumerate() {
            let stored = on_scene!(&self.store, s => s.pose(body.id)).map_err(|e| e.to_string())?;
            if stored != Some(body.pose) {
                return Err(format!(
                    "polygon {i}: the store's pose {stored:?} is not {:?}",
                    body.pose
                ));
            }
            for p in self.world_of(body) {
                let (bx, by) = (base[k], base[k + 1]);
                k += 2;
                if Some(p) != body.pose.apply(Point::new(bx, by)) {
                    return Err(format!(
                        "polygon {i}: vertex {p:?} is not the image of ({bx}, {by})"
                    ));
                }
                if snap(bx) != bx || snap(by) != by {
                    return Err(format!("polygon {i}: shape vertex ({bx}, {by}) is off the grid"));
                }
            }
        }
        Ok(())
    }
}

fn stats_delta(a: PlannerStats, b: PlannerStats) -> PlannerStats {
    PlannerStats {
        box_rejects: a.box_rejects - b.box_rejects,
        array_tests: a.array_tests - b.array_tests,
        sampled_tests: a.sampled_tests - b.sampled_tests,
        linear_tests: a.linear_tests - b.linear_tests,
        conversions: a.conversions - b.conversions,
        throwaway_conversions: a.throwaway_conversions - b.throwaway_conversions,
        invalidations: a.invalidations - b.invalidations,
    }
}

/// The bodies of a new scene: shapes (on the grid, counter-clockwise, about their
/// centres), positions (on the grid), velocities and turn rates. The shapes are ellipses
/// of random axes and rotation with `vertices` vertices at equal parameter steps, sized so
/// that they cover about a fifth of the box, on a jittered grid of cells.
#[allow(clippy::type_complexity)]
fn generate(settings: &Settings, rng: &mut SmallRng) -> Vec<(Vec<Point>, [f64; 2], [f64; 2], f64)> {
    let count = settings.polygons;
    let [w, h] = WORLD;
    let cols = ((count as f64 * w / h).sqrt().ceil() as usize).max(1);
    let rows = count.div_ceil(cols);
    let (cw, ch) = (w / cols as f64, h / rows as f64);
    let area_each = 0.2 * w * h / count as f64;
    (0..count)
        .map(|k| {
            let aspect: f64 = rng.random_range(0.45..=1.0);
            let a = (area_each / (std::f64::consts::PI * aspect))
                .sqrt()
                .min(0.45 * cw.max(ch))
                .min(0.25 * h);
            let b = a * aspect;
            let (col, row) = (k % cols, k / cols);
            let slack = |cell: f64| (0.5 * cell - a).max(0.0);
            let cx = (col as f64 + 0.5) * cw + rng.random_range(-1.0..=1.0) * slack(cw);
            let cy = (row as f64 + 0.5) * ch + rng.random_range(-1.0..=1.0) * slack(ch);
            let (cx, cy) = (snap(cx.clamp(a, w - a)), snap(cy.clamp(a, h - a)));
            let rot: f64 = rng.random_range(0.0..TAU);
            let phase: f64 = rng.random_range(0.0..TAU);
            let (c, s) = (rot.cos(), rot.sin());
            let n = settings.vertices;
            let points = (0..n)
                .map(|i| {
                    let t = phase + TAU * i as f64 / n as f64;
                    let (x, y) = (a * t.cos(), b * t.sin());
                    Point::new(snap(c * x - s * y), snap(s * x + c * y))
                })
                .collect();
            let dir: f64 = rng.random_range(0.0..TAU);
            let speed = BASE_SPEED * rng.random_range(0.6..=1.4);
            let omega = BASE_OMEGA * rng.random_range(-1.0..=1.0);
            (points, [cx, cy], [speed * dir.cos(), speed * dir.sin()], omega)
        })
        .collect()
}

#[cfg(test)]
mod tests;
