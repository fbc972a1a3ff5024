//! Intersection tests on [`LinkedPolygon`]s: the [`LinkedIntersection`] trait, which
//! [`Clm`](super::Clm), [`Convert`](super::Convert) and
//! [`LinearLinked`](super::LinearLinked) implement.

use super::Certificate;
use crate::kernel::{Exact, Kernel};
use crate::polygon::LinkedPolygon;
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
    /// once it has grown to the largest input) and random draws from `rng`.
    fn intersects_with_workspace<K: Kernel, R: Rng + ?Sized>(
        &self,
        kernel: K,
        p: &LinkedPolygon,
        q: &LinkedPolygon,
        rng: &mut R,
        workspace: &mut Self::Workspace,
    ) -> bool;

    /// A one-off query: a fresh workspace and a generator seeded from the operating
    /// system, so which vertices a randomized test samples cannot be known in advance
    /// (the expected bounds hold for every input chosen without seeing the draw; without
    /// the `os-rng` feature, seeded from a counter instead: docs/design.md). The
    /// answer never depends on the draw under [`Exact`]; use
    /// [`intersects_seeded`](Self::intersects_seeded) to reproduce a run exactly.
    fn intersects_with<K: Kernel>(&self, kernel: K, p: &LinkedPolygon, q: &LinkedPolygon) -> bool {
        self.intersects_with_workspace(kernel, p, q, &mut fresh_rng(), &mut Self::Workspace::default())
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
        self.intersects_with_workspace(kernel, p, q, &mut rng, &mut Self::Workspace::default())
    }

    /// A one-off query with the exact kernel.
    fn intersects(&self, p: &LinkedPolygon, q: &LinkedPolygon) -> bool {
        self.intersects_with(Exact, p, q)
    }

    /// The answer with a [`Certificate`] that proves it ([`verify_linked`] checks it):
    /// the test's own, completed on the walked arrays (O(n + m)) where the test found
    /// only the answer; arguments as
    /// [`intersects_with_workspace`](Self::intersects_with_workspace).
    ///
    /// # Precision
    /// Under [`Exact`] the certificate always verifies; under an inconsistent kernel it
    /// may not (see [`ArrayIntersection::certified_with`](super::ArrayIntersection::certified_with)).
    ///
    /// [`verify_linked`]: super::verify_linked
    fn certified_with_workspace<K: Kernel, R: Rng + ?Sized>(
        &self,
        kernel: K,
        p: &LinkedPolygon,
        q: &LinkedPolygon,
        rng: &mut R,
        workspace: &mut Self::Workspace,
    ) -> Certificate;

    /// A one-off certified query: a fresh workspace and a generator seeded from the
    /// operating system, as [`intersects_with`](Self::intersects_with).
    fn certified_with<K: Kernel>(&self, kernel: K, p: &LinkedPolygon, q: &LinkedPolygon) -> Certificate {
        self.certified_with_workspace(kernel, p, q, &mut fresh_rng(), &mut Self::Workspace::default())
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
        self.certified_with_workspace(kernel, p, q, &mut rng, &mut Self::Workspace::default())
    }

    /// A one-off certified query with the exact kernel.
    fn certified(&self, p: &LinkedPolygon, q: &LinkedPolygon) -> Certificate {
        self.certified_with(Exact, p, q)
    }
}
