//! The `polysect bench` code path in a tiny configuration: every experiment writes
//! parseable CSV with the expected columns and SVG files. No assertion on timings.

use polysect::experiments::{self, Config, Experiment};
use std::fs;
use std::path::Path;
use std::time::Duration;

fn tiny(out: &Path) -> Config {
    Config {
        log2_sizes: vec![4, 6],
        crossover_log2_sizes: vec![5.0, 5.5, 6.0],
        pairs: 2,
        large_pairs: 1,
        min_time: Duration::from_micros(200),
        trade_n: 16,
        trade_pairs: 4,
        trade_circle_log2: 8,
        ratio_log2_sizes: vec![6, 8],
        factor_log2_sizes: vec![6],
        factors: vec![0.5, 1.0],
        crossings_sizes: vec![5, 40],
        crossings_pairs: 1,
        progress: false,
        ..Config::quick(out)
    }
}

/// Parses a CSV file: the header and the rows, each with as many fields as the header.
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
        assert_eq!(row.len(), header.len(), "{}: {row:?}", path.display());
    }
    (header, rows)
}

fn column<'a>(header: &[String], rows: &'a [Vec<String>], name: &str) -> Vec<&'a str> {
    let i = header
        .iter()
        .position(|h| h == name)
        .unwrap_or_else(|| panic!("no column {name} in {header:?}"));
    rows.iter().map(|r| r[i].as_str()).collect()
}

#[test]
fn every_experiment_writes_csv_and_svg() {
    let dir = std::env::temp_dir().join(format!("polysect-bench-test-{}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    let config = tiny(&dir);
    let report = experiments::run(Experiment::ALL, &config).expect("the run writes its files");

    for file in &report.files {
        assert!(dir.join(file).is_file(), "{file} listed but missing");
    }
    let svgs: Vec<&String> = report.files.iter().filter(|f| f.ends_with(".svg")).collect();
    assert!(svgs.len() >= Experiment::ALL.len(), "{svgs:?}");
    for svg in svgs {
        let text = fs::read_to_string(dir.join(svg)).unwrap();
        assert!(
            text.starts_with("<svg") && text.trim_end().ends_with("</svg>"),
            "{svg}"
        );
        assert!(
            text.contains("<polyline") || text.contains("<circle"),
            "{svg} draws no data"
        );
    }

    // The curve experiments: one row per (family, relation, algorithm, n), times positive.
    for name in ["scaling.csv", "densities.csv", "clm_sqrt.csv", "crossover.csv"] {
        let (header, rows) = read_csv(&dir.join(name));
        for col in [
            "family",
            "relation",
            "algorithm",
            "kernel",
            "n",
            "median_ns",
            "ns_per_log2_total",
            "ns_per_sqrt_total",
            "median_iterations",
            "wrong",
        ] {
            column(&header, &rows, col);
        }
        assert!(!rows.is_empty(), "{name}");
        for t in column(&header, &rows, "median_ns") {
            let t: f64 = t.parse().unwrap();
            assert!(t > 0.0 && t.is_finite(), "{name}: {t}");
        }
        // Under the exact kernel every algorithm agrees with the reference.
        assert!(
            column(&header, &rows, "wrong").iter().all(|w| *w == "0"),
            "{name}"
        );
    }
    let (header, rows) = read_csv(&dir.join("scaling.csv"));
    let algs = column(&header, &rows, "algorithm");
    for alg in polysect::intersect::Algorithm::ALL {
        assert!(algs.contains(&alg.name()), "{alg} missing from scaling.csv");
    }
    let ns: Vec<&str> = column(&header, &rows, "n");
    assert!(ns.contains(&"16") && ns.contains(&"64"));

    // The trade table: every algorithm × kernel × case, exact rows without wrong answers.
    let (header, rows) = read_csv(&dir.join("trade.csv"));
    let cases: std::collections::BTreeSet<&str> = column(&header, &rows, "case").into_iter().collect();
    assert_eq!(cases.len(), 8, "{cases:?}");
    assert_eq!(rows.len(), 8 * polysect::intersect::Algorithm::ALL.len() * 2);
    let kernels = column(&header, &rows, "kernel");
    let wrong = column(&header, &rows, "wrong");
    for (k, w) in kernels.iter().zip(&wrong) {
        let w: usize = w.parse().unwrap();
        if *k == "exact" {
            assert_eq!(w, 0);
        }
    }
    for r in column(&header, &rows, "exact_over_fast") {
        let r: f64 = r.parse().unwrap();
        assert!(r > 0.0 && r.is_finite(), "{r}");
    }
    // The exact kernel's overhead: every algorithm at every size, disjoint and
    // intersecting, positive times.
    let (header, rows) = read_csv(&dir.join("trade_ratio.csv"));
    assert_eq!(rows.len(), 2 * 2 * polysect::intersect::Algorithm::ALL.len());
    assert_eq!(
        column(&header, &rows, "relation")
            .into_iter()
            .collect::<std::collections::BTreeSet<_>>(),
        ["disjoint", "intersecting"].into_iter().collect()
    );
    assert_eq!(
        column(&header, &rows, "n")
            .into_iter()
            .collect::<std::collections::BTreeSet<_>>(),
        ["256", "64"].into_iter().collect()
    );
    for name in ["fast_ns", "exact_ns", "exact_over_fast"] {
        for v in column(&header, &rows, name) {
            let v: f64 = v.parse().unwrap();
            assert!(v > 0.0 && v.is_finite(), "{name}: {v}");
        }
    }
    let md = fs::read_to_string(dir.join("trade.md")).unwrap();
    assert!(md.contains("Exact kernel time / fast kernel time"), "{md}");
    assert!(
        md.lines().filter(|l| l.starts_with("| ")).count() > 2 * polysect::intersect::Algorithm::ALL.len()
    );

    let (header, rows) = read_csv(&dir.join("clm_factor.csv"));
    // One row per factor and relation.
    assert_eq!(column(&header, &rows, "factor"), ["0.5", "0.5", "1", "1"]);
    assert_eq!(
        column(&header, &rows, "relation"),
        ["intersecting", "disjoint", "intersecting", "disjoint"]
    );

    // CLM against its memory limit and its variants: positive times at every size.
    let (header, rows) = read_csv(&dir.join("clm_limit.csv"));
    assert_eq!(rows.len(), 2 * 2, "two sizes, two relations");
    for name in [
        "clm_ns",
        "limit_ns",
        "clm_over_limit",
        "limit_two_ns",
        "clm_over_limit_two",
    ] {
        for v in column(&header, &rows, name) {
            let v: f64 = v.parse().unwrap();
            assert!(v > 0.0 && v.is_finite(), "{name}: {v}");
        }
    }
    let (header, rows) = read_csv(&dir.join("clm_variants.csv"));
    assert_eq!(rows.len(), 2 * 6, "one size, two relations, six variants");
    for v in column(&header, &rows, "median_ns") {
        let v: f64 = v.parse().unwrap();
        assert!(v > 0.0 && v.is_finite(), "{v}");
    }

    // Tables: every time cell carries its unit (the headers no longer promise ns).
    assert!(!report.summary.contains("median ns"), "{}", report.summary);
    let scaling = report
        .summary
        .split("## ")
        .find(|section| section.starts_with("scaling"))
        .expect("a scaling section");
    let scaling_rows: Vec<&str> = scaling
        .lines()
        .filter(|l| l.starts_with("| linear") || l.starts_with("| barba"))
        .collect();
    assert!(!scaling_rows.is_empty());
    for row in scaling_rows {
        for cell in row.split('|').skip(2).filter(|c| !c.trim().is_empty()) {
            for time in cell.split('/') {
                let time = time.trim();
                assert!(
                    ["ns", "µs", "ms", "s"]
                        .iter()
                        .any(|u| time.ends_with(&format!(" {u}")))
                        || time == "–",
                    "{time:?} in {row}"
                );
            }
        }
    }
    // Plots: axis labels name values, not field names; log ticks are round numbers.
    let trade = fs::read_to_string(dir.join("trade.svg")).unwrap();
    assert!(trade.contains("n = 16") && !trade.contains("trade_n"));
    for svg in report.files.iter().filter(|f| f.ends_with(".svg")) {
        let text = fs::read_to_string(dir.join(svg)).unwrap();
        for label in text
            .split("<text")
            .skip(1)
            .filter_map(|t| t.split_once('>')?.1.split('<').next())
        {
            let number = label.trim_end_matches(['k', 'M', 'G']);
            if number.parse::<f64>().is_ok() {
                let digits: String = number.chars().filter(char::is_ascii_digit).collect();
                let significant = digits.trim_start_matches('0').trim_end_matches('0').len();
                assert!(significant <= 3, "{svg}: tick label {label:?}");
            }
        }
    }
    // CLM's counts, apart: a row per (relation, n); every disjoint query runs five LPs
    // and four walks (samples of 4 and 8 vertices are never the whole polygon here).
    let (header, rows) = read_csv(&dir.join("clm_counts.csv"));
    assert_eq!(rows.len(), 2 * 2, "{rows:?}");
    let relations = column(&header, &rows, "relation");
    let calls = column(&header, &rows, "lp_calls_mean");
    let walks = column(&header, &rows, "walks_mean");
    for ((r, c), w) in relations.iter().zip(&calls).zip(&walks) {
        let (c, w): (f64, f64) = (c.parse().unwrap(), w.parse().unwrap());
        assert!((1.0..=5.0).contains(&c), "{r}: {c} LP calls");
        if *r == "disjoint" {
            assert_eq!((c, w), (5.0, 4.0), "disjoint queries run five LPs and four walks");
        }
    }
    for v in column(&header, &rows, "constraints_per_lp") {
        assert!(v.parse::<f64>().unwrap() >= 6.0, "{v}");
    }
    check_crossings_csv(&dir.join("crossings.csv"), &[5, 40]);
    let _ = fs::remove_dir_all(&dir);
}

/// The crossings experiment's table: every Δ and σ of the report in docs/crossings.md × n × algorithm, the
/// sweep agreeing with the brute force, the counts consistent.
fn check_crossings_csv(path: &Path, sizes: &[usize]) {
    let (header, rows) = read_csv(path);
    let params: std::collections::BTreeSet<(&str, &str)> = column(&header, &rows, "distribution")
        .into_iter()
        .zip(column(&header, &rows, "parameter"))
        .collect();
    let want: Vec<(&str, &str)> = ["10", "50", "100", "500"]
        .map(|d| ("uniform", d))
        .into_iter()
        .chain(["10", "20", "50", "100"].map(|s| ("normal", s)))
        .collect();
    assert_eq!(params, want.into_iter().collect());
    let algs = [
        "sweep",
        "brute",
        "brute-nobox",
        "brute-division",
        "sweep-division",
    ];
    assert_eq!(rows.len(), 8 * sizes.len() * algs.len());
    for (i, alg) in column(&header, &rows, "algorithm").iter().enumerate() {
        assert_eq!(*alg, algs[i % algs.len()]);
    }
    let num = |name: &str| -> Vec<f64> {
        column(&header, &rows, name)
            .iter()
            .map(|v| v.parse().unwrap())
            .collect()
    };
    assert!(num("median_ns").iter().all(|t| *t > 0.0 && t.is_finite()));
    assert!(num("wrong").iter().all(|w| *w == 0.0));
    for ((n, pairs), (cand, tests)) in num("n")
        .iter()
        .zip(num("brute_pairs"))
        .zip(num("candidates").into_iter().zip(num("tests")))
    {
        assert!(sizes.contains(&(*n as usize)));
        assert_eq!(pairs, n * n);
        assert!(tests <= cand && cand <= 2.0 * pairs, "{tests} {cand} {pairs}");
    }
}

#[test]
fn cli_bench_crossings_quick_writes_its_csv_and_plots() {
    let dir = std::env::temp_dir().join(format!("polysect-bench-crossings-{}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_polysect"))
        .args(["bench", "crossings", "--quick", "--no-progress", "--out"])
        .arg(&dir)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("| uniform Δ = 500 | 1000 |"), "{stdout}");
    check_crossings_csv(&dir.join("crossings.csv"), &[5, 50, 200, 1000]);
    for svg in [
        "crossings_uniform.svg",
        "crossings_normal.svg",
        "crossings_ratios.svg",
    ] {
        let text = fs::read_to_string(dir.join(svg)).unwrap();
        assert!(text.starts_with("<svg") && text.contains("<polyline"), "{svg}");
    }
    let _ = fs::remove_dir_all(&dir);
}

#[test]
fn experiment_names_round_trip() {
    for &e in Experiment::ALL {
        assert_eq!(e.name().parse::<Experiment>(), Ok(e));
    }
    assert!("nope".parse::<Experiment>().unwrap_err().contains("scaling"));
}

#[test]
fn cli_refuses_an_unknown_experiment_naming_the_valid_ones() {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_polysect"))
        .args(["bench", "nope", "--out", "/nonexistent-dir-never-created"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("crossover") && err.contains("trade"), "{err}");
}
