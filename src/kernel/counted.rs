//! [`Counted`]: a kernel that counts the predicates it is asked, for experiments that
//! measure work in predicates rather than in seconds (a research instrument, behind the
//! `instrument` feature).
//!
//! # Complexity
//! One thread-local increment per predicate on top of the wrapped kernel's cost.
//!
//! # Precision
//! Exactly the wrapped kernel's answers: every call is forwarded unchanged, and the
//! kernel of [`within`](Kernel::within) is the wrapped kernel's, counted too.

use super::{BoundingBox, DirectedLine, Kernel, Orientation, Point, Polynomial, Sign};
use std::cell::Cell;

thread_local! {
    static PREDICATES: Cell<u64> = const { Cell::new(0) };
}

/// `K`, counting each predicate it decides (`orient`, `cross`, `dot`, the degree-4
/// sign and their variants, each one call) in a counter of the calling thread, which
/// [`Counted::take`] reads and resets. The counter is shared by every `Counted` kernel
/// on the thread, whatever `K`.
///
/// ```
/// use polysect::kernel::Counted;
/// use polysect::{ConvexPolygon, Exact, Point};
/// use polysect::intersect::{ArrayIntersection, Barba};
/// let p = ConvexPolygon::new([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
/// let q = p.map(|v| Point::new(v.x + 3.0, v.y))?;
/// Counted::<Exact>::take();
/// assert!(!Barba.intersects_with(Counted(Exact), &p, &q));
/// let predicates = Counted::<Exact>::take();
/// assert!(predicates > 0);
/// assert_eq!(Counted::<Exact>::take(), 0);
/// # Ok::<(), polysect::PolygonError>(())
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Counted<K>(pub K);

impl<K> Counted<K> {
    /// The predicates counted on this thread since the last call, resetting the count.
    pub fn take() -> u64 {
        PREDICATES.with(|n| n.replace(0))
    }
}

#[inline]
fn count() {
    PREDICATES.with(|n| n.set(n.get() + 1));
}

impl<K: Kernel> Kernel for Counted<K> {
    const NAME: &'static str = K::NAME;

    #[inline]
    fn orient(self, a: Point, b: Point, c: Point) -> Orientation {
        count();
        self.0.orient(a, b, c)
    }

    #[inline]
    fn cross(self, a: Point, b: Point, c: Point, d: Point) -> Orientation {
        count();
        self.0.cross(a, b, c, d)
    }

    #[inline]
    fn dot(self, a: Point, b: Point, c: Point, d: Point) -> Sign {
        count();
        self.0.dot(a, b, c, d)
    }
}

impl<K: Kernel> crate::kernel::sealed::Predicates for Counted<K> {
    const EXACT: bool = K::EXACT;

    type Within = Counted<K::Within>;

    #[inline]
    fn within(self, boxes: [BoundingBox; 2]) -> Self::Within {
        Counted(self.0.within(boxes))
    }

    #[inline]
    fn within_differences(self, w: f64) -> Self::Within {
        Counted(self.0.within_differences(w))
    }

    #[inline]
    fn orient_line(self, line: &DirectedLine, c: Point) -> Orientation {
        count();
        self.0.orient_line(line, c)
    }

    #[inline]
    fn sign<P: Polynomial>(self, poly: &P) -> Sign {
        count();
        self.0.sign(poly)
    }

    #[inline]
    fn cross_of_short_edges(self, a: Point, b: Point, c: Point, d: Point) -> Orientation {
        count();
        self.0.cross_of_short_edges(a, b, c, d)
    }

    #[inline]
    fn cross_products_sign(self, factors: [[Point; 4]; 4]) -> Sign {
        count();
        self.0.cross_products_sign(factors)
    }

    #[inline]
    fn cross_products_sign_of_short_edges(self, factors: [[Point; 4]; 4]) -> Sign {
        count();
        self.0.cross_products_sign_of_short_edges(factors)
    }

    #[inline]
    fn within_short_edges(self, e: impl FnOnce() -> f64) -> Self {
        Counted(self.0.within_short_edges(e))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::sealed::Predicates as _;
    use crate::kernel::{Exact, Fast};

    #[test]
    fn counts_each_predicate_once_and_answers_as_the_kernel() {
        let (a, b, c, d) = (
            Point::new(0.0, 0.0),
            Point::new(1.0, 0.0),
            Point::new(0.0, 1.0),
            Point::new(1.0, 1.0),
        );
        Counted::<Exact>::take();
        let k = Counted(Exact);
        assert_eq!(k.orient(a, b, c), Exact.orient(a, b, c));
        assert_eq!(k.cross(a, b, c, d), Exact.cross(a, b, c, d));
        assert_eq!(k.dot(a, b, c, d), Exact.dot(a, b, c, d));
        assert_eq!(
            Counted::<Fast>::take(),
            3,
            "one count per call, shared by every K"
        );
        let w = k.within([BoundingBox::new(a, d), BoundingBox::new(a, d)]);
        assert_eq!(w.orient(a, d, b), Orientation::Cw);
        assert_eq!(Counted::<Exact>::take(), 1);
        // Another thread's counter is its own.
        std::thread::scope(|s| {
            s.spawn(|| {
                Counted(Fast).orient(a, b, c);
                assert_eq!(Counted::<Fast>::take(), 1);
            });
        });
        assert_eq!(Counted::<Exact>::take(), 0);
    }
}
