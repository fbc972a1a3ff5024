//! Every command the README shows with its output is run, and must print exactly that.
//!
//! The README writes such examples as `console` blocks: a line `$ COMMAND` (a here-document
//! `<<'EOF'` continues it up to the line `EOF`), then the lines it prints on standard
//! output. Each command runs under `sh -c` with the built `polysect` first on the `PATH`,
//! as a user who installed it would type it. So that no shown output escapes the check,
//! no other block of the README may show a JSON line.

use std::path::Path;
use std::process::Command;

const README: &str = include_str!("../README.md");

/// One `$ COMMAND` of a `console` block and the standard output shown below it.
struct Example {
    command: String,
    output: String,
    line: usize,
}

/// The fenced blocks of `text`: (info string, first line number of the body, body lines).
fn blocks(text: &str) -> Vec<(String, usize, Vec<&str>)> {
    let mut out = Vec::new();
    let mut open: Option<(String, usize, Vec<&str>)> = None;
    for (i, line) in text.lines().enumerate() {
        if let Some(info) = line.strip_prefix("```") {
            match open.take() {
                Some(block) => out.push(block),
                None => open = Some((info.trim().to_string(), i + 2, Vec::new())),
            }
        } else if let Some((_, _, body)) = open.as_mut() {
            body.push(line);
        }
    }
    assert!(open.is_none(), "README: a fenced block is never closed");
    out
}

fn examples(first_line: usize, body: &[&str]) -> Vec<Example> {
    let mut out: Vec<Example> = Vec::new();
    let mut i = 0;
    while i < body.len() {
        let line = body[i];
        let Some(command) = line.strip_prefix("$ ") else {
            let Some(last) = out.last_mut() else {
                panic!(
                    "README line {}: a console block starts with `$ COMMAND`",
                    first_line + i
                );
            };
            last.output.push_str(line);
            last.output.push('\n');
            i += 1;
            continue;
        };
        let mut command = command.to_string();
        let line_no = first_line + i;
        i += 1;
        if command.ends_with("<<'EOF'") || command.ends_with("<<EOF") {
            loop {
                let Some(more) = body.get(i) else {
                    panic!("README line {line_no}: the here-document never reaches EOF");
                };
                command.push('\n');
                command.push_str(more);
                i += 1;
                if *more == "EOF" {
                    break;
                }
            }
        }
        out.push(Example {
            command,
            output: String::new(),
            line: line_no,
        });
    }
    out
}

#[test]
fn every_readme_example_prints_what_it_shows() {
    let bin = Path::new(env!("CARGO_BIN_EXE_polysect"));
    let dir = bin.parent().expect("the binary has a directory");
    let path = format!("{}:{}", dir.display(), std::env::var("PATH").unwrap_or_default());
    let mut ran = 0;
    for (info, first_line, body) in blocks(README) {
        if info != "console" {
            for (k, line) in body.iter().enumerate() {
                assert!(
                    !line.trim_start().starts_with('{'),
                    "README line {}: a JSON line outside a `console` block is not checked; \
                     show it as `$ COMMAND` and its output",
                    first_line + k
                );
            }
            continue;
        }
        for example in examples(first_line, &body) {
            assert!(
                example.command.contains("polysect "),
                "README line {}: {}",
                example.line,
                example.command
            );
            let out = Command::new("sh")
                .arg("-c")
                .arg(&example.command)
                .env("PATH", &path)
                .output()
                .expect("sh runs");
            assert!(
                out.status.success(),
                "README line {}: `{}` failed: {}",
                example.line,
                example.command,
                String::from_utf8_lossy(&out.stderr)
            );
            let got = String::from_utf8(out.stdout).expect("UTF-8 output");
            assert_eq!(
                got, example.output,
                "README line {}: `{}` printed something else",
                example.line, example.command
            );
            ran += 1;
        }
    }
    // The certificate, hull and scene examples at least.
    assert!(ran >= 3, "only {ran} README examples found");
}

#[test]
fn the_parser_splits_commands_heredocs_and_output() {
    let body = [
        "$ echo 1 | polysect check",
        "out 1",
        "$ polysect scene <<'EOF'",
        "{}",
        "EOF",
        "a",
        "b",
    ];
    let got = examples(10, &body);
    assert_eq!(got.len(), 2);
    assert_eq!(
        (got[0].command.as_str(), got[0].output.as_str(), got[0].line),
        ("echo 1 | polysect check", "out 1\n", 10)
    );
    assert_eq!(
        (got[1].command.as_str(), got[1].output.as_str(), got[1].line),
        ("polysect scene <<'EOF'\n{}\nEOF", "a\nb\n", 12)
    );
}
