//! A scene of moving polygons: every step moves each polygon a little, then lists the
//! pairs that intersect.
//!
//! Run with `cargo run --example moving_scene`.

use polysect::intersect::{ArrayIntersection, Linear};
use polysect::store::{PolygonId, Scene};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

fn main() -> Result<(), polysect::store::SceneError> {
    // Seeded: the same run every time (without a seed, the scene's sampling generator is
    // seeded from the OS with the `os-rng` feature; see docs/design.md, "Randomness").
    let mut rng = SmallRng::seed_from_u64(2024);
    let mut scene = Scene::new();
    scene.seed(1);

    // 40 polygons of 8 to 256 vertices scattered over a 20 x 20 field, each with a velocity.
    let mut moving: Vec<(PolygonId, f64, f64)> = Vec::new();
    for _ in 0..40 {
        let n = 1 << rng.random_range(3..=8);
        let radius = rng.random_range(0.5..1.5);
        let (cx, cy) = (rng.random_range(0.0..20.0), rng.random_range(0.0..20.0));
        let shape = polysect::generate::regular_polygon(n, radius);
        let id = scene.insert_points(shape.vertices().iter().map(|p| [p.x + cx, p.y + cy]))?;
        moving.push((id, rng.random_range(-0.3..0.3), rng.random_range(-0.3..0.3)));
    }

    for step in 0..10 {
        // Move every polygon (a translation: snapshots move at once, linked lists when read).
        for &(id, dx, dy) in &moving {
            scene.translate(id, dx, dy)?;
        }
        // Sort and sweep over bounding boxes finds candidate pairs; the planner then picks, per
        // pair, the sampled test on the linked lists or an array test on snapshots.
        let pairs = scene.intersecting_pairs();
        // Name polygons by their index in `moving`, each pair in increasing order.
        let index = |id: PolygonId| moving.iter().position(|&(m, ..)| m == id).expect("live");
        let mut found: Vec<(usize, usize)> = pairs
            .iter()
            .map(|&(a, b)| (index(a).min(index(b)), index(a).max(index(b))))
            .collect();
        found.sort_unstable();
        let shown: Vec<String> = found.iter().take(6).map(|(a, b)| format!("{a}-{b}")).collect();
        println!(
            "step {step}: {:>2} intersecting pairs: {} ...",
            found.len(),
            shown.join(" ")
        );

        // Check against the all-pairs reference with the O(n + m) test on array snapshots.
        let arrays: Vec<_> = moving
            .iter()
            .map(|&(id, ..)| scene.polygon(id).map(|p| p.to_convex()))
            .collect::<Result<_, _>>()?;
        let mut expected = Vec::new();
        for i in 0..arrays.len() {
            for j in i + 1..arrays.len() {
                if Linear.intersects(&arrays[i], &arrays[j]) {
                    expected.push((i, j));
                }
            }
        }
        assert_eq!(found, expected);
    }
    // How the planner answered: box rejections, array tests on snapshots, sampled tests.
    println!("planner: {:?}", scene.stats());
    Ok(())
}
