//! `polysect scene`, and what every line protocol of the binary promises: a reply per
//! line as soon as it is computed (a client can wait for each), hostile input answered
//! line by line, output failures and closed pipes, bounded memory in long sessions.

use crate::common::run;
use polysect::protocol::scene::{SceneOptions, SceneSession};
use serde_json::{Value, json};
use std::io::{self, BufRead, BufReader, Read, Write};
use std::process::{Command, Stdio};
use std::sync::mpsc;
use std::time::Duration;

fn replies(args: &[&str], input: &str) -> Vec<Value> {
    let (code, out, err) = run(args, input.as_bytes());
    assert_eq!(code, 0, "stderr: {err}");
    out.lines()
        .map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("{e}: {l}")))
        .collect()
}

/// The README's session.
const SESSION: &str = r#"{"op": "add", "name": "square", "points": [[0,0],[4,0],[4,4],[0,4]]}
{"op": "add", "name": "tri", "points": [[5,1],[5,1],[7,1],[6,3],[5,1]]}
{"id": 1, "op": "intersects", "a": "square", "b": "tri"}
{"op": "translate", "name": "tri", "by": [-1, 0]}
{"id": 2, "op": "intersects", "a": "square", "b": "tri"}
{"op": "insert", "name": "square", "after": 1, "point": [5, 2]}
{"op": "vertices", "name": "square"}
{"op": "pairs"}
{"op": "remove", "name": "square", "vertex": 7}
{"op": "move", "name": "tri", "vertex": 0, "to": [3, 3]}
{"op": "insert", "name": "tri", "after": 0, "point": [4.5, 2]}
{"op": "drop", "name": "square"}
{"op": "pairs"}
"#;

#[test]
fn the_readme_session() {
    for strategy in ["planner", "sampled", "convert", "cached"] {
        for precision in ["exact", "fast"] {
            let got = replies(
                &[
                    "scene",
                    "--strategy",
                    strategy,
                    "--precision",
                    precision,
                    "--seed",
                    "7",
                ],
                SESSION,
            );
            let want = [
                json!({"ok": true}),
                json!({"ok": true}),
                json!({"id": 1, "intersects": false}),
                json!({"ok": true}),
                json!({"id": 2, "intersects": true}),
                json!({"vertex": 4}),
                json!({"ids": [0, 1, 4, 2, 3], "points": [[0.0, 0.0], [4.0, 0.0], [5.0, 2.0], [4.0, 4.0], [0.0, 4.0]]}),
                json!({"pairs": [["square", "tri"]]}),
                json!({"error": "line 9: polygon \"square\" has no vertex 7 (no such id was given)"}),
                json!({"ok": true}),
                json!({"error": "line 11: insert refused: placing a vertex at (4.5, 2) would make the polygon non-convex"}),
                json!({"ok": true}),
                json!({"pairs": []}),
            ];
            assert_eq!(got, want, "{strategy} {precision}");
        }
    }
    // The session with the README's options shown in its text.
    let readme = include_str!("../../README.md");
    assert!(readme.contains(r#"{"op": "insert", "name": "square", "after": 1, "point": [5, 2]}"#));
    assert!(
        readme.contains(
            r#"{"ids": [0,1,4,2,3], "points": [[0.0,0.0],[4.0,0.0],[5.0,2.0],[4.0,4.0],[0.0,4.0]]}"#
        )
    );
}

#[test]
fn usage_errors() {
    let (code, _, err) = run(&["scene", "--strategy", "eager"], b"");
    assert_eq!(code, 2);
    assert!(err.contains("planner") && err.contains("cached"), "{err}");
    let (code, _, err) = run(&["scene", "--seed", "x"], b"");
    assert_eq!(code, 2, "{err}");
    let (code, _, err) = run(&["scene", "/no/such/file"], b"");
    assert_eq!(code, 1);
    assert!(err.contains("cannot read"), "{err}");
}

/// Runs the binary as a co-process: writes one line, waits (at most 30 s) for its reply,
/// and only then writes the next, keeping standard input open throughout.
fn converse(args: &[&str], lines: &[String]) -> Vec<String> {
    let mut child = Command::new(env!("CARGO_BIN_EXE_polysect"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("the binary starts");
    let mut stdin = child.stdin.take().unwrap();
    let stdout = child.stdout.take().unwrap();
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        for line in BufReader::new(stdout).lines() {
            if tx.send(line).is_err() {
                break;
            }
        }
    });
    let mut got = Vec::new();
    for line in lines {
        stdin.write_all(line.as_bytes()).unwrap();
        stdin.write_all(b"\n").unwrap();
        stdin.flush().unwrap();
        match rx.recv_timeout(Duration::from_secs(30)) {
            Ok(reply) => got.push(reply.unwrap()),
            Err(_) => {
                let _ = child.kill();
                panic!("no reply to {line:?} while standard input stays open");
            }
        }
    }
    drop(stdin);
    assert!(child.wait().unwrap().success());
    got
}

#[test]
fn each_reply_comes_while_the_input_stays_open() {
    let session: Vec<String> = SESSION.lines().map(String::from).collect();
    let got = converse(&["scene"], &session);
    assert_eq!(got.len(), session.len());
    assert_eq!(got[4], r#"{"id": 2, "intersects": true}"#);
    let pair = r#"{"id": "x", "p": [[0,0],[2,0],[2,2],[0,2]], "q": [[1,1],[3,1],[3,3]]}"#.to_string();
    let bad = "not json".to_string();
    let got = converse(&["check"], &[pair.clone(), bad.clone(), pair.clone()]);
    assert_eq!(got[0], r#"{"id": "x", "intersects": true}"#);
    assert!(
        got[1].starts_with(r#"{"error": "line 2, column 1: "#),
        "{}",
        got[1]
    );
    let got = converse(&["crossings"], &[pair.clone(), bad, pair]);
    assert_eq!(got[2], r#"{"id": "x", "points": [[2.0,1.0],[2.0,2.0]]}"#);
}

#[test]
fn bad_lines_get_one_error_line_each_and_change_nothing() {
    let add = r#"{"op": "add", "name": "a", "points": [[0,0],[1,0],[0,1]]}"#;
    let cases: &[(&str, &str)] = &[
        (r#"{"op": "explode", "name": "a"}"#, r#"unknown op \"explode\""#),
        (
            r#"{"op": 3, "name": "a"}"#,
            "`op` must be a string, found a number",
        ),
        (r#"{"name": "a"}"#, "missing field `op`"),
        (
            r#"{"op": "add", "name": "b"}"#,
            "op `add` needs the field `points`",
        ),
        (
            r#"{"op": "add", "points": [[0,0],[1,0],[0,1]]}"#,
            "op `add` needs the field `name`",
        ),
        (
            r#"{"op": "add", "name": "a", "points": [[5,5],[6,5],[5,6]]}"#,
            r#"the name \"a\" is in use"#,
        ),
        (
            r#"{"op": "add", "name": "b", "points": [[0,0],[1,1],[2,2]]}"#,
            "points: all vertices lie on one line",
        ),
        (
            r#"{"op": "add", "name": "b", "points": "[[0,0]]"}"#,
            "`points` must be an array",
        ),
        (
            r#"{"op": "add", "name": ["b"], "points": [[0,0],[1,0],[0,1]]}"#,
            "`name` must be a string, found an array",
        ),
        (
            r#"{"op": "drop", "name": null}"#,
            "`name` must be a string, found null",
        ),
        (
            r#"{"op": "drop", "name": 1}"#,
            "`name` must be a string, found a number",
        ),
        (r#"{"op": "drop", "name": "zz"}"#, r#"no polygon is named \"zz\""#),
        (
            r#"{"op": "insert", "name": "a", "after": "0", "point": [1, 1]}"#,
            "`after` must be an integer vertex id, found a string",
        ),
        (
            r#"{"op": "insert", "name": "a", "after": 0.0, "point": [1, 1]}"#,
            "without fraction or exponent",
        ),
        (
            r#"{"op": "insert", "name": "a", "after": 1e0, "point": [1, 1]}"#,
            "without fraction or exponent",
        ),
        (
            r#"{"op": "insert", "name": "a", "after": -1, "point": [1, 1]}"#,
            "an id is not negative",
        ),
        (
            r#"{"op": "insert", "name": "a", "after": 99999999999999999999999, "point": [1, 1]}"#,
            "no vertex has an id this large",
        ),
        (
            r#"{"op": "insert", "name": "a", "after": 0, "point": [1, -1, 0]}"#,
            "`point` must be a point [x, y], found 3 numbers",
        ),
        (
            r#"{"op": "insert", "name": "a", "after": 0, "point": {"x": 1, "y": -1}}"#,
            "`point` must be a point [x, y], found an object",
        ),
        (
            r#"{"op": "insert", "name": "a", "after": 0}"#,
            "op `insert` needs the field `point`",
        ),
        (
            r#"{"op": "insert", "name": "a", "after": 0, "point": [0.5, 0]}"#,
            "insert refused",
        ),
        (
            r#"{"op": "insert", "name": "a", "after": 3, "point": [1, -1]}"#,
            r#"polygon \"a\" has no vertex 3 (no such id was given)"#,
        ),
        (
            r#"{"op": "remove", "name": "a", "vertex": 0}"#,
            "remove refused: a polygon keeps at least 3 vertices",
        ),
        (
            r#"{"op": "remove", "name": "a", "vertex": true}"#,
            "`vertex` must be an integer vertex id, found a boolean",
        ),
        (
            r#"{"op": "move", "name": "a", "vertex": 1, "to": [-1, 2]}"#,
            "move refused",
        ),
        (
            r#"{"op": "move", "name": "a", "vertex": 1, "to": [1e400, 0]}"#,
            "beyond the f64 range",
        ),
        (
            r#"{"op": "translate", "name": "a", "by": [1.7976931348623157e308, 0]}"#,
            "translation refused: rounding",
        ),
        (
            r#"{"op": "translate", "name": "a", "by": [1267650600228229401496703205376, 0]}"#,
            "translation refused: rounding",
        ),
        (
            r#"{"op": "translate", "name": "a", "by": ["1", 0]}"#,
            "`by`[0] must be a number",
        ),
        (
            r#"{"op": "intersects", "a": "a"}"#,
            "op `intersects` needs the field `b`",
        ),
        (
            r#"{"op": "intersects", "a": "a", "b": "nope"}"#,
            r#"no polygon is named \"nope\""#,
        ),
        (
            r#"{"op": "vertices", "name": "a", "name": "a"}"#,
            "repeated key `name`",
        ),
        (
            r#"{"op": "drop", "name": "a", "op": "pairs"}"#,
            "repeated key `op`",
        ),
        (r#"["drop", "a"]"#, "expected a JSON object"),
        (
            r#"{"op": "drop", "name": "a"} {"op": "pairs"}"#,
            "trailing characters",
        ),
        ("", "empty line"),
        ("{\"op\": \"drop\", \"name\": \"\\ud800\"}", "unpaired surrogate"),
    ];
    let mut input = format!("{add}\n");
    for (line, _) in cases {
        input.push_str(line);
        input.push('\n');
    }
    input.push_str("{\"op\": \"vertices\", \"name\": \"a\"}\n");
    let got = replies(&["scene"], &input);
    assert_eq!(got.len(), cases.len() + 2);
    assert_eq!(got[0], json!({"ok": true}));
    for (i, (line, needle)) in cases.iter().enumerate() {
        let message = got[i + 1]["error"]
            .as_str()
            .unwrap_or_else(|| panic!("{line} -> {}", got[i + 1]));
        assert!(message.starts_with(&format!("line {}", i + 2)), "{message}");
        let needle = needle.replace("\\\"", "\"");
        assert!(
            message.contains(&needle),
            "{line}\n -> {message}\n wants {needle}"
        );
    }
    assert_eq!(
        got.last().unwrap(),
        &json!({"ids": [0, 1, 2], "points": [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]})
    );
}

#[test]
fn hostile_lines_never_crash_a_session() {
    let nested = format!("{}{}", "[".repeat(100_000), "]".repeat(100_000));
    let garbage = "x".repeat(2_000_000);
    let lines = [
        nested.clone(),
        format!(r#"{{"op": "pairs", "junk": {nested}}}"#),
        format!(r#"{{"op": "add", "name": "{garbage}", "points": [[0,0],[1,0],[0,1]]}}"#),
        garbage.clone(),
        r#"{"op": "add", "name": "a", "points": [[0,0],[1,0],[0,"#.to_string(),
        format!(r#"{{"op": "pairs", "id": "{}"}}"#, "\\u00e9".repeat(50_000)),
        r#"{"op": "pairs"}"#.to_string(),
    ];
    let input = lines.join("\n");
    let (code, out, _) = run(&["scene"], input.as_bytes());
    assert_eq!(code, 0);
    let got: Vec<&str> = out.lines().collect();
    assert_eq!(got.len(), lines.len());
    assert!(got[0].contains("expected a JSON object"));
    assert!(got[1].starts_with(r#"{"pairs": []"#));
    assert!(got[2].starts_with(r#"{"ok": true}"#));
    assert!(got[3].contains("invalid JSON"));
    assert!(got[4].contains("invalid JSON"));
    assert!(got[5].ends_with(r#", "pairs": []}"#));
    assert_eq!(got[6], r#"{"pairs": []}"#);
}

/// Produces `count` lines from `make` on demand, so a long session needs no big buffer.
struct Lines<F: FnMut(usize) -> String> {
    make: F,
    next: usize,
    count: usize,
    pending: Vec<u8>,
    at: usize,
}

impl<F: FnMut(usize) -> String> Read for Lines<F> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        if self.at == self.pending.len() {
            if self.next == self.count {
                return Ok(0);
            }
            self.pending = (self.make)(self.next).into_bytes();
            self.pending.push(b'\n');
            self.at = 0;
            self.next += 1;
        }
        let n = buf.len().min(self.pending.len() - self.at);
        buf[..n].copy_from_slice(&self.pending[self.at..self.at + n]);
        self.at += n;
        Ok(n)
    }
}

/// Counts reply lines and the errors among them.
#[derive(Default)]
struct Tally {
    lines: usize,
    errors: usize,
    partial: Vec<u8>,
}

impl Write for Tally {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        for &b in buf {
            if b == b'\n' {
                self.lines += 1;
                self.errors += usize::from(self.partial.windows(8).any(|w| w == b"\"error\":"));
                self.partial.clear();
            } else if self.partial.len() < 64 {
                self.partial.push(b);
            }
        }
        Ok(buf.len())
    }
    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

#[test]
fn a_million_ops_in_one_session_keep_the_maps_bounded() {
    let mut session = SceneSession::new(SceneOptions {
        seed: Some(1),
        ..SceneOptions::default()
    });
    let mut tally = Tally::default();
    let count = 1_000_000;
    // Cycles of four lines: insert a vertex, query, remove it, list the pairs; every
    // 1,000 lines the polygon is added afresh and dropped at the end; now and then a
    // stale id or a bad line.
    let make = |i: usize| -> String {
        let (block, j) = (i % 1000, (i % 1000) / 4);
        let id = 3 + j - usize::from(j > 125); // the id this cycle's insert got
        match (block, i % 4) {
            (0, _) => r#"{"op": "add", "name": "sq", "points": [[0,0],[4,0],[4,4],[0,4]]}"#.to_string(),
            (999, _) => r#"{"op": "drop", "name": "sq"}"#.to_string(),
            (500, _) => r#"{"op": "insert", "name": "sq", "after": "0", "point": [2, -1]}"#.to_string(),
            (_, 0) => format!(
                r#"{{"op": "insert", "name": "sq", "after": 0, "point": [2, -{}]}}"#,
                1 + j % 7
            ),
            (_, 1) => r#"{"op": "intersects", "a": "sq", "b": "sq"}"#.to_string(),
            (_, 2) => format!(r#"{{"op": "remove", "name": "sq", "vertex": {id}}}"#),
            _ if j % 8 == 0 => format!(r#"{{"op": "remove", "name": "sq", "vertex": {}}}"#, id - 1),
            _ => r#"{"op": "pairs"}"#.to_string(),
        }
    };
    let input = Lines {
        make,
        next: 0,
        count,
        pending: Vec::new(),
        at: 0,
    };
    session.run(input, &mut tally).unwrap();
    assert_eq!(tally.lines, count);
    // The bad lines, the stale ids and the removals from the triangle: about 3.4%.
    assert!(
        tally.errors > count / 50 && tally.errors < count / 20,
        "{} errors",
        tally.errors
    );
    session.debug_validate().unwrap();
    // The session maps one id per live vertex, whatever the history.
    assert_eq!(
        session.mapped_vertices(),
        0,
        "every polygon was dropped at the end"
    );
    assert!(session.scene().is_empty());
}

#[test]
fn a_polygon_of_two_to_the_twenty_vertices() {
    let n = 1 << 20;
    let points: Vec<[f64; 2]> = (0..n)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / n as f64;
            [t.cos(), t.sin()]
        })
        .collect();
    let mut input = json!({"op": "add", "name": "big", "points": points}).to_string();
    input.push('\n');
    input.push_str(r#"{"op": "add", "name": "t", "points": [[0.5,0.5],[2,0.5],[2,2]]}"#);
    input.push('\n');
    input.push_str(r#"{"op": "intersects", "a": "big", "b": "t"}"#);
    input.push('\n');
    input.push_str(r#"{"op": "vertices", "name": "big"}"#);
    input.push('\n');
    input.push_str(r#"{"op": "drop", "name": "big"}"#);
    input.push('\n');
    let mut session = SceneSession::new(SceneOptions::default());
    let mut out = Vec::new();
    session.run(input.as_bytes(), &mut out).unwrap();
    let out = String::from_utf8(out).unwrap();
    let got: Vec<&str> = out.lines().collect();
    assert_eq!(got.len(), 5);
    assert_eq!(got[0], r#"{"ok": true}"#);
    assert_eq!(got[2], r#"{"intersects": true}"#);
    let vertices: Value = serde_json::from_str(got[3]).unwrap();
    let ids = vertices["ids"].as_array().unwrap();
    assert!(ids.len() > n - 16, "{} vertices survive cleaning", ids.len());
    assert_eq!(ids[0], 0);
    assert_eq!(got[4], r#"{"ok": true}"#);
    assert_eq!(session.mapped_vertices(), 3);
}

#[test]
fn output_failures_exit_1_and_closed_pipes_exit_0() {
    let full = std::path::Path::new("/dev/full");
    if full.exists() {
        for args in [
            vec!["list"],
            vec!["gen", "--count", "5"],
            vec!["check"],
            vec!["scene"],
            vec!["crossings"],
            vec!["--help"],
            vec![
                "demo",
                "--polygons",
                "2",
                "--max-log2",
                "4",
                "--steps",
                "2",
                "--svg",
                "/dev/null",
            ],
        ] {
            let input: &[u8] = match args[0] {
                "scene" => b"{\"op\": \"pairs\"}\n",
                "check" | "crossings" => b"{\"p\": [[0,0],[1,0],[0,1]], \"q\": [[0,0],[1,0],[0,1]]}\n",
                _ => b"",
            };
            let mut child = Command::new(env!("CARGO_BIN_EXE_polysect"))
                .args(&args)
                .stdin(Stdio::piped())
                .stdout(std::fs::OpenOptions::new().write(true).open(full).unwrap())
                .stderr(Stdio::piped())
                .spawn()
                .unwrap();
            let mut stdin = child.stdin.take().unwrap();
            let _ = stdin.write_all(input);
            drop(stdin);
            let out = child.wait_with_output().unwrap();
            let err = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(1), "{args:?}: {err}");
            assert_eq!(err.lines().count(), 1, "{args:?}: one line: {err}");
            assert!(err.contains("No space left"), "{args:?}: {err}");
        }
    }
    // An output directory that cannot be made.
    let (code, _, err) = run(
        &[
            "bench",
            "sqrt",
            "--quick",
            "--no-progress",
            "--out",
            "/proc/polysect-bench",
        ],
        b"",
    );
    assert_eq!(code, 1, "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("cannot create the directory /proc/polysect-bench"),
        "{err}"
    );
    // A reader that stops early: the writer stops quietly with status 0.
    let mut child = Command::new(env!("CARGO_BIN_EXE_polysect"))
        .args(["gen", "--count", "1000000"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut first)
        .unwrap();
    assert!(first.starts_with("{\"id\": 0"));
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert!(out.stderr.is_empty(), "{}", String::from_utf8_lossy(&out.stderr));
}

/// A line's own `"certificate"` decides for that `intersects` line (over the session's
/// `--certificate`); on any other op it is an error that changes nothing.
#[test]
fn a_lines_certificate_field_is_honoured_or_refused() {
    let input = r#"{"op": "add", "name": "p", "points": [[0,0],[2,0],[2,2],[0,2]]}
{"op": "add", "name": "q", "points": [[3,0],[4,0],[4,1]]}
{"op": "intersects", "a": "p", "b": "q", "certificate": true}
{"op": "intersects", "a": "p", "b": "q", "certificate": false}
{"op": "intersects", "a": "p", "b": "q"}
{"op": "translate", "name": "q", "by": [-5, 0], "certificate": true}
{"op": "intersects", "a": "p", "b": "q", "certificate": null}
{"op": "vertices", "name": "q"}
"#;
    for (args, plain_default) in [(&["scene"][..], true), (&["scene", "--certificate"][..], false)] {
        let got = replies(args, input);
        assert_eq!(got.len(), 8);
        assert_eq!(got[0], json!({"ok": true}));
        let edge = &got[2]["certificate"]["separating_edge"];
        assert_eq!(got[2]["intersects"], json!(false), "{}", got[2]);
        assert!(edge["from"].is_array() && edge["to"].is_array(), "{}", got[2]);
        assert_eq!(got[3], json!({"intersects": false}));
        if plain_default {
            assert_eq!(got[4], json!({"intersects": false}));
        } else {
            assert!(got[4]["certificate"].is_object(), "{}", got[4]);
        }
        assert!(
            got[5]["error"].as_str().unwrap().contains("certificate"),
            "{}",
            got[5]
        );
        assert!(
            got[6]["error"].as_str().unwrap().contains("certificate"),
            "{}",
            got[6]
        );
        // The refused translate changed nothing.
        assert_eq!(got[7]["points"], json!([[3.0, 0.0], [4.0, 0.0], [4.0, 1.0]]));
    }
}

/// Answers each line of `input` in one session, as parsed values.
fn session_replies(input: &str) -> Vec<Value> {
    let mut session = SceneSession::new(SceneOptions::default());
    input
        .lines()
        .map(|line| {
            let reply = session.answer_line(line.as_bytes());
            serde_json::from_str(&reply).unwrap_or_else(|e| panic!("{e}: {reply}"))
        })
        .collect()
}

/// The ops beyond the contract's (`names`, `meeting`, `bbox`, `contains`, `replace`,
/// `stats`, `clear`; docs/store.md): each answer, each refusal (naming its line), the
/// `"id"` echo, world polygons for posed ones, and a refused `replace` changing
/// nothing. tests/scene_differential.rs checks them against a reference model on long
/// random streams.
#[test]
fn the_other_ops_answer_refuse_and_echo() {
    let input = r#"{"op": "add", "name": "sq", "points": [[0,0],[4,0],[4,4],[0,4]]}
{"op": "add", "name": "b", "points": [[4,1],[6,1],[5,3]]}
{"op": "add", "name": "a", "points": [[10,10],[11,10],[10,11]]}
{"id": "n", "op": "names"}
{"op": "meeting", "name": "sq"}
{"op": "meeting", "name": "a"}
{"id": 5, "op": "bbox", "name": "b"}
{"op": "contains", "name": "sq", "point": [4, 2]}
{"op": "contains", "name": "sq", "point": [4.000000000000001, 2]}
{"op": "contains", "name": "sq", "point": [0, 0]}
{"op": "contains", "name": "b", "point": [1e300, -1e300]}
{"op": "replace", "name": "b", "points": [[5,5],[5,5],[9,5],[7,8]]}
{"op": "vertices", "name": "b"}
{"op": "meeting", "name": "sq"}
{"op": "replace", "name": "b", "points": [[0,0],[1,1],[2,2]]}
{"op": "replace", "name": "zz", "points": [[0,0],[1,0],[0,1]]}
{"op": "vertices", "name": "b"}
{"op": "pose", "name": "a", "rotation": [0, 1], "translation": [-6, -6]}
{"op": "bbox", "name": "a"}
{"op": "contains", "name": "a", "point": [-16, 4]}
{"op": "contains", "name": "a", "point": [10, 10]}
{"op": "meeting", "name": "sq"}
{"op": "stats"}
{"op": "replace", "name": "a", "points": [[10,10],[11,10],[10,11]]}
{"op": "vertices", "name": "a"}
{"op": "meeting", "name": "nobody"}
{"op": "bbox"}
{"op": "contains", "name": "sq"}
{"op": "contains", "name": "sq", "point": [1, "2"]}
{"op": "replace", "name": "sq"}
{"op": "names", "certificate": true}
{"id": [1], "op": "clear"}
{"op": "names"}
{"op": "stats"}
{"op": "add", "name": "sq", "points": [[0,0],[1,0],[0,1]]}
{"op": "names"}
"#;
    let got = session_replies(input);
    let ok = json!({"ok": true});
    let error = |i: usize| -> String {
        let message = got[i]["error"]
            .as_str()
            .unwrap_or_else(|| panic!("line {}: {}", i + 1, got[i]));
        let line = format!("line {}", i + 1);
        assert!(
            message.starts_with(&format!("{line}: ")) || message.starts_with(&format!("{line}, column ")),
            "{message}"
        );
        message.to_string()
    };
    assert_eq!(got[..3], [ok.clone(), ok.clone(), ok.clone()]);
    assert_eq!(got[3], json!({"id": "n", "names": ["a", "b", "sq"]}));
    // b's corner (4, 1) lies on sq's edge: touching meets.
    assert_eq!(got[4], json!({"names": ["b"]}));
    assert_eq!(got[5], json!({"names": []}));
    assert_eq!(got[6], json!({"id": 5, "min": [4.0, 1.0], "max": [6.0, 3.0]}));
    assert_eq!(got[7], json!({"contains": true}), "on an edge");
    assert_eq!(got[8], json!({"contains": false}), "one ulp outside");
    assert_eq!(got[9], json!({"contains": true}), "a vertex");
    assert_eq!(got[10], json!({"contains": false}));
    assert_eq!(got[11], ok);
    // New ids as for `add`: the repeat at input 1 gets none.
    assert_eq!(
        got[12],
        json!({"ids": [0, 2, 3], "points": [[5.0, 5.0], [9.0, 5.0], [7.0, 8.0]]})
    );
    assert_eq!(got[13], json!({"names": []}));
    assert!(error(14).contains("points"), "{}", got[14]);
    assert!(error(15).contains(r#"no polygon is named "zz""#), "{}", got[15]);
    // The refused replacements changed nothing.
    assert_eq!(got[16], got[12]);
    assert_eq!(got[17], ok);
    // A quarter turn, then (-6, -6): a's world corners are (-16, 4), (-16, 5), (-17, 4).
    assert_eq!(got[18], json!({"min": [-17.0, 4.0], "max": [-16.0, 5.0]}));
    assert_eq!(got[19], json!({"contains": true}), "a world vertex");
    assert_eq!(got[20], json!({"contains": false}), "not the shape's image");
    assert_eq!(got[21], json!({"names": []}));
    let stats = &got[22];
    assert_eq!(
        (&stats["polygons"], &stats["vertices"], &stats["posed"]),
        (&json!(3), &json!(10), &json!(1)),
        "{stats}"
    );
    assert!(
        stats["snapshots"].is_u64() && stats["heap_bytes"].as_u64() > Some(0),
        "{stats}"
    );
    for counter in [
        "box_rejects",
        "array_tests",
        "sampled_tests",
        "linear_tests",
        "conversions",
        "throwaway_conversions",
        "invalidations",
    ] {
        assert!(stats["planner"][counter].is_u64(), "{counter}: {stats}");
    }
    // Replacing a posed polygon gives a polygon never posed: no "shape".
    assert_eq!(got[23], ok);
    assert_eq!(
        got[24],
        json!({"ids": [0, 1, 2], "points": [[10.0, 10.0], [11.0, 10.0], [10.0, 11.0]]})
    );
    assert!(
        error(25).contains(r#"no polygon is named "nobody""#),
        "{}",
        got[25]
    );
    assert!(error(26).contains("needs the field `name`"), "{}", got[26]);
    assert!(error(27).contains("needs the field `point`"), "{}", got[27]);
    assert!(error(28).contains("point"), "{}", got[28]);
    assert!(error(29).contains("needs the field `points`"), "{}", got[29]);
    assert!(error(30).contains("certificate"), "{}", got[30]);
    assert_eq!(got[31], json!({"id": [1], "ok": true}));
    assert_eq!(got[32], json!({"names": []}));
    assert_eq!(
        (&got[33]["polygons"], &got[33]["vertices"], &got[33]["posed"]),
        (&json!(0), &json!(0), &json!(0))
    );
    assert_eq!(got[34], ok, "a cleared name is free");
    assert_eq!(got[35], json!({"names": ["sq"]}));
    assert_eq!(got.len(), 36);
}

/// An unknown op's message lists every op, the new ones too.
#[test]
fn an_unknown_op_lists_every_op() {
    let got = session_replies(r#"{"op": "explode"}"#);
    let message = got[0]["error"].as_str().unwrap();
    for op in [
        "add",
        "drop",
        "insert",
        "remove",
        "move",
        "translate",
        "pose",
        "replace",
        "clear",
        "intersects",
        "contact",
        "pairs",
        "meeting",
        "contains",
        "vertices",
        "bbox",
        "names",
        "stats",
    ] {
        assert!(message.contains(op), "{op}: {message}");
    }
}
