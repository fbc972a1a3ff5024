//! The scene protocol against a deliberately simple reference model.
//!
//! Long random op streams (messy adds, inserts valid or invalid by one ulp, collinear
//! inserts, removals down to the triangle, moves, translations near 2^1000 and among
//! subnormals, drops, stale names and ids, queries and `pairs` every few edits) run
//! through `SceneSession` under every strategy and both precisions, and through a
//! model that keeps a `Vec` of (id, point) per polygon, checks the whole polygon's
//! strict convexity exactly after every edit (O(n)), answers queries with `Linear` and
//! `pairs` by brute force over all pairs. Every reply must be equal; under the fast
//! kernel query answers may differ, and the test reports how often.
//!
//! Size: `POLYSECT_SCENE_OPS` ops per stream (default 2,500) × `POLYSECT_SCENE_SEEDS`
//! seeds (default 6) × 8 configurations.

use polysect::intersect::{ArrayIntersection, Linear};
use polysect::polygon::convex_hull;
use polysect::protocol::scene::{SceneOptions, SceneSession};
use polysect::store::Strategy;
use polysect::{ConvexPolygon, Exact, Fast, Kernel, Orientation, Point};
use rand::rngs::SmallRng;
use rand::seq::IndexedRandom;
use rand::{Rng, SeedableRng};
use serde_json::{Value, json};
use std::collections::BTreeMap;

fn env(name: &str, default: usize) -> usize {
    std::env::var(name)
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(default)
}

const BASE_SEED: u64 = 0xd1ff_5ce0;

// ---------------------------------------------------------------- the reference model

/// The reply the contract prescribes: a value, or an error (message not compared).
#[derive(Clone, Debug, PartialEq)]
enum Expect {
    Reply(Value),
    /// A reply holding at least these fields with these values (`stats`, whose other
    /// fields depend on the strategy).
    Fields(Value),
    Error,
}

/// Strictly convex, counter-clockwise, winding once: every turn strictly left
/// (exact), and the edge directions pass from the lower half-turn to the upper one
/// exactly once.
fn strictly_convex(v: &[Point]) -> bool {
    let n = v.len();
    if n < 3 || v.iter().any(|p| !p.is_finite()) {
        return false;
    }
    let turns_left = (0..n).all(|i| Exact.orient(v[i], v[(i + 1) % n], v[(i + 2) % n]) == Orientation::Ccw);
    let up = |a: Point, b: Point| b.y > a.y || (b.y == a.y && b.x > a.x);
    let windings = (0..n)
        .filter(|&i| !up(v[i], v[(i + 1) % n]) && up(v[(i + 1) % n], v[(i + 2) % n]))
        .count();
    turns_left && windings == 1
}

#[derive(Clone, Debug)]
struct RefPolygon {
    /// (id, point), counter-clockwise.
    vertices: Vec<(u64, Point)>,
    next_id: u64,
}

impl RefPolygon {
    fn points(&self) -> Vec<Point> {
        self.vertices.iter().map(|&(_, p)| p).collect()
    }

    fn position(&self, id: u64) -> Option<usize> {
        self.vertices.iter().position(|&(i, _)| i == id)
    }

    fn convex(&self) -> ConvexPolygon {
        ConvexPolygon::from_ccw_unchecked(self.points())
    }
}

#[derive(Default)]
struct Reference {
    polygons: BTreeMap<String, RefPolygon>,
}

fn pt(p: Point) -> Value {
    json!([p.x, p.y])
}

impl Reference {
    fn apply(&mut self, op: &Op) -> Expect {
        use Expect::*;
        let ok = || Reply(json!({"ok": true}));
        match op {
            Op::Add(name, points) | Op::Replace(name, points) => {
                if self.polygons.contains_key(name) != matches!(op, Op::Replace(..)) {
                    return Error;
                }
                let Ok(poly) = ConvexPolygon::new(points.iter().copied()) else {
                    return Error;
                };
                // Each survivor keeps the first input position holding its point (for a
                // valid polygon equal points form one cyclic run, whose first element
                // survives).
                let vertices: Vec<(u64, Point)> = poly
                    .vertices()
                    .iter()
                    .map(|&v| (points.iter().position(|&p| p == v).unwrap() as u64, v))
                    .collect();
                assert!(strictly_convex(poly.vertices()));
                self.polygons.insert(
                    name.clone(),
                    RefPolygon {
                        vertices,
                        next_id: points.len() as u64,
                    },
                );
                ok()
            }
            Op::Drop(name) => match self.polygons.remove(name) {
                Some(_) => ok(),
                None => Error,
            },
            Op::Insert(name, after, p) => {
                let Some(poly) = self.polygons.get_mut(name) else {
                    return Error;
                };
                let Some(i) = poly.position(*after) else {
                    return Error;
                };
                let mut trial = poly.vertices.clone();
                trial.insert(i + 1, (poly.next_id, *p));
                let pts: Vec<Point> = trial.iter().map(|&(_, q)| q).collect();
                if !strictly_convex(&pts) {
                    return Error;
                }
                poly.vertices = trial;
                poly.next_id += 1;
                Reply(json!({"vertex": poly.next_id - 1}))
            }
            Op::Remove(name, id) => {
                let Some(poly) = self.polygons.get_mut(name) else {
                    return Error;
                };
                match poly.position(*id) {
                    Some(i) if poly.vertices.len() > 3 => {
                        poly.vertices.remove(i);
                        ok()
                    }
                    _ => Error,
                }
            }
            Op::Move(name, id, to) => {
                let Some(poly) = self.polygons.get_mut(name) else {
                    return Error;
                };
                let Some(i) = poly.position(*id) else {
                    return Error;
                };
                let mut pts = poly.points();
                pts[i] = *to;
                if !strictly_convex(&pts) {
                    return Error;
                }
                poly.vertices[i].1 = *to;
                ok()
            }
            Op::Translate(name, by) => {
                let Some(poly) = self.polygons.get_mut(name) else {
                    return Error;
                };
                let pts: Vec<Point> = poly
                    .points()
                    .iter()
                    .map(|p| Point::new(p.x + by.x, p.y + by.y))
                    .collect();
                if !by.is_finite() || !strictly_convex(&pts) {
                    return Error;
                }
                for (v, p) in poly.vertices.iter_mut().zip(pts) {
                    v.1 = p;
                }
                ok()
            }
            Op::Intersects(a, b) => match (self.polygons.get(a), self.polygons.get(b)) {
                (Some(p), Some(q)) => {
                    Reply(json!({"intersects": Linear.intersects(&p.convex(), &q.convex())}))
                }
                _ => Error,
            },
            Op::Pairs => {
                let names: Vec<&String> = self.polygons.keys().collect(); // string order
                let mut pairs = Vec::new();
                for (i, a) in names.iter().enumerate() {
                    for b in &names[i + 1..] {
                        let (p, q) = (&self.polygons[*a], &self.polygons[*b]);
                        if Linear.intersects(&p.convex(), &q.convex()) {
                            pairs.push(json!([a, b]));
                        }
                    }
                }
                Reply(json!({ "pairs": pairs }))
            }
            Op::Vertices(name) => {
                let Some(poly) = self.polygons.get(name) else {
                    return Error;
                };
                let start = (0..poly.vertices.len())
                    .min_by_key(|&i| poly.vertices[i].0)
                    .unwrap();
                let mut v = poly.vertices.clone();
                v.rotate_left(start);
                Reply(json!({
                    "ids": v.iter().map(|&(i, _)| i).collect::<Vec<_>>(),
                    "points": v.iter().map(|&(_, p)| pt(p)).collect::<Vec<_>>(),
                }))
            }
            Op::Names => Reply(json!({"names": self.polygons.keys().collect::<Vec<_>>()})),
            Op::Meeting(name) => {
                let Some(p) = self.polygons.get(name) else {
                    return Error;
                };
                let names: Vec<&String> = self
                    .polygons
                    .iter()
                    .filter(|&(other, q)| other != name && Linear.intersects(&p.convex(), &q.convex()))
                    .map(|(other, _)| other)
                    .collect();
                Reply(json!({ "names": names }))
            }
            Op::Bbox(name) => {
                let Some(p) = self.polygons.get(name) else {
                    return Error;
                };
                let pts = p.points();
                let fold =
                    |f: fn(f64, f64) -> f64, c: fn(&Point) -> f64| pts.iter().map(c).reduce(f).unwrap();
                Reply(json!({
                    "min": [fold(f64::min, |p| p.x), fold(f64::min, |p| p.y)],
                    "max": [fold(f64::max, |p| p.x), fold(f64::max, |p| p.y)],
                }))
            }
            Op::Contains(name, x) => {
                let Some(p) = self.polygons.get(name) else {
                    return Error;
                };
                // Closed and counter-clockwise: inside iff strictly right of no edge.
                let v = p.points();
                let n = v.len();
                let inside = (0..n).all(|i| Exact.orient(v[i], v[(i + 1) % n], *x) != Orientation::Cw);
                Reply(json!({ "contains": inside }))
            }
            Op::Stats => Fields(json!({
                "polygons": self.polygons.len(),
                "vertices": self.polygons.values().map(|p| p.vertices.len()).sum::<usize>(),
                "posed": 0,
            })),
            Op::Clear => {
                self.polygons.clear();
                ok()
            }
            Op::Raw(_) => Error,
        }
    }
}

// ---------------------------------------------------------------- ops and their lines

#[derive(Clone, Debug)]
enum Op {
    Add(String, Vec<Point>),
    Drop(String),
    Insert(String, u64, Point),
    Remove(String, u64),
    Move(String, u64, Point),
    Translate(String, Point),
    Intersects(String, String),
    Pairs,
    Vertices(String),
    Replace(String, Vec<Point>),
    Names,
    Meeting(String),
    Bbox(String),
    Contains(String, Point),
    Stats,
    Clear,
    /// A line the contract refuses (its text).
    Raw(String),
}

impl Op {
    fn line(&self, id: Option<&Value>) -> String {
        let mut v = match self {
            Op::Add(name, points) => {
                json!({"op": "add", "name": name, "points": points.iter().map(|&p| pt(p)).collect::<Vec<_>>()})
            }
            Op::Drop(name) => json!({"op": "drop", "name": name}),
            Op::Insert(name, after, p) => {
                json!({"op": "insert", "name": name, "after": after, "point": pt(*p)})
            }
            Op::Remove(name, id) => json!({"op": "remove", "name": name, "vertex": id}),
            Op::Move(name, id, to) => json!({"op": "move", "name": name, "vertex": id, "to": pt(*to)}),
            Op::Translate(name, by) => json!({"op": "translate", "name": name, "by": pt(*by)}),
            Op::Intersects(a, b) => json!({"op": "intersects", "a": a, "b": b}),
            Op::Pairs => json!({"op": "pairs"}),
            Op::Vertices(name) => json!({"op": "vertices", "name": name}),
            Op::Replace(name, points) => {
                json!({"op": "replace", "name": name, "points": points.iter().map(|&p| pt(p)).collect::<Vec<_>>()})
            }
            Op::Names => json!({"op": "names"}),
            Op::Meeting(name) => json!({"op": "meeting", "name": name}),
            Op::Bbox(name) => json!({"op": "bbox", "name": name}),
            Op::Contains(name, p) => json!({"op": "contains", "name": name, "point": pt(*p)}),
            Op::Stats => json!({"op": "stats"}),
            Op::Clear => json!({"op": "clear"}),
            Op::Raw(text) => return text.clone(),
        };
        if let Some(id) = id {
            v["id"] = id.clone();
        }
        v.to_string()
    }

    fn kind(&self) -> &'static str {
        match self {
            Op::Add(..) => "add",
            Op::Drop(..) => "drop",
            Op::Insert(..) => "insert",
            Op::Remove(..) => "remove",
            Op::Move(..) => "move",
            Op::Translate(..) => "translate",
            Op::Intersects(..) => "intersects",
            Op::Pairs => "pairs",
            Op::Vertices(..) => "vertices",
            Op::Replace(..) => "replace",
            Op::Names => "names",
            Op::Meeting(..) => "meeting",
            Op::Bbox(..) => "bbox",
            Op::Contains(..) => "contains",
            Op::Stats => "stats",
            Op::Clear => "clear",
            Op::Raw(..) => "raw",
        }
    }

    fn is_query(&self) -> bool {
        matches!(
            self,
            Op::Intersects(..) | Op::Pairs | Op::Meeting(..) | Op::Contains(..)
        )
    }
}

// ---------------------------------------------------------------- the generator

/// A lattice at some scale: point (i, j) is (origin + i·step, origin + j·step), exact
/// for the small integers used.
#[derive(Clone, Copy, Debug)]
struct Frame {
    origin: f64,
    step: f64,
}

fn frames() -> [Frame; 5] {
    [
        Frame {
            origin: 0.0,
            step: 1.0,
        },
        Frame {
            origin: 0.0,
            step: 0.25,
        },
        // Near 2^1000: the step, 2^960, is 2^12 ulps of the origin.
        Frame {
            origin: 2f64.powi(1000),
            step: 2f64.powi(960),
        },
        // Subnormals: multiples of 2^-1070.
        Frame {
            origin: 0.0,
            step: 2f64.powi(-1070),
        },
        // Tiny normal numbers.
        Frame {
            origin: 0.0,
            step: 1.0e-300,
        },
    ]
}

fn gcd(a: i64, b: i64) -> i64 {
    if b == 0 { a.abs() } else { gcd(b, a % b) }
}

struct Gen {
    rng: SmallRng,
    dropped: Vec<String>,
}

impl Gen {
    fn name(&mut self) -> String {
        const POOL: [&str; 7] = ["a", "b", "c", "d", "e", "é \"q\"", "a\\b\u{1F600}"];
        (*POOL.choose(&mut self.rng).unwrap()).to_string()
    }

    /// A convex lattice polygon (lattice coordinates), counter-clockwise.
    fn lattice_polygon(&mut self) -> Vec<(i64, i64)> {
        let r = self.rng.random_range(2..=7);
        let (cx, cy) = (self.rng.random_range(-6..=6), self.rng.random_range(-6..=6));
        loop {
            let n = self.rng.random_range(3..=12);
            let pts: Vec<Point> = (0..n)
                .map(|_| {
                    Point::new(
                        (cx + self.rng.random_range(-r..=r)) as f64,
                        (cy + self.rng.random_range(-r..=r)) as f64,
                    )
                })
                .collect();
            if let Ok(h) = convex_hull(&pts) {
                return h.vertices().iter().map(|p| (p.x as i64, p.y as i64)).collect();
            }
        }
    }

    /// Points for an `add`: valid or not, clockwise or not, with repeats, a closing
    /// point and collinear middles, in one of the frames or in general position.
    fn add_points(&mut self) -> Vec<Point> {
        let rng = &mut self.rng;
        if rng.random_bool(0.15) {
            // General position: an ellipse with arbitrary float coordinates.
            let n = rng.random_range(3..=16);
            let (cx, cy, a, b) = (
                rng.random_range(-5.0..5.0),
                rng.random_range(-5.0..5.0),
                rng.random_range(0.5..4.0),
                rng.random_range(0.5..4.0),
            );
            let t0 = rng.random_range(0.0..1.0);
            return (0..n)
                .map(|i| {
                    let t = std::f64::consts::TAU * (i as f64 + t0) / n as f64;
                    Point::new(cx + a * t.cos(), cy + b * t.sin())
                })
                .collect();
        }
        let frame = *frames().choose(rng).unwrap();
        let hull = self.lattice_polygon();
        let rng = &mut self.rng;
        let mut lattice: Vec<(i64, i64)> = Vec::new();
        let n = hull.len();
        for i in 0..n {
            let (a, b) = (hull[i], hull[(i + 1) % n]);
            lattice.push(a);
            // Collinear middles on lattice edges.
            let g = gcd(b.0 - a.0, b.1 - a.1);
            if g >= 2 && rng.random_bool(0.4) {
                let k = rng.random_range(1..g);
                lattice.push((a.0 + (b.0 - a.0) / g * k, a.1 + (b.1 - a.1) / g * k));
            }
            // Repeats.
            if rng.random_bool(0.15) {
                let last = *lattice.last().unwrap();
                lattice.push(last);
            }
        }
        match rng.random_range(0..14) {
            0 => {
                let half = lattice.len() / 2;
                lattice.swap(0, half); // out of order, or reflex
            }
            1 => {
                // An interior point as a vertex: reflex (or collinear).
                let (sx, sy) = hull.iter().fold((0, 0), |s, p| (s.0 + p.0, s.1 + p.1));
                let at = rng.random_range(0..lattice.len());
                lattice.insert(at, (sx / n as i64, sy / n as i64));
            }
            2 => {
                // A spike: back along the last edge.
                let (a, b) = (lattice[0], lattice[1]);
                lattice.insert(2, a);
                lattice.insert(3, b);
            }
            3 => lattice.truncate(2),
            4 => lattice = (0..5).map(|i| (i, 2 * i)).collect(),
            _ => {}
        }
        let rng = &mut self.rng;
        if rng.random_bool(0.5) {
            lattice.reverse(); // clockwise
        }
        let shift = rng.random_range(0..lattice.len());
        lattice.rotate_left(shift);
        if rng.random_bool(0.3) {
            lattice.push(lattice[0]); // closing point
        }
        lattice
            .iter()
            .map(|&(i, j)| {
                Point::new(
                    frame.origin + i as f64 * frame.step,
                    frame.origin + j as f64 * frame.step,
                )
            })
            .collect()
    }

    /// A live id of `poly` most of the time; else a removed, never-given or foreign id.
    fn vertex_id(&mut self, poly: Option<&RefPolygon>) -> u64 {
        let rng = &mut self.rng;
        match (poly, rng.random_range(0..10)) {
            (Some(p), 0..=7) => p.vertices.choose(rng).unwrap().0,
            (Some(p), 8) => p.next_id + rng.random_range(0..3),
            (Some(p), _) => (0..p.next_id).find(|i| p.position(*i).is_none()).unwrap_or(0),
            (None, _) => rng.random_range(0..20),
        }
    }

    /// A point near edge (a, b) of a polygon: exactly on it (when the lattice allows),
    /// its rounded midpoint nudged by one ulp in some direction, pushed outwards a
    /// little, or far away.
    fn near_edge(&mut self, a: Point, b: Point) -> Point {
        let rng = &mut self.rng;
        let mid = Point::new(a.x / 2.0 + b.x / 2.0, a.y / 2.0 + b.y / 2.0);
        let ulp = |x: f64, up: bool| if up { x.next_up() } else { x.next_down() };
        match rng.random_range(0..6) {
            0 => mid,
            1 => Point::new(ulp(mid.x, rng.random()), mid.y),
            2 => Point::new(mid.x, ulp(mid.y, rng.random())),
            3 => Point::new(ulp(mid.x, rng.random()), ulp(mid.y, rng.random())),
            4 => {
                // Outwards (to the right of a→b for a counter-clockwise polygon).
                let (dx, dy) = (b.x - a.x, b.y - a.y);
                let f = rng.random_range(0.01..0.4);
                Point::new(mid.x + dy * f, mid.y - dx * f)
            }
            _ => Point::new(
                mid.x * rng.random_range(-3.0..3.0),
                mid.y + rng.random_range(-9.0..9.0),
            ),
        }
    }

    fn translation(&mut self, poly: Option<&RefPolygon>) -> Point {
        let rng = &mut self.rng;
        let scale_of = |p: Option<&RefPolygon>| {
            p.and_then(|p| p.vertices.first())
                .map_or(1.0, |v| v.1.x.abs().max(v.1.y.abs()))
        };
        let s = scale_of(poly);
        let tiny = 5e-324;
        let two1000 = 2f64.powi(1000);
        match rng.random_range(0..9) {
            0 => Point::new(rng.random_range(-3..=3) as f64, rng.random_range(-3..=3) as f64),
            1 => Point::new(0.5, -0.25),
            2 => Point::new(two1000 * rng.random_range(-2..=2) as f64, 0.0),
            3 => Point::new(two1000.next_up(), -two1000),
            4 => Point::new(
                tiny * rng.random_range(-40..40) as f64,
                tiny * rng.random_range(-40..40) as f64,
            ),
            5 => Point::new(f64::MAX, 0.0),
            6 => Point::new(s * 0.5, -s),
            7 => Point::new(-s, s.next_up()),
            _ => Point::new(rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0)),
        }
    }

    fn op(&mut self, reference: &Reference, step: usize) -> Op {
        if step % 7 == 6 {
            return if self.rng.random_bool(0.5) {
                Op::Pairs
            } else {
                Op::Intersects(self.name(), self.name())
            };
        }
        let name = match self.rng.random_range(0..10) {
            0..=7 if !reference.polygons.is_empty() => reference
                .polygons
                .keys()
                .nth(self.rng.random_range(0..reference.polygons.len()))
                .unwrap()
                .clone(),
            8 if !self.dropped.is_empty() => self.dropped.choose(&mut self.rng).unwrap().clone(),
            _ => self.name(),
        };
        let poly = reference.polygons.get(&name).cloned();
        let r = self.rng.random_range(0..100);
        let few = reference.polygons.len() < 3;
        match r {
            _ if few && r < 40 => Op::Add(self.name(), self.add_points()),
            0..=9 => Op::Add(self.name(), self.add_points()),
            10..=12 => {
                self.dropped.push(name.clone());
                Op::Drop(name)
            }
            13..=38 => {
                let after = self.vertex_id(poly.as_ref());
                let point = match poly.as_ref().and_then(|p| p.position(after).map(|i| (p, i))) {
                    Some((p, i)) => {
                        let (a, b) = (p.vertices[i].1, p.vertices[(i + 1) % p.vertices.len()].1);
                        self.near_edge(a, b)
                    }
                    None => Point::new(1.0, 1.0),
                };
                Op::Insert(name, after, point)
            }
            39..=52 => Op::Remove(name.clone(), self.vertex_id(poly.as_ref())),
            53..=66 => {
                let id = self.vertex_id(poly.as_ref());
                let to = match poly.as_ref().and_then(|p| p.position(id).map(|i| (p, i))) {
                    Some((p, i)) => {
                        let n = p.vertices.len();
                        let (u, v, w) = (
                            p.vertices[(i + n - 1) % n].1,
                            p.vertices[i].1,
                            p.vertices[(i + 1) % n].1,
                        );
                        match self.rng.random_range(0..4) {
                            0 => self.near_edge(u, w),
                            1 => Point::new(v.x.next_up(), v.y.next_down()),
                            2 => Point::new(
                                v.x * 1.5 - u.x * 0.25 - w.x * 0.25,
                                v.y * 1.5 - u.y * 0.25 - w.y * 0.25,
                            ),
                            _ => self.near_edge(v, w),
                        }
                    }
                    None => Point::new(2.0, 2.0),
                };
                Op::Move(name, id, to)
            }
            67..=78 => {
                let by = self.translation(poly.as_ref());
                Op::Translate(name, by)
            }
            79..=83 => Op::Intersects(name, self.name()),
            84..=85 => Op::Vertices(name),
            86 => Op::Pairs,
            87 => Op::Names,
            88 => Op::Meeting(name),
            89 => Op::Bbox(name),
            90..=91 => {
                let point = self.probe(poly.as_ref());
                Op::Contains(name, point)
            }
            92 => Op::Replace(name, self.add_points()),
            93 if self.rng.random_bool(0.2) => {
                self.dropped.extend(reference.polygons.keys().cloned());
                Op::Clear
            }
            93 => Op::Stats,
            _ => Op::Raw(self.bad_line()),
        }
    }

    /// A point to test for containment in `poly`: a vertex, a point near an edge (on
    /// it, an ulp off it, outside it), a corner of its box, or anywhere.
    fn probe(&mut self, poly: Option<&RefPolygon>) -> Point {
        let Some(p) = poly else {
            return Point::new(0.0, 0.0);
        };
        let v = p.points();
        let i = self.rng.random_range(0..v.len());
        match self.rng.random_range(0..5) {
            0 => v[i],
            1 | 2 => self.near_edge(v[i], v[(i + 1) % v.len()]),
            3 => Point::new(
                v.iter().map(|p| p.x).fold(f64::INFINITY, f64::min),
                v.iter().map(|p| p.y).fold(f64::INFINITY, f64::min),
            ),
            _ => Point::new(
                v[i].x * self.rng.random_range(-2.0..2.0),
                v[i].y * self.rng.random_range(-2.0..2.0),
            ),
        }
    }

    /// A line the protocol must refuse without changing anything.
    fn bad_line(&mut self) -> String {
        const BAD: [&str; 14] = [
            r#"{"op": "contains", "name": "a", "point": [1]}"#,
            r#"{"op": "contains", "name": "a"}"#,
            r#"{"op": "replace", "name": "a"}"#,
            r#"{"op": "meeting", "name": "a", "certificate": true}"#,
            r#"{"op": "add", "name": "a", "points": [[0,0],[1,0],[0,1e400]]}"#,
            r#"{"op": "insert", "name": "a", "after": "0", "point": [1, 1]}"#,
            r#"{"op": "remove", "name": "a", "vertex": -1}"#,
            r#"{"op": "remove", "name": "a", "vertex": 1.5}"#,
            r#"{"op": "move", "name": 3, "vertex": 0, "to": [0, 0]}"#,
            r#"{"op": "translate", "name": "a", "by": [1]}"#,
            r#"{"op": "explode", "name": "a"}"#,
            r#"{"op": "drop"}"#,
            r#"["op", "drop", "name", "a"]"#,
            r#"{"op": "drop", "name": "a", "name": "b"}"#,
        ];
        (*BAD.choose(&mut self.rng).unwrap()).to_string()
    }
}

// ---------------------------------------------------------------- the comparison

#[derive(Default, Debug)]
struct Tally {
    lines: usize,
    accepted: BTreeMap<&'static str, usize>,
    refused: BTreeMap<&'static str, usize>,
    fast_query_differences: usize,
    fast_queries: usize,
}

fn run_stream(seed: u64, ops: usize, tally: &mut Tally) {
    let mut generator = Gen {
        rng: SmallRng::seed_from_u64(seed),
        dropped: Vec::new(),
    };
    let mut reference = Reference::default();
    let mut stream = Vec::new();
    for step in 0..ops {
        let op = generator.op(&reference, step);
        let id = match generator.rng.random_range(0..6) {
            _ if matches!(op, Op::Raw(_)) => None,
            0 => Some(json!(step)),
            1 => Some(json!(format!("line-{step}"))),
            _ => None,
        };
        let expect = reference.apply(&op);
        match &expect {
            Expect::Reply(_) | Expect::Fields(_) => *tally.accepted.entry(op.kind()).or_default() += 1,
            Expect::Error => *tally.refused.entry(op.kind()).or_default() += 1,
        }
        stream.push((op, id, expect));
    }
    tally.lines += stream.len();
    for strategy in Strategy::ALL {
        let options = SceneOptions {
            strategy,
            seed: Some(seed),
            certificate: false,
        };
        let mut exact = SceneSession::with_kernel(Exact, options);
        compare(&mut exact, &stream, false, seed, strategy, tally);
        let mut fast = SceneSession::with_kernel(Fast, options);
        compare(&mut fast, &stream, true, seed, strategy, tally);
    }
}

fn compare<K: Kernel>(
    session: &mut SceneSession<K>,
    stream: &[(Op, Option<Value>, Expect)],
    fast: bool,
    seed: u64,
    strategy: Strategy,
    tally: &mut Tally,
) {
    for (step, (op, id, expect)) in stream.iter().enumerate() {
        let line = op.line(id.as_ref());
        let reply = session.answer_line(line.as_bytes());
        let mut got: Value = serde_json::from_str(&reply).unwrap_or_else(|e| panic!("{e}: {reply}"));
        let at = || format!("seed {seed:#x}, {strategy:?}, fast {fast}, step {step}: {line}\n -> {reply}");
        if let Some(id) = id {
            assert_eq!(got.get("id"), Some(id), "{}", at());
            got.as_object_mut().unwrap().remove("id");
        }
        match expect {
            Expect::Error => {
                let keys: Vec<&String> = got.as_object().unwrap().keys().collect();
                assert_eq!(keys, ["error"], "{}", at());
                let message = got["error"].as_str().unwrap();
                assert!(message.starts_with(&format!("line {}", step + 1)), "{}", at());
            }
            Expect::Reply(want) if fast && op.is_query() => {
                tally.fast_queries += 1;
                if &got != want {
                    tally.fast_query_differences += 1;
                    assert!(got.get("error").is_none(), "{}", at());
                }
            }
            Expect::Reply(want) => assert_eq!(&got, want, "{}", at()),
            Expect::Fields(want) => {
                for (key, value) in want.as_object().unwrap() {
                    assert_eq!(got.get(key), Some(value), "{key}: {}", at());
                }
                for key in ["snapshots", "heap_bytes", "planner"] {
                    assert!(got.get(key).is_some(), "{key}: {}", at());
                }
            }
        }
        if step % 16 == 0 {
            session
                .debug_validate()
                .unwrap_or_else(|e| panic!("{e}\n{}", at()));
        }
    }
    session.debug_validate().unwrap();
}

#[test]
fn scene_protocol_matches_the_reference_model() {
    let ops = env("POLYSECT_SCENE_OPS", 2_500);
    let seeds = env("POLYSECT_SCENE_SEEDS", 6);
    let mut tally = Tally::default();
    for s in 0..seeds as u64 {
        run_stream(BASE_SEED + s, ops, &mut tally);
    }
    println!(
        "{} lines ({ops} ops × {seeds} seeds) × {} strategies × 2 precisions",
        tally.lines,
        Strategy::ALL.len()
    );
    println!("accepted: {:?}", tally.accepted);
    println!("refused:  {:?}", tally.refused);
    println!(
        "fast kernel: {} of {} query answers differ from the exact reference",
        tally.fast_query_differences, tally.fast_queries
    );
    // The streams must reach every kind of outcome, or the comparison proves little.
    for kind in [
        "add",
        "insert",
        "remove",
        "move",
        "translate",
        "intersects",
        "pairs",
        "vertices",
        "drop",
        "replace",
        "names",
        "meeting",
        "bbox",
        "contains",
        "stats",
    ] {
        let (a, r) = (
            tally.accepted.get(kind).copied().unwrap_or(0),
            tally.refused.get(kind).copied().unwrap_or(0),
        );
        assert!(a >= tally.lines / 500, "too few accepted {kind}: {a}");
        if !matches!(kind, "pairs" | "names" | "stats") {
            assert!(r > 0, "no refused {kind}");
        }
    }
    assert!(tally.accepted.get("clear").copied().unwrap_or(0) > 0, "no clear");
}
