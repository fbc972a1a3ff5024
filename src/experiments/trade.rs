//! The speed–accuracy trade: every algorithm under both kernels on families of inputs
//! chosen to break floating-point predicates, counting wrong answers against
//! [`Linear`](crate::intersect::Linear) under the exact kernel and timing each query.
//!
//! | case | inputs |
//! |---|---|
//! | `random` | rotated random ellipses ([`Family::Rotated`]), any relation |
//! | `touching` | the lattice families (shared vertex, vertex on edge, shared edge, overlapping edges), touching and one lattice step apart |
//! | `one-ulp` | [`Family::OneUlpGap`]: touching, or one ulp apart, at offsets up to 2^52 |
//! | `scaled-2^1000`, `scaled-2^-1000` | lattice pairs multiplied by 2^±1000 (exact: powers of two) |
//! | `offset-2^40..52` | lattice pairs translated by 2^40, 2^44, 2^48 or 2^52 (exact on integers) |
//! | `needles` | [`needle_pair`]: needles of aspect ratio 10^12, touching or nearly (one in four: a needle's tip rounded onto an edge of the other next to its centre) |
//! | `circle` | a regular 2^k-gon of radius 1 against a small triangle whose tip lies a few ulps inside or outside the boundary |
//!
//! A query that panics (a fast-kernel answer can break an algorithm's invariants)
//! counts as wrong and is not timed; the `panics` column reports them. The
//! `exact_over_fast` column is the algorithm's exact median time over its fast one on
//! that case.
//!
//! # The exact kernel's overhead
//! A second table (`trade_ratio.csv`) measures what exactness costs on ordinary input:
//! random rotated ellipses ([`Family::Rotated`]) at the sizes
//! [`Config::ratio_log2_sizes`], [`Config::pairs_for`] pairs each (half of them, at
//! least two, disjoint, and as many intersecting; each relation a row of its own).
//! For each pair and
//! algorithm the fast and the exact query are timed in turn, three times each (fast,
//! exact, fast, exact, …, so a drift of the machine's speed hits both), each a timed
//! loop of [`Config::min_time`] / 2; the pair's ratio is the median exact time over
//! the median fast time, and the table reports the median over the pairs.

use super::measure::{median, time_per_query};
use super::plot::{Chart, Series};
use super::scaling::{draw, short_ns};
use super::{Config, Csv, PreparedPair, Report, ns};
use crate::generate::{self, Family, Relation, map_pair, regular_polygon};
use crate::intersect::Algorithm;
use crate::kernel::{Point, Precision};
use crate::polygon::{ConvexPolygon, convex_hull};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use std::f64::consts::{PI, TAU};
use std::io;
use std::panic::{AssertUnwindSafe, catch_unwind};

/// Aspect ratio (length / width) of [`needle_pair`]'s needles.
pub const NEEDLE_ASPECT: f64 = 1e12;

/// A needle: the hull of `n` random points on an ellipse with semi-axes 1 and
/// 1/[`NEEDLE_ASPECT`], rotated by `angle`, centred at `c`.
fn needle<R: Rng + ?Sized>(rng: &mut R, n: usize, angle: f64, c: Point) -> ConvexPolygon {
    let (cos, sin) = (angle.cos(), angle.sin());
    loop {
        let pts: Vec<Point> = (0..n.max(3))
            .map(|_| {
                let t: f64 = rng.random_range(0.0..TAU);
                let (x, y) = (t.cos(), t.sin() / NEEDLE_ASPECT);
                Point::new(c.x + cos * x - sin * y, c.y + sin * x + cos * y)
            })
            .collect();
        if let Ok(h) = convex_hull(&pts) {
            return h;
        }
    }
}

/// Two needles of aspect ratio 10^12 (length 2, width 2·10^-12) with about `n`
/// vertices each, touching or nearly touching: side by side at a distance within 0.01%
/// of the sum of their half-widths, crossing at an angle of 10^-9, tip to tip within
/// 10^-12, or a needle triangle whose tip is a rounded point of the other needle's
/// edge next to its centre (within an ulp of that edge's line). The exact answer
/// varies; compute it with an exact test.
pub fn needle_pair<R: Rng + ?Sized>(rng: &mut R, n: usize) -> (ConvexPolygon, ConvexPolygon) {
    let theta: f64 = rng.random_range(0.0..PI);
    let p = needle(rng, n, theta, Point::new(0.0, 0.0));
    let (u, normal) = (
        Point::new(theta.cos(), theta.sin()),
        Point::new(-theta.sin(), theta.cos()),
    );
    let w = 1.0 / NEEDLE_ASPECT;
    let q = match rng.random_range(0..4) {
        3 => {
            // A needle whose tip is a rounded point of an edge of P that passes next to
            // the origin (P's centre): the tip's coordinates are tiny, so rounding puts
            // it far closer to the edge's line than the error of an f64 determinant
            // over the edge's long coordinates.
            let k = p.len();
            let dot = |v: Point| v.x * u.x + v.y * u.y;
            let crossing: Vec<usize> = (0..k)
                .filter(|&i| (dot(p.vertex(i)) <= 0.0) != (dot(p.vertex(i + 1)) <= 0.0))
                .collect();
            let i = if crossing.is_empty() {
                0
            } else {
                crossing[rng.random_range(0..crossing.len())]
            };
            let (a, b) = (p.vertex(i), p.vertex(i + 1));
            let t0 = -dot(a) / (dot(b) - dot(a));
            let t = (t0 + rng.random_range(-0.05..0.05)).clamp(0.01, 0.99);
            let tip = Point::new(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y));
            let out = (b.y - a.y).atan2(b.x - a.x) - PI / 2.0 + rng.random_range(-1.4..1.4);
            let half = 0.5 / NEEDLE_ASPECT;
            let end = |s: f64| Point::new(tip.x + (out + s).cos(), tip.y + (out + s).sin());
            return (
                p,
                ConvexPolygon::new([tip, end(-half), end(half)]).expect("a thin triangle"),
            );
        }
        0 => {
            let d = 2.0 * w * (1.0 + rng.random_range(-1e-4..1e-4));
            let along = rng.random_range(-0.5..0.5);
            let c = Point::new(along * u.x + d * normal.x, along * u.y + d * normal.y);
            let tilt = rng.random_range(-1e-13..1e-13);
            needle(rng, n, theta + tilt, c)
        }
        1 => {
            let d = rng.random_range(-10.0 * w..10.0 * w);
            needle(rng, n, theta + 1e-9, Point::new(d * normal.x, d * normal.y))
        }
        _ => {
            let d = 2.0 + rng.random_range(-w..w);
            needle(rng, n, theta, Point::new(d * u.x, d * u.y))
        }
    };
    (p, q)
}

/// A small triangle (size 10^-6) outside `circle` whose tip lies within a few ulps of
/// the boundary: near a vertex or near an edge's midpoint.
fn near_boundary<R: Rng + ?Sized>(rng: &mut R, circle: &ConvexPolygon) -> ConvexPolygon {
    let i = rng.random_range(0..circle.len());
    let (a, b) = (circle.vertex(i), circle.vertex(i + 1));
    let base = if rng.random_bool(0.5) {
        a
    } else {
        Point::new((a.x + b.x) / 2.0, (a.y + b.y) / 2.0)
    };
    let r = base.x.hypot(base.y);
    let u = Point::new(base.x / r, base.y / r);
    let delta = rng.random_range(-2.0..2.0) * f64::EPSILON;
    let tip = Point::new(base.x * (1.0 + delta), base.y * (1.0 + delta));
    let s = 1e-6;
    let pts = [
        tip,
        Point::new(tip.x + s * (u.x - u.y), tip.y + s * (u.y + u.x)),
        Point::new(tip.x + s * (u.x + u.y), tip.y + s * (u.y - u.x)),
    ];
    ConvexPolygon::new(pts).expect("a non-degenerate triangle")
}

/// The input cases, in table order.
const CASES: [&str; 8] = [
    "random",
    "touching",
    "one-ulp",
    "scaled-2^1000",
    "scaled-2^-1000",
    "offset-2^40..52",
    "needles",
    "circle",
];

fn lattice(rng: &mut SmallRng, n: usize, i: usize) -> (ConvexPolygon, ConvexPolygon) {
    let fams = [
        Family::SharedVertex,
        Family::VertexOnEdge,
        Family::SharedEdge,
        Family::OverlappingEdges,
    ];
    let relation = if i.is_multiple_of(2) {
        Relation::Intersecting
    } else {
        Relation::Disjoint
    };
    generate::pair(fams[(i / 2) % fams.len()], n, relation, rng)
}

/// The pairs of one case.
fn case_pairs(config: &Config, case: &str, rng: &mut SmallRng) -> Vec<(ConvexPolygon, ConvexPolygon)> {
    let n = config.trade_n;
    // Needles are cheap and only some of them defeat the fast kernel: four times as many.
    let count = if case == "needles" {
        4 * config.trade_pairs
    } else {
        config.trade_pairs
    };
    let mut out = Vec::new();
    let mut i = 0;
    while out.len() < count && i < 4 * count + 8 {
        let pair = match case {
            "random" => Some(generate::pair(Family::Rotated, n, Relation::Any, rng)),
            "touching" => Some(lattice(rng, n, i)),
            "one-ulp" => {
                let relation = if i.is_multiple_of(2) {
                    Relation::Intersecting
                } else {
                    Relation::Disjoint
                };
                Some(generate::pair(Family::OneUlpGap, n, relation, rng))
            }
            "scaled-2^1000" => map_pair(&lattice(rng, n, i), |v| {
                Point::new(v.x * 2f64.powi(1000), v.y * 2f64.powi(1000))
            }),
            "scaled-2^-1000" => map_pair(&lattice(rng, n, i), |v| {
                Point::new(v.x * 2f64.powi(-1000), v.y * 2f64.powi(-1000))
            }),
            "offset-2^40..52" => {
                let off = 2f64.powi(40 + 4 * (i % 4) as i32);
                map_pair(&lattice(rng, n, i), |v| Point::new(v.x + off, v.y + off))
            }
            "needles" => Some(needle_pair(rng, n.min(64))),
            _ => None,
        };
        out.extend(pair);
        i += 1;
    }
    out
}

struct Cell {
    wrong: usize,
    panics: usize,
    cases: usize,
    median_ns: f64,
}

pub(crate) fn run(config: &Config) -> io::Result<Report> {
    let mut rng = SmallRng::seed_from_u64(config.seed ^ 0x7ade);
    let cases: Vec<&str> = CASES.to_vec();
    let combos: Vec<(Algorithm, Precision)> = Algorithm::ALL
        .iter()
        .flat_map(|&a| Precision::ALL.iter().map(move |&k| (a, k)))
        .collect();
    let bar = super::progress(config, "trade", cases.len());
    // Fast-kernel answers can violate an algorithm's invariants; such a panic is
    // caught and counted, and its message would only garble the progress bar.
    let hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    let mut cells: Vec<Vec<Cell>> = Vec::new();
    let min_time = config.min_time / 2;
    for &case in &cases {
        bar.set_message(format!("{case}: generating"));
        let mut prepared: Vec<PreparedPair> = if case == "circle" {
            let big = regular_polygon(1 << config.trade_circle_log2, 1.0);
            (0..(config.trade_pairs / 4).max(2))
                .map(|i| {
                    PreparedPair::new(big.clone(), near_boundary(&mut rng, &big), config.seed ^ i as u64)
                })
                .collect()
        } else {
            case_pairs(config, case, &mut rng)
                .into_iter()
                .enumerate()
                .map(|(i, (p, q))| PreparedPair::new(p, q, config.seed ^ i as u64))
                .collect()
        };
        bar.set_message(format!("{case}: measuring"));
        let mut row = Vec::new();
        for &(alg, precision) in &combos {
            let (mut wrong, mut panics, mut times) = (0, 0, Vec::new());
            for pp in prepared.iter_mut() {
                match catch_unwind(AssertUnwindSafe(|| pp.query(alg, precision))) {
                    Ok(answer) => {
                        wrong += usize::from(answer != pp.truth);
                        times.push(time_per_query(min_time, || pp.query(alg, precision)));
                    }
                    Err(_) => {
                        wrong += 1;
                        panics += 1;
                    }
                }
            }
            row.push(Cell {
                wrong,
                panics,
                cases: prepared.len(),
                median_ns: median(&mut times),
            });
        }
        cells.push(row);
        bar.inc(1);
    }
    std::panic::set_hook(hook);
    bar.finish();
    let ratios = overhead(config, &mut rng);

    let mut report = Report::default();
    let mut csv = Csv::new(&[
        "case",
        "algorithm",
        "kernel",
        "pairs",
        "wrong",
        "panics",
        "median_ns",
        "exact_over_fast",
    ]);
    for (ci, &case) in cases.iter().enumerate() {
        for (ai, &(alg, precision)) in combos.iter().enumerate() {
            let c = &cells[ci][ai];
            let time = |k: Precision| {
                let i = combos.iter().position(|&x| x == (alg, k)).expect("both kernels");
                cells[ci][i].median_ns
            };
            csv.row(&[
                case.into(),
                alg.to_string(),
                precision.to_string(),
                c.cases.to_string(),
                c.wrong.to_string(),
                c.panics.to_string(),
                ns(c.median_ns),
                format!("{:.4}", time(Precision::Exact) / time(Precision::Fast)),
            ]);
        }
    }
    csv.write(&config.out, "trade.csv", &mut report)?;
    let mut ratio_csv = Csv::new(&[
        "n",
        "relation",
        "algorithm",
        "pairs",
        "fast_ns",
        "exact_ns",
        "exact_over_fast",
    ]);
    for r in &ratios {
        ratio_csv.row(&[
            r.n.to_string(),
            relation_name(r.relation).into(),
            r.algorithm.to_string(),
            r.pairs.to_string(),
            ns(r.fast_ns),
            ns(r.exact_ns),
            format!("{:.4}", r.ratio),
        ]);
    }
    ratio_csv.write(&config.out, "trade_ratio.csv", &mut report)?;

    let mut md =
        String::from("Wrong answers / pairs, and median time per query, per case.\n\n| algorithm | kernel |");
    for case in &cases {
        let label = if *case == "circle" {
            format!("circle 2^{}", config.trade_circle_log2)
        } else {
            case.to_string()
        };
        md.push_str(&format!(" {label} |"));
    }
    md.push_str(" wrong, all cases |\n|---|---|");
    md.push_str(&"---|".repeat(cases.len() + 1));
    md.push('\n');
    let mut scatter: Vec<Series> = Vec::new();
    for (ai, &(alg, precision)) in combos.iter().enumerate() {
        md.push_str(&format!("| {alg} | {precision} |"));
        let (mut wrong, mut total) = (0, 0);
        for row in &cells {
            let c = &row[ai];
            let panics = if c.panics > 0 {
                format!(" ({} panics)", c.panics)
            } else {
                String::new()
            };
            let time = if c.median_ns.is_nan() {
                "–".into()
            } else {
                short_ns(c.median_ns)
            };
            md.push_str(&format!(" {}/{}{panics} · {time} |", c.wrong, c.cases));
            wrong += c.wrong;
            total += c.cases;
        }
        let rate = 100.0 * wrong as f64 / total.max(1) as f64;
        md.push_str(&format!(" {wrong}/{total} ({rate:.1}%) |\n"));
        scatter.push(Series::new(
            format!("{alg}/{precision}"),
            vec![(rate, cells[0][ai].median_ns)],
        ));
    }
    md.push_str(&overhead_table(&ratios));
    let path = config.out.join("trade.md");
    std::fs::write(&path, &md).map_err(super::naming(&path, "cannot write"))?;
    report.files.push("trade.md".into());
    let y_label = format!("ns per query (random ellipses, n = {})", config.trade_n);
    let chart = Chart {
        title: "time on random ellipses vs wrong answers on all cases",
        x_label: "wrong answers, all cases (%)",
        y_label: &y_label,
        log2_x: false,
        log_y: true,
        scatter: true,
    };
    draw(config, &mut report, "trade.svg", &chart, &scatter)?;
    report.summary = md;
    Ok(report)
}

/// The exact kernel's overhead for one algorithm at one size and relation.
struct Overhead {
    n: usize,
    relation: Relation,
    algorithm: Algorithm,
    pairs: usize,
    /// Median over the pairs of the median fast / exact time per query.
    fast_ns: f64,
    exact_ns: f64,
    /// Median over the pairs of exact / fast.
    ratio: f64,
}

/// Exact against fast on random rotated ellipses, interleaved per pair (module docs).
fn overhead(config: &Config, rng: &mut SmallRng) -> Vec<Overhead> {
    let bar = super::progress(config, "overhead", config.ratio_log2_sizes.len());
    let min_time = config.min_time / 2;
    let mut out = Vec::new();
    for (&log2, relation) in config
        .ratio_log2_sizes
        .iter()
        .flat_map(|l| [(l, Relation::Disjoint), (l, Relation::Intersecting)])
    {
        let n = 1usize << log2;
        bar.set_message(format!("n = 2^{log2}, {}", relation_name(relation)));
        let mut prepared: Vec<PreparedPair> = (0..config.pairs_for(n).div_ceil(2).max(2))
            .map(|i| {
                let (p, q) = generate::pair(Family::Rotated, n, relation, rng);
                PreparedPair::new(p, q, config.seed ^ i as u64)
            })
            .collect();
        for &alg in Algorithm::ALL {
            let (mut fast, mut exact, mut ratio) = (Vec::new(), Vec::new(), Vec::new());
            for pp in prepared.iter_mut() {
                let (mut f, mut e) = (Vec::new(), Vec::new());
                for _ in 0..3 {
                    f.push(time_per_query(min_time, || pp.query(alg, Precision::Fast)));
                    e.push(time_per_query(min_time, || pp.query(alg, Precision::Exact)));
                }
                let (f, e) = (median(&mut f), median(&mut e));
                fast.push(f);
                exact.push(e);
                ratio.push(e / f);
            }
            out.push(Overhead {
                n,
                relation,
                algorithm: alg,
                pairs: prepared.len(),
                fast_ns: median(&mut fast),
                exact_ns: median(&mut exact),
                ratio: median(&mut ratio),
            });
        }
        if relation == Relation::Intersecting {
            bar.inc(1);
        }
    }
    bar.finish();
    out
}

/// The name of a relation in the overhead table.
fn relation_name(relation: Relation) -> &'static str {
    match relation {
        Relation::Disjoint => "disjoint",
        Relation::Intersecting => "intersecting",
        _ => "any",
    }
}

/// The overhead as a markdown table: one row per algorithm, one column per size.
fn overhead_table(ratios: &[Overhead]) -> String {
    let mut sizes: Vec<usize> = ratios.iter().map(|r| r.n).collect();
    sizes.dedup();
    let mut md = String::from(
        "\nExact kernel time / fast kernel time on random rotated ellipses (median over pairs \
         of interleaved measurements; exact and fast ns per query in parentheses).\n\n| algorithm | pairs |",
    );
    for n in &sizes {
        md.push_str(&format!(" n = 2^{} |", n.trailing_zeros()));
    }
    md.push_str("\n|---|---|");
    md.push_str(&"---|".repeat(sizes.len()));
    md.push('\n');
    for (&alg, relation) in Algorithm::ALL
        .iter()
        .flat_map(|a| [(a, Relation::Disjoint), (a, Relation::Intersecting)])
    {
        md.push_str(&format!("| {alg} | {} |", relation_name(relation)));
        for &n in &sizes {
            match ratios
                .iter()
                .find(|r| r.n == n && r.algorithm == alg && r.relation == relation)
            {
                Some(r) => md.push_str(&format!(
                    " {:.2} ({} / {}) |",
                    r.ratio,
                    short_ns(r.exact_ns),
                    short_ns(r.fast_ns)
                )),
                None => md.push_str(" – |"),
            }
        }
        md.push('\n');
    }
    md
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::intersect::{ArrayIntersection, brute_force};

    #[test]
    fn needles_are_thin_and_near_each_other() {
        let mut rng = SmallRng::seed_from_u64(3);
        let mut answers = [0, 0];
        for _ in 0..30 {
            let (p, q) = needle_pair(&mut rng, 32);
            p.debug_validate().unwrap();
            q.debug_validate().unwrap();
            answers[usize::from(brute_force(crate::Exact, &p, &q))] += 1;
        }
        assert!(answers[0] > 0 && answers[1] > 0, "{answers:?}");
    }

    #[test]
    fn near_boundary_triangles_touch_or_miss_the_circle() {
        let mut rng = SmallRng::seed_from_u64(4);
        let big = regular_polygon(1 << 10, 1.0);
        let mut answers = [0, 0];
        for _ in 0..40 {
            let q = near_boundary(&mut rng, &big);
            answers[usize::from(crate::intersect::Linear.intersects(&big, &q))] += 1;
        }
        assert!(answers[0] > 0 && answers[1] > 0, "{answers:?}");
    }
}
