//! Unit tests of the line protocols: shapes, ids, errors and their places, blocks,
//! flushing.

use super::check::{check, check_line, crossings_line};
use super::points_json;
use super::scene::{SceneOptions, SceneSession};
use crate::intersect::{ArrayIntersection, Linear};
use crate::kernel::Point;
use serde_json::Value;
use std::cell::RefCell;
use std::io::{self, Read, Write};
use std::rc::Rc;

const TRI: &str = "[[0,0],[1,0],[0,1]]";

fn answer(line: &str) -> String {
    check_line(line.as_bytes(), |p, q| Linear.intersects(p, q))
}

fn json(text: &str) -> Value {
    serde_json::from_str(text).unwrap_or_else(|e| panic!("not JSON ({e}): {text}"))
}

fn error_of(reply: &str) -> String {
    json(reply)["error"]
        .as_str()
        .unwrap_or_else(|| panic!("not an error line: {reply}"))
        .to_string()
}

#[test]
fn answers_and_echoes_ids() {
    assert_eq!(
        answer(r#"{"p": [[0,0],[1,0],[0,1]], "q": [[1,0],[2,0],[2,1]]}"#),
        r#"{"intersects": true}"#
    );
    assert_eq!(
        answer(
            r#"{"id": "a", "p": [[0,0],[1,0],[0,1]], "q": [[1.5,0],[2,0],[2,1]], "extra": {"x": [1, null]}}"#
        ),
        r#"{"id": "a", "intersects": false}"#
    );
    // Keys may come in any order, with escapes, and with any whitespace.
    assert_eq!(
        answer("{ \"q\" :\t[[1,0] , [2,0],[2,1]]\r, \"\\u0070\": [[0,0],[1,0],[0,1]] , \"id\" : 3 }\r"),
        r#"{"id": 3, "intersects": true}"#
    );
}

#[test]
fn every_line_that_is_not_an_object_with_the_fields_is_an_error_line() {
    for (line, needle) in [
        // Not an object at all: one case per JSON kind.
        (
            r#"[[[0,0],[1,0],[0,1]], [[5,5],[6,5],[5,6]], 7]"#,
            "expected a JSON object",
        ),
        (r#"[[[0,0],[1,0],[0,1]], [[5,5],[6,5],[5,6]]]"#, "found an array"),
        ("7", "found a number"),
        (r#""p""#, "found a string"),
        ("null", "found null"),
        ("true", "found a boolean"),
        ("nope", "invalid JSON"),
        ("", "empty line"),
        ("   \t", "empty line"),
        ("{", "invalid JSON"),
        ("{}", "missing field `p`"),
        // Objects whose fields have the wrong shape.
        (r#"{"p": [[0,0],[1,0],[0,1]]}"#, "missing field `q`"),
        (
            r#"{"p": {"0": [0,0]}, "q": [[0,0],[1,0],[0,1]]}"#,
            "`p` must be an array of [x, y] points, found an object",
        ),
        (r#"{"p": "[[0,0]]", "q": []}"#, "found a string"),
        (r#"{"p": null, "q": []}"#, "found null"),
        (
            r#"{"p": [[0,0],{"x":1,"y":0},[0,1]], "q": []}"#,
            "`p`[1] must be a point [x, y], found an object",
        ),
        (
            r#"{"p": [[0,0],[1],[0,1]], "q": []}"#,
            "`p`[1] must be a point [x, y], found 1 numbers",
        ),
        (
            r#"{"p": [[0,0],[1,0],[0,1,2]], "q": []}"#,
            "`p`[2] must be a point [x, y], found 3 numbers",
        ),
        (r#"{"p": [[0,0],[],[0,1]], "q": []}"#, "found 0 numbers"),
        (
            r#"{"p": [[0,0],["1",0],[0,1]], "q": []}"#,
            "`p`[1][0] must be a number, found a string",
        ),
        (
            r#"{"p": [[0,0],[1,null],[0,1]], "q": []}"#,
            "`p`[1][1] must be a number, found null",
        ),
        (r#"{"p": [[0,0],[1,true],[0,1]], "q": []}"#, "found a boolean"),
        (
            r#"{"p": [[0,0],[1e400,0],[0,1]], "q": []}"#,
            "beyond the f64 range",
        ),
        (
            r#"{"p": [[0,0],[-1e309,0],[0,1]], "q": []}"#,
            "beyond the f64 range",
        ),
        (
            r#"{"p": [[0,0],[1,0],[0,1]], "q": [[0,0],[1,1]]}"#,
            "q: a polygon needs at least 3",
        ),
        (
            r#"{"p": [[0,0],[4,0],[4,4],[2,1],[0,4]], "q": [[0,0],[1,0],[0,1]]}"#,
            "p: vertex 3 is reflex",
        ),
        // Invalid JSON inside a line that starts well.
        (
            r#"{"p": [[0,0],[1,0],[0,1]], "q": [[0,0],[1,0],[0,"#,
            "invalid JSON",
        ),
        (r#"{"p": [[0,0],[1,0],[0,01]], "q": []}"#, "invalid number `01`"),
        (r#"{"p": [[0,0],[1,0],[0,1.]], "q": []}"#, "invalid number `1.`"),
        (r#"{"p": [[0,0],[1,0],[0,1]] "q": []}"#, "expected ',' or '}'"),
        (r#"{"p": [[0,0],[1,0],[0,1]],}"#, "expected a key"),
        (
            r#"{"p": [[0,0],[1,0],[0,1]], "q": [[0,0],[1,0],[0,1]]} {}"#,
            "trailing characters",
        ),
        (
            r#"{"p": [[0,0],[1,0],[0,1]], "q": [[0,0],[1,0],[0,1]], "x": "a	b"}"#,
            "control character",
        ),
        (
            r#"{"p": [[0,0],[1,0],[0,1]], "q": [[0,0],[1,0],[0,1]], "x": "\ud800"}"#,
            "unpaired surrogate",
        ),
        (
            r#"{"p": [[0,0],[1,0],[0,1]], "q": [[0,0],[1,0],[0,1]], "x": "\q"}"#,
            "invalid escape",
        ),
        (
            r#"{"p": [[0,0],[1,0],[0,1]], "q": [[0,0],[1,0],[0,1]], "x": tru}"#,
            "invalid JSON",
        ),
    ] {
        let reply = answer(line);
        let message = error_of(&reply);
        assert!(message.contains(needle), "{line} -> {message}");
        assert!(message.starts_with("line 1"), "{message}");
    }
    let reply = check_line(
        b"{\"p\": [[0,0],[1,0],[0,1]], \"q\": [], \"x\": \"\xff\"}",
        |_, _| true,
    );
    assert!(error_of(&reply).contains("invalid UTF-8"), "{reply}");
    let reply = check_line(b"\xff\xfe", |_, _| true);
    assert!(error_of(&reply).contains("invalid JSON"), "{reply}");
}

#[test]
fn ids_are_echoed_verbatim_on_every_kind_of_line() {
    let ids = [
        "12345678901234567890123",
        "1e400",
        "-0.0",
        "null",
        "true",
        r#""a \"quoted\" \\ \u00e9 \ud83d\ude00 string""#,
        r#"{"nested": [1, {"deep": null}], "b": "x"}"#,
        "[]",
        "\"\u{e9}\u{1f600}\"",
    ];
    for id in ids {
        let lines = [
            (format!(r#"{{"id": {id}, "p": {TRI}, "q": {TRI}}}"#), "intersects"),
            (format!(r#"{{"p": {TRI}, "q": {TRI}, "id": {id}}}"#), "intersects"),
            (format!(r#"{{"id": {id}, "p": "x", "q": {TRI}}}"#), "error"),
            (
                format!(r#"{{"p": [[0,0],[1,0]], "id": {id}, "q": {TRI}}}"#),
                "error",
            ),
            (format!(r#"{{"id": {id}, "p": {TRI}}}"#), "error"),
            (
                format!(r#"{{"id": {id}, "p": {TRI}, "q": {TRI}, "p": {TRI}}}"#),
                "error",
            ),
            (
                format!(r#"{{"id": {id}, "p": {TRI}, "q": [[0,0],[1,0],[0,"#),
                "error",
            ),
        ];
        for (line, key) in lines {
            let reply = answer(&line);
            let prefix = format!("{{\"id\": {id}, \"{key}\": ");
            assert!(reply.starts_with(&prefix), "{line}\n -> {reply}");
            if id != "1e400" {
                // (serde_json refuses numbers beyond f64, which JSON itself allows.)
                json(&reply);
            }
        }
    }
    // A repeated id is an error that echoes the first one.
    let reply = answer(&format!(r#"{{"id": 1, "id": 2, "p": {TRI}, "q": {TRI}}}"#));
    assert!(
        reply.starts_with(r#"{"id": 1, "error": "line 1, column 11: repeated key `id`"#),
        "{reply}"
    );
    // An id that is itself invalid JSON cannot be echoed.
    let reply = answer(&format!(r#"{{"id": [1,, "p": {TRI}, "q": {TRI}}}"#));
    assert!(reply.starts_with(r#"{"error": "#), "{reply}");
}

#[test]
fn repeated_keys_are_refused_by_name() {
    for (line, key) in [
        (format!(r#"{{"p": {TRI}, "q": {TRI}, "p": {TRI}}}"#), "p"),
        (format!(r#"{{"p": {TRI}, "q": {TRI}, "\u0071": {TRI}}}"#), "q"),
        (format!(r#"{{"p": {TRI}, "x": 1, "q": {TRI}, "x": 2}}"#), "x"),
    ] {
        let message = error_of(&answer(&line));
        assert!(message.contains(&format!("repeated key `{key}`")), "{message}");
    }
    // The same key inside an ignored value is not a repeat of the line's keys.
    assert_eq!(
        answer(&format!(r#"{{"p": {TRI}, "q": {TRI}, "x": {{"p": 1, "q": 2}}}}"#)),
        r#"{"intersects": true}"#
    );
}

#[test]
fn errors_name_the_line_and_the_column() {
    let input = format!(
        "{{\"p\": {TRI}, \"q\": {TRI}}}\n\n{{\"p\": {TRI}, \"q\": [[0,0],[1,0],[0,\"x\"]]}}\n{{\"p\": [[0,0],[4,0],[4,4],[2,1],[0,4]], \"q\": {TRI}}}\n{{\"p\": {TRI} \"q\": 1}}\n"
    );
    let mut out = Vec::new();
    check(input.as_bytes(), &mut out, |p, q| Linear.intersects(p, q)).unwrap();
    let out = String::from_utf8(out).unwrap();
    let replies: Vec<&str> = out.lines().collect();
    assert_eq!(replies.len(), 5);
    assert_eq!(replies[0], r#"{"intersects": true}"#);
    assert!(error_of(replies[1]).starts_with("line 2: empty line"));
    // The column is that of the string where a number belongs (bytes, from 1).
    let column = input.lines().nth(2).unwrap().find("\"x\"").unwrap() + 1;
    let third = error_of(replies[2]);
    assert!(
        third.starts_with(&format!("line 3, column {column}: `q`[2][1] must be a number")),
        "{third}"
    );
    assert!(error_of(replies[3]).starts_with("line 4: p: vertex 3 is reflex"));
    let column = input.lines().nth(4).unwrap().find("\"q\"").unwrap() + 1;
    let fifth = error_of(replies[4]);
    assert!(
        fifth.starts_with(&format!("line 5, column {column}: invalid JSON: expected ','")),
        "{fifth}"
    );
}

#[test]
fn parsing_is_correctly_rounded() {
    // 2^53 + 1 is a tie between 2^53 and 2^53 + 2 (round to even: 2^53); the extra
    // digits push it above the tie.
    let points = |line: &str| {
        let mut got = Vec::new();
        check(line.as_bytes(), io::sink(), |p, _| {
            got = p.vertices().to_vec();
            true
        })
        .unwrap();
        got
    };
    let p = points(&format!(
        r#"{{"p": [[9007199254740993.0000000000000001, 0.1], [0, 0], [0, 1]], "q": {TRI}}}"#
    ));
    assert!(p.contains(&Point::new(9007199254740994.0, 0.1)), "{p:?}");
    let p = points(&format!(
        r#"{{"p": [[123456789012345678901234567890, -0], [0, 1], [-1, 0]], "q": {TRI}}}"#
    ));
    assert!(
        p.contains(&Point::new(123456789012345678901234567890.0, 0.0)),
        "{p:?}"
    );
    let p = points(&format!(
        r#"{{"p": [[5e-324, 0], [0, 2.4703282292062328e-324], [0, 0]], "q": {TRI}}}"#
    ));
    assert!(
        p.contains(&Point::new(5e-324, 0.0)) && p.contains(&Point::new(0.0, 5e-324)),
        "{p:?}"
    );
}

#[test]
fn crossings_lines_answer_and_report_errors() {
    use crate::crossings::{Crossings, Sweep};
    let cross = |line: &str| crossings_line(line.as_bytes(), |p, q| Sweep.crossings(p, q));
    assert_eq!(
        cross(r#"{"id": 7, "p": [[0,0],[2,0],[2,2],[0,2]], "q": [[1,1],[3,1],[3,3]]}"#),
        r#"{"id": 7, "points": [[2.0,1.0],[2.0,2.0]]}"#
    );
    assert_eq!(
        cross(r#"{"p": [[0,0],[1,0],[0,1]], "q": [[5,5],[6,5],[5,6]]}"#),
        r#"{"points": []}"#
    );
    for (line, needle) in [
        (
            r#"{"p": [[0,0],[2,2],[2,0],[0,2]], "q": [[0,0],[1,0],[0,1]]}"#,
            "p: the boundary intersects itself",
        ),
        (
            r#"{"p": [[0,0],[1,0],[0,1]], "q": [[0,0],[1,1]]}"#,
            "q: a polygon needs at least 3",
        ),
        ("{", "invalid JSON"),
        (
            r#"[[[0,0],[1,0],[0,1]], [[5,5],[6,5],[5,6]], 7]"#,
            "expected a JSON object",
        ),
        (
            r#"{"p": [[0,0],[1,0],[0,1]], "q": [[5,5],[6,5],[5,6]], "q": []}"#,
            "repeated key `q`",
        ),
    ] {
        assert!(error_of(&cross(line)).contains(needle), "{line}");
    }
}

#[test]
fn printed_numbers_round_trip() {
    let values = [
        0.1,
        -0.0,
        5e-324,
        f64::MAX,
        f64::MIN_POSITIVE,
        -1.0f64.next_up(),
        1e16,
        123456.789,
        1e-7,
        2f64.powi(1000),
    ];
    let pts: Vec<Point> = values.iter().map(|&v| Point::new(v, -v)).collect();
    let text = points_json(&pts);
    let back: Vec<[f64; 2]> = serde_json::from_str(&text).unwrap();
    for (b, v) in back.iter().zip(values) {
        assert_eq!(b[0].to_bits(), v.to_bits(), "{text}");
        assert_eq!(b[1].to_bits(), (-v).to_bits(), "{text}");
    }
}

/// Hands out its input a few bytes per read (splitting tokens, strings and escapes
/// across blocks).
struct Trickle<'a> {
    data: &'a [u8],
    step: usize,
}

impl Read for Trickle<'_> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        let n = self.step.min(buf.len()).min(self.data.len());
        buf[..n].copy_from_slice(&self.data[..n]);
        self.data = &self.data[n..];
        Ok(n)
    }
}

#[test]
fn replies_do_not_depend_on_how_the_input_arrives() {
    let mut input = String::new();
    for line in [
        format!(
            r#"{{"id": "caf\u00e9 \ud83d\ude00", "p": [[0.1e1,0],[1.000000000000000000001,0],[0,1]], "q": {TRI}}}"#
        ),
        r#"{"id": 123456789012345678901234567890, "p": [[0,0],[1,0],[0,1]], "q": [[5,5],[6,5],[5,6]]}"#
            .to_string(),
        format!(r#"{{"p": [[0,0],[1,0],[0,"x"]], "q": {TRI}, "id": [1, {{"a": "b"}}]}}"#),
        "not json at all".to_string(),
        format!(r#"{{"p": {TRI}, "q": {TRI}, "skip": [[[[[[1e5, "\n", "\\"]]]]]]}}"#),
        format!("{{\"p\": {TRI}, \"q\": {TRI}}}"),
    ] {
        input.push_str(&line);
        input.push('\n');
    }
    input.push_str(&format!("{{\"p\": {TRI}, \"q\": {TRI}}}")); // no final newline
    let run = |reader: &mut dyn Read| {
        let mut out = Vec::new();
        check(reader, &mut out, |p, q| Linear.intersects(p, q)).unwrap();
        String::from_utf8(out).unwrap()
    };
    let whole = run(&mut input.as_bytes());
    assert_eq!(whole.lines().count(), 7, "{whole}");
    for step in [1, 2, 3, 7, 64] {
        let got = run(&mut Trickle {
            data: input.as_bytes(),
            step,
        });
        assert_eq!(got, whole, "step {step}");
    }
    // Blocks larger than the reader's buffer: a line of a few hundred kilobytes.
    let n = 20_000;
    let big: Vec<[f64; 2]> = (0..n)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / n as f64;
            [t.cos(), t.sin()]
        })
        .collect();
    let line = format!(
        "{}\n{}\n",
        serde_json::json!({"id": "big", "p": big, "q": [[0.5, 0.5], [2.0, 0.5], [2.0, 2.0]]}),
        serde_json::json!({"p": big, "q": [[5.0, 5.0], [6.0, 5.0], [5.0, 6.0]]})
    );
    let got = run(&mut line.as_bytes());
    assert_eq!(
        got,
        "{\"id\": \"big\", \"intersects\": true}\n{\"intersects\": false}\n"
    );
}

/// An output that records what was flushed.
#[derive(Clone, Default)]
struct Recorder {
    pending: Rc<RefCell<Vec<u8>>>,
    flushed: Rc<RefCell<Vec<u8>>>,
    flushes: Rc<RefCell<usize>>,
}

impl Write for Recorder {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        self.pending.borrow_mut().extend_from_slice(buf);
        Ok(buf.len())
    }
    fn flush(&mut self) -> io::Result<()> {
        let mut p = self.pending.borrow_mut();
        self.flushed.borrow_mut().extend(p.drain(..));
        *self.flushes.borrow_mut() += 1;
        Ok(())
    }
}

/// Gives one line per read, and checks before each read that every earlier line has
/// been answered and flushed: a client waiting for its reply would get it.
struct Interactive {
    lines: Vec<Vec<u8>>,
    next: usize,
    out: Recorder,
}

impl Read for Interactive {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        let answered = self.out.flushed.borrow().iter().filter(|&&b| b == b'\n').count();
        assert_eq!(
            answered, self.next,
            "a read would block before line {} was answered",
            self.next
        );
        let Some(line) = self.lines.get(self.next) else {
            return Ok(0);
        };
        assert!(line.len() <= buf.len());
        buf[..line.len()].copy_from_slice(line);
        self.next += 1;
        Ok(line.len())
    }
}

#[test]
fn every_reply_is_flushed_before_a_read_that_could_block() {
    let out = Recorder::default();
    let lines: Vec<Vec<u8>> = vec![
        format!("{{\"p\": {TRI}, \"q\": {TRI}}}\n").into_bytes(),
        b"not json\n".to_vec(),
        format!("{{\"id\": 3, \"p\": {TRI}, \"q\": {TRI}}}\n").into_bytes(),
    ];
    let reader = Interactive {
        lines,
        next: 0,
        out: out.clone(),
    };
    check(reader, out.clone(), |p, q| Linear.intersects(p, q)).unwrap();
    assert_eq!(out.flushed.borrow().iter().filter(|&&b| b == b'\n').count(), 3);
    // A session drives the same loop.
    let out = Recorder::default();
    let reader = Interactive {
        lines: vec![
            b"{\"op\": \"add\", \"name\": \"a\", \"points\": [[0,0],[1,0],[0,1]]}\n".to_vec(),
            b"{\"op\": \"vertices\", \"name\": \"a\"}\n".to_vec(),
        ],
        next: 0,
        out: out.clone(),
    };
    SceneSession::new(SceneOptions::default())
        .unwrap()
        .run(reader, out.clone())
        .unwrap();
    // Bulk input already read is answered without a flush per line.
    let out = Recorder::default();
    let bulk = format!("{{\"p\": {TRI}, \"q\": {TRI}}}\n").repeat(1000);
    check(bulk.as_bytes(), out.clone(), |p, q| Linear.intersects(p, q)).unwrap();
    assert_eq!(out.flushed.borrow().iter().filter(|&&b| b == b'\n').count(), 1000);
    assert!(*out.flushes.borrow() <= 3, "{} flushes", out.flushes.borrow());
}

#[test]
fn deep_nesting_and_long_values_are_skipped_or_echoed_without_recursion() {
    let deep = format!("{}{}", "[".repeat(200_000), "]".repeat(200_000));
    let line = format!(r#"{{"skip": {deep}, "p": {TRI}, "q": {TRI}, "id": {deep}}}"#);
    let reply = answer(&line);
    assert!(reply.starts_with(&format!("{{\"id\": {deep}, \"intersects\": true")));
    let unbalanced = format!(r#"{{"skip": {}, "p": {TRI}, "q": {TRI}}}"#, "[".repeat(100_000));
    assert!(error_of(&answer(&unbalanced)).contains("invalid JSON"));
    let long_string = format!(r#"{{"id": "{}", "p": {TRI}, "q": {TRI}}}"#, "x".repeat(300_000));
    assert!(answer(&long_string).ends_with("\"intersects\": true}"));
    let long_number = format!(
        r#"{{"p": [[0.{}1,0],[1,0],[0,1]], "q": {TRI}}}"#,
        "0".repeat(300_000)
    );
    assert_eq!(answer(&long_number), r#"{"intersects": true}"#);
}

#[test]
fn every_protocol_refuses_every_shape_that_is_not_its_object() {
    use crate::crossings::{Crossings, Sweep};
    let shapes = [
        (
            r#"[[[0,0],[1,0],[0,1]], [[5,5],[6,5],[5,6]], 7]"#,
            "found an array",
        ),
        (r#"[{"op": "pairs"}]"#, "found an array"),
        ("[]", "found an array"),
        ("42", "found a number"),
        (r#""{\"op\": \"pairs\"}""#, "found a string"),
        ("null", "found null"),
        ("false", "found a boolean"),
        ("{}", "missing field"),
        (r#"{"id": 5}"#, "missing field"),
        ("{\"x\": 1} {}", "trailing characters"),
    ];
    let mut session = SceneSession::new(SceneOptions::default()).unwrap();
    for (shape, needle) in shapes {
        let replies = [
            check_line(shape.as_bytes(), |_, _| true),
            crossings_line(shape.as_bytes(), |p, q| Sweep.crossings(p, q)),
            session.answer_line(shape.as_bytes()),
        ];
        for reply in replies {
            let message = error_of(&reply);
            assert!(message.contains(needle), "{shape} -> {message}");
        }
    }
    assert!(session.scene().is_empty());
}
