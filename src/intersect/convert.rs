//! [`Convert`], the naive path for linked polygons: walk both lists into sorted arrays,
//! then run an array test.
//!
//! Convert is the baseline the sublinear test ([`Clm`](super::Clm)) is measured
//! against (thesis 4.4, Figure 4.8): O(n) for the walk whatever the array algorithm
//! costs, but with a small constant, so it wins on small polygons.

use super::engine::{ArrayEngine, LinkedEngine};
use super::{ArrayIntersection, Barba, Certificate, Derivation, LinkedIntersection, Probe};
use crate::kernel::{Kernel, Point};
use crate::polygon::{ConvexPolygon, LinkedPolygon};
use rand::Rng;

/// Walks both linked lists into sorted arrays (O(n + m)) and runs the array test `A`.
///
/// # Complexity
/// O(n + m) for the walks (each step a dependent load at a random arena position)
/// plus the cost of `A`.
///
/// # Degeneracies and precision
/// Those of `A`: the walk itself decides nothing.
///
/// ```
/// use polysect::LinkedPolygon;
/// use polysect::intersect::{Convert, LinkedIntersection};
/// let p = LinkedPolygon::from_points([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
/// let q = LinkedPolygon::from_points([[2.0, 2.0], [3.0, 2.0], [3.0, 3.0]])?;
/// assert!(Convert::default().intersects(&p, &q)); // a shared vertex
/// # Ok::<(), polysect::PolygonError>(())
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Convert<A: ArrayIntersection = Barba>(pub A);

/// [`Convert`] with its default array algorithm, [`Barba`]: the one `Default`, so that
/// `Convert::default()` needs no type annotation (another algorithm: `Convert(Dobkin)`).
impl Default for Convert {
    #[inline]
    fn default() -> Self {
        Convert(Barba)
    }
}

/// Reusable arrays for [`Convert`].
#[derive(Clone, Debug, Default)]
pub struct ConvertWorkspace {
    p: Vec<Point>,
    q: Vec<Point>,
}

/// Appends the boundary of `poly` counter-clockwise, walking positions.
fn walk_into(poly: &LinkedPolygon, out: &mut Vec<Point>) {
    out.clear();
    out.reserve(poly.len());
    let mut pos = 0;
    for _ in 0..poly.len() {
        out.push(poly.point_at(pos));
        pos = poly.next_at(pos);
    }
}

impl<A: ArrayIntersection> LinkedIntersection for Convert<A> {
    const NAME: &'static str = "convert";
    type Workspace = ConvertWorkspace;

    fn intersects_with_workspace<K: Kernel, R: Rng + ?Sized>(
        &self,
        kernel: K,
        p: &LinkedPolygon,
        q: &LinkedPolygon,
        _rng: &mut R,
        ws: &mut ConvertWorkspace,
    ) -> bool {
        self.walked(p, q, ws, |pa, qa| self.0.intersects_with(kernel, pa, qa))
    }

    /// As the array algorithm's certified call on the walked arrays: coordinates are
    /// the vertices themselves, so its certificate holds for the linked polygons.
    fn certified_with_workspace<K: Kernel, R: Rng + ?Sized>(
        &self,
        kernel: K,
        p: &LinkedPolygon,
        q: &LinkedPolygon,
        _rng: &mut R,
        ws: &mut ConvertWorkspace,
    ) -> Certificate {
        self.walked(p, q, ws, |pa, qa| self.0.certified_with(kernel, pa, qa))
    }
}

impl<A: ArrayEngine> LinkedEngine for Convert<A> {
    fn intersects_in<K: Kernel, R: Rng + ?Sized, P: Probe>(
        &self,
        kernel: K,
        p: &LinkedPolygon,
        q: &LinkedPolygon,
        _rng: &mut R,
        ws: &mut ConvertWorkspace,
        probe: &mut P,
    ) -> bool {
        self.walked(p, q, ws, |pa, qa| self.0.intersects_probed(kernel, pa, qa, probe))
    }

    /// The array algorithm's derivation on the walked arrays.
    fn derive_in<K: Kernel, R: Rng + ?Sized, P: Probe>(
        &self,
        kernel: K,
        p: &LinkedPolygon,
        q: &LinkedPolygon,
        _rng: &mut R,
        ws: &mut ConvertWorkspace,
        probe: &mut P,
    ) -> Derivation {
        self.walked(p, q, ws, |pa, qa| self.0.derive_probed(kernel, pa, qa, probe))
    }

    /// As the array algorithm's certified call on the walked arrays.
    fn certified_in<K: Kernel, R: Rng + ?Sized, P: Probe>(
        &self,
        kernel: K,
        p: &LinkedPolygon,
        q: &LinkedPolygon,
        _rng: &mut R,
        ws: &mut ConvertWorkspace,
        probe: &mut P,
    ) -> Certificate {
        self.walked(p, q, ws, |pa, qa| self.0.certified_probed(kernel, pa, qa, probe))
    }
}

impl<A: ArrayIntersection> Convert<A> {
    /// Walks both lists into the workspace's arrays and runs `f` on them.
    fn walked<T>(
        &self,
        p: &LinkedPolygon,
        q: &LinkedPolygon,
        ws: &mut ConvertWorkspace,
        f: impl FnOnce(&ConvexPolygon, &ConvexPolygon) -> T,
    ) -> T {
        walk_into(p, &mut ws.p);
        walk_into(q, &mut ws.q);
        // The linked polygon is strictly convex and counter-clockwise by invariant.
        let pa = ConvexPolygon::from_ccw_unchecked(std::mem::take(&mut ws.p));
        let qa = ConvexPolygon::from_ccw_unchecked(std::mem::take(&mut ws.q));
        let out = f(&pa, &qa);
        ws.p = pa.into_vertices();
        ws.q = qa.into_vertices();
        out
    }
}
