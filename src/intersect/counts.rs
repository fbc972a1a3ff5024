//! [`Counts`]: a [`Probe`] that records, per query, the quantities the thesis reasons
//! with: pruning iterations (Barba, Dobkin, Chazelle–Dobkin; thesis 4.2.2) and, for
//! [`Clm`](super::Clm), the samples, each LP call with its number of constraints and
//! the constraints it examined, and each chain walk with its length (thesis 3.3.2,
//! 4.3.1), kept apart rather than summed.
//!
//! Recording allocates (one entry per LP call and per walk, at most five and four per
//! CLM query), so experiments fill a `Counts` in an untimed run and time the plain
//! query separately.

use super::{Probe, Which};
use crate::kernel::Point;
use crate::lp::{ArenaPoints, LpError, Separation};

/// One LP call of a CLM query.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LpCall {
    /// Points given to the LP (both sets): its constraints.
    pub constraints: usize,
    /// Points it examined (violation tests, one-dimensional steps, certification).
    pub work: u64,
}

/// Counts of one query (or, with [`Counts::clear`] skipped, of several).
///
/// ```
/// use polysect::generate::regular_polygon;
/// use polysect::intersect::{ArrayEngine, Barba, Counts};
/// let p = regular_polygon(1024, 1.0);
/// let q = p.map(|v| polysect::Point::new(v.x + 3.0, v.y))?;
/// let mut counts = Counts::default();
/// assert!(!Barba.intersects_probed(polysect::Exact, &p, &q, &mut counts));
/// assert!(counts.iterations <= 20); // log2 1024 + log2 1024
/// # Ok::<(), polysect::PolygonError>(())
/// ```
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Counts {
    /// Pruning iterations (for CLM: units of work, LP points examined plus chain
    /// vertices walked, the sum the [`Iterations`](super::Iterations) probe gets).
    pub iterations: u64,
    /// CLM's sample size from P (0 for the other algorithms).
    pub samples_p: usize,
    /// CLM's sample size from Q.
    pub samples_q: usize,
    /// CLM's LP calls, in the order they ran.
    pub lps: Vec<LpCall>,
    /// CLM's chain walks, vertices collected by each, in the order they ran.
    pub walks: Vec<usize>,
    /// CLM's sample points tested in the other sample's quadrilaterals
    /// ([`Probe::sample_quads`]).
    pub quad_tests: u64,
    /// CLM queries answered by a sample vertex in such a quadrilateral.
    pub inside: usize,
}

impl Counts {
    /// Forgets everything recorded.
    pub fn clear(&mut self) {
        self.iterations = 0;
        self.samples_p = 0;
        self.samples_q = 0;
        self.lps.clear();
        self.walks.clear();
        self.quad_tests = 0;
        self.inside = 0;
    }

    /// Number of LP calls.
    pub fn lp_calls(&self) -> usize {
        self.lps.len()
    }

    /// Constraints over all LP calls.
    pub fn lp_constraints(&self) -> usize {
        self.lps.iter().map(|c| c.constraints).sum()
    }

    /// Points examined over all LP calls.
    pub fn lp_work(&self) -> u64 {
        self.lps.iter().map(|c| c.work).sum()
    }

    /// Chain vertices over all walks.
    pub fn chain_steps(&self) -> usize {
        self.walks.iter().sum()
    }

    /// The longest walk (0 without walks).
    pub fn longest_walk(&self) -> usize {
        self.walks.iter().copied().max().unwrap_or(0)
    }

    /// Both samples together.
    pub fn samples(&self) -> usize {
        self.samples_p + self.samples_q
    }
}

impl Probe for Counts {
    #[inline]
    fn iteration(&mut self) {
        self.iterations += 1;
    }

    fn samples(&mut self, p: &ArenaPoints<'_>, q: &ArenaPoints<'_>) {
        self.samples_p += p.positions.len();
        self.samples_q += q.positions.len();
    }

    fn lp_call(
        &mut self,
        a: &ArenaPoints<'_>,
        b: &ArenaPoints<'_>,
        work: u64,
        _: &Result<Separation, LpError>,
    ) {
        let constraints = a.positions.len() + b.positions.len();
        self.lps.push(LpCall { constraints, work });
    }

    fn chain_walk(&mut self, chain: &ArenaPoints<'_>) {
        self.walks.push(chain.positions.len());
    }

    fn sample_quads(&mut self, tested: u64, inside: Option<(Which, Point, [Point; 4])>) {
        self.quad_tests += tested;
        self.inside += usize::from(inside.is_some());
    }
}

/// Means of [`Counts`] over several queries: what the experiments' CSVs report.
/// Per-LP and per-walk figures are ratios of totals (NaN without LP calls or walks).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CountsSummary {
    /// Queries summarised.
    pub queries: usize,
    /// Mean of [`Counts::iterations`].
    pub iterations_mean: f64,
    /// Mean number of samples (P and Q together).
    pub samples_mean: f64,
    /// Mean number of LP calls.
    pub lp_calls_mean: f64,
    /// Share of queries that ended after one LP call.
    pub one_lp_share: f64,
    /// Constraints (points given to the LP) per LP call.
    pub constraints_per_lp: f64,
    /// Points examined per LP call.
    pub work_per_lp: f64,
    /// Mean number of chain walks.
    pub walks_mean: f64,
    /// Chain vertices per walk.
    pub steps_per_walk: f64,
    /// The longest walk over all queries.
    pub longest_walk: usize,
}

impl CountsSummary {
    /// Summarises `counts` (all zeros and NaN ratios when empty).
    pub fn of<'a>(counts: impl IntoIterator<Item = &'a Counts>) -> CountsSummary {
        let mut s = CountsSummary::default();
        let (mut iterations, mut samples, mut lps, mut one_lp) = (0u64, 0usize, 0usize, 0usize);
        let (mut constraints, mut work, mut walks, mut steps) = (0usize, 0u64, 0usize, 0usize);
        for c in counts {
            s.queries += 1;
            iterations += c.iterations;
            samples += c.samples();
            lps += c.lp_calls();
            one_lp += usize::from(c.lp_calls() == 1);
            constraints += c.lp_constraints();
            work += c.lp_work();
            walks += c.walks.len();
            steps += c.chain_steps();
            s.longest_walk = s.longest_walk.max(c.longest_walk());
        }
        let ratio = |num: f64, den: usize| if den == 0 { f64::NAN } else { num / den as f64 };
        s.iterations_mean = ratio(iterations as f64, s.queries);
        s.samples_mean = ratio(samples as f64, s.queries);
        s.lp_calls_mean = ratio(lps as f64, s.queries);
        s.one_lp_share = ratio(one_lp as f64, s.queries);
        s.constraints_per_lp = ratio(constraints as f64, lps);
        s.work_per_lp = ratio(work as f64, lps);
        s.walks_mean = ratio(walks as f64, s.queries);
        s.steps_per_walk = ratio(steps as f64, walks);
        s
    }
}
