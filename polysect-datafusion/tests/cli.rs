//! The `polysect-datafusion` binary: `gen` writes GeoParquet, `join` prints the pairs,
//! which equal the core `Scene`'s on the same polygons.

mod common;

use polysect_datafusion::tables::{self, Layout, TableSpec};
use std::collections::BTreeSet;
use std::process::Command;

const BIN: &str = env!("CARGO_BIN_EXE_polysect-datafusion");

fn gen_file(dir: &std::path::Path, name: &str, spec: &TableSpec) -> std::path::PathBuf {
    let path = dir.join(name);
    let layout = match spec.layout {
        Layout::Uniform => "uniform",
        Layout::Clustered => "clustered",
    };
    let status = Command::new(BIN)
        .args(["gen", "--out"])
        .arg(&path)
        .args([
            "--rows",
            &spec.rows.to_string(),
            "--vertices",
            &spec.vertices.to_string(),
        ])
        .args([
            "--seed",
            &spec.seed.to_string(),
            "--partners",
            &spec.partners.to_string(),
            "--layout",
            layout,
        ])
        .status()
        .unwrap();
    assert!(status.success());
    path
}

fn pairs(stdout: &[u8]) -> Vec<(i64, i64)> {
    let text = String::from_utf8(stdout.to_vec()).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("left_id,right_id"));
    lines
        .map(|l| {
            let (a, b) = l.split_once(',').unwrap();
            (a.parse().unwrap(), b.parse().unwrap())
        })
        .collect()
}

#[test]
fn gen_then_join_prints_the_scenes_pairs() {
    let dir = std::env::temp_dir().join(format!("polysect-datafusion-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let a = TableSpec {
        rows: 700,
        vertices: 12,
        seed: 11,
        partners: 2.0,
        layout: Layout::Uniform,
    };
    let b = TableSpec {
        rows: 500,
        vertices: 5,
        seed: 12,
        partners: 2.0,
        layout: Layout::Uniform,
    };
    let (pa, pb) = (gen_file(&dir, "a.parquet", &a), gen_file(&dir, "b.parquet", &b));
    let expected = common::scene_pairs(&tables::polygons(&a), &tables::polygons(&b));
    assert!(expected.len() > 100, "{}", expected.len());
    for extra in [&[][..], &["--cell-size", "0.3"][..]] {
        let out = Command::new(BIN)
            .arg("join")
            .arg(&pa)
            .arg(&pb)
            .args(extra)
            .output()
            .unwrap();
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        let got = pairs(&out.stdout);
        let set: BTreeSet<(i64, i64)> = got.iter().copied().collect();
        assert_eq!(set.len(), got.len(), "duplicates");
        assert_eq!(set, expected);
        assert!(String::from_utf8_lossy(&out.stderr).contains(&format!("{} pairs", expected.len())));
    }
    // The file is GeoParquet: its metadata names the WKB column.
    let bytes = std::fs::read(&pa).unwrap();
    assert!(bytes.windows(22).any(|w| w == br#""primary_column":"geom"#));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_input_is_an_error_saying_what() {
    let out = Command::new(BIN)
        .args(["join", "/nonexistent/a.parquet", "/nonexistent/b.parquet"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(!out.stderr.is_empty());
    let out = Command::new(BIN)
        .args(["join", "a", "b", "--cell-size=0"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("--cell-size"),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let out = Command::new(BIN)
        .args(["gen", "--out", "x.parquet", "--vertices", "2"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
}
