use super::engine::*;
use super::witness::*;
use super::*;
use crate::Exact;
use crate::Point;
use crate::intersect::Which;
use crate::intersect::{Iterations, brute_force};
use crate::kernel::sealed::Predicates as _;

fn poly(pts: &[[f64; 2]]) -> ConvexPolygon {
    ConvexPolygon::new(pts.iter().copied()).unwrap()
}

#[test]
fn hand_cases() {
    let sq = poly(&[[0., 0.], [2., 0.], [2., 2.], [0., 2.]]);
    let cases: &[(&[[f64; 2]], bool)] = &[
        (&[[1., 1.], [1.5, 1.], [1., 1.5]], true),
        (&[[-1., -1.], [3., -1.], [3., 3.], [-1., 3.]], true),
        (&[[2., 2.], [3., 2.], [3., 3.]], true),
        (&[[2., 0.5], [3., 0.], [3., 1.]], true),
        (&[[2., 0.], [3., 0.], [3., 2.], [2., 2.]], true),
        (&[[2.5, 0.], [3., 0.], [3., 2.]], false),
        (&[[3., 3.], [4., 3.], [4., 4.]], false),
        (&[[1.5, 3.], [3., 1.5], [3., 3.]], false),
    ];
    for (q, want) in cases {
        let q = poly(q);
        assert_eq!(Barba.intersects(&sq, &q), *want, "{q:?}");
        assert_eq!(Barba.intersects(&q, &sq), *want, "{q:?}");
    }
}

/// A regular 64-gon against squares with edges parallel to its edges (parallel
/// lines among e0, e1, e2 and between T_P and T_Q), touching from outside along
/// an edge, at a vertex, and one step apart.
#[test]
fn parallel_edges_and_tangencies() {
    let n = 64;
    let big = crate::generate::regular_polygon(n, 1.0);
    let v = big.vertices();
    for i in 0..n {
        let (a, b) = (v[i], v[(i + 1) % n]);
        let d = Point::new(b.x - a.x, b.y - a.y);
        let out = Point::new(d.y, -d.x); // outward normal, same length as the edge
        for (shift, want) in [(0.0, true), (1.0, false)] {
            let a2 = Point::new(a.x + shift * out.x, a.y + shift * out.y);
            let b2 = Point::new(b.x + shift * out.x, b.y + shift * out.y);
            let sq = ConvexPolygon::new([
                [a2.x, a2.y],
                [a2.x + out.x, a2.y + out.y],
                [b2.x + out.x, b2.y + out.y],
                [b2.x, b2.y],
            ]);
            let Ok(sq) = sq else { continue };
            let truth = brute_force(Exact, &big, &sq);
            if shift == 0.0 {
                // Rounding may move the copied corners; the oracle decides.
                assert_eq!(Barba.intersects(&big, &sq), truth, "edge {i}");
            } else {
                assert_eq!(truth, want);
            }
            assert_eq!(Barba.intersects(&big, &sq), truth, "edge {i} shift {shift}");
            assert_eq!(
                Barba.intersects(&sq, &big),
                truth,
                "edge {i} shift {shift} swapped"
            );
        }
        // A triangle with one vertex exactly on vertex i of the big polygon.
        let tri = poly(&[
            [a.x, a.y],
            [a.x * 2.0, a.y * 2.0 + 0.5],
            [a.x * 2.0 + 0.5, a.y * 2.0],
        ]);
        assert!(Barba.intersects(&big, &tri) && Barba.intersects(&tri, &big));
    }
}

/// The disjoint derivation's own certificate (`lift`, before any rerun with the
/// roles exchanged) on every disjoint pair of the families, touching ones and
/// one-ulp gaps included: whatever it returns verifies exactly, and on the ellipse
/// families (where a Q edge that fails to lift is common) it nearly always returns
/// one, through P's edges at the triangle vertex nearest the line when needed.
#[test]
fn disjoint_exits_lift_to_certificates() {
    use crate::generate::{self, Family, Relation};
    use crate::intersect::verify;
    use rand::SeedableRng;
    let mut rng = rand::rngs::SmallRng::seed_from_u64(0xce47);
    let (mut by_p_edge, mut ellipses, mut unlifted) = (0, 0, 0);
    for &family in Family::ALL {
        for log2 in [4, 7, 10] {
            for _ in 0..40 {
                let Ok((p, q)) = generate::try_pair(family, 1 << log2, Relation::Disjoint, &mut rng) else {
                    continue;
                };
                if brute_force(Exact, &p, &q) {
                    continue;
                }
                let (pv, qv) = (p.vertices(), q.vertices());
                let k = Exact.within([p.bounding_box(), q.bounding_box()]);
                let Exit::Apart { pr, q: qs, line } = run::<_, (), Record, Ours, _, _>(k, pv, qv, &mut ())
                else {
                    panic!("{family:?}: a disjoint pair ends without separation");
                };
                let lifted = lift(k, pv, qv, pr, qs, line);
                if let Some(c) = lifted {
                    assert_eq!(verify(&p, &q, &c), Ok(()), "{family:?} 2^{log2}: {c:?}");
                    by_p_edge += usize::from(
                        matches!(line, Sep::QLine(..))
                            && matches!(c, Certificate::Separated { of: Which::P, .. }),
                    );
                }
                if matches!(family, Family::Ellipse | Family::Rotated | Family::NonUniform) {
                    ellipses += 1;
                    unlifted += usize::from(lifted.is_none());
                }
                // The certified call completes what `lift` leaves, and verifies.
                let c = Barba.certified(&p, &q);
                assert_eq!(verify(&p, &q, &c), Ok(()), "{family:?} 2^{log2}: {c:?}");
            }
        }
    }
    assert!(by_p_edge > 0, "P's edges at the nearest vertex were never needed");
    // Before P's edges were tried, one ellipse pair in four needed the rerun.
    assert!(20 * unlifted <= ellipses, "{unlifted} of {ellipses} not lifted");
}

/// The meeting exits' witnesses on every intersecting pair of the families (touching
/// ones, one-ulp gaps and nested pairs included), at ordinary scale and scaled by
/// 2^600 and 2^-600 (exact: powers of two): whatever the run ends on, its certificate
/// exists and verifies, in particular where T_P meets a segment Q' (the orientation
/// table and the proper crossing resolved without a second contact test), and where
/// that segment is Q's own edge (Q' was all of Q: no search in Q).
#[test]
fn meeting_exits_give_certificates() {
    use crate::generate::{self, Family, Relation, map_pair};
    use crate::intersect::verify;
    use rand::SeedableRng;
    let mut rng = rand::rngs::SmallRng::seed_from_u64(0x5e9);
    let (mut segments, mut crossings, mut q_edges) = (0, 0, 0);
    for &family in Family::ALL {
        for log2 in [3, 6, 9] {
            for _ in 0..12 {
                let Ok(base) = generate::try_pair(family, 1 << log2, Relation::Intersecting, &mut rng) else {
                    continue;
                };
                for scale in [1.0, 2f64.powi(600), 2f64.powi(-600)] {
                    let Some((p, q)) = map_pair(&base, |v| Point::new(v.x * scale, v.y * scale)) else {
                        continue;
                    };
                    if !brute_force(Exact, &p, &q) {
                        continue;
                    }
                    let (pv, qv) = (p.vertices(), q.vertices());
                    let k = Exact.within([p.bounding_box(), q.bounding_box()]);
                    let exit = run::<_, (), Record, Ours, _, _>(k, pv, qv, &mut ());
                    let segment = matches!(exit, Exit::Segment(_));
                    // The segment is Q's own edge Q[d] → Q[c] when Q' was all of Q.
                    let q_edge = matches!(exit, Exit::Segment(s) if s.q_edge);
                    let c = meet_certificate(k, pv, qv, exit)
                        .unwrap_or_else(|| panic!("{family:?} 2^{log2} ×{scale}: {exit:?} gave none"));
                    assert_eq!(verify(&p, &q, &c), Ok(()), "{family:?} 2^{log2} ×{scale}: {c:?}");
                    segments += usize::from(segment);
                    let crossed = segment && matches!(c, Certificate::CrossingEdges { .. });
                    crossings += usize::from(crossed);
                    q_edges += usize::from(q_edge && !matches!(c, Certificate::VertexInside { .. }));
                    let certified = Barba.certified(&p, &q);
                    assert_eq!(verify(&p, &q, &certified), Ok(()), "{family:?}: {certified:?}");
                }
            }
        }
    }
    assert!(
        segments > 0 && crossings > 0 && q_edges > 0,
        "{segments} segment exits, {crossings} crossings, {q_edges} edge pairs on Q's edge"
    );
}

/// `certified_with` (the run that completes its certificate where it ends) and
/// `certified_probed` (the derivation, completed by the fallback) give the same
/// certificate on every family, both relations, every variant's choice of Barba
/// included; and it verifies.
/// On polygons of 2^13 vertices the chord searches are long enough for the regula
/// falsi probes and their test in Q's triangle (`reduce_chord`'s `apex`): every
/// certificate verifies, under both certified calls.
#[test]
fn long_chords_give_certificates() {
    use crate::generate::{self, Family, Relation};
    use crate::intersect::verify;
    use rand::SeedableRng;
    let mut rng = rand::rngs::SmallRng::seed_from_u64(0x1f8);
    let mut checked = 0;
    for family in [Family::Ellipse, Family::Rotated, Family::NonUniform] {
        for _ in 0..40 {
            let (p, q) = generate::pair(family, 1 << 13, Relation::Intersecting, &mut rng);
            let c = Barba.certified_with(Exact, &p, &q);
            assert_eq!(c, Barba.certified_probed(Exact, &p, &q, &mut ()), "{family:?}");
            assert_eq!(verify(&p, &q, &c), Ok(()), "{family:?}: {c:?}");
            checked += 1;
        }
    }
    assert_eq!(checked, 120);
}

#[test]
fn certified_with_matches_the_derivation() {
    use crate::generate::{self, Family, Relation};
    use crate::intersect::verify;
    use rand::SeedableRng;
    let mut rng = rand::rngs::SmallRng::seed_from_u64(0xc47);
    let mut compared = 0;
    for &family in Family::ALL {
        for log2 in [3, 6, 10] {
            for relation in [Relation::Intersecting, Relation::Disjoint] {
                for _ in 0..6 {
                    let Ok((p, q)) = generate::try_pair(family, 1 << log2, relation, &mut rng) else {
                        continue;
                    };
                    let c = Barba.certified_with(Exact, &p, &q);
                    assert_eq!(c, Barba.certified_probed(Exact, &p, &q, &mut ()), "{family:?}");
                    assert_eq!(verify(&p, &q, &c), Ok(()), "{family:?} 2^{log2}: {c:?}");
                    let v = BarbaVariant::<false, 4, true>;
                    assert_eq!(
                        v.certified_with(Exact, &p, &q),
                        v.certified_probed(Exact, &p, &q, &mut ()),
                        "{family:?}"
                    );
                    compared += 1;
                }
            }
        }
    }
    assert!(compared > 100, "{compared} pairs");
}

#[test]
fn iterations_are_logarithmic() {
    let n = 1 << 12;
    let big = crate::generate::regular_polygon(n, 1.0);
    let far = crate::generate::regular_polygon(n, 1.0)
        .map(|p| Point::new(p.x + 2.5, p.y))
        .unwrap();
    let mut it = Iterations::default();
    assert!(!Barba.intersects_probed(Exact, &big, &far, &mut it));
    assert!(it.0 <= 4 * 12, "{} iterations", it.0);
}
