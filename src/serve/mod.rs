//! The live page: `polysect serve` runs a small web server whose page shows convex
//! polygons moving, colliding and being edited in a real [`Scene`](crate::store::Scene).
//!
//! # Architecture
//! The simulation runs **in this process**, in Rust, one [`Simulation`] per open page;
//! the page is plain HTML, JavaScript and a canvas (built into the binary with
//! `include_str!`), talking to it over one WebSocket. The page asks for a frame, the
//! server moves and turns the polygons (an absolute pose each), asks the store for the
//! intersecting pairs and answers with one pose per polygon, the pairs, the figures and,
//! for scenes of at most [`MAX_WORLD_POINTS`](sim::MAX_WORLD_POINTS) vertices, every
//! world point as binary `f64` data; edits from the page go through the store's
//! validated edits and come back as the edited vertex. The shapes cross the wire once
//! per scene, as binary `f64` data. docs/live.md argues
//! the choice against compiling the library to WebAssembly.
//!
//! # Threads and bounds
//! One thread accepts connections; each connection gets a thread that reads one request
//! head (at most [`http::MAX_HEAD_BYTES`], all of it within [`HEAD_DEADLINE`], else
//! 408) and either answers it (the page, its script) or upgrades it to the WebSocket
//! and runs a [`Session`] until the page closes or sends nothing for [`IDLE_TIMEOUT`]
//! (closed with status 1001). At most [`MAX_CONNECTIONS`] connections are served at
//! once and at most [`MAX_SESSIONS`] of them are pages. When every connection is taken,
//! the one that has been sending its head the longest is closed to make room (so slow
//! heads cannot shut normal clients out); when none is sending a head, the new one gets
//! 503. [`Config`] holds these limits. WebSocket messages above
//! [`protocol::MAX_TRANSPORT_BYTES`] close the connection; smaller ones above
//! [`protocol::MAX_MESSAGE_BYTES`] get an error reply; a text message that is not UTF-8
//! gets an error reply and a 1007 close.
//!
//! # Who may connect
//! Every request's `Host` must name this server ([`http::host_names_server`]: loopback
//! names and addresses when bound to loopback, else the bound address), else 421: a page
//! that reached the server through a DNS name of its own (DNS rebinding) is refused. A
//! WebSocket handshake whose `Origin` is not `http://` + that `Host` is refused (403),
//! so other web sites cannot drive it. A non-loopback address gets a warning
//! ([`Server::exposure_warning`]).
//!
//! # Precision
//! The store decides every pair with the precision chosen on the page; positions are
//! exact on both sides of the wire (see [`sim`]).

mod contact;
pub mod http;
pub mod protocol;
pub mod sim;
pub mod trace;

pub use contact::{penetration_normal, separation_normal};
pub use protocol::{Reply, Session};
pub use sim::{Settings, Simulation};

use std::io::{self, Read, Write};
use std::net::{IpAddr, SocketAddr, TcpListener, TcpStream};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, PoisonError};
use std::time::{Duration, Instant};
use tungstenite::protocol::{CloseFrame, Role, WebSocket, WebSocketConfig, frame::coding::CloseCode};
use tungstenite::{Error as WsError, Message};

/// Connections served at once (page loads, scripts, WebSockets).
pub const MAX_CONNECTIONS: usize = 32;
/// Pages (WebSocket sessions) served at once.
pub const MAX_SESSIONS: usize = 8;
/// The time a connection has to send its whole request head.
pub const HEAD_DEADLINE: Duration = Duration::from_secs(10);
/// A page that sends no message for this long is closed (WebSocket status 1001).
pub const IDLE_TIMEOUT: Duration = Duration::from_secs(600);
/// The time an HTTP response, or one batch of WebSocket replies, has to be written.
pub const WRITE_DEADLINE: Duration = Duration::from_secs(30);

const INDEX_HTML: &str = include_str!("assets/index.html");
const LIVE_JS: &str = include_str!("assets/live.js");

/// The server's limits. [`Config::default`] is what `polysect serve` uses: the constants
/// of this module.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Config {
    /// Connections served at once ([`MAX_CONNECTIONS`]).
    pub connections: usize,
    /// Pages served at once ([`MAX_SESSIONS`]).
    pub sessions: usize,
    /// The time to send a whole request head ([`HEAD_DEADLINE`]).
    pub head_deadline: Duration,
    /// The longest a page may stay silent ([`IDLE_TIMEOUT`]).
    pub idle_timeout: Duration,
}

impl Default for Config {
    fn default() -> Self {
        Config {
            connections: MAX_CONNECTIONS,
            sessions: MAX_SESSIONS,
            head_deadline: HEAD_DEADLINE,
            idle_timeout: IDLE_TIMEOUT,
        }
    }
}

/// A bound, listening server.
#[derive(Debug)]
pub struct Server {
    listener: TcpListener,
    addr: SocketAddr,
    config: Config,
}

impl Server {
    /// Listens on `bind:port` (port 0: one the system chooses), with the default
    /// [`Config`].
    ///
    /// # Errors
    /// The address cannot be bound; the message names the address and the port (for a
    /// port in use: "port P is already in use").
    pub fn bind(bind: IpAddr, port: u16) -> io::Result<Server> {
        let listener = TcpListener::bind((bind, port)).map_err(|e| {
            let what = if e.kind() == io::ErrorKind::AddrInUse {
                format!("port {port} is already in use")
            } else {
                e.to_string()
            };
            io::Error::new(
                e.kind(),
                format!(
                    "cannot listen on {} (port {port}): {what}",
                    SocketAddr::new(bind, port)
                ),
            )
        })?;
        let addr = listener.local_addr()?;
        Ok(Server {
            listener,
            addr,
            config: Config::default(),
        })
    }

    /// The same server with other limits (at least one connection and one page).
    pub fn with_config(self, config: Config) -> Server {
        Server {
            config: Config {
                connections: config.connections.max(1),
                sessions: config.sessions.max(1),
                ..config
            },
            ..self
        }
    }

    /// The address it listens on (the port chosen when asked for port 0).
    pub fn local_addr(&self) -> SocketAddr {
        self.addr
    }

    /// The page's address, `http://ADDR:PORT/` (IPv6 addresses in brackets).
    pub fn url(&self) -> String {
        format!("http://{}/", self.addr)
    }

    /// A warning to print before serving on an address other hosts can reach, or `None`
    /// on loopback.
    pub fn exposure_warning(&self) -> Option<String> {
        exposure_warning(self.addr)
    }

    /// Serves until the process ends. Returns only if accepting fails for good.
    ///
    /// # Errors
    /// The listening socket fails.
    pub fn run(self) -> io::Result<()> {
        let shared = Arc::new(Shared {
            config: self.config,
            addr: self.addr,
            connections: Arc::new(AtomicUsize::new(0)),
            sessions: Arc::new(AtomicUsize::new(0)),
            refusals: Arc::new(AtomicUsize::new(0)),
            heads: Mutex::new(Heads::default()),
        });
        for stream in self.listener.incoming() {
            let stream = match stream {
                Ok(s) => s,
                // Per-connection failures (a peer that reset, too many open files for a
                // moment) must not stop the server.
                Err(_) => {
                    std::thread::sleep(Duration::from_millis(10));
                    continue;
                }
            };
            let max = shared.config.connections;
            let slot = Slot::take(&shared.connections, max).or_else(|| {
                // Full: the connection that has been sending its head the longest makes
                // room (its slot is given back as its thread ends, so at most `max` more
                // are ever in flight).
                shared
                    .evict_oldest_head()
                    .then(|| Slot::take(&shared.connections, 2 * max))
                    .flatten()
            });
            match slot {
                Some(slot) => {
                    let shared = Arc::clone(&shared);
                    std::thread::spawn(move || {
                        let _slot = slot;
                        let _ = handle(stream, &shared);
                    });
                }
                None => refuse(stream, &shared),
            }
        }
        Ok(())
    }
}

fn exposure_warning(addr: SocketAddr) -> Option<String> {
    (!addr.ip().is_loopback()).then(|| {
        format!(
            "warning: listening on {addr}, which other hosts can reach: anyone who can connect \
             can open pages and use this machine's CPU and memory (trusted networks only)"
        )
    })
}

/// What every connection's thread shares.
struct Shared {
    config: Config,
    addr: SocketAddr,
    connections: Arc<AtomicUsize>,
    sessions: Arc<AtomicUsize>,
    refusals: Arc<AtomicUsize>,
    heads: Mutex<Heads>,
}

/// The connections still sending their request head, oldest first.
#[derive(Default)]
struct Heads {
    next: u64,
    waiting: Vec<(u64, TcpStream)>,
}

impl Shared {
    fn heads(&self) -> std::sync::MutexGuard<'_, Heads> {
        self.heads.lock().unwrap_or_else(PoisonError::into_inner)
    }

    /// Closes the connection that has waited longest for its head; false if none waits.
    fn evict_oldest_head(&self) -> bool {
        let mut heads = self.heads();
        if heads.waiting.is_empty() {
            return false;
        }
        let (_, stream) = heads.waiting.remove(0);
        drop(heads);
        let _ = stream.shutdown(std::net::Shutdown::Both);
        true
    }
}

/// A connection listed in [`Heads`] until dropped.
struct Waiting<'a> {
    shared: &'a Shared,
    id: u64,
}

impl<'a> Waiting<'a> {
    fn new(shared: &'a Shared, stream: &TcpStream) -> io::Result<Waiting<'a>> {
        let clone = stream.try_clone()?;
        let mut heads = shared.heads();
        let id = heads.next;
        heads.next += 1;
        heads.waiting.push((id, clone));
        Ok(Waiting { shared, id })
    }
}

impl Drop for Waiting<'_> {
    fn drop(&mut self) {
        let mut heads = self.shared.heads();
        if let Some(k) = heads.waiting.iter().position(|(id, _)| *id == self.id) {
            heads.waiting.remove(k);
        }
    }
}

/// Answers 503 to a connection beyond the limit, on a thread of its own (at most as many
/// at once as connections; beyond that the connection is closed unanswered).
fn refuse(stream: TcpStream, shared: &Shared) {
    let Some(slot) = Slot::take(&shared.refusals, shared.config.connections) else {
        return;
    };
    std::thread::spawn(move || {
        let _slot = slot;
        let mut stream = Timed::new(stream);
        stream.write_by = Some(Instant::now() + Duration::from_secs(1));
        if http::respond_error(&mut stream, 503, "the server is busy; try again in a moment").is_ok() {
            let _ = linger_close(stream.stream);
        }
    });
}

/// A counted place in a bounded pool, given back on drop.
struct Slot(Arc<AtomicUsize>);

impl Slot {
    fn take(counter: &Arc<AtomicUsize>, max: usize) -> Option<Slot> {
        counter
            .fetch_update(Ordering::AcqRel, Ordering::Acquire, |n| {
                (n < max).then_some(n + 1)
            })
            .ok()
            .map(|_| Slot(Arc::clone(counter)))
    }
}

impl Drop for Slot {
    fn drop(&mut self) {
        self.0.fetch_sub(1, Ordering::AcqRel);
    }
}

/// A socket whose reads and writes end by deadlines: each call waits at most until its
/// deadline (`None`: reads wait for ever, writes up to [`WRITE_DEADLINE`] per call) and
/// fails with `TimedOut` once it has passed, so a peer sending or reading a byte at a
/// time cannot stretch it.
struct Timed {
    stream: TcpStream,
    read_by: Option<Instant>,
    write_by: Option<Instant>,
}

impl Timed {
    fn new(stream: TcpStream) -> Timed {
        Timed {
            stream,
            read_by: None,
            write_by: None,
        }
    }
}

/// The time left until `deadline`, or a `TimedOut` error once it has passed.
fn left(deadline: Instant) -> io::Result<Duration> {
    let left = deadline.saturating_duration_since(Instant::now());
    if left.is_zero() {
        Err(io::Error::new(io::ErrorKind::TimedOut, "deadline passed"))
    } else {
        Ok(left)
    }
}

/// A read or write timeout as `TimedOut` (Unix reports `WouldBlock`).
fn timed_out(e: io::Error) -> io::Error {
    if e.kind() == io::ErrorKind::WouldBlock {
        io::Error::new(io::ErrorKind::TimedOut, e)
    } else {
        e
    }
}

impl Read for Timed {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        let timeout = self.read_by.map(left).transpose()?;
        self.stream.set_read_timeout(timeout)?;
        self.stream.read(buf).map_err(timed_out)
    }
}

impl Write for Timed {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        let timeout = match self.write_by {
            Some(t) => left(t)?,
            None => WRITE_DEADLINE,
        };
        self.stream.set_write_timeout(Some(timeout))?;
        self.stream.write(buf).map_err(timed_out)
    }

    fn flush(&mut self) -> io::Result<()> {
        self.stream.flush()
    }
}

fn handle(stream: TcpStream, shared: &Shared) -> io::Result<()> {
    stream.set_nodelay(true)?;
    let mut stream = Timed::new(stream);
    let start = Instant::now();
    stream.read_by = Some(start + shared.config.head_deadline);
    stream.write_by = Some(start + shared.config.head_deadline + WRITE_DEADLINE);
    let waiting = Waiting::new(shared, &stream.stream)?;
    let head = http::read_request(&mut stream);
    drop(waiting);
    let (request, rest) = match head {
        Ok(r) => r,
        Err(http::HeadError::Io(e)) if e.kind() == io::ErrorKind::TimedOut => {
            let secs = shared.config.head_deadline.as_secs_f64();
            http::respond_error(
                &mut stream,
                408,
                &format!("the request head did not arrive within {secs} s"),
            )?;
            return linger_close(stream.stream);
        }
        Err(http::HeadError::Io(e)) => return Err(e),
        Err(http::HeadError::Bad(status, m)) => {
            http::respond_error(&mut stream, status, &m)?;
            return linger_close(stream.stream);
        }
    };
    stream.read_by = None;
    if let Err((status, m)) = check_host(&request, shared.addr) {
        http::respond_error(&mut stream, status, &m)?;
        return linger_close(stream.stream);
    }
    let head_only = request.method == "HEAD";
    if request.method != "GET" && !head_only {
        http::respond_error(&mut stream, 405, "only GET and HEAD are served")?;
        return linger_close(stream.stream);
    }
    match request.path.as_str() {
        "/" | "/index.html" => http::respond(
            &mut stream,
            200,
            "text/html; charset=utf-8",
            INDEX_HTML.as_bytes(),
            head_only,
        ),
        "/live.js" => http::respond(
            &mut stream,
            200,
            "text/javascript; charset=utf-8",
            LIVE_JS.as_bytes(),
            head_only,
        ),
        "/ws" => websocket(stream, &request, rest, shared),
        _ => http::respond_error(&mut stream, 404, "not found"),
    }
}

/// The `Host` check against DNS rebinding: the request must name this server by an
/// address it answers on (module docs).
fn check_host(request: &http::Request, bound: SocketAddr) -> Result<(), (u16, String)> {
    let Some(host) = request.header("host") else {
        return Err((400, "a Host header is required".into()));
    };
    if http::host_names_server(host, bound) {
        Ok(())
    } else {
        Err((
            421,
            format!(
                "Host {host:?} does not name this server; open http://{bound}/ (only this \
                 address{} is served, against DNS rebinding)",
                if bound.ip().is_loopback() {
                    ", localhost and the loopback addresses"
                } else {
                    ""
                }
            ),
        ))
    }
}

/// Closes after an error answer without resetting the connection: a peer still sending
/// (a request head that was too large, a body) would otherwise get a reset before it
/// reads the answer. Reads and drops at most 1 MiB for at most a second.
fn linger_close(stream: TcpStream) -> io::Result<()> {
    stream.shutdown(std::net::Shutdown::Write)?;
    let mut stream = Timed {
        stream,
        read_by: Some(Instant::now() + Duration::from_secs(1)),
        write_by: None,
    };
    let mut sink = [0u8; 8192];
    let mut left = 1usize << 20;
    while left > 0 {
        match stream.read(&mut sink) {
            Ok(0) | Err(_) => break,
            Ok(n) => left = left.saturating_sub(n),
        }
    }
    Ok(())
}

/// Completes the WebSocket handshake (RFC 6455 section 4.2) and runs a session.
fn websocket(mut stream: Timed, request: &http::Request, rest: Vec<u8>, shared: &Shared) -> io::Result<()> {
    let key = match request.header("sec-websocket-key") {
        Some(k)
            if request.header_has("upgrade", "websocket") && request.header_has("connection", "upgrade") =>
        {
            k
        }
        _ => return http::respond_error(&mut stream, 426, "this address takes a WebSocket upgrade"),
    };
    if request.header("sec-websocket-version") != Some("13") {
        return http::respond_error(&mut stream, 400, "only WebSocket version 13 is supported");
    }
    // Browsers always send Origin: only pages served from this same host may connect
    // (the Host itself was checked).
    if let Some(origin) = request.header("origin") {
        let host = request.header("host").unwrap_or("");
        if origin
            .strip_prefix("http://")
            .is_none_or(|o| !o.eq_ignore_ascii_case(host))
        {
            return http::respond_error(&mut stream, 403, "cross-origin WebSocket refused");
        }
    }
    let Some(_session_slot) = Slot::take(&shared.sessions, shared.config.sessions) else {
        return http::respond_error(&mut stream, 503, "too many pages open; close one and reload");
    };
    let accept = tungstenite::handshake::derive_accept_key(key.as_bytes());
    stream.write_all(
        format!(
            "HTTP/1.1 101 Switching Protocols\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n\
             Sec-WebSocket-Accept: {accept}\r\n\r\n"
        )
        .as_bytes(),
    )?;
    let idle = shared.config.idle_timeout;
    stream.read_by = Some(Instant::now() + idle);
    stream.write_by = None;
    let config = WebSocketConfig::default()
        .max_message_size(Some(protocol::MAX_TRANSPORT_BYTES))
        .max_frame_size(Some(protocol::MAX_TRANSPORT_BYTES));
    let mut ws = WebSocket::from_partially_read(stream, rest, Role::Server, Some(config));
    let mut session = Session::new();
    send_all(&mut ws, session.start())?;
    loop {
        let replies = match ws.read() {
            Ok(Message::Text(t)) => session.handle(t.as_bytes()),
            Ok(Message::Binary(_)) => vec![protocol::error_reply("binary messages are not accepted".into())],
            Ok(Message::Close(_)) | Err(WsError::ConnectionClosed | WsError::AlreadyClosed) => return Ok(()),
            // Pings and pongs are answered by the transport and do not count as activity.
            Ok(_) => continue,
            Err(WsError::Capacity(e)) => return close(&mut ws, CloseCode::Size, &e.to_string()),
            Err(WsError::Utf8(_)) => {
                // RFC 6455 section 8.1: a text message that is not UTF-8 fails the
                // connection (status 1007); the page learns why first.
                send_all(
                    &mut ws,
                    vec![protocol::error_reply(
                        "invalid message: a text message must be UTF-8".into(),
                    )],
                )?;
                return close(&mut ws, CloseCode::Invalid, "a text message must be UTF-8");
            }
            Err(WsError::Io(e)) if e.kind() == io::ErrorKind::TimedOut => {
                let secs = idle.as_secs_f64();
                return close(&mut ws, CloseCode::Away, &format!("no message for {secs} s"));
            }
            Err(WsError::Io(e)) => return Err(e),
            Err(e) => return Err(io::Error::other(e)),
        };
        ws.get_mut().read_by = Some(Instant::now() + idle);
        send_all(&mut ws, replies)?;
    }
}

/// Sends a close frame with `code` and `reason` and waits a moment for the reply.
fn close(ws: &mut WebSocket<Timed>, code: CloseCode, reason: &str) -> io::Result<()> {
    let soon = Instant::now() + Duration::from_secs(1);
    ws.get_mut().read_by = Some(soon);
    ws.get_mut().write_by = Some(soon);
    let _ = ws.close(Some(CloseFrame {
        code,
        reason: reason.to_string().into(),
    }));
    let _ = ws.flush();
    // Read until the peer's close frame (or the second is up), so that the close frame
    // is not lost to a reset.
    while ws.read().is_ok() {}
    Ok(())
}

fn send_all(ws: &mut WebSocket<Timed>, replies: Vec<Reply>) -> io::Result<()> {
    ws.get_mut().write_by = Some(Instant::now() + WRITE_DEADLINE);
    for r in replies {
        let m = match r {
            Reply::Text(t) => Message::text(t),
            Reply::Binary(b) => Message::binary(b),
        };
        ws.write(m).map_err(io::Error::other)?;
    }
    let flushed = ws.flush().map_err(io::Error::other);
    ws.get_mut().write_by = None;
    flushed
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_loopback_addresses_serve_without_a_warning() {
        for quiet in ["127.0.0.1:8080", "[::1]:8080", "127.1.2.3:1"] {
            assert_eq!(exposure_warning(quiet.parse().unwrap()), None, "{quiet}");
        }
        for loud in [
            "0.0.0.0:8080",
            "[::]:8080",
            "192.168.1.5:9000",
            "[2001:db8::1]:80",
        ] {
            let w = exposure_warning(loud.parse().unwrap()).expect("a warning");
            assert!(w.contains("other hosts can reach") && w.contains(loud), "{w}");
        }
    }
}
