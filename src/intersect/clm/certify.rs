//! Certification: the certificate of a certified query from what the query recorded
//! (module docs of [`super`], "Certificate").

use super::quads::{Quad, sample_quads};
use super::witness::{
    Cone, Radon, WitnessVertex, cone_witness, in_triangles, resolve_linked_chords, straddle_certificate,
    witness_certificate,
};
use super::{ClmWorkspace, Set};
use crate::intersect::ArrayEngine;
use crate::intersect::certificate::{from_support, supports_left, supports_right};
use crate::intersect::{Barba, Certificate, Derivation, Which};
use crate::kernel::{Kernel, Orientation, Point};
use crate::lp::WitnessPoint;
use crate::polygon::{ConvexPolygon, LinkedPolygon};
use rand::Rng;

/// The certificate of a certified query from its trace (module docs), or `None` when
/// the trace gives none in O(1) (then the caller walks the polygons). `rng` serves the
/// drawn witnesses ([`drawn_witness`]).
pub(super) fn certify<K: Kernel, R: Rng + ?Sized>(
    k: K,
    answer: bool,
    p: &LinkedPolygon,
    q: &LinkedPolygon,
    ws: &mut ClmWorkspace,
    rng: &mut R,
) -> Option<Certificate> {
    let ClmWorkspace {
        rp,
        rq,
        cp,
        cq,
        chain,
        chain2,
        lp,
        rp_points,
        rq_points,
        chain_points,
        trace,
        draws,
        ..
    } = ws;
    let (lp, trace) = (&*lp, &*trace);
    let set = |s: Set| -> (&[u32], &LinkedPolygon) {
        let positions = match s {
            Set::Rp => &*rp,
            Set::Rq => &*rq,
            Set::Cp => &*cp,
            Set::Cq => &*cq,
            Set::Chain => &*chain,
            Set::Chain2 => &*chain2,
        };
        (positions, if s.of() == Which::P { p } else { q })
    };
    // The points at a set's positions, index for index.
    let points = |s: Set| -> &[Point] {
        match s {
            Set::Rp => rp_points,
            Set::Rq => rq_points,
            Set::Cp | Set::Cq | Set::Chain | Set::Chain2 => &chain_points[s.chain_index()],
        }
    };
    if answer {
        if let Some((of, point)) = trace.inside {
            return Some(Certificate::VertexInside { of, point });
        }
        // The LP's witness; else a vertex inside among the points it examined; else its
        // two crossing chords, resolved by walks from the nearest sample or chain vertex.
        let (a, b) = trace.meet?;
        if lp.witness_points().is_empty() {
            // The chain walk found the sets' hulls intersecting (`walk_or_lp`): both are
            // in boundary order, so they are convex polygons.
            let samples = (a, b) == (Set::Rp, Set::Rq) || (a, b) == (Set::Rq, Set::Rp);
            // Samples the walk found meeting are in boundary order already.
            let drawn = |[pc, qc]: [(Point, Point); 2], rng: &mut R| {
                let quads = (|| Quad::new(pc, rp_points), || Quad::new(qc, rq_points));
                draws.witness(k, (p, q), quads, rng)
            };
            return convex_sets_certificate(k, (p, q), (a, b), set, points, samples.then_some(drawn), rng);
        }
        // The sets are one of each polygon. Witness points keep their index in their
        // set until a pair of chords needs the arena positions (most queries end
        // before, with a vertex inside).
        let (a_of, b_of) = (a.of(), b.of());
        let vertex = |w: WitnessPoint| WitnessVertex {
            point: w.point,
            of: if w.in_b { b_of } else { a_of },
            pos: w.index,
        };
        // The LP's last step: its violating point beyond a chord of the other set (five
        // points), or a mixed pair of bounds (the other set's bound beyond a chord of
        // the violating point's set).
        let straddle = lp.straddle();
        let mixed = if straddle.is_none() { lp.mixed() } else { None };
        let samples = (a, b) == (Set::Rp, Set::Rq) || (a, b) == (Set::Rq, Set::Rp);
        if samples {
            // That point in the quadrilateral of the chord's sample on the chord (the
            // sample vertex farthest beyond it on either side): no pass but that one.
            let named = match (straddle, mixed) {
                (Some([x, _, b, c, _]), _) => Some((x, [b, c])),
                (None, Some([y, x, x1, _, _])) => Some((y, [x, x1])),
                _ => None,
            };
            // The prefix test's quadrilaterals, where it ran: their tests are done.
            let mut quads = trace.spread.map_or((None, None), |(a, b)| (Some(a), Some(b)));
            // (Tests turn the quadrilaterals off with a cap of 0 rounds.)
            if let Some((z, [u, v])) = named
                && draws.rounds != Some(0)
            {
                let (z, of) = ((vertex(z).of, z.point), vertex(u).of);
                if let Some(c) =
                    sample_quads(k, z, (of, (u.point, v.point)), (rp_points, rq_points), &mut quads)
                {
                    draws.found += 1;
                    return Some(c);
                }
            }
            // A drawn vertex of one polygon in the other sample's quadrilateral.
            let quads = (
                || quads.0.unwrap_or_else(|| Quad::spread(rp_points)),
                || quads.1.unwrap_or_else(|| Quad::spread(rq_points)),
            );
            if let Some(c) = draws.witness(k, (p, q), quads, rng) {
                return Some(c);
            }
        }
        // The last step's five points: a vertex inside or two chords.
        let mut chords = None;
        if let Some([x, x0, b, c, y0]) = straddle {
            match straddle_certificate(k, [vertex(x), vertex(x0)], [vertex(b), vertex(c), vertex(y0)]) {
                Radon::Inside(c) => return Some(c),
                Radon::Chords(pc, qc) => chords = Some((pc, qc)),
                Radon::Nothing => {}
            }
        } else if let Some([y, x, x1, t, x0]) = mixed {
            let (x, x1, t, x0) = (vertex(x), vertex(x1), vertex(t), vertex(x0));
            if let Some(c) = in_triangles(k, vertex(y), &[[x, x1, t], [x, x1, x0]]) {
                return Some(c);
            }
        }
        // The points the LP examined (which hold most of its witness): those of the
        // other set than the violating point in the cone it sees its own set in.
        if let Some(&x) = lp.witness_points().first() {
            match cone_witness(
                k,
                x,
                || lp.examined(),
                |in_b| if in_b { b_of } else { a_of },
                chords.is_none(),
            ) {
                Cone::Inside(c) => return Some(c),
                Cone::Chords(own, other) => {
                    let (own, other) = (own.map(|w| w.index), other.map(|w| w.index));
                    chords = Some(if vertex(x).of == Which::P {
                        (own, other)
                    } else {
                        (other, own)
                    });
                }
                _ => {}
            }
        }
        // Two crossing chords: from the last step, else from the cone, else from the
        // whole witness.
        let (pc, qc) = match chords {
            Some(c) => c,
            None => match witness_certificate(k, lp.witness_points().iter().map(|&w| vertex(w))) {
                Radon::Inside(c) => return Some(c),
                Radon::Chords(pc, qc) => (pc, qc),
                Radon::Nothing => return None,
            },
        };
        let (p_set, q_set) = if a_of == Which::P { (a, b) } else { (b, a) };
        // Before walking: a drawn vertex of one polygon in the other's sample hull.
        let starts = |s: Set| (set(s).0, points(s));
        // A chord's ends from indices in its set to arena positions.
        let ends = |s: Set, [i, j]: [Option<usize>; 2]| {
            let positions = set(s).0;
            Some((positions[i?] as usize, positions[j?] as usize))
        };
        return resolve_linked_chords(
            k,
            p,
            ends(p_set, pc)?,
            starts(p_set),
            q,
            ends(q_set, qc)?,
            starts(q_set),
        );
    }
    // The lines whose tangent vertices are extreme in the whole polygons separate them.
    trace.lines.iter().rev().find_map(|&(t, a, b)| {
        let ((a_pos, a_poly), (b_pos, b_poly)) = (set(a), set(b));
        let (ta, tb) = (a_pos[t.a] as usize, b_pos[t.b] as usize);
        let line = (t.start, t.end);
        if !supports_right(k, line, a_poly, ta) || !supports_left(k, line, b_poly, tb) {
            return None;
        }
        from_support(k, line, a_poly, ta, b_poly, tb).map(|c| c.relative_to(a.of()))
    })
}

/// The certificate of intersecting sets `a` and `b` (one of each polygon, given by
/// `set` and `points`) that the chain walk found meeting: each is in boundary order
/// (a sample put in order, or a chain in walk order, either way round), so it lists the
/// vertices of a strictly convex polygon, inside its own polygon. Barba's certified
/// search on the two, O(log r), gives a vertex of one inside the other (a vertex of its
/// polygon inside the other polygon) or two crossing edges, which are chords of the
/// polygons, resolved along them as the LP's chords are, unless `drawn` (given when
/// the sets are the two samples) finds a drawn vertex inside first. `None` for sets of
/// fewer than three points (the caller reran the LP for those) or if the search gives
/// no witness (only an inconsistent kernel).
#[inline(never)]
#[allow(clippy::too_many_arguments)]
pub(super) fn convex_sets_certificate<'a, K: Kernel, R: Rng + ?Sized>(
    k: K,
    (p, q): (&LinkedPolygon, &LinkedPolygon),
    (a, b): (Set, Set),
    set: impl Fn(Set) -> (&'a [u32], &'a LinkedPolygon),
    points: impl Fn(Set) -> &'a [Point],
    drawn: Option<impl FnOnce([(Point, Point); 2], &mut R) -> Option<Certificate>>,
    rng: &mut R,
) -> Option<Certificate> {
    let polygon = |s: Set| -> Option<ConvexPolygon> {
        let v = points(s);
        if v.len() < 3 {
            return None;
        }
        // Strictly convex: the first three points give the orientation.
        let turn = k.orient(v[0], v[1], v[2]);
        if turn == Orientation::Collinear {
            return None;
        }
        let mut v = v.to_vec();
        if turn == Orientation::Cw {
            v.reverse();
        }
        Some(ConvexPolygon::from_ccw_unchecked(v))
    };
    let Derivation::Certified(c) = Barba.derive_probed(k, &polygon(a)?, &polygon(b)?, &mut ()) else {
        return None;
    };
    let (p_set, q_set) = if a.of() == Which::P { (a, b) } else { (b, a) };
    match c.relative_to(a.of()) {
        c @ Certificate::VertexInside { .. } => Some(c),
        Certificate::CrossingEdges { p: [u, v], q: [s, t] } => {
            // Before walking: a drawn vertex of one polygon in the other's sample hull.
            if let Some(c) = drawn.and_then(|drawn| drawn([(u, v), (s, t)], rng)) {
                return Some(c);
            }
            // The chords' ends at their arena positions.
            let at = |set_of: Set, x: Point| {
                let i = points(set_of).iter().position(|&y| y == x)?;
                Some(set(set_of).0[i] as usize)
            };
            let starts = |s: Set| (set(s).0, points(s));
            resolve_linked_chords(
                k,
                p,
                (at(p_set, u)?, at(p_set, v)?),
                starts(p_set),
                q,
                (at(q_set, s)?, at(q_set, t)?),
                starts(q_set),
            )
        }
        Certificate::Separated { .. } => None,
    }
}
