use super::chords::*;
use super::separation::*;
use super::verify::*;
use super::*;
use crate::kernel::sealed::Predicates as _;
use crate::kernel::{DirectedLine, Kernel, SegmentContact, segment_contact};
use crate::{ConvexPolygon, Exact, LinkedPolygon};

fn poly(pts: &[[f64; 2]]) -> ConvexPolygon {
    ConvexPolygon::new(pts.iter().copied()).unwrap()
}

const SQ: [[f64; 2]; 4] = [[0., 0.], [2., 0.], [2., 2.], [0., 2.]];

#[test]
fn verify_accepts_each_kind_and_names_what_is_wrong() {
    let p = poly(&SQ);
    let q = poly(&[[3., 0.], [4., 0.], [4., 1.]]);
    let pt = Point::new;
    let sep = Certificate::Separated {
        of: Which::P,
        from: pt(2., 0.),
        to: pt(2., 2.),
    };
    assert_eq!(verify(&p, &q, &sep), Ok(()));
    assert!(!sep.intersects());
    // The same edge walked clockwise.
    let cw = Certificate::Separated {
        of: Which::P,
        from: pt(2., 2.),
        to: pt(2., 0.),
    };
    let e = verify(&p, &q, &cw).unwrap_err();
    assert!(matches!(e, CertificateError::Clockwise { .. }));
    assert!(e.to_string().contains("clockwise"), "{e}");
    // Not consecutive.
    let diag = Certificate::Separated {
        of: Which::P,
        from: pt(0., 0.),
        to: pt(2., 2.),
    };
    let e = verify(&p, &q, &diag).unwrap_err();
    assert_eq!(
        e.to_string(),
        "(0.0, 0.0) → (2.0, 2.0) is not an edge of P: the vertex after (0.0, 0.0) (counter-clockwise) is (2.0, 0.0)"
    );
    // The wrong polygon.
    let wrong = Certificate::Separated {
        of: Which::Q,
        from: pt(2., 0.),
        to: pt(2., 2.),
    };
    assert_eq!(
        verify(&p, &q, &wrong).unwrap_err().to_string(),
        "(2.0, 0.0) is not a vertex of Q"
    );
    // An edge that does not separate: Q lies on its inner side.
    let bad = Certificate::Separated {
        of: Which::P,
        from: pt(0., 2.),
        to: pt(0., 0.),
    };
    assert!(matches!(
        verify(&p, &q, &bad),
        Err(CertificateError::NotSeparating { side: Ccw, .. })
    ));

    let r = poly(&[[1., 1.], [3., 1.], [3., 3.]]);
    let inside = Certificate::VertexInside {
        of: Which::Q,
        point: pt(1., 1.),
    };
    assert_eq!(verify(&p, &r, &inside), Ok(()));
    let outside = Certificate::VertexInside {
        of: Which::Q,
        point: pt(3., 3.),
    };
    assert_eq!(
        verify(&p, &r, &outside).unwrap_err().to_string(),
        "vertex (3.0, 3.0) of Q is outside P: strictly right of its edge (2.0, 0.0) → (2.0, 2.0)"
    );
    let cross = Certificate::CrossingEdges {
        p: [pt(2., 0.), pt(2., 2.)],
        q: [pt(1., 1.), pt(3., 1.)],
    };
    assert_eq!(verify(&p, &r, &cross), Ok(()));
    let apart = Certificate::CrossingEdges {
        p: [pt(0., 0.), pt(2., 0.)],
        q: [pt(3., 1.), pt(3., 3.)],
    };
    assert!(matches!(
        verify(&p, &r, &apart),
        Err(CertificateError::EdgesDisjoint { .. })
    ));
    // Linked polygons in shuffled arena order verify the same way.
    use rand::SeedableRng;
    let mut rng = rand::rngs::SmallRng::seed_from_u64(3);
    let (lp, lr) = (
        LinkedPolygon::from_convex_shuffled(&p, &mut rng),
        LinkedPolygon::from_convex_shuffled(&r, &mut rng),
    );
    assert_eq!(verify_linked(&lp, &lr, &cross), Ok(()));
    // (The arena order decides which offending edge is named.)
    assert!(matches!(
        verify_linked(&lp, &lr, &outside),
        Err(CertificateError::Outside { .. })
    ));
}

/// `reduce_chord` where its triangle test misses, on concrete points (a 10-gon with
/// integer coordinates, the chord from (8, 0) to (−8, 0) over the top, the segment's
/// other end at (0, −1)): ends outside the triangle (0, 4, 8) but in the polygon, one
/// of them on the chord from vertex 0 to vertex 2 and one an ulp beyond that chord,
/// are found inside by the search; an end an ulp outside the polygon gives an edge
/// that meets the segment. At scales 1, 2^600 and 2^-600 (exact).
#[test]
fn chord_reduction_past_the_triangle_test() {
    let base = [
        (8., 0.),
        (8., 3.),
        (7., 5.),
        (5., 7.),
        (0., 8.),
        (-5., 7.),
        (-7., 5.),
        (-8., 3.),
        (-8., 0.),
        (0., -4.),
    ];
    let far = (0., -1.);
    // Each end, and whether it lies in the polygon.
    let ends = [
        ((6., 5.), true),
        ((7.5, 2.5), true),
        ((f64::from_bits(7.5f64.to_bits() + 1), 2.5), true),
        ((f64::from_bits(8f64.to_bits() + 1), 1.), false),
    ];
    for scale in [1.0, 2f64.powi(600), 2f64.powi(-600)] {
        let pt = |(x, y): (f64, f64)| Point::new(x * scale, y * scale);
        let pv: Vec<Point> = base.iter().map(|&v| pt(v)).collect();
        let n = pv.len();
        let inside = |x: Point| (0..n).all(|i| Exact.orient(pv[i], pv[(i + 1) % n], x) != Cw);
        for (k, &(near, in_p)) in ends.iter().enumerate() {
            let (s, t) = (pt(far), pt(near));
            match reduce_chord(Exact, &pv, (0, 8), (s, t), None, None) {
                Reduced::Inside(x) => {
                    assert!(in_p && x == t && inside(x), "×{scale} {near:?}");
                }
                Reduced::Edge(e, contact, _) => {
                    assert!(!in_p && contact.meets(), "×{scale} {near:?}");
                    assert!(
                        segment_contact(Exact, pv[e], pv[(e + 1) % n], s, t).meets(),
                        "×{scale} {near:?}: edge {e}"
                    );
                }
                Reduced::Beyond(_) | Reduced::Fail => panic!("×{scale} {near:?}: failed"),
            }
            // The triangle test misses every end; the triangle (0, 2, 4) holds the
            // first two only (the second on its edge), the third is an ulp beyond it.
            let in_triangle = |a: usize, b: usize, c: usize| {
                [(a, b), (b, c), (c, a)]
                    .iter()
                    .all(|&(u, v)| Exact.orient(pv[u], pv[v], t) != Cw)
            };
            assert!(!in_triangle(0, 4, 8), "×{scale} {near:?}");
            assert_eq!(in_triangle(0, 2, 4), k < 2, "×{scale} {near:?}");
            assert_eq!(inside(t), in_p, "×{scale} {near:?}");
        }
    }
}

/// The chain search finds the crossing edge a scan finds, on every family's polygons
/// (touching, one-ulp, nested and ordinary pairs, up to 2^12 vertices, so that long
/// chains take the regula falsi probes) for lines through two vertices,
/// with the side of the edge's end; and every chord of P crossing a chord of Q properly resolves to a certificate
/// that verifies, at ordinary scale and scaled by 2^600 and 2^-600.
#[test]
fn chain_search_finds_the_crossing_and_chords_resolve() {
    use crate::generate::{self, Family, Relation, map_pair};
    use rand::{Rng, SeedableRng};
    let mut rng = rand::rngs::SmallRng::seed_from_u64(0x1e7);
    let (mut searches, mut resolved) = (0, 0);
    for &family in Family::ALL {
        // 2^12: chains long enough for `regula_falsi`.
        for log2 in [3, 6, 10, 12] {
            for relation in [Relation::Intersecting, Relation::Any] {
                let Ok(base) = generate::try_pair(family, 1 << log2, relation, &mut rng) else {
                    continue;
                };
                for scale in [1.0, 2f64.powi(600), 2f64.powi(-600)] {
                    let Some((p, q)) = map_pair(&base, |v| Point::new(v.x * scale, v.y * scale)) else {
                        continue;
                    };
                    let (pv, qv) = (p.vertices(), q.vertices());
                    let (n, m) = (pv.len(), qv.len());
                    for _ in 0..20 {
                        // A chord of P and a line through two vertices of Q.
                        let (i, len) = (rng.random_range(0..n), rng.random_range(2..n));
                        let j = (i + len) % n;
                        let (c, d) = (rng.random_range(0..m), rng.random_range(0..m));
                        let (s, t) = (qv[c], qv[d]);
                        let line = DirectedLine::new(s, t);
                        let at = |off: usize| pv[(i + off) % n];
                        let sigma = Exact.orient_line(&line, at(0));
                        let end = Exact.orient_line(&line, at(len));
                        if c == d || sigma == Collinear || end != sigma.reverse() {
                            continue;
                        }
                        let sides: Vec<bool> = (0..=len)
                            .map(|o| Exact.orient_line(&line, at(o)) == sigma)
                            .collect();
                        let Some(first_off) = sides.iter().position(|&x| !x) else {
                            unreachable!("the chain ends off sigma's side");
                        };
                        // One crossing (a convex chain): sides hold until first_off.
                        let Ok((lo, o_next)) =
                            crossing_edge(Exact, &line, &at, (at(0), at(len)), len, sigma, &|_, _| false)
                        else {
                            unreachable!("no probe is accepted");
                        };
                        if sides[first_off..].iter().all(|&x| !x) {
                            assert_eq!(lo + 1, first_off, "{family:?} 2^{log2} ×{scale}");
                            assert_eq!(o_next, Exact.orient_line(&line, at(lo + 1)));
                            searches += 1;
                        }
                        if segment_contact(Exact, pv[i], pv[j], s, t) == SegmentContact::Crossing {
                            let cert = resolve_chords(Exact, pv, (i, j), qv, (c, d))
                                .unwrap_or_else(|| panic!("{family:?} 2^{log2} ×{scale}: none"));
                            assert_eq!(verify(&p, &q, &cert), Ok(()), "{family:?} 2^{log2} ×{scale}");
                            resolved += 1;
                        }
                    }
                }
            }
        }
    }
    assert!(
        searches > 300 && resolved > 80,
        "{searches} searches, {resolved} resolved"
    );
}

#[test]
fn resolve_chords_turns_diagonals_into_witnesses() {
    // Two squares rotated against each other: the diagonals cross at the centre.
    let p = poly(&[[0., 0.], [4., 0.], [4., 4.], [0., 4.]]);
    let q = poly(&[[2., -1.], [5., 2.], [2., 5.], [-1., 2.]]);
    let c = resolve_chords(Exact, p.vertices(), (0, 2), q.vertices(), (0, 2)).unwrap();
    assert_eq!(verify(&p, &q, &c), Ok(()), "{c:?}");
    // A thin cross: no vertex inside, only crossing edges.
    let h = poly(&[[-10., -1.], [10., -1.], [10., 1.], [-10., 1.]]);
    let v = poly(&[[-1., -10.], [1., -10.], [1., 10.], [-1., 10.]]);
    let c = resolve_chords(Exact, h.vertices(), (0, 2), v.vertices(), (1, 3)).unwrap();
    assert!(matches!(c, Certificate::CrossingEdges { .. }), "{c:?}");
    assert_eq!(verify(&h, &v, &c), Ok(()));
    // Disjoint segments: no certificate.
    let far = poly(&[[20., 20.], [21., 20.], [21., 21.]]);
    assert_eq!(
        resolve_chords(Exact, h.vertices(), (0, 2), far.vertices(), (0, 1)),
        None
    );
}

/// The positions of a linked polygon in boundary order.

#[test]
fn faces_of_a_common_support_line_give_the_separating_edge() {
    let p = poly(&SQ);
    let q = poly(&[[3., 3.], [4., 3.], [4., 4.]]);
    // The line x + y = 5.5... through no vertex: faces (2,2) of P and (3,3) of Q.
    let c = from_faces(Exact, p.vertices(), &[2], q.vertices(), &[0]).unwrap();
    assert_eq!(verify(&p, &q, &c), Ok(()), "{c:?}");
}
