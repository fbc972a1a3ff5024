//! Planning a batch of queries on a [`Scene`]: bounding boxes, the choice of conversions
//! (convert once answering without a snapshot has cost as much as converting), and the route of each pair (the rule is in the module docs of
//! [`store`](super)); warm starts decide what they can first. The cost model it asks is
//! `cost.rs`; answering the routes is `query.rs`.

use super::cost::Strategy;
use super::route::Route;
use super::scene::{PlanMark, PolygonId, Scene, SceneError};
use super::warm::{self, Warm};
use crate::kernel::Kernel;

/// A planned batch: a route per pair (in input order), the polygons to convert first,
/// and the estimated costs of the conversions and of the answers, in nanoseconds.
pub(super) struct Plan {
    pub(super) routes: Vec<Result<Route, SceneError>>,
    /// The keys of each query's P and Q, beside its route ((0, 0) for an error).
    pub(super) keys: Vec<(usize, usize)>,
    pub(super) chosen: Vec<usize>,
    pub(super) convert_ns: f64,
    pub(super) answer_ns: f64,
}

impl<K: Kernel> Scene<K> {
    /// Plans queries between live keys (`Err` entries are passed through): bounding
    /// boxes, then the strategy; returns the routes and the keys to convert before
    /// answering. O(1) per pair and per polygon involved (per-polygon marks), so a batch
    /// is planned in linear time.
    ///
    /// The planner knows every query of the batch before deciding: a polygon without a
    /// snapshot is charged, per query, what its conversion would save that query (all of
    /// it when the other polygon has or will have a snapshot, half when both lack one),
    /// and is converted when [`Account::should_convert`] says so for the batch's total.
    /// Polygons whose partners were chosen are then offered the other half once more.
    pub(super) fn plan(&mut self, pairs: impl Iterator<Item = Result<(usize, usize), SceneError>>) -> Plan {
        self.plan_warm(pairs, &mut [])
    }

    /// [`plan`](Self::plan) with the last frame's state of each pair (an empty slice
    /// for none): a pair its warm start decides gets [`Route::Warm`] (or the linear walk)
    /// and is left out of the planner's accounts; each state is left as this frame's
    /// where planning decided it, `None` where the answer will.
    pub(super) fn plan_warm(
        &mut self,
        pairs: impl Iterator<Item = Result<(usize, usize), SceneError>>,
        warm: &mut [Option<Warm>],
    ) -> Plan {
        let mut routes: Vec<Result<Route, SceneError>> = Vec::with_capacity(pairs.size_hint().0);
        let mut touched = Vec::new();
        let mut keys = Vec::with_capacity(routes.capacity());
        for (i, pair) in pairs.enumerate() {
            keys.push(*pair.as_ref().unwrap_or(&(0, 0)));
            let route = pair.map(|(a, b)| {
                let decided = warm.get_mut(i).and_then(|w| self.warm_route(a, b, w));
                decided.unwrap_or_else(|| self.plan_boxes(a, b, &mut touched))
            });
            routes.push(route);
        }
        let mut chosen = Vec::new();
        match self.strategy {
            Strategy::Sampled | Strategy::Convert => {}
            Strategy::Cached => chosen.extend(touched.iter().copied()),
            Strategy::Planner => {
                self.choose(&touched, &mut chosen);
                if !chosen.is_empty() {
                    // A partner chosen now turns the half savings into whole ones.
                    for k in &chosen {
                        self.entries[*k].plan.convert = true;
                    }
                    for route in routes.iter().flatten() {
                        if let Route::Sampled(a, b) = *route {
                            for (k, other) in [(a, b), (b, a)] {
                                let (ek, eo) = (&self.entries[k], &self.entries[other]);
                                if !ek.will_have_snapshot() && eo.plan.convert && !eo.has_array() {
                                    let half = 0.5 * self.saving(a, b);
                                    self.entries[k].plan.known_ns += half;
                                }
                            }
                        }
                    }
                    self.choose(&touched, &mut chosen);
                }
            }
        }
        let (mut convert_ns, mut answer_ns) = (0.0, 0.0);
        for k in &chosen {
            self.entries[*k].plan.convert = true;
            convert_ns += self.costs.convert_cost(self.entries[*k].polygon.arena());
        }
        for route in routes.iter_mut().flatten() {
            if let Route::Sampled(a, b) = *route {
                let (r, cost) = self.finish_route(a, b);
                *route = r;
                answer_ns += cost;
            }
        }
        for k in touched {
            self.entries[k].plan = PlanMark::default();
        }
        Plan {
            routes,
            keys,
            chosen,
            convert_ns,
            answer_ns,
        }
    }

    /// The warm start of pair (a, b), whose last-frame state is `w`: the route when it
    /// decides the pair, with `w` set to this frame's state; `None` (and `w` cleared)
    /// when the planner must. A kept certificate is checked (O(1) plus the climb); a pair
    /// separated without one is walked linearly, which answers it and finds one.
    fn warm_route(&mut self, a: usize, b: usize, w: &mut Option<Warm>) -> Option<Route> {
        let state = w.take()?;
        if matches!(state, Warm::Intersecting) {
            return None;
        }
        self.entries[a].polygon.materialized();
        self.entries[b].polygon.materialized();
        let (p, q) = (self.entries[a].polygon.get(), self.entries[b].polygon.get());
        let found = match state {
            Warm::Intersecting => return None,
            Warm::Certified { of, from, deep } => {
                let kept = warm::check(self.kernel, p, q, of, from, deep);
                let counter = match kept {
                    Some(_) => &mut self.warm.stats.hits,
                    None => &mut self.warm.stats.misses,
                };
                *counter += 1;
                kept?
            }
            Warm::Separated => {
                self.warm.stats.fills += 1;
                let Some(found) = warm::fill(self.kernel, p, q) else {
                    // They met since: the answer is `true`, proved by the (certified)
                    // linear walk again, only on this frame.
                    *w = Some(Warm::Intersecting);
                    return Some(Route::Linear(a, b));
                };
                found
            }
        };
        *w = Some(found.warm);
        Some(Route::Warm {
            of: found.of,
            from: found.from,
            to: found.to,
        })
    }

    /// The box test; a live pair is left as `Sampled` for now, its polygons marked and
    /// credited with the saving a snapshot would bring.
    fn plan_boxes(&mut self, a: usize, b: usize, touched: &mut Vec<usize>) -> Route {
        if a == b {
            return Route::Known(true);
        }
        if !self.entries[a].bbox.overlaps(&self.entries[b].bbox) {
            self.stats.box_rejects += 1;
            return Route::Known(false);
        }
        // Posed polygons whose boxes meet: the snapshots their lazy poses owe (small
        // polygons; a large one is read through its pose).
        self.settle(a);
        self.settle(b);
        let saving = self.saving(a, b);
        for (k, other) in [(a, b), (b, a)] {
            let has_other = self.entries[other].has_array();
            let e = &mut self.entries[k];
            e.account.queried();
            if !e.has_array() {
                if !e.plan.touched {
                    e.plan.touched = true;
                    touched.push(k);
                }
                e.plan.known_ns += if has_other { saving } else { 0.5 * saving };
                e.plan.known += 1;
            }
        }
        Route::Sampled(a, b)
    }

    /// Appends to `chosen` the touched polygons, not yet chosen, that the planner
    /// converts.
    fn choose(&self, touched: &[usize], chosen: &mut Vec<usize>) {
        for &k in touched {
            let e = &self.entries[k];
            let cost = self.costs.convert_cost(e.polygon.arena());
            if !e.plan.convert && e.account.should_convert(cost, e.plan.known_ns, e.plan.known) {
                chosen.push(k);
            }
        }
    }

    /// What snapshots of both polygons would save one query between them.
    fn saving(&self, a: usize, b: usize) -> f64 {
        self.costs
            .saving(self.entries[a].polygon.arena(), self.entries[b].polygon.arena())
    }

    /// The route of a live pair once conversions are chosen, and its estimated cost;
    /// unconverted polygons add what they cost to their accounts.
    fn finish_route(&mut self, a: usize, b: usize) -> (Route, f64) {
        let (pa, pb) = (self.entries[a].polygon.arena(), self.entries[b].polygon.arena());
        let (na, nb) = (pa.vertices, pb.vertices);
        let (ha, hb) = (
            self.entries[a].will_have_snapshot(),
            self.entries[b].will_have_snapshot(),
        );
        let linear_arrays = self.costs.array_is_linear(na, nb);
        if ha && hb {
            self.stats.array_tests += 1;
            return (Route::Arrays(a, b, linear_arrays), self.costs.array_cost(na, nb));
        }
        if self.strategy == Strategy::Convert {
            self.stats.throwaway_conversions += 2;
            let cost =
                self.costs.convert_cost(pa) + self.costs.convert_cost(pb) + self.costs.array_cost(na, nb);
            return (Route::Throwaway(a, b, linear_arrays), cost);
        }
        let saving = self.costs.saving(pa, pb);
        for (k, has_other) in [(a, hb), (b, ha)] {
            if !self.entries[k].will_have_snapshot() {
                self.entries[k]
                    .account
                    .pay(if has_other { saving } else { 0.5 * saving });
            }
        }
        if self.strategy == Strategy::Planner && self.costs.prefers_linear(pa, pb) {
            self.stats.linear_tests += 1;
            return (Route::Linear(a, b), self.costs.linear_cost(pa, pb));
        }
        self.stats.sampled_tests += 1;
        (Route::Sampled(a, b), self.costs.sampled_cost(pa, pb))
    }

    /// Plans a batch given by handles; a stale or foreign handle plans as its error.
    pub(super) fn plan_pairs(&mut self, pairs: &[(PolygonId, PolygonId)]) -> Plan {
        let keys = pairs.iter().map(|&(a, b)| Ok((self.key(a)?, self.key(b)?)));
        let keys: Vec<Result<(usize, usize), SceneError>> = keys.collect();
        self.plan(keys.into_iter())
    }

    /// The candidate pairs of a frame, their plan, and (with warm starts) each pair's
    /// state as far as planning decided it.
    pub(super) fn plan_frame(&mut self) -> (Vec<(usize, usize)>, Plan, Vec<Option<Warm>>) {
        self.flush_broad_phase();
        let candidates = self.broad.overlapping_pairs();
        let mut warm = if self.warm_starts {
            let entries = &self.entries;
            self.warm.take(&candidates, |k| entries[k].generation)
        } else {
            Vec::new()
        };
        let plan = self.plan_warm(candidates.iter().map(|&pair| Ok(pair)), &mut warm);
        (candidates, plan, warm)
    }

    /// Keeps this frame's state of every candidate pair: what planning decided, else
    /// what the answer was.
    pub(super) fn keep_frame(
        &mut self,
        candidates: &[(usize, usize)],
        warm: Vec<Option<Warm>>,
        hits: impl Iterator<Item = bool>,
    ) {
        if !self.warm_starts {
            return;
        }
        let states = warm
            .into_iter()
            .zip(hits)
            .map(|(w, hit)| w.unwrap_or(if hit { Warm::Intersecting } else { Warm::Separated }));
        let entries = &self.entries;
        self.warm.keep(candidates, states, |k| entries[k].generation);
    }
}
