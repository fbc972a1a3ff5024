//! The certified modes of a run ([`Derive`], [`Certify`]) and the certificates they build
//! from what a run found: separating edges, vertices inside, crossing edges,
//! and the lift of the small-Q end game.

use super::engine::{Exit, Mode, Range, Record, SMALL_Q, SegmentExit, SegmentTable, Sep, SmallQ, run};
use super::{Ours, Variant};
use crate::intersect::certificate::{
    Reduced, crossing, edge_between, endpoint_on_other, extreme_left, reduce_chord, resolve_chords,
    resolve_crossing_chords, separates,
};
use crate::intersect::engine::{Completer, Completion};
use crate::intersect::{Certificate, Derivation, Which};
use crate::kernel::{Kernel, Orientation, Point, SegmentContact, point_on_segment};
use crate::polygon::Vertices;
use Orientation::{Ccw, Collinear, Cw};

/// The certified call: the exit turned into a certificate where it ends, so that no
/// [`Exit`] is returned and matched again.
pub(super) struct Derive;

impl Mode for Derive {
    type Out = Derivation;
    const CERTIFY: bool = true;
    #[inline(always)]
    fn done<K: Kernel, V: Variant, PV: Vertices + ?Sized, QV: Vertices + ?Sized>(
        k: K,
        pv: &PV,
        qv: &QV,
        _: bool,
        exit: impl FnOnce() -> Exit,
    ) -> Derivation {
        // A vertex inside is its own certificate, built where the run ends (each call
        // site's exit is a known variant, so this match folds away there); the other
        // exits go out of line.
        match exit() {
            Exit::PInside(i) => Derivation::Certified(Certificate::VertexInside {
                of: Which::P,
                point: pv.get(i),
            }),
            Exit::QInside(j) => Derivation::Certified(Certificate::VertexInside {
                of: Which::Q,
                point: qv.get(j),
            }),
            // The other exits read vertices all over both polygons: on slices (a
            // computed polygon's vertices collected first, O(n), only where a run ends).
            Exit::Segment(exit) => {
                pv.with_slice(|pv| qv.with_slice(|qv| segment_derivation(k, pv, qv, exit)))
            }
            other => pv.with_slice(|pv| qv.with_slice(|qv| derivation::<K, V>(k, pv, qv, other))),
        }
    }
}

/// The certified call without a probe: [`Derive`]'s derivation completed where the run
/// ends ([`Completer`] where it gives only the
/// answer), so that the certificate is written once, in the caller's place.
pub(super) struct Certify;

impl Mode for Certify {
    type Out = Certificate;
    const CERTIFY: bool = true;
    #[inline(always)]
    fn done<K: Kernel, V: Variant, PV: Vertices + ?Sized, QV: Vertices + ?Sized>(
        k: K,
        pv: &PV,
        qv: &QV,
        _: bool,
        exit: impl FnOnce() -> Exit,
    ) -> Certificate {
        match exit() {
            Exit::PInside(i) => Certificate::VertexInside {
                of: Which::P,
                point: pv.get(i),
            },
            Exit::QInside(j) => Certificate::VertexInside {
                of: Which::Q,
                point: qv.get(j),
            },
            // As in `Derive`: the other exits on slices.
            Exit::Segment(exit) => {
                pv.with_slice(|pv| qv.with_slice(|qv| segment_certificate(k, pv, qv, exit)))
            }
            other => pv.with_slice(|pv| qv.with_slice(|qv| completed::<K, V>(k, pv, qv, other))),
        }
    }
}

/// [`Certify`]'s certificate for an exit other than a vertex inside or a segment.
/// [`derivation`]'s body is written out here (no call, no [`Derivation`] moved).
#[inline(never)]
pub(super) fn completed<K: Kernel, V: Variant>(k: K, pv: &[Point], qv: &[Point], exit: Exit) -> Certificate {
    let complete = |answer| Completer::complete(k, pv, qv, Derivation::Answer(answer), &mut ());
    match exit {
        Exit::Apart { pr, q, line } => {
            match lift(k, pv, qv, pr, q, line).or_else(|| rerun_lift::<K, V>(k, pv, qv)) {
                Some(c) => c,
                None => complete(false),
            }
        }
        Exit::Stuck(answer) => complete(answer),
        meet => match meet_certificate(k, pv, qv, meet) {
            Some(c) => c,
            None => complete(true),
        },
    }
}

/// The run with the roles exchanged, which ends on other pieces, and its separating
/// edge if [`lift`] finds one.
#[inline]
pub(super) fn rerun_lift<K: Kernel, V: Variant>(k: K, pv: &[Point], qv: &[Point]) -> Option<Certificate> {
    match run::<K, (), Record, V, _, _>(k, qv, pv, &mut ()) {
        Exit::Apart { pr, q, line } => lift(k, qv, pv, pr, q, line).map(Certificate::swapped),
        _ => None,
    }
}

/// [`Certify`]'s certificate for a segment exit ([`segment_witness`]).
#[inline(never)]
pub(super) fn segment_certificate<K: Kernel>(
    k: K,
    pv: &[Point],
    qv: &[Point],
    exit: SegmentExit,
) -> Certificate {
    segment_witness(
        k,
        pv,
        qv,
        exit,
        |c| c,
        || Completer::complete(k, pv, qv, Derivation::Answer(true), &mut ()),
    )
}

/// The certified call's result for a run's exit (the module docs' "Certificate"). Out
/// of line, so that the certified loop's code stays the plain loop's.
#[inline(never)]
pub(super) fn derivation<K: Kernel, V: Variant>(k: K, pv: &[Point], qv: &[Point], exit: Exit) -> Derivation {
    match exit {
        Exit::Apart { pr, q, line } => lift(k, pv, qv, pr, q, line)
            .or_else(|| rerun_lift::<K, V>(k, pv, qv))
            .map_or(Derivation::Answer(false), Derivation::Certified),
        Exit::Stuck(answer) => Derivation::Answer(answer),
        meet => meet_certificate(k, pv, qv, meet).map_or(Derivation::Answer(true), Derivation::Certified),
    }
}

/// The witness of an intersecting pair from Barba's run, or `None` when the run finds
/// the pair disjoint (or an inconsistent kernel gets stuck): what [`Linear`]'s and
/// [`Dobkin`](crate::intersect::Dobkin)'s certified calls use for intersecting pairs.
pub(crate) fn meeting_certificate<K: Kernel>(k: K, pv: &[Point], qv: &[Point]) -> Option<Certificate> {
    meet_certificate(k, pv, qv, run::<K, (), Record, Ours, _, _>(k, pv, qv, &mut ()))
}

/// The certificate of a meeting exit (`None` for the others).
pub(super) fn meet_certificate<K: Kernel>(
    k: K,
    pv: &[Point],
    qv: &[Point],
    exit: Exit,
) -> Option<Certificate> {
    match exit {
        Exit::PInside(i) => Some(Certificate::VertexInside {
            of: Which::P,
            point: pv[i],
        }),
        Exit::QInside(j) => Some(Certificate::VertexInside {
            of: Which::Q,
            point: qv[j],
        }),
        Exit::Chord { a, b, e } => resolve_chords(k, pv, (a, b), qv, (e, (e + 1) % qv.len())),
        Exit::Small { pr, qs } => small_witness(k, pv, pr, qv, qs),
        Exit::Segment(exit) => segment_witness(k, pv, qv, exit, Some, || None),
        Exit::Apart { .. } | Exit::Stuck(_) => None,
    }
}

/// T_P meets the hull of the explicit Q': a vertex of T_P in it (a vertex of P in Q), a
/// vertex of it in T_P (a vertex of Q in P), or else an edge of T_P (a chord of P)
/// crossing one of its edges (an edge of Q, or its closing chord), resolved by
/// [`resolve_chords`] with one binary search within P'. The vertex tests stop at the
/// first edge a vertex is strictly outside of; only the crossing reads the full table
/// of the orientations of T_P's vertices against Q''s edges and of Q''s vertices
/// against T_P's edges (at most 36 predicates).
pub(super) fn small_witness<K: Kernel>(
    k: K,
    pv: &[Point],
    pr: Range,
    qv: &[Point],
    small: SmallQ,
) -> Option<Certificate> {
    let t = pr.triangle(pv.len());
    let tp = t.map(|i| pv[i]);
    let (qi, len) = small.indices(qv.len());
    if len == 2 {
        // Q' is a segment (certified runs end there with `Exit::Segment` instead).
        return match SegmentTable::axis(k, &tp, [qv[qi[0]], qv[qi[1]]]) {
            Ok(_) => None,
            Err(table) => {
                let exit = SegmentExit::new(pv.len(), qv.len(), pr, small, table);
                segment_witness(k, pv, qv, exit, Some, || None)
            }
        };
    }
    let qp: [Point; SMALL_Q] = std::array::from_fn(|j| if j < len { qv[qi[j]] } else { Point::default() });
    // A vertex of either inside the other, each test stopping at the first edge it is
    // strictly outside of.
    if let Some(a) = (0..3).find(|&a| (0..len).all(|e| k.orient(qp[e], qp[(e + 1) % len], tp[a]) != Cw)) {
        return Some(Certificate::VertexInside {
            of: Which::P,
            point: tp[a],
        });
    }
    if let Some(j) = (0..len).find(|&j| (0..3).all(|a| k.orient(tp[a], tp[(a + 1) % 3], qp[j]) != Cw)) {
        return Some(Certificate::VertexInside {
            of: Which::Q,
            point: qp[j],
        });
    }
    // The full tables, only for the crossing.
    let mut t_side = [[Collinear; SMALL_Q]; 3];
    for (a, row) in t_side.iter_mut().enumerate() {
        for (e, o) in row.iter_mut().enumerate().take(len) {
            *o = k.orient(qp[e], qp[(e + 1) % len], tp[a]);
        }
    }
    let mut q_side = [[Collinear; 3]; SMALL_Q];
    for (j, row) in q_side.iter_mut().enumerate().take(len) {
        for (a, o) in row.iter_mut().enumerate() {
            *o = k.orient(tp[a], tp[(a + 1) % 3], qp[j]);
        }
    }
    // No vertex of either in the other, yet they meet: some edge of T_P crosses some
    // edge of Q' properly. Edges of Q come before Q''s closing chord (one search less).
    let straddle = |x: Orientation, y: Orientation| x != Collinear && y == x.reverse();
    let (a, e) = (0..len).find_map(|e| {
        (0..3)
            .find(|&a| {
                straddle(q_side[e][a], q_side[(e + 1) % len][a])
                    && straddle(t_side[a][e], t_side[(a + 1) % 3][e])
            })
            .map(|a| (a, e))
    })?;
    let (a, b) = pr.chord(a);
    resolve_crossing_chords(k, pv, (t[a], t[b]), qv, (qi[e], qi[(e + 1) % len]))
}

/// T_P meets the segment Q' (a chord of Q), as its orientation table shows: a vertex of
/// T_P on the segment (a vertex of P in Q), an end of the segment in T_P (a vertex of Q
/// in P), or else an edge of T_P (a chord of P) crossing the segment properly, resolved
/// by [`reduce_chord`] (one search within P', then one within Q' if needed) starting
/// from the table's orientations: which end of the segment lies beyond the chord, and
/// the chord's start against the segment's line. The steps of
/// [`resolve_chords`] that the table already decides are not taken.
#[inline(always)]
pub(super) fn segment_witness<K: Kernel, O>(
    k: K,
    pv: &[Point],
    qv: &[Point],
    exit: SegmentExit,
    certified: impl Fn(Certificate) -> O,
    unproven: impl Fn() -> O,
) -> O {
    let SegmentExit {
        t,
        closing_reversed,
        c,
        d,
        q_mid,
        q_edge,
        table: SegmentTable { o, w },
    } = exit;
    let n = pv.len();
    let inside = |of: Which, point: Point| certified(Certificate::VertexInside { of, point });
    let qp = [qv[c], qv[d]];
    if o.contains(&Collinear)
        && let Some(a) = (0..3).find(|&a| o[a] == Collinear && point_on_segment(k, qp[0], qp[1], pv[t[a]]))
    {
        return inside(Which::P, pv[t[a]]);
    }
    if let Some(j) = (0..2).find(|&j| w[j].iter().all(|&x| x != Cw)) {
        return inside(Which::Q, qp[j]);
    }
    // Neither end inside T_P and no vertex of T_P on the segment, yet they meet: an
    // edge of T_P crosses the segment properly (both pairs strictly apart).
    let straddle = |x: Orientation, y: Orientation| x != Collinear && y == x.reverse();
    let Some(a) = (0..3).find(|&a| straddle(o[a], o[(a + 1) % 3]) && straddle(w[0][a], w[1][a])) else {
        return unproven();
    };
    // The chord between T_P's vertices ca and cb: T_P's edge a → a + 1, or P''s closing
    // chord given reversed (0 → 2), so that the chain behind it lies in P'.
    let reversed = a == 2 && closing_reversed;
    let (ca, cb) = if reversed { (0, 2) } else { (a, (a + 1) % 3) };
    // The end strictly right of the chord t[ca] → t[cb]: right of T_P's edge a → a + 1,
    // or left of it for P''s closing chord.
    let beyond = if reversed { Ccw } else { Cw };
    let near = if w[0][a] == beyond { qp[0] } else { qp[1] };
    // P's chord reduced to an edge (one search within P', from the table's orientations;
    // none when the chord is an edge of P), then, if that edge crosses the segment and
    // the segment is a chord of Q (not its edge Q[d] → Q[c]), Q's chord reduced against
    // it from the orientations P's search found.
    // This is `certificate::resolve_crossing` written out with Q's edge known from Q'
    // (`q_edge`): calling it costs 12 more instructions per certified intersecting
    // query at 2^10 (1,549.5 -> 1,561.9) and 8 at 2^14.
    let (i, j) = (t[ca], t[cb]);
    // The chord's end on the side of Q''s chain (strictly right of Q[c] → Q[d]) is a
    // vertex of P; inside the triangle of Q[c], the chain's middle vertex and Q[d] it is
    // inside Q (two orientations, no search).
    let x = if o[ca] == Cw { i } else { j };
    let qm = qv[q_mid];
    if k.orient(qp[0], qm, pv[x]) != Cw && k.orient(qm, qp[1], pv[x]) != Cw {
        return inside(Which::P, pv[x]);
    }
    let next = |x: usize| if x + 1 == n { 0 } else { x + 1 };
    let (e, contact, known_q) = if let Some(e) = edge_between(n, i, j) {
        (e, SegmentContact::Crossing, None)
    } else {
        match reduce_chord(k, pv, (i, j), (qp[0], qp[1]), Some((near, o[ca])), Some(qm)) {
            Reduced::Edge(e, contact, next) => (e, contact, next),
            Reduced::Inside(x) => return inside(Which::Q, x),
            Reduced::Beyond(x) => return inside(Which::P, x),
            Reduced::Fail => return unproven(),
        }
    };
    if q_edge {
        // Q' was all of Q: the segment is Q's edge from Q[d] to Q[c].
        return certified(crossing(pv, e, qv, d));
    }
    let (u, v) = (pv[e], pv[next(e)]);
    if contact != SegmentContact::Crossing {
        return match endpoint_on_other(k, (u, v), (qp[0], qp[1])) {
            Some(c) => certified(c),
            None => unproven(),
        };
    }
    match reduce_chord(k, qv, (c, d), (u, v), known_q, None) {
        Reduced::Edge(f, ..) => certified(crossing(pv, e, qv, f)),
        Reduced::Inside(x) => inside(Which::P, x),
        Reduced::Beyond(x) => inside(Which::Q, x),
        Reduced::Fail => unproven(),
    }
}

/// The certified call's result for a segment exit ([`segment_witness`]), out of line.
#[inline(never)]
pub(super) fn segment_derivation<K: Kernel>(
    k: K,
    pv: &[Point],
    qv: &[Point],
    exit: SegmentExit,
) -> Derivation {
    segment_witness(k, pv, qv, exit, Derivation::Certified, || {
        Derivation::Answer(true)
    })
}

/// A separating edge for the whole polygons from a run's final separation of the
/// pieces, when the final line is an edge of P or of Q that also supports the other
/// polygon: the piece's vertex deepest towards the line is checked to be extreme in
/// the whole polygon ([`separates`], O(1)). `None` when that check fails (the line
/// separates the pieces but not the polygons).
pub(super) fn lift<K: Kernel>(
    k: K,
    pv: &[Point],
    qv: &[Point],
    pr: Range,
    q: SmallQ,
    line: Sep,
) -> Option<Certificate> {
    let (n, m) = (pv.len(), qv.len());
    let deepest = |(s, u): (Point, Point), v: &[Point], cands: &[usize]| {
        cands.iter().copied().reduce(|best, c| {
            if k.cross(s, u, v[best], v[c]) == Orientation::Ccw {
                c
            } else {
                best
            }
        })
    };
    let line = match line {
        // P' is all of P: its closing chord is an edge.
        Sep::PChord if pr.len == n => Sep::PEdge(pr.idx(n, pr.len - 1)),
        other => other,
    };
    match line {
        Sep::QLine(i, j) if (i + 1) % m == j => {
            let (s, u) = (qv[i], qv[j]);
            let t = deepest((s, u), pv, &pr.triangle(n))?;
            // P' lies strictly right of the edge (the run found all of T_P there); so
            // does P if no neighbour of t lies deeper ([`separates`] without its first
            // orientation). The run ended because no chain of P' holds P''s farthest
            // point towards the line strictly inside, so that point is a triangle
            // vertex, t: only a neighbour outside P' (t an end of a proper range) can
            // lie deeper, and only it is checked.
            let deeper = |x: usize| k.cross(s, u, pv[t], pv[x]) == Orientation::Ccw;
            let outside = pr.len < n;
            let next_deeper =
                outside && t == pr.idx(n, pr.len - 1) && deeper(if t + 1 == n { 0 } else { t + 1 });
            let prev_deeper = outside && t == pr.start && deeper(if t == 0 { n - 1 } else { t - 1 });
            if !next_deeper && !prev_deeper {
                return Some(Certificate::Separated {
                    of: Which::Q,
                    from: s,
                    to: u,
                });
            }
            // Otherwise P crosses the edge's line away from P' (a chain pruned by an
            // earlier line), and the separating directions are turned away from this
            // edge's normal towards those of P's edges at P''s vertex t nearest the
            // line: each is checked against Q's extreme vertex (one search).
            if let Some(c) = [(t + n - 1) % n, t].into_iter().find_map(|e| {
                let (a, b) = (pv[e], pv[(e + 1) % n]);
                separates(k, a, b, qv, extreme_left(k, qv, (a, b))).then_some(Certificate::Separated {
                    of: Which::P,
                    from: a,
                    to: b,
                })
            }) {
                return Some(c);
            }
            // Else P's deepest vertex, found by a search, may still be strictly outside.
            separates(k, s, u, pv, extreme_left(k, pv, (s, u))).then_some(Certificate::Separated {
                of: Which::Q,
                from: s,
                to: u,
            })
        }
        Sep::PEdge(e) => {
            let (s, u) = (pv[e], pv[(e + 1) % n]);
            // Candidates only (each is checked): a Q' of at most six vertices whole.
            let (idx, len) = if q.range.len < SMALL_Q || q.chord {
                q.indices(m)
            } else {
                // K's six vertices.
                let r = q.range;
                let m1 = (r.len - 2) / 2;
                let mut out = [0; SMALL_Q];
                for (slot, pos) in out.iter_mut().zip([0, 1, m1, m1 + 1, r.len - 2, r.len - 1]) {
                    *slot = r.idx(m, pos);
                }
                (out, 6)
            };
            let w = deepest((s, u), qv, &idx[..len])?;
            let w = if separates(k, s, u, qv, w) {
                w
            } else {
                extreme_left(k, qv, (s, u))
            };
            separates(k, s, u, qv, w).then_some(Certificate::Separated {
                of: Which::P,
                from: s,
                to: u,
            })
        }
        _ => None,
    }
}
