//! The `polysect` binary from outside, one test crate for every subcommand (each module
//! is one subcommand's contract or one concern of all of them): the binary is built
//! once and the tests link the library once.

#[path = "../common/mod.rs"]
mod common;

/// The JSON lines the binary prints for `input` under `args`, after it exited with 0
/// (a failure shows its standard error).
fn answers(args: &[&str], input: &str) -> Vec<serde_json::Value> {
    let (code, out, err) = common::run(args, input.as_bytes());
    assert_eq!(code, 0, "stderr: {err}");
    out.lines()
        .map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("not a JSON line ({e}): {l}")))
        .collect()
}

mod certificates;
mod check;
mod contact;
mod crossings;
mod gen_simple;
mod hull;
mod options;
mod scene;
