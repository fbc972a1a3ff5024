//! The engines' probed entry points: what every algorithm implements once, generic
//! over a [`Probe`], and what the public traits' calls run with the unit probe `()`.
//!
//! [`ArrayIntersection`] and [`LinkedIntersection`] are what a library user calls; the
//! engines below add the probe (the thesis's iteration counts, the work counts, step
//! traces, the tests that count fallbacks) and the derivation a certified call
//! completes. They are an API with the `instrument` feature and crate-private without
//! it; [`array_entry_points!`] and [`linked_entry_points!`] write the public calls of
//! an algorithm as its engine's with `()`, so both run one body.

use super::{ArrayIntersection, Certificate, Derivation, LinkedIntersection, Probe};
use crate::kernel::{Kernel, Point};
use crate::polygon::{ConvexPolygon, LinkedPolygon};
use rand::Rng;

/// The completing searches the certified calls end with where a derivation gave only
/// the answer. Declared here and implemented for [`Completer`] in `fallback.rs`, whose
/// searches are algorithms' (Barba's witness, Dobkin's separation): so the engines'
/// default calls, and Barba's certified run that completes where it ends, reach them
/// without depending on the file that runs them.
pub(crate) trait Completion {
    /// The certificate of `derivation` for the polygons with vertices `pv` and `qv`,
    /// reporting each completion to `probe`.
    fn complete<K: Kernel, P: Probe>(
        k: K,
        pv: &[Point],
        qv: &[Point],
        derivation: Derivation,
        probe: &mut P,
    ) -> Certificate;

    /// [`complete`](Self::complete) for linked polygons (completed on the walked
    /// arrays).
    fn complete_linked<K: Kernel, P: Probe>(
        k: K,
        p: &LinkedPolygon,
        q: &LinkedPolygon,
        derivation: Derivation,
        probe: &mut P,
    ) -> Certificate;
}

/// The implementer of [`Completion`] (in `fallback.rs`).
pub(crate) struct Completer;

instrument_pub! {
    /// An array test's run reporting to a probe, and its derivation.
    trait ArrayEngine: ArrayIntersection {
        /// Whether `p` and `q` intersect, reporting each pruning iteration to `probe`.
        fn intersects_probed<K: Kernel, P: Probe>(
            &self,
            kernel: K,
            p: &ConvexPolygon,
            q: &ConvexPolygon,
            probe: &mut P,
        ) -> bool;

        /// The algorithm's run with what it can prove from its own findings: a
        /// certificate, or only the answer (docs/certificates.md says which exits give
        /// which).
        fn derive_probed<K: Kernel, P: Probe>(
            &self,
            kernel: K,
            p: &ConvexPolygon,
            q: &ConvexPolygon,
            probe: &mut P,
        ) -> Derivation;

        /// [`ArrayIntersection::certified_with`] reporting to `probe`: the derivation,
        /// completed where it gave only the answer (each completion is reported as a
        /// [`Fallback`](super::Fallback)).
        #[inline]
        fn certified_probed<K: Kernel, P: Probe>(
            &self,
            kernel: K,
            p: &ConvexPolygon,
            q: &ConvexPolygon,
            probe: &mut P,
        ) -> Certificate {
            let derivation = self.derive_probed(kernel, p, q, probe);
            Completer::complete(kernel, p.vertices(), q.vertices(), derivation, probe)
        }
    }
}

instrument_pub! {
    /// A linked test's run reporting to a probe, and its derivation.
    trait LinkedEngine: LinkedIntersection {
        /// Whether `p` and `q` intersect, with scratch memory from `workspace` (no
        /// allocation once it has grown to the largest input) and random draws from
        /// `rng`, reporting each unit of work to `probe`.
        fn intersects_in<K: Kernel, R: Rng + ?Sized, P: Probe>(
            &self,
            kernel: K,
            p: &LinkedPolygon,
            q: &LinkedPolygon,
            rng: &mut R,
            workspace: &mut Self::Workspace,
            probe: &mut P,
        ) -> bool;

        /// The test's run with what it can prove from its own findings: a certificate,
        /// or only the answer; arguments as [`intersects_in`](Self::intersects_in).
        fn derive_in<K: Kernel, R: Rng + ?Sized, P: Probe>(
            &self,
            kernel: K,
            p: &LinkedPolygon,
            q: &LinkedPolygon,
            rng: &mut R,
            workspace: &mut Self::Workspace,
            probe: &mut P,
        ) -> Derivation;

        /// [`LinkedIntersection::certified_with_workspace`] reporting to `probe`: the
        /// derivation, completed on the walked arrays (O(n + m)) where it gave only the
        /// answer; the probe also hears of each completion.
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
            Completer::complete_linked(kernel, p, q, derivation, probe)
        }
    }
}

/// The [`ArrayIntersection`] calls of an algorithm that implements [`ArrayEngine`]:
/// its engine's, with the unit probe. `certified` takes `all` (both calls) or `plain`
/// (only `intersects_with`, for an algorithm that writes its own certified call).
macro_rules! array_entry_points {
    (plain) => {
        #[inline]
        fn intersects_with<K: $crate::kernel::Kernel>(
            &self,
            kernel: K,
            p: &$crate::polygon::ConvexPolygon,
            q: &$crate::polygon::ConvexPolygon,
        ) -> bool {
            $crate::intersect::engine::ArrayEngine::intersects_probed(self, kernel, p, q, &mut ())
        }
    };
    (all) => {
        $crate::intersect::engine::array_entry_points!(plain);

        #[inline]
        fn certified_with<K: $crate::kernel::Kernel>(
            &self,
            kernel: K,
            p: &$crate::polygon::ConvexPolygon,
            q: &$crate::polygon::ConvexPolygon,
        ) -> $crate::intersect::Certificate {
            $crate::intersect::engine::ArrayEngine::certified_probed(self, kernel, p, q, &mut ())
        }
    };
}

/// The required [`LinkedIntersection`] calls of an algorithm that implements
/// [`LinkedEngine`]: its engine's, with the unit probe.
macro_rules! linked_entry_points {
    () => {
        #[inline]
        fn intersects_with_workspace<K: $crate::kernel::Kernel, R: $crate::rand::Rng + ?Sized>(
            &self,
            kernel: K,
            p: &$crate::polygon::LinkedPolygon,
            q: &$crate::polygon::LinkedPolygon,
            rng: &mut R,
            workspace: &mut Self::Workspace,
        ) -> bool {
            $crate::intersect::engine::LinkedEngine::intersects_in(
                self,
                kernel,
                p,
                q,
                rng,
                workspace,
                &mut (),
            )
        }

        #[inline]
        fn certified_with_workspace<K: $crate::kernel::Kernel, R: $crate::rand::Rng + ?Sized>(
            &self,
            kernel: K,
            p: &$crate::polygon::LinkedPolygon,
            q: &$crate::polygon::LinkedPolygon,
            rng: &mut R,
            workspace: &mut Self::Workspace,
        ) -> $crate::intersect::Certificate {
            $crate::intersect::engine::LinkedEngine::certified_in(self, kernel, p, q, rng, workspace, &mut ())
        }
    };
}

pub(crate) use {array_entry_points, linked_entry_points};
