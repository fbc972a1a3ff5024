//! Walking the chains the LP's line cuts off, in lockstep on both polygons, and the
//! LPs of chain against chain.

use super::lp_call::{counted_lp, walk_or_lp};
use super::sampling::shuffle;
use super::{ClmWorkspace, Set};
use crate::intersect::{Probe, Which};
use crate::kernel::{DirectedLine, Kernel, Orientation, Point};
use crate::lp::{ArenaPoints, Bitangent, LpWorkspace, Separation, separate_chains};
use crate::polygon::LinkedPolygon;
use rand::Rng;

/// How [`walk_and_decide`] treats walked chains: shuffled for the LP
/// ([`LpOrder::Caller`]), and whether the chain-against-chain LPs are walks
/// ([`ClmVariant::chain_walk`]; then C′_P and C′_Q stay in walk order, and C_P and C_Q
/// are copied in walk order before their shuffle).
#[derive(Clone, Copy)]
pub(super) struct ChainOrder {
    pub(super) shuffle: bool,
    pub(super) walk: bool,
    /// With the samples in boundary order ([`ClmVariant::sample_walk`]), the indices of
    /// the first line's tangent vertices in R_P and R_Q: the sample-against-chain LPs
    /// are walks from there and the chain's first vertex.
    pub(super) samples: Option<[usize; 2]>,
}

/// The four chain buffers (positions, and the points at them), indexed by
/// [`Set::chain_index`].
pub(super) struct Chains(pub(super) [Vec<u32>; 4], pub(super) [Vec<Point>; 4]);

impl Chains {
    #[inline]
    fn get(&self, s: Set) -> &[u32] {
        &self.0[s.chain_index()]
    }

    #[inline]
    fn points(&self, s: Set) -> &[Point] {
        &self.1[s.chain_index()]
    }

    /// Both buffers of a chain, taken out to be written by a walk.
    #[inline]
    fn take(&mut self, s: Set) -> (Vec<u32>, Vec<Point>) {
        let i = s.chain_index();
        (std::mem::take(&mut self.0[i]), std::mem::take(&mut self.1[i]))
    }

    /// Puts back the buffers of a finished walk.
    #[inline]
    fn put(&mut self, s: Set, (positions, points): (Vec<u32>, Vec<Point>)) {
        let i = s.chain_index();
        (self.0[i], self.1[i]) = (positions, points);
    }

    /// Both buffers of a chain in place.
    #[inline]
    fn buffers(&mut self, s: Set) -> (&mut Vec<u32>, &mut Vec<Point>) {
        let i = s.chain_index();
        (&mut self.0[i], &mut self.1[i])
    }
}

impl Set {
    /// The buffer of a chain set in [`Chains`] (samples have none).
    #[inline]
    pub(super) fn chain_index(self) -> usize {
        match self {
            Set::Cp => 0,
            Set::Cq => 1,
            Set::Chain => 2,
            Set::Chain2 => 3,
            Set::Rp | Set::Rq => unreachable!("samples are not walked"),
        }
    }
}

/// A walk in progress in one of the lockstep slots: the chain set it fills, and that
/// set's buffers (positions and points), taken out of [`Chains`] while it walks.
pub(super) struct Active<'a> {
    set: Set,
    walk: Walk<'a>,
    cursor: Cursor,
    buffers: (Vec<u32>, Vec<Point>),
}

impl<'a> Active<'a> {
    /// Starts `walk` into the buffers of `set`.
    fn start<K: Kernel>(k: K, set: Set, walk: Walk<'a>, chains: &mut Chains) -> Self {
        let mut buffers = chains.take(set);
        let cursor = walk.start(k, &mut buffers);
        Active {
            set,
            walk,
            cursor,
            buffers,
        }
    }
}

/// Steps 3–5 of the module docs after the first LP, as a schedule of chain walks kept
/// two at a time in lockstep, so that their cache misses (each step is a dependent
/// load at a random arena position) overlap for the whole query rather than only
/// while both walks of a pair last. `first` are the walks of C_P and C_Q. When a walk
/// ends, the LP that needed it runs at once (an intersection there ends the query),
/// and the walk that LP's line calls for takes the freed slot:
/// * C_Q done: LP(R_P, C_Q); its line starts C′_P.
/// * C_P done: LP(R_Q, C_P); its line starts C′_Q.
/// * C′_P done: LP(C′_P, C_Q). C′_Q done: LP(C′_Q, C_P).
///
/// The answer is the disjunction of the four LPs' verdicts, so the order in which
/// walks end does not change it. A sample that is its whole polygon has decided its
/// sub-test already: its second chain is not walked. With `order.shuffle` each chain
/// is shuffled when walked ([`LpOrder::Caller`]); with `order.walk` the last two LPs are
/// [`separate_chains`] on the chains in walk order, started from C′'s first vertex (the
/// tangent vertex it was walked from) and the far chain's tangent vertex on the line
/// that started C′ (see [`chain_against_chain`]).
#[allow(clippy::too_many_arguments)]
pub(super) fn walk_and_decide<K: Kernel, R: Rng + ?Sized, P: Probe, const CERT: bool>(
    k: K,
    p: &LinkedPolygon,
    q: &LinkedPolygon,
    first: [Walk<'_>; 2],
    chains: &mut Chains,
    order: ChainOrder,
    rng: &mut R,
    ws: &mut ClmWorkspace,
    probe: &mut P,
) -> bool {
    let ClmWorkspace {
        rp,
        rq,
        rp_points,
        rq_points,
        lp,
        walked,
        trace,
        ordered,
        ..
    } = ws;
    // Per polygon (P, Q): its first chain's tangent vertex on the line of the
    // sample-against-chain LP, where the chain-against-chain walk starts: its position
    // when the chain is shuffled, else its index in the chain.
    let mut far_tangent = [0usize; 2];
    let p_open = rp.len() < p.len();
    let q_open = rq.len() < q.len();
    let mut slots: [Option<Active<'_>>; 2] = [None, None];
    for (slot, (walk, set)) in slots.iter_mut().zip(first.into_iter().zip([Set::Cp, Set::Cq])) {
        *slot = Some(Active::start(k, set, walk, chains));
    }
    // At the top of this loop at least one slot walks: the loop ends when none does.
    // An answer found while the other slot still walks leaves the loop with that slot's
    // buffers out of `chains`; they go back below, so the workspace keeps them.
    let answer = 'decide: loop {
        // Step every active walk until one of them ends.
        lockstep(k, &mut slots);
        for slot in &mut slots {
            let Some(Active { set, buffers, .. }) = slot.take_if(|a| a.cursor.done) else {
                continue;
            };
            chains.put(set, buffers);
            let len = chains.get(set).len();
            probe.chain_walk(&ArenaPoints {
                polygon: if set.of() == Which::P { p } else { q },
                positions: chains.get(set),
            });
            *walked += len as u64;
            let side = usize::from(set.of() == Which::Q);
            let second = matches!(set, Set::Chain | Set::Chain2);
            if order.walk && order.shuffle && !second {
                let (positions, points) = &mut ordered[side];
                positions.clone_from(&chains.0[set.chain_index()]);
                points.clone_from(&chains.1[set.chain_index()]);
            }
            if order.walk && second {
                let far = if set == Set::Chain { Set::Cq } else { Set::Cp };
                let far_side = usize::from(far.of() == Which::Q);
                let before = lp.work;
                let walked = if order.shuffle {
                    chain_against_chain(k, set, far, chains, &ordered[far_side], far_tangent[far_side], lp)
                } else {
                    let start = [0, far_tangent[far_side]];
                    separate_chains(k, chains.points(set), chains.points(far), start, &mut lp.work)
                };
                match walked {
                    Some(Separation::Separated(line)) => {
                        report_lp(
                            p,
                            q,
                            (set, far),
                            chains,
                            lp.work - before,
                            Separation::Separated(line),
                            probe,
                        );
                        if CERT {
                            trace.lines.push((line, set, far));
                        }
                        continue;
                    }
                    Some(Separation::Intersecting) if !CERT => {
                        report_lp(
                            p,
                            q,
                            (set, far),
                            chains,
                            lp.work - before,
                            Separation::Intersecting,
                            probe,
                        );
                        break 'decide true;
                    }
                    // No answer, or a certified query's intersection (the LP records the
                    // witness): the LP decides.
                    _ => {}
                }
            }
            if order.shuffle {
                let (positions, points) = chains.buffers(set);
                shuffle(positions, points, rng);
            }
            // The LP this chain completes: (near set, its polygon, far chain, its polygon).
            let (near, far) = match set {
                Set::Cq => (Set::Rp, Set::Cq),
                Set::Cp => (Set::Rq, Set::Cp),
                Set::Chain => (Set::Chain, Set::Cq),
                _ => (Set::Chain2, Set::Cp),
            };
            let polygon = |s: Set| if s.of() == Which::P { p } else { q };
            let (near_positions, near_points) = match near {
                Set::Rp => (&rp[..], &rp_points[..]),
                Set::Rq => (&rq[..], &rq_points[..]),
                s => (chains.get(s), chains.points(s)),
            };
            let a = ArenaPoints {
                polygon: polygon(near),
                positions: near_positions,
            };
            let b = ArenaPoints {
                polygon: polygon(far),
                positions: chains.get(far),
            };
            let result = match (near, order.samples) {
                (Set::Rp | Set::Rq, Some(tangents)) => {
                    let start = [tangents[usize::from(near == Set::Rq)], 0];
                    walk_or_lp::<K, R, P, CERT>(
                        k,
                        (&a, near_points),
                        (&b, chains.points(far)),
                        start,
                        0,
                        rng,
                        lp,
                        probe,
                    )
                }
                _ => counted_lp(k, (&a, near_points), (&b, chains.points(far)), rng, lp, probe),
            };
            let Ok(Separation::Separated(line)) = result else {
                if CERT {
                    trace.meet = Some((near, far));
                }
                break 'decide true;
            };
            if CERT {
                trace.lines.push((line, near, far));
            }
            if matches!(near, Set::Rp | Set::Rq) {
                far_tangent[usize::from(far.of() == Which::Q)] = if order.shuffle {
                    chains.get(far)[line.b] as usize
                } else {
                    line.b
                };
            }
            // After a first chain, the second chain of the other polygon, beyond the line
            // (the near set is on its right: its far side is the left).
            let next = match near {
                Set::Rp if p_open => Some((Set::Chain, p, rp[line.a])),
                Set::Rq if q_open => Some((Set::Chain2, q, rq[line.a])),
                _ => None,
            };
            if let Some((set, poly, t)) = next {
                let walk = Walk::new(poly, line.start, line.end, Orientation::Ccw, t as usize);
                *slot = Some(Active::start(k, set, walk, chains));
            }
        }
        if slots.iter().all(Option::is_none) {
            break false;
        }
    };
    for Active { set, buffers, .. } in slots.into_iter().flatten() {
        chains.put(set, buffers);
    }
    answer
}

/// [`separate_chains`] on the second chain `near` (C′_P or C′_Q, in walk order: its
/// first vertex is the tangent vertex it was walked from) and the first chain `far` of
/// the other polygon in walk order (`ordered`: its positions and points), started at
/// the far chain's vertex at position `tangent`. The answer's index into `far` is into
/// its (shuffled) buffer in `chains`, as the LP's would be. `None` when the walk gives
/// no answer.
pub(super) fn chain_against_chain<K: Kernel>(
    k: K,
    near: Set,
    far: Set,
    chains: &Chains,
    (positions, points): &(Vec<u32>, Vec<Point>),
    tangent: usize,
    lp: &mut LpWorkspace,
) -> Option<Separation> {
    let j = positions.iter().position(|&x| x as usize == tangent).unwrap_or(0);
    match separate_chains(k, chains.points(near), points, [0, j], &mut lp.work)? {
        Separation::Separated(line) => {
            let at = positions[line.b];
            let b = chains.get(far).iter().position(|&x| x == at)?;
            Some(Separation::Separated(Bitangent { b, ..line }))
        }
        Separation::Intersecting => Some(Separation::Intersecting),
    }
}

/// Reports to `probe` a chain-against-chain separation decided without the LP, as an
/// LP call on the two chains.
pub(super) fn report_lp<P: Probe>(
    p: &LinkedPolygon,
    q: &LinkedPolygon,
    (a, b): (Set, Set),
    chains: &Chains,
    work: u64,
    result: Separation,
    probe: &mut P,
) {
    let set = |s: Set| ArenaPoints {
        polygon: if s.of() == Which::P { p } else { q },
        positions: chains.get(s),
    };
    probe.lp_call(&set(a), &set(b), work, &Ok(result));
}

/// One chain walk (see [`walk_and_decide`]): from the tangent vertex at position `t` of
/// `poly`, along the side where the neighbour lies strictly on the `far` side of the
/// directed line (s, e).
#[derive(Clone, Copy)]
pub(super) struct Walk<'a> {
    poly: &'a LinkedPolygon,
    /// The line, directed so that the far side is its left (reversed when `far` is the
    /// right: `orient(e, s, x) = −orient(s, e, x)`, exactly under an exact kernel), its
    /// direction computed once for all the walk's side tests.
    line: DirectedLine,
    t: usize,
}

impl<'a> Walk<'a> {
    pub(super) fn new(poly: &'a LinkedPolygon, s: Point, e: Point, far: Orientation, t: usize) -> Self {
        let line = if far == Orientation::Cw {
            DirectedLine::new(e, s)
        } else {
            debug_assert_eq!(far, Orientation::Ccw);
            DirectedLine::new(s, e)
        };
        Walk { poly, line, t }
    }
}

/// The state of a walk in progress.
pub(super) struct Cursor {
    v: usize,
    forward: bool,
    steps_left: usize,
    done: bool,
}

impl Walk<'_> {
    #[inline(always)]
    fn is_far<K: Kernel>(&self, k: K, x: Point) -> bool {
        k.orient_line(&self.line, x) == Orientation::Ccw
    }

    /// Starts the walk, writing its first vertices and their points to `out`.
    fn start<K: Kernel>(&self, k: K, (out, points): &mut (Vec<u32>, Vec<Point>)) -> Cursor {
        out.clear();
        points.clear();
        let done = Cursor {
            v: 0,
            forward: true,
            steps_left: 0,
            done: true,
        };
        let (poly, t) = (self.poly, self.t);
        let (next, prev) = (poly.next_at(t), poly.prev_at(t));
        let (next_point, prev_point) = (poly.point_at(next), poly.point_at(prev));
        let forward = if self.is_far(k, next_point) {
            true
        } else if self.is_far(k, prev_point) {
            false
        } else {
            out.extend([prev as u32, t as u32, next as u32]);
            points.extend([prev_point, poly.point_at(t), next_point]);
            return done;
        };
        out.push(t as u32);
        points.push(poly.point_at(t));
        Cursor {
            v: if forward { next } else { prev },
            forward,
            // At most n − 1 further vertices; the cap also bounds walks under an
            // inconsistent kernel.
            steps_left: poly.len() - 1,
            done: false,
        }
    }

    /// One step from the vertex at `v`: records it and its point in `pos` and `point`,
    /// and returns the next vertex, or `None` if `v` closes the chain (it is not
    /// strictly beyond the line) or the next vertex is the start (the walk went
    /// around).
    #[inline(always)]
    fn step<K: Kernel>(
        &self,
        k: K,
        v: usize,
        forward: bool,
        pos: &mut u32,
        point: &mut Point,
    ) -> Option<usize> {
        let x = self.poly.point_at(v);
        (*pos, *point) = (v as u32, x);
        if !self.is_far(k, x) {
            return None;
        }
        let next = if forward {
            self.poly.next_at(v)
        } else {
            self.poly.prev_at(v)
        };
        (next != self.t).then_some(next)
    }
}

/// How many steps of each walk [`lockstep`] takes between two checks of its buffers'
/// room.
pub(super) const CHUNK: usize = 64;

/// Makes room for `m` more vertices in a walk's buffers, returning the slices to write
/// them to (the buffers are cut back to what was written by [`close`]).
#[inline(always)]
pub(super) fn open((positions, points): &mut (Vec<u32>, Vec<Point>), m: usize) -> (&mut [u32], &mut [Point]) {
    let len = positions.len();
    positions.resize(len + m, 0);
    points.resize(len + m, Point::new(0.0, 0.0));
    (&mut positions[len..], &mut points[len..])
}

/// After `steps` steps of a chunk that [`open`] made room for `m` of: the buffers keep
/// the vertices written, and the cursor moves to `next` (`None`: the chain is closed)
/// or ends at the step cap.
#[inline(always)]
pub(super) fn close(
    (positions, points): &mut (Vec<u32>, Vec<Point>),
    c: &mut Cursor,
    m: usize,
    steps: usize,
    next: Option<usize>,
) {
    let len = positions.len() - (m - steps);
    positions.truncate(len);
    points.truncate(len);
    c.steps_left -= steps;
    match next {
        Some(v) if c.steps_left > 0 => c.v = v,
        _ => c.done = true,
    }
}

/// Steps the active walks in lockstep (one step of each per round) until one of them
/// ends: their cache misses overlap. The steps run in chunks written to slices, with
/// each walk's state in locals, so that a step is a load, a side test and two stores.
pub(super) fn lockstep<K: Kernel>(k: K, slots: &mut [Option<Active<'_>>; 2]) {
    match slots {
        [Some(a), Some(b)] => {
            while !a.cursor.done && !b.cursor.done {
                let m = CHUNK.min(a.cursor.steps_left).min(b.cursor.steps_left);
                let (wa, wb) = (a.walk, b.walk);
                let (fa, fb) = (a.cursor.forward, b.cursor.forward);
                let (mut va, mut vb) = (Some(a.cursor.v), Some(b.cursor.v));
                let ((pa, xa), (pb, xb)) = (open(&mut a.buffers, m), open(&mut b.buffers, m));
                let mut steps = 0;
                let slots_a = pa.iter_mut().zip(xa.iter_mut());
                for ((pa, xa), (pb, xb)) in slots_a.zip(pb.iter_mut().zip(xb.iter_mut())) {
                    let (Some(u), Some(w)) = (va, vb) else {
                        break;
                    };
                    va = wa.step(k, u, fa, pa, xa);
                    vb = wb.step(k, w, fb, pb, xb);
                    steps += 1;
                }
                close(&mut a.buffers, &mut a.cursor, m, steps, va);
                close(&mut b.buffers, &mut b.cursor, m, steps, vb);
            }
        }
        [Some(a), None] | [None, Some(a)] => {
            while !a.cursor.done {
                let m = CHUNK.min(a.cursor.steps_left);
                let (w, forward) = (a.walk, a.cursor.forward);
                let mut v = Some(a.cursor.v);
                let (positions, points) = open(&mut a.buffers, m);
                let mut steps = 0;
                for (pos, point) in positions.iter_mut().zip(points.iter_mut()) {
                    let Some(u) = v else {
                        break;
                    };
                    v = w.step(k, u, forward, pos, point);
                    steps += 1;
                }
                close(&mut a.buffers, &mut a.cursor, m, steps, v);
            }
        }
        [None, None] => {}
    }
}
