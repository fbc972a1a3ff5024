//! The points where the boundaries of two simple (not necessarily convex) polygons meet.
//!
//! Run with `cargo run --example simple_crossings`.

use polysect::crossings::{Brute, Crossings, Sweep};
use polysect::{Fast, SimplePolygon};

fn main() -> Result<(), polysect::SimplePolygonError> {
    // A comb with three teeth pointing up...
    let comb = SimplePolygon::new([
        [0.0, 0.0],
        [7.0, 0.0],
        [7.0, 3.0],
        [6.0, 3.0],
        [6.0, 1.0],
        [4.0, 1.0],
        [4.0, 3.0],
        [3.0, 3.0],
        [3.0, 1.0],
        [1.0, 1.0],
        [1.0, 3.0],
        [0.0, 3.0],
    ])?;
    // ...and a bar across the teeth, whose top edge runs along their tips.
    let bar = SimplePolygon::new([[-1.0, 2.0], [8.0, 2.0], [8.0, 3.0], [-1.0, 3.0]])?;

    // The sweep takes O((n + m + k) log(n + m)) for k crossings; the brute force checks
    // every pair of edges in O(n m). Both decide every predicate exactly and report
    // each point once, sorted; shared stretches of boundary give their end points.
    let points = Sweep.crossings(&comb, &bar);
    assert_eq!(points, Brute.crossings(&comb, &bar));
    println!("{} points where the boundaries meet:", points.len());
    for p in &points {
        println!("  ({}, {})", p.x, p.y);
    }

    // The fast kernel (plain floating point) gives the same points on these inputs.
    assert_eq!(Sweep.crossings_with(Fast, &comb, &bar), points);

    // Invalid input is refused with a reason: this "polygon" crosses itself.
    let bow_tie = SimplePolygon::new([[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]]);
    println!("a bow tie: {}", bow_tie.unwrap_err());
    Ok(())
}
