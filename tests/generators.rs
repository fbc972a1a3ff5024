//! Every generator under hostile parameters: huge, tiny, zero, negative, NaN and
//! infinite values, n = 0, 1, 2, 3 and sizes no machine can hold. Each call must
//! return (an `Ok` whose polygons are valid and finite, or an `Err`), never panic,
//! never allocate for a size it refuses.

use polysect::generate::simple::{
    GenerateError, PointDistribution, SimpleMethod, random_points, random_simple_polygon, space_partition,
    star_order,
};
use polysect::generate::{
    self, Density, Family, MAX_VERTICES, Relation, map_pair, try_ellipse_polygon, try_pair,
    try_regular_polygon,
};
use polysect::{ConvexPolygon, Point};
use rand::SeedableRng;
use rand::rngs::SmallRng;
use std::panic::{AssertUnwindSafe, catch_unwind};

const SEED: u64 = 0x6e_0001;

/// Hostile vertex counts; the last two must be refused before any allocation.
const SIZES: [usize; 7] = [0, 1, 2, 3, 40, MAX_VERTICES + 1, usize::MAX];

/// Hostile reals.
const VALUES: [f64; 16] = [
    0.0,
    -0.0,
    1.0,
    -1.0,
    5e-324,
    -5e-324,
    1e-310,
    1e-300,
    1e300,
    -1e300,
    1.7e308,
    -1.7e308,
    f64::MAX,
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
];

/// Runs `f`, turning a panic into a failure message naming `what`.
fn no_panic<T>(what: &str, failures: &mut Vec<String>, f: impl FnOnce() -> T) -> Option<T> {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(v) => Some(v),
        Err(e) => {
            let msg = e
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| e.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_default();
            failures.push(format!("{what}: panicked: {msg}"));
            None
        }
    }
}

fn check_convex(what: &str, p: &ConvexPolygon, failures: &mut Vec<String>) {
    if let Err(e) = p.debug_validate() {
        failures.push(format!("{what}: invalid polygon: {e}"));
    }
}

fn distributions() -> Vec<PointDistribution> {
    let mut out = Vec::new();
    for &a in &VALUES {
        for &b in &VALUES {
            out.push(PointDistribution::Uniform { min: a, max: b });
            out.push(PointDistribution::Normal { mean: a, sigma: b });
        }
    }
    for size in [0, 1, 2, 3, 7, u32::MAX] {
        out.push(PointDistribution::Grid { size });
    }
    out
}

#[test]
fn simple_polygon_generators_never_panic() {
    let mut failures = Vec::new();
    let mut rng = SmallRng::seed_from_u64(SEED);
    let mut made = 0;
    for dist in distributions() {
        let _ = no_panic(&format!("{dist:?}.sample"), &mut failures, || {
            dist.sample(&mut rng)
        });
        let valid = dist.validate().is_ok();
        for &n in &SIZES {
            let what = format!("random_points({dist:?}, {n})");
            if let Some(r) = no_panic(&what, &mut failures, || random_points(dist, n, &mut rng)) {
                match r {
                    Ok(pts) if pts.iter().any(|p| !p.is_finite()) => {
                        failures.push(format!("{what}: a non-finite point"))
                    }
                    Ok(_) if !valid => failures.push(format!("{what}: accepted parameters validate refuses")),
                    _ => {}
                }
            }
            for &method in SimpleMethod::ALL {
                let what = format!("random_simple_polygon({method}, {dist:?}, {n})");
                let r = no_panic(&what, &mut failures, || {
                    random_simple_polygon(method, dist, n, &mut rng)
                });
                match r {
                    Some(Ok(p)) => {
                        made += 1;
                        if let Err(e) = p.debug_validate() {
                            failures.push(format!("{what}: invalid polygon: {e}"));
                        }
                        if p.vertices().iter().any(|v| !v.is_finite()) {
                            failures.push(format!("{what}: a non-finite vertex"));
                        }
                    }
                    Some(Err(GenerateError::GaveUp { .. })) if n > MAX_VERTICES => {
                        failures.push(format!("{what}: a huge size must be refused as invalid"))
                    }
                    Some(Err(_)) | None => {}
                }
            }
        }
    }
    // The two cases that used to panic, by name.
    for (dist, method) in [
        (
            PointDistribution::Normal {
                mean: 0.0,
                sigma: 1e308,
            },
            SimpleMethod::Star,
        ),
        (
            PointDistribution::Normal {
                mean: 0.0,
                sigma: 1e308,
            },
            SimpleMethod::SpacePartition,
        ),
    ] {
        let r = random_simple_polygon(method, dist, 50, &mut rng);
        assert!(matches!(r, Err(GenerateError::InvalidParameters(_))), "{r:?}");
    }
    for &method in SimpleMethod::ALL {
        let dist = PointDistribution::Uniform {
            min: -1.7e308,
            max: 1.7e308,
        };
        let p = random_simple_polygon(method, dist, 50, &mut rng).expect("a wide range is valid");
        assert_eq!(p.len(), 50);
        assert!(p.vertices().iter().all(|v| v.is_finite()));
    }
    // Point sets built by hand: too few, repeated, not finite, near f64::MAX.
    let big = f64::MAX;
    let sets: Vec<Vec<Point>> = vec![
        vec![],
        vec![Point::new(0.0, 0.0); 2],
        vec![Point::new(0.0, 0.0); 5],
        vec![
            Point::new(0.0, 0.0),
            Point::new(f64::NAN, 1.0),
            Point::new(1.0, 0.0),
        ],
        vec![
            Point::new(0.0, 0.0),
            Point::new(f64::INFINITY, 1.0),
            Point::new(1.0, 0.0),
        ],
        vec![
            Point::new(-big, -big),
            Point::new(big, -big),
            Point::new(big, big),
            Point::new(-big, big),
            Point::new(0.0, 0.0),
            Point::new(big / 2.0, -big / 3.0),
        ],
        (0..20).map(|i| Point::new(i as f64, 0.0)).collect(),
    ];
    for pts in &sets {
        let _ = no_panic(&format!("space_partition({pts:?})"), &mut failures, || {
            space_partition(pts, &mut rng)
        });
        for center in [
            Point::new(0.0, 0.0),
            Point::new(f64::NAN, 0.0),
            Point::new(big, -big),
        ] {
            let _ = no_panic(&format!("star_order({pts:?}, {center:?})"), &mut failures, || {
                star_order(pts, center)
            });
        }
    }
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
    assert!(
        made > 100,
        "only {made} polygons made: the sweep tests too little"
    );
}

#[test]
fn convex_generators_never_panic() {
    let mut failures = Vec::new();
    let mut rng = SmallRng::seed_from_u64(SEED ^ 1);
    let densities: Vec<Density> = [
        vec![],
        vec![1.0],
        vec![0.0, 0.0],
        vec![-1.0, 1.0],
        vec![f64::NAN, 1.0, 2.0],
        vec![f64::INFINITY, 1.0],
        vec![f64::MAX, f64::MAX, f64::MAX],
        vec![5e-324, 0.0],
        vec![-1.0, -2.0, -3.0],
    ]
    .into_iter()
    .map(|weights| Density::PiecewiseLinear { weights })
    .chain([Density::Uniform, Density::random(&mut rng)])
    .collect();
    for density in &densities {
        let what = format!("{density:?}.sample");
        if let Some(x) = no_panic(&what, &mut failures, || density.sample(&mut rng))
            && !(0.0..=1.0).contains(&x)
        {
            failures.push(format!("{what}: {x} outside [0, 1]"));
        }
        for &n in &SIZES {
            for rotate in [false, true] {
                let what = format!("try_ellipse_polygon({n}, {density:?}, {rotate})");
                match no_panic(&what, &mut failures, || {
                    try_ellipse_polygon(&mut rng, n, density, rotate)
                }) {
                    Some(Ok(p)) => check_convex(&what, &p, &mut failures),
                    Some(Err(_)) if n <= MAX_VERTICES => {
                        failures.push(format!("{what}: refused a valid size"))
                    }
                    _ => {}
                }
            }
        }
    }
    for &n in &SIZES {
        for &radius in &VALUES {
            let what = format!("try_regular_polygon({n}, {radius})");
            match no_panic(&what, &mut failures, || try_regular_polygon(n, radius)) {
                Some(Ok(p)) => check_convex(&what, &p, &mut failures),
                Some(Err(_)) if n <= MAX_VERTICES && radius.is_finite() && radius >= 1e-300 => {
                    failures.push(format!("{what}: refused valid parameters"))
                }
                _ => {}
            }
        }
        for &family in Family::ALL {
            for relation in [Relation::Any, Relation::Intersecting, Relation::Disjoint] {
                let what = format!("try_pair({family}, {n}, {relation:?})");
                match no_panic(&what, &mut failures, || try_pair(family, n, relation, &mut rng)) {
                    Some(Ok((p, q))) => {
                        check_convex(&what, &p, &mut failures);
                        check_convex(&what, &q, &mut failures);
                        // map_pair with hostile maps: an Option, never a panic.
                        for &s in &VALUES {
                            let _ = no_panic(&format!("map_pair(×{s})"), &mut failures, || {
                                map_pair(&(p.clone(), q.clone()), |v| Point::new(v.x * s, v.y * s))
                            });
                        }
                    }
                    Some(Err(_)) if n <= MAX_VERTICES => {
                        failures.push(format!("{what}: refused a valid size"))
                    }
                    _ => {}
                }
            }
        }
    }
    // The panicking wrappers agree with the fallible ones on valid input.
    let p = generate::regular_polygon(5, 2.0);
    assert_eq!(Ok(p), try_regular_polygon(5, 2.0));
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// Given semi-axes: what cannot be drawn (zero, NaN, infinite, below
/// `MIN_AXIS`, above `MAX_AXIS`) is an error, everything else a valid polygon, and
/// every call returns within a deadline. Each call runs on its own thread so that a
/// generator that never returns fails the test instead of hanging it.
#[test]
fn ellipse_generators_with_hostile_axes_return_in_bounded_time() {
    use polysect::generate::{
        MAX_AXIS, MAX_AXIS_RATIO, MIN_AXIS, try_ellipse_polygon_axes, try_pair_with_axes,
    };
    use std::sync::mpsc;
    use std::time::Duration;

    let hostile = [
        (0.0, 0.0),
        (f64::NAN, 1.0),
        (f64::INFINITY, 1.0),
        (5e-324, 5e-324),
        (1e-30, 1e-30),
        (1e-100, 1e-100),
        (1.0, 1e-300),
        (-1.0, 1.0),
        (1.0, f64::MAX),
        (1e300, 1.0),
        (1.0, MIN_AXIS / 2.0),
        (MAX_AXIS * 2.0, MAX_AXIS),
        (1.0, 1.0 / MAX_AXIS_RATIO / 2.0),
    ];
    let drawable = [
        (1.0, 0.1),
        (MIN_AXIS, MIN_AXIS),
        (1.0, MIN_AXIS),
        (1e-6, 1e-6),
        (MAX_AXIS, MAX_AXIS),
        (MAX_AXIS, MAX_AXIS / MAX_AXIS_RATIO),
    ];
    let families = [Family::Ellipse, Family::Rotated, Family::NonUniform];
    let relations = [Relation::Any, Relation::Intersecting, Relation::Disjoint];
    let mut failures = Vec::new();
    for (axes, must_draw) in hostile
        .iter()
        .map(|&ab| (ab, false))
        .chain(drawable.iter().map(|&ab| (ab, true)))
    {
        let (tx, rx) = mpsc::channel();
        std::thread::spawn(move || {
            let mut rng = SmallRng::seed_from_u64(SEED);
            let mut out = Vec::new();
            for rotate in [false, true] {
                let r = try_ellipse_polygon_axes(&mut rng, 64, &Density::Uniform, rotate, Some(axes));
                out.push((format!("polygon rotate={rotate}"), r.map(|p| vec![p])));
            }
            for family in families {
                for relation in relations {
                    let r = try_pair_with_axes(family, 64, relation, Some(axes), &mut rng);
                    out.push((format!("pair {family} {relation:?}"), r.map(|(p, q)| vec![p, q])));
                }
            }
            let _ = tx.send(out);
        });
        let Ok(out) = rx.recv_timeout(Duration::from_secs(20)) else {
            failures.push(format!("axes {axes:?}: no answer within 20 s"));
            continue;
        };
        for (what, r) in out {
            match r {
                Ok(polys) if must_draw => {
                    for p in &polys {
                        check_convex(&format!("axes {axes:?} {what}"), p, &mut failures);
                    }
                }
                Ok(_) => failures.push(format!("axes {axes:?} {what}: drew what cannot be drawn")),
                Err(e) if must_draw => failures.push(format!("axes {axes:?} {what}: refused: {e}")),
                Err(_) => {}
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}
