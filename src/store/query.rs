//! Answering planned queries on a [`Scene`]: one query, batches (in parallel with the
//! `parallel` feature), the polygons meeting one, all intersecting pairs, each plain or
//! with certificates.

use super::planner::Plan;
use super::route::{
    ArrayRef, QueryWorkspace, Route, array_certified, array_test, linear_certified, linear_test,
    sampled_certified, sampled_test,
};
use super::scene::{PolygonId, Scene, SceneError};
use crate::intersect::{Certificate, Which};
use crate::kernel::{Exact, Kernel, Point};
use crate::polygon::ConvexPolygon;
use rand::rngs::SmallRng;
use rand::{RngCore, SeedableRng};
#[cfg(feature = "parallel")]
use rayon::prelude::*;

/// Conversions, or answers, run on other threads too only when there are several and
/// their estimated cost reaches this: handing work to other threads costs microseconds,
/// and far more when the machine is busy (the caller waits for a worker to wake up).
const PARALLEL_MIN_NS: f64 = 1e6;

impl<K: Kernel> Scene<K> {
    /// Answers one planned route; `seed` seeds the sampled test's generator (per pair, so
    /// answers and times never depend on the order or the thread).
    fn answer(&self, route: Route, ws: &mut QueryWorkspace, seed: u64) -> bool {
        let e = |k: usize| &self.entries[k];
        let snapshot = |k: usize| e(k).array().expect("planned array");
        match route {
            Route::Known(v) => v,
            Route::Warm { .. } => false,
            Route::Arrays(a, b, linear) => array_test(self.kernel, snapshot(a), snapshot(b), linear),
            Route::Linear(a, b) => linear_test(self.kernel, e(a).polygon.get(), e(b).polygon.get()),
            Route::Sampled(a, b) => {
                let mut rng = SmallRng::seed_from_u64(seed);
                sampled_test(self.kernel, e(a).polygon.get(), e(b).polygon.get(), ws, &mut rng)
            }
            Route::Throwaway(a, b, linear) => array_test(
                self.kernel,
                ArrayRef::Stored(&e(a).polygon.get().to_convex()),
                ArrayRef::Stored(&e(b).polygon.get().to_convex()),
                linear,
            ),
        }
    }

    /// The certificate of a planned query between keys `a` and `b` (the query's P and
    /// Q): the certified call of the route's test, with the scene's kernel. A pair
    /// rejected by its bounding boxes is known to be disjoint exactly, so its separating
    /// edge is searched with the exact kernel (the array test when both snapshots are
    /// valid, else the sampled test); a polygon against itself is proved by its first
    /// vertex.
    fn answer_certified(
        &self,
        route: Route,
        (a, b): (usize, usize),
        ws: &mut QueryWorkspace,
        seed: u64,
    ) -> Certificate {
        let e = |k: usize| &self.entries[k];
        let snapshot = |k: usize| e(k).array().expect("planned array");
        match route {
            Route::Known(true) => {
                let point = e(a).polygon.get().point_at(0);
                Certificate::VertexInside { of: Which::P, point }
            }
            Route::Known(false) => match (e(a).array(), e(b).array()) {
                (Some(p), Some(q)) => array_certified(Exact, p, q, false),
                _ => {
                    let mut rng = SmallRng::seed_from_u64(seed);
                    sampled_certified(Exact, e(a).polygon.get(), e(b).polygon.get(), ws, &mut rng)
                }
            },
            Route::Warm { of, from, to } => Certificate::Separated { of, from, to },
            Route::Arrays(a, b, linear) => array_certified(self.kernel, snapshot(a), snapshot(b), linear),
            Route::Linear(a, b) => linear_certified(self.kernel, e(a).polygon.get(), e(b).polygon.get()),
            Route::Sampled(a, b) => {
                let mut rng = SmallRng::seed_from_u64(seed);
                sampled_certified(self.kernel, e(a).polygon.get(), e(b).polygon.get(), ws, &mut rng)
            }
            Route::Throwaway(a, b, linear) => array_certified(
                self.kernel,
                ArrayRef::Stored(&e(a).polygon.get().to_convex()),
                ArrayRef::Stored(&e(b).polygon.get().to_convex()),
                linear,
            ),
        }
    }

    /// Whether polygons `a` and `b` intersect (closed sets: touching counts).
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon` for either handle.
    pub fn intersects(&mut self, a: PolygonId, b: PolygonId) -> Result<bool, SceneError> {
        self.query(a, b, |s, route, _, ws, seed| s.answer(route, ws, seed))
    }

    /// [`intersects`](Self::intersects) with a [`Certificate`] of the answer (`a` is the
    /// certificate's P, `b` its Q; the answer is [`Certificate::intersects`]), planned
    /// exactly as `intersects` plans: the same strategy, conversions and counters, and
    /// the certified call of the test the plan chose. The certificate names vertices of
    /// the polygons as they are now; [`verify_linked`](crate::intersect::verify_linked)
    /// checks it exactly.
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon` for either handle.
    ///
    /// # Precision
    /// Under the exact kernel the certificate always verifies; under the fast kernel it
    /// may not, exactly when the fast answer may be wrong (docs/certificates.md).
    ///
    /// ```
    /// use polysect::store::Scene;
    /// use polysect::intersect::verify_linked;
    /// let mut scene = Scene::new();
    /// let a = scene.insert_points([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
    /// let b = scene.insert_points([[2.0, 1.0], [4.0, 0.0], [4.0, 3.0]])?;
    /// let c = scene.intersects_certified(a, b)?;
    /// assert!(c.intersects()); // (2, 1) lies on a's edge
    /// assert_eq!(verify_linked(scene.polygon(a)?, scene.polygon(b)?, &c), Ok(()));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn intersects_certified(&mut self, a: PolygonId, b: PolygonId) -> Result<Certificate, SceneError> {
        self.query(a, b, |s, route, keys, ws, seed| {
            s.answer_certified(route, keys, ws, seed)
        })
    }

    /// Plans one query, builds the conversions it chose and answers it with `answer`.
    fn query<T>(
        &mut self,
        a: PolygonId,
        b: PolygonId,
        answer: impl FnOnce(&Self, Route, (usize, usize), &mut QueryWorkspace, u64) -> T,
    ) -> Result<T, SceneError> {
        let (ka, kb) = (self.key(a)?, self.key(b)?);
        let mut plan = self.plan(std::iter::once(Ok((ka, kb))));
        for k in plan.chosen {
            self.convert(k);
        }
        let route = plan.routes.pop().expect("one route")?;
        let mut ws = std::mem::take(&mut self.workspace);
        let seed = self.rng.next_u64();
        let answer = answer(self, route, (ka, kb), &mut ws, seed);
        self.workspace = ws;
        Ok(answer)
    }

    /// Answers many queries: planned together (the planner sees the whole batch before
    /// choosing conversions), then conversions built and pairs answered, each in
    /// parallel (with the `parallel` feature) when there are several and their estimated
    /// cost (at least 1 ms) pays for handing work to other threads. Results are in input order and do not depend on the number of threads.
    /// A pair with a stale or foreign handle gets that error in its place; the other
    /// pairs are answered.
    pub fn intersects_batch(&mut self, pairs: &[(PolygonId, PolygonId)]) -> Vec<Result<bool, SceneError>> {
        let plan = self.plan_pairs(pairs);
        self.run_plan(plan)
    }

    /// [`intersects_batch`](Self::intersects_batch) with certificates, as
    /// [`intersects_certified`](Self::intersects_certified) gives them (in each pair, the
    /// first polygon is the certificate's P).
    pub fn intersects_batch_certified(
        &mut self,
        pairs: &[(PolygonId, PolygonId)],
    ) -> Vec<Result<Certificate, SceneError>> {
        let plan = self.plan_pairs(pairs);
        self.run_plan_certified(plan)
    }

    pub(super) fn run_plan(&mut self, plan: Plan) -> Vec<Result<bool, SceneError>> {
        self.run_plan_with(plan, |s, route, _, ws, seed| s.answer(route, ws, seed))
    }

    fn run_plan_certified(&mut self, plan: Plan) -> Vec<Result<Certificate, SceneError>> {
        self.run_plan_with(plan, |s, route, keys, ws, seed| {
            s.answer_certified(route, keys, ws, seed)
        })
    }

    /// Converts the chosen polygons and answers the routes; the sampled test of route `i`
    /// is seeded from one draw of the scene's generator and `i`, so answers do not
    /// depend on the number of threads.
    #[cfg_attr(not(feature = "parallel"), allow(unused_variables))]
    fn run_plan_with<T: Send>(
        &mut self,
        plan: Plan,
        answer: impl Fn(&Self, Route, (usize, usize), &mut QueryWorkspace, u64) -> T + Sync,
    ) -> Vec<Result<T, SceneError>> {
        let base: u64 = self.rng.next_u64();
        // Without the `parallel` feature everything runs on the calling thread.
        #[cfg(feature = "parallel")]
        let threads = rayon::current_num_threads() > 1;
        #[cfg(not(feature = "parallel"))]
        let threads = false;
        let parallel_convert = threads && plan.chosen.len() > 1 && plan.convert_ns >= PARALLEL_MIN_NS;
        let parallel = threads && plan.routes.len() > 64 && plan.answer_ns >= PARALLEL_MIN_NS;
        self.convert_all(plan.chosen, parallel_convert);
        let mut ws = std::mem::take(&mut self.workspace);
        let this = &*self;
        let keys = &plan.keys;
        let answer = |ws: &mut QueryWorkspace, (i, route): (usize, &Result<Route, SceneError>)| {
            let route = route.clone()?;
            let seed = base ^ (i as u64).wrapping_mul(0x9e37_79b9_7f4a_7c15);
            Ok(answer(this, route, keys[i], ws, seed))
        };
        let answers = match () {
            #[cfg(feature = "parallel")]
            () if parallel => plan
                .routes
                .par_iter()
                .enumerate()
                .with_min_len(64)
                .map_init(QueryWorkspace::default, answer)
                .collect(),
            () => plan
                .routes
                .iter()
                .enumerate()
                .map(|r| answer(&mut ws, r))
                .collect(),
        };
        self.workspace = ws;
        answers
    }

    #[cfg_attr(not(feature = "parallel"), allow(unused_variables))]
    fn convert_all(&mut self, mut keys: Vec<usize>, parallel: bool) {
        keys.sort_unstable();
        keys.dedup();
        for &k in &keys {
            self.entries[k].polygon.materialized();
        }
        let convert = |&k: &usize| (k, self.entries[k].polygon.get().to_convex());
        let snapshots: Vec<(usize, ConvexPolygon)> = match () {
            #[cfg(feature = "parallel")]
            () if parallel => keys.par_iter().with_min_len(16).map(convert).collect(),
            () => keys.iter().map(convert).collect(),
        };
        for (k, s) in snapshots {
            self.install_snapshot(k, s);
        }
    }

    /// All polygons other than `a` that intersect it, in slot order.
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon`.
    pub fn intersecting(&mut self, a: PolygonId) -> Result<Vec<PolygonId>, SceneError> {
        let ka = self.key(a)?;
        self.flush_broad_phase();
        let mut candidates: Vec<usize> = self
            .broad
            .overlapping(&self.entries[ka].bbox)
            .filter(|&k| k != ka)
            .collect();
        candidates.sort_unstable();
        let plan = self.plan(candidates.iter().map(|&k| Ok((ka, k))));
        let answers = self.run_plan(plan);
        Ok(candidates
            .into_iter()
            .zip(answers)
            .filter(|(_, hit)| matches!(hit, Ok(true)))
            .map(|(k, _)| self.id_of(k))
            .collect())
    }

    /// All intersecting pairs `(a, b)` with `a` before `b` in slot order, sorted.
    ///
    /// With warm starts ([`set_warm_starts`](Self::set_warm_starts), off by default), a
    /// pair found separated by the last call is first checked against the separating
    /// edge found then; the answer is the same, only its cost differs.
    pub fn intersecting_pairs(&mut self) -> Vec<(PolygonId, PolygonId)> {
        let (candidates, plan, warm) = self.plan_frame();
        let answers = self.run_plan(plan);
        self.keep_frame(
            &candidates,
            warm,
            answers.iter().map(|hit| matches!(hit, Ok(true))),
        );
        candidates
            .into_iter()
            .zip(answers)
            .filter(|(_, hit)| matches!(hit, Ok(true)))
            .map(|((a, b), _)| (self.id_of(a), self.id_of(b)))
            .collect()
    }

    /// [`intersecting_pairs`](Self::intersecting_pairs), each with the certificate of
    /// its intersection (`a` is the certificate's P). Pairs the broad phase rejects get
    /// none: they are not in the answer.
    pub fn intersecting_pairs_certified(&mut self) -> Vec<(PolygonId, PolygonId, Certificate)> {
        self.candidate_pairs_certified()
            .into_iter()
            .filter_map(|(a, b, c)| Some((a, b, c.ok().filter(Certificate::intersects)?)))
            .collect()
    }

    /// Every candidate pair (boxes overlap) with the certificate of its answer, in one
    /// planned pass: an intersection witness, or for a pair found disjoint its separating
    /// edge (`a` is the certificate's P). What a caller needs that keeps separating
    /// edges for later contacts without asking the disjoint pairs a second time.
    pub fn candidate_pairs_certified(
        &mut self,
    ) -> Vec<(PolygonId, PolygonId, Result<Certificate, SceneError>)> {
        let (candidates, plan, warm) = self.plan_frame();
        let answers = self.run_plan_certified(plan);
        let hits = answers.iter().map(|c| matches!(c, Ok(c) if c.intersects()));
        self.keep_frame(&candidates, warm, hits);
        candidates
            .into_iter()
            .zip(answers)
            .map(|((a, b), c)| (self.id_of(a), self.id_of(b), c))
            .collect()
    }

    /// Whether `point` lies in the polygon (its world polygon when posed), boundary
    /// included, decided with the scene's kernel: exact under [`Exact`] for every finite
    /// point; a NaN or infinite point is in no polygon.
    ///
    /// # Complexity
    /// O(1) when the point is outside the bounding box; otherwise O(log n) on the array
    /// snapshot when the polygon has one, else the sampled test on the linked polygon,
    /// expected O(√n) over the scene generator's draws
    /// ([`LinkedPolygon::contains_point_with`](crate::LinkedPolygon::contains_point_with)).
    /// It converts nothing and leaves the planner's counters alone.
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon`.
    ///
    /// ```
    /// use polysect::store::Scene;
    /// let mut scene = Scene::new();
    /// let a = scene.insert_points([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
    /// assert!(scene.contains_point(a, [2.0, 1.0])?); // on an edge
    /// assert!(!scene.contains_point(a, [2.0f64.next_up(), 1.0])?);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn contains_point(&mut self, id: PolygonId, point: impl Into<Point>) -> Result<bool, SceneError> {
        let key = self.key(id)?;
        let x = point.into();
        let e = &mut self.entries[key];
        // The box contains the polygon and its comparisons are exact, so a point outside
        // it is outside the polygon; a NaN fails every comparison and is refused here too.
        if !e.bbox.contains_point(x) {
            return Ok(false);
        }
        Ok(match &e.snapshot {
            Some(s) => s.contains_point_with(self.kernel, x),
            None => e
                .polygon
                .materialized()
                .contains_point_with(self.kernel, x, &mut self.rng),
        })
    }

    /// Pairs of polygons whose bounding boxes overlap (the broad phase's candidates).
    pub fn candidate_pairs(&mut self) -> Vec<(PolygonId, PolygonId)> {
        self.flush_broad_phase();
        self.broad
            .overlapping_pairs()
            .into_iter()
            .map(|(a, b)| (self.id_of(a), self.id_of(b)))
            .collect()
    }
}
