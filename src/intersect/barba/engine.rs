//! The search: ranges of P and Q, the pruning steps, the small-Q end game and the
//! segment table, generic over what a run records ([`Mode`]).

use super::{Variant, known};
use crate::intersect::certificate::{same_direction, turn_gt};
use crate::intersect::{ArrayIntersection, Linear, Probe};
use crate::kernel::{Kernel, Orientation, Point, ShortEdges, line_meet_side, segments_intersect};
use crate::polygon::{ConvexPolygon, Vertices};
use Orientation::{Ccw, Collinear, Cw};

/// `len ≥ 3` consecutive vertices of a polygon from array index `start`. For P' it may
/// also be the whole of P with the thesis's first triangle (`thirds`, see
/// [`BarbaVariant`]): then T_P is at positions 0, ⌊n/3⌋, ⌊2n/3⌋ and all three sides of
/// T_P are chords with chains of P behind them.
#[derive(Clone, Copy, Debug)]
pub(super) struct Range {
    pub(super) start: usize,
    pub(super) len: usize,
    pub(super) thirds: bool,
}

impl Range {
    #[inline]
    pub(super) fn idx(self, n: usize, pos: usize) -> usize {
        let i = self.start + pos;
        if i >= n { i - n } else { i }
    }
    #[inline]
    fn at<W: Vertices + ?Sized>(self, v: &W, pos: usize) -> Point {
        v.get(self.idx(v.len(), pos))
    }
    #[inline]
    fn sub<W: Vertices + ?Sized>(self, v: &W, from: usize, to: usize) -> Range {
        let s = self.start + from;
        Range {
            start: if s >= v.len() { s - v.len() } else { s },
            len: to - from + 1,
            thirds: false,
        }
    }
    /// Position of T_P's middle vertex (and of the middle edge of a chain).
    #[inline]
    fn mid(self) -> usize {
        (self.len - 1) / 2
    }
    /// Positions in P' of T_P's vertices.
    #[inline]
    fn tri(self) -> [usize; 3] {
        if self.thirds {
            [0, self.len / 3, 2 * self.len / 3]
        } else {
            [0, self.mid(), self.len - 1]
        }
    }
    /// The array indices of T_P's vertices.
    #[inline]
    pub(super) fn triangle(self, n: usize) -> [usize; 3] {
        self.tri().map(|pos| self.idx(n, pos))
    }
    /// The positions of the ends of the chain of P' behind T_P's edge `c` → `c + 1`
    /// (for P''s closing chord, edge 2 of an ordinary range, there is none).
    #[inline]
    fn chain_ends(self, c: usize) -> Option<(usize, usize)> {
        let t = self.tri();
        match c {
            0 | 1 => Some((t[c], t[c + 1])),
            _ if self.thirds => Some((t[2], self.len)),
            _ => None,
        }
    }
    /// T_P's edge `a` → `a + 1` as a pair of triangle vertices whose counter-clockwise
    /// chain of P lies in P' (an ordinary range's closing edge 2 → 0 is given as 0 → 2),
    /// so that reducing the chord to an edge searches P' only.
    #[inline]
    pub(super) fn chord(self, a: usize) -> (usize, usize) {
        if a == 2 && !self.thirds {
            (0, 2)
        } else {
            (a, (a + 1) % 3)
        }
    }
}

/// Below this many vertices Q' is used as it is instead of through its edge hull.
pub(super) const SMALL_Q: usize = 7;

/// Q' given explicitly for the constant-size finish: the vertices of `range` (fewer
/// than [`SMALL_Q`]), or only its first and last vertex when `chord` (the segment
/// Q' shrinks to after a witness beyond Q's closing chord).
#[derive(Clone, Copy, Debug)]
pub(super) struct SmallQ {
    pub(super) range: Range,
    pub(super) chord: bool,
}

impl SmallQ {
    /// The array indices of its vertices (counter-clockwise), and how many there are.
    pub(super) fn indices(self, m: usize) -> ([usize; SMALL_Q], usize) {
        let mut out = [0; SMALL_Q];
        if self.chord {
            out[0] = self.range.idx(m, 0);
            out[1] = self.range.idx(m, self.range.len - 1);
            (out, 2)
        } else {
            let len = self.range.len.min(SMALL_Q);
            for (pos, slot) in out.iter_mut().enumerate().take(len) {
                *slot = self.range.idx(m, pos);
            }
            (out, len)
        }
    }
}

/// The line by which a run found P' and Q' disjoint.
#[derive(Clone, Copy, Debug)]
pub(super) enum Sep {
    /// The line through vertices `i` → `j` of Q (an edge of Q', or a chord of Q when it
    /// closes the small Q'), with Q' on its closed left and T_P strictly right.
    QLine(usize, usize),
    /// The edge of P starting at this index (a chain of P' without interior vertices).
    PEdge(usize),
    /// P''s closing chord.
    PChord,
}

/// How a run ended: the plain call reduces it to the answer, the certified call
/// turns it into a certificate.
#[derive(Clone, Copy, Debug)]
pub(super) enum Exit {
    /// Vertex `i` of P lies in K ⊆ Q (step 1).
    PInside(usize),
    /// Vertex `j` of Q lies in T_P ⊆ P (step 3).
    QInside(usize),
    /// The chord between vertices `a` and `b` of P meets the edge of Q starting at `e`
    /// (step 4).
    Chord { a: usize, b: usize, e: usize },
    /// T_P of `pr` meets the explicit Q' `qs` (constant-size finish).
    Small { pr: Range, qs: SmallQ },
    /// T_P meets the segment Q' (a chord of Q), with the orientations the certified
    /// finish decided it by ([`SegmentExit`]).
    Segment(SegmentExit),
    /// P' = CH(`pr`) and Q' (`q`) are disjoint, by `line`.
    Apart { pr: Range, q: SmallQ, line: Sep },
    /// An inconsistent kernel: the reference's answer on the remaining pieces.
    Stuck(bool),
}

/// What a run returns: the plain call's answer ([`Plain`]), the [`Exit`] ([`Record`]),
/// or the certified call's [`Derivation`](crate::intersect::Derivation) (`witness::Derive`), the last two built only in those
/// cases. The algorithm is written once.
pub(super) trait Mode {
    type Out;
    /// Whether the run's exits are turned into certificates: then the finish against a
    /// segment Q' computes all nine orientations between T_P and the segment, decides
    /// with them, and hands them to the witness ([`Exit::Segment`]).
    const CERTIFY: bool;
    /// The run on `pv` and `qv` ended with this answer; `exit` says how.
    fn done<K: Kernel, V: Variant, PV: Vertices + ?Sized, QV: Vertices + ?Sized>(
        k: K,
        pv: &PV,
        qv: &QV,
        meets: bool,
        exit: impl FnOnce() -> Exit,
    ) -> Self::Out;
}

/// The plain call: the answer alone.
pub(super) struct Plain;

impl Mode for Plain {
    type Out = bool;
    const CERTIFY: bool = false;
    #[inline(always)]
    fn done<K: Kernel, V: Variant, PV: Vertices + ?Sized, QV: Vertices + ?Sized>(
        _: K,
        _: &PV,
        _: &QV,
        meets: bool,
        _: impl FnOnce() -> Exit,
    ) -> bool {
        meets
    }
}

/// How the run ended (the run with the roles exchanged, [`meeting_certificate`]).
pub(super) struct Record;

impl Mode for Record {
    type Out = Exit;
    const CERTIFY: bool = true;
    #[inline(always)]
    fn done<K: Kernel, V: Variant, PV: Vertices + ?Sized, QV: Vertices + ?Sized>(
        _: K,
        _: &PV,
        _: &QV,
        _: bool,
        exit: impl FnOnce() -> Exit,
    ) -> Exit {
        exit()
    }
}

/// What one iteration of the main loop decided (small, so that it is returned in
/// registers; [`run`] turns a decision into an [`Exit`]).
#[derive(Clone, Copy)]
pub(super) enum Step {
    /// T_P's vertex `i` lies in K (step 1).
    InK(u8),
    /// K's vertex `x` (the ends of T_Q's edges, in order) lies in T_P (step 3).
    InTriangle(u8),
    /// T_P's edge `a` → `a + 1` meets T_Q's edge `j` (step 4).
    Crossing(u8, u8),
    /// T_Q's line `j` has T_P strictly outside and P''s farthest point towards it is a
    /// triangle vertex (step 2).
    ApartLine(u8),
    /// T_P's edge `a` separates and closes a chain without interior vertices, or is
    /// P''s closing chord (`a` = 2) (step 5).
    ApartEdge(u8),
    /// Keep chain 0 (`P[a..=mid]`) or 1 (`P[mid..=b]`).
    KeepP(usize),
    /// Keep the pocket beyond chord 0, 1 or 2.
    KeepQ(usize),
    /// Only an inconsistent kernel gets here.
    Stuck,
}

/// Positions in Q' of the starts of T_Q's three edges.
#[inline]
pub(super) fn e_positions(qr: Range) -> [usize; 3] {
    [0, (qr.len - 2) / 2, qr.len - 2]
}

/// Orientations of T_P's vertices (rows) against T_Q's lines (columns), computed
/// lazily and carried over when a step keeps two rows or two columns.
pub(super) struct SideCache(pub(super) [[Option<Orientation>; 3]; 3]);

impl SideCache {
    fn keep_rows(&mut self, chain: usize) {
        let old = self.0;
        // Chain c keeps vertices c and c + 1 as the new 0 and 2.
        self.0 = [old[chain], [None; 3], old[(chain + 1) % 3]];
    }
    fn keep_cols(&mut self, pocket: usize) {
        for row in &mut self.0 {
            let old = *row;
            *row = [old[pocket], None, old[pocket + 1]];
        }
    }
}

/// The test, returning what mode `M` asks for, in variant `V`.
pub(super) fn run<K: Kernel, P: Probe, M: Mode, V: Variant, PV: Vertices + ?Sized, QV: Vertices + ?Sized>(
    k: K,
    pv: &PV,
    qv: &QV,
    probe: &mut P,
) -> M::Out {
    let mut pr = Range {
        start: 0,
        len: pv.len(),
        thirds: V::THIRDS,
    };
    let mut qr = Range {
        start: 0,
        len: qv.len(),
        thirds: false,
    };
    let mut cache = SideCache([[None; 3]; 3]);
    loop {
        if qr.len < V::SMALL_Q {
            let qs = SmallQ {
                range: qr,
                chord: false,
            };
            return against_small::<K, P, M, V, PV, QV>(k, pv, pr, qv, qs, probe);
        }
        probe.iteration();
        pr = known::<V>(pr);
        probe.kept(crate::intersect::Kept::Barba {
            p: crate::intersect::Span::new(pr.start, pr.len),
            tp: pr.tri(),
            q: crate::intersect::Span::new(qr.start, qr.len),
        });
        let decision = step::<K, V, PV, QV>(k, pv, pr, qv, qr, &mut cache);
        let (n, m) = (pv.len(), qv.len());
        let (tp, ep) = (pr.tri(), e_positions(qr));
        // A certified run computes its exit's positions only where it ends (the thirds
        // triangle's two divisions are not paid on every iteration).
        let tp = move || if M::CERTIFY { pr.tri() } else { tp };
        let ep = move || if M::CERTIFY { e_positions(qr) } else { ep };
        let apart = |line| Exit::Apart {
            pr,
            q: SmallQ {
                range: qr,
                chord: false,
            },
            line,
        };
        match decision {
            Step::InK(i) => {
                return M::done::<K, V, PV, QV>(k, pv, qv, true, || {
                    Exit::PInside(pr.idx(n, tp()[i as usize]))
                });
            }
            Step::InTriangle(x) => {
                return M::done::<K, V, PV, QV>(k, pv, qv, true, || {
                    Exit::QInside(qr.idx(m, ep()[x as usize / 2] + x as usize % 2))
                });
            }
            Step::Crossing(a, j) => {
                let (a, b) = pr.chord(a as usize);
                return M::done::<K, V, PV, QV>(k, pv, qv, true, || Exit::Chord {
                    a: pr.idx(n, tp()[a]),
                    b: pr.idx(n, tp()[b]),
                    e: qr.idx(m, ep()[j as usize]),
                });
            }
            Step::ApartLine(j) => {
                let e = ep()[j as usize];
                return M::done::<K, V, PV, QV>(k, pv, qv, false, || {
                    apart(Sep::QLine(qr.idx(m, e), qr.idx(m, e + 1)))
                });
            }
            Step::ApartEdge(2) if !pr.thirds => {
                return M::done::<K, V, PV, QV>(k, pv, qv, false, || apart(Sep::PChord));
            }
            Step::ApartEdge(a) => {
                return M::done::<K, V, PV, QV>(k, pv, qv, false, || {
                    apart(Sep::PEdge(pr.idx(n, tp()[a as usize])))
                });
            }
            Step::KeepP(chain) => {
                let Some((from, to)) = pr.chain_ends(chain) else {
                    unreachable!("only a chain behind a triangle edge is kept")
                };
                pr = pr.sub(pv, from, to);
                cache.keep_rows(chain);
            }
            Step::KeepQ(2) => {
                let qs = SmallQ {
                    range: qr,
                    chord: true,
                };
                return against_small::<K, P, M, V, PV, QV>(k, pv, pr, qv, qs, probe);
            }
            Step::KeepQ(pocket) => {
                let m1 = (qr.len - 2) / 2;
                qr = if pocket == 0 {
                    qr.sub(qv, 0, m1 + 1)
                } else {
                    qr.sub(qv, m1, qr.len - 1)
                };
                cache.keep_cols(pocket);
            }
            Step::Stuck => {
                let answer = fallback(k, pv, pr, qv, qr);
                return M::done::<K, V, PV, QV>(k, pv, qv, answer, || Exit::Stuck(answer));
            }
        }
    }
}

/// One iteration of the main loop (steps 1–5 of the module docs; in variant `V` step 5
/// may come before step 2).
pub(super) fn step<K: Kernel, V: Variant, PV: Vertices + ?Sized, QV: Vertices + ?Sized>(
    k: K,
    pv: &PV,
    pr: Range,
    qv: &QV,
    qr: Range,
    cache: &mut SideCache,
) -> Step {
    let pr = known::<V>(pr);
    let t = pr.tri().map(|pos| pr.at(pv, pos));
    let m1 = (qr.len - 2) / 2;
    let lines = [
        (qr.at(qv, 0), qr.at(qv, 1)),
        (qr.at(qv, m1), qr.at(qv, m1 + 1)),
        (qr.at(qv, qr.len - 2), qr.at(qv, qr.len - 1)),
    ];
    let chords = [
        (lines[0].1, lines[1].0),
        (lines[1].1, lines[2].0),
        (lines[2].1, lines[0].0),
    ];
    let mut side =
        |i: usize, j: usize| *cache.0[i][j].get_or_insert_with(|| k.orient(lines[j].0, lines[j].1, t[i]));

    // 1. A vertex of T_P inside T_Q: a witness in a pocket, or a point of K ⊆ Q.
    for (i, &ti) in t.iter().enumerate() {
        if (0..3).all(|j| side(i, j) != Cw) {
            return match chords.iter().position(|c| k.orient(c.0, c.1, ti) == Cw) {
                Some(pocket) => Step::KeepQ(pocket),
                None => Step::InK(i as u8),
            };
        }
    }
    let kv = [
        lines[0].0, lines[0].1, lines[1].0, lines[1].1, lines[2].0, lines[2].1,
    ];
    // 5 first, in the variant that tries the edges of T_P before those of T_Q.
    if V::P_EDGES_FIRST
        && let Some(decision) = apart_by_triangle_edge(k, pr, &t, &kv, &lines)
    {
        return decision;
    }
    // 2. A line of T_Q with T_P strictly outside.
    for (j, &line) in lines.iter().enumerate() {
        if (0..3).all(|i| side(i, j) == Cw) {
            return match prune_by_line(k, pv, pr, line) {
                Some(chain) => Step::KeepP(chain),
                None => Step::ApartLine(j as u8),
            };
        }
    }
    // 3. A vertex of K inside T_P.
    if let Some(x) = kv
        .iter()
        .position(|&x| (0..3).all(|i| k.orient(t[i], t[(i + 1) % 3], x) != Cw))
    {
        return Step::InTriangle(x as u8);
    }
    // 4. Transversal crossings of T_P's edges with T_Q's lines.
    let sides: [[Orientation; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| side(i, j)));
    for a in 0..3 {
        let b = (a + 1) % 3;
        for j in 0..3 {
            let (sa, sb) = (sides[a][j], sides[b][j]);
            if sa == Collinear || sb != sa.reverse() {
                continue;
            }
            let (s, u) = lines[j];
            if segments_intersect(k, t[a], t[b], s, u) {
                return Step::Crossing(a as u8, j as u8);
            }
            // The crossing X lies on the segment t[a]t[b]: when both ends are on the
            // same side of another line, so is X, without the degree-4 predicate.
            let inside = (0..3)
                .filter(|&l| l != j)
                .all(|l| match (sides[a][l], sides[b][l]) {
                    (Cw, Cw) => false,
                    (x, y) if x != Cw && y != Cw => true,
                    _ => line_meet_side(k, (t[a], t[b]), lines[j], lines[l]) != Cw,
                });
            if inside {
                let before_s = k.orient(t[a], t[b], s);
                let after = k.cross(t[a], t[b], s, u) == before_s.reverse();
                return Step::KeepQ(if after { j } else { (j + 2) % 3 });
            }
        }
    }
    // 5. T_P and T_Q are disjoint: find the edge of T_P whose line misses T_Q.
    if V::P_EDGES_FIRST {
        return Step::Stuck;
    }
    apart_by_triangle_edge(k, pr, &t, &kv, &lines).unwrap_or(Step::Stuck)
}

/// Step 5: an edge of T_P whose line has K strictly outside and misses T_Q, and what
/// it prunes (`None`: no edge of T_P separates T_P from T_Q).
#[inline]
pub(super) fn apart_by_triangle_edge<K: Kernel>(
    k: K,
    pr: Range,
    t: &[Point; 3],
    kv: &[Point; 6],
    lines: &[(Point, Point); 3],
) -> Option<Step> {
    (0..3).find_map(|a| {
        let b = (a + 1) % 3;
        (kv.iter().all(|&x| k.orient(t[a], t[b], x) == Cw) && line_misses_hull(k, (t[a], t[b]), lines)).then(
            || match keep_chain(pr, a) {
                Some(chain) => Step::KeepP(chain),
                None => Step::ApartEdge(a as u8),
            },
        )
    })
}

/// Chain `c` of P' if it has an interior vertex; otherwise (`None`) P' ∩ Q' = ∅.
#[inline]
pub(super) fn keep_chain(pr: Range, c: usize) -> Option<usize> {
    let (from, to) = pr.chain_ends(c)?;
    (to - from >= 2).then_some(c)
}

/// T_P lies strictly right of the line s→u and Q' on or left of it: the chain of P'
/// that holds P''s farthest point towards the line strictly inside, if any (`None`:
/// P' ∩ Q' = ∅).
///
/// The farthest point is where the edge directions pass the direction u→s (they
/// turn monotonically), so chain c holds it strictly inside iff u→s is turned
/// strictly beyond the chain's first edge and strictly before its last edge.
/// Otherwise the farthest point is a triangle vertex, strictly right of the line.
#[inline]
pub(super) fn prune_by_line<K: Kernel, PV: Vertices + ?Sized>(
    k: K,
    pv: &PV,
    pr: Range,
    (s, u): (Point, Point),
) -> Option<usize> {
    // Every cross product here is of two edges, short next to the polygons at large n.
    let k = ShortEdges(k);
    let at = |i: usize| pr.at(pv, i);
    let holds_peak = |from: usize, to: usize| {
        let (first, end) = ((at(from), at(from + 1)), (at(to - 1), at(to)));
        !same_direction(k, first, (u, s)) && turn_gt(k, first, end, (u, s))
    };
    let t = pr.tri();
    if t[1] - t[0] >= 2 && holds_peak(t[0], t[1]) {
        Some(0)
    } else if t[2] - t[1] >= 2 && holds_peak(t[1], t[2]) {
        Some(1)
    } else if pr.thirds && pr.len - t[2] >= 2 && holds_peak(t[2], pr.len) {
        Some(2)
    } else {
        None
    }
}

/// Whether the line through `l` misses T_Q = ∩ H(lines[j]): the line meets T_Q iff
/// it lies inside the half-planes it is parallel to and, when it crosses some line,
/// one of the crossing points lies in all three half-planes (an end of the interval).
pub(super) fn line_misses_hull<K: Kernel>(k: K, l: (Point, Point), lines: &[(Point, Point); 3]) -> bool {
    let mut crossing = [false; 3];
    for (j, &(s, u)) in lines.iter().enumerate() {
        if k.cross(l.0, l.1, s, u) == Collinear {
            if k.orient(s, u, l.0) == Cw {
                return true;
            }
        } else {
            crossing[j] = true;
        }
    }
    if !crossing.iter().any(|&c| c) {
        return false;
    }
    !(0..3).any(|j| {
        crossing[j]
            && (0..3).all(|m| m == j || !crossing[m] || line_meet_side(k, l, lines[j], lines[m]) != Cw)
    })
}

/// Prunes P' against a Q' of at most six vertices (or a segment) given explicitly.
pub(super) fn against_small<
    K: Kernel,
    P: Probe,
    M: Mode,
    V: Variant,
    PV: Vertices + ?Sized,
    QV: Vertices + ?Sized,
>(
    k: K,
    pv: &PV,
    mut pr: Range,
    qv: &QV,
    small: SmallQ,
    probe: &mut P,
) -> M::Out {
    let (idx, len) = small.indices(qv.len());
    let mut qs = [Point::default(); SMALL_Q];
    for (slot, &i) in qs.iter_mut().zip(&idx[..len]) {
        *slot = qv.get(i);
    }
    let qs = &qs[..len];
    let n = pv.len();
    loop {
        probe.iteration();
        pr = known::<V>(pr);
        probe.kept(crate::intersect::Kept::BarbaSmall {
            p: crate::intersect::Span::new(pr.start, pr.len),
            tp: pr.tri(),
            q: &idx[..len],
        });
        let tp = pr.tri();
        let t = tp.map(|pos| pr.at(pv, pos));
        let axis = if M::CERTIFY && small.chord {
            match SegmentTable::axis(k, &t, [qs[0], qs[1]]) {
                Ok(axis) => Some(axis),
                Err(table) => {
                    // From the positions and indices at hand (no division again).
                    return M::done::<K, V, PV, QV>(k, pv, qv, true, || {
                        let r = small.range;
                        Exit::Segment(SegmentExit {
                            t: tp.map(|pos| pr.idx(n, pos)),
                            closing_reversed: !pr.thirds,
                            c: idx[0],
                            d: idx[1],
                            q_mid: r.idx(qv.len(), (r.len - 1) / 2),
                            q_edge: r.len == qv.len(),
                            table,
                        })
                    });
                }
            }
        } else {
            separating_axis(k, &t, qs)
        };
        let Some(axis) = axis else {
            return M::done::<K, V, PV, QV>(k, pv, qv, true, || Exit::Small { pr, qs: small });
        };
        let keep = match axis {
            Axis::OfQ(i, j) => prune_by_line(k, pv, pr, (qs[i], qs[j])),
            Axis::OfTriangle(c) => keep_chain(pr, c),
        };
        match keep.and_then(|c| pr.chain_ends(c)) {
            Some((from, to)) => pr = pr.sub(pv, from, to),
            None => {
                return M::done::<K, V, PV, QV>(k, pv, qv, false, || {
                    let line = match axis {
                        Axis::OfQ(i, j) => Sep::QLine(idx[i], idx[j]),
                        Axis::OfTriangle(2) if !pr.thirds => Sep::PChord,
                        Axis::OfTriangle(c) => Sep::PEdge(pr.idx(n, tp[c])),
                    };
                    Exit::Apart { pr, q: small, line }
                });
            }
        }
    }
}

/// A strictly separating line between a triangle and a small convex set.
pub(super) enum Axis {
    /// The line through the small set's points `i` → `j` (the set on or left of it).
    OfQ(usize, usize),
    /// The line of triangle edge i → i+1 (the small set strictly right of it).
    OfTriangle(usize),
}

/// Separating-axis test between a proper counter-clockwise triangle `t` and a convex
/// polygon or segment `qs` (counter-clockwise, in convex position). Complete: the
/// edges of the Minkowski difference are parallel to edges of `t` or of `qs`
/// (both directions for a segment).
pub(super) fn separating_axis<K: Kernel>(k: K, t: &[Point; 3], qs: &[Point]) -> Option<Axis> {
    let n = qs.len();
    let q_edges = (0..n).map(|i| (i, (i + 1) % n));
    let reversed = (0..n).filter(move |_| n == 2).map(|i| ((i + 1) % n, i));
    for (i, j) in q_edges.chain(reversed) {
        if t.iter().all(|&x| k.orient(qs[i], qs[j], x) == Cw) {
            return Some(Axis::OfQ(i, j));
        }
    }
    (0..3)
        .find(|&i| qs.iter().all(|&x| k.orient(t[i], t[(i + 1) % 3], x) == Cw))
        .map(Axis::OfTriangle)
}

/// The orientations between a triangle T_P and a segment Q' = (q₀, q₁): `o[a]` of
/// T_P's vertex `a` against the line q₀ → q₁, `w[j][a]` of the segment's end `j`
/// against T_P's edge `a` → `a + 1`. Nine predicates decide whether they meet and, if
/// they do, which witness they have ([`segment_witness`]).
#[derive(Clone, Copy, Debug)]
pub(super) struct SegmentTable {
    pub(super) o: [Orientation; 3],
    pub(super) w: [[Orientation; 3]; 2],
}

impl SegmentTable {
    /// [`separating_axis`] for the segment `q`, in the same order and with the same
    /// predicates under an exact kernel (the line q₁ → q₀ has T_P strictly right iff
    /// every `o` is counter-clockwise), or, when none separates, the whole table: the
    /// orientations the separation tests skipped are computed then, each once.
    #[inline]
    pub(super) fn axis<K: Kernel>(k: K, t: &[Point; 3], q: [Point; 2]) -> Result<Axis, SegmentTable> {
        let o: [Orientation; 3] = std::array::from_fn(|a| k.orient(q[0], q[1], t[a]));
        if o.iter().all(|&x| x == Cw) {
            return Ok(Axis::OfQ(0, 1));
        }
        if o.iter().all(|&x| x == Ccw) {
            return Ok(Axis::OfQ(1, 0));
        }
        let mut w = [[Collinear; 3]; 2];
        for a in 0..3 {
            let b = (a + 1) % 3;
            w[0][a] = k.orient(t[a], t[b], q[0]);
            if w[0][a] == Cw {
                w[1][a] = k.orient(t[a], t[b], q[1]);
                if w[1][a] == Cw {
                    return Ok(Axis::OfTriangle(a));
                }
            }
        }
        for a in 0..3 {
            if w[0][a] != Cw {
                w[1][a] = k.orient(t[a], t[(a + 1) % 3], q[1]);
            }
        }
        Err(SegmentTable { o, w })
    }
}

/// Where the certified finish found T_P meeting the segment Q' = Q[c]–Q[d] (a chord of
/// Q): what the witness ([`segment_witness`]) reads, in array indices, so that it
/// computes none of them again.
#[derive(Clone, Copy, Debug)]
pub(super) struct SegmentExit {
    /// T_P's vertices.
    pub(super) t: [usize; 3],
    /// Whether T_P's edge 2 → 0 is P''s closing chord (an ordinary range, not the
    /// thirds triangle), reduced as 0 → 2 so that its chain lies in P'.
    pub(super) closing_reversed: bool,
    /// The segment's ends: Q''s first and last vertex.
    pub(super) c: usize,
    pub(super) d: usize,
    /// The middle vertex of Q''s chain from `c` to `d`.
    pub(super) q_mid: usize,
    /// Whether Q' was all of Q, so that the segment is Q's edge Q[d] → Q[c].
    pub(super) q_edge: bool,
    pub(super) table: SegmentTable,
}

impl SegmentExit {
    #[inline]
    pub(super) fn new(n: usize, m: usize, pr: Range, small: SmallQ, table: SegmentTable) -> SegmentExit {
        let r = small.range;
        SegmentExit {
            t: pr.triangle(n),
            closing_reversed: !pr.thirds,
            c: r.idx(m, 0),
            d: r.idx(m, r.len - 1),
            q_mid: r.idx(m, (r.len - 1) / 2),
            q_edge: r.len == m,
            table,
        }
    }
}

/// Only for kernels that contradict themselves: the O(n + m) reference on the
/// remaining pieces.
pub(super) fn fallback<K: Kernel, PV: Vertices + ?Sized, QV: Vertices + ?Sized>(
    k: K,
    pv: &PV,
    pr: Range,
    qv: &QV,
    qr: Range,
) -> bool {
    let p = ConvexPolygon::from_ccw_unchecked((0..pr.len).map(|i| pr.at(pv, i)).collect());
    let q = ConvexPolygon::from_ccw_unchecked((0..qr.len).map(|i| qr.at(qv, i)).collect());
    Linear.intersects_with(k, &p, &q)
}
