//! The library's surface as a user meets it: serde forms of points, polygons and
//! handles, error messages and their sources, the checked regular polygon, `Point`
//! arithmetic, the `rand` re-export.

use polysect::generate::{GenerateError, MAX_VERTICES, regular_polygon, try_regular_polygon};
use polysect::rand::SeedableRng;
use polysect::rand::rngs::SmallRng;
use polysect::store::{PolygonId, Scene, SceneError};
use polysect::{ConvexPolygon, EditError, LinkedPolygon, Point, PolygonError};
use std::error::Error;

const SQUARE_ARRAYS: &str = "[[0.0,0.0],[4.0,0.0],[4.0,4.0],[0.0,4.0]]";
const SQUARE_OBJECTS: &str = r#"[{"x":0,"y":0},{"x":4,"y":0},{"x":4,"y":4},{"x":0,"y":4}]"#;

#[test]
fn polygons_serialise_as_coordinate_pairs_and_read_both_forms() {
    let p = ConvexPolygon::new([[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]]).unwrap();
    assert_eq!(serde_json::to_string(&p).unwrap(), SQUARE_ARRAYS);
    let linked = LinkedPolygon::from_convex(&p);
    assert_eq!(serde_json::to_string(&linked).unwrap(), SQUARE_ARRAYS);
    for text in [
        SQUARE_ARRAYS,
        SQUARE_OBJECTS,
        r#"[[0,0],{"x":4,"y":0},[4,4],{"y":4,"x":0}]"#,
    ] {
        assert_eq!(serde_json::from_str::<ConvexPolygon>(text).unwrap(), p, "{text}");
        let back: LinkedPolygon = serde_json::from_str(text).unwrap();
        assert_eq!(back.to_convex(), p, "{text}");
    }
    // Still validated on the way in, whichever the form.
    for bad in [
        "[[0,0],[4,0],[4,4],[2,1],[0,4]]",
        r#"[{"x":0,"y":0},{"x":4,"y":0},{"x":4,"y":4},{"x":2,"y":1},{"x":0,"y":4}]"#,
    ] {
        let err = serde_json::from_str::<ConvexPolygon>(bad)
            .unwrap_err()
            .to_string();
        assert!(err.contains("vertex 3 is reflex"), "{err}");
    }
    assert!(serde_json::from_str::<ConvexPolygon>("[[0,0,0],[1,0],[0,1]]").is_err());
}

#[test]
fn polygon_ids_round_trip_through_serde() {
    let mut scene = Scene::new();
    let a = scene.insert_points([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]).unwrap();
    scene.remove(a).unwrap();
    let b = scene.insert_points([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]).unwrap();
    let text = serde_json::to_string(&b).unwrap();
    let back: PolygonId = serde_json::from_str(&text).unwrap();
    assert_eq!(back, b);
    assert!(scene.polygon(back).is_ok());
    // The stale handle read back is still stale: same slot, older generation.
    let stale: PolygonId = serde_json::from_str(&serde_json::to_string(&a).unwrap()).unwrap();
    assert_eq!(scene.polygon(stale).unwrap_err(), SceneError::StalePolygon(a));
}

#[test]
fn scene_errors_name_the_polygon_and_expose_their_source() {
    let mut scene = Scene::new();
    let a = scene.insert_points([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]).unwrap();
    let first = scene.polygon(a).unwrap().first();
    let err = scene.remove_vertex(a, first).unwrap_err();
    assert_eq!(err.polygon(), Some(a));
    assert_eq!(
        err.to_string(),
        format!("polygon {a}: a polygon keeps at least 3 vertices; removal refused")
    );
    assert!(
        err.to_string().starts_with("polygon #0 (generation 0): "),
        "{err}"
    );
    let source = err.source().expect("an edit error has a source");
    assert_eq!(source.to_string(), EditError::TooFewVertices.to_string());
    assert!(source.downcast_ref::<EditError>().is_some());

    let err = scene.insert_points([[0.0, 0.0], [1.0, 1.0]]).unwrap_err();
    assert_eq!(err.polygon(), None);
    assert!(err.source().unwrap().downcast_ref::<PolygonError>().is_some());
    assert_eq!(
        err.to_string(),
        "invalid polygon: a polygon needs at least 3 distinct vertices, found 2"
    );

    scene.remove(a).unwrap();
    let err = scene.intersects(a, a).unwrap_err();
    assert_eq!(err, SceneError::StalePolygon(a));
    assert!(err.source().is_none());
    assert_eq!(
        err.to_string(),
        "polygon #0 (generation 0) is stale (the polygon was removed)"
    );
}

#[test]
fn regular_polygon_refuses_what_is_not_a_polygon() {
    for radius in [0.0, -0.0, -2.0, f64::INFINITY, f64::NEG_INFINITY, f64::NAN] {
        assert!(
            matches!(
                try_regular_polygon(5, radius),
                Err(GenerateError::InvalidParameters(_))
            ),
            "radius {radius}"
        );
    }
    assert!(matches!(
        try_regular_polygon(MAX_VERTICES + 1, 1.0),
        Err(GenerateError::InvalidParameters(_))
    ));
    // Fewer than 3 vertices are taken as 3, like every generator.
    assert_eq!(try_regular_polygon(2, 1.0).unwrap().len(), 3);
    // A subnormal radius rounds vertices together: fewer vertices, or an error.
    if let Ok(p) = try_regular_polygon(7, f64::from_bits(1)) {
        assert!(p.len() < 7);
        p.debug_validate().unwrap();
    }
    assert_eq!(regular_polygon(6, 1.0).len(), 6);
}

#[test]
#[should_panic(expected = "regular_polygon(5, 0.0): invalid generator parameters")]
fn regular_polygon_panics_with_the_reason() {
    let _ = regular_polygon(5, 0.0);
}

#[test]
fn edit_errors_print_extreme_coordinates_briefly() {
    let mut p = LinkedPolygon::from_points([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]).unwrap();
    let err = p.translate(f64::MAX, 0.0).unwrap_err();
    let text = err.to_string();
    assert!(text.contains("1.7976931348623157e308"), "{text}");
    assert!(text.len() < 160, "{} characters: {text}", text.len());
    let err = p.insert_after(p.first(), Point::new(1e300, -5e-324)).unwrap_err();
    assert_eq!(
        err.to_string(),
        "placing a vertex at (1e300, -5e-324) would make the polygon non-convex"
    );
    let err = p.move_vertex(p.first(), Point::new(f64::NAN, 2.0)).unwrap_err();
    assert_eq!(err.to_string(), "point (NaN, 2) has a non-finite coordinate");
}

#[test]
fn point_arithmetic_and_the_rand_re_export() {
    let (a, b) = (Point::new(1.5, -2.0), Point::new(0.25, 4.0));
    assert_eq!(a + b - b, a);
    assert_eq!((a - b) * 2.0, Point::new(2.5, -12.0));
    assert_eq!(-(-a), a);
    assert_eq!(a.to_string(), "(1.5, -2)");
    // The generator of the re-exported rand drives the sampled queries.
    let mut rng = SmallRng::seed_from_u64(5);
    let square = ConvexPolygon::new([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]).unwrap();
    let p = LinkedPolygon::from_convex_shuffled(&square, &mut rng);
    assert!(p.contains_point_with(polysect::Exact, a + Point::new(0.0, 3.0), &mut rng));
}

/// One box type: the array polygon, the linked polygon and the scene give the same
/// `BoundingBox`, and it follows an edit.
#[test]
fn one_bounding_box_type_everywhere() {
    use polysect::BoundingBox;
    let p = ConvexPolygon::new([[1.0, -2.0], [5.0, 0.0], [3.0, 4.0], [-1.0, 1.0]]).unwrap();
    let want = BoundingBox::new(Point::new(-1.0, -2.0), Point::new(5.0, 4.0));
    let from_array: BoundingBox = p.bounding_box();
    let linked = LinkedPolygon::from_convex(&p);
    let from_linked: BoundingBox = linked.bounding_box();
    let mut scene = Scene::new();
    let id = scene.insert(linked);
    let from_scene: polysect::store::BoundingBox = scene.bounding_box(id).unwrap();
    assert_eq!([from_array, from_linked, from_scene], [want; 3]);
    assert_eq!(BoundingBox::of(p.vertices().iter().copied()), Some(want));
    let mut linked = LinkedPolygon::from_convex(&p);
    let v = linked.first();
    linked.move_vertex(v, Point::new(1.0, -3.0)).unwrap();
    assert_eq!(linked.bounding_box().min, Point::new(-1.0, -3.0));
    assert!(want.contains_point([5.0, 4.0]) && !want.contains_point([5.0, 4.5]));
}

/// `Point` measures and operators a user reaches for, and the honest name of
/// `ConvexPolygon::rotated`.
#[test]
fn point_arithmetic_and_starting_at() {
    let (a, b) = (Point::new(3.0, 0.0), Point::new(0.0, 4.0));
    assert_eq!(a.distance(b), 5.0);
    assert_eq!((b - a).length(), 5.0);
    assert_eq!((a.dot(b), a.cross(b)), (0.0, 12.0));
    assert_eq!(0.5 * (a + b), Point::new(1.5, 2.0));
    let p = ConvexPolygon::new([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]).unwrap();
    let q = p.starting_at(2);
    assert_eq!(q.vertices()[0], Point::new(2.0, 2.0));
    assert_eq!((q.area(), q.bounding_box()), (p.area(), p.bounding_box()));
}
