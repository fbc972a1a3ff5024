//! `polysect hull` per the CLI conventions of the line protocols: JSON Lines
//! `{"points": ...}` in, one `{"hull": ..., "diameter": ...}` or `{"error": ...}` line
//! out per input line, in order, the `"id"` echoed first; each line answered before the
//! next is read.

use serde_json::{Value, json};
use std::io::{BufRead, BufReader, Write};
use std::process::{Command, Stdio};

use crate::answers;
use crate::common::run;

#[test]
fn hulls_diameters_and_degenerate_sets() {
    let input = concat!(
        // A square with points on its edges and inside, a repeated corner.
        r#"{"id": 1, "points": [[2,2],[0,0],[1,0],[2,0],[2,1],[0,2],[1,1],[0,0],[0,1]]}"#,
        "\n",
        // The lowest row has two points: the hull starts at its left one.
        r#"{"points": [[5,0],[1,0],[3,4]]}"#,
        "\n",
        // One point, repeated.
        r#"{"points": [[7,-1],[7,-1]]}"#,
        "\n",
        // Collinear, descending to the right: the lowest end first.
        r#"{"points": [[0,3],[1,2],[3,0],[2,1]]}"#,
        "\n",
        // A long thin triangle: the diameter is its long side.
        r#"{"points": [[0,0],[10,1],[1,1]], "other": "ignored"}"#,
        "\n",
    );
    let want = [
        json!({"id": 1, "hull": [[0.0,0.0],[2.0,0.0],[2.0,2.0],[0.0,2.0]], "diameter": [[0.0,0.0],[2.0,2.0]]}),
        json!({"hull": [[1.0,0.0],[5.0,0.0],[3.0,4.0]], "diameter": [[1.0,0.0],[3.0,4.0]]}),
        json!({"hull": [[7.0,-1.0]], "diameter": [[7.0,-1.0],[7.0,-1.0]]}),
        json!({"hull": [[3.0,0.0],[0.0,3.0]], "diameter": [[3.0,0.0],[0.0,3.0]]}),
        json!({"hull": [[0.0,0.0],[10.0,1.0],[1.0,1.0]], "diameter": [[0.0,0.0],[10.0,1.0]]}),
    ];
    for algorithm in ["graham", "monotone"] {
        assert_eq!(
            answers(&["hull", "--algorithm", algorithm], input),
            want,
            "{algorithm}"
        );
    }
    assert_eq!(answers(&["hull"], input), want, "default");
}

#[test]
fn numbers_round_trip_exactly() {
    let input = r#"{"points": [[0.1, 0.2], [1e300, -1e-300], [5e-324, 3], [0.30000000000000004, 1e300]]}"#;
    let (code, out, _) = run(&["hull"], format!("{input}\n").as_bytes());
    assert_eq!(code, 0);
    let v: Value = serde_json::from_str(out.trim()).unwrap();
    let hull: Vec<[f64; 2]> = serde_json::from_value(v["hull"].clone()).unwrap();
    for p in [
        [0.1, 0.2],
        [1e300, -1e-300],
        [5e-324, 3.0],
        [0.30000000000000004, 1e300],
    ] {
        assert!(hull.contains(&p), "{p:?} in {hull:?}");
    }
}

#[test]
fn bad_lines_get_located_errors_and_the_run_goes_on() {
    let input = concat!(
        "{\"points\": []}\n",
        "{\"pts\": [[0,0]]}\n",
        "{\"points\": [[0,0],[1]]}\n",
        "{\"points\": [[0,0]], \"points\": [[1,1]]}\n",
        "[[0,0],[1,1]]\n",
        "{\"id\": \"x\", \"points\": [[0, 1e999]]}\n",
        "\n",
        "{\"points\": \"no\"}\n",
        "{\"points\": [[1,2]]}\n",
    );
    let got = answers(&["hull", "--algorithm", "graham"], input);
    assert_eq!(got.len(), 9);
    let err = |i: usize| {
        got[i]["error"]
            .as_str()
            .unwrap_or_else(|| panic!("line {i}: {}", got[i]))
            .to_string()
    };
    assert!(err(0).starts_with("line 1: `points` is empty"), "{}", err(0));
    assert_eq!(err(1), "line 2: missing field `points`");
    assert!(err(2).starts_with("line 3, column "), "{}", err(2));
    assert!(err(3).contains("repeated key `points`"), "{}", err(3));
    assert!(
        err(4).starts_with("line 5, column 1: expected a JSON object"),
        "{}",
        err(4)
    );
    assert_eq!(got[5]["id"], json!("x"));
    assert!(err(5).starts_with("line 6, column "), "{}", err(5));
    assert!(err(6).starts_with("line 7: empty line"), "{}", err(6));
    assert!(err(7).contains("must be an array"), "{}", err(7));
    assert_eq!(
        got[8],
        json!({"hull": [[1.0, 2.0]], "diameter": [[1.0, 2.0], [1.0, 2.0]]})
    );
}

#[test]
fn unknown_algorithm_is_a_usage_error() {
    let (code, out, err) = run(&["hull", "--algorithm", "jarvis"], b"");
    assert_eq!(code, 2);
    assert!(out.is_empty());
    assert!(err.contains("graham, monotone"), "{err}");
}

#[test]
fn answers_each_line_before_reading_the_next() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_polysect"))
        .args(["hull", "--algorithm", "graham"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .expect("the binary starts");
    let mut stdin = child.stdin.take().unwrap();
    let mut stdout = BufReader::new(child.stdout.take().unwrap());
    for i in 0..3 {
        writeln!(stdin, "{{\"id\": {i}, \"points\": [[0,0],[{i},1],[3,0]]}}").unwrap();
        stdin.flush().unwrap();
        let mut reply = String::new();
        stdout.read_line(&mut reply).unwrap();
        let v: Value = serde_json::from_str(&reply).unwrap();
        assert_eq!(v["id"], json!(i), "{reply}");
        assert!(v.get("hull").is_some(), "{reply}");
    }
    drop(stdin);
    assert!(child.wait().unwrap().success());
}
