//! The query: samples, the LP on them, the walks, and the decision.

use super::lp_call::{counted_lp_after, walk_or_lp};
use super::ordering::boundary_order;
use super::quads::{Quad, prefix_inside};
use super::sampling::{
    PREFIX, arena, draw_below, fisher_yates, gather, next_points, prefix_of, sample, sample_size, shuffle,
};
use super::walks::{ChainOrder, Chains, Walk, walk_and_decide};
use super::{ClmVariant, ClmWorkspace, LpOrder, Sampling, Set};
use crate::intersect::{Probe, Which};
use crate::kernel::{Kernel, Orientation, Point};
use crate::lp::{ArenaPoints, LpError, Separation, separating_line};
use crate::polygon::{LinkedPolygon, box_of};
use rand::Rng;

/// [`prefix_inside`] on the parts `part` of the two samples (P's points, Q's) and
/// `quads` (P's, Q's): counts the points tested as work and reports them to `probe`.
/// When a point lies inside, also reports the samples and then `prefix_lp` (the work
/// and result of an LP on the prefixes that ran before, not reported yet) first and,
/// with `CERT`, records the certificate; then true, the answer (intersecting).
#[allow(clippy::too_many_arguments)]
pub(super) fn quads_answer<K: Kernel, P: Probe, const CERT: bool>(
    k: K,
    (p, q): (&LinkedPolygon, &LinkedPolygon),
    part: fn(&[Point]) -> &[Point],
    quads: &(Quad, Quad),
    prefix_lp: Option<(u64, Result<Separation, LpError>)>,
    ws: &mut ClmWorkspace,
    probe: &mut P,
) -> bool {
    let (a, b) = (part(&ws.rp_points), part(&ws.rq_points));
    let (tested, found) = prefix_inside(k, (a, &quads.0), (b, &quads.1));
    ws.tested += tested;
    let Some((of, point)) = found else {
        probe.sample_quads(tested, None);
        return false;
    };
    probe.samples(&arena(p, &ws.rp), &arena(q, &ws.rq));
    if let Some((work, result)) = prefix_lp {
        let (pa, pb) = (arena(p, prefix_of(&ws.rp)), arena(q, prefix_of(&ws.rq)));
        probe.lp_call(&pa, &pb, work, &result);
    }
    let quad = if of == Which::P { &quads.1 } else { &quads.0 };
    probe.sample_quads(tested, Some((of, point, quad.corners())));
    if CERT {
        ws.trace.inside = Some((of, point));
    }
    true
}

/// The test; with `CERT` it also records in `ws.trace` what its certificate needs.
pub(super) fn clm<K: Kernel, R: Rng + ?Sized, P: Probe, const CERT: bool>(
    k: K,
    v: ClmVariant,
    p: &LinkedPolygon,
    q: &LinkedPolygon,
    rng: &mut R,
    ws: &mut ClmWorkspace,
    probe: &mut P,
) -> bool {
    if CERT {
        ws.trace.inside = None;
        ws.trace.meet = None;
        ws.trace.spread = None;
        ws.trace.lines.clear();
    }
    ws.lp.record_witness(CERT);
    // With the samples in boundary order nothing is in random order: the LPs that
    // still run shuffle their points themselves.
    let caller_random = v.lp_order == LpOrder::Caller && !v.sample_walk;
    ws.lp.keep_order(caller_random);
    ws.rp.clear();
    ws.rq.clear();
    let (rp_len, rq_len) = (sample_size(v.factor, p.len()), sample_size(v.factor, q.len()));
    // Independent draws on both sides (see `sample`), of which the prefix LP below
    // uses the first PREFIX.
    let independent = v.sampling == Sampling::Independent
        && rp_len.saturating_mul(16) <= p.len()
        && rq_len.saturating_mul(16) <= q.len();
    // With the prefix LP, independent samples are drawn in two parts: the prefixes
    // first, the rest only if the prefixes' hulls are disjoint (most intersecting
    // queries end there without reading the rest).
    let prefix_first = v.sample_walk && independent;
    let (first_p, first_q) = if prefix_first {
        (PREFIX.min(rp_len), PREFIX.min(rq_len))
    } else {
        (rp_len, rq_len)
    };
    match v.sampling {
        Sampling::Independent => {
            sample(p, first_p, rng, &mut ws.sample, &mut ws.rp);
            sample(q, first_q, rng, &mut ws.sample, &mut ws.rq);
            if caller_random {
                // Only independent draws come in random order.
                for (r, poly) in [(&mut ws.rp, p), (&mut ws.rq, q)] {
                    if r.len().saturating_mul(16) > poly.len() {
                        shuffle(r, &mut [], rng);
                    }
                }
            }
        }
        Sampling::FisherYates => {
            fisher_yates(p.len(), rp_len, rng, &mut ws.perm, &mut ws.swaps, &mut ws.rp);
            fisher_yates(q.len(), rq_len, rng, &mut ws.perm, &mut ws.swaps, &mut ws.rq);
        }
    }
    // One pass of independent reads per sample (their cache misses overlap), so the
    // LPs that use a sample read contiguous memory.
    gather(p, &ws.rp, &mut ws.rp_points);
    gather(q, &ws.rq, &mut ws.rq_points);
    // Intersecting samples usually show within a few dozen points: an LP on a short
    // prefix of each sample answers most intersecting queries before the samples are
    // put in order (a prefix of a random sample is a random sample).
    let mut spent = 0;
    let prefix_lp = v.sample_walk && (rp_len > PREFIX || rq_len > PREFIX);
    // The prefixes' quadrilaterals (P's, Q's).
    let prefix_quads = (prefix_lp && v.prefix_quads).then(|| {
        let (a, b) = (prefix_of(&ws.rp_points), prefix_of(&ws.rq_points));
        (Quad::spread(a), Quad::spread(b))
    });
    // The prefix LP's work and result, once it ran.
    let mut prefix_lp_ran = None;
    if prefix_lp {
        let before = ws.lp.work;
        // A prefix vertex of one polygon in a quadrilateral of the other prefix's
        // points answers most intersecting queries before any LP.
        if let Some(quads) = &prefix_quads
            && quads_answer::<K, P, CERT>(k, (p, q), prefix_of, quads, None, ws, probe)
        {
            return true;
        }
        let (a, b) = (prefix_of(&ws.rp_points), prefix_of(&ws.rq_points));
        // Distinct samples come in arena order: the LP shuffles them.
        let random = v.sampling == Sampling::FisherYates || independent;
        ws.lp.keep_order(random);
        let meet = separating_line(k.within([box_of(a), box_of(b)]), a, b, rng, &mut ws.lp);
        ws.lp.keep_order(caller_random);
        spent = ws.lp.work - before;
        prefix_lp_ran = Some((spent, meet));
        if meet == Ok(Separation::Intersecting) {
            let (rp, rq) = (arena(p, &ws.rp), arena(q, &ws.rq));
            probe.samples(&rp, &rq);
            probe.lp_call(&rp, &rq, spent, &meet);
            if CERT {
                // The witness's indices are the prefixes', the samples' own.
                ws.trace.meet = Some((Set::Rp, Set::Rq));
                ws.trace.spread = prefix_quads;
            }
            return true;
        }
    }
    if prefix_first {
        // The rest of the samples, read in one more pass of independent reads.
        for (poly, r, positions, points) in [
            (p, rp_len, &mut ws.rp, &mut ws.rp_points),
            (q, rq_len, &mut ws.rq, &mut ws.rq_points),
        ] {
            let drawn = positions.len();
            draw_below(rng, poly.len() as u32, r - drawn, positions);
            points.extend(positions[drawn..].iter().map(|&i| poly.point_at(i as usize)));
        }
        // The next points of each sample in the prefixes' quadrilaterals: about half
        // of the intersecting queries whose prefix hulls are disjoint end here, before
        // the samples are put in order.
        if let Some(quads) = &prefix_quads
            && quads_answer::<K, P, CERT>(k, (p, q), next_points, quads, prefix_lp_ran, ws, probe)
        {
            return true;
        }
    }
    // Both samples in boundary order, or neither: then the LPs decide.
    let ordered = v.sample_walk
        && boundary_order(k, &mut ws.rp, &mut ws.rp_points, &mut ws.order)
        && boundary_order(k, &mut ws.rq, &mut ws.rq_points, &mut ws.order);
    let rp = ArenaPoints {
        polygon: p,
        positions: &ws.rp,
    };
    let rq = ArenaPoints {
        polygon: q,
        positions: &ws.rq,
    };
    probe.samples(&rp, &rq);
    let first_lp = if ordered {
        walk_or_lp::<K, R, P, CERT>(
            k,
            (&rp, &ws.rp_points),
            (&rq, &ws.rq_points),
            [0, 0],
            spent,
            rng,
            &mut ws.lp,
            probe,
        )
    } else {
        counted_lp_after(
            k,
            (&rp, &ws.rp_points),
            (&rq, &ws.rq_points),
            spent,
            rng,
            &mut ws.lp,
            probe,
        )
    };
    let t = match first_lp {
        Ok(Separation::Separated(t)) => t,
        // Samples are never empty (polygons have ≥ 3 vertices), so only a real
        // intersection of the sample hulls gets here.
        _ => {
            if CERT {
                ws.trace.meet = Some((Set::Rp, Set::Rq));
            }
            return true;
        }
    };
    if CERT {
        ws.trace.lines.push((t, Set::Rp, Set::Rq));
    }
    if ws.rp.len() == p.len() && ws.rq.len() == q.len() {
        return false; // the LP saw both polygons whole
    }
    let (tp, tq) = (ws.rp[t.a] as usize, ws.rq[t.b] as usize);
    // P lies on the right of the line, Q on the left: P's far side is the left.
    let first = [
        Walk::new(p, t.start, t.end, Orientation::Ccw, tp),
        Walk::new(q, t.start, t.end, Orientation::Cw, tq),
    ];
    // The chains are walked into buffers taken out of the workspace for the schedule
    // and put back after it, whatever it answers.
    let mut chains = Chains(
        [
            std::mem::take(&mut ws.cp),
            std::mem::take(&mut ws.cq),
            std::mem::take(&mut ws.chain),
            std::mem::take(&mut ws.chain2),
        ],
        std::mem::take(&mut ws.chain_points),
    );
    let order = ChainOrder {
        shuffle: caller_random,
        walk: v.chain_walk,
        samples: ordered.then_some([t.a, t.b]),
    };
    let answer = walk_and_decide::<K, R, P, CERT>(k, p, q, first, &mut chains, order, rng, ws, probe);
    let Chains([cp, cq, chain, chain2], points) = chains;
    (ws.cp, ws.cq, ws.chain, ws.chain2) = (cp, cq, chain, chain2);
    ws.chain_points = points;
    answer
}
