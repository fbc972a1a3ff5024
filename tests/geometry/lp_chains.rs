//! `separate_chains` (the walk for two convex chains) against the LP (`separating_line`)
//! and an exact brute force: random chains of random convex polygons on a coarse grid
//! (many exact touchings) and in floating point, chains touching at a vertex or along
//! an edge and the same moved by ±2^-40 (a gap or an overlap far below the
//! coordinates), one- and two-point chains on a common line, edges on a common
//! separator, and everything scaled by 2^±500 or shifted by 2^40; every start pair and
//! both orientations of each chain.

use crate::hulls::hulls_intersect;
use polysect::kernel::Kernel;
use polysect::lp::{LpWorkspace, Separation, separate_chains, separating_line};
use polysect::polygon::{HullAlgorithm, hull_vertices};
use polysect::{Exact, Fast, Orientation, Point, Sign};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

const SEED: u64 = 0xc4a1;

/// A strictly convex counter-clockwise polygon from random points (grid or float) at
/// `offset`, or `None` when they are collinear.
fn random_polygon(rng: &mut SmallRng, grid: bool, offset: Point) -> Option<Vec<Point>> {
    let n = rng.random_range(3..=9);
    let pts: Vec<Point> = (0..n)
        .map(|_| {
            if grid {
                Point::new(
                    offset.x + rng.random_range(0..=5) as f64,
                    offset.y + rng.random_range(0..=5) as f64,
                )
            } else {
                Point::new(
                    offset.x + rng.random::<f64>() * 5.0,
                    offset.y + rng.random::<f64>() * 5.0,
                )
            }
        })
        .collect();
    hull_vertices(&pts, HullAlgorithm::default()).ok()
}

/// A random contiguous run (cyclically) of `poly`'s vertices, reversed half the time:
/// the kind of chain CLM walks.
fn random_chain(rng: &mut SmallRng, poly: &[Point]) -> Vec<Point> {
    let m = poly.len();
    let (s, len) = (rng.random_range(0..m), rng.random_range(1..=m));
    let mut c: Vec<Point> = (0..len).map(|t| poly[(s + t) % m]).collect();
    if rng.random_bool(0.5) {
        c.reverse();
    }
    c
}

/// Runs the walk from every start pair (both argument orders) and checks it against the
/// brute force and the LP: the same verdict, and when separated, a correct bitangent on
/// the LP's line. Returns whether the hulls intersect.
fn check(a: &[Point], b: &[Point], rng: &mut SmallRng, ws: &mut LpWorkspace, undecided: &mut usize) -> bool {
    let truth = hulls_intersect(a, b);
    for (a, b) in [(a, b), (b, a)] {
        let lp = separating_line(Exact, a, b, rng, ws).unwrap();
        assert_eq!(
            matches!(lp, Separation::Intersecting),
            truth,
            "LP\nA = {a:?}\nB = {b:?}"
        );
        for i in 0..a.len() {
            for j in 0..b.len() {
                let mut work = 0;
                let Some(got) = separate_chains(Exact, a, b, [i, j], &mut work) else {
                    assert!(
                        truth,
                        "no answer on disjoint hulls\nA = {a:?}\nB = {b:?}\nstart {i}, {j}"
                    );
                    *undecided += 1;
                    continue;
                };
                let ctx = || format!("\nA = {a:?}\nB = {b:?}\nstart {i}, {j}\ngot {got:?}\nLP {lp:?}");
                assert_eq!(matches!(got, Separation::Intersecting), truth, "verdict{}", ctx());
                assert!(
                    work <= 4 * (a.len() + b.len()) as u64 + 20,
                    "work {work}{}",
                    ctx()
                );
                let (Separation::Separated(t), Separation::Separated(l)) = (got, lp) else {
                    continue;
                };
                let k = Exact;
                assert_eq!((a[t.a], b[t.b]), (t.start, t.end), "{}", ctx());
                assert!(
                    a.iter().all(|&x| k.orient(t.start, t.end, x) != Orientation::Ccw),
                    "A left{}",
                    ctx()
                );
                assert!(
                    b.iter().all(|&x| k.orient(t.start, t.end, x) != Orientation::Cw),
                    "B right{}",
                    ctx()
                );
                // The LP's line: the same line, the same direction.
                assert_eq!(
                    k.orient(l.start, l.end, t.start),
                    Orientation::Collinear,
                    "line{}",
                    ctx()
                );
                assert_eq!(
                    k.orient(l.start, l.end, t.end),
                    Orientation::Collinear,
                    "line{}",
                    ctx()
                );
                assert_eq!(
                    k.dot(l.start, l.end, t.start, t.end),
                    Sign::Positive,
                    "direction{}",
                    ctx()
                );
                // A kernel that is not exact answers only with a checked separation.
                if let Some(Separation::Separated(f)) = separate_chains(Fast, a, b, [i, j], &mut work) {
                    assert!(
                        a.iter()
                            .all(|&x| Fast.orient(f.start, f.end, x) != Orientation::Ccw)
                    );
                    assert!(
                        b.iter()
                            .all(|&x| Fast.orient(f.start, f.end, x) != Orientation::Cw)
                    );
                }
            }
        }
    }
    truth
}

#[test]
fn random_chains_agree_with_lp_and_brute_force() {
    let mut rng = SmallRng::seed_from_u64(SEED);
    let mut ws = LpWorkspace::new();
    let (mut cases, mut meets, mut undecided) = (0, 0, 0);
    while cases < 3000 {
        let grid = rng.random_bool(0.7);
        let off = Point::new(rng.random_range(-4..=4) as f64, rng.random_range(-4..=4) as f64);
        let (Some(p), Some(q)) = (
            random_polygon(&mut rng, grid, Point::new(0.0, 0.0)),
            random_polygon(&mut rng, grid, off),
        ) else {
            continue;
        };
        let (a, b) = (random_chain(&mut rng, &p), random_chain(&mut rng, &q));
        meets += usize::from(check(&a, &b, &mut rng, &mut ws, &mut undecided));
        cases += 1;
    }
    assert!(
        meets > cases / 10 && meets < cases * 9 / 10,
        "{meets} of {cases} intersect"
    );
    eprintln!("{meets} of {cases} intersect; {undecided} walks left to the LP");
    // Intersecting chains may be left to the LP, but seldom.
    assert!(undecided * 10 < meets, "{undecided} undecided walks");
}

/// P's point reflection through one of its vertices (touching there) or through the
/// midpoint of one of its edges (touching along it), then moved by `shift`.
fn reflected(p: &[Point], through_edge: bool, at: usize, shift: Point) -> Vec<Point> {
    let (u, v) = (p[at], p[(at + 1) % p.len()]);
    let c = if through_edge {
        Point::new(u.x + v.x, u.y + v.y)
    } else {
        Point::new(2.0 * u.x, 2.0 * u.y)
    };
    p.iter()
        .map(|x| Point::new(c.x - x.x + shift.x, c.y - x.y + shift.y))
        .collect()
}

#[test]
fn touching_and_one_tiny_step_apart() {
    let mut rng = SmallRng::seed_from_u64(SEED + 1);
    let mut ws = LpWorkspace::new();
    let tiny = (-40f64).exp2();
    let (mut cases, mut meets, mut undecided) = (0, 0, 0);
    while cases < 1500 {
        let Some(p) = random_polygon(&mut rng, true, Point::new(0.0, 0.0)) else {
            continue;
        };
        let at = rng.random_range(0..p.len());
        let through_edge = rng.random_bool(0.5);
        let steps = [-tiny, 0.0, tiny];
        let shift = Point::new(steps[rng.random_range(0..3)], steps[rng.random_range(0..3)]);
        let q = reflected(&p, through_edge, at, shift);
        // Chains that contain the touching vertex or edge, and random ones.
        let (a, b) = if rng.random_bool(0.5) {
            (random_chain(&mut rng, &p), random_chain(&mut rng, &q))
        } else {
            let m = p.len();
            let around = |poly: &[Point], rng: &mut SmallRng| -> Vec<Point> {
                let len = rng.random_range(2..=m);
                let s = (at + m - rng.random_range(0..len.min(m))) % m;
                (0..len).map(|t| poly[(s + t) % m]).collect()
            };
            (around(&p, &mut rng), around(&q, &mut rng))
        };
        meets += usize::from(check(&a, &b, &mut rng, &mut ws, &mut undecided));
        cases += 1;
    }
    assert!(
        meets > cases / 5 && meets < cases * 4 / 5,
        "{meets} of {cases} intersect"
    );
}

#[test]
fn collinear_chains_and_edges_on_the_separator() {
    let mut rng = SmallRng::seed_from_u64(SEED + 2);
    let mut ws = LpWorkspace::new();
    let mut undecided = 0;
    let dirs = [(1.0, 0.0), (0.0, 1.0), (1.0, 1.0), (2.0, -1.0), (-1.0, 3.0)];
    for &(dx, dy) in &dirs {
        let on = |t: f64| Point::new(t * dx, t * dy);
        let off = |t: f64, s: f64| Point::new(t * dx - s * dy, t * dy + s * dx);
        for a0 in -2..=2 {
            for a1 in a0..=3 {
                for b0 in -1..=4 {
                    for b1 in b0..=5 {
                        let (a0, a1, b0, b1) = (a0 as f64, a1 as f64, b0 as f64, b1 as f64);
                        // Points and segments on one line.
                        let a: Vec<Point> = if a0 == a1 {
                            vec![on(a0)]
                        } else {
                            vec![on(a0), on(a1)]
                        };
                        let b: Vec<Point> = if b0 == b1 {
                            vec![on(b0)]
                        } else {
                            vec![on(b1), on(b0)]
                        };
                        check(&a, &b, &mut rng, &mut ws, &mut undecided);
                        // Edges on the line, the polygons on either side of it.
                        if a0 < a1 && b0 < b1 {
                            let a = vec![on(a0), off(a0 - 1.0, -2.0), off(a1, -1.0), on(a1)];
                            let b = vec![on(b1), off(b1 + 1.0, 2.0), off(b0, 1.0), on(b0)];
                            check(&a, &b, &mut rng, &mut ws, &mut undecided);
                        }
                    }
                }
            }
        }
    }
}

#[test]
fn extreme_scales_keep_the_exact_verdict() {
    let mut rng = SmallRng::seed_from_u64(SEED + 3);
    let mut ws = LpWorkspace::new();
    let mut undecided = 0;
    let mut cases = 0;
    while cases < 600 {
        let off = Point::new(rng.random_range(-5..=5) as f64, rng.random_range(-5..=5) as f64);
        let (Some(p), Some(q)) = (
            random_polygon(&mut rng, true, Point::new(0.0, 0.0)),
            random_polygon(&mut rng, true, off),
        ) else {
            continue;
        };
        let (a, b) = (random_chain(&mut rng, &p), random_chain(&mut rng, &q));
        let truth = hulls_intersect(&a, &b);
        let transforms: [(f64, f64); 4] = [
            (500f64.exp2(), 0.0),
            ((-500f64).exp2(), 0.0),
            (1.0, 40f64.exp2()),
            (1.0, -(52f64.exp2())),
        ];
        for (scale, shift) in transforms {
            let map = |c: &[Point]| -> Vec<Point> {
                c.iter()
                    .map(|x| Point::new(x.x * scale + shift, x.y * scale - shift))
                    .collect()
            };
            let (a, b) = (map(&a), map(&b));
            assert_eq!(
                check(&a, &b, &mut rng, &mut ws, &mut undecided),
                truth,
                "scale {scale}, shift {shift}"
            );
        }
        cases += 1;
    }
}
