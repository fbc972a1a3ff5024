use super::*;
use polysect::PolygonError;

/// A WKB polygon written field by field: byte order, type code, optional SRID, rings.
fn build(little: bool, code: u32, srid: Option<u32>, rings: &[&[[f64; 2]]]) -> Vec<u8> {
    let u32b = |v: u32| if little { v.to_le_bytes() } else { v.to_be_bytes() };
    let f64b = |v: f64| if little { v.to_le_bytes() } else { v.to_be_bytes() };
    let mut out = vec![u8::from(little)];
    out.extend_from_slice(&u32b(code));
    if let Some(s) = srid {
        out.extend_from_slice(&u32b(s));
    }
    out.extend_from_slice(&u32b(rings.len() as u32));
    for ring in rings {
        out.extend_from_slice(&u32b(ring.len() as u32));
        for [x, y] in ring.iter() {
            out.extend_from_slice(&f64b(*x));
            out.extend_from_slice(&f64b(*y));
        }
    }
    out
}

const SQUARE: &[[f64; 2]] = &[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0], [0.0, 0.0]];

fn square() -> ConvexPolygon {
    ConvexPolygon::new([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]).unwrap()
}

#[test]
fn both_byte_orders_and_ewkb_read_the_same_polygon() {
    for little in [true, false] {
        assert_eq!(parse_polygon(&build(little, 3, None, &[SQUARE])), Ok(square()));
        let ewkb = build(little, 3 | EWKB_SRID, Some(4326), &[SQUARE]);
        assert_eq!(parse_polygon(&ewkb), Ok(square()));
    }
}

#[test]
fn writer_round_trips_and_matches_the_field_layout() {
    let p = square();
    let bytes = polygon_to_wkb(&p);
    assert_eq!(bytes, build(true, 3, None, &[SQUARE]));
    assert_eq!(parse_polygon(&bytes), Ok(p));
}

#[test]
fn clockwise_rings_and_collinear_points_are_cleaned() {
    let cw = [
        [0.0, 0.0],
        [0.0, 2.0],
        [2.0, 2.0],
        [2.0, 1.0],
        [2.0, 0.0],
        [0.0, 0.0],
    ];
    assert_eq!(parse_polygon(&build(true, 3, None, &[&cw])), Ok(square()));
}

#[test]
fn header_errors_say_what_was_found() {
    assert_eq!(
        parse_polygon(&[]),
        Err(WkbError::Truncated {
            offset: 0,
            field: "byte-order byte"
        })
    );
    assert_eq!(
        parse_polygon(&[2, 3, 0, 0, 0]),
        Err(WkbError::ByteOrder { byte: 2 })
    );
    assert_eq!(
        parse_polygon(&[1, 3, 0]),
        Err(WkbError::Truncated {
            offset: 1,
            field: "geometry type"
        })
    );
    for code in [1, 6, 1003, 2003, 3003, 3 | 0x8000_0000, 3 | 0x4000_0000] {
        assert_eq!(
            parse_polygon(&build(true, code, None, &[SQUARE])),
            Err(WkbError::GeometryType { code })
        );
    }
    let msg = WkbError::GeometryType { code: 6 }.to_string();
    assert!(msg.contains("MultiPolygon"), "{msg}");
    let msg = WkbError::GeometryType { code: 1003 }.to_string();
    assert!(msg.contains("Polygon Z"), "{msg}");
}

#[test]
fn ring_structure_errors() {
    assert_eq!(parse_polygon(&build(true, 3, None, &[])), Err(WkbError::Empty));
    let hole: &[[f64; 2]] = &[[0.5, 0.5], [1.0, 0.5], [1.0, 1.0], [0.5, 0.5]];
    assert_eq!(
        parse_polygon(&build(false, 3, None, &[SQUARE, hole])),
        Err(WkbError::Holes { count: 1 })
    );
    let short: &[[f64; 2]] = &[[0.0, 0.0], [1.0, 0.0], [0.0, 0.0]];
    assert_eq!(
        parse_polygon(&build(true, 3, None, &[short])),
        Err(WkbError::RingTooShort { points: 3 })
    );
    let open: &[[f64; 2]] = &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    assert_eq!(
        parse_polygon(&build(true, 3, None, &[open])),
        Err(WkbError::RingNotClosed)
    );
    let mut trailing = build(true, 3, None, &[SQUARE]);
    let end = trailing.len();
    trailing.push(0);
    assert_eq!(
        parse_polygon(&trailing),
        Err(WkbError::TrailingBytes { offset: end })
    );
}

#[test]
fn truncation_is_reported_where_it_happens_and_a_lying_count_allocates_nothing() {
    let whole = build(true, 3, None, &[SQUARE]);
    // Cut inside the third point: the error names the first missing whole point.
    let cut = &whole[..9 + 4 + 16 * 2 + 5];
    assert_eq!(
        parse_polygon(cut),
        Err(WkbError::Truncated {
            offset: 13 + 32,
            field: "ring's points"
        })
    );
    // A header claiming u32::MAX points over no data.
    let mut lying = build(true, 3, None, &[]);
    lying[5..9].copy_from_slice(&1u32.to_le_bytes());
    lying.extend_from_slice(&u32::MAX.to_le_bytes());
    assert_eq!(
        parse_polygon(&lying),
        Err(WkbError::Truncated {
            offset: 13,
            field: "ring's points"
        })
    );
    // Every prefix of a valid value is an error, never a panic.
    for n in 0..whole.len() {
        assert!(parse_polygon(&whole[..n]).is_err(), "prefix of {n} bytes");
    }
}

#[test]
fn non_convex_and_degenerate_rings_carry_the_polygon_error() {
    let dart: &[[f64; 2]] = &[[0.0, 0.0], [2.0, 0.0], [1.0, 0.5], [1.0, 2.0], [0.0, 0.0]];
    assert!(matches!(
        parse_polygon(&build(true, 3, None, &[dart])),
        Err(WkbError::Polygon(_))
    ));
    let flat: &[[f64; 2]] = &[[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [0.0, 0.0]];
    assert_eq!(
        parse_polygon(&build(true, 3, None, &[flat])),
        Err(WkbError::Polygon(PolygonError::AllCollinear))
    );
    let nan: &[[f64; 2]] = &[[0.0, 0.0], [f64::NAN, 0.0], [1.0, 1.0], [0.0, 0.0]];
    assert!(matches!(
        parse_polygon(&build(true, 3, None, &[nan])),
        Err(WkbError::Polygon(PolygonError::NonFinite { index: 1, .. }))
    ));
    let msg = parse_polygon(&build(true, 3, None, &[dart]))
        .unwrap_err()
        .to_string();
    assert!(msg.starts_with("WKB ring is not a convex polygon"), "{msg}");
}

#[test]
fn huge_and_tiny_coordinates_are_read_exactly() {
    let big = f64::MAX / 2.0;
    let pts = [[-big, -big], [big, -big], [big, big], [-big, big]];
    let p = ConvexPolygon::new(pts).unwrap();
    assert_eq!(parse_polygon(&polygon_to_wkb(&p)), Ok(p));
    let t = f64::MIN_POSITIVE;
    let q = ConvexPolygon::new([[0.0, 0.0], [t, 0.0], [0.0, t]]).unwrap();
    assert_eq!(parse_polygon(&polygon_to_wkb(&q)), Ok(q));
}
