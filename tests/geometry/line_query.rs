//! Line, ray and segment queries on convex polygons (O(log n)) against linear
//! references: the line chord against `line_chord_linear` (every vertex and edge
//! visited), rays and segments against a segment test on every edge plus a
//! containment test, on random polygons and lines and on adversarial ones (lines
//! through vertices, along edges, tangent; every start vertex; huge, tiny and offset
//! coordinates).
//!
//! `POLYSECT_LINE_ROUNDS` scales the random rounds (default 300).

use polysect::generate::{Family, Relation, pair};
use polysect::kernel::{point_on_segment, segments_intersect};
use polysect::polygon::{Chord, ChordEnd, LineQueryError, convex_hull, line_chord_linear};
use polysect::{ConvexPolygon, Exact, Kernel, Orientation, Point};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

const SEED: u64 = 0x0011_e5ec;

fn rounds() -> usize {
    std::env::var("POLYSECT_LINE_ROUNDS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(300)
}

/// The closed polygon contains `p` (linear).
fn contains(poly: &ConvexPolygon, p: Point) -> bool {
    let v = poly.vertices();
    (0..v.len()).all(|i| Exact.orient(v[i], v[(i + 1) % v.len()], p) != Orientation::Cw)
}

/// `q` is the point a line-chord end stands for.
fn at_end(poly: &ConvexPolygon, end: ChordEnd, q: Point) -> bool {
    let v = poly.vertices();
    match end {
        ChordEnd::Vertex(i) => v[i] == q,
        ChordEnd::Edge(i) => point_on_segment(Exact, v[i], v[(i + 1) % v.len()], q),
        ChordEnd::Query => unreachable!(),
    }
}

/// The segment `a b` meets the closed polygon (linear: an edge test on every edge, or
/// containment of `a`).
fn segment_meets(poly: &ConvexPolygon, a: Point, b: Point) -> bool {
    let v = poly.vertices();
    contains(poly, a) || (0..v.len()).any(|i| segments_intersect(Exact, a, b, v[i], v[(i + 1) % v.len()]))
}

/// Every query on one polygon and one directed line, against the references. `far` is
/// a point on the ray beyond the polygon (so the ray meets it iff the segment a–far does).
fn check(poly: &ConvexPolygon, a: Point, b: Point, far: Option<Point>, what: &str) {
    let line = poly.line_chord(a, b).unwrap();
    assert_eq!(
        line,
        line_chord_linear(poly, a, b).unwrap(),
        "{what}: line {a:?} → {b:?}"
    );
    let ray = poly.ray_chord(a, b).unwrap();
    let seg = poly.segment_chord(a, b).unwrap();
    // Clipping never invents a chord, and keeps the line's boundary ends where they stay.
    for (name, clip, end_inside) in [("ray", ray, None), ("segment", seg, Some(b))] {
        let Some(c) = clip else { continue };
        let l = line.unwrap_or_else(|| panic!("{what}: {name} hits but the line misses"));
        let want_from = if contains(poly, a) && !at_end(poly, l.from, a) {
            ChordEnd::Query
        } else {
            l.from
        };
        assert_eq!(c.from, want_from, "{what}: {name} from");
        let want_to = match end_inside {
            Some(q) if contains(poly, q) && !at_end(poly, l.to, q) => ChordEnd::Query,
            _ => l.to,
        };
        assert_eq!(c.to, want_to, "{what}: {name} to");
    }
    assert_eq!(
        seg.is_some(),
        segment_meets(poly, a, b),
        "{what}: segment {a:?} {b:?} hit"
    );
    if let Some(far) = far {
        assert_eq!(
            ray.is_some(),
            segment_meets(poly, a, far),
            "{what}: ray {a:?} → {b:?} hit"
        );
    }
    // The parameters are ordered (approximately computed; tiny slack).
    for c in [line, ray, seg].into_iter().flatten() {
        let (t0, t1) = c.parameters(poly, a, b);
        assert!(t0 <= t1 + 1e-9 * t1.abs().max(1.0), "{what}: {c:?} {t0} {t1}");
    }
}

/// A random polygon on a small integer grid (collinear runs, many exact touchings).
fn grid_polygon(rng: &mut SmallRng, span: i32) -> ConvexPolygon {
    loop {
        let n = rng.random_range(3..30);
        let pts: Vec<Point> = (0..n)
            .map(|_| {
                Point::new(
                    rng.random_range(-span..=span) as f64,
                    rng.random_range(-span..=span) as f64,
                )
            })
            .collect();
        if let Ok(h) = convex_hull(&pts) {
            let start = rng.random_range(0..h.len());
            return h.starting_at(start);
        }
    }
}

#[test]
fn grid_polygons_and_grid_lines() {
    // Integer coordinates: lines through vertices, along edges and tangent are common,
    // and the far point of each ray is exact.
    let mut rng = SmallRng::seed_from_u64(SEED);
    for round in 0..rounds() * 10 {
        let poly = grid_polygon(&mut rng, 6);
        let a = Point::new(rng.random_range(-9..=9) as f64, rng.random_range(-9..=9) as f64);
        let b = Point::new(rng.random_range(-9..=9) as f64, rng.random_range(-9..=9) as f64);
        if a == b {
            continue;
        }
        let far = Point::new(a.x + 100.0 * (b.x - a.x), a.y + 100.0 * (b.y - a.y));
        check(&poly, a, b, Some(far), &format!("round {round}"));
        // Lines through two vertices (along an edge when they are neighbours).
        let v = poly.vertices();
        let (i, j) = (rng.random_range(0..v.len()), rng.random_range(0..v.len()));
        if i != j {
            check(
                &poly,
                v[i],
                v[j],
                None,
                &format!("round {round} vertices {i} {j}"),
            );
            let far = Point::new(
                v[i].x + 100.0 * (v[j].x - v[i].x),
                v[i].y + 100.0 * (v[j].y - v[i].y),
            );
            check(
                &poly,
                v[i],
                v[j],
                Some(far),
                &format!("round {round} vertices {i} {j}"),
            );
        }
    }
}

#[test]
fn large_polygons_and_random_lines() {
    let mut rng = SmallRng::seed_from_u64(SEED + 1);
    for round in 0..rounds() {
        let n = 1 << rng.random_range(2..13);
        let family = [Family::Ellipse, Family::Rotated, Family::NonUniform][round % 3];
        let (p, _) = pair(family, n, Relation::Any, &mut rng);
        let polysect::BoundingBox { min: lo, max: hi } = p.bounding_box();
        let pick = |rng: &mut SmallRng| {
            Point::new(
                rng.random_range(lo.x - 1.0..hi.x + 1.0),
                rng.random_range(lo.y - 1.0..hi.y + 1.0),
            )
        };
        for _ in 0..20 {
            let (a, b) = (pick(&mut rng), pick(&mut rng));
            check(&p, a, b, None, &format!("round {round} n {n}"));
        }
        // Through a vertex and a point inside, and tangent-ish through two vertices.
        let v = p.vertices();
        let i = rng.random_range(0..v.len());
        check(
            &p,
            v[i],
            v[(i + 1) % v.len()],
            None,
            &format!("round {round} along edge {i}"),
        );
        check(
            &p,
            v[(i + 1) % v.len()],
            v[i],
            None,
            &format!("round {round} along edge {i} reversed"),
        );
        check(
            &p,
            v[i],
            v[(i + v.len() / 2) % v.len()],
            None,
            &format!("round {round} diagonal {i}"),
        );
    }
}

#[test]
fn extreme_coordinates() {
    let mut rng = SmallRng::seed_from_u64(SEED + 2);
    for (scale, offset) in [
        (1e300, 0.0),
        (1e-300, 0.0),
        (5e-324, 0.0),
        (1.0, 2f64.powi(52)),
        (1e-3, 1e6),
    ] {
        for round in 0..rounds() / 3 {
            let g = grid_polygon(&mut rng, 6);
            let map = |p: Point| Point::new(offset + scale * p.x, offset + scale * p.y);
            let Ok(poly) = g.map(map) else { continue };
            let a = map(Point::new(
                rng.random_range(-9..=9) as f64,
                rng.random_range(-9..=9) as f64,
            ));
            let b = map(Point::new(
                rng.random_range(-9..=9) as f64,
                rng.random_range(-9..=9) as f64,
            ));
            if a != b {
                check(
                    &poly,
                    a,
                    b,
                    None,
                    &format!("scale {scale:e} offset {offset:e} round {round}"),
                );
            }
        }
    }
}

#[test]
fn documented_cases_and_errors() {
    let sq = ConvexPolygon::new([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]).unwrap();
    let p = |x: f64, y: f64| Point::new(x, y);
    let chord = |from, to| Some(Chord { from, to });
    use ChordEnd::*;
    // Along the bottom edge, both ways.
    assert_eq!(
        sq.line_chord(p(-1., 0.), p(5., 0.)),
        Ok(chord(Vertex(0), Vertex(1)))
    );
    assert_eq!(
        sq.line_chord(p(5., 0.), p(-1., 0.)),
        Ok(chord(Vertex(1), Vertex(0)))
    );
    // Along the top edge (opposite to the polygon's direction there), both ways.
    assert_eq!(
        sq.line_chord(p(-1., 2.), p(5., 2.)),
        Ok(chord(Vertex(3), Vertex(2)))
    );
    assert_eq!(
        sq.line_chord(p(5., 2.), p(-1., 2.)),
        Ok(chord(Vertex(2), Vertex(3)))
    );
    // Diagonal: vertex to vertex.
    assert_eq!(
        sq.line_chord(p(-1., -1.), p(3., 3.)),
        Ok(chord(Vertex(0), Vertex(2)))
    );
    // A ray starting on the entry vertex keeps it; starting on the exit, a single point
    // from the query's start to the exit.
    assert_eq!(
        sq.ray_chord(p(0., 0.), p(1., 1.)),
        Ok(chord(Vertex(0), Vertex(2)))
    );
    assert_eq!(sq.ray_chord(p(2., 2.), p(3., 3.)), Ok(chord(Query, Vertex(2))));
    assert_eq!(sq.ray_chord(p(2.5, 2.5), p(3., 3.)), Ok(None));
    // A segment inside: both ends are the query's.
    assert_eq!(sq.segment_chord(p(0.5, 0.5), p(1., 1.5)), Ok(chord(Query, Query)));
    // A segment ending exactly on the entry edge: a single point.
    assert_eq!(sq.segment_chord(p(-1., 1.), p(0., 1.)), Ok(chord(Edge(3), Query)));
    assert_eq!(sq.segment_chord(p(-1., 1.), p(-0.5, 1.)), Ok(None));
    // Errors.
    assert_eq!(
        sq.line_chord(p(1., 1.), p(1., 1.)),
        Err(LineQueryError::SamePoint)
    );
    assert_eq!(
        sq.ray_chord(p(f64::NAN, 1.), p(1., 1.)),
        Err(LineQueryError::NonFinite)
    );
    assert_eq!(
        sq.segment_chord(p(0., 1.), p(f64::INFINITY, 1.)),
        Err(LineQueryError::NonFinite)
    );
    // One ulp past a vertex: the line misses; through it: touches.
    let tri = ConvexPolygon::new([[0.0, 0.0], [4.0, 0.0], [2.0, 1.0]]).unwrap();
    let up = |x: f64| f64::from_bits(x.to_bits() + 1);
    assert_eq!(
        tri.line_chord(p(0., 1.), p(4., 1.)),
        Ok(chord(Vertex(2), Vertex(2)))
    );
    assert_eq!(tri.line_chord(p(0., up(1.)), p(4., up(1.))), Ok(None));
}
