//! The contact normal of a colliding pair, for the collision impulse, taken from the
//! store's certificates (docs/live.md, "The contact normal").
//!
//! * **From the last disjoint frame**: while a pair's boxes overlap and the polygons do
//!   not, the store's certificate is a separating edge ([`Certificate::Separated`]);
//!   its outward unit normal, oriented from `a` towards `b`, is the direction in which
//!   the two meet: [`separation_normal`].
//! * **From the penetration**, when the pair was never seen disjoint with overlapping
//!   boxes (placed or edited into contact): the library's penetration normal
//!   ([`crate::contact::depth_with`]), the direction of the shortest translation of `b`
//!   that leaves the two only touching: [`penetration_normal`].
//!
//! Both are oriented from `a` (the certificate's P) towards `b`.
//!
//! # Complexity
//! O(1) from a separating edge; O(n + m) from the penetration (the vertices the caller
//! walked, validated into arrays, and the library's walk over their Minkowski
//! difference's edges).
//!
//! # Precision
//! A separating edge's normal is plain floating point: a direction for the physics, not
//! a predicate, and nothing is decided from it (`None` for a degenerate edge). The
//! penetration normal is the library's: each component correctly rounded from the
//! exact direction.

use crate::intersect::{Certificate, Which};
use crate::kernel::{Exact, Point};
use crate::polygon::ConvexPolygon;

/// The outward unit normal of the counter-clockwise edge `from` → `to` (the edge
/// turned clockwise), or `None` for a degenerate edge.
fn outward(from: Point, to: Point) -> Option<[f64; 2]> {
    let (dx, dy) = (to.x - from.x, to.y - from.y);
    let len = dx.hypot(dy);
    (len > 0.0 && len.is_finite()).then(|| [dy / len, -dx / len])
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

/// The unit normal from `a` towards `b` of two polygons that meet: the library's
/// penetration normal ([`crate::contact::depth_with`] under the exact kernel), the
/// direction of the shortest translation of `b` after which the two only touch, with
/// `a` and `b` the two polygons' vertices, counter-clockwise. `None` when they do not
/// meet or a vertex list is not a strictly convex polygon. O(n + m).
///
/// ```
/// use polysect::Point;
/// use polysect::serve::penetration_normal;
/// let square = |x: f64, y: f64| [(x, y), (x + 2.0, y), (x + 2.0, y + 2.0), (x, y + 2.0)].map(Point::from).to_vec();
/// // b overlaps a's right side by 0.2: b leaves along +x.
/// assert_eq!(penetration_normal(&square(0.0, 0.0), &square(1.8, 0.5)), Some([1.0, 0.0]));
/// ```
pub fn penetration_normal(a: &[Point], b: &[Point]) -> Option<[f64; 2]> {
    let p = ConvexPolygon::new(a.iter().copied()).ok()?;
    let q = ConvexPolygon::new(b.iter().copied()).ok()?;
    let normal = crate::contact::depth_with(Exact, &p, &q)?.normal;
    normal.iter().all(|c| c.is_finite()).then_some(normal)
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
        let degenerate = Certificate::Separated {
            of: Which::P,
            from: a[0],
            to: a[0],
        };
        assert_eq!(separation_normal(&degenerate), None);
    }

    #[test]
    fn meeting_pairs_take_the_librarys_penetration_normal() {
        let a = square(0.0, 0.0);
        // b overlaps a's right side by 0.2 (and its top by 1.5): the shortest way out is +x.
        assert_eq!(penetration_normal(&a, &square(1.8, 0.5)), Some([1.0, 0.0]));
        // b overlaps a's top by 0.1: +y.
        assert_eq!(penetration_normal(&a, &square(0.5, 1.9)), Some([0.0, 1.0]));
        // From b towards a it is the opposite.
        assert_eq!(penetration_normal(&square(0.5, 1.9), &a), Some([0.0, -1.0]));
        // Touching along an edge: depth 0, a direction that separates them.
        assert_eq!(penetration_normal(&a, &square(2.0, 0.0)), Some([1.0, 0.0]));
        // Apart, or not a polygon: none.
        assert_eq!(penetration_normal(&a, &square(3.0, 0.0)), None);
        assert_eq!(penetration_normal(&a, &a[..2]), None);
        // Equal to the library's normal on random overlapping pairs.
        let mut rng = <rand::rngs::SmallRng as rand::SeedableRng>::seed_from_u64(5);
        for _ in 0..200 {
            use rand::Rng;
            let p = crate::generate::ellipse_polygon(&mut rng, 24, &crate::generate::Density::Uniform, true);
            let (dx, dy) = (rng.random_range(-1.5..1.5), rng.random_range(-1.5..1.5));
            let q = p.map(|v| Point::new(v.x + dx, v.y + dy)).unwrap();
            let want = crate::contact::depth(&p, &q).map(|d| d.normal);
            assert_eq!(penetration_normal(p.vertices(), q.vertices()), want);
        }
    }
}
