//! Standard input or a named file in, buffered standard output out.

use std::io::{self, BufWriter, Read};

pub(crate) fn open_input(file: Option<&str>) -> io::Result<Box<dyn Read>> {
    Ok(match file {
        None | Some("-") => Box::new(io::stdin().lock()),
        Some(path) => {
            let cannot = |e: io::Error| io::Error::new(e.kind(), format!("cannot read {path}: {e}"));
            let file = std::fs::File::open(path).map_err(cannot)?;
            Box::new(InputFile {
                path: path.to_string(),
                file,
            })
        }
    })
}

/// A file whose read errors name it.
pub(crate) struct InputFile {
    path: String,
    file: std::fs::File,
}

impl Read for InputFile {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        self.file
            .read(buf)
            .map_err(|e| io::Error::new(e.kind(), format!("cannot read {}: {e}", self.path)))
    }
}

/// Standard output, buffered; the protocols flush it whenever they would wait for input.
pub(crate) fn output() -> BufWriter<io::StdoutLock<'static>> {
    BufWriter::with_capacity(64 * 1024, io::stdout().lock())
}
