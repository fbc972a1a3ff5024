//! `polysect serve` from outside: the contract (URL line, page at `/`, assets from any
//! directory, exit 0 on SIGINT/SIGTERM, a port in use named in the error) and the
//! WebSocket protocol over a real socket. The browser test is tests/live_page.rs.
#![cfg(unix)]

use polysect::serve::{Config, Server};
use std::io::{BufRead, BufReader, Read, Write};
use std::net::{TcpListener, TcpStream};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};
use tungstenite::Message;

/// A running `polysect serve`, killed if the test fails before stopping it.
struct Served {
    child: Child,
    addr: String,
}

impl Served {
    fn start(args: &[&str]) -> Served {
        let dir = std::env::temp_dir();
        let mut child = Command::new(env!("CARGO_BIN_EXE_polysect"))
            .arg("serve")
            .args(args)
            .current_dir(&dir) // the assets are in the binary, not next to it
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("polysect starts");
        let mut line = String::new();
        BufReader::new(child.stdout.take().expect("stdout"))
            .read_line(&mut line)
            .expect("the URL line");
        let addr = line
            .trim()
            .strip_prefix("http://")
            .and_then(|s| s.strip_suffix('/'))
            .unwrap_or_else(|| panic!("not a URL line: {line:?}"))
            .to_string();
        Served { child, addr }
    }

    fn signal(&mut self, sig: &str) -> i32 {
        let ok = Command::new("kill")
            .args([&format!("-{sig}"), &self.child.id().to_string()])
            .status()
            .expect("kill runs");
        assert!(ok.success());
        let start = Instant::now();
        loop {
            if let Some(status) = self.child.try_wait().expect("wait") {
                return status.code().unwrap_or(-1);
            }
            assert!(
                start.elapsed() < Duration::from_secs(5),
                "still running 5 s after SIG{sig}"
            );
            std::thread::sleep(Duration::from_millis(20));
        }
    }
}

impl Drop for Served {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn get(addr: &str, raw: &str) -> (u16, String) {
    let mut s = TcpStream::connect(addr).expect("connects");
    s.write_all(raw.as_bytes()).expect("sends");
    let mut out = Vec::new();
    s.read_to_end(&mut out).expect("reads");
    let text = String::from_utf8_lossy(&out).to_string();
    let status = text
        .split(' ')
        .nth(1)
        .and_then(|c| c.parse().ok())
        .unwrap_or_else(|| panic!("no status in {text:?}"));
    (status, text)
}

#[test]
fn prints_the_url_serves_the_page_and_stops_on_sigterm_with_status_0() {
    let mut s = Served::start(&["--port", "0"]);
    assert!(
        s.addr.starts_with("127.0.0.1:"),
        "loopback by default: {}",
        s.addr
    );
    let (status, page) = get(&s.addr, &format!("GET / HTTP/1.1\r\nHost: {}\r\n\r\n", s.addr));
    assert_eq!(status, 200);
    assert!(page.contains("<canvas id=\"view\">") && page.contains("/live.js"));
    let (status, js) = get(
        &s.addr,
        &format!("GET /live.js HTTP/1.1\r\nHost: {}\r\n\r\n", s.addr),
    );
    assert_eq!(status, 200);
    assert!(js.contains("text/javascript") && js.contains("new WebSocket"));
    let (status, head) = get(&s.addr, &format!("HEAD / HTTP/1.1\r\nHost: {}\r\n\r\n", s.addr));
    assert_eq!(status, 200);
    assert!(!head.contains("<canvas"), "HEAD has no body");
    assert_eq!(
        get(
            &s.addr,
            &format!("GET /secret HTTP/1.1\r\nHost: {}\r\n\r\n", s.addr)
        )
        .0,
        404
    );
    assert_eq!(
        get(
            &s.addr,
            &format!("POST / HTTP/1.1\r\nHost: {}\r\nContent-Length: 0\r\n\r\n", s.addr)
        )
        .0,
        405
    );
    assert_eq!(
        get(&s.addr, &format!("GET /ws HTTP/1.1\r\nHost: {}\r\n\r\n", s.addr)).0,
        426
    );
    assert_eq!(get(&s.addr, "\x16\x03\x01 garbage\r\n\r\n").0, 400);
    let huge = format!("GET / HTTP/1.1\r\nX: {}\r\n\r\n", "a".repeat(20_000));
    assert_eq!(get(&s.addr, &huge).0, 431);
    assert_eq!(s.signal("TERM"), 0);
}

#[test]
fn stops_on_sigint_with_status_0_even_with_a_page_open() {
    let mut s = Served::start(&["--port", "0", "--bind", "127.0.0.1"]);
    let stream = TcpStream::connect(&s.addr).expect("connects");
    let (_ws, _) = tungstenite::client::client(format!("ws://{}/ws", s.addr), stream).expect("handshake");
    assert_eq!(s.signal("INT"), 0);
}

#[test]
fn a_port_in_use_is_an_error_naming_the_port() {
    let taken = TcpListener::bind("127.0.0.1:0").expect("a free port");
    let port = taken.local_addr().expect("addr").port().to_string();
    let out = Command::new(env!("CARGO_BIN_EXE_polysect"))
        .args(["serve", "--port", &port])
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains(&format!("port {port} is already in use")), "{err}");
    assert!(out.stdout.is_empty(), "no URL when not listening");
    let out = Command::new(env!("CARGO_BIN_EXE_polysect"))
        .args(["serve", "--bind", "not-an-address"])
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(2), "a usage error");
}

#[test]
fn websocket_sessions_answer_and_refuse_as_the_protocol_says() {
    let s = Served::start(&["--port", "0"]);
    let stream = TcpStream::connect(&s.addr).expect("connects");
    let (mut ws, _) = tungstenite::client::client(format!("ws://{}/ws", s.addr), stream).expect("handshake");
    let read_text = |ws: &mut tungstenite::WebSocket<TcpStream>| -> serde_json::Value {
        match ws.read().expect("a message") {
            Message::Text(t) => serde_json::from_str(&t).expect("JSON"),
            other => panic!("expected text, got {other:?}"),
        }
    };
    assert_eq!(read_text(&mut ws)["type"], "settings");
    let scene = read_text(&mut ws);
    assert_eq!(scene["type"], "scene");
    let n: u64 = scene["sizes"]
        .as_array()
        .expect("sizes")
        .iter()
        .map(|v| v.as_u64().expect("n"))
        .sum();
    match ws.read().expect("the vertices") {
        Message::Binary(b) => assert_eq!(b.len() as u64, 16 * n),
        other => panic!("expected binary, got {other:?}"),
    }
    ws.send(Message::text("{\"op\":\"frame\"}")).expect("sends");
    let f = read_text(&mut ws);
    assert_eq!(f["type"], "frame");
    assert_eq!(f["frame"], 1);
    // A small scene's frame is followed by its world points, as many as the shapes'.
    assert_eq!(f["world"], true);
    match ws.read().expect("the world points") {
        Message::Binary(b) => assert_eq!(b.len() as u64, 16 * n),
        other => panic!("expected binary, got {other:?}"),
    }
    ws.send(Message::text("{\"op\":\"teleport\"}")).expect("sends");
    assert!(
        read_text(&mut ws)["message"]
            .as_str()
            .expect("error")
            .contains("unknown variant")
    );
    ws.send(Message::binary(vec![1u8, 2, 3])).expect("sends");
    assert!(
        read_text(&mut ws)["message"]
            .as_str()
            .expect("error")
            .contains("binary")
    );
    ws.send(Message::text(format!(
        "{{\"op\":\"frame\",\"x\":\"{}\"}}",
        "y".repeat(100_000)
    )))
    .expect("sends");
    assert!(
        read_text(&mut ws)["message"]
            .as_str()
            .expect("error")
            .contains("exceeds the limit")
    );
    // The session goes on after every error.
    ws.send(Message::text("{\"op\":\"frame\"}")).expect("sends");
    assert_eq!(read_text(&mut ws)["frame"], 2);
    assert!(matches!(ws.read().expect("the world points"), Message::Binary(_)));
    // Above the transport limit the connection is closed (status 1009).
    // Only the frame header is sent: the server refuses on the declared
    // length, and a client still writing a 2 MiB payload into a socket the
    // server has already closed would race with the close frame.
    let mut header = vec![0x82u8, 0x80 | 127];
    header.extend_from_slice(&(2u64 << 20).to_be_bytes());
    header.extend_from_slice(&[1, 2, 3, 4]);
    ws.get_mut().write_all(&header).expect("sends the header");
    let closed = loop {
        match ws.read() {
            Ok(Message::Close(f)) => break f.map(|f| u16::from(f.code)),
            Ok(_) => continue,
            Err(_) => break None,
        }
    };
    assert_eq!(closed, Some(1009));
}

#[test]
fn cross_origin_websockets_are_refused() {
    let s = Served::start(&["--port", "0"]);
    let raw = format!(
        "GET /ws HTTP/1.1\r\nHost: {}\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n\
         Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\
         Origin: http://elsewhere.example\r\n\r\n",
        s.addr
    );
    assert_eq!(get(&s.addr, &raw).0, 403);
    let same = raw.replace("http://elsewhere.example", &format!("http://{}", s.addr));
    let mut stream = TcpStream::connect(&s.addr).expect("connects");
    stream.write_all(same.as_bytes()).expect("sends");
    let mut head = [0u8; 12];
    stream.read_exact(&mut head).expect("reads");
    assert_eq!(&head, b"HTTP/1.1 101");
}

// ---------------------------------------------------------------- limits under hostile use

/// A server of this process with `config` on 127.0.0.1 (any free port), serving on a
/// thread of its own until the test process ends; its `ADDR:PORT`.
fn library_server(config: Config) -> String {
    let server = Server::bind("127.0.0.1".parse().expect("an address"), 0)
        .expect("binds")
        .with_config(config);
    let addr = server.local_addr().to_string();
    std::thread::spawn(move || server.run());
    addr
}

/// How a slow client's connection ended.
#[derive(Debug, PartialEq)]
enum Cut {
    /// The server answered (the status) and closed.
    Answered(u16),
    /// The server closed without an answer.
    Closed,
    /// Still open after `LONG`.
    StillOpen,
}

/// Far longer than any deadline the tests set: only a server that never cuts reaches it.
const LONG: Duration = Duration::from_secs(20);

/// Sends a request head one byte every 100 ms, never finishing it, until the server
/// answers or closes (or `LONG` passes).
fn dribble(addr: &str) -> Cut {
    let mut s = TcpStream::connect(addr).expect("connects");
    s.set_read_timeout(Some(Duration::from_millis(100)))
        .expect("timeout");
    let head = format!("GET / HTTP/1.1\r\nHost: {addr}\r\nX-Slow: ");
    let mut bytes = head.bytes().chain(std::iter::repeat(b'a'));
    let start = Instant::now();
    let mut answer = Vec::new();
    while start.elapsed() < LONG {
        if answer.is_empty() && s.write_all(&[bytes.next().expect("endless")]).is_err() {
            return Cut::Closed;
        }
        let mut buf = [0u8; 512];
        match s.read(&mut buf) {
            Ok(0) | Err(_) if !answer.is_empty() => break,
            Ok(0) => return Cut::Closed,
            Ok(n) => answer.extend_from_slice(&buf[..n]),
            Err(e)
                if matches!(
                    e.kind(),
                    std::io::ErrorKind::WouldBlock | std::io::ErrorKind::TimedOut
                ) => {}
            Err(_) => return Cut::Closed,
        }
    }
    if answer.is_empty() {
        return Cut::StillOpen;
    }
    let text = String::from_utf8_lossy(&answer);
    Cut::Answered(
        text.split(' ')
            .nth(1)
            .and_then(|c| c.parse().ok())
            .unwrap_or_else(|| panic!("no status in {text:?}")),
    )
}

#[test]
fn slow_heads_are_cut_at_the_deadline_and_a_normal_client_is_served_meanwhile() {
    let addr = library_server(Config {
        connections: 4,
        head_deadline: Duration::from_secs(1),
        ..Config::default()
    });
    let slow: Vec<_> = (0..4)
        .map(|_| {
            let addr = addr.clone();
            std::thread::spawn(move || dribble(&addr))
        })
        .collect();
    // Every connection is taken by a slow head.
    std::thread::sleep(Duration::from_millis(400));
    let (status, page) = get(&addr, &format!("GET / HTTP/1.1\r\nHost: {addr}\r\n\r\n"));
    assert_eq!(status, 200, "{page}");
    let cuts: Vec<Cut> = slow
        .into_iter()
        .map(|h| h.join().expect("the slow client ends"))
        .collect();
    assert!(!cuts.contains(&Cut::StillOpen), "{cuts:?}");
    // At most one made room for the normal client; the others met the deadline.
    let timed_out = cuts.iter().filter(|c| **c == Cut::Answered(408)).count();
    assert!(timed_out >= 3, "{cuts:?}");
    // And after the attack the server serves as before.
    assert_eq!(
        get(&addr, &format!("GET /live.js HTTP/1.1\r\nHost: {addr}\r\n\r\n")).0,
        200
    );
}

fn open_page(addr: &str) -> tungstenite::WebSocket<TcpStream> {
    let stream = TcpStream::connect(addr).expect("connects");
    stream.set_read_timeout(Some(LONG)).expect("timeout");
    let (mut ws, _) = tungstenite::client::client(format!("ws://{addr}/ws"), stream).expect("handshake");
    for _ in 0..3 {
        ws.read().expect("settings, scene, vertices");
    }
    ws
}

#[test]
fn a_full_server_answers_503() {
    let addr = library_server(Config {
        connections: 2,
        sessions: 2,
        ..Config::default()
    });
    let pages = [open_page(&addr), open_page(&addr)];
    let (status, text) = get(&addr, &format!("GET / HTTP/1.1\r\nHost: {addr}\r\n\r\n"));
    assert_eq!(status, 503, "{text}");
    drop(pages);
    // The pages' connections are given back as their threads end.
    let start = Instant::now();
    loop {
        let (status, _) = get(&addr, &format!("GET / HTTP/1.1\r\nHost: {addr}\r\n\r\n"));
        if status == 200 {
            break;
        }
        assert!(start.elapsed() < LONG, "still {status} after the pages closed");
        std::thread::sleep(Duration::from_millis(50));
    }
}

#[test]
fn requests_naming_another_host_are_refused() {
    let s = Served::start(&["--port", "0"]);
    let port = s.addr.rsplit(':').next().expect("a port");
    let rebound = format!("rebind.attacker.example:{port}");
    let (status, text) = get(&s.addr, &format!("GET / HTTP/1.1\r\nHost: {rebound}\r\n\r\n"));
    assert_eq!(status, 421, "{text}");
    assert!(text.contains("does not name this server"), "{text}");
    // The WebSocket handshake of a rebound page: its Origin matches its Host.
    let handshake = |host: &str| {
        format!(
            "GET /ws HTTP/1.1\r\nHost: {host}\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n\
             Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\
             Origin: http://{host}\r\n\r\n"
        )
    };
    assert_eq!(get(&s.addr, &handshake(&rebound)).0, 421);
    assert_eq!(get(&s.addr, "GET / HTTP/1.1\r\n\r\n").0, 400, "no Host");
    assert_eq!(
        get(
            &s.addr,
            &format!(
                "GET / HTTP/1.1\r\nHost: 127.0.0.1:{}\r\n\r\n",
                port.parse::<u16>().unwrap() ^ 1
            )
        )
        .0,
        421,
        "another port"
    );
    // The loopback names are this server.
    for host in [
        format!("localhost:{port}"),
        format!("[::1]:{port}"),
        s.addr.clone(),
    ] {
        let (status, text) = get(&s.addr, &format!("GET / HTTP/1.1\r\nHost: {host}\r\n\r\n"));
        assert_eq!(status, 200, "{host}: {text}");
    }
    let mut stream = TcpStream::connect(&s.addr).expect("connects");
    stream
        .write_all(handshake(&format!("localhost:{port}")).as_bytes())
        .expect("sends");
    let mut head = [0u8; 12];
    stream.read_exact(&mut head).expect("reads");
    assert_eq!(&head, b"HTTP/1.1 101");
}

#[test]
fn idle_pages_are_closed_and_active_ones_are_not() {
    let addr = library_server(Config {
        idle_timeout: Duration::from_secs(1),
        ..Config::default()
    });
    // Active: a frame every 200 ms for three idle timeouts.
    let mut active = open_page(&addr);
    for _ in 0..15 {
        active
            .send(Message::text("{\"op\":\"frame\"}"))
            .expect("still open");
        assert!(matches!(active.read().expect("a frame"), Message::Text(_)));
        assert!(matches!(
            active.read().expect("its world points"),
            Message::Binary(_)
        ));
        std::thread::sleep(Duration::from_millis(200));
    }
    // Idle: closed with status 1001 (going away).
    let mut idle = open_page(&addr);
    let closed = loop {
        match idle.read() {
            Ok(Message::Close(f)) => break f.map(|f| u16::from(f.code)),
            Ok(_) => continue,
            Err(e) => panic!("no close frame: {e}"),
        }
    };
    assert_eq!(closed, Some(1001));
}

#[test]
fn a_text_message_that_is_not_utf8_gets_an_error_and_a_close_frame() {
    let s = Served::start(&["--port", "0"]);
    let mut ws = open_page(&s.addr);
    // A masked text frame (as a client must send) whose payload is not UTF-8.
    let payload = b"\xff\xfe{\"op\":\"frame\"}";
    let mask = [0x12u8, 0x34, 0x56, 0x78];
    let mut frame = vec![0x81u8, 0x80 | payload.len() as u8];
    frame.extend_from_slice(&mask);
    frame.extend(payload.iter().enumerate().map(|(i, b)| b ^ mask[i % 4]));
    ws.get_mut().write_all(&frame).expect("sends");
    match ws.read().expect("an answer") {
        Message::Text(t) => {
            let v: serde_json::Value = serde_json::from_str(&t).expect("JSON");
            assert_eq!(v["type"], "error");
            assert!(v["message"].as_str().expect("a message").contains("UTF-8"), "{v}");
        }
        other => panic!("expected the error reply, got {other:?}"),
    }
    match ws.read() {
        Ok(Message::Close(f)) => assert_eq!(f.map(|f| u16::from(f.code)), Some(1007)),
        other => panic!("expected the close frame, got {other:?}"),
    }
}

#[test]
fn loopback_serves_without_a_warning() {
    let mut s = Served::start(&["--port", "0", "--bind", "127.0.0.1"]);
    assert_eq!(s.signal("TERM"), 0);
    let mut err = String::new();
    s.child
        .stderr
        .take()
        .expect("stderr")
        .read_to_string(&mut err)
        .expect("reads");
    assert!(err.is_empty(), "{err}");
}
