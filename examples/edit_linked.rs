//! Editing a linked polygon in place, and querying it between edits.
//!
//! Run with `cargo run --example edit_linked`.

use polysect::intersect::{Clm, LinkedIntersection};
use polysect::{Exact, LinkedPolygon, Point};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    // A unit square; the vertices are stored in an arena and linked in
    // counter-clockwise order, whatever order they were given in.
    let mut p = LinkedPolygon::from_points([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])?;
    // A triangle to the right of it, not touching it.
    let q = LinkedPolygon::from_points([[2.0, 0.0], [3.0, 0.0], [3.0, 1.0]])?;
    show("start", &p);
    println!(
        "  meets the triangle: {}",
        Clm.intersects_seeded(Exact, &p, &q, 1)
    );

    // Every edit is O(1) and checked: it keeps the polygon convex or is refused with
    // an error, leaving the polygon unchanged. Handles (`VertexId`) stay valid across
    // other edits.
    let a = p.first(); // (0, 0)
    let b = p.next(a)?; // (1, 0)
    let c = p.next(b)?; // (1, 1)

    // Insert a vertex after `b`, pushing the right edge out to a point at x = 1.5.
    let tip = p.insert_after(b, Point::new(1.5, 0.5))?;
    show("after inserting (1.5, 0.5)", &p);

    // An edit that would make the polygon reflex is refused.
    match p.insert_after(a, Point::new(0.5, 0.5)) {
        Ok(_) => unreachable!("an interior point cannot become a vertex"),
        Err(e) => println!("  inserting (0.5, 0.5) after (0, 0) is refused: {e}"),
    }

    // Move the new vertex until it touches the triangle's left corner at (2, 0)...
    // (moving it straight there would make the polygon reflex at `b`, so move `b` too).
    p.move_vertex(b, Point::new(1.0, -0.5))?;
    p.move_vertex(tip, Point::new(2.0, 0.0))?;
    show("after two moves", &p);
    println!(
        "  meets the triangle: {}",
        Clm.intersects_seeded(Exact, &p, &q, 2)
    );

    // ...then remove it again. The handle is now stale: using it is an error.
    p.remove(tip)?;
    println!("  the removed vertex's handle: {:?}", p.point(tip));
    p.translate(0.25, 0.0)?;
    p.remove(c)?;
    show("after removing the tip and (1, 1), moved right by 0.25", &p);
    println!(
        "  meets the triangle: {}",
        Clm.intersects_seeded(Exact, &p, &q, 3)
    );

    // A snapshot as a sorted array, for the O(log n) array algorithms.
    let array = p.to_convex();
    println!("  as an array: {} vertices", array.len());
    Ok(())
}

fn show(label: &str, p: &LinkedPolygon) {
    let vertices: Vec<String> = p.iter().map(|(_, v)| format!("({}, {})", v.x, v.y)).collect();
    println!("{label}: {}", vertices.join(" "));
}
