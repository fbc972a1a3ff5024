//! Two convex polygons and every intersection algorithm.
//!
//! Run with `cargo run --example two_polygons` (the example needs no optional feature).

use polysect::intersect::{
    Algorithm, ArrayIntersection, Barba, Clm, Convert, Dobkin, Linear, LinkedIntersection,
};
use polysect::{ConvexPolygon, Exact, Fast, LinkedPolygon, Point, Precision};
use rand::SeedableRng;
use rand::rngs::SmallRng;

fn main() -> Result<(), polysect::PolygonError> {
    // A regular 64-gon of radius 1 around the origin, and a square that just touches it
    // from the right: polygons are closed sets, so touching counts as intersecting.
    let circle = polysect::generate::regular_polygon(64, 1.0);
    let square = ConvexPolygon::new([[1.0, -0.5], [2.0, -0.5], [2.0, 0.5], [1.0, 0.5]])?;
    // The same square moved a little further right: now the two are disjoint.
    let apart = square.map(|p| Point::new(p.x + 0.01, p.y))?;

    // One algorithm, called directly. `intersects` decides every predicate exactly;
    // `intersects_with(Fast, ..)` uses plain floating point instead.
    println!("Barba, exact:  touching {}", Barba.intersects(&circle, &square));
    println!(
        "Barba, fast:   touching {}",
        Barba.intersects_with(Fast, &circle, &square)
    );
    println!("Dobkin, exact: apart    {}", Dobkin.intersects(&circle, &apart));

    // Every algorithm by name, as the CLI's `--algorithm` lists them. The linked-list
    // algorithms (clm, convert) link the arrays in a shuffled order first; a seeded
    // generator makes their runs reproducible (the answer never depends on it).
    let mut rng = SmallRng::seed_from_u64(7);
    println!(
        "\n{:<16} {:>9} {:>10} {:>6}",
        "algorithm", "touching", "apart", "steps"
    );
    for &algorithm in Algorithm::ALL {
        let (touching, steps) = algorithm.run_rng(Precision::Exact, &circle, &square, &mut rng);
        let (disjoint, _) = algorithm.run_rng(Precision::Exact, &circle, &apart, &mut rng);
        println!(
            "{:<16} {:>9} {:>10} {:>6}",
            algorithm.name(),
            touching,
            disjoint,
            steps
        );
        // Every algorithm agrees with the O(n + m) reference.
        assert_eq!(touching, Linear.intersects(&circle, &square));
        assert_eq!(disjoint, Linear.intersects(&circle, &apart));
    }

    // The sublinear test runs on linked polygons directly, without building arrays.
    let p = LinkedPolygon::from_convex(&circle);
    let q = LinkedPolygon::from_convex(&square);
    println!(
        "\nClm on linked polygons (seed 1): {}",
        Clm.intersects_seeded(Exact, &p, &q, 1)
    );
    println!(
        "Convert on linked polygons:      {}",
        <Convert>::default().intersects(&p, &q)
    );
    Ok(())
}
