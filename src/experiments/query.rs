//! A pair prepared for repeated queries: arrays, linked copies in shuffled arena order,
//! workspaces and an RNG, so a timed loop measures the query alone.

use crate::intersect::{
    Algorithm, ArrayIntersection, Barba, ChazelleDobkin, Clm, ClmVariant, ClmWithFactor, ClmWorkspace,
    Convert, ConvertWorkspace, Counts, Dobkin, Iterations, Linear, Probe,
};
use crate::intersect::{ArrayEngine, LinkedEngine};
use crate::kernel::{Exact, Fast, Kernel, Precision};
use crate::polygon::{ConvexPolygon, LinkedPolygon};
use rand::SeedableRng;
use rand::rngs::SmallRng;

/// Both kernels, for loops over [`Precision::ALL`].
pub type Kernels = [Precision; 2];

/// Two array polygons, their linked copies, and the scratch memory of the linked tests.
pub struct PreparedPair {
    pub p: ConvexPolygon,
    pub q: ConvexPolygon,
    lp: LinkedPolygon,
    lq: LinkedPolygon,
    rng: SmallRng,
    clm: ClmWorkspace,
    convert: ConvertWorkspace,
    /// The exact answer ([`Linear`] under [`Exact`]).
    pub truth: bool,
}

impl PreparedPair {
    /// Links `p` and `q` in shuffled arena order (seeded by `seed`) and computes the
    /// exact answer.
    pub fn new(p: ConvexPolygon, q: ConvexPolygon, seed: u64) -> PreparedPair {
        let mut rng = SmallRng::seed_from_u64(seed);
        let lp = LinkedPolygon::from_convex_shuffled(&p, &mut rng);
        let lq = LinkedPolygon::from_convex_shuffled(&q, &mut rng);
        let truth = Linear.intersects_with(Exact, &p, &q);
        PreparedPair {
            p,
            q,
            lp,
            lq,
            rng,
            clm: ClmWorkspace::default(),
            convert: ConvertWorkspace::default(),
            truth,
        }
    }

    /// Vertices of the larger polygon.
    pub fn n(&self) -> usize {
        self.p.len().max(self.q.len())
    }

    /// Runs `alg` once under `precision`.
    #[inline]
    pub fn query(&mut self, alg: Algorithm, precision: Precision) -> bool {
        match precision {
            Precision::Fast => self.query_probed(alg, Fast, &mut ()),
            Precision::Exact => self.query_probed(alg, Exact, &mut ()),
        }
    }

    /// Runs `alg` once under `precision`, returning the answer and its iterations.
    pub fn iterations(&mut self, alg: Algorithm, precision: Precision) -> (bool, u64) {
        let mut it = Iterations::default();
        let answer = match precision {
            Precision::Fast => self.query_probed(alg, Fast, &mut it),
            Precision::Exact => self.query_probed(alg, Exact, &mut it),
        };
        (answer, it.0)
    }

    /// Runs `alg` once under `precision`, returning the answer and its [`Counts`]
    /// (iterations; for CLM also samples, LP calls and chain walks).
    pub fn counts(&mut self, alg: Algorithm, precision: Precision) -> (bool, Counts) {
        let mut counts = Counts::default();
        let answer = match precision {
            Precision::Fast => self.query_probed(alg, Fast, &mut counts),
            Precision::Exact => self.query_probed(alg, Exact, &mut counts),
        };
        (answer, counts)
    }

    /// The linked copies the linked tests run on (shuffled arenas).
    pub fn arenas(&self) -> (&LinkedPolygon, &LinkedPolygon) {
        (&self.lp, &self.lq)
    }

    /// Runs a CLM variant once under the exact kernel.
    #[inline]
    pub fn query_clm_variant(&mut self, v: ClmVariant) -> bool {
        v.intersects_in(Exact, &self.lp, &self.lq, &mut self.rng, &mut self.clm, &mut ())
    }

    /// Runs a CLM variant once under the exact kernel, returning its [`Counts`].
    pub fn counts_clm_variant(&mut self, v: ClmVariant) -> Counts {
        let mut counts = Counts::default();
        v.intersects_in(
            Exact,
            &self.lp,
            &self.lq,
            &mut self.rng,
            &mut self.clm,
            &mut counts,
        );
        counts
    }

    /// Runs CLM with sample factor `c` once under the exact kernel.
    #[inline]
    pub fn query_clm_factor(&mut self, c: f64) -> bool {
        ClmWithFactor(c).intersects_in(Exact, &self.lp, &self.lq, &mut self.rng, &mut self.clm, &mut ())
    }

    #[inline]
    fn query_probed<K: Kernel, P: Probe>(&mut self, alg: Algorithm, k: K, probe: &mut P) -> bool {
        let (p, q) = (&self.p, &self.q);
        match alg {
            Algorithm::Linear => Linear.intersects_probed(k, p, q, probe),
            Algorithm::Barba => Barba.intersects_probed(k, p, q, probe),
            Algorithm::Dobkin => Dobkin.intersects_probed(k, p, q, probe),
            Algorithm::ChazelleDobkin => ChazelleDobkin.intersects_probed(k, p, q, probe),
            Algorithm::Clm => Clm.intersects_in(k, &self.lp, &self.lq, &mut self.rng, &mut self.clm, probe),
            Algorithm::Convert => <Convert>::default().intersects_in(
                k,
                &self.lp,
                &self.lq,
                &mut self.rng,
                &mut self.convert,
                probe,
            ),
        }
    }
}
