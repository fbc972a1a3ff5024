//! The `scene` protocol: one [`Scene`] driven by JSON Lines operations, one reply line
//! per input line.
//!
//! # Names and ids
//! Polygons are named by the caller (any JSON string). Vertices are named by integer
//! ids: `add` gives the k-th input point (from 0) the id k if it survives cleaning, and
//! no id otherwise (of consecutive equal points the first survives, a repeated closing
//! point is dropped in favour of the first, collinear middle points are dropped; the
//! input may be clockwise). Each accepted `insert` takes the next id: the first is the
//! number of points `add` was given, then one more each time; a refused insert takes
//! none. Ids are never reused.
//!
//! Each polygon keeps its ids in an ordered map from id to [`VertexId`], updated at
//! every insert and removal, so the session holds one entry per live vertex: memory
//! is bounded by the live polygons whatever the history. An edit is O(log n) on top of
//! the scene's O(1); `vertices` is O(n).
//!
//! # Queries and housekeeping beyond the contract's ops
//! docs/store.md ("The `scene` protocol's other ops") gives the wire format and the
//! decisions behind it:
//! * `{"op":"names"}` → `{"names":[...]}`, every name in string order (by code point);
//!   O(P log P) for P polygons.
//! * `{"op":"meeting","name":N}` → `{"names":[...]}`: the polygons other than N that
//!   intersect it, in string order ([`Scene::intersecting`], planned like `pairs`).
//! * `{"op":"bbox","name":N}` → `{"min":[x,y],"max":[x,y]}`: the tight box of the
//!   polygon (its world polygon when posed), O(n).
//! * `{"op":"contains","name":N,"point":[x,y]}` → `{"contains":true|false}`: boundary
//!   included, decided by the session's kernel ([`Scene::contains_point`]).
//! * `{"op":"replace","name":N,"points":[...]}` → `{"ok":true}`: `drop` then `add`
//!   under the same name in one line. Refused, changing nothing, unless N is in use and
//!   the points are valid as for `add`. The new polygon is a new polygon: its ids are
//!   given as by `add` (from 0), and it is not posed (its points are world points).
//! * `{"op":"stats"}` → `{"polygons":P,"vertices":V,"posed":k,"snapshots":s,
//!   "heap_bytes":b,"planner":{...}}`, the planner's counters ([`Scene::stats`]) inside;
//!   O(P).
//! * `{"op":"clear"}` → `{"ok":true}`: drops every polygon (names become free); the
//!   session's options and line numbers go on. O(P).
//!
//! # Precision
//! Edits are always validated with the exact kernel (that is how [`LinkedPolygon`]
//! edits work); the session's kernel `K` decides queries only (`intersects`, `pairs`,
//! `meeting`, `contains`, `contact`).

use super::json::shown;
use super::line::{Channel, Stop, each_line, json_string};
use super::{certified_answer_json, write_point};
use crate::intersect::verified_or_exact_linked;
use crate::kernel::{Exact, Kernel, Point, Pose};
use crate::polygon::{ConvexPolygon, EditError, LinkedPolygon, VertexId};
use crate::store::{PolygonId, Scene, SceneError, Strategy};
use std::collections::{BTreeMap, HashMap};
use std::fmt::Write as _;
use std::io::{self, Read, Write};

/// How a session answers; see [`SceneSession::with_kernel`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SceneOptions {
    /// How the scene answers queries (the planner by default).
    pub strategy: Strategy,
    /// A fixed seed for the sampled test's generator (reproducible runs); `None` seeds
    /// it from the operating system (the default; see docs/design.md, "Randomness").
    pub seed: Option<u64>,
    /// Answer `intersects` with a certificate as `check --certificate` does.
    pub certificate: bool,
}

/// A polygon of the session: its handle, its ids and the next id to give.
#[derive(Clone, Debug)]
struct Named {
    id: PolygonId,
    vertices: BTreeMap<u64, VertexId>,
    next_id: u64,
}

/// One `scene` session: a [`Scene`] plus the caller's names and vertex ids.
///
/// ```
/// use polysect::protocol::scene::{SceneOptions, SceneSession};
/// let mut session = SceneSession::new(SceneOptions::default());
/// let input = br#"{"op": "add", "name": "a", "points": [[0,0],[0,2],[2,2],[2,0]]}
/// {"op": "vertices", "name": "a"}
/// {"op": "insert", "name": "a", "after": 0, "point": [1, -1]}
/// {"id": "x", "op": "remove", "name": "b", "vertex": 0}
/// "#;
/// let mut out = Vec::new();
/// session.run(&input[..], &mut out)?;
/// let out = String::from_utf8(out).unwrap();
/// let lines: Vec<&str> = out.lines().collect();
/// assert_eq!(lines[0], r#"{"ok": true}"#);
/// // The input was clockwise: counter-clockwise from id 0 the ids run 0, 3, 2, 1.
/// assert_eq!(lines[1], r#"{"ids": [0,3,2,1], "points": [[0.0,0.0],[2.0,0.0],[2.0,2.0],[0.0,2.0]]}"#);
/// assert_eq!(lines[2], r#"{"vertex": 4}"#);
/// assert_eq!(lines[3], r#"{"id": "x", "error": "line 4: no polygon is named \"b\""}"#);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug)]
pub struct SceneSession<K: Kernel = Exact> {
    scene: Scene<K>,
    polygons: HashMap<String, Named>,
    names: HashMap<PolygonId, String>,
    certificate: bool,
    /// Lines answered so far (error messages number the next one from here).
    lines: u64,
}

impl SceneSession<Exact> {
    /// A session on the exact kernel.
    pub fn new(options: SceneOptions) -> Self {
        SceneSession::with_kernel(Exact, options)
    }
}

/// The object every line should be, for messages.
const SHAPE: &str = r#"{"op": ..., ...}"#;

const OPS: &str = "add, drop, insert, remove, move, translate, pose, replace, clear, intersects, contact, pairs, \
     meeting, contains, vertices, bbox, names, stats";

const KEYS: [&str; 13] = [
    "op",
    "name",
    "points",
    "after",
    "point",
    "vertex",
    "to",
    "by",
    "a",
    "b",
    "rotation",
    "translation",
    "certificate",
];

/// One line's fields, each typed as its key says wherever it appears.
#[derive(Debug, Default)]
struct OpLine {
    op: Option<String>,
    name: Option<String>,
    points: Option<Vec<Point>>,
    after: Option<u64>,
    point: Option<Point>,
    vertex: Option<u64>,
    to: Option<Point>,
    by: Option<Point>,
    a: Option<String>,
    b: Option<String>,
    rotation: Option<Point>,
    translation: Option<Point>,
    certificate: Option<bool>,
}

fn parse_op<R: Read, W: Write>(ch: &mut Channel<R, W>) -> Result<OpLine, Stop> {
    let mut l = OpLine::default();
    ch.object(SHAPE, &KEYS, |ch, key| {
        let field = KEYS[key];
        match key {
            0 => l.op = ch.string(field)?,
            1 => l.name = ch.string(field)?,
            2 => l.points = ch.points(field)?,
            3 => l.after = ch.integer(field)?,
            4 => l.point = ch.point(field)?,
            5 => l.vertex = ch.integer(field)?,
            6 => l.to = ch.point(field)?,
            7 => l.by = ch.point(field)?,
            8 => l.a = ch.string(field)?,
            9 => l.b = ch.string(field)?,
            10 => l.rotation = ch.point(field)?,
            11 => l.translation = ch.point(field)?,
            _ => l.certificate = ch.boolean(field)?,
        }
        Ok(())
    })?;
    Ok(l)
}

/// The ids of the cleaned polygon's vertices (`cleaned`, counter-clockwise from the first
/// surviving input point): each survivor's input index. Survivors appear in the input in
/// boundary order, forwards for counter-clockwise input and backwards for clockwise
/// input, each as the first point of its run of equal points (the closing repeats of the
/// first survivor come after every other survivor); the points in between are repeats or
/// collinear middle points, which lie strictly between two survivors and so equal none.
/// A greedy scan in either order therefore finds them. `None` if neither order matches
/// (not a cleaning of `input`).
fn survivor_ids(input: &[Point], cleaned: &[Point]) -> Option<Vec<u64>> {
    let m = cleaned.len();
    if m == 0 {
        return None;
    }
    [1, m - 1].into_iter().find_map(|step| {
        let mut ids = vec![0u64; m];
        let mut j = 0;
        for (k, &p) in input.iter().enumerate() {
            let at = (j * step) % m;
            if j < m && p == cleaned[at] {
                ids[at] = k as u64;
                j += 1;
            }
        }
        (j == m).then_some(ids)
    })
}

/// A validated polygon for `add` or `replace`: the linked polygon, its ids, the next id.
type Prepared = (LinkedPolygon, BTreeMap<u64, VertexId>, u64);

/// Validates and cleans `points` and gives each survivor its id (module docs).
fn prepare(points: Vec<Point>) -> Result<Prepared, String> {
    let polygon = ConvexPolygon::new(points.iter().copied()).map_err(|e| format!("points: {e}"))?;
    let ids = survivor_ids(&points, polygon.vertices())
        .ok_or("internal error: the cleaned polygon's vertices were not found in the input")?;
    let next_id = points.len() as u64;
    drop(points);
    let linked = LinkedPolygon::from_convex(&polygon);
    drop(polygon);
    // `from_convex` links the vertices in boundary order from `first`.
    let vertices: BTreeMap<u64, VertexId> = ids.into_iter().zip(linked.iter().map(|(v, _)| v)).collect();
    Ok((linked, vertices, next_id))
}

/// `"names": [...]`, each name a JSON string.
fn names_json<'a>(names: impl IntoIterator<Item = &'a str>) -> String {
    let mut out = String::from("\"names\": [");
    for (i, name) in names.into_iter().enumerate() {
        if i > 0 {
            out.push(',');
        }
        out.push_str(&json_string(name));
    }
    out.push(']');
    out
}

impl<K: Kernel> SceneSession<K> {
    /// A session whose queries use `kernel`, with the options' strategy, seed and
    /// certificates.
    pub fn with_kernel(kernel: K, options: SceneOptions) -> Self {
        let mut scene = Scene::with_kernel(kernel);
        scene.set_strategy(options.strategy);
        if let Some(seed) = options.seed {
            scene.seed(seed);
        }
        SceneSession {
            scene,
            polygons: HashMap::new(),
            names: HashMap::new(),
            certificate: options.certificate,
            lines: 0,
        }
    }

    /// The scene (read-only).
    pub fn scene(&self) -> &Scene<K> {
        &self.scene
    }

    /// Answers every line of `input` on `output`, one reply line per input line, in
    /// order, flushing whenever the next line is not already read. Lines are numbered
    /// on from the lines this session answered before.
    ///
    /// # Errors
    /// Only I/O errors; a bad line gets an error line and changes nothing.
    pub fn run<R: Read, W: Write>(&mut self, input: R, output: W) -> io::Result<()> {
        let mut ch = Channel::new(input, output);
        ch.set_line_number(self.lines);
        let mut lines = self.lines;
        let result = each_line(
            &mut ch,
            |ch| {
                lines += 1;
                parse_op(ch)
            },
            |ch, parsed| {
                // `pairs` streams its reply: its size is the answer's, not the scene's.
                if let Ok(OpLine { op: Some(op), .. }) = &parsed
                    && op == "pairs"
                {
                    ch.reply_streamed(|out| self.write_pairs(out))?;
                    return Ok(true);
                }
                let body = match parsed.and_then(|l| self.apply(l).map_err(|m| ch.located(None, &m))) {
                    Ok(body) => body,
                    Err(text) => format!("\"error\": {}", json_string(&text)),
                };
                ch.reply(&body)?;
                Ok(true)
            },
        );
        self.lines = lines;
        result
    }

    /// Answers one line (a newline in it ends it) and returns the reply without its
    /// newline.
    ///
    /// # Panics
    /// Never: the session reads a slice and writes a `Vec` (neither can fail), and
    /// every reply it writes is UTF-8.
    pub fn answer_line(&mut self, line: &[u8]) -> String {
        let line = line.split(|&b| b == b'\n').next().unwrap_or_default();
        let input: &[u8] = if line.is_empty() { b"\n" } else { line };
        let mut out = Vec::new();
        self.run(input, &mut out)
            .expect("reading a slice and writing a Vec cannot fail");
        let mut text = String::from_utf8(out).expect("replies are UTF-8");
        if text.ends_with('\n') {
            text.pop();
        }
        text
    }

    /// Number of vertex ids the session maps (one per live vertex).
    pub fn mapped_vertices(&self) -> usize {
        self.polygons.values().map(|n| n.vertices.len()).sum()
    }

    /// Every polygon by name with its vertices and their ids, counter-clockwise from the
    /// smallest id: what `vertices` would answer for each (for tests that check a refused
    /// line changed nothing).
    pub(crate) fn state(&self) -> BTreeMap<String, Vec<(u64, Point)>> {
        self.polygons
            .iter()
            .map(|(name, named)| {
                let ids: HashMap<VertexId, u64> = named.vertices.iter().map(|(&id, &v)| (v, id)).collect();
                let start = named.vertices.first_key_value().map(|(_, &v)| v);
                let walk: Vec<(u64, Point)> = match (self.scene.polygon(named.id), start) {
                    (Ok(poly), Some(start)) => poly
                        .iter_from(start)
                        .map(|it| {
                            it.map(|(v, p)| (ids.get(&v).copied().unwrap_or(u64::MAX), p))
                                .collect()
                        })
                        .unwrap_or_default(),
                    _ => Vec::new(),
                };
                (name.clone(), walk)
            })
            .collect()
    }

    /// Checks the scene's invariants and that the names and ids match it exactly: every
    /// name has a live polygon, every live vertex exactly one id, every id is below the
    /// polygon's next id.
    ///
    /// # Errors
    /// A description of the first mismatch found.
    pub fn debug_validate(&self) -> Result<(), String> {
        self.scene.debug_validate()?;
        if self.polygons.len() != self.scene.len() || self.names.len() != self.scene.len() {
            return Err(format!(
                "{} names, {} handles, {} polygons",
                self.polygons.len(),
                self.names.len(),
                self.scene.len()
            ));
        }
        for (name, named) in &self.polygons {
            if self.names.get(&named.id) != Some(name) {
                return Err(format!("{name:?}: the handle maps to another name"));
            }
            let poly = self
                .scene
                .polygon(named.id)
                .map_err(|e| format!("{name:?}: {e}"))?;
            if named.vertices.len() != poly.len() {
                return Err(format!(
                    "{name:?}: {} ids for {} vertices",
                    named.vertices.len(),
                    poly.len()
                ));
            }
            for (&id, &v) in &named.vertices {
                if !poly.has_vertex(v) || id >= named.next_id {
                    return Err(format!("{name:?}: id {id} is stale or beyond {}", named.next_id));
                }
            }
        }
        Ok(())
    }

    fn named(&self, name: &str) -> Result<&Named, String> {
        self.polygons
            .get(name)
            .ok_or_else(|| format!("no polygon is named {}", quoted(name)))
    }

    fn vertex(&self, name: &str, id: u64) -> Result<(PolygonId, VertexId), String> {
        let named = self.named(name)?;
        match named.vertices.get(&id) {
            Some(&v) => Ok((named.id, v)),
            None => Err(format!(
                "polygon {} has no vertex {id} ({})",
                quoted(name),
                if id < named.next_id {
                    "it was removed"
                } else {
                    "no such id was given"
                }
            )),
        }
    }

    /// Applies one parsed line: the reply body, or the error message (nothing changed).
    fn apply(&mut self, l: OpLine) -> Result<String, String> {
        let op = l.op.ok_or("missing field `op`")?;
        let need = |field: &str| format!("op `{op}` needs the field `{field}`");
        if l.certificate.is_some() && op != "intersects" {
            return Err(format!(
                "the field `certificate` applies only to op `intersects`, not to `{op}`"
            ));
        }
        match op.as_str() {
            "add" => {
                let name = l.name.ok_or_else(|| need("name"))?;
                let points = l.points.ok_or_else(|| need("points"))?;
                self.add(name, points)
            }
            "drop" => self.drop_polygon(&l.name.ok_or_else(|| need("name"))?),
            "insert" => {
                let name = l.name.ok_or_else(|| need("name"))?;
                let after = l.after.ok_or_else(|| need("after"))?;
                let point = l.point.ok_or_else(|| need("point"))?;
                self.insert(&name, after, point)
            }
            "remove" => {
                let name = l.name.ok_or_else(|| need("name"))?;
                let vertex = l.vertex.ok_or_else(|| need("vertex"))?;
                let (pid, v) = self.vertex(&name, vertex)?;
                self.scene
                    .remove_vertex(pid, v)
                    .map_err(|e| format!("remove refused: {}", reason(&e)))?;
                if let Some(named) = self.polygons.get_mut(&name) {
                    named.vertices.remove(&vertex);
                }
                Ok(OK.into())
            }
            "move" => {
                let name = l.name.ok_or_else(|| need("name"))?;
                let vertex = l.vertex.ok_or_else(|| need("vertex"))?;
                let to = l.to.ok_or_else(|| need("to"))?;
                let (pid, v) = self.vertex(&name, vertex)?;
                self.scene
                    .move_vertex(pid, v, to)
                    .map_err(|e| format!("move refused: {}", reason(&e)))?;
                Ok(OK.into())
            }
            "translate" => {
                let name = l.name.ok_or_else(|| need("name"))?;
                let by = l.by.ok_or_else(|| need("by"))?;
                let pid = self.named(&name)?.id;
                self.scene.translate(pid, by.x, by.y).map_err(|e| match e {
                    // Its message starts with "translation refused".
                    SceneError::Edit(_, EditError::RoundingBreaksConvexity { .. }) => reason(&e),
                    _ => format!("translate refused: {}", reason(&e)),
                })?;
                Ok(OK.into())
            }
            "pose" => {
                let name = l.name.ok_or_else(|| need("name"))?;
                let rotation = l.rotation.unwrap_or(Point::new(1.0, 0.0));
                let translation = l.translation.unwrap_or(Point::new(0.0, 0.0));
                let pid = self.named(&name)?.id;
                let pose = Pose::new([rotation.x, rotation.y], [translation.x, translation.y])
                    .map_err(|e| format!("pose refused: {e}"))?;
                self.scene
                    .set_pose(pid, pose)
                    .map_err(|e| format!("pose refused: {}", reason(&e)))?;
                Ok(OK.into())
            }
            "intersects" => {
                let a = l.a.ok_or_else(|| need("a"))?;
                let b = l.b.ok_or_else(|| need("b"))?;
                self.intersects(&a, &b, l.certificate.unwrap_or(self.certificate))
            }
            "contact" => {
                let a = l.a.ok_or_else(|| need("a"))?;
                let b = l.b.ok_or_else(|| need("b"))?;
                self.contact(&a, &b)
            }
            "pairs" => {
                // Answered by `write_pairs` as the pairs are found.
                let mut out = Vec::new();
                self.write_pairs(&mut out)
                    .map_err(|e| format!("internal error: {e}"))?;
                String::from_utf8(out).map_err(|e| format!("internal error: {e}"))
            }
            "vertices" => self.vertices(&l.name.ok_or_else(|| need("name"))?),
            "replace" => {
                let name = l.name.ok_or_else(|| need("name"))?;
                let points = l.points.ok_or_else(|| need("points"))?;
                self.replace(name, points)
            }
            "clear" => self.clear(),
            "names" => Ok(self.names_reply()),
            "meeting" => self.meeting(&l.name.ok_or_else(|| need("name"))?),
            "contains" => {
                let name = l.name.ok_or_else(|| need("name"))?;
                let point = l.point.ok_or_else(|| need("point"))?;
                self.contains(&name, point)
            }
            "bbox" => self.bbox(&l.name.ok_or_else(|| need("name"))?),
            "stats" => Ok(self.stats_reply()),
            other => Err(format!("unknown op {} (valid: {OPS})", quoted(other))),
        }
    }

    fn add(&mut self, name: String, points: Vec<Point>) -> Result<String, String> {
        if self.polygons.contains_key(&name) {
            return Err(format!("the name {} is in use", quoted(&name)));
        }
        let prepared = prepare(points)?;
        self.install(name, prepared);
        Ok(OK.into())
    }

    /// Gives `name` the prepared polygon (the name is free).
    fn install(&mut self, name: String, (linked, vertices, next_id): Prepared) {
        let id = self.scene.insert(linked);
        self.names.insert(id, name.clone());
        self.polygons.insert(
            name,
            Named {
                id,
                vertices,
                next_id,
            },
        );
    }

    /// `replace`: `drop` then `add` under the same name in one line, refused (changing
    /// nothing) unless the name is in use and the points are a valid polygon.
    fn replace(&mut self, name: String, points: Vec<Point>) -> Result<String, String> {
        self.named(&name)?;
        let prepared = prepare(points)?;
        self.drop_polygon(&name)?;
        self.install(name, prepared);
        Ok(OK.into())
    }

    /// `clear`: drops every polygon. O(polygons).
    fn clear(&mut self) -> Result<String, String> {
        for (_, named) in self.polygons.drain() {
            self.scene
                .remove(named.id)
                .map_err(|e| format!("internal error: {e}"))?;
        }
        self.names.clear();
        Ok(OK.into())
    }

    /// The names in string order (by Unicode code point, as Rust orders strings).
    fn sorted_names(&self) -> Vec<&str> {
        let mut names: Vec<&str> = self.polygons.keys().map(String::as_str).collect();
        names.sort_unstable();
        names
    }

    fn names_reply(&self) -> String {
        names_json(self.sorted_names())
    }

    /// `meeting`: the polygons intersecting `name` (itself not included), in string order.
    fn meeting(&mut self, name: &str) -> Result<String, String> {
        let id = self.named(name)?.id;
        let hits = self
            .scene
            .intersecting(id)
            .map_err(|e| format!("internal error: {e}"))?;
        let mut names: Vec<&str> = hits
            .iter()
            .filter_map(|h| self.names.get(h).map(String::as_str))
            .collect();
        names.sort_unstable();
        Ok(names_json(names))
    }

    /// `contains`: whether the polygon (its world polygon when posed) holds `point`,
    /// boundary included.
    fn contains(&mut self, name: &str, point: Point) -> Result<String, String> {
        let id = self.named(name)?.id;
        let inside = self
            .scene
            .contains_point(id, point)
            .map_err(|e| format!("internal error: {e}"))?;
        Ok(format!("\"contains\": {inside}"))
    }

    /// `bbox`: the tight bounding box of the polygon (its world polygon when posed). O(n).
    fn bbox(&self, name: &str) -> Result<String, String> {
        let id = self.named(name)?.id;
        let b = self
            .scene
            .polygon(id)
            .map_err(|e| format!("internal error: {e}"))?
            .bounding_box();
        let mut out = String::from("\"min\": ");
        write_point(&mut out, b.min);
        out.push_str(", \"max\": ");
        write_point(&mut out, b.max);
        Ok(out)
    }

    /// `stats`: counts of the scene and the planner's counters. O(polygons).
    fn stats_reply(&self) -> String {
        let scene = &self.scene;
        let (mut vertices, mut posed) = (0usize, 0usize);
        for id in scene.ids() {
            vertices += scene.polygon(id).map_or(0, LinkedPolygon::len);
            posed += usize::from(scene.pose(id).ok().flatten().is_some());
        }
        let s = scene.stats();
        format!(
            "\"polygons\": {}, \"vertices\": {vertices}, \"posed\": {posed}, \"snapshots\": {}, \
             \"heap_bytes\": {}, \"planner\": {{\"box_rejects\": {}, \"array_tests\": {}, \
             \"sampled_tests\": {}, \"linear_tests\": {}, \"conversions\": {}, \
             \"throwaway_conversions\": {}, \"invalidations\": {}}}",
            scene.len(),
            scene.snapshot_count(),
            scene.heap_bytes(),
            s.box_rejects,
            s.array_tests,
            s.sampled_tests,
            s.linear_tests,
            s.conversions,
            s.throwaway_conversions,
            s.invalidations,
        )
    }

    fn drop_polygon(&mut self, name: &str) -> Result<String, String> {
        let named = self
            .polygons
            .remove(name)
            .ok_or_else(|| format!("no polygon is named {}", quoted(name)))?;
        self.names.remove(&named.id);
        self.scene
            .remove(named.id)
            .map_err(|e| format!("internal error: {e}"))?;
        Ok(OK.into())
    }

    fn insert(&mut self, name: &str, after: u64, point: Point) -> Result<String, String> {
        let (pid, v) = self.vertex(name, after)?;
        let new = self
            .scene
            .insert_vertex(pid, v, point)
            .map_err(|e| format!("insert refused: {}", reason(&e)))?;
        let named = self
            .polygons
            .get_mut(name)
            .ok_or("internal error: the polygon vanished")?;
        let id = named.next_id;
        named.next_id += 1;
        named.vertices.insert(id, new);
        Ok(format!("\"vertex\": {id}"))
    }

    /// The `intersects` reply; with certificates (the line's `"certificate"`, else the
    /// session's option), the certificate for the pair (`a` is
    /// its P, `b` its Q) after the answer, in the format of `check --certificate`. Under
    /// a kernel other than the exact one the certificate is verified exactly before it
    /// is printed (O(n + m)) and replaced by the exact reference's if it fails, so every
    /// printed certificate verifies.
    fn intersects(&mut self, a: &str, b: &str, certificate: bool) -> Result<String, String> {
        let (ia, ib) = (self.named(a)?.id, self.named(b)?.id);
        if certificate {
            let internal = |e: SceneError| format!("internal error: {e}");
            let mut certificate = self.scene.intersects_certified(ia, ib).map_err(internal)?;
            if K::NAME != Exact::NAME {
                let (p, q) = (
                    self.scene.polygon(ia).map_err(internal)?,
                    self.scene.polygon(ib).map_err(internal)?,
                );
                certificate = verified_or_exact_linked(p, q, certificate);
            }
            return Ok(certified_answer_json(&certificate));
        }
        let hit = self
            .scene
            .intersects(ia, ib)
            .map_err(|e| format!("internal error: {e}"))?;
        Ok(format!("\"intersects\": {hit}"))
    }

    /// The `contact` reply: as a `polysect contact` line for the two polygons (`a` is P):
    /// the distance alone when they do not meet (the same reply, without the exact
    /// rationals), else the full contact.
    fn contact(&mut self, a: &str, b: &str) -> Result<String, String> {
        let (ia, ib) = (self.named(a)?.id, self.named(b)?.id);
        let internal = |e: SceneError| format!("internal error: {e}");
        if let Some(d) = self.scene.distance(ia, ib).map_err(internal)? {
            return Ok(super::contact::distance_json(&d));
        }
        let contact = self.scene.contact(ia, ib).map_err(internal)?;
        Ok(super::contact::contact_json(&contact))
    }

    /// Writes `"pairs": [...]` as the pairs are found: names in each pair in string
    /// order, pairs sorted. Memory: the names' order plus one polygon's candidates at a
    /// time (`Scene::intersecting_pairs_ordered`), whatever the number of pairs.
    fn write_pairs<W: Write>(&mut self, out: &mut W) -> io::Result<()> {
        let mut order: Vec<(&str, PolygonId)> = self
            .polygons
            .iter()
            .map(|(name, n)| (name.as_str(), n.id))
            .collect();
        order.sort_unstable_by(|x, y| x.0.cmp(y.0));
        let ids: Vec<PolygonId> = order.iter().map(|&(_, id)| id).collect();
        let names = &self.names;
        out.write_all(b"\"pairs\": [")?;
        let mut first = true;
        self.scene.intersecting_pairs_ordered(&ids, |a, later| {
            let Some(a) = names.get(&a) else {
                return Ok::<(), io::Error>(());
            };
            let a = json_string(a);
            for b in later {
                let Some(b) = names.get(b) else { continue };
                let sep = if first { "" } else { "," };
                first = false;
                write!(out, "{sep}[{a},{}]", json_string(b))?;
            }
            Ok(())
        })?;
        out.write_all(b"]")
    }

    fn vertices(&self, name: &str) -> Result<String, String> {
        let named = self.named(name)?;
        let poly = self
            .scene
            .polygon(named.id)
            .map_err(|e| format!("internal error: {e}"))?;
        let (_, &start) = named
            .vertices
            .first_key_value()
            .ok_or("internal error: a polygon without ids")?;
        let ids: HashMap<VertexId, u64> = named.vertices.iter().map(|(&id, &v)| (v, id)).collect();
        let walk = poly
            .iter_from(start)
            .map_err(|e| format!("internal error: {e}"))?;
        let mut id_text = String::from("\"ids\": [");
        let mut point_text = String::from("\"points\": [");
        for (i, (v, p)) in walk.enumerate() {
            if i > 0 {
                id_text.push(',');
                point_text.push(',');
            }
            let id = ids.get(&v).ok_or("internal error: a vertex without an id")?;
            let _ = write!(id_text, "{id}");
            write_point(&mut point_text, p);
        }
        id_text.push_str("], ");
        point_text.push(']');
        id_text.push_str(&point_text);
        if self.scene.pose(named.id).ok().flatten().is_some() {
            let shape = self
                .scene
                .shape(named.id)
                .map_err(|e| format!("internal error: {e}"))?;
            let walk = shape
                .iter_from(start)
                .map_err(|e| format!("internal error: {e}"))?;
            id_text.push_str(", \"shape\": [");
            for (i, (_, p)) in walk.enumerate() {
                if i > 0 {
                    id_text.push(',');
                }
                write_point(&mut id_text, p);
            }
            id_text.push(']');
        }
        Ok(id_text)
    }
}

const OK: &str = "\"ok\": true";

/// A name for a message: as a JSON string, shortened when long.
fn quoted(name: &str) -> String {
    json_string(&shown(name.as_bytes()))
}

/// Why the store refused an edit, in the session's terms: the edit's own message,
/// without the store's polygon handle (the session names polygons by the caller's names).
fn reason(e: &SceneError) -> String {
    match e {
        SceneError::Edit(_, edit) => edit.to_string(),
        SceneError::Pose(_, pose) => pose.to_string(),
        other => other.to_string(),
    }
}

#[cfg(test)]
mod tests;
