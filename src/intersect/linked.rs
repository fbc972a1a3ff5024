//! Intersection tests on [`LinkedPolygon`]s ([`LinkedIntersection`]) and [`Convert`],
//! the naive path: walk both linked lists into sorted arrays, then run an array test.
//!
//! Convert is the baseline the sublinear test ([`Clm`](super::Clm)) is measured
//! against (thesis 4.4, Figure 4.8): O(n) for the walk whatever the array algorithm
//! costs, but with a small constant, so it wins on small polygons.

use super::fallback::complete_linked;
use super::{ArrayIntersection, Barba, Certificate, Derivation, Probe};
use crate::kernel::{Exact, Kernel, Point};
use crate::polygon::{ConvexPolygon, LinkedPolygon};
use crate::seeding::fresh_rng;
use rand::Rng;
use rand::SeedableRng;
use rand::rngs::SmallRng;

/// An intersection test on two convex polygons stored as linked lists in arenas.
///
/// Randomized tests draw from the caller's RNG; their answer never depends on the draw
/// (under [`Exact`]), only their running time does.
pub trait LinkedIntersection {
    /// The name used by the CLI's `--algorithm` and by benches.
    const NAME: &'static str;
    /// Scratch memory reused across queries (buffers, sampling marks).
    type Workspace: Default;

    /// Whether `p` and `q` intersect, with scratch memory from `workspace` (no allocation
    /// once it has grown to the largest input) and random draws from `rng`, reporting
    /// each unit of work to `probe`.
    fn intersects_in<K: Kernel, R: Rng + ?Sized, P: Probe>(
        &self,
        kernel: K,
        p: &LinkedPolygon,
        q: &LinkedPolygon,
        rng: &mut R,
        workspace: &mut Self::Workspace,
        probe: &mut P,
    ) -> bool;

    /// [`intersects_in`](Self::intersects_in) without a probe.
    #[inline]
    fn intersects_with_workspace<K: Kernel, R: Rng + ?Sized>(
        &self,
        kernel: K,
        p: &LinkedPolygon,
        q: &LinkedPolygon,
        rng: &mut R,
        workspace: &mut Self::Workspace,
    ) -> bool {
        self.intersects_in(kernel, p, q, rng, workspace, &mut ())
    }

    /// A one-off query: a fresh workspace and a generator seeded from the operating
    /// system, so which vertices a randomized test samples cannot be known in advance
    /// (the expected bounds hold for every input chosen without seeing the draw; without
    /// the `os-rng` feature, seeded from a counter instead: docs/design.md). The
    /// answer never depends on the draw under [`Exact`]; use
    /// [`intersects_seeded`](Self::intersects_seeded) to reproduce a run exactly.
    fn intersects_with<K: Kernel>(&self, kernel: K, p: &LinkedPolygon, q: &LinkedPolygon) -> bool {
        self.intersects_in(
            kernel,
            p,
            q,
            &mut fresh_rng(),
            &mut Self::Workspace::default(),
            &mut (),
        )
    }

    /// A one-off query with a generator seeded with `seed`: the same draws every time
    /// (reproducible timings and fast-kernel answers). Whoever knows the seed knows the
    /// sample, so inputs chosen with that knowledge can defeat the expected bounds
    /// (never the answer).
    ///
    /// ```
    /// use polysect::intersect::{Clm, LinkedIntersection};
    /// use polysect::{Exact, LinkedPolygon};
    /// let p = LinkedPolygon::from_points([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
    /// let q = LinkedPolygon::from_points([[2.0, 2.0], [3.0, 2.0], [3.0, 3.0]])?;
    /// assert!(Clm.intersects_seeded(Exact, &p, &q, 42));
    /// # Ok::<(), polysect::PolygonError>(())
    /// ```
    fn intersects_seeded<K: Kernel>(
        &self,
        kernel: K,
        p: &LinkedPolygon,
        q: &LinkedPolygon,
        seed: u64,
    ) -> bool {
        let mut rng = SmallRng::seed_from_u64(seed);
        self.intersects_in(kernel, p, q, &mut rng, &mut Self::Workspace::default(), &mut ())
    }

    /// A one-off query with the exact kernel.
    fn intersects(&self, p: &LinkedPolygon, q: &LinkedPolygon) -> bool {
        self.intersects_with(Exact, p, q)
    }

    /// The test's run with what it can prove from its own findings: a certificate, or
    /// only the answer; arguments as [`intersects_in`](Self::intersects_in).
    fn derive_in<K: Kernel, R: Rng + ?Sized, P: Probe>(
        &self,
        kernel: K,
        p: &LinkedPolygon,
        q: &LinkedPolygon,
        rng: &mut R,
        workspace: &mut Self::Workspace,
        probe: &mut P,
    ) -> Derivation;

    /// The answer with a [`Certificate`] that proves it ([`verify_linked`] checks it):
    /// the test's own ([`derive_in`](Self::derive_in)), completed on the walked arrays
    /// (O(n + m)) where it gave only the answer; arguments as
    /// [`intersects_in`](Self::intersects_in). The probe also hears of each fallback.
    ///
    /// # Precision
    /// Under [`Exact`] the certificate always verifies; under an inconsistent kernel it
    /// may not (see [`ArrayIntersection::certified_probed`]).
    ///
    /// [`verify_linked`]: super::verify_linked
    #[inline]
    fn certified_in<K: Kernel, R: Rng + ?Sized, P: Probe>(
        &self,
        kernel: K,
        p: &LinkedPolygon,
        q: &LinkedPolygon,
        rng: &mut R,
        workspace: &mut Self::Workspace,
        probe: &mut P,
    ) -> Certificate {
        let derivation = self.derive_in(kernel, p, q, rng, workspace, probe);
        complete_linked(kernel, p, q, derivation, probe)
    }

    /// [`certified_in`](Self::certified_in) without a probe.
    #[inline]
    fn certified_with_workspace<K: Kernel, R: Rng + ?Sized>(
        &self,
        kernel: K,
        p: &LinkedPolygon,
        q: &LinkedPolygon,
        rng: &mut R,
        workspace: &mut Self::Workspace,
    ) -> Certificate {
        self.certified_in(kernel, p, q, rng, workspace, &mut ())
    }

    /// A one-off certified query: a fresh workspace and a generator seeded from the
    /// operating system, as [`intersects_with`](Self::intersects_with).
    fn certified_with<K: Kernel>(&self, kernel: K, p: &LinkedPolygon, q: &LinkedPolygon) -> Certificate {
        self.certified_in(
            kernel,
            p,
            q,
            &mut fresh_rng(),
            &mut Self::Workspace::default(),
            &mut (),
        )
    }

    /// A one-off certified query with a generator seeded with `seed`, as
    /// [`intersects_seeded`](Self::intersects_seeded).
    fn certified_seeded<K: Kernel>(
        &self,
        kernel: K,
        p: &LinkedPolygon,
        q: &LinkedPolygon,
        seed: u64,
    ) -> Certificate {
        let mut rng = SmallRng::seed_from_u64(seed);
        self.certified_in(kernel, p, q, &mut rng, &mut Self::Workspace::default(), &mut ())
    }

    /// A one-off certified query with the exact kernel.
    fn certified(&self, p: &LinkedPolygon, q: &LinkedPolygon) -> Certificate {
        self.certified_with(Exact, p, q)
    }
}

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

    /// The array algorithm's derivation on the walked arrays: coordinates are the
    /// vertices themselves, so its certificate holds for the linked polygons.
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
