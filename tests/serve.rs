//! `polysect serve` from outside: the contract (URL line, page at `/`, assets from any
//! directory, exit 0 on SIGINT/SIGTERM, a port in use named in the error) and the
//! WebSocket protocol over a real socket. The browser test is tests/live_page.rs.
#![cfg(unix)]

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
    let (status, page) = get(&s.addr, "GET / HTTP/1.1\r\nHost: x\r\n\r\n");
    assert_eq!(status, 200);
    assert!(page.contains("<canvas id=\"view\">") && page.contains("/live.js"));
    let (status, js) = get(&s.addr, "GET /live.js HTTP/1.1\r\nHost: x\r\n\r\n");
    assert_eq!(status, 200);
    assert!(js.contains("text/javascript") && js.contains("new WebSocket"));
    let (status, head) = get(&s.addr, "HEAD / HTTP/1.1\r\nHost: x\r\n\r\n");
    assert_eq!(status, 200);
    assert!(!head.contains("<canvas"), "HEAD has no body");
    assert_eq!(get(&s.addr, "GET /secret HTTP/1.1\r\nHost: x\r\n\r\n").0, 404);
    assert_eq!(
        get(&s.addr, "POST / HTTP/1.1\r\nHost: x\r\nContent-Length: 0\r\n\r\n").0,
        405
    );
    assert_eq!(get(&s.addr, "GET /ws HTTP/1.1\r\nHost: x\r\n\r\n").0, 426);
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
