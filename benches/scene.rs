//! Whole frames of a scene, polysect beside parry2d-f64, in one run.
//!
//! A frame is "update every polygon, then report all intersecting pairs". polysect
//! drives a [`Scene`] (planner, exact kernel, cost model calibrated on this machine at
//! start-up) through its public API as a user would: [`Scene::translate`] for rigid
//! motion, [`Scene::move_vertex`] for deformation, [`Scene::intersecting_pairs`] for the
//! pairs. parry2d-f64 keeps one `ConvexPolygon` per polygon with a pose, computes the
//! boxes, rebuilds its `Bvh` every frame, traverses it against itself and runs
//! `intersection_test` with the poses on every candidate pair; a deformed polygon's
//! shape is rebuilt from its points (what a parry user does after moving vertices).
//!
//! Workloads (the scene's density gives each polygon a few overlapping neighbours):
//! - `rigid-2000x16`, `rigid-2000x256`: every polygon translated each frame, bouncing
//!   inside the world square;
//! - `deform-500x256`, `deform-100x4096`, `deform-20x65536`: 8 vertex moves per polygon
//!   per frame (each vertex pushed in or out along its position relative to the chord of
//!   its neighbours, only moves that keep the polygon strictly convex);
//! - `static-1000x64`: nothing moves, all pairs every frame (parry keeps its tree);
//! - `rigid-20000x16`, `rigid-2000x1024`: larger rigid scenes;
//! - `teleport-2000x16`, `teleport-2000x256`: every polygon translated to a random place
//!   each frame (no coherence: the worst case for warm starts).
//!
//! Three sides run every frame, in an order rotating with the frame: `polysect-warm`
//! (warm starts on), `polysect` (the scene as it comes: warm starts off) and `parry2d`;
//! all three counts must agree.
//!
//! Both sides see the same coordinates bit for bit: vertices, positions and steps lie
//! on a grid of 2^-40 well inside 2^12, so every translation is exact and parry's pose
//! applied to its local points gives our coordinates. Each frame's motion is drawn
//! outside the timed region; the side being timed applies it and finds the pairs, then
//! (untimed) the other side applies the same motion and the two pair counts are
//! asserted equal, every frame. On the first frame both are also checked against a
//! brute force over all pairs (exact linear test on every pair whose boxes overlap).
//!
//! `cargo bench --bench scene`; ratios polysect / parry2d per workload come from one run.
//! Both sides run every frame, so besides criterion's figures the bench prints, per
//! workload, a paired comparison over the same frames (each side's time per frame, the
//! ratio of the totals and the median per-frame ratio): on a busy machine the pairing
//! keeps the ratio meaningful when the speed drifts between criterion's two runs.
//! `POLYSECT_SCENE_DEFAULT_COSTS=1` uses the default cost model instead of calibrating
//! (for profiling runs).

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use parry2d_f64::bounding_volume::Aabb;
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::partitioning::{Bvh, BvhBuildStrategy, BvhWorkspace};
use parry2d_f64::query::intersection_test;
use parry2d_f64::shape::ConvexPolygon as ParryPolygon;
use polysect::intersect::{ArrayIntersection, Linear};
use polysect::polygon::convex_hull;
use polysect::store::{CostModel, PolygonId, Scene};
use polysect::{ConvexPolygon, Exact, Kernel, Orientation, Point, VertexId};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use std::cell::RefCell;
use std::f64::consts::TAU;
use std::time::{Duration, Instant};

/// Every coordinate is a multiple of this (2^-40).
const GRID: f64 = 1.0 / (1u64 << 40) as f64;

fn snap(x: f64) -> f64 {
    (x / GRID).round() * GRID
}

#[derive(Clone, Copy, Debug)]
enum Motion {
    Rigid,
    /// Every polygon teleported to a random place each frame (no coherence).
    Teleport,
    Deform {
        moves: usize,
    },
    Static,
    /// Every body turns and moves each frame: a new absolute pose (angle, position).
    Rotate,
}

#[derive(Clone, Copy, Debug)]
struct Workload {
    name: &'static str,
    count: usize,
    vertices: usize,
    motion: Motion,
}

const WORKLOADS: [Workload; 14] = [
    Workload {
        name: "rotate-2000x16",
        count: 2000,
        vertices: 16,
        motion: Motion::Rotate,
    },
    Workload {
        name: "rotate-2000x256",
        count: 2000,
        vertices: 256,
        motion: Motion::Rotate,
    },
    Workload {
        name: "rotate-500x1024",
        count: 500,
        vertices: 1024,
        motion: Motion::Rotate,
    },
    Workload {
        name: "rotate-20000x16",
        count: 20000,
        vertices: 16,
        motion: Motion::Rotate,
    },
    Workload {
        name: "rigid-2000x16",
        count: 2000,
        vertices: 16,
        motion: Motion::Rigid,
    },
    Workload {
        name: "rigid-2000x256",
        count: 2000,
        vertices: 256,
        motion: Motion::Rigid,
    },
    Workload {
        name: "rigid-20000x16",
        count: 20000,
        vertices: 16,
        motion: Motion::Rigid,
    },
    Workload {
        name: "rigid-2000x1024",
        count: 2000,
        vertices: 1024,
        motion: Motion::Rigid,
    },
    Workload {
        name: "teleport-2000x16",
        count: 2000,
        vertices: 16,
        motion: Motion::Teleport,
    },
    Workload {
        name: "teleport-2000x256",
        count: 2000,
        vertices: 256,
        motion: Motion::Teleport,
    },
    Workload {
        name: "deform-500x256",
        count: 500,
        vertices: 256,
        motion: Motion::Deform { moves: 8 },
    },
    Workload {
        name: "deform-100x4096",
        count: 100,
        vertices: 4096,
        motion: Motion::Deform { moves: 8 },
    },
    Workload {
        name: "deform-20x65536",
        count: 20,
        vertices: 65536,
        motion: Motion::Deform { moves: 8 },
    },
    Workload {
        name: "static-1000x64",
        count: 1000,
        vertices: 64,
        motion: Motion::Static,
    },
];

/// One frame's updates.
enum Frame {
    /// Per polygon, its translation.
    Translate(Vec<(f64, f64)>),
    /// (polygon, vertex index in counter-clockwise order, new point).
    Moves(Vec<(usize, usize, Point)>),
    /// Per body, its new absolute pose: angle and position.
    Poses(Vec<(f64, f64, f64)>),
    Nothing,
}

/// The reference state both sides follow: each polygon's points (counter-clockwise,
/// in world coordinates) and, for rigid motion, its velocity.
struct Mirror {
    points: Vec<Vec<Point>>,
    velocity: Vec<(f64, f64)>,
    side: f64,
    rng: SmallRng,
    /// Turning bodies: shapes about their centres, angle, angular velocity, position.
    local: Vec<Vec<Point>>,
    angle: Vec<(f64, f64)>,
    position: Vec<(f64, f64)>,
    rotating: bool,
}

impl Mirror {
    fn new(w: &Workload, seed: u64) -> Mirror {
        let mut rng = SmallRng::seed_from_u64(seed);
        // About three overlapping neighbours per polygon for radii around 1.
        let side = (4.0 * std::f64::consts::PI * w.count as f64 / 3.0)
            .sqrt()
            .max(4.0);
        let mut points = Vec::with_capacity(w.count);
        let mut velocity = Vec::with_capacity(w.count);
        let (mut local, mut angle, mut position) = (Vec::new(), Vec::new(), Vec::new());
        for _ in 0..w.count {
            let (a, b) = (rng.random_range(0.5..1.0), rng.random_range(0.5..1.0));
            let phi: f64 = rng.random_range(0.0..TAU);
            let (cx, cy) = (
                snap(rng.random_range(1.0..side - 1.0)),
                snap(rng.random_range(1.0..side - 1.0)),
            );
            let pts: Vec<Point> = (0..w.vertices)
                .map(|_| {
                    let t: f64 = rng.random_range(0.0..TAU);
                    let (x, y) = (a * t.cos(), b * t.sin());
                    Point::new(
                        snap(cx + phi.cos() * x - phi.sin() * y),
                        snap(cy + phi.sin() * x + phi.cos() * y),
                    )
                })
                .collect();
            let hull = convex_hull(&pts).expect("points on an ellipse");
            points.push(hull.vertices().to_vec());
            local.push(
                hull.vertices()
                    .iter()
                    .map(|p| Point::new(p.x - cx, p.y - cy))
                    .collect(),
            );
            angle.push((0.0, rng.random_range(-0.05..0.05)));
            position.push((cx, cy));
            let speed = 0.05;
            let dir: f64 = rng.random_range(0.0..TAU);
            velocity.push((snap(speed * dir.cos()), snap(speed * dir.sin())));
        }
        Mirror {
            points,
            velocity,
            side,
            rng,
            local,
            angle,
            position,
            rotating: matches!(w.motion, Motion::Rotate),
        }
    }

    /// Draws the next frame's motion and applies it to the mirror.
    fn step(&mut self, motion: Motion) -> Frame {
        match motion {
            Motion::Static => Frame::Nothing,
            Motion::Rotate => {
                let mut poses = Vec::with_capacity(self.points.len());
                for k in 0..self.points.len() {
                    let (v, p) = (&mut self.velocity[k], &mut self.position[k]);
                    if (p.0 < 0.0 && v.0 < 0.0) || (p.0 > self.side && v.0 > 0.0) {
                        v.0 = -v.0;
                    }
                    if (p.1 < 0.0 && v.1 < 0.0) || (p.1 > self.side && v.1 > 0.0) {
                        v.1 = -v.1;
                    }
                    *p = (p.0 + v.0, p.1 + v.1);
                    let a = &mut self.angle[k];
                    a.0 += a.1;
                    let pose = polysect::kernel::Pose::from_angle(a.0, [p.0, p.1]).expect("finite");
                    self.points[k] = self.local[k]
                        .iter()
                        .map(|&q| pose.apply(q).expect("no overflow"))
                        .collect();
                    poses.push((a.0, p.0, p.1));
                }
                Frame::Poses(poses)
            }
            Motion::Rigid => {
                let mut steps = Vec::with_capacity(self.points.len());
                for (pts, v) in self.points.iter_mut().zip(&mut self.velocity) {
                    // Bounce off the walls of the world square (the first vertex stands
                    // for the polygon).
                    let p = pts[0];
                    if (p.x < 0.0 && v.0 < 0.0) || (p.x > self.side && v.0 > 0.0) {
                        v.0 = -v.0;
                    }
                    if (p.y < 0.0 && v.1 < 0.0) || (p.y > self.side && v.1 > 0.0) {
                        v.1 = -v.1;
                    }
                    for q in pts.iter_mut() {
                        *q = Point::new(q.x + v.0, q.y + v.1);
                    }
                    steps.push(*v);
                }
                Frame::Translate(steps)
            }
            Motion::Teleport => {
                let mut steps = Vec::with_capacity(self.points.len());
                for pts in &mut self.points {
                    let p = pts[0];
                    let to = (
                        snap(self.rng.random_range(1.0..self.side - 1.0)),
                        snap(self.rng.random_range(1.0..self.side - 1.0)),
                    );
                    let v = (to.0 - p.x, to.1 - p.y);
                    for q in pts.iter_mut() {
                        *q = Point::new(q.x + v.0, q.y + v.1);
                    }
                    steps.push(v);
                }
                Frame::Translate(steps)
            }
            Motion::Deform { moves } => {
                let mut out = Vec::with_capacity(self.points.len() * moves);
                for (k, pts) in self.points.iter_mut().enumerate() {
                    let n = pts.len();
                    for _ in 0..moves {
                        let i = self.rng.random_range(0..n);
                        let (pp, p, nx, nn) = (
                            pts[(i + n - 2) % n],
                            pts[(i + n - 1) % n],
                            pts[(i + 1) % n],
                            pts[(i + 2) % n],
                        );
                        let v = pts[i];
                        let (mx, my) = ((p.x + nx.x) / 2.0, (p.y + nx.y) / 2.0);
                        let t = self.rng.random_range(-0.5..0.5);
                        let to = Point::new(snap(v.x + t * (v.x - mx)), snap(v.y + t * (v.y - my)));
                        let valid = Exact.orient(p, nx, to) == Orientation::Cw
                            && Exact.orient(pp, p, to) == Orientation::Ccw
                            && Exact.orient(to, nx, nn) == Orientation::Ccw;
                        if valid && to != v {
                            pts[i] = to;
                            out.push((k, i, to));
                        }
                    }
                }
                Frame::Moves(out)
            }
        }
    }

    /// Intersecting pairs by brute force: every pair, boxes then the exact linear test.
    fn brute_force_pairs(&self) -> usize {
        let polys: Vec<ConvexPolygon> = self
            .points
            .iter()
            .map(|p| ConvexPolygon::from_ccw_unchecked(p.clone()))
            .collect();
        let boxes: Vec<polysect::BoundingBox> = polys.iter().map(|p| p.bounding_box()).collect();
        let mut count = 0;
        for i in 0..polys.len() {
            for j in i + 1..polys.len() {
                let (a, b) = (boxes[i], boxes[j]);
                if a.overlaps(&b) && Linear.intersects(&polys[i], &polys[j]) {
                    count += 1;
                }
            }
        }
        count
    }
}

/// polysect's side: the scene, its handles, and each polygon's vertex handles in
/// counter-clockwise order (index i is the mirror's point i).
struct Ours {
    scene: Scene,
    ids: Vec<PolygonId>,
    vertices: Vec<Vec<VertexId>>,
}

impl Ours {
    fn new(mirror: &Mirror, costs: CostModel) -> Ours {
        let mut scene = Scene::new();
        scene.set_costs(costs);
        let mut ids = Vec::new();
        let mut vertices = Vec::new();
        // Turning bodies are added as their shapes; the first frame poses them.
        let shapes = if mirror.rotating {
            &mirror.local
        } else {
            &mirror.points
        };
        for pts in shapes {
            let id = scene.insert_points(pts.iter().copied()).expect("a valid polygon");
            let poly = scene.polygon(id).unwrap();
            let start = poly.iter().position(|(_, p)| p == pts[0]).expect("first point");
            let mut handles: Vec<VertexId> = poly.iter().map(|(v, _)| v).collect();
            handles.rotate_left(start);
            assert_eq!(handles.len(), pts.len());
            ids.push(id);
            vertices.push(handles);
        }
        Ours { scene, ids, vertices }
    }

    fn frame(&mut self, frame: &Frame) -> usize {
        match frame {
            Frame::Translate(steps) => {
                for (&id, &(dx, dy)) in self.ids.iter().zip(steps) {
                    self.scene.translate(id, dx, dy).expect("an exact translation");
                }
            }
            Frame::Moves(moves) => {
                for &(k, i, to) in moves {
                    self.scene
                        .move_vertex(self.ids[k], self.vertices[k][i], to)
                        .expect("a move checked on the mirror");
                }
            }
            Frame::Poses(poses) => {
                for (&id, &(angle, tx, ty)) in self.ids.iter().zip(poses) {
                    let pose = polysect::kernel::Pose::from_angle(angle, [tx, ty]).expect("finite");
                    self.scene.set_pose(id, pose).expect("a convex image");
                }
            }
            Frame::Nothing => {}
        }
        self.scene.intersecting_pairs().len()
    }
}

/// parry2d's side: local shapes, poses, points (for deformation), and the tree.
struct Parry {
    shapes: Vec<ParryPolygon>,
    poses: Vec<Pose>,
    points: Vec<Vec<Vector>>,
    aabbs: Vec<Aabb>,
    bvh: Bvh,
    workspace: BvhWorkspace,
    candidates: Vec<(u32, u32)>,
}

fn parry_shape(points: Vec<Vector>) -> ParryPolygon {
    ParryPolygon::from_convex_polyline_unmodified(points).expect("a valid convex polygon")
}

impl Parry {
    fn new(mirror: &Mirror) -> Parry {
        let shapes = if mirror.rotating {
            &mirror.local
        } else {
            &mirror.points
        };
        let points: Vec<Vec<Vector>> = shapes
            .iter()
            .map(|p| p.iter().map(|v| Vector::new(v.x, v.y)).collect())
            .collect();
        let shapes = points.iter().map(|p| parry_shape(p.clone())).collect();
        let mut parry = Parry {
            shapes,
            poses: if mirror.rotating {
                mirror
                    .position
                    .iter()
                    .map(|&(x, y)| Pose::new(Vector::new(x, y), 0.0))
                    .collect()
            } else {
                vec![Pose::identity(); points.len()]
            },
            points,
            aabbs: Vec::new(),
            bvh: Bvh::new(),
            workspace: BvhWorkspace::default(),
            candidates: Vec::new(),
        };
        parry.rebuild_tree();
        parry
    }

    fn rebuild_tree(&mut self) {
        self.aabbs.clear();
        self.aabbs
            .extend(self.shapes.iter().zip(&self.poses).map(|(s, p)| s.aabb(p)));
        self.bvh = Bvh::from_leaves(BvhBuildStrategy::Binned, &self.aabbs);
    }

    fn frame(&mut self, frame: &Frame) -> usize {
        match frame {
            Frame::Translate(steps) => {
                for (pose, &(dx, dy)) in self.poses.iter_mut().zip(steps) {
                    pose.translation += Vector::new(dx, dy);
                }
                self.rebuild_tree();
            }
            Frame::Moves(moves) => {
                let mut changed = vec![false; self.points.len()];
                for &(k, i, to) in moves {
                    self.points[k][i] = Vector::new(to.x, to.y);
                    changed[k] = true;
                }
                for (k, c) in changed.into_iter().enumerate() {
                    if c {
                        self.shapes[k] = parry_shape(self.points[k].clone());
                    }
                }
                self.rebuild_tree();
            }
            Frame::Poses(poses) => {
                for (pose, &(angle, tx, ty)) in self.poses.iter_mut().zip(poses) {
                    *pose = Pose::new(Vector::new(tx, ty), angle);
                }
                self.rebuild_tree();
            }
            Frame::Nothing => {}
        }
        self.candidates.clear();
        let candidates = &mut self.candidates;
        self.bvh
            .traverse_bvtt_single_tree::<false>(&mut self.workspace, &mut |a, b| candidates.push((a, b)));
        self.candidates
            .iter()
            .filter(|&&(a, b)| {
                let (a, b) = (a as usize, b as usize);
                intersection_test(&self.poses[a], &self.shapes[a], &self.poses[b], &self.shapes[b])
                    .expect("supported shapes")
                    .intersecting
            })
            .count()
    }
}

/// The three sides criterion times: polysect with warm starts, polysect as it comes
/// (without them), parry2d.
const SIDES: [&str; 3] = ["polysect-warm", "polysect", "parry2d"];

/// Every side and the mirror; every frame is applied to each in turn.
struct World {
    workload: Workload,
    mirror: Mirror,
    ours: Ours,
    /// The same scene as it comes: warm starts off.
    cold: Ours,
    parry: Parry,
    frames: u64,
    /// Per frame, each side's time (in [`SIDES`] order), whichever side criterion timed:
    /// the paired comparison printed after each workload.
    paired: Vec<[Duration; 3]>,
    /// Frames on which parry2d's count differed from the exact one (rotating scenes).
    parry_differs: u64,
}

fn workload_is_rotating(w: &Workload) -> bool {
    matches!(w.motion, Motion::Rotate)
}

impl World {
    fn new(workload: Workload, costs: CostModel) -> World {
        let mirror = Mirror::new(&workload, 0x5ce4e ^ workload.count as u64);
        let mut ours = Ours::new(&mirror, costs);
        ours.scene.set_warm_starts(true);
        let mut world = World {
            workload,
            ours,
            cold: Ours::new(&mirror, costs),
            parry: Parry::new(&mirror),
            mirror,
            frames: 0,
            paired: Vec::new(),
            parry_differs: 0,
        };
        // The first frame, checked against brute force.
        let frame = world.mirror.step(workload.motion);
        let (a, b, c) = (
            world.ours.frame(&frame),
            world.cold.frame(&frame),
            world.parry.frame(&frame),
        );
        let want = world.mirror.brute_force_pairs();
        assert_eq!(a, want, "{}: polysect (warm) against brute force", workload.name);
        assert_eq!(b, want, "{}: polysect against brute force", workload.name);
        if workload_is_rotating(&workload) {
            // parry rounds its own rotated coordinates (and uses tolerances): report.
            if c != want {
                eprintln!(
                    "{}: parry2d finds {c} pairs on the first frame, exactly {want}",
                    workload.name
                );
            }
        } else {
            assert_eq!(c, want, "{}: parry2d against brute force", workload.name);
        }
        eprintln!("{}: {want} intersecting pairs on the first frame", workload.name);
        world
    }

    fn side_frame(&mut self, side: usize, frame: &Frame) -> usize {
        match side {
            0 => self.ours.frame(frame),
            1 => self.cold.frame(frame),
            _ => self.parry.frame(frame),
        }
    }

    /// Runs `iters` frames, every side on each (in an order rotating with the frame, so
    /// that none always runs after the same other); returns side `timed`'s total for
    /// criterion, keeps every side's time for the paired comparison and compares the
    /// counts.
    fn run(&mut self, iters: u64, timed: usize) -> Duration {
        let mut total = Duration::ZERO;
        for _ in 0..iters {
            let frame = self.mirror.step(self.workload.motion);
            let mut times = [Duration::ZERO; 3];
            let mut counts = [0; 3];
            for i in 0..3 {
                let side = (i + self.frames as usize) % 3;
                let start = Instant::now();
                counts[side] = self.side_frame(side, &frame);
                times[side] = start.elapsed().max(Duration::from_nanos(1));
            }
            total += times[timed];
            self.paired.push(times);
            self.frames += 1;
            if counts[2] != counts[1] {
                self.parry_differs += 1;
            }
            assert!(
                counts[0] == counts[1] && (counts[1] == counts[2] || workload_is_rotating(&self.workload)),
                "{} frame {}: pair counts differ: {counts:?} ({SIDES:?})",
                self.workload.name,
                self.frames
            );
        }
        total
    }

    /// The paired comparison over every frame run so far: each side's mean time per
    /// frame over the same frames, ratios of the totals and medians of the per-frame
    /// ratios.
    fn paired_report(&self) -> String {
        let frames = self.paired.len().max(1) as f64;
        let ms = |i: usize| self.paired.iter().map(|t| t[i].as_secs_f64()).sum::<f64>() * 1e3 / frames;
        let median = |i: usize, j: usize| {
            let mut r: Vec<f64> = self
                .paired
                .iter()
                .map(|t| t[i].as_secs_f64() / t[j].as_secs_f64())
                .collect();
            r.sort_by(f64::total_cmp);
            r.get(r.len() / 2).copied().unwrap_or(f64::NAN)
        };
        let (warm, cold, parry) = (ms(0), ms(1), ms(2));
        let st = self.ours.scene.stats();
        let ws = self.ours.scene.warm_stats();
        let per = |x: u64| x as f64 / (self.frames + 1) as f64;
        format!(
            "{}: polysect-warm routes per frame: {:.0} box rejects, {:.0} array, {:.0} linear, {:.0} sampled tests, {:.1} conversions; warm starts {:.0} hits, {:.1} misses, {:.1} fills\n\
             {}: paired over {} frames: polysect-warm {:.3} ms, polysect {:.3} ms, parry2d {:.3} ms per frame; \
             warm/polysect {:.3} (median per frame {:.3}), warm/parry2d {:.2} (median {:.2}), polysect/parry2d {:.2} (median {:.2}); \
             parry2d's count differed on {} frames",
            self.workload.name,
            per(st.box_rejects),
            per(st.array_tests),
            per(st.linear_tests),
            per(st.sampled_tests),
            per(st.conversions),
            per(ws.hits),
            per(ws.misses),
            per(ws.fills),
            self.workload.name,
            self.paired.len(),
            warm,
            cold,
            parry,
            warm / cold,
            median(0, 1),
            warm / parry,
            median(0, 2),
            cold / parry,
            median(1, 2),
            self.parry_differs,
        )
    }
}

fn scene(c: &mut Criterion) {
    // `POLYSECT_SCENE_DEFAULT_COSTS=1` skips the calibration (for profiling runs).
    let costs = if std::env::var_os("POLYSECT_SCENE_DEFAULT_COSTS").is_some() {
        CostModel::default()
    } else {
        Scene::new().calibrate()
    };
    eprintln!("cost model: {costs:?}");
    // A workload is built (and its first frame brute-forced) only when criterion's
    // filter, the first free argument, may select it: a plain filter (names and `|`) is
    // matched here as criterion would; any other regex builds every workload.
    let args: Vec<String> = std::env::args().skip(1).collect();
    let takes_value = |o: &str| {
        o.starts_with("--")
            && !o.contains('=')
            && !["--bench", "--test", "--list", "--exact", "--quick"].contains(&o)
    };
    let filter: Option<String> = (0..args.len())
        .find(|&i| !args[i].starts_with('-') && (i == 0 || !takes_value(&args[i - 1])))
        .map(|i| args[i].clone())
        .filter(|f| f.chars().all(|c| c.is_ascii_alphanumeric() || "-_/|".contains(c)));
    for workload in WORKLOADS {
        let wanted = |side: &str| {
            let id = format!("scene/{}/{side}", workload.name);
            filter
                .as_deref()
                .is_none_or(|f| f.split('|').any(|alt| id.contains(alt)))
        };
        if !SIDES.iter().any(|s| wanted(s)) {
            continue;
        }
        let world = RefCell::new(World::new(workload, costs));
        let mut group = c.benchmark_group(format!("scene/{}", workload.name));
        group.sample_size(10);
        for (i, side) in SIDES.iter().enumerate() {
            group.bench_function(BenchmarkId::from_parameter(side), |b| {
                b.iter_custom(|iters| world.borrow_mut().run(iters, i))
            });
        }
        group.finish();
        // A workload filtered out on the command line ran no frame: nothing to pair.
        if !world.borrow().paired.is_empty() {
            eprintln!("{}", world.borrow().paired_report());
        }
    }
}

criterion_group!(benches, scene);
criterion_main!(benches);
