//! The live page's message protocol: one [`Session`] per WebSocket connection turns
//! each message from the page into replies. Pure (no sockets), so it is unit-tested on
//! hostile input.
//!
//! # From the page (JSON text messages, at most [`MAX_MESSAGE_BYTES`] bytes)
//! - `{"op":"frame"}`: one frame; the polygons move unless paused.
//! - `{"op":"step"}`: one frame that moves the polygons even while paused.
//! - `{"op":"settings", ...}` with any of `polygons`, `vertices`, `seed` (a new scene),
//!   `strategy` (`planner|sampled|convert|cached`), `precision` (`exact|fast`), `speed`,
//!   `paused` (changed in place).
//! - `{"op":"move","scene":S,"polygon":I,"vertex":V,"to":[x,y]}`,
//!   `{"op":"insert","scene":S,"polygon":I,"after":V,"point":[x,y]}`,
//!   `{"op":"remove","scene":S,"polygon":I,"vertex":V}`: edits at world points (the
//!   pointer; the simulation maps them into the polygon's shape). `S`
//!   is the scene number the page is showing: an edit meant for an older scene is an
//!   error, never applied to the new one.
//! - `{"op":"trace","scene":S,"polygons":[A,B],"algorithm":"barba|dobkin|chazelle-dobkin|clm"}`:
//!   a step-through trace of the algorithm on polygons A (as P) and B (as Q) at their
//!   current positions (at most [`MAX_TRACE_VERTICES`](super::sim::MAX_TRACE_VERTICES)
//!   vertices each).
//!
//! Unknown fields and ops, wrong types, numbers out of range, messages too large or not
//! UTF-8, binary messages: an `error` reply, and nothing changes.
//!
//! # To the page
//! - `{"type":"settings", ...}`: the settings in force (after every `settings` message).
//! - `{"type":"scene","scene":S,"world":[w,h],"sizes":[n0,n1,...]}` followed by one
//!   binary message: every polygon's shape vertices as little-endian `f64` pairs,
//!   counter-clockwise, polygon after polygon; vertex `k` of a polygon has wire id `k`.
//! - `{"type":"frame", ...}`: a [`Frame`](super::sim::Frame): one pose per polygon, the
//!   pairs, figures; when its `world` is true (at most
//!   [`MAX_WORLD_POINTS`](super::sim::MAX_WORLD_POINTS) vertices in all) it is followed
//!   by one binary message of every world point, in the order of the scene's shapes.
//! - `{"type":"edit", ...}`: an accepted [`Edit`](super::sim::Edit) (its point in shape
//!   coordinates).
//! - `{"type":"refused","op":..,"polygon":I,"reason":"..."}`: the store refused an edit;
//!   the reason is the store error's text.
//! - `{"type":"trace", ...}`: a trace ([`super::trace::trace_json`]): the
//!   two polygons' vertices, the steps (kept and pruned index ranges, marks, text), the
//!   answer and the certificate; the last step carries the answer.
//! - `{"type":"error","message":"..."}`: the message was malformed or named nothing.

use super::sim::{EditFailure, Settings, Simulation, WORLD};
use super::trace::trace_json;
use crate::intersect::Algorithm;
use crate::kernel::Precision;
use crate::store::Strategy;
use serde::Deserialize;
use serde_json::json;

/// The largest message the page may send, in bytes (the transport closes the connection
/// above [`MAX_TRANSPORT_BYTES`]; between the two the message gets an error reply).
pub const MAX_MESSAGE_BYTES: usize = 4096;
/// Messages above this close the connection (WebSocket status 1009).
pub const MAX_TRANSPORT_BYTES: usize = 1 << 20;

/// The algorithms the step-through mode traces.
pub const TRACED: &[Algorithm] = &[
    Algorithm::Barba,
    Algorithm::Dobkin,
    Algorithm::ChazelleDobkin,
    Algorithm::Clm,
];

/// A reply to the page.
#[derive(Clone, Debug, PartialEq)]
pub enum Reply {
    /// A JSON text message.
    Text(String),
    /// A binary message (the scene's vertices).
    Binary(Vec<u8>),
}

#[derive(Deserialize, Debug)]
#[serde(tag = "op", rename_all = "lowercase", deny_unknown_fields)]
enum Request {
    Frame {},
    Step {},
    Settings {
        polygons: Option<usize>,
        vertices: Option<usize>,
        seed: Option<u64>,
        strategy: Option<String>,
        precision: Option<String>,
        speed: Option<f64>,
        paused: Option<bool>,
    },
    Move {
        scene: u64,
        polygon: usize,
        vertex: u32,
        to: [f64; 2],
    },
    Insert {
        scene: u64,
        polygon: usize,
        after: u32,
        point: [f64; 2],
    },
    Remove {
        scene: u64,
        polygon: usize,
        vertex: u32,
    },
    Trace {
        scene: u64,
        polygons: [usize; 2],
        algorithm: String,
    },
}

/// One page's state: its simulation and the scene counter.
#[derive(Debug)]
pub struct Session {
    sim: Simulation,
    scenes: u64,
}

impl Default for Session {
    fn default() -> Self {
        Session::new()
    }
}

impl Session {
    /// A session on the default scene ([`Settings::default`]).
    ///
    /// # Panics
    /// Never: the default settings are valid (a unit test builds them).
    pub fn new() -> Session {
        Session {
            sim: Simulation::new(Settings::default(), 1).expect("the default settings are valid"),
            scenes: 1,
        }
    }

    /// The session's simulation.
    pub fn simulation(&self) -> &Simulation {
        &self.sim
    }

    /// What the page needs first: the settings and the scene.
    pub fn start(&self) -> Vec<Reply> {
        let mut out = vec![self.settings_reply()];
        out.extend(self.scene_replies());
        out
    }

    /// Answers one text message from the page. Never panics on any input.
    pub fn handle(&mut self, message: &[u8]) -> Vec<Reply> {
        if message.len() > MAX_MESSAGE_BYTES {
            return vec![error_reply(format!(
                "message of {} bytes exceeds the limit of {MAX_MESSAGE_BYTES} bytes",
                message.len()
            ))];
        }
        let request: Request = match serde_json::from_slice(message) {
            Ok(r) => r,
            Err(e) => return vec![error_reply(format!("invalid message: {e}"))],
        };
        match request {
            Request::Frame {} => self.frame(!self.sim.settings().paused),
            Request::Step {} => self.frame(true),
            Request::Settings {
                polygons,
                vertices,
                seed,
                strategy,
                precision,
                speed,
                paused,
            } => {
                let old = self.sim.settings();
                let strategy = match strategy.as_deref().map(parse_strategy).transpose() {
                    Ok(s) => s.unwrap_or(old.strategy),
                    Err(e) => return vec![error_reply(e)],
                };
                let precision = match precision.as_deref().map(str::parse::<Precision>).transpose() {
                    Ok(p) => p.unwrap_or(old.precision),
                    Err(e) => return vec![error_reply(e)],
                };
                let new = Settings {
                    polygons: polygons.unwrap_or(old.polygons),
                    vertices: vertices.unwrap_or(old.vertices),
                    seed: seed.unwrap_or(old.seed),
                    strategy,
                    precision,
                    speed: speed.unwrap_or(old.speed),
                    paused: paused.unwrap_or(old.paused),
                };
                if let Err(e) = new.validate() {
                    return vec![error_reply(e)];
                }
                if (new.polygons, new.vertices, new.seed) != (old.polygons, old.vertices, old.seed) {
                    match Simulation::new(new, self.scenes + 1) {
                        Ok(sim) => {
                            self.scenes += 1;
                            self.sim = sim;
                            return self.start();
                        }
                        Err(e) => return vec![error_reply(e)],
                    }
                }
                if let Err(e) = self
                    .sim
                    .adjust(new.strategy, new.precision, new.speed, new.paused)
                {
                    return vec![error_reply(e)];
                }
                vec![self.settings_reply()]
            }
            Request::Move {
                scene,
                polygon,
                vertex,
                to,
            } => self.edit("move", scene, polygon, |s| s.move_vertex(polygon, vertex, to)),
            Request::Insert {
                scene,
                polygon,
                after,
                point,
            } => self.edit("insert", scene, polygon, |s| {
                s.insert_vertex(polygon, after, point)
            }),
            Request::Remove {
                scene,
                polygon,
                vertex,
            } => self.edit("remove", scene, polygon, |s| s.remove_vertex(polygon, vertex)),
            Request::Trace {
                scene,
                polygons,
                algorithm,
            } => vec![self.trace(scene, polygons, &algorithm)],
        }
    }

    fn edit(
        &mut self,
        op: &str,
        scene: u64,
        polygon: usize,
        f: impl FnOnce(&mut Simulation) -> Result<super::sim::Edit, EditFailure>,
    ) -> Vec<Reply> {
        if scene != self.sim.scene() {
            return vec![error_reply(format!(
                "the {op} is for scene {scene}, but scene {} is showing",
                self.sim.scene()
            ))];
        }
        vec![match f(&mut self.sim) {
            Ok(edit) => {
                let mut v = serde_json::to_value(&edit).expect("serialisable");
                v["type"] = json!("edit");
                Reply::Text(v.to_string())
            }
            Err(EditFailure::Refused(reason)) => Reply::Text(
                json!({"type": "refused", "op": op, "polygon": polygon, "reason": reason}).to_string(),
            ),
            Err(EditFailure::Invalid(m)) => error_reply(m),
        }]
    }

    fn trace(&self, scene: u64, [a, b]: [usize; 2], algorithm: &str) -> Reply {
        if scene != self.sim.scene() {
            return error_reply(format!(
                "the trace is for scene {scene}, but scene {} is showing",
                self.sim.scene()
            ));
        }
        let algorithm = match algorithm.parse::<Algorithm>() {
            Ok(a) if TRACED.contains(&a) => a,
            Ok(a) => {
                return error_reply(format!(
                    "no step-through for {a} (traced: barba, dobkin, chazelle-dobkin, clm)"
                ));
            }
            Err(e) => return error_reply(e),
        };
        match self.sim.trace(a, b, algorithm) {
            Ok((p, q, t)) => Reply::Text(trace_json(scene, [a, b], &p, &q, &t).to_string()),
            Err(e) => error_reply(e),
        }
    }

    fn frame(&mut self, advance: bool) -> Vec<Reply> {
        let f = self.sim.frame(advance);
        let mut v = serde_json::to_value(&f).expect("serialisable");
        v["type"] = json!("frame");
        let mut out = vec![Reply::Text(v.to_string())];
        if f.world {
            out.push(Reply::Binary(le_bytes(self.sim.world_coordinates())));
        }
        out
    }

    fn settings_reply(&self) -> Reply {
        let s = self.sim.settings();
        Reply::Text(
            json!({
                "type": "settings",
                "polygons": s.polygons,
                "vertices": s.vertices,
                "seed": s.seed,
                "strategy": s.strategy.name(),
                "precision": s.precision.name(),
                "speed": s.speed,
                "paused": s.paused,
            })
            .to_string(),
        )
    }

    fn scene_replies(&self) -> Vec<Reply> {
        let (sizes, coords) = self.sim.base_vertices();
        let bytes = le_bytes(coords);
        vec![
            Reply::Text(
                json!({"type": "scene", "scene": self.sim.scene(), "world": WORLD, "sizes": sizes})
                    .to_string(),
            ),
            Reply::Binary(bytes),
        ]
    }
}

fn le_bytes(coords: Vec<f64>) -> Vec<u8> {
    coords.into_iter().flat_map(f64::to_le_bytes).collect()
}

fn parse_strategy(s: &str) -> Result<Strategy, String> {
    Strategy::ALL
        .into_iter()
        .find(|x| x.name() == s)
        .ok_or_else(|| format!("unknown strategy '{s}' (valid: planner, sampled, convert, cached)"))
}

/// An `error` reply with `message`.
pub fn error_reply(message: String) -> Reply {
    Reply::Text(json!({"type": "error", "message": message}).to_string())
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::Value;

    fn texts(replies: &[Reply]) -> Vec<Value> {
        replies
            .iter()
            .filter_map(|r| match r {
                Reply::Text(t) => Some(serde_json::from_str(t).expect("replies are JSON")),
                Reply::Binary(_) => None,
            })
            .collect()
    }

    fn one(session: &mut Session, msg: &str) -> Value {
        let r = texts(&session.handle(msg.as_bytes()));
        assert_eq!(r.len(), 1, "{msg}: {r:?}");
        r.into_iter().next().expect("one reply")
    }

    fn assert_error_reply(session: &mut Session, msg: &[u8], contains: &str) {
        let r = texts(&session.handle(msg));
        assert_eq!(r.len(), 1);
        assert_eq!(r[0]["type"], "error", "{:?}", String::from_utf8_lossy(msg));
        let m = r[0]["message"].as_str().expect("a message");
        assert!(m.contains(contains), "{m:?} should contain {contains:?}");
    }

    #[test]
    fn start_sends_settings_then_the_scene_and_its_vertices() {
        let s = Session::new();
        let r = s.start();
        assert_eq!(r.len(), 3);
        let t = texts(&r);
        assert_eq!(t[0]["type"], "settings");
        assert_eq!(t[1]["type"], "scene");
        let sizes: usize = t[1]["sizes"]
            .as_array()
            .expect("sizes")
            .iter()
            .map(|n| n.as_u64().unwrap() as usize)
            .sum();
        match &r[2] {
            Reply::Binary(b) => assert_eq!(b.len(), sizes * 16),
            other => panic!("expected the vertices, got {other:?}"),
        }
    }

    #[test]
    fn malformed_messages_get_errors_and_change_nothing() {
        let mut s = Session::new();
        let frame0 = s.simulation().frame_number();
        for (msg, contains) in [
            (&b"not json"[..], "invalid message"),
            (b"", "invalid message"),
            (b"{", "invalid message"),
            (b"[1,2]", "invalid message"),
            (b"\"frame\"", "invalid message"),
            (b"{}", "missing field `op`"),
            (b"{\"op\":\"explode\"}", "unknown variant `explode`"),
            (b"{\"op\":7}", "invalid message"),
            (b"{\"op\":\"frame\",\"extra\":1}", "unknown field `extra`"),
            (
                b"{\"op\":\"move\",\"scene\":1,\"polygon\":0,\"vertex\":0}",
                "missing field `to`",
            ),
            (
                b"{\"op\":\"move\",\"scene\":1,\"polygon\":0,\"vertex\":0,\"to\":[1]}",
                "invalid message",
            ),
            (
                b"{\"op\":\"move\",\"scene\":1,\"polygon\":0,\"vertex\":0,\"to\":[1,2,3]}",
                "invalid message",
            ),
            (
                b"{\"op\":\"move\",\"scene\":1,\"polygon\":0,\"vertex\":0,\"to\":[\"1\",2]}",
                "invalid message",
            ),
            (
                b"{\"op\":\"move\",\"scene\":1,\"polygon\":0,\"vertex\":0,\"to\":[1e400,2]}",
                "invalid message",
            ),
            (
                b"{\"op\":\"move\",\"scene\":1,\"polygon\":-1,\"vertex\":0,\"to\":[1,2]}",
                "invalid message",
            ),
            (
                b"{\"op\":\"move\",\"scene\":1,\"polygon\":0,\"vertex\":4294967296,\"to\":[1,2]}",
                "invalid message",
            ),
            (
                b"{\"op\":\"remove\",\"scene\":1,\"polygon\":0.5,\"vertex\":0}",
                "invalid message",
            ),
            (b"{\"op\":\"settings\",\"polygons\":\"many\"}", "invalid message"),
            (b"{\"op\":\"settings\",\"polygons\":0}", "polygons must be"),
            (b"{\"op\":\"settings\",\"polygons\":1000000}", "polygons must be"),
            (b"{\"op\":\"settings\",\"vertices\":2}", "vertices must be"),
            (
                b"{\"op\":\"settings\",\"polygons\":1000,\"vertices\":65536}",
                "in all",
            ),
            (b"{\"op\":\"settings\",\"speed\":-3}", "speed must be"),
            (b"{\"op\":\"settings\",\"speed\":1e308}", "speed must be"),
            (
                b"{\"op\":\"settings\",\"strategy\":\"psychic\"}",
                "unknown strategy",
            ),
            (
                b"{\"op\":\"settings\",\"precision\":\"approximate\"}",
                "unknown precision",
            ),
            (b"\xff\xfe{\"op\":\"frame\"}", "invalid message"),
        ] {
            assert_error_reply(&mut s, msg, contains);
        }
        assert_eq!(s.simulation().frame_number(), frame0);
        assert_eq!(s.simulation().settings(), Settings::default());
    }

    #[test]
    fn huge_and_deeply_nested_messages_are_refused() {
        let mut s = Session::new();
        let huge = format!("{{\"op\":\"frame\",\"pad\":\"{}\"}}", "x".repeat(10 << 20));
        assert_error_reply(&mut s, huge.as_bytes(), "exceeds the limit");
        let deep = format!("{}{}", "[".repeat(4000), "]".repeat(4000));
        assert_error_reply(&mut s, &deep.as_bytes()[..MAX_MESSAGE_BYTES], "invalid message");
        let deep = "[".repeat(MAX_MESSAGE_BYTES);
        assert_error_reply(&mut s, deep.as_bytes(), "invalid message");
    }

    #[test]
    fn edits_with_stale_or_unknown_ids_are_errors() {
        let mut s = Session::new();
        let scene = s.simulation().scene();
        // A removal, then the same vertex again.
        let r = one(
            &mut s,
            &format!("{{\"op\":\"remove\",\"scene\":{scene},\"polygon\":0,\"vertex\":3}}"),
        );
        assert_eq!(r["type"], "edit");
        assert_eq!(r["kind"], "remove");
        assert_error_reply(
            &mut s,
            format!("{{\"op\":\"remove\",\"scene\":{scene},\"polygon\":0,\"vertex\":3}}").as_bytes(),
            "was removed",
        );
        assert_error_reply(
            &mut s,
            format!("{{\"op\":\"move\",\"scene\":{scene},\"polygon\":0,\"vertex\":3,\"to\":[5,5]}}")
                .as_bytes(),
            "was removed",
        );
        assert_error_reply(
            &mut s,
            format!("{{\"op\":\"insert\",\"scene\":{scene},\"polygon\":0,\"after\":3,\"point\":[5,5]}}")
                .as_bytes(),
            "was removed",
        );
        assert_error_reply(
            &mut s,
            format!("{{\"op\":\"remove\",\"scene\":{scene},\"polygon\":0,\"vertex\":4000}}").as_bytes(),
            "no vertex 4000",
        );
        assert_error_reply(
            &mut s,
            format!("{{\"op\":\"remove\",\"scene\":{scene},\"polygon\":36,\"vertex\":0}}").as_bytes(),
            "no polygon 36",
        );
        // A new scene: edits naming the old one are refused.
        let r = texts(&s.handle(b"{\"op\":\"settings\",\"polygons\":5}"));
        assert_eq!(r[1]["type"], "scene");
        assert_eq!(r[1]["scene"], scene + 1);
        assert_error_reply(
            &mut s,
            format!("{{\"op\":\"remove\",\"scene\":{scene},\"polygon\":0,\"vertex\":0}}").as_bytes(),
            "is for scene",
        );
    }

    #[test]
    fn refused_edits_carry_the_stores_reason() {
        let mut s = Session::new();
        let scene = s.simulation().scene();
        let centre = {
            let p = &s.simulation().current_vertices()[2];
            let n = p.len() as f64;
            p.iter().fold([0.0, 0.0], |c, v| [c[0] + v.x / n, c[1] + v.y / n])
        };
        let r = one(
            &mut s,
            &format!(
                "{{\"op\":\"move\",\"scene\":{scene},\"polygon\":2,\"vertex\":0,\"to\":[{},{}]}}",
                centre[0], centre[1]
            ),
        );
        assert_eq!(r["type"], "refused");
        assert!(
            r["reason"]
                .as_str()
                .expect("a reason")
                .contains("would make the polygon non-convex")
        );
    }

    #[test]
    fn frames_move_unless_paused_and_step_moves_anyway() {
        let mut s = Session::new();
        let f = one(&mut s, "{\"op\":\"frame\"}");
        assert_eq!(f["type"], "frame");
        assert_eq!(f["frame"], 1);
        assert_eq!(f["poses"].as_array().expect("poses").len(), 4 * 36);
        assert_eq!(f["world"], true);
        // The world points follow: the store's own coordinates, in the shapes' order.
        let replies = s.handle(b"{\"op\":\"step\"}");
        let Some(Reply::Binary(bytes)) = replies.get(1) else {
            panic!("a binary message of world points after the frame: {replies:?}")
        };
        let world: Vec<f64> = s
            .simulation()
            .current_vertices()
            .iter()
            .flatten()
            .flat_map(|p| [p.x, p.y])
            .collect();
        let sent: Vec<f64> = bytes
            .chunks_exact(8)
            .map(|b| f64::from_le_bytes(b.try_into().expect("8 bytes")))
            .collect();
        assert_eq!(sent, world);
        let r = one(
            &mut s,
            "{\"op\":\"settings\",\"paused\":true,\"strategy\":\"cached\",\"precision\":\"fast\"}",
        );
        assert_eq!(r["paused"], true);
        assert_eq!(r["strategy"], "cached");
        assert_eq!(r["precision"], "fast");
        assert_eq!(one(&mut s, "{\"op\":\"frame\"}")["frame"], 2);
        assert_eq!(one(&mut s, "{\"op\":\"step\"}")["frame"], 3);
        assert_eq!(one(&mut s, "{\"op\":\"frame\"}")["advanced"], false);
    }

    #[test]
    fn traces_end_in_the_librarys_answer_and_bad_requests_are_errors() {
        let mut session = Session::new();
        let scene = session.simulation().scene();
        let polygons = session.simulation().current_vertices();
        let p = crate::ConvexPolygon::new(polygons[0].iter().copied()).unwrap();
        let q = crate::ConvexPolygon::new(polygons[1].iter().copied()).unwrap();
        for name in ["barba", "dobkin", "chazelle-dobkin", "clm"] {
            let msg = format!(r#"{{"op":"trace","scene":{scene},"polygons":[0,1],"algorithm":"{name}"}}"#);
            let v = one(&mut session, &msg);
            assert_eq!(v["type"], "trace", "{v}");
            let steps = v["steps"].as_array().unwrap();
            let want = crate::intersect::Algorithm::Linear.intersects(crate::Precision::Exact, &p, &q);
            assert_eq!(steps.last().unwrap()["answer"], json!(want), "{name}");
            assert_eq!(v["answer"], json!(want));
            assert_eq!(v["p"].as_array().unwrap().len(), p.len());
        }
        for (msg, contains) in [
            (
                format!(r#"{{"op":"trace","scene":{scene},"polygons":[0,0],"algorithm":"barba"}}"#),
                "two different",
            ),
            (
                format!(r#"{{"op":"trace","scene":{scene},"polygons":[0,9999],"algorithm":"barba"}}"#),
                "no polygon 9999",
            ),
            (
                format!(r#"{{"op":"trace","scene":{scene},"polygons":[0,1],"algorithm":"linear"}}"#),
                "no step-through",
            ),
            (
                format!(r#"{{"op":"trace","scene":{scene},"polygons":[0,1],"algorithm":"nope"}}"#),
                "unknown algorithm",
            ),
            (
                format!(
                    r#"{{"op":"trace","scene":{},"polygons":[0,1],"algorithm":"barba"}}"#,
                    scene + 1
                ),
                "scene",
            ),
            (
                format!(r#"{{"op":"trace","scene":{scene},"polygons":[0],"algorithm":"barba"}}"#),
                "invalid",
            ),
        ] {
            assert_error_reply(&mut session, msg.as_bytes(), contains);
        }
        // Polygons too large to trace.
        let big = Settings {
            polygons: 2,
            vertices: crate::serve::sim::MAX_TRACE_VERTICES + 1,
            ..Settings::default()
        };
        let mut session = Session {
            sim: Simulation::new(big, 1).unwrap(),
            scenes: 1,
        };
        let msg = r#"{"op":"trace","scene":1,"polygons":[0,1],"algorithm":"barba"}"#;
        assert_error_reply(&mut session, msg.as_bytes(), "at most");
    }
}
