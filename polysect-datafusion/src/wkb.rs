//! Well-Known Binary (WKB) polygons to and from [`ConvexPolygon`].
//!
//! Reads one geometry type: a 2D `Polygon` (ISO type code 3, or the EWKB form with the
//! SRID flag `0x20000000`, whose SRID is skipped) with exactly one ring, in either byte
//! order. Everything else is refused with a [`WkbError`] saying what was found and at
//! which byte: other geometry types (multipolygons included), Z and M coordinates,
//! empty polygons, holes, rings that are not closed or that are too short, and rings
//! that are not strictly convex polygons (the [`PolygonError`] from
//! [`ConvexPolygon::new`], with the vertex index counted in the ring).
//!
//! # Complexity
//! O(n) for a ring of n points, plus [`ConvexPolygon::new`]'s validation (O(n); its
//! error reporting for an out-of-order ring costs O(n log n)). Nothing is allocated
//! before the declared point count is checked against the bytes present, so a lying
//! header cannot make the parser allocate more than the input's size.
//!
//! # Degeneracies
//! The closing point must equal the first point bit for bit (`-0.0` and `0.0` are
//! equal); it is dropped. Repeated and collinear points inside the ring are cleaned by
//! [`ConvexPolygon::new`], so a ring with a vertex in the middle of an edge reads as the
//! polygon without it. Either orientation is accepted.
//!
//! # Precision
//! Coordinates are read as the `f64`s they are; nothing is rounded.

use polysect::{ConvexPolygon, Point, PolygonError};
use std::fmt;

/// Why a byte string is not a WKB polygon this crate reads. Offsets count bytes from
/// the start of the value.
#[derive(Clone, Debug, PartialEq)]
pub enum WkbError {
    /// The value ends before the field that starts at `offset`.
    Truncated {
        /// Where the missing field starts.
        offset: usize,
        /// What was being read.
        field: &'static str,
    },
    /// The byte-order byte is neither 0 (big endian) nor 1 (little endian).
    ByteOrder {
        /// The byte found.
        byte: u8,
    },
    /// A geometry type other than a 2D polygon.
    GeometryType {
        /// The type code as read (EWKB flags included).
        code: u32,
    },
    /// A polygon with no rings (`POLYGON EMPTY`).
    Empty,
    /// A polygon with interior rings.
    Holes {
        /// How many interior rings it has.
        count: u32,
    },
    /// The ring has fewer than four points (a closed ring needs three corners and the
    /// closing point).
    RingTooShort {
        /// How many points it has.
        points: u32,
    },
    /// The ring's last point differs from its first.
    RingNotClosed,
    /// Bytes follow the polygon.
    TrailingBytes {
        /// Where they start.
        offset: usize,
    },
    /// The ring is not a strictly convex polygon (indices count points in the ring).
    Polygon(PolygonError),
}

impl fmt::Display for WkbError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            WkbError::Truncated { offset, field } => {
                write!(f, "WKB ends at byte {offset}, before the {field}")
            }
            WkbError::ByteOrder { byte } => {
                write!(
                    f,
                    "WKB byte-order byte is {byte}, not 0 (big endian) or 1 (little endian)"
                )
            }
            WkbError::GeometryType { code } => {
                write!(
                    f,
                    "WKB geometry type {code} ({}) is not a 2D Polygon (3)",
                    type_name(*code)
                )
            }
            WkbError::Empty => write!(f, "WKB polygon is empty (no rings)"),
            WkbError::Holes { count } => {
                write!(
                    f,
                    "WKB polygon has {count} interior ring(s); a convex polygon has none"
                )
            }
            WkbError::RingTooShort { points } => {
                write!(
                    f,
                    "WKB ring has {points} point(s); a closed ring needs at least 4"
                )
            }
            WkbError::RingNotClosed => {
                write!(f, "WKB ring is not closed (last point differs from the first)")
            }
            WkbError::TrailingBytes { offset } => {
                write!(f, "WKB has bytes after the polygon, from byte {offset}")
            }
            WkbError::Polygon(e) => write!(f, "WKB ring is not a convex polygon: {e}"),
        }
    }
}

impl std::error::Error for WkbError {}

/// A readable name for a WKB type code, for error messages.
fn type_name(code: u32) -> String {
    let flags = code & 0xF000_0000;
    let iso = code & 0x0FFF_FFFF;
    let (base, dims) = (iso % 1000, iso / 1000);
    let name = match base {
        0 => "Geometry",
        1 => "Point",
        2 => "LineString",
        3 => "Polygon",
        4 => "MultiPoint",
        5 => "MultiLineString",
        6 => "MultiPolygon",
        7 => "GeometryCollection",
        15 => "PolyhedralSurface",
        16 => "TIN",
        17 => "Triangle",
        _ => "unknown type",
    };
    let mut dim = match dims {
        0 => "",
        1 => " Z",
        2 => " M",
        3 => " ZM",
        _ => " (unknown dimensions)",
    }
    .to_string();
    if flags & 0x8000_0000 != 0 {
        dim.push_str(" Z (EWKB)");
    }
    if flags & 0x4000_0000 != 0 {
        dim.push_str(" M (EWKB)");
    }
    format!("{name}{dim}")
}

/// A cursor over the value that reads fields in the value's byte order.
struct Reader<'a> {
    bytes: &'a [u8],
    at: usize,
    little: bool,
}

impl Reader<'_> {
    fn take<const N: usize>(&mut self, field: &'static str) -> Result<[u8; N], WkbError> {
        let end = self.at.checked_add(N).filter(|&e| e <= self.bytes.len());
        let Some(end) = end else {
            return Err(WkbError::Truncated {
                offset: self.at,
                field,
            });
        };
        let mut out = [0; N];
        out.copy_from_slice(&self.bytes[self.at..end]);
        self.at = end;
        Ok(out)
    }

    fn u32(&mut self, field: &'static str) -> Result<u32, WkbError> {
        let b = self.take::<4>(field)?;
        Ok(if self.little {
            u32::from_le_bytes(b)
        } else {
            u32::from_be_bytes(b)
        })
    }

    fn f64(&mut self, field: &'static str) -> Result<f64, WkbError> {
        let b = self.take::<8>(field)?;
        Ok(if self.little {
            f64::from_le_bytes(b)
        } else {
            f64::from_be_bytes(b)
        })
    }
}

/// The EWKB flag saying a 4-byte SRID follows the type code.
const EWKB_SRID: u32 = 0x2000_0000;

/// The ring's points as written, closing point included, after checking the header.
fn read_ring(bytes: &[u8]) -> Result<Vec<Point>, WkbError> {
    let Some(&order) = bytes.first() else {
        return Err(WkbError::Truncated {
            offset: 0,
            field: "byte-order byte",
        });
    };
    let little = match order {
        0 => false,
        1 => true,
        byte => return Err(WkbError::ByteOrder { byte }),
    };
    let mut r = Reader { bytes, at: 1, little };
    let code = r.u32("geometry type")?;
    if code & !EWKB_SRID != 3 {
        return Err(WkbError::GeometryType { code });
    }
    if code & EWKB_SRID != 0 {
        r.u32("SRID")?;
    }
    let rings = r.u32("ring count")?;
    match rings {
        0 => return Err(WkbError::Empty),
        1 => {}
        n => return Err(WkbError::Holes { count: n - 1 }),
    }
    let points = r.u32("point count")?;
    if points < 4 {
        return Err(WkbError::RingTooShort { points });
    }
    // Check the declared count against the bytes present before allocating.
    let need = (points as usize).saturating_mul(16);
    if bytes.len() - r.at < need {
        let whole = (bytes.len() - r.at) / 16;
        return Err(WkbError::Truncated {
            offset: r.at + whole * 16,
            field: "ring's points",
        });
    }
    let mut ring = Vec::with_capacity(points as usize);
    for _ in 0..points {
        let x = r.f64("x coordinate")?;
        let y = r.f64("y coordinate")?;
        ring.push(Point::new(x, y));
    }
    if r.at != bytes.len() {
        return Err(WkbError::TrailingBytes { offset: r.at });
    }
    Ok(ring)
}

/// Reads a WKB polygon as a validated [`ConvexPolygon`].
///
/// # Errors
/// A [`WkbError`] for anything but a closed single-ring 2D polygon whose ring is a
/// strictly convex polygon after cleaning (see the module docs).
///
/// ```
/// use polysect_datafusion::wkb::{parse_polygon, polygon_to_wkb};
/// use polysect::ConvexPolygon;
/// let p = ConvexPolygon::new([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])?;
/// assert_eq!(parse_polygon(&polygon_to_wkb(&p))?, p);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn parse_polygon(bytes: &[u8]) -> Result<ConvexPolygon, WkbError> {
    let mut ring = read_ring(bytes)?;
    let (first, last) = (ring[0], ring[ring.len() - 1]);
    if first.x != last.x || first.y != last.y {
        return Err(WkbError::RingNotClosed);
    }
    ring.pop();
    ConvexPolygon::new(ring).map_err(WkbError::Polygon)
}

/// Writes `points` as a little-endian WKB polygon with one ring, closing it.
///
/// Nothing is checked: this writes test input too, invalid rings included.
pub fn ring_to_wkb(points: &[Point]) -> Vec<u8> {
    let closed = points.len() + usize::from(!points.is_empty());
    let mut out = Vec::with_capacity(13 + 16 * closed);
    out.push(1);
    out.extend_from_slice(&3u32.to_le_bytes());
    out.extend_from_slice(&1u32.to_le_bytes());
    out.extend_from_slice(&(closed as u32).to_le_bytes());
    for p in points.iter().chain(points.first()) {
        out.extend_from_slice(&p.x.to_le_bytes());
        out.extend_from_slice(&p.y.to_le_bytes());
    }
    out
}

/// Writes a convex polygon as a little-endian WKB polygon (counter-clockwise, closed).
pub fn polygon_to_wkb(p: &ConvexPolygon) -> Vec<u8> {
    ring_to_wkb(p.vertices())
}

#[cfg(test)]
mod tests;
