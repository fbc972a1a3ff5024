//! Posed polygons read through their poses: the array test's view gives the answers and
//! the certificates (equal, and valid on the world polygons) of the snapshot that
//! `settle` would have built, on random poses and sizes around the threshold.

use super::super::route::{ArrayRef, array_certified, array_test};
use super::pose::VIEW_MIN_VERTICES;
use super::*;
use crate::intersect::{ArrayIntersection, Linear, verify};
use crate::kernel::Pose;
use rand::Rng;

const SEED: u64 = 0x0038_0006;

fn ellipse(rng: &mut SmallRng, n: usize) -> Vec<Point> {
    let (a, b) = (rng.random_range(0.5..1.0), rng.random_range(0.5..1.0));
    let pts: Vec<Point> = (0..n)
        .map(|_| {
            let t: f64 = rng.random_range(0.0..std::f64::consts::TAU);
            Point::new(a * t.cos(), b * t.sin())
        })
        .collect();
    crate::polygon::convex_hull(&pts).unwrap().into_vertices()
}

/// The snapshot `settle` builds for a polygon read through its pose.
fn settled(scene: &Scene, key: usize) -> ConvexPolygon {
    match scene.entries[key].array() {
        Some(ArrayRef::Posed(view, _)) => ConvexPolygon::from_ccw_unchecked(view.to_points()),
        other => panic!("polygon {key} is not read through its pose: {other:?}"),
    }
}

#[test]
fn the_view_answers_and_certifies_as_the_settled_snapshot() {
    let mut rng = SmallRng::seed_from_u64(SEED);
    let mut viewed = 0;
    let mut hits = 0;
    for _ in 0..8 {
        let mut scene = Scene::new();
        scene.set_strategy(Strategy::Cached);
        let ids: Vec<PolygonId> = (0..16)
            .map(|i| {
                let n = if i % 4 == 0 {
                    rng.random_range(3..VIEW_MIN_VERTICES)
                } else {
                    rng.random_range(VIEW_MIN_VERTICES..300)
                };
                scene.insert_points(ellipse(&mut rng, n)).unwrap()
            })
            .collect();
        for frame in 0..6 {
            for &id in &ids {
                let angle: f64 = rng.random_range(0.0..std::f64::consts::TAU);
                let pose = Pose::from_angle(angle, [rng.random_range(0.0..3.0), rng.random_range(0.0..3.0)])
                    .unwrap();
                scene.set_pose(id, pose).unwrap();
            }
            if frame < 2 {
                // The planner converts (cached strategy): the next lazy poses owe snapshots.
                scene.intersecting_pairs();
                continue;
            }
            scene.debug_validate().unwrap();
            let keys: Vec<usize> = ids.iter().map(|&id| scene.key(id).unwrap()).collect();
            // What the planner does to polygons whose boxes meet: small ones get their
            // snapshots, large ones stay read through their poses.
            for &k in &keys {
                scene.settle(k);
            }
            let worlds: Vec<ConvexPolygon> = ids
                .iter()
                .map(|&id| scene.polygon(id).unwrap().to_convex())
                .collect();
            for (i, &a) in keys.iter().enumerate() {
                let pa = scene.entries[a].array().expect("a settled or viewed polygon");
                let large = scene.entries[a].posed.as_ref().unwrap().array.len() >= VIEW_MIN_VERTICES;
                assert_eq!(
                    matches!(pa, ArrayRef::Posed(..)),
                    large,
                    "read through the pose iff large"
                );
                let sa = if large {
                    settled(&scene, a)
                } else {
                    scene.entries[a].snapshot.clone().unwrap()
                };
                for (j, &b) in keys.iter().enumerate() {
                    let pb = scene.entries[b].array().expect("a settled or viewed polygon");
                    let sb = match pb {
                        ArrayRef::Posed(..) => settled(&scene, b),
                        ArrayRef::Stored(s) => s.clone(),
                    };
                    viewed += usize::from(large);
                    let want = Linear.intersects(&worlds[i], &worlds[j]);
                    hits += usize::from(want);
                    let got = array_test(Exact, pa, pb, false);
                    assert_eq!(got, want);
                    assert_eq!(
                        array_test(Exact, ArrayRef::Stored(&sa), ArrayRef::Stored(&sb), false),
                        want
                    );
                    let c = array_certified(Exact, pa, pb, false);
                    let d = array_certified(Exact, ArrayRef::Stored(&sa), ArrayRef::Stored(&sb), false);
                    assert_eq!(c, d, "the view's certificate is the snapshot's");
                    assert_eq!(c.intersects(), want);
                    assert_eq!(verify(&worlds[i], &worlds[j], &c), Ok(()));
                    // The linear walk of a pair with a view reads the world arrays.
                    assert_eq!(array_test(Exact, pa, pb, true), want);
                    let l = array_certified(Exact, pa, pb, true);
                    assert_eq!(verify(&worlds[i], &worlds[j], &l), Ok(()));
                }
            }
            // And the scene's own frame, through the planner.
            let mut got: Vec<(usize, usize)> = scene
                .intersecting_pairs()
                .into_iter()
                .map(|(a, b)| {
                    let (i, j) = (
                        ids.iter().position(|&x| x == a).unwrap(),
                        ids.iter().position(|&x| x == b).unwrap(),
                    );
                    (i.min(j), i.max(j))
                })
                .collect();
            got.sort_unstable();
            let want: Vec<(usize, usize)> = (0..ids.len())
                .flat_map(|i| (i + 1..ids.len()).map(move |j| (i, j)))
                .filter(|&(i, j)| Linear.intersects(&worlds[i], &worlds[j]))
                .collect();
            assert_eq!(got, want);
        }
    }
    assert!(viewed > 1000, "{viewed} pairs read through a pose");
    assert!(hits > 100, "{hits} intersecting pairs");
}
