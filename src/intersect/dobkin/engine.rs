//! The engine of [`Dobkin`](super::Dobkin): the extreme-vertex searches, the chains and
//! the chain-pair searches of the module docs' steps 1–5.

use crate::intersect::{Probe, Which};
use crate::kernel::{Kernel, Orientation, Point};

/// How both chain-pair searches ended (each search's `verdict` says why).
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Outcome {
    /// Search `s` found its regions disjoint: the polygons are disjoint.
    Apart(usize),
    /// Both searches met.
    Meet,
}

/// The polygon that owns the left chain of each chain-pair search (the other owns the
/// right chain): search 0 is L_P against R_Q, search 1 is L_Q against R_P.
pub(super) const SEARCH_A: [Which; 2] = [Which::P, Which::Q];

/// Runs both chain-pair searches until one finds its regions disjoint (the polygons
/// are disjoint) or both meet.
/// Then hands the outcome and the searches to `then` (so that they stay on this frame).
#[inline]
pub(super) fn run<K: Kernel, P: Probe, T, const LEMMA_BY_LEMMA: bool>(
    k: K,
    pv: &[Point],
    qv: &[Point],
    probe: &mut P,
    then: impl FnOnce(Outcome, &[PairSearch<'_>; 2]) -> T,
) -> T {
    let [p_top, p_bottom, q_top, q_bottom] = extremes(k, pv, qv);
    let (pl, pr) = chains(pv, p_top, p_bottom);
    let (ql, qr) = chains(qv, q_top, q_bottom);
    // Both chain pairs advance in lockstep: their memory accesses are
    // independent, so the processor overlaps the cache misses on large arrays.
    let mut searches = [PairSearch::new(pv, pl, qv, qr), PairSearch::new(qv, ql, pv, pr)];
    let [a, b] = &mut searches;
    let (mut ra, mut rb) = (None, None);
    let outcome = loop {
        if ra.is_none() {
            ra = a.step::<K, P, LEMMA_BY_LEMMA>(k, probe);
            if ra == Some(false) {
                break Outcome::Apart(0);
            }
        }
        if rb.is_none() {
            rb = b.step::<K, P, LEMMA_BY_LEMMA>(k, probe);
            if rb == Some(false) {
                break Outcome::Apart(1);
            }
        }
        if ra.is_some() && rb.is_some() {
            break Outcome::Meet;
        }
    };
    then(outcome, &searches)
}

/// A chain: `len` consecutive vertices of a polygon starting at array index `start`.
#[derive(Clone, Copy, Debug)]
pub(super) struct Chain {
    pub(super) start: usize,
    pub(super) len: usize,
}

/// The vertex at position `pos` of a chain.
#[inline]
pub(super) fn at(v: &[Point], c: Chain, pos: usize) -> Point {
    let i = c.start + pos;
    v[if i >= v.len() { i - v.len() } else { i }]
}

/// Direction classes of an edge, counter-clockwise from east, decided by comparing
/// the endpoints' coordinates (no arithmetic).
pub(super) const EAST: u8 = 0;
pub(super) const UP: u8 = 1;
pub(super) const WEST: u8 = 2;
pub(super) const DOWN: u8 = 3;

#[inline]
pub(super) fn class(a: Point, b: Point) -> u8 {
    if b.y > a.y {
        UP
    } else if b.y < a.y {
        DOWN
    } else if b.x > a.x {
        EAST
    } else {
        WEST
    }
}

/// The left chain (top to bottom, strictly descending) and the right chain (bottom
/// to top, strictly ascending) of a counter-clockwise polygon, given the first
/// downward edge (`top`) and the first upward edge (`bottom`).
pub(super) fn chains(v: &[Point], top_left: usize, bottom_right: usize) -> (Chain, Chain) {
    let n = v.len();
    let edge_class = |i: usize| class(v[i], v[(i + 1) % n]);
    let before = |i: usize| (i + n - 1) % n;
    let top_right = if edge_class(before(top_left)) == WEST {
        before(top_left)
    } else {
        top_left
    };
    let bottom_left = if edge_class(before(bottom_right)) == EAST {
        before(bottom_right)
    } else {
        bottom_right
    };
    let span = |from: usize, to: usize| Chain {
        start: from,
        len: (to + n - from) % n + 1,
    };
    (span(top_left, bottom_left), span(bottom_right, top_right))
}

/// The starts of the first downward and the first upward edge of `p` and of `q`
/// (each the first edge of its class following an edge of another class): four
/// binary searches over the edges' turn from edge 0, run in lockstep so that their
/// independent memory accesses overlap. The turn is measured in classes rotated so
/// that edge 0's class is 0; edges of edge 0's class turned less than edge 0 (one
/// `cross`) come last (rank 4), so the rank grows monotonically along the array.
pub(super) fn extremes<K: Kernel>(k: K, p: &[Point], q: &[Point]) -> [usize; 4] {
    let polys = [p, p, q, q];
    let targets = [DOWN, UP, DOWN, UP];
    let c0 = polys.map(|v| class(v[0], v[1]));
    let goal: [u8; 4] = std::array::from_fn(|s| match (targets[s] + 4 - c0[s]) % 4 {
        0 => 4,
        r => r,
    });
    let rank = |s: usize, i: usize| {
        let v = polys[s];
        let (a, b) = (v[i], v[(i + 1) % v.len()]);
        let r = (class(a, b) + 4 - c0[s]) % 4;
        if r == 0 && i > 0 && k.cross(v[0], v[1], a, b) == Orientation::Cw {
            4
        } else {
            r
        }
    };
    let mut lo = [0; 4];
    let mut hi = polys.map(|v| v.len());
    loop {
        let mut active = false;
        for s in 0..4 {
            if lo[s] < hi[s] {
                active = true;
                let mid = lo[s] + (hi[s] - lo[s]) / 2;
                if rank(s, mid) >= goal[s] {
                    hi[s] = mid;
                } else {
                    lo[s] = mid + 1;
                }
            }
        }
        if !active {
            return std::array::from_fn(|s| lo[s] % polys[s].len());
        }
    }
}

/// Which chain a vertex bounding the y-interval belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Side {
    Left,
    Right,
}

/// A vertex bounding the common y-interval: its chain and its point (its position is
/// found again by [`PairSearch::position`] when a certificate needs it).
#[derive(Clone, Copy, Debug)]
pub(super) struct Bound {
    pub(super) side: Side,
    pub(super) p: Point,
}

/// A height test at the bounding vertex `w`: `other` is the position in the other chain
/// of the vertex at or just below (right chain) or above (left chain) that height, the
/// start of the other chain's edge there.
#[derive(Clone, Copy, Debug)]
pub(super) struct Tested {
    pub(super) w: Bound,
    pub(super) other: usize,
}

/// Why a chain-pair search found its two regions disjoint.
#[derive(Clone, Copy, Debug)]
pub(super) enum Apart {
    /// The y-ranges are disjoint: `lo` is the higher bottom, `hi` the lower top.
    Heights { lo: Bound, hi: Bound },
    /// g < 0 at its maximum, the height of this test (or of one of these two, where g
    /// is linear on the interval).
    At(Tested, Option<Tested>),
}

/// A decided chain-pair search.
#[derive(Clone, Copy, Debug)]
pub(super) enum Verdict {
    /// The regions meet: a test found x_L ≤ x_R ([`PairSearch::met`] gives it).
    Meet,
    Apart(Apart),
}

/// The search of step 4 of the module docs: whether the region right of left chain
/// `l` (of polygon `lv`) meets the region left of right chain `r` (of polygon `rv`),
/// one pruning iteration per [`PairSearch::step`].
pub(super) struct PairSearch<'a> {
    pub(super) lv: &'a [Point],
    pub(super) l: Chain,
    pub(super) rv: &'a [Point],
    pub(super) r: Chain,
    /// Left positions `i0..=i1` descend from top to bottom; right `j0..=j1` ascend.
    pub(super) i0: usize,
    pub(super) i1: usize,
    pub(super) j0: usize,
    pub(super) j1: usize,
    /// The vertices whose heights bound the common y-interval I.
    pub(super) lo: Bound,
    pub(super) hi: Bound,
    /// Which height test decided the search (read back by [`PairSearch::verdict`]).
    pub(super) decided: Decided,
}

/// Which test decided a chain-pair search: each test's answer and the position it
/// found in the other chain.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Decided {
    Not,
    /// The y-ranges are disjoint.
    Heights,
    /// The test at `lo`, or at `hi`.
    Lo(bool, usize),
    Hi(bool, usize),
    /// g linear on I: the test at `lo`, then (if it failed) the one at `hi`.
    Both((bool, usize), Option<(bool, usize)>),
}

impl<'a> PairSearch<'a> {
    pub(super) fn new(lv: &'a [Point], l: Chain, rv: &'a [Point], r: Chain) -> Self {
        let (i0, i1, j0, j1) = (0, l.len - 1, 0, r.len - 1);
        let (lt, lb) = (at(lv, l, i0), at(lv, l, i1));
        let (rb, rt) = (at(rv, r, j0), at(rv, r, j1));
        let bound = |side, p| Bound { side, p };
        let lo = if lb.y >= rb.y {
            bound(Side::Left, lb)
        } else {
            bound(Side::Right, rb)
        };
        let hi = if lt.y <= rt.y {
            bound(Side::Left, lt)
        } else {
            bound(Side::Right, rt)
        };
        PairSearch {
            lv,
            l,
            rv,
            r,
            i0,
            i1,
            j0,
            j1,
            lo,
            hi,
            decided: Decided::Not,
        }
    }

    #[inline]
    pub(super) fn lp(&self, i: usize) -> Point {
        at(self.lv, self.l, i)
    }

    #[inline]
    pub(super) fn rp(&self, j: usize) -> Point {
        at(self.rv, self.r, j)
    }

    /// Is `x_L ≤ x_R` at the height of the bounding vertex `w`? With the position in
    /// the other chain of the vertex at or next to that height.
    #[inline]
    pub(super) fn test<K: Kernel>(&self, k: K, w: Bound) -> (bool, usize) {
        match w.side {
            Side::Left => inside_right_chain(k, &|j| self.rp(j), self.j0, self.j1, w.p),
            Side::Right => inside_left_chain(k, &|i| self.lp(i), self.i0, self.i1, w.p),
        }
    }

    /// Decides the search by one height test, where the maximum of g is.
    #[inline]
    pub(super) fn at_height<K: Kernel>(&mut self, k: K, lo: bool) -> bool {
        let (inside, other) = self.test(k, if lo { self.lo } else { self.hi });
        self.decided = if lo {
            Decided::Lo(inside, other)
        } else {
            Decided::Hi(inside, other)
        };
        inside
    }

    /// Why the search was decided (its final state, which deciding leaves unchanged,
    /// and the deciding tests). For certificates only.
    #[inline]
    pub(super) fn verdict(&self) -> Option<Verdict> {
        let at = |w: Bound, (inside, other): (bool, usize)| {
            let t = Tested { w, other };
            if inside {
                Verdict::Meet
            } else {
                Verdict::Apart(Apart::At(t, None))
            }
        };
        Some(match self.decided {
            Decided::Not => return None,
            Decided::Heights => Verdict::Apart(Apart::Heights {
                lo: self.lo,
                hi: self.hi,
            }),
            Decided::Lo(inside, other) => at(self.lo, (inside, other)),
            Decided::Hi(inside, other) => at(self.hi, (inside, other)),
            Decided::Both(lo, None) => at(self.lo, lo),
            Decided::Both(lo, Some(hi)) => match (at(self.lo, lo), at(self.hi, hi)) {
                (Verdict::Apart(Apart::At(a, _)), Verdict::Apart(Apart::At(b, _))) => {
                    Verdict::Apart(Apart::At(a, Some(b)))
                }
                (_, hi) => hi,
            },
        })
    }

    /// The test that decided the search if it met (`verdict` is then `Verdict::Meet`),
    /// read off the deciding test alone: the witness asks only this.
    #[inline]
    pub(super) fn met(&self) -> Option<Tested> {
        let (w, other) = match self.decided {
            Decided::Lo(true, other) | Decided::Both((true, other), _) => (self.lo, other),
            Decided::Hi(true, other) | Decided::Both(_, Some((true, other))) => (self.hi, other),
            _ => return None,
        };
        Some(Tested { w, other })
    }

    /// Decides the search by the tests at both ends of I (g is linear there).
    #[inline]
    pub(super) fn at_both_ends<K: Kernel>(&mut self, k: K) -> bool {
        let lo = self.test(k, self.lo);
        let hi = if lo.0 { None } else { Some(self.test(k, self.hi)) };
        self.decided = Decided::Both(lo, hi);
        lo.0 || hi.is_some_and(|h| h.0)
    }

    /// One pruning iteration; `Some(answer)` once the search is decided (then
    /// `verdict` says why). `#[inline]` so that every codegen unit that runs the
    /// searches has its own copy, called without the cross-unit calling convention
    /// (the loop in [`run`] calls it once per iteration).
    #[inline]
    pub(super) fn step<K: Kernel, P: Probe, const LEMMA_BY_LEMMA: bool>(
        &mut self,
        k: K,
        probe: &mut P,
    ) -> Option<bool> {
        // Only the heights are read on the way: copying the bounds costs more.
        let (lo_y, hi_y) = (self.lo.p.y, self.hi.p.y);
        if lo_y > hi_y {
            self.decided = Decided::Heights;
            return Some(false);
        }
        if lo_y == hi_y {
            return Some(self.at_height(k, true));
        }
        let (le, re) = (self.i1 - self.i0, self.j1 - self.j0);
        // Both chains linear on I (or, with an inconsistent kernel, a chain that no
        // longer covers I): g is linear, test both ends.
        if (le <= 1 && re <= 1) || le == 0 || re == 0 {
            return Some(self.at_both_ends(k));
        }
        probe.iteration();
        probe.kept(crate::intersect::Kept::Dobkin {
            left: self.lv,
            l: crate::intersect::Span::new(self.l.start + self.i0, le + 1),
            right: self.rv,
            r: crate::intersect::Span::new(self.r.start + self.j0, re + 1),
            heights: [lo_y, hi_y],
        });
        let ke = self.i0 + le / 2; // e = (lp(ke), lp(ke + 1)), top to bottom
        let kf = self.j0 + re / 2; // f = (rp(kf), rp(kf + 1)), bottom to top
        let (e_top, e_bot) = (self.lp(ke), self.lp(ke + 1));
        let (f_bot, f_top) = (self.rp(kf), self.rp(kf + 1));
        let left = |p| Bound { side: Side::Left, p };
        let right = |p| Bound { side: Side::Right, p };
        // Two edges, short next to the polygons at large n: see `cross_of_short_edges`.
        let up = k.cross_of_short_edges(f_bot, f_top, e_bot, e_top) != Orientation::Cw;
        if LEMMA_BY_LEMMA {
            return self.lemma_by_lemma(k, up, [ke, kf], [e_top, e_bot, f_bot, f_top]);
        }
        if up {
            // s_R ≥ s_L: g is non-decreasing below min(top(e), top(f)).
            if e_top.y <= f_top.y {
                if e_top.y >= hi_y {
                    return Some(self.at_height(k, false));
                }
                self.i1 = ke;
                if e_top.y > lo_y {
                    self.lo = left(e_top);
                }
            } else {
                if f_top.y >= hi_y {
                    return Some(self.at_height(k, false));
                }
                self.j0 = kf + 1;
                if f_top.y > lo_y {
                    self.lo = right(f_top);
                }
            }
        } else if e_bot.y >= f_bot.y {
            // s_R < s_L: g is decreasing above max(bottom(e), bottom(f)).
            if e_bot.y <= lo_y {
                return Some(self.at_height(k, true));
            }
            self.i0 = ke + 1;
            if e_bot.y < hi_y {
                self.hi = left(e_bot);
            }
        } else {
            if f_bot.y <= lo_y {
                return Some(self.at_height(k, true));
            }
            self.j1 = kf;
            if f_bot.y < hi_y {
                self.hi = right(f_bot);
            }
        }
        None
    }

    /// One iteration of [`DobkinVariant<true>`]: every pruning rule tested by its own
    /// `if` (the thesis's Code 3.1 form), given the slope comparison `up` (s_R ≥ s_L),
    /// the medians' positions `[ke, kf]` and their points `[e_top, e_bot, f_bot, f_top]`.
    #[inline]
    pub(super) fn lemma_by_lemma<K: Kernel>(
        &mut self,
        k: K,
        up: bool,
        [ke, kf]: [usize; 2],
        [e_top, e_bot, f_bot, f_top]: [Point; 4],
    ) -> Option<bool> {
        let (lo_y, hi_y) = (self.lo.p.y, self.hi.p.y);
        let left = |p| Bound { side: Side::Left, p };
        let right = |p| Bound { side: Side::Right, p };
        if up {
            // g is non-decreasing below min(top(e), top(f)): if that is at or above the
            // top of I, the maximum is there.
            if e_top.y.min(f_top.y) >= hi_y {
                return Some(self.at_height(k, false));
            }
            // e ends no higher than f: L below e is pruned and I starts at top(e).
            if e_top.y <= f_top.y {
                self.i1 = ke;
                if e_top.y > lo_y {
                    self.lo = left(e_top);
                }
            }
            // Its symmetric version: f ends lower, R below f is pruned.
            if f_top.y < e_top.y {
                self.j0 = kf + 1;
                if f_top.y > lo_y {
                    self.lo = right(f_top);
                }
            }
            // f starts at or below the start of I: R below f is pruned (f covers it).
            if f_bot.y <= self.lo.p.y {
                self.j0 = self.j0.max(kf);
            }
            // Its symmetric version: L below e is pruned.
            if e_bot.y <= self.lo.p.y {
                self.i1 = self.i1.min(ke + 1);
            }
        } else {
            // g is decreasing above max(bottom(e), bottom(f)): if that is at or below
            // the bottom of I, the maximum is there.
            if e_bot.y.max(f_bot.y) <= lo_y {
                return Some(self.at_height(k, true));
            }
            // e starts no lower than f: L above e is pruned and I ends at bottom(e).
            if e_bot.y >= f_bot.y {
                self.i0 = ke + 1;
                if e_bot.y < hi_y {
                    self.hi = left(e_bot);
                }
            }
            // Its symmetric version: f starts higher, R above f is pruned.
            if f_bot.y > e_bot.y {
                self.j1 = kf;
                if f_bot.y < hi_y {
                    self.hi = right(f_bot);
                }
            }
            // f ends at or above the end of I: R above f is pruned (f covers it).
            if f_top.y >= self.hi.p.y {
                self.j1 = self.j1.min(kf + 1);
            }
            // Its symmetric version: L above e is pruned.
            if e_top.y >= self.hi.p.y {
                self.i0 = self.i0.max(ke);
            }
        }
        None
    }

    /// The position of vertex `p` in its chain (chains are strictly monotone in y), for
    /// certificates only. A bound of I is an end of its chain's remaining range (a cut
    /// at a median edge moves the range's end and the bound to the same vertex), so the
    /// two ends are compared first; a binary search on heights otherwise.
    pub(super) fn position(&self, b: Bound) -> usize {
        match b.side {
            Side::Left if self.lp(self.i1) == b.p => self.i1,
            Side::Left if self.lp(self.i0) == b.p => self.i0,
            Side::Left => first(self.l.len, |i| self.lp(i).y > b.p.y),
            Side::Right if self.rp(self.j0) == b.p => self.j0,
            Side::Right if self.rp(self.j1) == b.p => self.j1,
            Side::Right => first(self.r.len, |j| self.rp(j).y < b.p.y),
        }
    }

    /// The last position of the left chain at or above height `y` (0 if none), by a
    /// binary search on the chain's contiguous pieces: for certificates.
    #[inline]
    pub(super) fn left_position(&self, y: f64) -> usize {
        chain_partition(self.lv, self.l, |p| p.y >= y).max(1) - 1
    }

    /// The last position of the right chain at or below height `y` (0 if none).
    #[inline]
    pub(super) fn right_position(&self, y: f64) -> usize {
        chain_partition(self.rv, self.r, |p| p.y <= y).max(1) - 1
    }

    /// [`inside_left_chain`] on the whole left chain, for certificates.
    pub(super) fn inside_left_whole<K: Kernel>(&self, k: K, w: Point) -> (bool, usize) {
        let lo = self.left_position(w.y);
        (inside_left_at(k, &|i| self.lp(i), lo, self.l.len - 1, w), lo)
    }

    /// [`inside_right_chain`] on the whole right chain, for certificates.
    pub(super) fn inside_right_whole<K: Kernel>(&self, k: K, w: Point) -> (bool, usize) {
        let lo = self.right_position(w.y);
        (inside_right_at(k, &|j| self.rp(j), lo, self.r.len - 1, w), lo)
    }

    /// The array index of a chain position.
    #[inline]
    pub(super) fn index(&self, side: Side, pos: usize) -> usize {
        let (v, c) = match side {
            Side::Left => (self.lv, self.l),
            Side::Right => (self.rv, self.r),
        };
        (c.start + pos) % v.len()
    }
}

/// The first position in `0..len` (the last if none) where `before` turns false;
/// `before` must be true on a prefix and false after it.
pub(super) fn first(len: usize, before: impl Fn(usize) -> bool) -> usize {
    let (mut lo, mut hi) = (0, len - 1);
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if before(mid) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    lo
}

/// Whether `w` lies on or left of the ascending right chain (positions `j0..=j1`) at
/// the height of `w`, and the position of the chain's vertex at or just below it.
pub(super) fn inside_right_chain<K: Kernel>(
    k: K,
    rp: &impl Fn(usize) -> Point,
    j0: usize,
    j1: usize,
    w: Point,
) -> (bool, usize) {
    // Last position with y ≤ w.y (clamped to the range).
    let (mut lo, mut hi) = (j0, j1);
    while lo < hi {
        let mid = lo + (hi - lo).div_ceil(2);
        if rp(mid).y <= w.y {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    (inside_right_at(k, rp, lo, j1, w), lo)
}

/// Whether `w` lies on or left of the ascending right chain at its height, given the
/// position `lo` of the chain's vertex at or just below it (`last`: the last position).
#[inline]
pub(super) fn inside_right_at<K: Kernel>(
    k: K,
    rp: &impl Fn(usize) -> Point,
    lo: usize,
    last: usize,
    w: Point,
) -> bool {
    let a = rp(lo);
    if a.y == w.y || lo == last {
        return w.x <= a.x;
    }
    k.orient(a, rp(lo + 1), w) != Orientation::Cw
}

/// Whether `w` lies on or right of the descending left chain (positions `i0..=i1`)
/// at the height of `w`, and the position of the chain's vertex at or just above it.
pub(super) fn inside_left_chain<K: Kernel>(
    k: K,
    lp: &impl Fn(usize) -> Point,
    i0: usize,
    i1: usize,
    w: Point,
) -> (bool, usize) {
    // Last position with y ≥ w.y (clamped to the range).
    let (mut lo, mut hi) = (i0, i1);
    while lo < hi {
        let mid = lo + (hi - lo).div_ceil(2);
        if lp(mid).y >= w.y {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    (inside_left_at(k, lp, lo, i1, w), lo)
}

/// Whether `w` lies on or right of the descending left chain at its height, given the
/// position `lo` of the chain's vertex at or just above it (`last`: the last position).
#[inline]
pub(super) fn inside_left_at<K: Kernel>(
    k: K,
    lp: &impl Fn(usize) -> Point,
    lo: usize,
    last: usize,
    w: Point,
) -> bool {
    let a = lp(lo);
    if a.y == w.y || lo == last {
        return a.x <= w.x;
    }
    k.orient(a, lp(lo + 1), w) != Orientation::Cw
}

/// The number of leading positions of chain `c` of `v` whose vertices satisfy `before`
/// (true on a prefix of the chain): `partition_point` on the chain's one or two
/// contiguous pieces of the array.
pub(super) fn chain_partition(v: &[Point], c: Chain, before: impl Fn(&Point) -> bool) -> usize {
    let end = c.start + c.len;
    if end <= v.len() {
        return v[c.start..end].partition_point(before);
    }
    // Wrapped: the head's last vertex says which piece holds the boundary, so only
    // that piece is searched.
    let head = &v[c.start..];
    if before(&v[v.len() - 1]) {
        head.len() + v[..end - v.len()].partition_point(before)
    } else {
        head.partition_point(before)
    }
}
