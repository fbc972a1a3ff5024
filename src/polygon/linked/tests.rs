use super::sampling::SampleWorkspace;
use super::*;
use rand::SeedableRng;
use rand::rngs::SmallRng;

fn square() -> LinkedPolygon {
    LinkedPolygon::from_points([[0., 0.], [4., 0.], [4., 4.], [0., 4.]]).unwrap()
}

#[test]
fn removal_keeps_storage_dense_and_links_valid() {
    let mut rng = SmallRng::seed_from_u64(3);
    let n = 64;
    let pts: Vec<Point> = (0..n)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / n as f64;
            Point::new(a.cos(), a.sin())
        })
        .collect();
    let mut p = LinkedPolygon::from_convex_shuffled(&ConvexPolygon::new(pts).unwrap(), &mut rng);
    p.debug_validate().unwrap();
    while p.len() > 3 {
        let v = p.random_vertex(&mut rng);
        p.remove(v).unwrap();
        p.debug_validate().unwrap();
        assert_eq!(p.point(v), Err(EditError::StaleHandle));
    }
    assert_eq!(p.remove(p.first()), Err(EditError::TooFewVertices));
}

#[test]
fn stale_handles_never_alias_reused_slots() {
    let mut p = square();
    let a = p.first();
    let v = p.insert_after(a, Point::new(2., -1.)).unwrap();
    p.remove(v).unwrap();
    // The slab reuses the slot; the old handle must not see the new vertex.
    let w = p.insert_after(a, Point::new(2., -0.5)).unwrap();
    assert_eq!(v.slot, w.slot);
    assert_eq!(p.point(v), Err(EditError::StaleHandle));
    assert_eq!(
        p.move_vertex(v, Point::new(2., -0.25)),
        Err(EditError::StaleHandle)
    );
    assert_eq!(p.point(w), Ok(Point::new(2., -0.5)));
    let other = square();
    assert!(other.has_vertex(other.first()));
}

#[test]
fn a_handle_of_another_polygon_is_refused_by_every_method() {
    let mut a = square();
    let b = LinkedPolygon::from_points([[10., 10.], [11., 10.], [11., 11.]]).unwrap();
    // The same slot and generation exist in `a`: only the owner tells them apart.
    let vb = b.next(b.first()).unwrap();
    let twin = a.next(a.first()).unwrap();
    assert_eq!((vb.slot, vb.generation), (twin.slot, twin.generation));
    let copy = a.clone();
    let from_copy = copy.first();
    let before: Vec<_> = a.iter().map(|(_, p)| p).collect();
    for foreign in [vb, from_copy] {
        assert!(!a.has_vertex(foreign));
        assert_eq!(a.point(foreign), Err(EditError::ForeignHandle));
        assert_eq!(a.next(foreign), Err(EditError::ForeignHandle));
        assert_eq!(a.prev(foreign), Err(EditError::ForeignHandle));
        assert_eq!(a.position(foreign), Err(EditError::ForeignHandle));
        assert!(matches!(a.iter_from(foreign), Err(EditError::ForeignHandle)));
        assert_eq!(
            a.insert_after(foreign, Point::new(2., -1.)),
            Err(EditError::ForeignHandle)
        );
        assert_eq!(a.remove(foreign), Err(EditError::ForeignHandle));
        assert_eq!(
            a.move_vertex(foreign, Point::new(5., -1.)),
            Err(EditError::ForeignHandle)
        );
    }
    assert_eq!(a.iter().map(|(_, p)| p).collect::<Vec<_>>(), before);
    // The original's handles are foreign to the clone too, and each polygon still
    // accepts its own.
    assert_eq!(copy.point(a.first()), Err(EditError::ForeignHandle));
    assert!(copy.has_vertex(from_copy) && a.has_vertex(twin) && b.has_vertex(vb));
    // A removed vertex of this polygon stays stale, not foreign.
    let v = a.insert_after(a.first(), Point::new(2., -1.)).unwrap();
    a.remove(v).unwrap();
    assert_eq!(a.point(v), Err(EditError::StaleHandle));
    a.debug_validate().unwrap();
}

#[test]
fn refused_edits_change_nothing() {
    let mut p = square();
    let before: Vec<_> = p.iter().collect();
    let a = p.first(); // (0, 0); next is (4, 0)
    for bad in [
        Point::new(2., 0.),   // on the edge: collinear vertex
        Point::new(2., 1.),   // inside
        Point::new(5., -1.),  // beyond the line through the next edge
        Point::new(-1., -1.), // beyond the line through the previous edge
        Point::new(0., 0.),   // duplicate of a
        Point::new(f64::NAN, 0.),
    ] {
        assert!(p.insert_after(a, bad).is_err(), "{bad:?}");
        assert_eq!(p.iter().collect::<Vec<_>>(), before);
    }
    let b = p.next(a).unwrap(); // (4, 0)
    for bad in [
        Point::new(2., 2.),
        Point::new(4., 4.),
        Point::new(6., 5.),
        Point::new(0., -1.),
    ] {
        assert!(p.move_vertex(b, bad).is_err(), "{bad:?}");
        assert_eq!(p.iter().collect::<Vec<_>>(), before);
    }
    assert_eq!(p.move_vertex(b, Point::new(5., -1.)), Ok(Point::new(4., 0.)));
    p.debug_validate().unwrap();
}

#[cfg(feature = "serde")]
#[test]
fn serde_round_trip_validates() {
    let p = square();
    let text = serde_json::to_string(&p).unwrap();
    assert_eq!(text, "[[0.0,0.0],[4.0,0.0],[4.0,4.0],[0.0,4.0]]");
    let back: LinkedPolygon = serde_json::from_str(&text).unwrap();
    assert_eq!(back.to_convex(), p.to_convex());
    let bad = r#"[{"x":0,"y":0},{"x":4,"y":0},{"x":4,"y":4},{"x":2,"y":1},{"x":0,"y":4}]"#;
    let err = serde_json::from_str::<LinkedPolygon>(bad)
        .unwrap_err()
        .to_string();
    assert!(err.contains("vertex 3 is reflex"), "{err}");
}

#[test]
fn moves_on_a_triangle_keep_orientation() {
    let mut t = LinkedPolygon::from_points([[0., 0.], [1., 0.], [0., 1.]]).unwrap();
    let v = t.next(t.first()).unwrap();
    // Moving (1,0) across the opposite side would flip the triangle: refused.
    assert!(t.move_vertex(v, Point::new(-1., 2.)).is_err());
    assert!(t.move_vertex(v, Point::new(3., 3.)).is_ok());
    t.debug_validate().unwrap();
}

#[test]
fn sample_positions_are_distinct_and_complete() {
    let mut rng = SmallRng::seed_from_u64(9);
    let pts: Vec<Point> = (0..100)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / 100.0;
            Point::new(a.cos(), a.sin())
        })
        .collect();
    let p = LinkedPolygon::from_convex(&ConvexPolygon::new(pts).unwrap());
    let mut ws = SampleWorkspace::default();
    for k in [0, 1, 10, 50, 51, 99, 100, 500] {
        let mut out = Vec::new();
        p.sample_positions(k, &mut rng, &mut ws, &mut out);
        assert_eq!(out.len(), k.min(100));
        let mut s = out.clone();
        s.sort();
        s.dedup();
        assert_eq!(s.len(), out.len(), "k = {k}");
    }
}
