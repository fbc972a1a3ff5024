//! `polysect crossings` per the CLI contract: JSON Lines in, one `{"points": ...}`
//! or `{"error": ...}` line out per input line, in order.

use serde_json::json;

use crate::answers;
use crate::common::run;

const SQUARE: &str = "[[0,0],[4,0],[4,4],[0,4]]";

fn line(q: &str) -> String {
    format!("{{\"p\": {SQUARE}, \"q\": {q}}}\n")
}

#[test]
fn reports_crossings_touchings_and_overlaps() {
    let input = [
        // Crossing the right edge, a vertex on the top edge.
        line("[[3,1],[6,1],[2,4]]"),
        // Corner on corner.
        line("[[4,4],[6,4],[6,6]]"),
        // Collinear overlap beyond both ends of the top edge.
        line("[[-1,4],[5,4],[2,6]]"),
        // Disjoint, clockwise, with a repeated closing vertex.
        line("[[5,5],[5,6],[6,5],[5,5]]"),
        // Identical.
        line(SQUARE),
    ]
    .concat();
    let want = [
        json!({"points": [[2.0, 4.0], [4.0, 1.0], [4.0, 2.5]]}),
        json!({"points": [[4.0, 4.0]]}),
        json!({"points": [[0.0, 4.0], [4.0, 4.0]]}),
        json!({"points": []}),
        json!({"points": [[0.0, 0.0], [0.0, 4.0], [4.0, 0.0], [4.0, 4.0]]}),
    ];
    for algorithm in ["sweep", "brute"] {
        for precision in ["exact", "fast"] {
            let got = answers(
                &["crossings", "--algorithm", algorithm, "--precision", precision],
                &input,
            );
            assert_eq!(got, want, "{algorithm} {precision}");
        }
    }
    // The default is the sweep with the exact kernel.
    assert_eq!(answers(&["crossings"], &input), want);
}

#[test]
fn touching_exclude_keeps_proper_crossings_and_overlap_ends_only() {
    let input = [
        // A proper crossing pair and a vertex on the top edge.
        line("[[3,1],[6,1],[2,4]]"),
        // Corner on corner: a touching only.
        line("[[4,4],[6,4],[6,6]]"),
        // An overlap (both its ends are kept).
        line("[[-1,4],[5,4],[2,6]]"),
        // A vertex on the right edge where Q's boundary passes through P's: still only
        // touching edge pairs, so nothing.
        line("[[4,2],[5,0],[5,3],[3,3]]"),
    ]
    .concat();
    let want = [
        json!({"points": [[4.0, 1.0], [4.0, 2.5]]}),
        json!({"points": []}),
        json!({"points": [[0.0, 4.0], [4.0, 4.0]]}),
        json!({"points": [[4.0, 3.0]]}),
    ];
    for algorithm in ["sweep", "brute"] {
        let got = answers(
            &["crossings", "--algorithm", algorithm, "--touching", "exclude"],
            &input,
        );
        assert_eq!(got, want, "{algorithm}");
    }
    // The default includes touchings, and an unknown mode is a usage error.
    assert_eq!(
        answers(&["crossings", "--touching", "include"], &input),
        answers(&["crossings"], &input)
    );
    let (code, _, err) = run(&["crossings", "--touching", "never"], b"");
    assert_eq!(code, 2);
    assert!(err.contains("include, exclude"), "{err}");
}

#[test]
fn bad_lines_give_error_lines_and_never_stop_the_run() {
    let input = format!(
        "{}{}{}{}{}{}{}",
        "{\"id\": \"bowtie\", \"p\": [[0,0],[2,2],[2,0],[0,2]], \"q\": [[0,0],[1,0],[0,1]]}\n",
        "{\"id\": 2, \"p\": [[0,0],[1,0],[0,1]], \"q\": [[0,0],[1,1]]}\n",
        "{\"p\": [[0,0],[1,0],[0,1]], \"q\": [[0,0],[1,0],[1e999,1]]}\n",
        "not json\n",
        "\n",
        "{\"p\": [[0,0],[1,0],[2,0]], \"q\": [[0,0],[1,0],[0,1]]}\n",
        "{\"id\": [1], \"p\": [[0,0],[2,0],[2,2],[0,2]], \"q\": [[1,1],[3,1],[3,3]]}\n",
    );
    let got = answers(&["crossings"], &input);
    assert_eq!(got.len(), 7);
    let error = |i: usize| {
        got[i]["error"]
            .as_str()
            .unwrap_or_else(|| panic!("line {i}: {}", got[i]))
            .to_owned()
    };
    assert_eq!(got[0]["id"], json!("bowtie"));
    assert!(
        error(0).contains("p: the boundary intersects itself: edges 0-1 and 2-3 cross"),
        "{}",
        error(0)
    );
    assert_eq!(got[1]["id"], json!(2));
    assert!(error(1).contains("q: a polygon needs at least 3 distinct vertices"));
    assert!(error(2).contains("beyond the f64 range"), "{}", error(2));
    assert!(error(3).contains("invalid JSON"));
    assert!(error(4).contains("empty line"));
    assert!(error(5).contains("p: all vertices lie on one line"));
    assert_eq!(got[6], json!({"id": [1], "points": [[2.0, 1.0], [2.0, 2.0]]}));
}

#[test]
fn points_print_round_trip_and_extremes_work() {
    // A crossing at a non-dyadic point, and a touching at 2^-1000 scale.
    let tiny = 2f64.powi(-1000);
    let input = format!(
        "{}{}",
        line("[[1,-1],[2,5],[0,5]]"),
        serde_json::to_string(&json!({
            "p": [[0.0, 0.0], [tiny, 0.0], [tiny, tiny]],
            "q": [[tiny, tiny], [2.0 * tiny, tiny], [2.0 * tiny, 2.0 * tiny]],
        }))
        .unwrap()
            + "\n",
    );
    let got = answers(&["crossings"], &input);
    let pts = got[0]["points"].as_array().unwrap();
    assert_eq!(pts.len(), 4);
    let first: Vec<f64> = serde_json::from_value(pts[0].clone()).unwrap();
    // The left edge of Q from (0,5) to (1,-1) crosses y = 4 at x = 1/6.
    assert!(
        (first[0] - 1.0 / 6.0).abs() < 1e-15 && first[1] == 4.0,
        "{first:?}"
    );
    assert_eq!(got[1], json!({"points": [[tiny, tiny]]}));
}

#[test]
fn unknown_algorithm_is_a_usage_error_and_list_names_both() {
    let (code, _, err) = run(&["crossings", "--algorithm", "bentley-ottmann"], b"");
    assert_eq!(code, 2);
    assert!(err.contains("valid: sweep, brute"), "{err}");
    let (code, out, _) = run(&["list"], b"");
    assert_eq!(code, 0);
    assert!(out.contains("sweep, brute"), "{out}");
}

#[test]
fn reads_a_file_argument() {
    let dir = std::env::temp_dir().join(format!("polysect-crossings-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("pairs.jsonl");
    std::fs::write(&path, line("[[3,1],[6,1],[2,4]]")).unwrap();
    let got = answers(&["crossings", path.to_str().unwrap()], "");
    assert_eq!(got, vec![json!({"points": [[2.0, 4.0], [4.0, 1.0], [4.0, 2.5]]})]);
    std::fs::remove_dir_all(&dir).unwrap();
}
