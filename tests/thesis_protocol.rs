//! `polysect bench --protocol thesis --quick`: the thesis's chapter 4 protocol in its
//! CI size. Checks the CSV it writes: every column, a row for each algorithm of each
//! experiment at each size, the pairs of both outcomes adding up to the pairs generated,
//! the same pairs for every algorithm, no wrong answers, iterations within the thesis's
//! bounds, CLM's counts consistent (five LPs and four walks on every disjoint pair).
//! No assertion on timings beyond "positive and finite".

use polysect::experiments::ThesisConfig;
use polysect::experiments::thesis::{CSV_HEADER, algorithms};
use polysect::intersect::Algorithm;
use std::collections::BTreeMap;
use std::fs;
use std::path::Path;
use std::process::Command;

fn read_csv(path: &Path) -> (Vec<String>, Vec<Vec<String>>) {
    let text = fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut lines = text.lines();
    let header: Vec<String> = lines
        .next()
        .expect("a header")
        .split(',')
        .map(String::from)
        .collect();
    let rows: Vec<Vec<String>> = lines.map(|l| l.split(',').map(String::from).collect()).collect();
    for row in &rows {
        assert_eq!(row.len(), header.len(), "{row:?}");
    }
    (header, rows)
}

#[test]
fn quick_thesis_protocol_writes_a_consistent_csv() {
    let dir = std::env::temp_dir().join(format!("polysect-thesis-{}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    let output = Command::new(env!("CARGO_BIN_EXE_polysect"))
        .args([
            "bench",
            "--protocol",
            "thesis",
            "--quick",
            "--no-progress",
            "--out",
        ])
        .arg(&dir)
        .output()
        .expect("polysect runs");
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(
        output.status.success(),
        "{stdout}\n{}",
        String::from_utf8_lossy(&output.stderr)
    );
    assert!(stdout.contains("CLM counts per query"), "{stdout}");
    // A mean over no LP or no walk is shown as "—", never as NaN.
    assert!(!stdout.contains("NaN") && !stdout.contains("inf"), "{stdout}");

    let config = ThesisConfig::quick(&dir);
    let (header, rows) = read_csv(&dir.join("thesis.csv"));
    assert_eq!(header, CSV_HEADER.map(String::from).to_vec());
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let get = |row: &[String], name: &str| row[col(name)].clone();
    let float = |row: &[String], name: &str| -> f64 {
        get(row, name)
            .parse()
            .unwrap_or_else(|_| panic!("{name} of {row:?}"))
    };

    // (family, algorithm, log2 n) → pairs over both outcomes.
    let mut pairs: BTreeMap<(String, String, u32), usize> = BTreeMap::new();
    for row in &rows {
        let key = (
            get(row, "family"),
            get(row, "algorithm"),
            float(row, "log2_total") as u32,
        );
        *pairs.entry(key).or_default() += float(row, "pairs") as usize;
        assert_eq!(get(row, "wrong"), "0", "{row:?}");
        assert_eq!(get(row, "over_bound"), "0", "{row:?}");
        for t in ["mean_ns", "median_ns"] {
            let t = float(row, t);
            assert!(t > 0.0 && t.is_finite(), "{row:?}");
        }
        let alg: Algorithm = get(row, "algorithm").parse().unwrap();
        if Algorithm::LOGARITHMIC.contains(&alg) {
            assert!(
                float(row, "iterations_mean") <= float(row, "bound_mean"),
                "{row:?}"
            );
        }
        if alg == Algorithm::Clm {
            let calls = float(row, "lp_calls_mean");
            // An intersecting query may end before any LP (a sample vertex inside the
            // other sample's quadrilateral).
            assert!((0.0..=5.0).contains(&calls), "{row:?}");
            assert!(float(row, "constraints_per_lp") >= 6.0, "{row:?}");
            assert!(float(row, "samples_mean") >= 6.0, "{row:?}");
            if get(row, "outcome") == "disjoint" {
                assert_eq!(calls, 5.0, "every disjoint query runs five LPs: {row:?}");
                assert_eq!(float(row, "walks_mean"), 4.0, "{row:?}");
                assert_eq!(float(row, "one_lp_share"), 0.0, "{row:?}");
                assert!(float(row, "steps_per_walk") >= 2.0, "{row:?}");
            }
        }
    }
    for &family in &config.families {
        for &alg in algorithms(family) {
            let sizes = if Algorithm::LINKED.contains(&alg) {
                &config.linked_log2_totals
            } else {
                &config.log2_totals
            };
            for &lt in sizes {
                let key = (family.to_string(), alg.to_string(), lt);
                assert_eq!(
                    pairs.get(&key).copied(),
                    Some(config.pairs),
                    "{key:?}: intersecting + disjoint pairs"
                );
            }
        }
    }
    // Every algorithm of a family saw the same pairs: equal counts per outcome.
    let mut per_outcome: BTreeMap<(String, u32, String), Vec<String>> = BTreeMap::new();
    for row in &rows {
        per_outcome
            .entry((
                get(row, "family"),
                float(row, "log2_total") as u32,
                get(row, "outcome"),
            ))
            .or_default()
            .push(get(row, "pairs"));
    }
    for (key, counts) in per_outcome {
        assert!(counts.windows(2).all(|w| w[0] == w[1]), "{key:?}: {counts:?}");
    }
    for fig in [
        "thesis_fig4_2a_ellipse.svg",
        "thesis_fig4_3_rotated.svg",
        "thesis_fig4_6.svg",
        "thesis_fig4_8.svg",
    ] {
        let svg = fs::read_to_string(dir.join(fig)).unwrap_or_else(|e| panic!("{fig}: {e}"));
        assert!(svg.contains("<polyline"), "{fig} draws no data");
    }
    let _ = fs::remove_dir_all(&dir);
}
