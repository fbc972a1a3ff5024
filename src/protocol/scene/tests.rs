use super::*;

fn pts(v: &[[f64; 2]]) -> Vec<Point> {
    v.iter().map(|&p| p.into()).collect()
}

fn ids_of(input: &[[f64; 2]]) -> Vec<u64> {
    let input = pts(input);
    let poly = ConvexPolygon::new(input.iter().copied()).unwrap();
    survivor_ids(&input, poly.vertices()).unwrap()
}

#[test]
fn survivors_keep_their_input_positions() {
    // Counter-clockwise, plain.
    assert_eq!(ids_of(&[[0., 0.], [1., 0.], [0., 1.]]), [0, 1, 2]);
    // Clockwise: cleaned counter-clockwise from input 0, so ids run 0, 2, 1.
    assert_eq!(ids_of(&[[0., 0.], [0., 1.], [1., 0.]]), [0, 2, 1]);
    // Repeats: the first of each run; the closing repeat of the first point is dropped.
    assert_eq!(
        ids_of(&[
            [0., 0.],
            [0., 0.],
            [1., 0.],
            [1., 0.],
            [0., 1.],
            [0., 0.],
            [0., 0.]
        ]),
        [0, 2, 4]
    );
    // Collinear middles get no id; a collinear first point moves the start.
    assert_eq!(
        ids_of(&[[1., 0.], [2., 0.], [2., 2.], [0., 2.], [0., 1.], [0., 0.]]),
        [1, 2, 3, 5]
    );
    // Clockwise with a collinear first point and a closing repeat of it.
    assert_eq!(
        ids_of(&[[1., 0.], [0., 0.], [0., 2.], [2., 2.], [2., 0.], [1., 0.]]),
        [1, 4, 3, 2]
    );
}

/// The reply `pairs` gave before it streamed: every pair at once from the scene's
/// sweep, mapped to names, sorted.
fn pairs_reply_held(session: &mut SceneSession) -> String {
    let mut pairs: Vec<(String, String)> = session
        .scene
        .intersecting_pairs()
        .into_iter()
        .map(|(a, b)| {
            let (a, b) = (session.names[&a].clone(), session.names[&b].clone());
            if a <= b { (a, b) } else { (b, a) }
        })
        .collect();
    pairs.sort_unstable();
    let body: Vec<String> = pairs
        .iter()
        .map(|(a, b)| format!("[{},{}]", json_string(a), json_string(b)))
        .collect();
    format!("{{\"pairs\": [{}]}}", body.join(","))
}

#[test]
fn streamed_pairs_equal_the_held_reply_byte_for_byte() {
    use rand::rngs::SmallRng;
    use rand::{Rng, SeedableRng};
    let mut rng = SmallRng::seed_from_u64(0x5ca1e);
    for round in 0..20 {
        let mut session = SceneSession::new(SceneOptions {
            seed: Some(round),
            ..SceneOptions::default()
        });
        let count = rng.random_range(0..40);
        for i in 0..count {
            // Names whose string order differs from insertion order, some escaped.
            let name = match i % 3 {
                0 => format!("p{}", count - i),
                1 => format!("\\\"{i}"),
                _ => format!("é{i}"),
            };
            let (cx, cy) = (rng.random_range(-4.0..4.0), rng.random_range(-4.0..4.0));
            let r: f64 = rng.random_range(0.1..3.0);
            let line = format!(
                r#"{{"op":"add","name":{},"points":[[{},{}],[{},{}],[{},{}],[{},{}]]}}"#,
                json_string(&name),
                cx - r,
                cy,
                cx,
                cy - r,
                cx + r,
                cy,
                cx,
                cy + r
            );
            assert_eq!(session.answer_line(line.as_bytes()), r#"{"ok": true}"#);
            if i % 5 == 4 {
                let by = format!(
                    r#"{{"op":"translate","name":{},"by":[1.5,-0.5]}}"#,
                    json_string(&name)
                );
                session.answer_line(by.as_bytes());
            }
        }
        let want = pairs_reply_held(&mut session);
        assert_eq!(session.answer_line(br#"{"op":"pairs"}"#), want, "round {round}");
        let with_id = session.answer_line(br#"{"id":[7],"op":"pairs"}"#);
        assert_eq!(with_id, want.replacen('{', r#"{"id": [7], "#, 1));
    }
}

/// A writer that records what it had received at each flush.
#[derive(Default)]
struct FlushRecorder {
    got: Vec<u8>,
    at_flush: Vec<String>,
}

impl Write for FlushRecorder {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        self.got.extend_from_slice(buf);
        Ok(buf.len())
    }
    fn flush(&mut self) -> io::Result<()> {
        self.at_flush.push(String::from_utf8(self.got.clone()).unwrap());
        Ok(())
    }
}

#[test]
fn replies_before_a_pairs_line_are_flushed_before_it_is_computed() {
    // All three lines arrive in one read, so no read flushes between them: only the
    // `pairs` line's own flush can deliver the first two replies before it is answered.
    let input = br#"{"op":"add","name":"a","points":[[0,0],[1,0],[0,1]]}
{"op":"add","name":"b","points":[[0,0],[1,0],[0,1]]}
{"op":"pairs"}
"#;
    let mut out = FlushRecorder::default();
    let mut session = SceneSession::new(SceneOptions::default());
    session.run(&input[..], &mut out).unwrap();
    let two = "{\"ok\": true}\n{\"ok\": true}\n";
    assert_eq!(
        out.at_flush.first().map(String::as_str),
        Some(two),
        "{:?}",
        out.at_flush
    );
    assert_eq!(
        String::from_utf8(out.got).unwrap(),
        format!("{two}{{\"pairs\": [[\"a\",\"b\"]]}}\n")
    );
}

/// A reader that fails after its first block.
struct BreaksAfter<'a>(Option<&'a [u8]>);

impl Read for BreaksAfter<'_> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        match self.0.take() {
            Some(b) => {
                buf[..b.len()].copy_from_slice(b);
                Ok(b.len())
            }
            None => Err(io::Error::other("connection reset")),
        }
    }
}

#[test]
fn replies_are_flushed_when_the_input_fails() {
    let input = br#"{"op":"add","name":"a","points":[[0,0],[1,0],[0,1]]}
{"op":"add","name":"a","points":[[0,0],[1,0],[0,1]]}
"#;
    let mut out = FlushRecorder::default();
    let mut session = SceneSession::new(SceneOptions::default());
    assert!(session.run(BreaksAfter(Some(&input[..])), &mut out).is_err());
    let last = out.at_flush.last().cloned().unwrap_or_default();
    assert_eq!(last.lines().count(), 2, "{last}");
}
