//! The live page: `polysect serve` runs a small web server whose page shows convex
//! polygons moving, colliding and being edited in a real [`Scene`](crate::store::Scene).
//!
//! # Architecture
//! The simulation runs **in this process**, in Rust, one [`Simulation`] per open page;
//! the page is plain HTML, JavaScript and a canvas (built into the binary with
//! `include_str!`), talking to it over one WebSocket. The page asks for a frame, the
//! server moves the polygons, asks the store for the intersecting pairs and answers with
//! what changed: one offset per polygon, the pairs, the figures; edits from the page go
//! through the store's validated O(1) edits and come back as the edited vertex. Whole
//! polygons cross the wire once per scene, as binary `f64` data. docs/live.md argues
//! the choice against compiling the library to WebAssembly.
//!
//! # Threads and bounds
//! One thread accepts connections; each connection gets a thread that reads one request
//! head (at most [`http::MAX_HEAD_BYTES`], 10 s to arrive) and either answers it (the
//! page, its script) or upgrades it to the WebSocket and runs a [`Session`] until the
//! page closes. At most [`MAX_CONNECTIONS`] connections are served at once and at most
//! [`MAX_SESSIONS`] of them are pages (a busy server answers 503). WebSocket messages
//! above [`protocol::MAX_TRANSPORT_BYTES`] close the connection; smaller ones above
//! [`protocol::MAX_MESSAGE_BYTES`] get an error reply. A WebSocket handshake whose
//! `Origin` is not this server is refused (403), so other web sites cannot drive it.
//!
//! # Precision
//! The store decides every pair with the precision chosen on the page; positions are
//! exact on both sides of the wire (see [`sim`]).

mod contact;
pub mod http;
pub mod protocol;
pub mod sim;
pub mod trace;

pub use contact::{separation_normal, witness_normal};
pub use protocol::{Reply, Session};
pub use sim::{Settings, Simulation};

use std::io;
use std::net::{IpAddr, SocketAddr, TcpListener, TcpStream};
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Duration;
use tungstenite::protocol::{CloseFrame, Role, WebSocket, WebSocketConfig, frame::coding::CloseCode};
use tungstenite::{Error as WsError, Message};

/// Connections served at once (page loads, scripts, WebSockets).
pub const MAX_CONNECTIONS: usize = 32;
/// Pages (WebSocket sessions) served at once.
pub const MAX_SESSIONS: usize = 8;

const INDEX_HTML: &str = include_str!("assets/index.html");
const LIVE_JS: &str = include_str!("assets/live.js");

/// A bound, listening server.
#[derive(Debug)]
pub struct Server {
    listener: TcpListener,
    addr: SocketAddr,
}

impl Server {
    /// Listens on `bind:port` (port 0: one the system chooses).
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
        Ok(Server { listener, addr })
    }

    /// The address it listens on (the port chosen when asked for port 0).
    pub fn local_addr(&self) -> SocketAddr {
        self.addr
    }

    /// The page's address, `http://ADDR:PORT/` (IPv6 addresses in brackets).
    pub fn url(&self) -> String {
        format!("http://{}/", self.addr)
    }

    /// Serves until the process ends. Returns only if accepting fails for good.
    ///
    /// # Errors
    /// The listening socket fails.
    pub fn run(self) -> io::Result<()> {
        let connections = Arc::new(AtomicUsize::new(0));
        let sessions = Arc::new(AtomicUsize::new(0));
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
            let Some(slot) = Slot::take(&connections, MAX_CONNECTIONS) else {
                drop(stream);
                continue;
            };
            let sessions = Arc::clone(&sessions);
            std::thread::spawn(move || {
                let _slot = slot;
                let _ = handle(stream, &sessions);
            });
        }
        Ok(())
    }
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

fn handle(mut stream: TcpStream, sessions: &Arc<AtomicUsize>) -> io::Result<()> {
    stream.set_read_timeout(Some(Duration::from_secs(10)))?;
    stream.set_write_timeout(Some(Duration::from_secs(30)))?;
    stream.set_nodelay(true)?;
    let (request, rest) = match http::read_request(&mut stream) {
        Ok(r) => r,
        Err(http::HeadError::Io(e)) => return Err(e),
        Err(http::HeadError::Bad(status, m)) => {
            http::respond_error(&mut stream, status, &m)?;
            return linger_close(stream);
        }
    };
    let head_only = request.method == "HEAD";
    if request.method != "GET" && !head_only {
        http::respond_error(&mut stream, 405, "only GET and HEAD are served")?;
        return linger_close(stream);
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
        "/ws" => websocket(stream, &request, rest, sessions),
        _ => http::respond_error(&mut stream, 404, "not found"),
    }
}

/// Closes after an error answer without resetting the connection: a peer still sending
/// (a request head that was too large, a body) would otherwise get a reset before it
/// reads the answer. Reads and drops at most 1 MiB for at most a second.
fn linger_close(mut stream: TcpStream) -> io::Result<()> {
    stream.shutdown(std::net::Shutdown::Write)?;
    stream.set_read_timeout(Some(Duration::from_secs(1)))?;
    let mut sink = [0u8; 8192];
    let mut left = 1usize << 20;
    while left > 0 {
        match io::Read::read(&mut stream, &mut sink) {
            Ok(0) | Err(_) => break,
            Ok(n) => left = left.saturating_sub(n),
        }
    }
    Ok(())
}

/// Completes the WebSocket handshake (RFC 6455 section 4.2) and runs a session.
fn websocket(
    mut stream: TcpStream,
    request: &http::Request,
    rest: Vec<u8>,
    sessions: &Arc<AtomicUsize>,
) -> io::Result<()> {
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
    // Browsers always send Origin: only pages served from this same host may connect.
    if let Some(origin) = request.header("origin") {
        let host = request.header("host").unwrap_or("");
        if origin.strip_prefix("http://").is_none_or(|o| o != host) {
            return http::respond_error(&mut stream, 403, "cross-origin WebSocket refused");
        }
    }
    let Some(_session_slot) = Slot::take(sessions, MAX_SESSIONS) else {
        return http::respond_error(&mut stream, 503, "too many pages open; close one and reload");
    };
    let accept = tungstenite::handshake::derive_accept_key(key.as_bytes());
    io::Write::write_all(
        &mut stream,
        format!(
            "HTTP/1.1 101 Switching Protocols\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n\
             Sec-WebSocket-Accept: {accept}\r\n\r\n"
        )
        .as_bytes(),
    )?;
    // A page may stay open and idle (paused) for a long time.
    stream.set_read_timeout(None)?;
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
            Ok(_) => continue,
            Err(WsError::Capacity(e)) => {
                let _ = ws.close(Some(CloseFrame {
                    code: CloseCode::Size,
                    reason: format!("{e}").into(),
                }));
                let _ = ws.flush();
                return Ok(());
            }
            Err(WsError::Io(e)) => return Err(e),
            Err(e) => return Err(io::Error::other(e)),
        };
        send_all(&mut ws, replies)?;
    }
}

fn send_all(ws: &mut WebSocket<TcpStream>, replies: Vec<Reply>) -> io::Result<()> {
    for r in replies {
        let m = match r {
            Reply::Text(t) => Message::text(t),
            Reply::Binary(b) => Message::binary(b),
        };
        ws.write(m).map_err(io::Error::other)?;
    }
    ws.flush().map_err(io::Error::other)
}
