//! Shared by the CLI test files.

use std::io::Write;
use std::process::{Command, Stdio};

/// Runs the `polysect` binary with `args`, feeding `input` on standard input from a
/// separate thread (so large inputs and outputs cannot deadlock on full pipes); returns
/// the exit code, standard output and standard error.
pub fn run(args: &[&str], input: &[u8]) -> (i32, String, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_polysect"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary starts");
    let mut stdin = child.stdin.take().expect("piped stdin");
    let input = input.to_vec();
    let writer = std::thread::spawn(move || stdin.write_all(&input));
    let out = child.wait_with_output().expect("the binary finishes");
    writer
        .join()
        .expect("the writer thread")
        .expect("stdin accepts the input");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8(out.stdout).expect("UTF-8 output"),
        String::from_utf8(out.stderr).expect("UTF-8 errors"),
    )
}
