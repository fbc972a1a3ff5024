//! Just enough HTTP/1.1 for the page: read one bounded request head, parse it with
//! `httparse`, answer with a complete response and close. No keep-alive, no bodies.

use std::io::{self, Read, Write};
use std::net::{IpAddr, SocketAddr};

/// The largest request head accepted, in bytes.
pub const MAX_HEAD_BYTES: usize = 8192;
const MAX_HEADERS: usize = 32;

/// A parsed request head.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Request {
    /// The method (`GET`, `HEAD`, ...), as sent.
    pub method: String,
    /// The path without the query string.
    pub path: String,
    /// Header names in lower case, values as sent (non-UTF-8 values are dropped).
    pub headers: Vec<(String, String)>,
}

impl Request {
    /// The first header named `name` (lower case).
    pub fn header(&self, name: &str) -> Option<&str> {
        self.headers
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, v)| v.as_str())
    }

    /// Whether `name` lists `token` (comma-separated, case-insensitive), as
    /// `Connection: keep-alive, Upgrade` does.
    pub fn header_has(&self, name: &str, token: &str) -> bool {
        self.header(name)
            .is_some_and(|v| v.split(',').any(|t| t.trim().eq_ignore_ascii_case(token)))
    }
}

/// Why a request head could not be read.
#[derive(Debug)]
pub enum HeadError {
    /// Reading failed or the peer closed early.
    Io(io::Error),
    /// Answer with this status and message.
    Bad(u16, String),
}

/// Reads a request head (up to the blank line) from `stream`, at most
/// [`MAX_HEAD_BYTES`]; returns it parsed and the bytes read past it.
///
/// # Errors
/// `Io` when reading fails or the peer closes early; `Bad(431)` when the head is too
/// large; `Bad(400)` when it does not parse.
pub fn read_request(stream: &mut impl Read) -> Result<(Request, Vec<u8>), HeadError> {
    let mut buf = Vec::with_capacity(1024);
    let mut chunk = [0u8; 1024];
    loop {
        let n = stream.read(&mut chunk).map_err(HeadError::Io)?;
        if n == 0 {
            return Err(HeadError::Io(io::Error::new(
                io::ErrorKind::UnexpectedEof,
                "the connection closed before the request head ended",
            )));
        }
        buf.extend_from_slice(&chunk[..n]);
        let mut headers = [httparse::EMPTY_HEADER; MAX_HEADERS];
        let mut req = httparse::Request::new(&mut headers);
        match req.parse(&buf) {
            Ok(httparse::Status::Complete(len)) => {
                let path = req.path.unwrap_or("/");
                let request = Request {
                    method: req.method.unwrap_or("").to_string(),
                    path: path.split(['?', '#']).next().unwrap_or("/").to_string(),
                    headers: req
                        .headers
                        .iter()
                        .filter_map(|h| {
                            std::str::from_utf8(h.value)
                                .ok()
                                .map(|v| (h.name.to_ascii_lowercase(), v.trim().to_string()))
                        })
                        .collect(),
                };
                return Ok((request, buf[len..].to_vec()));
            }
            Ok(httparse::Status::Partial) if buf.len() < MAX_HEAD_BYTES => {}
            Ok(httparse::Status::Partial) => {
                return Err(HeadError::Bad(
                    431,
                    format!("request head larger than {MAX_HEAD_BYTES} bytes"),
                ));
            }
            Err(e) => return Err(HeadError::Bad(400, format!("malformed request: {e}"))),
        }
    }
}

/// Whether a `Host` header value names the server bound to `bound`: the port must be
/// the bound port (or absent when that is 80), and the host
/// - an IP address: the bound address; any loopback address when bound to loopback; any
///   address when bound to all interfaces (`0.0.0.0`, `::`);
/// - a name: only `localhost` (any case), and only when bound to loopback or to all
///   interfaces.
///
/// Any other name is refused: a page that reached this server through a name of its own
/// (DNS rebinding) sends that name.
pub fn host_names_server(host: &str, bound: SocketAddr) -> bool {
    let (name, port) = match host.strip_prefix('[') {
        Some(bracketed) => match bracketed.split_once(']') {
            Some((inside, after)) => (inside, after),
            None => return false,
        },
        None => match host.find(':') {
            Some(k) => (&host[..k], &host[k..]),
            None => (host, ""),
        },
    };
    let port_ok = match port {
        "" => bound.port() == 80,
        p => {
            p.strip_prefix(':')
                .filter(|d| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit()))
                .and_then(|d| d.parse::<u16>().ok())
                == Some(bound.port())
        }
    };
    if !port_ok {
        return false;
    }
    let ip = bound.ip();
    let bracketed = host.starts_with('[');
    match name.parse::<IpAddr>() {
        // An IPv6 address only in brackets, an IPv4 one only without.
        Ok(addr) if addr.is_ipv6() == bracketed => {
            addr == ip || (ip.is_loopback() && addr.is_loopback()) || ip.is_unspecified()
        }
        Ok(_) => false,
        Err(_) => {
            !bracketed && name.eq_ignore_ascii_case("localhost") && (ip.is_loopback() || ip.is_unspecified())
        }
    }
}

fn reason(status: u16) -> &'static str {
    match status {
        200 => "OK",
        400 => "Bad Request",
        403 => "Forbidden",
        404 => "Not Found",
        405 => "Method Not Allowed",
        408 => "Request Timeout",
        421 => "Misdirected Request",
        426 => "Upgrade Required",
        431 => "Request Header Fields Too Large",
        503 => "Service Unavailable",
        _ => "Error",
    }
}

/// Writes a complete response and flushes; `head_only` omits the body (for HEAD).
///
/// # Errors
/// Writing to `stream` failed.
pub fn respond(
    stream: &mut impl Write,
    status: u16,
    content_type: &str,
    body: &[u8],
    head_only: bool,
) -> io::Result<()> {
    write!(
        stream,
        "HTTP/1.1 {status} {}\r\nContent-Type: {content_type}\r\nContent-Length: {}\r\n\
         Cache-Control: no-store\r\nX-Content-Type-Options: nosniff\r\nConnection: close\r\n\r\n",
        reason(status),
        body.len()
    )?;
    if !head_only {
        stream.write_all(body)?;
    }
    stream.flush()
}

/// A plain-text error response.
///
/// # Errors
/// Writing to `stream` failed.
pub fn respond_error(stream: &mut impl Write, status: u16, message: &str) -> io::Result<()> {
    respond(
        stream,
        status,
        "text/plain; charset=utf-8",
        format!("{message}\n").as_bytes(),
        false,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A reader that hands out at most `step` bytes per read.
    struct Trickle<'a> {
        data: &'a [u8],
        step: usize,
    }

    impl Read for Trickle<'_> {
        fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
            let n = self.step.min(buf.len()).min(self.data.len());
            buf[..n].copy_from_slice(&self.data[..n]);
            self.data = &self.data[n..];
            Ok(n)
        }
    }

    #[test]
    fn parses_a_request_arriving_in_pieces() {
        let raw = b"GET /ws?x=1 HTTP/1.1\r\nHost: 127.0.0.1:8080\r\nConnection: keep-alive, Upgrade\r\n\
                    Upgrade: websocket\r\n\r\nrest";
        let (req, rest) = read_request(&mut Trickle { data: raw, step: 7 }).expect("parses");
        assert_eq!(req.method, "GET");
        assert_eq!(req.path, "/ws");
        assert_eq!(req.header("host"), Some("127.0.0.1:8080"));
        assert!(req.header_has("connection", "upgrade"));
        assert!(!req.header_has("connection", "close"));
        assert!(rest.starts_with(b"rest") || rest.is_empty());
    }

    #[test]
    fn the_host_must_name_the_bound_address() {
        let local: SocketAddr = "127.0.0.1:8080".parse().unwrap();
        for host in [
            "127.0.0.1:8080",
            "localhost:8080",
            "LocalHost:8080",
            "[::1]:8080",
            "127.0.0.2:8080",
        ] {
            assert!(host_names_server(host, local), "{host}");
        }
        for host in [
            "rebind.attacker.example:8080",
            "localhost.attacker.example:8080",
            "127.0.0.1.nip.io:8080",
            "127.0.0.1:8081",
            "127.0.0.1",
            "localhost",
            "127.0.0.1:",
            "127.0.0.1:+8080",
            "127.0.0.1:08080x",
            "[127.0.0.1]:8080",
            "::1:8080",
            "[::1:8080",
            "[::1]8080",
            "10.0.0.1:8080",
            "",
            ":8080",
        ] {
            assert!(!host_names_server(host, local), "{host}");
        }
        let on_80: SocketAddr = "127.0.0.1:80".parse().unwrap();
        assert!(host_names_server("localhost", on_80));
        assert!(host_names_server("127.0.0.1:80", on_80));
        let lan: SocketAddr = "192.168.1.5:9000".parse().unwrap();
        assert!(host_names_server("192.168.1.5:9000", lan));
        assert!(!host_names_server("localhost:9000", lan));
        assert!(!host_names_server("127.0.0.1:9000", lan));
        assert!(!host_names_server("mybox.example:9000", lan));
        let all: SocketAddr = "0.0.0.0:9000".parse().unwrap();
        assert!(host_names_server("192.168.1.5:9000", all));
        assert!(host_names_server("localhost:9000", all));
        assert!(!host_names_server("mybox.example:9000", all));
        let v6: SocketAddr = "[::1]:9000".parse().unwrap();
        assert!(host_names_server("[::1]:9000", v6));
        assert!(host_names_server("localhost:9000", v6));
        assert!(!host_names_server("[::2]:9000", v6));
    }

    #[test]
    fn refuses_garbage_huge_and_truncated_heads() {
        let garbage = b"\x00\x01\x02 nonsense\r\n\r\n";
        assert!(matches!(
            read_request(&mut Trickle {
                data: garbage,
                step: 64
            }),
            Err(HeadError::Bad(400, _))
        ));
        let huge = format!("GET / HTTP/1.1\r\nX: {}\r\n\r\n", "a".repeat(3 * MAX_HEAD_BYTES));
        assert!(matches!(
            read_request(&mut Trickle {
                data: huge.as_bytes(),
                step: 1000
            }),
            Err(HeadError::Bad(431, _))
        ));
        let many: String = (0..100).map(|i| format!("H{i}: v\r\n")).collect();
        let many = format!("GET / HTTP/1.1\r\n{many}\r\n");
        assert!(matches!(
            read_request(&mut Trickle {
                data: many.as_bytes(),
                step: 1000
            }),
            Err(HeadError::Bad(400, _))
        ));
        assert!(matches!(
            read_request(&mut Trickle {
                data: b"GET / HT",
                step: 3
            }),
            Err(HeadError::Io(_))
        ));
    }
}
