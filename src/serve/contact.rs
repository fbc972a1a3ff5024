//! The contact normal of a colliding pair, for the elastic bounce, taken from the
//! store's certificates (docs/live.md, "The contact normal").
//!
//! * **From the last disjoint frame**: while a pair's boxes overlap and the polygons do
//!   not, the store's certificate is a separating edge ([`Certificate::Separated`]);
//!   its outward unit normal, oriented from `a` towards `b`, is the direction in which
//!   the two meet: [`separation_normal`].
//! * **From the contact witness**, when the pair was never seen disjoint with
//!   overlapping boxes (placed or edited into contact): [`witness_normal`]. For a
//!   vertex of one polygon inside the other, the outward normal of the other polygon's
//!   edge nearest that vertex; for two crossing edges, the difference of their outward
//!   normals (each edge pushes the other polygon out along its own normal).
//!
//! Both are oriented from `a` (the certificate's P) towards `b`.
//!
//! # Complexity
//! O(1) from a separating edge; O(m) for a vertex witness (the nearest edge of the
//! other polygon, whose vertices the caller walked), O(1) for crossing edges.
//!
//! # Precision
//! Plain floating point: a normal is a direction for the physics, not a predicate, and
//! nothing is decided from it. `None` where the edges are degenerate (zero or
//! non-finite length) or the two normals of crossing edges cancel.

use crate::intersect::{Certificate, Which};
use crate::kernel::Point;

/// The outward unit normal of the counter-clockwise edge `from` → `to` (the edge
/// turned clockwise), or `None` for a degenerate edge.
fn outward(from: Point, to: Point) -> Option<[f64; 2]> {
    let (dx, dy) = (to.x - from.x, to.y - from.y);
    let len = dx.hypot(dy);
    (len > 0.0 && len.is_finite()).then(|| [dy / len, -dx / len])
}

fn unit(v: [f64; 2]) -> Option<[f64; 2]> {
    let len = v[0].hypot(v[1]);
    (len > 0.0 && len.is_finite()).then(|| [v[0] / len, v[1] / len])
}

fn neg(v: [f64; 2]) -> [f64; 2] {
    [-v[0], -v[1]]
}

/// The unit normal from `a` (the certificate's P) towards `b` given by a separating
/// edge, or `None` for another certificate or a degenerate edge.
///
/// ```
/// use polysect::intersect::{Certificate, Which};
/// use polysect::serve::separation_normal;
/// use polysect::Point;
/// // Q's edge (2, 2) → (2, 0), counter-clockwise: Q lies on its +x side, P on its
/// // outer side (-x), so the normal from P towards Q is +x.
/// let c = Certificate::Separated { of: Which::Q, from: Point::new(2.0, 2.0), to: Point::new(2.0, 0.0) };
/// assert_eq!(separation_normal(&c), Some([1.0, 0.0]));
/// ```
pub fn separation_normal(certificate: &Certificate) -> Option<[f64; 2]> {
    match *certificate {
        Certificate::Separated { of, from, to } => {
            let u = outward(from, to)?;
            Some(if of == Which::P { u } else { neg(u) })
        }
        _ => None,
    }
}

/// The unit normal from `a` towards `b` given by an intersection witness (module docs),
/// with `a` and `b` the two polygons' vertices, counter-clockwise; `None` for a
/// separating certificate or a degenerate witness.
pub fn witness_normal(certificate: &Certificate, a: &[Point], b: &[Point]) -> Option<[f64; 2]> {
    match *certificate {
        Certificate::Separated { .. } => None,
        Certificate::VertexInside { of, point } => {
            let other = if of == Which::P { b } else { a };
            let u = nearest_edge_normal(other, point)?;
            // The other polygon's edge pushes the vertex out along u.
            Some(if of == Which::P { neg(u) } else { u })
        }
        Certificate::CrossingEdges { p, q } => {
            let (up, uq) = (outward(p[0], p[1])?, outward(q[0], q[1])?);
            unit([up[0] - uq[0], up[1] - uq[1]])
        }
    }
}

/// The outward unit normal of the edge of `poly` nearest `x` (a point inside it).
fn nearest_edge_normal(poly: &[Point], x: Point) -> Option<[f64; 2]> {
    let n = poly.len();
    (0..n)
        .filter_map(|i| {
            let (s, e) = (poly[i], poly[(i + 1) % n]);
            let u = outward(s, e)?;
            // Distance from x to the edge's line (x is inside: the line's distance).
            let d = (u[0] * (s.x - x.x) + u[1] * (s.y - x.y)).abs();
            Some((d, u))
        })
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, u)| u)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(x: f64, y: f64) -> Vec<Point> {
        [(x, y), (x + 2.0, y), (x + 2.0, y + 2.0), (x, y + 2.0)]
            .map(|(x, y)| Point::new(x, y))
            .to_vec()
    }

    #[test]
    fn separating_edges_give_their_outward_normal_from_a_to_b() {
        let (a, b) = (square(0.0, 0.0), square(3.0, 0.5));
        // a's right edge separates: from a towards b is +x.
        let c = Certificate::Separated {
            of: Which::P,
            from: a[1],
            to: a[2],
        };
        assert_eq!(separation_normal(&c), Some([1.0, 0.0]));
        // b's left edge (3, 2.5) → (3, 0.5): its outer side is -x, the normal from a to b +x.
        let c = Certificate::Separated {
            of: Which::Q,
            from: b[3],
            to: b[0],
        };
        assert_eq!(separation_normal(&c), Some([1.0, 0.0]));
        assert_eq!(witness_normal(&c, &a, &b), None);
        let degenerate = Certificate::Separated {
            of: Which::P,
            from: a[0],
            to: a[0],
        };
        assert_eq!(separation_normal(&degenerate), None);
    }

    #[test]
    fn witnesses_give_the_nearest_edge_or_the_crossing_edges_normals() {
        let (a, b) = (square(0.0, 0.0), square(1.8, 0.5));
        // b's vertex (1.8, 0.5) lies in a, nearest a's right edge: from a to b is +x.
        let c = Certificate::VertexInside {
            of: Which::Q,
            point: b[0],
        };
        assert_eq!(witness_normal(&c, &a, &b), Some([1.0, 0.0]));
        // a's vertex (2, 2) lies in b, nearest b's left edge (outward -x): +x again.
        let c = Certificate::VertexInside {
            of: Which::P,
            point: a[2],
        };
        assert_eq!(witness_normal(&c, &a, &b), Some([1.0, 0.0]));
        // a's top edge crosses b's left edge: the normals (0, 1) and (-1, 0) give (1, 1)/√2.
        let c = Certificate::CrossingEdges {
            p: [a[2], a[3]],
            q: [b[3], b[0]],
        };
        let n = witness_normal(&c, &a, &b).unwrap();
        assert!((n[0] - n[1]).abs() < 1e-15 && n[0] > 0.0);
        assert_eq!(separation_normal(&c), None);
        // Parallel edges of the same direction cancel: no normal.
        let c = Certificate::CrossingEdges {
            p: [a[1], a[2]],
            q: [a[1], a[2]],
        };
        assert_eq!(witness_normal(&c, &a, &a), None);
    }
}
