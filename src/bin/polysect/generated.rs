//! `polysect gen`: generated pairs as JSON lines in the `check` and `crossings` input
//! formats.

use crate::args::{OrderArg, RelationArg};
use crate::failure::Failure;
use polysect::generate::simple::{GenerateError, PointDistribution, SimpleMethod, random_simple_polygon};
use polysect::generate::{self, Family, Relation};
use polysect::intersect::Algorithm;
use polysect::protocol;
use polysect::{ConvexPolygon, Precision};
use rand::SeedableRng;
use rand::rngs::SmallRng;
use std::io::{self, BufWriter, Write};

pub(crate) fn gen_pairs(
    family: Family,
    n: usize,
    count: u64,
    relation: RelationArg,
    order: OrderArg,
    seed: u64,
    axes: Option<(f64, f64)>,
) -> io::Result<()> {
    if axes.is_some() && !matches!(family, Family::Ellipse | Family::Rotated | Family::NonUniform) {
        return Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            format!("--a/--b apply to the ellipse families (ellipse, rotated, non-uniform), not to {family}"),
        ));
    }
    let mut rng = SmallRng::seed_from_u64(seed);
    let relation = match relation {
        RelationArg::Any => Relation::Any,
        RelationArg::Intersecting => Relation::Intersecting,
        RelationArg::Disjoint => Relation::Disjoint,
    };
    let mut out = BufWriter::new(io::stdout().lock());
    for i in 0..count {
        let (p, q) = generate::try_pair_with_axes(family, n, relation, axes, &mut rng)
            .map_err(|e| io::Error::new(io::ErrorKind::InvalidInput, e))?;
        let expected = Algorithm::Linear.intersects(Precision::Exact, &p, &q);
        let mut write_order = |poly: &ConvexPolygon| {
            let mut v = poly.vertices().to_vec();
            let reverse = match order {
                OrderArg::Ccw => false,
                OrderArg::Cw => true,
                OrderArg::Random => rand::Rng::random_bool(&mut rng, 0.5),
            };
            if reverse {
                v.reverse();
            }
            protocol::points_json(&v)
        };
        let (pj, qj) = (write_order(&p), write_order(&q));
        writeln!(
            out,
            "{{\"id\": {i}, \"family\": \"{family}\", \"n\": {n}, \"expected\": {expected}, \"p\": {pj}, \"q\": {qj}}}"
        )?;
    }
    out.flush()
}

/// Pairs of random simple polygons as `crossings` input lines. Parameters are checked
/// (as a usage error) before anything is written.
pub(crate) fn gen_simple(
    method: SimpleMethod,
    dist: PointDistribution,
    n: usize,
    count: usize,
    order: OrderArg,
    seed: u64,
) -> Result<(), Failure> {
    let mut rng = SmallRng::seed_from_u64(seed);
    let mut out = BufWriter::new(io::stdout().lock());
    let distribution = match dist {
        PointDistribution::Normal { sigma, .. } => format!("\"sigma\": {sigma:?}"),
        PointDistribution::Uniform { max, .. } => format!("\"delta\": {max:?}"),
        PointDistribution::Grid { size } => format!("\"grid\": {size}"),
    };
    for i in 0..count {
        let mut polygon = || match random_simple_polygon(method, dist, n, &mut rng) {
            Ok(p) => Ok(p),
            Err(e @ GenerateError::InvalidParameters(_)) => Err(Failure::Usage {
                command: "gen",
                message: e.to_string(),
            }),
            Err(e) => Err(Failure::Io(io::Error::other(e.to_string()))),
        };
        let (p, q) = (polygon()?, polygon()?);
        let mut write_order = |poly: &polysect::SimplePolygon| {
            let mut v = poly.vertices().to_vec();
            let reverse = match order {
                OrderArg::Ccw => false,
                OrderArg::Cw => true,
                OrderArg::Random => rand::Rng::random_bool(&mut rng, 0.5),
            };
            // Counter-clockwise first (exact), then the order asked for.
            if poly.is_ccw() == reverse {
                v.reverse();
            }
            protocol::points_json(&v)
        };
        let (pj, qj) = (write_order(&p), write_order(&q));
        writeln!(
            out,
            "{{\"id\": {i}, \"method\": \"{method}\", {distribution}, \"n\": {n}, \"p\": {pj}, \"q\": {qj}}}"
        )
        .map_err(Failure::Io)?;
    }
    out.flush().map_err(Failure::Io)
}
