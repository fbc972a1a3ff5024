use super::*;
use crate::ConvexPolygon;
use crate::intersect::{ArrayIntersection, Linear};

fn reference_pairs(polygons: &[Vec<Point>]) -> Vec<[usize; 2]> {
    let convex: Vec<ConvexPolygon> = polygons
        .iter()
        .map(|p| ConvexPolygon::new(p.iter().copied()).expect("valid"))
        .collect();
    let mut out = Vec::new();
    for i in 0..convex.len() {
        for j in i + 1..convex.len() {
            if Linear.intersects(&convex[i], &convex[j]) {
                out.push([i, j]);
            }
        }
    }
    out
}

#[test]
fn settings_out_of_bounds_are_refused_with_the_field_named() {
    let ok = Settings::default();
    assert!(ok.validate().is_ok());
    for (bad, word) in [
        (Settings { polygons: 0, ..ok }, "polygons"),
        (Settings { polygons: 1001, ..ok }, "polygons"),
        (Settings { vertices: 2, ..ok }, "vertices"),
        (
            Settings {
                vertices: 65_537,
                ..ok
            },
            "vertices",
        ),
        (
            Settings {
                polygons: 100,
                vertices: 65_536,
                ..ok
            },
            "in all",
        ),
        (Settings { speed: -1.0, ..ok }, "speed"),
        (
            Settings {
                speed: f64::NAN,
                ..ok
            },
            "speed",
        ),
    ] {
        let e = bad.validate().expect_err("out of bounds");
        assert!(e.contains(word), "{e}");
    }
}

/// Frames of the default scene, under every strategy and both precisions: the
/// store's world coordinates stay the shapes' images under the poses, and the pairs the
/// frame reports are the exact reference's pairs on those coordinates.
#[test]
fn frames_keep_exact_positions_and_report_the_reference_pairs() {
    for strategy in Strategy::ALL {
        for precision in Precision::ALL {
            let settings = Settings {
                polygons: 24,
                vertices: 7,
                seed: 3,
                strategy,
                precision,
                speed: 3.0,
                ..Settings::default()
            };
            let mut sim = Simulation::new(settings, 1).expect("valid settings");
            let (_, base) = sim.base_vertices();
            let mut collided = 0;
            for _ in 0..120 {
                let f = sim.frame(true);
                let now = sim.current_vertices();
                if precision == Precision::Exact {
                    assert_eq!(f.pairs, reference_pairs(&now), "{strategy:?} frame {}", f.frame);
                }
                assert_eq!(f.poses.len(), 4 * sim.len());
                collided += f.pairs.len();
            }
            sim.debug_validate(&base).expect("world = shape under pose");
            assert!(collided > 0, "the scene collides");
        }
    }
}

#[test]
fn the_default_scene_collides_within_a_second() {
    let mut sim = Simulation::new(Settings::default(), 1).expect("valid");
    let first = (0..60).find(|_| !sim.frame(true).pairs.is_empty());
    assert!(first.is_some(), "no collision in 60 frames");
}

/// How far each shape reaches from its pivot (its origin).
fn reaches(sim: &Simulation) -> Vec<f64> {
    let (sizes, base) = sim.base_vertices();
    let mut at = 0;
    sizes
        .iter()
        .map(|&n| {
            let r = (at..at + n)
                .map(|k| base[2 * k].hypot(base[2 * k + 1]))
                .fold(0.0, f64::max);
            at += n;
            r
        })
        .collect()
}

#[test]
fn polygons_stay_in_the_box() {
    let mut sim = Simulation::new(
        Settings {
            polygons: 10,
            speed: MAX_SPEED,
            ..Settings::default()
        },
        1,
    )
    .expect("valid");
    for _ in 0..2000 {
        sim.frame(true);
    }
    // Walls bounce the boxes; a turn can carry a polygon past a wall by its reach.
    for (poly, r) in sim.current_vertices().into_iter().zip(reaches(&sim)) {
        let m = MAX_STEP + r;
        for p in poly {
            assert!((-m..=WORLD[0] + m).contains(&p.x), "{p:?}");
            assert!((-m..=WORLD[1] + m).contains(&p.y), "{p:?}");
        }
    }
    for body in &sim.bodies {
        let [x, y] = body.position;
        assert!(
            (-MAX_STEP..=WORLD[0] + MAX_STEP).contains(&x) && (-MAX_STEP..=WORLD[1] + MAX_STEP).contains(&y)
        );
    }
}

/// The bodies turn: every world polygon's orientation changes with the frames, the store
/// holds each body's pose (no drift: the world points are the shapes' images), and
/// collisions change turn rates.
#[test]
fn bodies_turn_and_collisions_change_their_turn_rates() {
    let mut sim = Simulation::new(Settings::default(), 1).expect("valid");
    let (_, base) = sim.base_vertices();
    let start = sim.turning();
    assert!(start.iter().all(|&(a, w)| a == 0.0 && w.abs() <= BASE_OMEGA));
    let edge = |sim: &Simulation| -> Vec<f64> {
        sim.current_vertices()
            .iter()
            .map(|p| (p[1].y - p[0].y).atan2(p[1].x - p[0].x))
            .collect()
    };
    let before = edge(&sim);
    let mut collided = 0;
    for _ in 0..600 {
        collided += sim.frame(true).pairs.len();
    }
    assert!(collided > 0);
    let after = edge(&sim);
    let now = sim.turning();
    for (i, ((b, a), &(angle, omega))) in before.iter().zip(&after).zip(&now).enumerate() {
        // Edge 0's direction turned by the body's angle (up to rounding), modulo 2π.
        let turned = (a - b - angle + 3.0 * PI).rem_euclid(TAU) - PI;
        assert!(
            turned.abs() < 1e-6,
            "polygon {i}: edge turned by {} but the angle is {angle}",
            a - b
        );
        assert!(omega.abs() <= MAX_OMEGA, "polygon {i}: {omega}");
    }
    assert!(
        now.iter().zip(&start).filter(|((_, w), (_, w0))| w != w0).count() >= 4,
        "collisions change turn rates"
    );
    assert!(
        now.iter().filter(|(a, _)| a.abs() > 0.1).count() >= sim.len() / 2,
        "the bodies turn"
    );
    sim.debug_validate(&base).expect("world = shape under pose");
}

/// Thousands of frames with collisions, bounces and clamps: the kinetic energy never
/// grows beyond its start (up to rounding), every state stays finite.
#[test]
fn energy_never_grows_over_thousands_of_frames() {
    for seed in [1, 2, 3] {
        let mut sim = Simulation::new(
            Settings {
                polygons: 24,
                vertices: 7,
                seed,
                speed: 3.0,
                ..Settings::default()
            },
            1,
        )
        .expect("valid");
        let e0 = sim.energy();
        assert!(e0 > 0.0);
        let (mut collided, mut least) = (0, e0);
        for frame in 0..5000 {
            collided += sim.frame(true).pairs.len();
            let e = sim.energy();
            assert!(
                e.is_finite() && e <= e0 * (1.0 + 1e-9),
                "seed {seed} frame {frame}: {e0} → {e}"
            );
            least = least.min(e);
        }
        assert!(
            collided > 100,
            "seed {seed}: only {collided} colliding pair-frames"
        );
        // Stable, not dying out: clamps take some energy, never most of it.
        assert!(least > 0.05 * e0, "seed {seed}: energy fell from {e0} to {least}");
        for body in &sim.bodies {
            assert!(body.velocity.iter().all(|v| v.is_finite()) && body.omega.is_finite());
        }
    }
}

/// A drag while the polygon spins: the page sends a world point, the vertex lands there
/// (within rounding), then turns with its polygon; a refused edit changes nothing.
#[test]
fn edits_while_spinning_land_under_the_pointer_and_refusals_change_nothing() {
    let mut sim = Simulation::new(
        Settings {
            polygons: 4,
            vertices: 8,
            ..Settings::default()
        },
        1,
    )
    .expect("valid");
    for _ in 0..40 {
        sim.frame(true);
    }
    assert!(sim.bodies[0].angle.abs() > 0.01, "polygon 0 has turned");
    let now = sim.current_vertices();
    let c = now[0]
        .iter()
        .fold((0.0, 0.0), |s, p| (s.0 + p.x / 8.0, s.1 + p.y / 8.0));
    let v = now[0][0];
    let to = [v.x + 0.1 * (v.x - c.0), v.y + 0.1 * (v.y - c.1)];
    let e = sim.move_vertex(0, 0, to).expect("valid move");
    let w = sim.current_vertices()[0][0];
    assert!(
        (w.x - to[0]).hypot(w.y - to[1]) < 1e-9,
        "{w:?} is not under {to:?}"
    );
    let (_, base) = sim.base_vertices();
    assert_eq!(
        e.point,
        Some([base[0], base[1]]),
        "the edit carries the shape point"
    );
    sim.debug_validate(&base).expect("world = shape under pose");
    // Refused: into the centre. Shape, pose and world points unchanged.
    let (pose, world) = (sim.bodies[0].pose, sim.current_vertices());
    match sim.move_vertex(0, 0, [c.0, c.1]) {
        Err(EditFailure::Refused(r)) => assert!(r.contains("non-convex"), "{r}"),
        other => panic!("expected a refusal, got {other:?}"),
    }
    match sim.insert_vertex(0, 3, [c.0, c.1]) {
        Err(EditFailure::Refused(_)) => {}
        other => panic!("an insertion inside is refused, got {other:?}"),
    }
    assert_eq!(sim.base_vertices().1, base);
    assert_eq!((sim.bodies[0].pose, sim.current_vertices()), (pose, world));
    // The moved vertex travels and turns with its polygon.
    for _ in 0..40 {
        sim.frame(true);
    }
    sim.debug_validate(&base).expect("world = shape under pose");
    let later = sim.current_vertices()[0][0];
    assert_ne!(later, w);
}

#[test]
fn edits_go_through_the_store_and_keep_positions_exact() {
    let settings = Settings {
        polygons: 4,
        vertices: 8,
        ..Settings::default()
    };
    let mut sim = Simulation::new(settings, 1).expect("valid");
    for _ in 0..10 {
        sim.frame(true);
    }
    let (_, mut base) = sim.base_vertices();
    let now = sim.current_vertices();
    // Pull vertex 0 of polygon 0 outwards a little, away from the centre.
    let c = now[0]
        .iter()
        .fold((0.0, 0.0), |s, p| (s.0 + p.x / 8.0, s.1 + p.y / 8.0));
    let v = now[0][0];
    let to = [v.x + 0.1 * (v.x - c.0), v.y + 0.1 * (v.y - c.1)];
    let e = sim.move_vertex(0, 0, to).expect("valid move");
    let p = e.point.expect("a point");
    base[0] = p[0];
    base[1] = p[1];
    sim.debug_validate(&base).expect("world = shape under pose");
    // Into the centre: refused with the store's reason.
    match sim.move_vertex(0, 0, [c.0, c.1]) {
        Err(EditFailure::Refused(r)) => assert!(r.contains("non-convex"), "{r}"),
        other => panic!("expected a refusal, got {other:?}"),
    }
    // Remove down to three, then refused.
    for w in 3..8 {
        sim.remove_vertex(0, w).expect("removal above three vertices");
    }
    assert!(matches!(sim.remove_vertex(0, 0), Err(EditFailure::Refused(_))));
    assert!(matches!(sim.remove_vertex(0, 5), Err(EditFailure::Invalid(m)) if m.contains("was removed")));
    assert!(matches!(sim.remove_vertex(0, 99), Err(EditFailure::Invalid(m)) if m.contains("no vertex 99")));
    assert!(matches!(sim.remove_vertex(9, 0), Err(EditFailure::Invalid(m)) if m.contains("no polygon 9")));
    assert!(
        matches!(sim.move_vertex(1, 0, [1e9, 0.0]), Err(EditFailure::Invalid(m)) if m.contains("outside"))
    );
}

/// Inserting and removing one vertex over and over uses up the polygon's ids (they
/// are never reused); then insertions are refused with a message, removals go on.
#[test]
fn vertex_ids_are_bounded() {
    let mut sim = Simulation::new(
        Settings {
            polygons: 1,
            ..Settings::default()
        },
        1,
    )
    .expect("valid");
    let poly = &sim.current_vertices()[0];
    let (a, b) = (poly[0], poly[1]);
    let (ex, ey) = (b.x - a.x, b.y - a.y);
    // Just outside the middle of edge 0 → 1 (outward is to the right of a → b).
    let out = [0.5 * (a.x + b.x) + 0.01 * ey, 0.5 * (a.y + b.y) - 0.01 * ex];
    let first = sim.settings().vertices as u32;
    for k in first..MAX_VERTEX_IDS as u32 {
        let e = sim.insert_vertex(0, 0, out).expect("valid insertion");
        assert_eq!(e.vertex, k);
        sim.remove_vertex(0, k).expect("removal");
    }
    match sim.insert_vertex(0, 0, out) {
        Err(EditFailure::Invalid(m)) => assert!(m.contains("used all its"), "{m}"),
        other => panic!("expected the id limit, got {other:?}"),
    }
    sim.remove_vertex(0, 5).expect("removals still work");
}

#[test]
fn switching_precision_keeps_polygons_handles_and_poses() {
    let mut sim = Simulation::new(Settings::default(), 1).expect("valid");
    for _ in 0..5 {
        sim.frame(true);
    }
    let before = sim.current_vertices();
    let s = sim.settings();
    sim.adjust(Strategy::Sampled, Precision::Fast, 2.0, true)
        .expect("valid");
    assert_eq!(sim.current_vertices(), before);
    assert_eq!(sim.settings().precision, Precision::Fast);
    let f = sim.frame(false);
    assert_eq!(f.totals.conversions, 0, "the sampled strategy converts nothing");
    sim.remove_vertex(0, 1)
        .expect("the old wire ids still name vertices");
    sim.adjust(s.strategy, Precision::Exact, 1.0, false)
        .expect("valid");
    assert!(sim.adjust(s.strategy, Precision::Exact, 9.0, false).is_err());
}

/// Insertions and removals without end on one polygon: the wire-id map holds the live
/// vertices only, and its memory stays within a small factor of the most vertices the
/// polygon had at once, however many ids were handed out.
#[test]
fn vertex_id_memory_is_bounded_by_the_live_polygon() {
    let mut sim = Simulation::new(
        Settings {
            polygons: 1,
            ..Settings::default()
        },
        1,
    )
    .expect("valid");
    let n = sim.settings().vertices;
    let poly = &sim.current_vertices()[0];
    let (a, b) = (poly[0], poly[1]);
    let (ex, ey) = (b.x - a.x, b.y - a.y);
    let out = [0.5 * (a.x + b.x) + 0.01 * ey, 0.5 * (a.y + b.y) - 0.01 * ex];
    let cycles = 200_000u32;
    let mut most = 0;
    for k in 0..cycles {
        let e = sim.insert_vertex(0, 0, out).expect("valid insertion");
        assert_eq!(e.vertex, n as u32 + k, "ids are never reused");
        assert_eq!(sim.bodies[0].ids.len(), n + 1);
        most = most.max(sim.bodies[0].ids.capacity());
        sim.remove_vertex(0, e.vertex).expect("removal");
        assert_eq!(sim.bodies[0].ids.len(), n);
    }
    assert!(
        most <= 4 * (n + 1),
        "{cycles} cycles on {} live vertices: the id map grew to {most} entries",
        n + 1
    );
    let (_, base) = sim.base_vertices();
    sim.debug_validate(&base).expect("consistent");
}

/// A scene of exactly [`MAX_TOTAL_VERTICES`] vertices: no insertion is accepted, in any
/// polygon, until a removal makes room; then exactly one.
#[test]
fn insertions_are_refused_at_the_total_vertex_bound() {
    let settings = Settings {
        polygons: 64,
        vertices: MAX_TOTAL_VERTICES / 64,
        ..Settings::default()
    };
    assert!(
        settings.vertices < MAX_VERTICES,
        "the per-polygon bound is not the one hit"
    );
    let mut sim = Simulation::new(settings, 1).expect("valid: exactly the bound");
    let now = sim.current_vertices();
    let total: usize = now.iter().map(Vec::len).sum();
    assert_eq!(total, MAX_TOTAL_VERTICES);
    // Just outside the middle of edge 4 → 5, by a millionth of the edge: the turn
    // there is far smaller than the polygon's turn per vertex, so the store would
    // accept it; only the bound refuses it.
    let bump = |i: usize| {
        let (a, b) = (now[i][4], now[i][5]);
        let (ex, ey) = (b.x - a.x, b.y - a.y);
        [0.5 * (a.x + b.x) + 1e-6 * ey, 0.5 * (a.y + b.y) - 1e-6 * ex]
    };
    for i in [0, 17, 63] {
        match sim.insert_vertex(i, 4, bump(i)) {
            Err(EditFailure::Invalid(m)) => assert!(m.contains("in all"), "{m}"),
            other => panic!("polygon {i}: expected the bound in all, got {other:?}"),
        }
    }
    sim.remove_vertex(0, 5).expect("removal");
    sim.insert_vertex(17, 4, bump(17)).expect("room for one");
    match sim.insert_vertex(63, 4, bump(63)) {
        Err(EditFailure::Invalid(m)) => assert!(m.contains("in all"), "{m}"),
        other => panic!("expected the bound in all, got {other:?}"),
    }
    let total: usize = sim.current_vertices().iter().map(Vec::len).sum();
    assert_eq!(total, MAX_TOTAL_VERTICES);
}

/// Numbers in messages are printed shortest round-trip (`1e308`, not 309 digits).
#[test]
fn messages_print_floats_in_their_shortest_form() {
    let e = Settings {
        speed: 1e308,
        ..Settings::default()
    }
    .validate()
    .expect_err("out of bounds");
    assert!(e.ends_with("not 1e308"), "{e}");
    let mut sim = Simulation::new(Settings::default(), 1).expect("valid");
    match sim.move_vertex(0, 0, [1e308, -2.5e-300]) {
        Err(EditFailure::Invalid(m)) => assert!(m.contains("point (1e308, -2.5e-300)"), "{m}"),
        other => panic!("expected the area error, got {other:?}"),
    }
}
