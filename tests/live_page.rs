//! The live page in a real browser: headless Chromium driven through WebDriver
//! (chromedriver), spoken over plain HTTP here. Ignored by default (it needs the Debian
//! packages `chromium` and `chromium-driver`); CI runs
//! `cargo test --release --test live_page -- --ignored live_page_in_a_browser`.
//!
//! `CHROMIUM` and `CHROMEDRIVER` override the browser and driver paths.
#![cfg(unix)]

use polysect::intersect::{ArrayIntersection, Linear};
use polysect::{ConvexPolygon, Exact, Kernel, Orientation, Point};
use serde_json::{Value, json};
use std::io::{BufRead, BufReader, Read, Write};
use std::net::{TcpListener, TcpStream};
use std::path::PathBuf;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

// ---------------------------------------------------------------- processes

/// A child process killed (and reaped) when dropped, unless already stopped.
struct Proc(Child);

impl Drop for Proc {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

fn start_polysect() -> (Proc, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_polysect"))
        .args(["serve", "--port", "0"])
        .current_dir(std::env::temp_dir())
        .stdout(Stdio::piped())
        .spawn()
        .expect("polysect starts");
    let mut line = String::new();
    BufReader::new(child.stdout.take().expect("stdout"))
        .read_line(&mut line)
        .expect("the URL line");
    (Proc(child), line.trim().to_string())
}

fn free_port() -> u16 {
    TcpListener::bind("127.0.0.1:0")
        .expect("a free port")
        .local_addr()
        .expect("addr")
        .port()
}

fn target_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target")
}

// ---------------------------------------------------------------- WebDriver over HTTP

/// Sends one HTTP/1.1 request (Connection: close) and returns the status and body.
fn http(addr: &str, method: &str, path: &str, body: Option<&Value>) -> (u16, Vec<u8>) {
    let body = body.map(|b| b.to_string()).unwrap_or_default();
    let mut s = TcpStream::connect(addr).expect("the driver listens");
    s.set_read_timeout(Some(Duration::from_secs(120)))
        .expect("timeout");
    write!(
        s,
        "{method} {path} HTTP/1.1\r\nHost: {addr}\r\nContent-Type: application/json\r\n\
         Content-Length: {}\r\nConnection: close\r\n\r\n{body}",
        body.len()
    )
    .expect("sends");
    // The driver may keep the connection open: read the head, then exactly the body.
    let mut raw = Vec::new();
    let mut chunk = [0u8; 65536];
    let mut read_more = |raw: &mut Vec<u8>| -> bool {
        let n = s.read(&mut chunk).expect("reads the answer");
        raw.extend_from_slice(&chunk[..n]);
        n > 0
    };
    let split = loop {
        if let Some(p) = raw.windows(4).position(|w| w == b"\r\n\r\n") {
            break p;
        }
        assert!(read_more(&mut raw), "the driver closed before answering");
    };
    let head = String::from_utf8_lossy(&raw[..split]).to_ascii_lowercase();
    let status = head
        .split(' ')
        .nth(1)
        .and_then(|c| c.parse().ok())
        .expect("a status");
    let header = |name: &str| {
        head.lines()
            .find_map(|l| l.strip_prefix(name).map(|v| v.trim().to_string()))
    };
    let body_at = split + 4;
    if let Some(len) = header("content-length:").and_then(|v| v.parse::<usize>().ok()) {
        while raw.len() < body_at + len {
            assert!(read_more(&mut raw), "the driver closed mid-body");
        }
        return (status, raw[body_at..body_at + len].to_vec());
    }
    if header("transfer-encoding:").is_some_and(|v| v.contains("chunked")) {
        while !raw[body_at..].windows(5).any(|w| w == b"0\r\n\r\n") {
            assert!(read_more(&mut raw), "the driver closed mid-body");
        }
        return (status, dechunk(&raw[body_at..]));
    }
    while read_more(&mut raw) {}
    (status, raw[body_at..].to_vec())
}

fn dechunk(mut data: &[u8]) -> Vec<u8> {
    let mut out = Vec::new();
    loop {
        let eol = data
            .windows(2)
            .position(|w| w == b"\r\n")
            .expect("chunk size line");
        let size = usize::from_str_radix(String::from_utf8_lossy(&data[..eol]).trim(), 16).expect("hex size");
        if size == 0 {
            return out;
        }
        out.extend_from_slice(&data[eol + 2..eol + 2 + size]);
        data = &data[eol + 4 + size..];
    }
}

struct Browser {
    addr: String,
    session: String,
    profile: PathBuf,
    _driver: Proc,
}

impl Browser {
    fn start() -> Browser {
        let chromium = std::env::var("CHROMIUM").unwrap_or_else(|_| "/usr/bin/chromium".into());
        let chromedriver = std::env::var("CHROMEDRIVER").unwrap_or_else(|_| "chromedriver".into());
        let port = free_port();
        let driver = Proc(
            Command::new(&chromedriver)
                .arg(format!("--port={port}"))
                .stdout(Stdio::null())
                .stderr(Stdio::null())
                .spawn()
                .unwrap_or_else(|e| panic!("cannot start {chromedriver}: {e} (install chromium-driver)")),
        );
        let addr = format!("127.0.0.1:{port}");
        let start = Instant::now();
        while TcpStream::connect(&addr).is_err() {
            assert!(
                start.elapsed() < Duration::from_secs(20),
                "chromedriver did not listen"
            );
            std::thread::sleep(Duration::from_millis(50));
        }
        let profile = target_dir().join(format!("live_page_profile_{port}"));
        // Chromium on a closed network: no background connections, no sandbox as root.
        let caps = json!({"capabilities": {"alwaysMatch": {
            "browserName": "chrome",
            "goog:chromeOptions": {
                "binary": chromium,
                "args": ["--headless", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                         "--disable-quic", "--no-first-run", "--disable-background-networking",
                         "--disable-component-update", "--disable-sync", "--hide-scrollbars",
                         "--window-size=1280,800", "--force-device-scale-factor=1",
                         format!("--user-data-dir={}", profile.display())]
            }
        }}});
        let (status, body) = http(&addr, "POST", "/session", Some(&caps));
        let v: Value = serde_json::from_slice(&body).expect("JSON");
        assert_eq!(status, 200, "new session: {v}");
        let session = v["value"]["sessionId"]
            .as_str()
            .expect("a session id")
            .to_string();
        Browser {
            addr,
            session,
            profile,
            _driver: driver,
        }
    }

    fn cmd(&self, method: &str, path: &str, body: Option<Value>) -> Value {
        let path = format!("/session/{}{path}", self.session);
        let (status, payload) = http(&self.addr, method, &path, body.as_ref());
        let v: Value = serde_json::from_slice(&payload).expect("JSON");
        assert_eq!(status, 200, "{method} {path}: {v}");
        v["value"].clone()
    }

    fn goto(&self, url: &str) {
        self.cmd("POST", "/url", Some(json!({ "url": url })));
    }

    fn js(&self, script: &str) -> Value {
        self.cmd(
            "POST",
            "/execute/sync",
            Some(json!({"script": script, "args": []})),
        )
    }

    fn element(&self, css: &str) -> String {
        let v = self.cmd(
            "POST",
            "/element",
            Some(json!({"using": "css selector", "value": css})),
        );
        v["element-6066-11e4-a52e-4f735466cecf"]
            .as_str()
            .expect("an element")
            .to_string()
    }

    fn click(&self, css: &str) {
        let e = self.element(css);
        self.cmd("POST", &format!("/element/{e}/click"), Some(json!({})));
    }

    fn type_into(&self, css: &str, text: &str) {
        let e = self.element(css);
        self.cmd("POST", &format!("/element/{e}/clear"), Some(json!({})));
        self.cmd(
            "POST",
            &format!("/element/{e}/value"),
            Some(json!({ "text": text })),
        );
    }

    /// A real mouse drag from `from` to `to` (viewport CSS pixels).
    fn drag(&self, from: [f64; 2], to: [f64; 2], millis: u64) {
        let at = |p: [f64; 2]| (p[0].round() as i64, p[1].round() as i64);
        let ((x0, y0), (x1, y1)) = (at(from), at(to));
        self.cmd(
            "POST",
            "/actions",
            Some(json!({"actions": [{
                "type": "pointer", "id": "mouse", "parameters": {"pointerType": "mouse"},
                "actions": [
                    {"type": "pointerMove", "duration": 0, "x": x0, "y": y0, "origin": "viewport"},
                    {"type": "pointerDown", "button": 0},
                    {"type": "pause", "duration": 50},
                    {"type": "pointerMove", "duration": millis, "x": x1, "y": y1, "origin": "viewport"},
                    {"type": "pointerUp", "button": 0}
                ]
            }]})),
        );
    }

    fn screenshot(&self) -> Vec<u8> {
        let b64 = self.cmd("GET", "/screenshot", None);
        data_encoding::BASE64
            .decode(b64.as_str().expect("base64").as_bytes())
            .expect("valid base64")
    }

    /// Polls `script` (an expression) until it is true.
    fn wait_for(&self, what: &str, script: &str, secs: u64) {
        let start = Instant::now();
        while self.js(&format!("return !!({script});")) != json!(true) {
            assert!(
                start.elapsed() < Duration::from_secs(secs),
                "timed out waiting for {what}"
            );
            std::thread::sleep(Duration::from_millis(50));
        }
    }
}

impl Drop for Browser {
    fn drop(&mut self) {
        let _ = http(&self.addr, "DELETE", &format!("/session/{}", self.session), None);
        let _ = std::fs::remove_dir_all(&self.profile);
    }
}

// ---------------------------------------------------------------- what the page shows

struct Shown {
    frame: u64,
    pairs: Vec<[usize; 2]>,
    polygons: Vec<Vec<Point>>,
    ids: Vec<Vec<u32>>,
}

/// The direction of a polygon's edge from vertex 0 to vertex 1, in radians.
fn direction(p: &[Point]) -> f64 {
    (p[1].y - p[0].y).atan2(p[1].x - p[0].x)
}

/// The status box comes first in the sidebar (after the title, before the help and
/// every control) and is entirely in the viewport, however the sidebar is scrolled.
fn status_in_view(b: &Browser) {
    let v = b.js(
        "const e = document.getElementById('status'), s = e.getBoundingClientRect(); \
         return [s.top, s.bottom, window.innerHeight, e.previousElementSibling.tagName, e.nextElementSibling.id];",
    );
    let [top, bottom, height] = [0, 1, 2].map(|k| v[k].as_f64().expect("a number"));
    assert!(
        top >= 0.0 && bottom <= height,
        "the status box spans {top}..{bottom}, the viewport ends at {height}"
    );
    assert_eq!(
        (&v[3], &v[4]),
        (&json!("H1"), &json!("help")),
        "the status box is not at the top"
    );
}

/// What the page shows, once the drawn pairs account for every edit it received.
fn t_step(b: &Browser) -> u64 {
    b.js("return window.polysect.trace.step;").as_u64().expect("step")
}

fn shown(b: &Browser) -> Shown {
    b.wait_for("a consistent frame", "window.polysect.shown().consistent", 20);
    let v = b.js("return window.polysect.shown();");
    let pts = |p: &Value| -> Vec<Point> {
        p.as_array()
            .expect("points")
            .iter()
            .map(|xy| Point::new(xy[0].as_f64().expect("x"), xy[1].as_f64().expect("y")))
            .collect()
    };
    Shown {
        frame: v["frame"].as_u64().expect("frame"),
        pairs: serde_json::from_value(v["pairs"].clone()).expect("pairs"),
        polygons: v["polygons"]
            .as_array()
            .expect("polygons")
            .iter()
            .map(pts)
            .collect(),
        ids: serde_json::from_value(v["ids"].clone()).expect("ids"),
    }
}

/// The exact reference's intersecting pairs on the page's own coordinates.
fn reference_pairs(polygons: &[Vec<Point>]) -> Vec<[usize; 2]> {
    let convex: Vec<ConvexPolygon> = polygons
        .iter()
        .enumerate()
        .map(|(i, p)| ConvexPolygon::new(p.iter().copied()).unwrap_or_else(|e| panic!("polygon {i}: {e}")))
        .collect();
    let mut out = Vec::new();
    for i in 0..convex.len() {
        for j in i + 1..convex.len() {
            if Linear.intersects(&convex[i], &convex[j]) {
                out.push([i, j]);
            }
        }
    }
    out
}

fn assert_pairs_match_the_library(b: &Browser) -> Shown {
    let s = shown(b);
    assert_eq!(
        s.pairs,
        reference_pairs(&s.polygons),
        "frame {}: the page's colliding pairs differ from the exact reference",
        s.frame
    );
    s
}

fn centroid(p: &[Point]) -> Point {
    let n = p.len() as f64;
    let (x, y) = p.iter().fold((0.0, 0.0), |(x, y), v| (x + v.x, y + v.y));
    Point::new(x / n, y / n)
}

fn to_screen(b: &Browser, p: Point) -> [f64; 2] {
    let v = b.js(&format!("return window.polysect.toScreen({}, {});", p.x, p.y));
    [v[0].as_f64().expect("x"), v[1].as_f64().expect("y")]
}

// ---------------------------------------------------------------- pixels

struct Image {
    width: usize,
    height: usize,
    rgba: Vec<u8>,
}

fn decode_png(bytes: &[u8]) -> Image {
    let mut decoder = png::Decoder::new(std::io::Cursor::new(bytes));
    decoder.set_transformations(png::Transformations::EXPAND | png::Transformations::STRIP_16);
    let mut reader = decoder.read_info().expect("a PNG");
    let mut buf = vec![0; reader.output_buffer_size().expect("size")];
    let info = reader.next_frame(&mut buf).expect("a frame");
    let channels = info.color_type.samples();
    let rgba = buf[..info.buffer_size()]
        .chunks(channels)
        .flat_map(|c| match channels {
            4 => [c[0], c[1], c[2], c[3]],
            3 => [c[0], c[1], c[2], 255],
            _ => [c[0], c[0], c[0], 255],
        })
        .collect();
    Image {
        width: info.width as usize,
        height: info.height as usize,
        rgba,
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Paint {
    /// The plain polygon fill (blue).
    Plain,
    /// The colliding fill (red-orange).
    Hit,
    Other,
}

fn classify(img: &Image, x: usize, y: usize) -> Paint {
    let i = 4 * (y * img.width + x);
    let (r, g, b) = (img.rgba[i] as i32, img.rgba[i + 1] as i32, img.rgba[i + 2] as i32);
    if b > r + 40 && b > g + 10 {
        Paint::Plain
    } else if r > g + 50 && r > b + 50 {
        Paint::Hit
    } else {
        Paint::Other
    }
}

/// The paint that most pixels of the 5×5 block around `at` have.
fn paint_at(img: &Image, at: [f64; 2]) -> Paint {
    let (cx, cy) = (at[0].round() as i64, at[1].round() as i64);
    let mut counts = [0; 3];
    for dy in -2..=2 {
        for dx in -2..=2 {
            let (x, y) = (cx + dx, cy + dy);
            if x >= 0 && y >= 0 && (x as usize) < img.width && (y as usize) < img.height {
                counts[classify(img, x as usize, y as usize) as usize] += 1;
            }
        }
    }
    match counts.iter().enumerate().max_by_key(|(_, c)| **c).map(|(k, _)| k) {
        Some(0) => Paint::Plain,
        Some(1) => Paint::Hit,
        _ => Paint::Other,
    }
}

/// Starts the server and a browser on its page; returns once frames are drawn.
fn open_page() -> (Proc, String, Browser) {
    let (server, url) = start_polysect();
    let b = Browser::start();
    b.goto(&url);
    b.wait_for(
        "the first frames",
        "window.polysect.ready && window.polysect.frame > 3",
        30,
    );
    (server, url, b)
}

/// Pauses, then steps until at least `pairs` pairs collide (at most 400 steps).
fn pause_on_collisions(b: &Browser, pairs: u64) {
    b.click("#pause");
    b.wait_for(
        "pause",
        "window.polysect.settings.paused && window.polysect.idle",
        10,
    );
    for _ in 0..400 {
        if b.js("return window.polysect.shown().pairs.length;").as_u64() >= Some(pairs) {
            return;
        }
        b.click("#step");
        b.wait_for("the step", "window.polysect.idle", 10);
    }
}

/// Picks a strategy and a precision in the page's menus and waits until they are in
/// force. Frames already on their way then still carry the old counters: returns the
/// frame number after which frames carry the new ones.
fn choose(b: &Browser, strategy: &str, precision: &str) -> u64 {
    b.click(&format!("#strategy option[value={strategy}]"));
    b.click(&format!("#precision option[value={precision}]"));
    b.wait_for(
        "the settings",
        &format!(
            "window.polysect.settings.strategy === '{strategy}' && window.polysect.settings.precision === '{precision}'"
        ),
        20,
    );
    b.js("return window.polysect.frame;").as_u64().expect("frame") + 3
}

// ---------------------------------------------------------------- the test

#[test]
#[ignore = "needs chromium and chromium-driver (Debian packages); CI runs it"]
fn live_page_in_a_browser() {
    // 1. The simulation starts by itself and advances.
    let (mut server, _url, b) = open_page();
    let first = shown(&b);
    std::thread::sleep(Duration::from_millis(500));
    let later = shown(&b);
    assert!(
        later.frame > first.frame,
        "frames advance: {} then {}",
        first.frame,
        later.frame
    );
    assert_ne!(first.polygons, later.polygons, "polygons move");
    // They turn: edge 0's direction changes (a translation keeps it).
    let turned = first
        .polygons
        .iter()
        .zip(&later.polygons)
        .filter(|(a, b)| (direction(a) - direction(b)).abs() > 1e-4)
        .count();
    assert!(
        2 * turned >= first.polygons.len(),
        "only {turned} of {} polygons turned",
        first.polygons.len()
    );
    // The status box sits at the top of the sidebar, in view.
    status_in_view(&b);

    // 2. Collisions appear within the first seconds, and every colliding pair the page
    //    shows is the exact reference's answer for the page's own coordinates.
    b.wait_for("a collision", "window.polysect.shown().pairs.length > 0", 15);
    let mut frames = Vec::new();
    for _ in 0..6 {
        frames.push(assert_pairs_match_the_library(&b).frame);
        std::thread::sleep(Duration::from_millis(150));
    }
    assert!(
        frames.windows(2).all(|w| w[0] <= w[1]) && frames[0] < frames[5],
        "{frames:?}"
    );

    // 3. The store controls reach the store: `sampled` converts nothing and samples;
    //    `cached` converts. (A precision change starts the planner's counters again.)
    let since = choose(&b, "sampled", "fast");
    b.wait_for(
        "the sampled strategy at work",
        &format!("window.polysect.frame > {since} && window.polysect.figures.totals.sampled_tests > 20"),
        20,
    );
    assert_eq!(
        b.js("return window.polysect.figures.totals.conversions;"),
        json!(0)
    );
    let since = choose(&b, "cached", "exact");
    b.wait_for(
        "the cached strategy converting",
        &format!(
            "window.polysect.frame > {since} && window.polysect.figures.totals.conversions > 0 \
             && window.polysect.figures.totals.array_tests > 0 && window.polysect.figures.totals.sampled_tests === 0"
        ),
        20,
    );

    // 4. Pause while a pair collides; the picture shows it: a screenshot whose pixels at
    //    every polygon's centroid have the colliding fill exactly for the colliding ones.
    pause_on_collisions(&b, 1);
    let paused = assert_pairs_match_the_library(&b);
    assert!(!paused.pairs.is_empty(), "a colliding pair while paused");
    std::thread::sleep(Duration::from_millis(300));
    assert_eq!(shown(&b).frame, paused.frame, "paused means paused");
    // The polygons carry their numbers; hidden for the pixel check at their centroids.
    b.wait_for("the polygon numbers", "window.polysect.numbered > 0", 10);
    b.click("#showNumbers");
    b.wait_for("the numbers hidden", "window.polysect.numbered === 0", 10);
    std::thread::sleep(Duration::from_millis(100));
    let png = b.screenshot();
    let path = target_dir().join("live_page.png");
    std::fs::write(&path, &png).expect("screenshot saved");
    let img = decode_png(&png);
    let dpr = b.js("return window.devicePixelRatio;").as_f64().expect("dpr");
    let colliding: std::collections::BTreeSet<usize> = paused.pairs.iter().flatten().copied().collect();
    let (mut hit, mut plain) = (0, 0);
    for (i, poly) in paused.polygons.iter().enumerate() {
        let at = to_screen(&b, centroid(poly)).map(|c| c * dpr);
        let want = if colliding.contains(&i) {
            Paint::Hit
        } else {
            Paint::Plain
        };
        assert_eq!(
            paint_at(&img, at),
            want,
            "polygon {i} at {at:?} in {}",
            path.display()
        );
        if want == Paint::Hit {
            hit += 1;
        } else {
            plain += 1;
        }
    }
    assert!(
        hit >= 2 && plain >= 1,
        "{hit} colliding and {plain} plain polygons checked"
    );
    b.click("#showNumbers");

    // 5. Editing, on a scene of triangles (any triangle is convex, so the test knows from
    //    the orientation alone which drags the store must accept).
    b.type_into("#polygons", "6");
    b.type_into("#vertices", "3");
    b.click("#apply");
    b.wait_for(
        "the triangle scene",
        "window.polysect.ready && window.polysect.settings.vertices === 3 && window.polysect.shown().polygons.length === 6",
        20,
    );
    // A new scene keeps the user's pause, and the button says so.
    assert_eq!(
        (
            b.js("return window.polysect.settings.paused;"),
            b.js("return document.getElementById('pause').textContent;")
        ),
        (json!(true), json!("Resume"))
    );
    let before = assert_pairs_match_the_library(&b);
    // A disjoint pair (a, c); a's vertex whose opposite edge has c's centroid deepest
    // on its inner side moves onto c's centroid: the drag keeps a convex, so it is
    // accepted and the pair flips to colliding.
    let (a, c) = (0..6)
        .flat_map(|i| (0..6).map(move |j| (i, j)))
        .find(|&(i, j)| i != j && !before.pairs.contains(&[i.min(j), i.max(j)]))
        .expect("a disjoint pair");
    let target = centroid(&before.polygons[c]);
    let tri = &before.polygons[a];
    let (k, _) = (0..3)
        .map(|k| {
            let (p, n) = (tri[(k + 2) % 3], tri[(k + 1) % 3]);
            // Distance of the target from line p→n on the side where the vertex is.
            let len = (n.x - p.x).hypot(n.y - p.y);
            let side = ((n.x - p.x) * (target.y - p.y) - (n.y - p.y) * (target.x - p.x)) / len;
            (k, -side)
        })
        .max_by(|x, y| x.1.total_cmp(&y.1))
        .expect("three vertices");
    let (p, n) = (tri[(k + 2) % 3], tri[(k + 1) % 3]);
    assert_eq!(
        Exact.orient(p, n, target),
        Orientation::Cw,
        "the target keeps the triangle convex"
    );
    let vertex_id = before.ids[a][k];
    b.drag(to_screen(&b, tri[k]), to_screen(&b, target), 300);
    b.wait_for(
        "the drag's edit",
        &format!(
            "(() => {{ const s = window.polysect.shown(); return s.consistent && s.pairs.some(p => p[0] === {} && p[1] === {}); }})()",
            a.min(c),
            a.max(c)
        ),
        20,
    );
    let after = assert_pairs_match_the_library(&b);
    assert!(
        after.pairs.contains(&[a.min(c), a.max(c)]),
        "the drag flipped ({a}, {c}) to colliding"
    );
    let moved = after.polygons[a][after.ids[a]
        .iter()
        .position(|&v| v == vertex_id)
        .expect("vertex kept")];
    let scale = b
        .js("return window.polysect.toScreen(1, 0)[0] - window.polysect.toScreen(0, 0)[0];")
        .as_f64()
        .expect("scale");
    assert!(
        (moved.x - target.x).hypot(moved.y - target.y) * scale < 2.0,
        "the vertex follows the pointer: {moved:?} vs {target:?}"
    );

    // 6. A convexity-breaking drag is refused with the store's reason, and nothing moves:
    //    the vertex of another triangle dragged across its opposite edge.
    // Just across the opposite edge (0.3 of the triangle's height beyond it), inside the box.
    let world = b.js("return window.polysect.world;");
    let (w, h) = (world[0].as_f64().expect("w"), world[1].as_f64().expect("h"));
    let (d, k, across) = (0..6)
        .filter(|&i| i != a && i != c)
        .flat_map(|i| (0..3).map(move |k| (i, k)))
        .map(|(i, k)| {
            let t = &after.polygons[i];
            let (v, p, n) = (t[k], t[(k + 2) % 3], t[(k + 1) % 3]);
            let m = Point::new(0.5 * (p.x + n.x), 0.5 * (p.y + n.y));
            (i, k, Point::new(m.x + 0.3 * (m.x - v.x), m.y + 0.3 * (m.y - v.y)))
        })
        .find(|(_, _, t)| (10.0..w - 10.0).contains(&t.x) && (10.0..h - 10.0).contains(&t.y))
        .expect("a target inside the box");
    let tri = after.polygons[d].clone();
    let (v, p, n) = (tri[k], tri[(k + 2) % 3], tri[(k + 1) % 3]);
    assert_eq!(
        Exact.orient(p, n, across),
        Orientation::Ccw,
        "the target would flip the triangle"
    );
    let refusals = b.js("return window.polysect.refusals;").as_u64().expect("count");
    b.drag(to_screen(&b, v), to_screen(&b, across), 0);
    b.wait_for(
        "the refusal",
        &format!("window.polysect.refusals > {refusals}"),
        20,
    );
    let reason = b.js("return window.polysect.status;");
    let reason = reason.as_str().expect("text");
    assert!(
        reason.starts_with(&format!("Refused move on polygon {d}: placing a vertex at"))
            && reason.contains("would make the polygon non-convex"),
        "the page shows the store's reason: {reason:?}"
    );
    let now = assert_pairs_match_the_library(&b);
    assert_eq!(now.polygons[d], tri, "the refused drag moved nothing");
    status_in_view(&b);

    // 6b. Step-through: each algorithm's trace on a pair, stepped to its end with the
    // page's buttons; the last step's answer and the certificate are the library's.
    let pair = now.pairs.first().copied().unwrap_or([0, 1]);
    for algorithm in ["barba", "dobkin", "chazelle-dobkin", "clm"] {
        let traces = b.js("return window.polysect.traces;").as_u64().expect("count");
        b.type_into("#traceA", &pair[0].to_string());
        b.type_into("#traceB", &pair[1].to_string());
        b.js(&format!(
            "document.getElementById('traceAlgorithm').value = '{algorithm}'; return true;"
        ));
        b.click("#trace");
        b.wait_for("the trace", &format!("window.polysect.traces > {traces}"), 20);
        let t = b.js("return window.polysect.trace;");
        assert_eq!(t["algorithm"], json!(algorithm));
        if algorithm == "barba" {
            // Only the pair is drawn: no other polygon's fill shows at its centroid.
            std::thread::sleep(Duration::from_millis(200));
            let img = decode_png(&b.screenshot());
            let mut bare = 0;
            for (i, poly) in now.polygons.iter().enumerate().filter(|(i, _)| !pair.contains(i)) {
                let at = to_screen(&b, centroid(poly)).map(|c| c * dpr);
                let paint = paint_at(&img, at);
                assert!(
                    paint != Paint::Plain && paint != Paint::Hit,
                    "polygon {i} drawn during the trace of {pair:?}"
                );
                // Not even faintly: the trace's background itself (unless one of the
                // pair's zoomed lines happens to cross there).
                let (x, y) = (at[0].round() as usize, at[1].round() as usize);
                let k = 4 * (y * img.width + x);
                if img.rgba[k..k + 3]
                    .iter()
                    .zip([251, 252, 254])
                    .all(|(&c, w)| (c as i32 - w).abs() <= 2)
                {
                    bare += 1;
                }
            }
            assert!(bare >= 1, "the scene shows behind the trace of {pair:?}");
        }
        let steps = t["steps"].as_u64().expect("steps");
        for k in 1..steps {
            assert_eq!(t_step(&b), k - 1);
            b.click("#traceForward");
        }
        b.click("#traceBack");
        b.click("#traceForward");
        let t = b.js("return window.polysect.trace;");
        assert_eq!(
            t["step"].as_u64(),
            Some(steps - 1),
            "{algorithm}: stepped to the end"
        );
        let pts = |v: &Value| -> ConvexPolygon {
            ConvexPolygon::new(
                v.as_array()
                    .expect("points")
                    .iter()
                    .map(|xy| Point::new(xy[0].as_f64().expect("x"), xy[1].as_f64().expect("y"))),
            )
            .expect("a convex polygon")
        };
        let (p, q) = (pts(&t["p"]), pts(&t["q"]));
        let want = Linear.intersects(&p, &q);
        assert_eq!(
            t["stepAnswer"],
            json!(want),
            "{algorithm}: the last step's answer"
        );
        let certificate = polysect::certificate_json::certificate_from_json(&t["certificate"].to_string())
            .expect("a certificate");
        assert_eq!(
            polysect::intersect::verify(&p, &q, &certificate),
            Ok(()),
            "{algorithm}"
        );
        assert!(
            t["text"].as_str().expect("text").contains("certificate"),
            "{algorithm}"
        );
    }
    // The certificate wraps inside the sidebar: nothing overflows sideways, and the
    // step-through's inputs and buttons stay in view above it.
    let fits = b.js(
        "const side = document.getElementById('side'), t = document.getElementById('traceText'); \
         return side.scrollWidth <= side.clientWidth && t.scrollWidth <= t.clientWidth + 1;",
    );
    assert_eq!(fits, json!(true), "the certificate text overflows the sidebar");
    let clear = b.js(
        "const t = document.getElementById('traceText').getBoundingClientRect(), \
         s = document.getElementById('status').getBoundingClientRect(); \
         return ['traceA', 'traceB', 'traceAlgorithm', 'trace', 'traceBack', 'traceForward', 'traceClose'].every((id) => { \
           const r = document.getElementById(id).getBoundingClientRect(); \
           return r.bottom <= t.top + 0.5 && r.top >= s.bottom && r.bottom <= window.innerHeight; });",
    );
    assert_eq!(
        clear,
        json!(true),
        "the certificate text or the status box covers the step-through's inputs, or they are out of view"
    );
    let zoom = b.js("return window.polysect.traceZoom;").as_f64().expect("zoom");
    assert!(
        zoom > 1.0,
        "the trace is drawn zoomed on its two polygons: {zoom}"
    );
    // Closing a trace opened while paused (by the user) leaves the motion paused.
    b.click("#traceClose");
    std::thread::sleep(Duration::from_millis(300));
    assert_eq!(b.js("return window.polysect.settings.paused;"), json!(true));
    assert_eq!(
        b.js("return document.getElementById('pause').textContent;"),
        json!("Resume")
    );

    // 6c. A trace of a running simulation pauses it while shown and resumes it on Close;
    // a refused trace does not pause; a success clears an old error from the status.
    b.click("#pause");
    b.wait_for("running", "!window.polysect.settings.paused", 10);
    let (refusals, errors) = (
        b.js("return window.polysect.refusals;").as_u64().expect("count"),
        b.js("return window.polysect.errors;").as_u64().expect("count"),
    );
    b.type_into("#traceA", "0");
    b.type_into("#traceB", "0");
    b.click("#trace");
    b.wait_for(
        "the refused trace",
        &format!("window.polysect.refusals > {refusals} || window.polysect.errors > {errors}"),
        20,
    );
    std::thread::sleep(Duration::from_millis(300));
    assert_eq!(
        b.js("return window.polysect.settings.paused;"),
        json!(false),
        "a refused trace leaves the motion running"
    );
    assert!(
        b.js("return document.getElementById('status').className;") != json!("ok"),
        "the refusal is shown"
    );
    // An index out of range: refused the same way, the motion still running.
    let errors = b.js("return window.polysect.errors;").as_u64().expect("count");
    b.type_into("#traceB", "999");
    b.click("#trace");
    b.wait_for(
        "the out-of-range trace refused",
        &format!("window.polysect.errors > {errors}"),
        20,
    );
    let status = b.js("return window.polysect.status;");
    assert!(
        status.as_str().is_some_and(|t| t.contains("no polygon 999")),
        "{status}"
    );
    std::thread::sleep(Duration::from_millis(300));
    assert_eq!(
        (
            b.js("return window.polysect.settings.paused;"),
            b.js("return document.getElementById('pause').textContent;")
        ),
        (json!(false), json!("Pause")),
        "a refused trace leaves the motion running"
    );
    let traces = b.js("return window.polysect.traces;").as_u64().expect("count");
    b.type_into("#traceB", "1");
    b.click("#trace");
    b.wait_for("the trace", &format!("window.polysect.traces > {traces}"), 20);
    b.wait_for("paused for the trace", "window.polysect.settings.paused", 10);
    assert_eq!(
        b.js("return document.getElementById('status').className;"),
        json!("ok"),
        "the trace's success replaced the old refusal"
    );
    b.click("#traceClose");
    b.wait_for(
        "running again after Close",
        "!window.polysect.settings.paused",
        10,
    );
    assert_eq!(b.js("return window.polysect.trace;"), Value::Null);
    assert_eq!(
        b.js("return document.getElementById('pause').textContent;"),
        json!("Pause")
    );
    // A new scene chosen while a trace holds the motion starts moving.
    let traces = traces + 1;
    b.click("#trace");
    b.wait_for("the trace", &format!("window.polysect.traces > {traces}"), 20);
    b.wait_for("paused for the trace", "window.polysect.settings.paused", 10);
    let scene = b.js("return window.polysect.scene;").as_u64().expect("scene");
    b.type_into("#polygons", "8");
    b.click("#apply");
    b.wait_for(
        "the new scene, moving",
        &format!(
            "window.polysect.scene > {scene} && window.polysect.ready && !window.polysect.settings.paused"
        ),
        20,
    );
    assert_eq!(
        b.js("return document.getElementById('pause').textContent;"),
        json!("Pause")
    );
    // The help text is in view without scrolling (the window is 1280 × 800).
    let help =
        b.js("return document.getElementById('help').getBoundingClientRect().bottom <= window.innerHeight;");
    assert_eq!(help, json!(true), "the help text is below the fold");

    // 6d. An edit while the bodies spin (slowly, so that the vertex is still under the
    // pointer when the drag starts): a vertex pulled outwards is accepted.
    b.js("const s = document.getElementById('speed'); s.value = '0.1'; s.dispatchEvent(new Event('input')); return true;");
    b.wait_for("the slow speed", "window.polysect.settings.speed === 0.1", 10);
    let spin = shown(&b);
    let (edits, refusals, errors) = (
        b.js("return window.polysect.edits;").as_u64().expect("count"),
        b.js("return window.polysect.refusals;").as_u64().expect("count"),
        b.js("return window.polysect.errors;").as_u64().expect("count"),
    );
    let tri = &spin.polygons[0];
    let c = centroid(tri);
    let (v, len) = (tri[0], (tri[0].x - c.x).hypot(tri[0].y - c.y));
    let out = Point::new(v.x + 15.0 * (v.x - c.x) / len, v.y + 15.0 * (v.y - c.y) / len);
    b.drag(to_screen(&b, v), to_screen(&b, out), 200);
    b.wait_for(
        "the edit while spinning",
        &format!("window.polysect.edits > {edits}"),
        20,
    );
    assert_eq!(
        (
            b.js("return window.polysect.refusals;").as_u64(),
            b.js("return window.polysect.errors;").as_u64()
        ),
        (Some(refusals), Some(errors)),
        "the drag while spinning was refused: {}",
        b.js("return window.polysect.status;")
    );
    std::thread::sleep(Duration::from_millis(300));
    let spun = shown(&b);
    assert!(spun.frame > spin.frame, "still running");
    assert!(
        (1..spin.polygons.len())
            .any(|i| (direction(&spin.polygons[i]) - direction(&spun.polygons[i])).abs() > 1e-6),
        "still turning"
    );

    // 7. SIGTERM stops the server with status 0.
    drop(b);
    let pid = server.0.id().to_string();
    assert!(
        Command::new("kill")
            .args(["-TERM", &pid])
            .status()
            .expect("kill")
            .success()
    );
    let start = Instant::now();
    let status = loop {
        if let Some(s) = server.0.try_wait().expect("wait") {
            break s;
        }
        assert!(
            start.elapsed() < Duration::from_secs(5),
            "still running after SIGTERM"
        );
        std::thread::sleep(Duration::from_millis(20));
    };
    assert_eq!(status.code(), Some(0));
}

/// Measures the page's frame rate on the two sizes the design names (200 polygons of 64
/// vertices; 20 of 65,536), following the display (the default) and unthrottled, and
/// checks that the page's own fps counter agrees with the frames the test counts over
/// the same wall-clock window. Prints the figures for docs/results.md.
#[test]
#[ignore = "a measurement: needs chromium and chromium-driver; run by hand"]
fn live_page_fps() {
    let (_server, url) = start_polysect();
    let b = Browser::start();
    let secs: f64 = std::env::var("LIVE_FPS_SECONDS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(5.0);
    println!(
        "| scene | mode | fps (page) | fps (counted) | update | broad | narrow | response | draw (ms) |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    for (polygons, vertices) in [(200, 64), (20, 65_536)] {
        for mode in ["display", "unthrottled"] {
            let extra = if mode == "unthrottled" { "&unthrottled" } else { "" };
            b.goto(&format!("{url}?polygons={polygons}&vertices={vertices}{extra}"));
            b.wait_for(
                "the scene",
                &format!(
                    "window.polysect.ready && window.polysect.settings.polygons === {polygons} && \
                     window.polysect.settings.vertices === {vertices} && window.polysect.frame > 10"
                ),
                120,
            );
            std::thread::sleep(Duration::from_secs(2));
            let read = |b: &Browser| {
                b.js("return [window.polysect.frame, performance.now(), window.polysect.fps, window.polysect.drawMs, window.polysect.figures.timing];")
            };
            let (mut fps, mut timing) = (Vec::new(), Vec::new());
            let t0 = read(&b);
            let start = Instant::now();
            while start.elapsed().as_secs_f64() < secs {
                std::thread::sleep(Duration::from_millis(500));
                let v = read(&b);
                fps.push(v[2].as_f64().expect("fps"));
                timing.push(v.clone());
            }
            let t1 = read(&b);
            let frames = t1[0].as_f64().expect("frame") - t0[0].as_f64().expect("frame");
            let counted = 1000.0 * frames / (t1[1].as_f64().expect("t") - t0[1].as_f64().expect("t"));
            let page = fps.iter().sum::<f64>() / fps.len() as f64;
            let mean = |key: &str| {
                timing
                    .iter()
                    .map(|v| v[4][key].as_f64().unwrap_or(0.0))
                    .sum::<f64>()
                    / timing.len() as f64
            };
            let draw = timing.iter().map(|v| v[3].as_f64().unwrap_or(0.0)).sum::<f64>() / timing.len() as f64;
            println!(
                "| {polygons} × {vertices} | {mode} | {page:.1} | {counted:.1} | {:.2} | {:.2} | {:.2} | {:.2} | {draw:.2} |",
                mean("update_ms"),
                mean("broad_ms"),
                mean("narrow_ms"),
                mean("response_ms"),
            );
            assert!(counted > 0.0, "the simulation advanced");
            assert!(
                (page - counted).abs() <= 0.25 * counted + 1.0,
                "the page's counter ({page:.1}) tracks the frames counted ({counted:.1})"
            );
        }
    }
}

/// Takes the pictures of docs/live.md (docs/img/live_simulation.png,
/// docs/img/live_editing.png and docs/img/live_trace.png): the default scene paused on
/// collisions, then a scene in editing: a dragged vertex, an inserted one, a refused
/// drag and its reason, the pointer over a vertex; then a step of a trace.
#[test]
#[ignore = "writes docs/img; needs chromium and chromium-driver; run by hand"]
fn live_page_screenshots() {
    let out = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("docs/img");
    let (_server, _url, b) = open_page();
    b.wait_for("collisions", "window.polysect.shown().pairs.length >= 2", 30);
    pause_on_collisions(&b, 2);
    std::thread::sleep(Duration::from_millis(400));
    std::fs::write(out.join("live_simulation.png"), b.screenshot()).expect("written");

    b.type_into("#polygons", "12");
    b.type_into("#vertices", "10");
    b.type_into("#seed", "4");
    b.click("#apply");
    b.wait_for(
        "the editing scene",
        "window.polysect.ready && window.polysect.settings.vertices === 10 && window.polysect.shown().polygons.length === 12",
        20,
    );
    let s = shown(&b);
    let edits = |b: &Browser| b.js("return window.polysect.shown().ids.flat().length;");
    // Pull a vertex of polygon 0 outwards by a fifth of its distance from the centroid.
    let (p0, c0) = (&s.polygons[0], centroid(&s.polygons[0]));
    let v = p0[0];
    let to = Point::new(v.x + 0.2 * (v.x - c0.x), v.y + 0.2 * (v.y - c0.y));
    b.drag(to_screen(&b, v), to_screen(&b, to), 200);
    // Insert a vertex just outside the middle of an edge of polygon 1 (3 px out).
    let p1 = &s.polygons[1];
    let (a, z) = (p1[2], p1[3]);
    let m = to_screen(&b, Point::new(0.5 * (a.x + z.x), 0.5 * (a.y + z.y)));
    let c1 = to_screen(&b, centroid(p1));
    let (ox, oy) = (m[0] - c1[0], m[1] - c1[1]);
    let len = ox.hypot(oy);
    let before = edits(&b);
    let click = [m[0] + 3.0 * ox / len, m[1] + 3.0 * oy / len];
    b.drag(click, click, 0);
    b.wait_for(
        "the insertion",
        &format!("window.polysect.shown().ids.flat().length > {before}"),
        10,
    );
    // A vertex of polygon 2 dragged into its own interior: refused.
    let p2 = &s.polygons[2];
    b.drag(to_screen(&b, p2[0]), to_screen(&b, centroid(p2)), 0);
    b.wait_for("the refusal", "window.polysect.refusals > 0", 10);
    // Hover over the moved vertex of polygon 0.
    let moved = shown(&b).polygons[0][0];
    let at = to_screen(&b, moved).map(|c| c.round() as i64);
    b.cmd(
        "POST",
        "/actions",
        Some(json!({"actions": [{"type": "pointer", "id": "mouse", "parameters": {"pointerType": "mouse"},
            "actions": [{"type": "pointerMove", "duration": 0, "x": at[0], "y": at[1], "origin": "viewport"}]}]})),
    );
    std::thread::sleep(Duration::from_millis(400));
    std::fs::write(out.join("live_editing.png"), b.screenshot()).expect("written");

    // The step-through: Barba–Langerman on the two closest untouched polygons, a
    // middle step.
    let c: Vec<Point> = s.polygons.iter().map(|p| centroid(p)).collect();
    let n = c.len();
    let (i, j) = (3..n)
        .flat_map(|i| (i + 1..n).map(move |j| (i, j)))
        .min_by(|&(a, b), &(x, y)| {
            let d = |u: usize, v: usize| (c[u].x - c[v].x).hypot(c[u].y - c[v].y);
            d(a, b).total_cmp(&d(x, y))
        })
        .expect("a pair");
    b.type_into("#traceA", &i.to_string());
    b.type_into("#traceB", &j.to_string());
    b.click("#trace");
    b.wait_for("the trace", "window.polysect.traces > 0", 20);
    let steps = b
        .js("return window.polysect.trace.steps;")
        .as_u64()
        .expect("steps");
    for _ in 0..steps / 2 {
        b.click("#traceForward");
    }
    std::thread::sleep(Duration::from_millis(400));
    std::fs::write(out.join("live_trace.png"), b.screenshot()).expect("written");
}

/// Without a browser: the served page has the controls and text the browser test uses
/// (the polygon numbers' switch, the help at the top, the wrapping certificate box) and
/// its script pauses for a trace only on the answer and resumes on Close.
#[test]
fn the_served_page_has_the_help_the_numbers_and_the_trace_controls() {
    let (_server, url) = start_polysect();
    let addr = url
        .trim_start_matches("http://")
        .trim_end_matches('/')
        .to_string();
    let fetch = |path: &str| -> String {
        let mut s = TcpStream::connect(&addr).expect("connects");
        write!(
            s,
            "GET {path} HTTP/1.1\r\nHost: {addr}\r\nConnection: close\r\n\r\n"
        )
        .expect("sends");
        let mut out = String::new();
        s.read_to_string(&mut out).expect("reads");
        out
    };
    let page = fetch("/");
    let (help, side) = (
        page.find("id=\"help\"").expect("the help text"),
        page.find("<fieldset>").expect("the controls"),
    );
    assert!(help < side, "the help text comes before the controls");
    let status = page.find("id=\"status\"").expect("the status box");
    assert!(status < help, "the status box is at the top of the sidebar");
    assert!(
        page.contains("id=\"showNumbers\""),
        "the polygon numbers can be switched"
    );
    assert!(
        page.contains("#traceText { overflow-wrap: anywhere;"),
        "the certificate text wraps"
    );
    let js = fetch("/live.js");
    for needle in [
        "function drawNumbers()",
        "function traceView(t)",
        "resumeAfterTrace",
        "clearStaleError(",
        "get numbered()",
        "get traceZoom()",
    ] {
        assert!(js.contains(needle), "live.js lacks {needle}");
    }
}
