use crate::kernel::Point;
use std::fmt;

/// Why a vertex list is not a valid convex polygon. Indices are positions in the
/// input list, counting from 0.
#[derive(Clone, Debug, PartialEq)]
pub enum PolygonError {
    /// A coordinate is NaN or infinite.
    NonFinite {
        /// Position of the vertex in the input list.
        index: usize,
        /// The vertex as given.
        point: Point,
    },
    /// Fewer than three distinct vertices after removing repeats.
    TooFewVertices {
        /// How many distinct vertices the list has.
        distinct: usize,
    },
    /// All vertices lie on one line: the region has no area.
    AllCollinear,
    /// The boundary runs along a line and comes back on itself at this vertex
    /// (a zero-width spike).
    DoublesBack {
        /// Position of the vertex in the input list.
        index: usize,
    },
    /// The boundary turns the other way at this vertex than at the others.
    Reflex {
        /// Position of the vertex in the input list.
        index: usize,
    },
    /// The vertices are in convex position but not listed in boundary order, so
    /// the boundary crosses itself (a bowtie); the turn at this vertex is wrong.
    OutOfOrder {
        /// Position of the vertex in the input list.
        index: usize,
    },
    /// Every turn goes the same way but the boundary winds around more than once
    /// (a star polygon such as the pentagram).
    WindsMoreThanOnce {
        /// How many times the boundary winds around its interior.
        times: usize,
    },
    /// A polygon with interior rings (holes) given where a convex polygon is expected.
    HasHoles {
        /// Number of interior rings.
        count: usize,
    },
    /// A shape constructor ([`ConvexPolygon::rectangle`](super::ConvexPolygon::rectangle)
    /// and its siblings) was given a parameter it cannot build a polygon from: not
    /// finite, a size that is zero or negative, fewer than three vertices, or a value
    /// for which rounding to `f64` would collapse the shape.
    BadParameter {
        /// The parameter's name, as in the constructor's signature.
        parameter: &'static str,
        /// What is wrong with it.
        reason: String,
    },
}

impl fmt::Display for PolygonError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PolygonError::NonFinite { index, point } => {
                write!(f, "vertex {index} has a non-finite coordinate {point}")
            }
            PolygonError::TooFewVertices { distinct } => write!(
                f,
                "a polygon needs at least 3 distinct vertices, found {distinct}"
            ),
            PolygonError::AllCollinear => {
                write!(f, "all vertices lie on one line: the polygon has no area")
            }
            PolygonError::DoublesBack { index } => write!(
                f,
                "vertex {index}: the boundary runs back along the line it came on"
            ),
            PolygonError::Reflex { index } => {
                write!(f, "vertex {index} is reflex: the polygon is not convex")
            }
            PolygonError::OutOfOrder { index } => write!(
                f,
                "vertex {index}: the vertices are not in boundary order (the boundary crosses itself)"
            ),
            PolygonError::WindsMoreThanOnce { times } => write!(
                f,
                "the boundary winds around {times} times; a convex polygon winds once"
            ),
            PolygonError::HasHoles { count } => {
                write!(
                    f,
                    "the polygon has {count} interior ring(s); a convex polygon has no holes"
                )
            }
            PolygonError::BadParameter { parameter, reason } => {
                write!(f, "parameter `{parameter}`: {reason}")
            }
        }
    }
}

impl std::error::Error for PolygonError {}

/// Why an edit of a [`LinkedPolygon`](super::LinkedPolygon) was refused. A refused
/// edit changes nothing.
#[derive(Clone, Debug, PartialEq)]
pub enum EditError {
    /// The handle names a vertex of this polygon that has been removed.
    StaleHandle,
    /// The handle belongs to another polygon (or to another copy of this one).
    ForeignHandle,
    /// The new point is NaN or infinite.
    NonFinite {
        /// The point as given.
        point: Point,
    },
    /// The polygon would stop being strictly convex: the new point is not in the
    /// region outside the edge and inside the lines through the neighbouring edges.
    WouldBreakConvexity {
        /// The point that was refused.
        point: Point,
    },
    /// A removal would leave fewer than three vertices.
    TooFewVertices,
    /// A translation would round the vertices (this one first, in counter-clockwise
    /// order) so that the polygon is no longer strictly convex.
    RoundingBreaksConvexity {
        /// The first vertex (counter-clockwise) whose rounded position breaks convexity.
        point: Point,
    },
}

/// Points print in their shortest round-trip form, with an exponent for huge and tiny
/// coordinates (see [`Point`]'s `Display`): a translation by `f64::MAX` reads
/// `(1.7976931348623157e308, 0)`, not a 309-digit number.
impl fmt::Display for EditError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            EditError::StaleHandle => write!(f, "the vertex handle is stale (the vertex was removed)"),
            EditError::ForeignHandle => write!(
                f,
                "the vertex handle belongs to another polygon, not to the one being queried or edited"
            ),
            EditError::NonFinite { point } => write!(f, "point {point} has a non-finite coordinate"),
            EditError::WouldBreakConvexity { point } => {
                write!(f, "placing a vertex at {point} would make the polygon non-convex")
            }
            EditError::TooFewVertices => {
                write!(f, "a polygon keeps at least 3 vertices; removal refused")
            }
            EditError::RoundingBreaksConvexity { point } => write!(
                f,
                "translation refused: rounding moves the vertex to {point} and the polygon would \
                 no longer be strictly convex"
            ),
        }
    }
}

impl std::error::Error for EditError {}
