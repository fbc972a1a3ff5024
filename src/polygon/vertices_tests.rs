//! The vertex accesses: a slice reads itself, a posed view reads `Pose::apply` of the
//! shape, and both hand the same slice to `with_slice`.

use super::*;
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

const SEED: u64 = 0x7057_0006;

fn random_shape(rng: &mut SmallRng, n: usize) -> Vec<Point> {
    (0..n)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / n as f64;
            let r = rng.random_range(0.5..2.0);
            Point::new(r * t.cos(), r * t.sin())
        })
        .collect()
}

#[test]
fn a_slice_reads_its_own_vertices() {
    let mut rng = SmallRng::seed_from_u64(SEED);
    let v = random_shape(&mut rng, 17);
    let s: &[Point] = &v;
    assert_eq!(Vertices::len(s), 17);
    for (i, &p) in v.iter().enumerate() {
        assert_eq!(Vertices::get(s, i), p);
    }
    assert_eq!(s.with_slice(|w| w.as_ptr()), v.as_ptr());
}

#[test]
fn a_posed_view_reads_each_vertex_as_pose_apply_rounds_it() {
    let mut rng = SmallRng::seed_from_u64(SEED + 1);
    for _ in 0..200 {
        let n = rng.random_range(3..40);
        let shape = random_shape(&mut rng, n);
        let pose = Pose::from_angle(
            rng.random_range(-10.0..10.0),
            [rng.random_range(-1e3..1e3), rng.random_range(-1e3..1e3)],
        )
        .unwrap();
        let view = PosedVertices::new_unchecked(&shape, pose);
        assert_eq!(view.len(), n);
        let want: Vec<Point> = shape.iter().map(|&p| pose.apply(p).unwrap()).collect();
        for (i, &w) in want.iter().enumerate() {
            let got = view.get(i);
            assert_eq!((got.x.to_bits(), got.y.to_bits()), (w.x.to_bits(), w.y.to_bits()));
        }
        assert_eq!(view.to_points(), want);
        assert_eq!(view.with_slice(|w| w.to_vec()), want);
    }
}

#[test]
fn the_identity_view_is_the_shape() {
    let mut rng = SmallRng::seed_from_u64(SEED + 2);
    let shape = random_shape(&mut rng, 9);
    let view = PosedVertices::new_unchecked(&shape, Pose::identity());
    assert_eq!(view.to_points(), shape);
}
