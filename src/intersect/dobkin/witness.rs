//! The certificates of [`Dobkin`](super::Dobkin) (module docs, "Certificate"): the
//! witness of two searches that met and the separating edge of one that failed.

use super::engine::{Apart, Outcome, PairSearch, SEARCH_A, Side, Tested, Verdict, run};
use crate::intersect::certificate::{Boundary, from_faces, resolve_chords, separates};
use crate::intersect::{Certificate, Derivation, Which};
use crate::kernel::{Kernel, Orientation, Point};

/// The witness of two searches that both met: the vertex each tested, if it lies in
/// the other polygon ([`vertex_inside`]), else the edge beside it ([`beside`]); only
/// the answer if none holds.
pub(super) fn meeting<K: Kernel>(k: K, searches: &[PairSearch<'_>; 2]) -> Derivation {
    let mut missed = [None; 2];
    for (s, slot) in missed.iter_mut().enumerate() {
        if let Some(t) = searches[s].met() {
            match vertex_inside(k, searches, s, t) {
                Ok(c) => return Derivation::Certified(c),
                Err(g) => *slot = g.map(|g| (t, g)),
            }
        }
    }
    match (0..2).find_map(|s| missed[s].and_then(|(t, g)| beside(k, searches, s, t, g))) {
        Some(c) => Derivation::Certified(c),
        None => Derivation::Answer(true),
    }
}

/// The height test where search `s` met tested a vertex w inside one of the other
/// polygon's chains; if w also lies inside that polygon's opposite chain at its height
/// (found by a binary search on heights, then one `orient`), w is a vertex inside.
/// Otherwise `Err` with the position in that opposite chain of its vertex at or next to
/// w's height (`None` if w's height is outside the chain).
pub(super) fn vertex_inside<K: Kernel>(
    k: K,
    searches: &[PairSearch<'_>; 2],
    s: usize,
    t: Tested,
) -> Result<Certificate, Option<usize>> {
    let other = &searches[1 - s];
    let w = t.w.p;
    let ((inside, pos), of) = match t.w.side {
        // w is a vertex of this search's left-chain polygon A, inside R_B at its height:
        // it is in B iff it is also inside L_B, the other search's left chain.
        Side::Left => {
            let len = other.l.len;
            if !(other.lp(len - 1).y <= w.y && w.y <= other.lp(0).y) {
                return Err(None);
            }
            (other.inside_left_whole(k, w), SEARCH_A[s])
        }
        // w is a vertex of B, inside L_A: it is in A iff also inside R_A.
        Side::Right => {
            let len = other.r.len;
            if !(other.rp(0).y <= w.y && w.y <= other.rp(len - 1).y) {
                return Err(None);
            }
            (other.inside_right_whole(k, w), SEARCH_A[s].other())
        }
    };
    if inside {
        Ok(Certificate::VertexInside { of, point: w })
    } else {
        Err(Some(pos))
    }
}

/// Where [`vertex_inside`] failed: w, a vertex of polygon X on one of its chains, lies
/// inside Y's opposite chain at its height (the search's test) but outside Y's chain on
/// w's side, whose edge g at that height (at position `g` of that chain) passes beyond
/// w at the point Z. If Z is in X, it lies on the horizontal segment from w to X's
/// other chain, inside the triangle of w and X's edge r at that height (one binary
/// search on heights): then an end of g lies in the triangle (a vertex inside), or r
/// meets g (crossing edges), or g crosses a chord from w to an end of r, resolved
/// with [`resolve_chords`]. `None` when Z is not in X (the polygons meet at other
/// heights). Out of line: one query in five gets here.
#[inline(never)]
pub(super) fn beside<K: Kernel>(
    k: K,
    searches: &[PairSearch<'_>; 2],
    s: usize,
    t: Tested,
    g: usize,
) -> Option<Certificate> {
    let (this, other) = (&searches[s], &searches[1 - s]);
    let w = t.w.p;
    // Both chains are the other search's: X's chain opposite w and Y's on w's side.
    let (x_side, y_side, x_poly, y_poly, x_which) = match t.w.side {
        Side::Left => (Side::Right, Side::Left, other.rv, other.lv, SEARCH_A[s]),
        Side::Right => (Side::Left, Side::Right, other.lv, other.rv, SEARCH_A[s].other()),
    };
    let (x_len, y_len) = match x_side {
        Side::Right => (other.r.len, other.l.len),
        Side::Left => (other.l.len, other.r.len),
    };
    if x_len < 2 || y_len < 2 {
        return None;
    }
    let r = match x_side {
        Side::Right => other.right_position(w.y),
        Side::Left => other.left_position(w.y),
    }
    .min(x_len - 2);
    let g = g.min(y_len - 2);
    let xi = [other.index(x_side, r), other.index(x_side, r + 1)];
    let yi = [other.index(y_side, g), other.index(y_side, g + 1)];
    let iw = this.index(t.w.side, this.position(t.w));
    if x_poly[iw] != w {
        return None;
    }
    let inside = || {
        let tri = [w, x_poly[xi[0]], x_poly[xi[1]]];
        let o = k.orient(tri[0], tri[1], tri[2]);
        if o == Orientation::Collinear {
            return None;
        }
        yi.iter()
            .map(|&i| y_poly[i])
            .find(|&y| (0..3).all(|a| k.orient(tri[a], tri[(a + 1) % 3], y) != o.reverse()))
            .map(|point| Certificate::VertexInside { of: Which::Q, point })
    };
    let found = inside()
        .or_else(|| resolve_chords(k, x_poly, (xi[0], xi[1]), y_poly, (yi[0], yi[1])))
        .or_else(|| {
            xi.iter()
                .filter(|&&i| i != iw)
                .find_map(|&i| resolve_chords(k, x_poly, (iw, i), y_poly, (yi[0], yi[1])))
        })?;
    Some(found.relative_to(x_which))
}

/// A separating edge of two polygons found disjoint by Dobkin's test, or `None` when
/// the test finds them intersecting: [`Barba`](crate::intersect::Barba)'s certified call falls
/// back on this when its last separating line does not lift to the whole polygons.
pub(crate) fn separating_certificate<K: Kernel>(k: K, pv: &[Point], qv: &[Point]) -> Option<Certificate> {
    run::<_, _, _, false>(k, pv, qv, &mut (), |outcome, searches| match outcome {
        Outcome::Apart(s) => match separation(k, searches, s) {
            Derivation::Certified(c) => Some(c),
            Derivation::Answer(_) => None,
        },
        Outcome::Meet => None,
    })
}

/// The separating edge of search `s`, which found its regions disjoint; only the
/// answer if none is found.
pub(super) fn separation<K: Kernel>(k: K, searches: &[PairSearch<'_>; 2], s: usize) -> Derivation {
    let found = match searches[s].verdict() {
        Some(Verdict::Apart(why)) => searches[s].separation(k, why),
        _ => None,
    };
    match found {
        Some(c) => Derivation::Certified(c.relative_to(SEARCH_A[s])),
        None => Derivation::Answer(false),
    }
}

impl PairSearch<'_> {
    /// disjoint, named with the left chain's polygon as P (module docs, "Certificate").
    pub(super) fn separation<K: Kernel>(&self, k: K, why: Apart) -> Option<Certificate> {
        let (a, b) = (self.lv, self.rv);
        match why {
            // The y-ranges are disjoint: the polygon whose bottom is `lo` lies above.
            Apart::Heights { lo, hi } => {
                debug_assert!(lo.p.y > hi.p.y && lo.side != hi.side);
                if lo.side == Side::Left {
                    // A above B: A's bottom-left ends its left chain, B's top-right its
                    // right chain.
                    let x = self.index(Side::Left, self.l.len - 1);
                    let y = self.index(Side::Right, self.r.len - 1);
                    apart_in_height(k, a, x, b, y)
                } else {
                    // B above A: B's bottom-left is its right chain's start or the vertex
                    // before it (a horizontal bottom), A's top-right the left chain's
                    // start or the vertex before it.
                    let x = level_prev(b, self.index(Side::Right, 0));
                    let y = level_prev(a, self.index(Side::Left, 0));
                    apart_in_height(k, b, x, a, y).map(Certificate::swapped)
                }
            }
            Apart::At(t, other) => self
                .separation_at(k, t)
                .or_else(|| other.and_then(|t| self.separation_at(k, t))),
        }
    }

    /// Whether the failed height test at `t` was decided by `orient` of the tested vertex
    /// against the other chain's edge at `t.other` (then that `orient` was `Cw`), rather
    /// than by comparing x coordinates (a vertex at the same height, or the range's
    /// last position): see [`inside_right_at`] and [`inside_left_at`].
    #[inline]
    pub(super) fn failed_by_orient(&self, t: Tested) -> bool {
        match t.w.side {
            Side::Left => t.other != self.j1 && self.rp(t.other).y != t.w.p.y,
            Side::Right => t.other != self.i1 && self.lp(t.other).y != t.w.p.y,
        }
    }

    /// Candidates at the height of a failed test where g is maximal: the tested vertex
    /// and the other chain's edge there (then their neighbours).
    pub(super) fn separation_at<K: Kernel>(&self, k: K, t: Tested) -> Option<Certificate> {
        let (a, b) = (self.lv, self.rv);
        let w = self.index(t.w.side, self.position(t.w));
        let (other_side, other_len) = match t.w.side {
            Side::Left => (Side::Right, self.r.len),
            Side::Right => (Side::Left, self.l.len),
        };
        let e0 = self.index(other_side, t.other);
        let mut edge = [e0, e0];
        let mut len = 1;
        if t.other + 1 < other_len {
            edge[1] = self.index(other_side, t.other + 1);
            len = 2;
        }
        let (wv, ev) = if t.w.side == Side::Left { (a, b) } else { (b, a) };
        // The certificate names the left chain's polygon as P.
        let (e_of, w_of) = if t.w.side == Side::Left {
            (Which::Q, Which::P)
        } else {
            (Which::P, Which::Q)
        };
        let edge_of = |of, u: usize, v: usize, poly: &[Point]| Certificate::Separated {
            of,
            from: poly[u],
            to: poly[v],
        };
        if len == 2 {
            // Where g is maximal inside I the other chain's edge there is the separating
            // edge (the slopes bracket it): try it first; then the faces {w} and e as
            // `from_faces` would, without e again: the edges next to e against w, w's
            // edges against e's ends.
            // The failed test found w strictly outside e by this `orient` unless it
            // compared x coordinates instead: only the local test is left then.
            let (e0, e1) = (edge[0], edge[1]);
            if (self.failed_by_orient(t) || k.orient(ev[e0], ev[e1], wv[w]) == Orientation::Cw)
                && deepest_against(k, ev[e0], ev[e1], wv, w)
            {
                return Some(edge_of(e_of, e0, e1, ev));
            }
            for (u, v) in [(ev.prev(e0), e0), (e1, ev.next(e1))] {
                if separates(k, ev[u], ev[v], wv, w) {
                    return Some(edge_of(e_of, u, v, ev));
                }
            }
            for (u, v) in [(wv.prev(w), w), (w, wv.next(w))] {
                if separates(k, wv[u], wv[v], ev, e0) || separates(k, wv[u], wv[v], ev, e1) {
                    return Some(edge_of(w_of, u, v, wv));
                }
            }
        }
        let wide_w = [w, wv.prev(w), wv.next(w)];
        let wide_e = [ev.prev(edge[0]), edge[0], edge[len - 1], ev.next(edge[len - 1])];
        let found = |fw: &[usize], fe: &[usize]| {
            if t.w.side == Side::Left {
                from_faces(k, a, fw, b, fe)
            } else {
                from_faces(k, b, fw, a, fe).map(Certificate::swapped)
            }
        };
        if len == 1
            && let Some(c) = found(&[w], &edge[..1])
        {
            return Some(c);
        }
        found(&wide_w, &wide_e)
    }
}

/// Whether vertex `w` of `b` is locally, hence (convexity) globally, the deepest of `b`
/// against the line `u` → `v`: [`separates`] without its `orient`.
#[inline]
pub(super) fn deepest_against<K: Kernel>(k: K, u: Point, v: Point, b: &[Point], w: usize) -> bool {
    let x = b[w];
    k.cross(u, v, x, b[b.next(w)]) != Orientation::Ccw && k.cross(u, v, x, b[b.prev(w)]) != Orientation::Ccw
}

/// `v`'s vertex before `i` if the edge from it to `i` is horizontal, else `i`.
#[inline]
pub(super) fn level_prev(v: &[Point], i: usize) -> usize {
    let j = v.prev(i);
    if v[j].y == v[i].y { j } else { i }
}

/// The separating edge of polygons `xv` and `yv` when all of `xv` lies strictly above
/// all of `yv`, from `xv`'s bottom-left vertex `x` and `yv`'s top-right vertex `y`
/// (named with `xv` as P). `x − y` is the lowest (then leftmost) vertex of the
/// Minkowski difference X − Y, and 0 lies strictly below it, so one of the two edges
/// of X − Y at `x − y` has 0 strictly on its outer side (module docs of
/// [`certificate`](crate::intersect::certificate)): the edge leaving it is the one of X at `x` or
/// of Y at `y` that turns least from east, the edge arriving the one that turns most
/// from west. Each is a cross product to choose the edge and an `orient` to test it;
/// `None` only if both tests fail (never under the exact kernel).
pub(super) fn apart_in_height<K: Kernel>(
    k: K,
    xv: &[Point],
    x: usize,
    yv: &[Point],
    y: usize,
) -> Option<Certificate> {
    use Orientation::{Ccw, Cw};
    let (x0, y0) = (xv[x], yv[y]);
    let x_edge = |from: Point, to: Point| Certificate::Separated {
        of: Which::P,
        from,
        to,
    };
    let y_edge = |from: Point, to: Point| Certificate::Separated {
        of: Which::Q,
        from,
        to,
    };
    // Leaving x − y: X's edge x → next(x) or −Y's, parallel to y → next(y) reversed.
    let (xn, yn) = (xv[xv.next(x)], yv[yv.next(y)]);
    if k.cross(x0, xn, yn, y0) == Cw {
        if k.orient(y0, yn, x0) == Cw {
            return Some(y_edge(y0, yn));
        }
    } else if k.orient(x0, xn, y0) == Cw {
        return Some(x_edge(x0, xn));
    }
    // Arriving at x − y: X's edge prev(x) → x or −Y's, parallel to prev(y) → y reversed.
    let (xp, yp) = (xv[xv.prev(x)], yv[yv.prev(y)]);
    if k.cross(xp, x0, y0, yp) == Ccw {
        (k.orient(yp, y0, x0) == Cw).then(|| y_edge(yp, y0))
    } else {
        (k.orient(xp, x0, y0) == Cw).then(|| x_edge(xp, x0))
    }
}
