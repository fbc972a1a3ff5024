//! Conversions between polysect's polygons and `geo-types` polygons.
//!
//! A `geo_types::Polygon` converts to a [`ConvexPolygon`] through the same validation
//! as any vertex list (either orientation, closing vertex optional); interior rings are
//! refused, since a convex polygon has no holes. The other way, the exterior ring is
//! closed and counter-clockwise.

use crate::kernel::Point;
use crate::polygon::{ConvexPolygon, LinkedPolygon, PolygonError};

impl From<Point> for geo_types::Coord<f64> {
    fn from(p: Point) -> Self {
        geo_types::Coord { x: p.x, y: p.y }
    }
}

impl From<geo_types::Coord<f64>> for Point {
    fn from(c: geo_types::Coord<f64>) -> Self {
        Point::new(c.x, c.y)
    }
}

impl From<&ConvexPolygon> for geo_types::Polygon<f64> {
    fn from(p: &ConvexPolygon) -> Self {
        let ring: Vec<geo_types::Coord<f64>> = p.vertices().iter().map(|&v| v.into()).collect();
        geo_types::Polygon::new(geo_types::LineString::new(ring), vec![])
    }
}

impl From<&LinkedPolygon> for geo_types::Polygon<f64> {
    fn from(p: &LinkedPolygon) -> Self {
        (&p.to_convex()).into()
    }
}

impl TryFrom<&geo_types::Polygon<f64>> for ConvexPolygon {
    type Error = PolygonError;
    fn try_from(p: &geo_types::Polygon<f64>) -> Result<Self, Self::Error> {
        if !p.interiors().is_empty() {
            return Err(PolygonError::HasHoles {
                count: p.interiors().len(),
            });
        }
        ConvexPolygon::new(p.exterior().coords().map(|&c| Point::from(c)))
    }
}

impl TryFrom<&geo_types::Polygon<f64>> for LinkedPolygon {
    type Error = PolygonError;
    fn try_from(p: &geo_types::Polygon<f64>) -> Result<Self, Self::Error> {
        ConvexPolygon::try_from(p).map(|c| LinkedPolygon::from_convex(&c))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_through_geo_types() {
        let p = ConvexPolygon::new([[0., 0.], [0., 2.], [2., 2.], [2., 0.]]).unwrap();
        let g: geo_types::Polygon<f64> = (&p).into();
        assert_eq!(g.exterior().0.len(), 5, "geo closes the ring");
        let back = ConvexPolygon::try_from(&g).unwrap();
        assert_eq!(back, p);
        let l = LinkedPolygon::try_from(&g).unwrap();
        assert_eq!(l.to_convex(), p);
        let holed = geo_types::Polygon::new(g.exterior().clone(), vec![g.exterior().clone()]);
        assert_eq!(
            ConvexPolygon::try_from(&holed),
            Err(PolygonError::HasHoles { count: 1 })
        );
        let reflex = geo_types::Polygon::new(
            geo_types::LineString::from(vec![(0., 0.), (4., 0.), (4., 4.), (2., 1.), (0., 4.)]),
            vec![],
        );
        assert_eq!(
            ConvexPolygon::try_from(&reflex),
            Err(PolygonError::Reflex { index: 3 })
        );
    }
}
