use super::*;
use polysect::rand::rngs::SmallRng;
use polysect::rand::{Rng, SeedableRng};

const SEED: u64 = 0x6772_6964;

/// Coordinates from every scale, signs and the extremes included.
fn coordinate(rng: &mut SmallRng) -> f64 {
    match rng.random_range(0..6) {
        0 => rng.random_range(-10.0..10.0),
        1 => f64::MAX * rng.random_range(-1.0..1.0),
        2 => [
            f64::MAX,
            -f64::MAX,
            0.0,
            -0.0,
            f64::MIN_POSITIVE,
            -f64::MIN_POSITIVE,
        ][rng.random_range(0..6)],
        3 => rng.random_range(-1.0..1.0) * 10f64.powi(rng.random_range(-300..300)),
        4 => f64::from_bits(
            rng.random::<u64>() & !(0x7FFu64 << 52) | (u64::from(rng.random_range(0..0x7FEu32)) << 52),
        ),
        _ => rng.random_range(-1e6f64..1e6).round(),
    }
}

fn grid(rng: &mut SmallRng) -> Grid {
    let s = match rng.random_range(0..4) {
        0 => rng.random_range(0.01..10.0),
        1 => 10f64.powi(rng.random_range(-300..300)),
        2 => f64::MAX,
        _ => f64::MIN_POSITIVE * rng.random_range(1.0..4.0),
    };
    Grid::new(s, Point::new(coordinate(rng), coordinate(rng))).unwrap()
}

#[test]
fn columns_never_decrease_as_coordinates_grow() {
    let mut rng = SmallRng::seed_from_u64(SEED);
    for _ in 0..20_000 {
        let g = grid(&mut rng);
        let (mut a, mut b) = (coordinate(&mut rng), coordinate(&mut rng));
        if a > b {
            std::mem::swap(&mut a, &mut b);
        }
        assert!(
            g.index(a, g.origin.x) <= g.index(b, g.origin.x),
            "{g:?} {a:e} {b:e}"
        );
        // One ulp apart.
        let up = f64::from_bits(if a >= 0.0 {
            a.to_bits() + 1
        } else {
            a.to_bits() - 1
        });
        if up.is_finite() && a != 0.0 {
            assert!(g.index(a, g.origin.x) <= g.index(up, g.origin.x), "{g:?} {a:e}");
        }
    }
}

#[test]
fn overlapping_boxes_share_exactly_their_reference_cell() {
    let mut rng = SmallRng::seed_from_u64(SEED + 1);
    let mut checked = 0;
    while checked < 5_000 {
        // Small cells against the boxes make blocks large; keep them testable.
        let g = Grid::new(
            rng.random_range(0.05..3.0),
            Point::new(rng.random_range(-5.0..5.0), 0.0),
        )
        .unwrap();
        let boxed = |rng: &mut SmallRng| {
            let (x, y) = (rng.random_range(-5.0..5.0), rng.random_range(-5.0..5.0));
            // Corners sometimes snapped to a coarse lattice so boxes touch exactly.
            let snap = |v: f64| if v.abs() < 2.0 { (v * 4.0).round() / 4.0 } else { v };
            let (w, h) = (rng.random_range(0.0..3.0), rng.random_range(0.0..3.0));
            BoundingBox::new(Point::new(snap(x), snap(y)), Point::new(snap(x + w), snap(y + h)))
        };
        let (a, b) = (boxed(&mut rng), boxed(&mut rng));
        if !a.overlaps(&b) {
            continue;
        }
        checked += 1;
        let ca: Vec<i64> = g.cells(&a).unwrap().ids().collect();
        let cb: Vec<i64> = g.cells(&b).unwrap().ids().collect();
        let shared: Vec<i64> = ca.iter().copied().filter(|c| cb.contains(c)).collect();
        let r = g.reference_cell(&a, &b);
        assert!(shared.contains(&r), "{g:?} {a:?} {b:?}");
        assert_eq!(g.reference_cell(&b, &a), r, "symmetric");
        // Each block lists each cell once, so the pair meets in r exactly once.
        assert_eq!(ca.iter().filter(|&&c| c == r).count(), 1);
    }
}

#[test]
fn chosen_grids_bound_the_cells_of_every_box_even_at_the_extremes() {
    let mut rng = SmallRng::seed_from_u64(SEED + 2);
    for _ in 0..5_000 {
        let mut xs = [coordinate(&mut rng), coordinate(&mut rng)];
        let mut ys = [coordinate(&mut rng), coordinate(&mut rng)];
        xs.sort_by(f64::total_cmp);
        ys.sort_by(f64::total_cmp);
        let extent = BoundingBox::new(Point::new(xs[0], ys[0]), Point::new(xs[1], ys[1]));
        let typical_half_side = coordinate(&mut rng).abs();
        let g = Grid::for_boxes(&BoxStats {
            extent,
            typical_half_side,
        });
        assert!(g.cell_size().is_finite() && g.cell_size() > 0.0, "{g:?}");
        // The whole extent, the largest box the data can have.
        let block = g.cells(&extent).unwrap();
        assert!(block.len() <= (MAX_COLUMNS as u64 + 3).pow(2), "{block:?} {g:?}");
    }
}

#[test]
fn bad_parameters_and_huge_blocks_are_errors() {
    let o = Point::new(0.0, 0.0);
    for s in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(matches!(Grid::new(s, o), Err(GridError::CellSize(_))));
    }
    assert!(matches!(
        Grid::new(1.0, Point::new(f64::NAN, 0.0)),
        Err(GridError::Origin(_))
    ));
    let g = Grid::new(1e-3, o).unwrap();
    let b = BoundingBox::new(o, Point::new(1e3, 1e3));
    let e = g.cells(&b).unwrap_err();
    assert!(matches!(e, GridError::TooManyCells { .. }));
    assert!(e.to_string().contains("use a larger cell size"));
}

#[test]
fn cell_ids_are_distinct_for_distinct_cells() {
    let ids = [
        cell_id(0, 0),
        cell_id(0, -1),
        cell_id(-1, 0),
        cell_id(i32::MAX, i32::MIN),
        cell_id(i32::MIN, i32::MAX),
    ];
    for (i, a) in ids.iter().enumerate() {
        for b in &ids[i + 1..] {
            assert_ne!(a, b);
        }
    }
}
