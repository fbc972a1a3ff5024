//! Inputs shared by the modules that check algorithms against references.

use polysect::{ConvexPolygon, Point};

/// The hostile companions of a large polygon `p` for its `i`-th case, each with its
/// family and a description: a copy shrunken about the vertex average (containment,
/// started at vertex `i`), then triangles around a vertex, from an edge's midpoint
/// outwards, and just outside a vertex.
pub fn companions(p: &ConvexPolygon, i: usize) -> Vec<(ConvexPolygon, &'static str, String)> {
    let n = p.len();
    let mut out = Vec::new();
    let sum = p
        .vertices()
        .iter()
        .fold(Point::new(0., 0.), |s, v| Point::new(s.x + v.x, s.y + v.y));
    let c = Point::new(sum.x / n as f64, sum.y / n as f64);
    let f = [0.5, 0.9, 0.999][i % 3];
    if let Ok(inner) = p.map(|v| Point::new(c.x + f * (v.x - c.x), c.y + f * (v.y - c.y))) {
        out.push((inner.starting_at(i), "containment", format!("contained n={n}")));
    }
    let v = p.vertex(i * 7);
    let w = p.vertex(i * 7 + 1);
    let s = 0.01 * (1 + i % 5) as f64;
    let triangles = [
        [[v.x, v.y], [v.x + s, v.y], [v.x, v.y + s]],
        [
            [(v.x + w.x) / 2.0, (v.y + w.y) / 2.0],
            [v.x * 1.5, v.y * 1.5],
            [w.x * 1.5, w.y * 1.5],
        ],
        [
            [v.x * 1.01, v.y * 1.01],
            [v.x * 1.3, v.y * 1.01],
            [v.x * 1.01, v.y * 1.3],
        ],
    ];
    for t in triangles {
        if let Ok(t) = ConvexPolygon::new(t) {
            out.push((t, "triangle-vs-large", format!("triangle n={n} #{i}")));
        }
    }
    out
}
