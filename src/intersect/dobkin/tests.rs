use super::engine::*;
use super::*;
use crate::Exact;
use crate::Point;

fn poly(pts: &[[f64; 2]]) -> ConvexPolygon {
    ConvexPolygon::new(pts.iter().copied()).unwrap()
}

#[test]
fn chains_with_horizontal_top_and_bottom() {
    // A square starting at every vertex: top-left is (0,2), bottom-right (2,0).
    let sq = [[0., 0.], [2., 0.], [2., 2.], [0., 2.]];
    for s in 0..4 {
        let pts: Vec<[f64; 2]> = (0..4).map(|i| sq[(s + i) % 4]).collect();
        let p = poly(&pts);
        let v = p.vertices();
        let [t, b, _, _] = extremes(Exact, v, v);
        let (l, r) = chains(v, t, b);
        assert_eq!(
            (at(v, l, 0), at(v, l, l.len - 1)),
            (Point::new(0., 2.), Point::new(0., 0.))
        );
        assert_eq!(
            (at(v, r, 0), at(v, r, r.len - 1)),
            (Point::new(2., 0.), Point::new(2., 2.))
        );
        assert_eq!((l.len, r.len), (2, 2));
    }
    // A diamond: single top and bottom vertices shared by both chains.
    let d = poly(&[[0., -1.], [1., 0.], [0., 1.], [-1., 0.]]);
    let [t, b, _, _] = extremes(Exact, d.vertices(), d.vertices());
    let (l, r) = chains(d.vertices(), t, b);
    assert_eq!((l.len, r.len), (3, 3));
    assert_eq!(at(d.vertices(), l, 0), Point::new(0., 1.));
    assert_eq!(at(d.vertices(), r, 0), Point::new(0., -1.));
}

/// Dobkin's own derivation (no completing search) and its verification, for both
/// orders of the pair and every start index of small polygons.
fn certifies_itself(p: &ConvexPolygon, q: &ConvexPolygon, what: &str) {
    let starts = |c: &ConvexPolygon| if c.len() <= 8 { c.len() } else { 2 };
    for (a, b) in [(p, q), (q, p)] {
        for i in 0..starts(a) {
            for j in 0..starts(b) {
                let (a, b) = (a.starting_at(i), b.starting_at(j));
                let want = crate::intersect::Linear.intersects(&a, &b);
                match Dobkin.derive_probed(Exact, &a, &b, &mut ()) {
                    Derivation::Certified(c) => {
                        assert_eq!(c.intersects(), want, "{what}: {c:?}");
                        assert_eq!(
                            crate::intersect::verify(&a, &b, &c),
                            Ok(()),
                            "{what}: {c:?}\n{a:?}\n{b:?}"
                        );
                    }
                    Derivation::Answer(answer) => {
                        assert_eq!(answer, want, "{what}");
                        assert!(answer, "{what}: a disjoint pair not certified\n{a:?}\n{b:?}");
                    }
                }
            }
        }
    }
}

/// `q` moved straight up until its lowest vertex is just above `p`'s highest one
/// (one ulp where the translation allows it), and `dx` sideways.
fn stacked(p: &ConvexPolygon, q: &ConvexPolygon, dx: f64) -> Option<ConvexPolygon> {
    let top = p.vertices().iter().map(|v| v.y).fold(f64::MIN, f64::max);
    let bottom = q.vertices().iter().map(|v| v.y).fold(f64::MAX, f64::min);
    let mut dy = top - bottom;
    for _ in 0..64 {
        let moved = q.map(|v| Point::new(v.x + dx, v.y + dy)).ok()?;
        if moved.vertices().iter().all(|v| v.y > top) {
            return Some(moved);
        }
        dy = dy.next_up();
    }
    None
}

#[test]
fn disjoint_heights_certified_from_the_lowest_vertex_of_the_difference() {
    // Horizontal tops and bottoms: squares and triangles stacked with every
    // horizontal offset, one ulp apart and far apart.
    let sq = poly(&[[0., 0.], [2., 0.], [2., 2.], [0., 2.]]);
    let tri_up = poly(&[[0., 0.], [2., 0.], [1., 1.]]);
    let tri_down = poly(&[[1., 0.], [2., 1.], [0., 1.]]);
    for lower in [&sq, &tri_up, &tri_down] {
        for upper in [&sq, &tri_up, &tri_down] {
            for dx in [-3., -2., -1.5, -1., -0.5, 0., 0.5, 1., 1.5, 2., 3.] {
                let q = stacked(lower, upper, dx).unwrap();
                certifies_itself(lower, &q, &format!("stacked one ulp apart, dx = {dx}"));
                let far = q.map(|v| Point::new(v.x, v.y + 5.)).unwrap();
                certifies_itself(lower, &far, &format!("stacked apart, dx = {dx}"));
            }
        }
    }
    // Every generator family, stacked with random offsets, and carried to the
    // extremes of f64.
    use crate::generate::{self, Family, Relation};
    use rand::{Rng, SeedableRng};
    let mut rng = rand::rngs::SmallRng::seed_from_u64(0xd0b1);
    for &family in Family::ALL {
        for i in 0..24 {
            let n = [3, 4, 5, 7, 12, 40, 300][i % 7];
            let (p, q) = generate::pair(family, n, Relation::Any, &mut rng);
            let b = p.bounding_box();
            let width = b.max.x - b.min.x;
            let dx = rng.random_range(-1.0..1.0) * width;
            let Some(q) = stacked(&p, &q, dx) else { continue };
            let what = format!("{family} n={n} #{i}");
            certifies_itself(&p, &q, &what);
            for scale in [2f64.powi(-1000), 2f64.powi(600)] {
                if let Some((p, q)) =
                    generate::map_pair(&(p.clone(), q.clone()), |v| Point::new(v.x * scale, v.y * scale))
                {
                    certifies_itself(&p, &q, &format!("{what} scaled {scale:e}"));
                }
            }
        }
    }
}

#[test]
fn disjoint_pairs_certified_by_the_search_itself() {
    // The faces at the maximum of g, where the failed test's `orient` is reused:
    // every family's disjoint pairs (touching families: their one-ulp gaps and
    // shared-edge neighbours), and the extremes of f64.
    use crate::generate::{self, Family, Relation};
    use rand::SeedableRng;
    let mut rng = rand::rngs::SmallRng::seed_from_u64(0xd0b2);
    for &family in Family::ALL {
        for i in 0..30 {
            let n = [3, 4, 6, 9, 17, 64, 500][i % 7];
            let (p, q) = generate::pair(family, n, Relation::Disjoint, &mut rng);
            let what = format!("{family} n={n} #{i}");
            certifies_itself(&p, &q, &what);
            let o = 2f64.powi(52);
            if let Some((p, q)) = generate::map_pair(&(p, q), |v| Point::new(v.x + o, v.y - o)) {
                certifies_itself(&p, &q, &format!("{what} offset 2^52"));
            }
        }
    }
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
        (&[[0., 2.], [2., 2.], [1., 3.]], true), // shared horizontal top edge
        (&[[0., 2.5], [2., 2.5], [1., 3.]], false),
        (&[[2.5, 0.], [3., 0.], [3., 2.]], false),
        (&[[3., 3.], [4., 3.], [4., 4.]], false),
        (&[[1.5, 3.], [3., 1.5], [3., 3.]], false),
    ];
    for (q, want) in cases {
        let q = poly(q);
        assert_eq!(Dobkin.intersects(&sq, &q), *want, "{q:?}");
        assert_eq!(Dobkin.intersects(&q, &sq), *want, "{q:?}");
    }
}
