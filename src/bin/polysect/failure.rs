//! Why a command failed, and so its exit code.

use std::io;

/// Why a command failed, and so its exit code.
pub(crate) enum Failure {
    /// Exit 2: a usage error found after parsing (options that do not fit together,
    /// an output name render cannot write, a run that would not fit in memory).
    Usage { command: &'static str, message: String },
    /// Exit 1: input or output failed (0 when the reader closed the output pipe).
    Io(io::Error),
    /// Exit 3: `check --verify-expected` found answers that disagree with "expected".
    Disagreed(String),
}

impl From<io::Error> for Failure {
    fn from(e: io::Error) -> Self {
        Failure::Io(e)
    }
}
