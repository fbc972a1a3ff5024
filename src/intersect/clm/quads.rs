//! Quadrilaterals of sample vertices (inside their polygon) and the drawn witnesses
//! tested in them.

use super::Draws;
use super::sampling::{PREFIX, below};
use crate::intersect::{Certificate, Which};
use crate::kernel::{Kernel, Orientation, Point};
use crate::polygon::LinkedPolygon;
use rand::Rng;

/// How many rounds of draws (one vertex of each polygon per round) [`drawn_witness`]
/// tries before a chord is walked.
pub(super) const DRAW_ROUNDS: u32 = 16;

impl Draws {
    /// [`drawn_witness`] against the quadrilaterals of the two samples (`samples`:
    /// R_P's points, R_Q's) on P's and Q's chord (`chords`, crossing). Counts the
    /// outcome.
    pub(super) fn witness<K: Kernel, R: Rng + ?Sized>(
        &mut self,
        k: K,
        (p, q): (&LinkedPolygon, &LinkedPolygon),
        quads: (impl FnOnce() -> Quad, impl FnOnce() -> Quad),
        rng: &mut R,
    ) -> Option<Certificate> {
        let rounds = self.rounds.unwrap_or(DRAW_ROUNDS);
        let found = drawn_witness(k, (p, q), quads, rounds, rng);
        if found.is_some() {
            self.found += 1;
        } else {
            self.walked += 1;
        }
        found
    }
}

/// A quadrilateral of sample vertices of one polygon (so inside it): a chord a–b and
/// the sample vertices farthest from its line on its left and on its right, chosen by
/// distances computed in `f64` (a guide: [`Quad::contains`] checks exactly).
#[derive(Clone, Copy, Debug)]
pub(super) struct Quad {
    chord: (Point, Point),
    left: Option<Point>,
    right: Option<Point>,
}

impl Quad {
    /// The quadrilateral on the chord between `sample`'s lowest and highest x among
    /// about 16 of its points (every ⌈len/16⌉-th); empty for an empty sample.
    pub(super) fn spread(sample: &[Point]) -> Quad {
        let Some(first) = sample.first() else {
            return Quad {
                chord: (Point::new(0.0, 0.0), Point::new(0.0, 0.0)),
                left: None,
                right: None,
            };
        };
        // Indices and coordinates, not points, are carried through the loop.
        let (mut lo, mut hi, mut lo_x, mut hi_x) = (0, 0, first.x, first.x);
        let (stride, mut i) = (Quad::stride(sample), 0);
        while let Some(v) = sample.get(i) {
            if v.x < lo_x {
                (lo, lo_x) = (i, v.x);
            } else if v.x > hi_x {
                (hi, hi_x) = (i, v.x);
            }
            i += stride;
        }
        Quad::new((sample[lo], sample[hi]), sample)
    }

    /// The corners counter-clockwise: the chord's ends and the vertices right and left
    /// of it (a chord end repeats for a missing one).
    pub(super) fn corners(&self) -> [Point; 4] {
        let (a, b) = self.chord;
        [a, self.right.unwrap_or(a), b, self.left.unwrap_or(b)]
    }

    /// The step through a sample that visits about 16 of its points.
    #[inline]
    fn stride(sample: &[Point]) -> usize {
        (sample.len() / 16).max(1)
    }

    /// The quadrilateral on `chord` with the farthest of about 16 of `sample`'s
    /// points (every ⌈len/16⌉-th) on each side.
    pub(super) fn new((a, b): (Point, Point), sample: &[Point]) -> Quad {
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        let (mut left, mut right) = ((0.0, usize::MAX), (0.0, usize::MAX));
        let (stride, mut i) = (Quad::stride(sample), 0);
        while let Some(x) = sample.get(i) {
            let h = dx * (x.y - a.y) - dy * (x.x - a.x);
            if h > left.0 {
                left = (h, i);
            } else if h < right.0 {
                right = (h, i);
            }
            i += stride;
        }
        Quad {
            chord: (a, b),
            left: sample.get(left.1).copied(),
            right: sample.get(right.1).copied(),
        }
    }

    /// Whether `y` lies in the triangle of the chord and its vertex on y's side,
    /// boundary included (three orientations; a fourth checks that vertex's side when
    /// the answer is yes). A point on the chord's line is not looked at.
    /// Most points tested are outside: the same three signs are computed in `f64`
    /// first (a guide), and only a point they put inside is tested exactly. A point
    /// that rounding puts outside is missed, which only costs the caller another draw.
    #[inline]
    pub(super) fn contains<K: Kernel>(&self, k: K, y: Point) -> bool {
        let (a, b) = self.chord;
        let turn = |u: Point, v: Point| (v.x - u.x) * (y.y - u.y) - (v.y - u.y) * (y.x - u.x);
        let h = turn(a, b);
        let guide = if h > 0.0 {
            self.left.is_some_and(|w| turn(b, w) >= 0.0 && turn(w, a) >= 0.0)
        } else if h < 0.0 {
            self.right.is_some_and(|w| turn(a, w) >= 0.0 && turn(w, b) >= 0.0)
        } else {
            false
        };
        guide && self.contains_exactly(k, y)
    }

    /// [`contains`](Self::contains)'s test, exact.
    #[inline(never)]
    fn contains_exactly<K: Kernel>(&self, k: K, y: Point) -> bool {
        let (a, b) = self.chord;
        match k.orient(a, b, y) {
            Orientation::Ccw => self.left.is_some_and(|w| {
                k.orient(b, w, y) != Orientation::Cw
                    && k.orient(w, a, y) != Orientation::Cw
                    && k.orient(a, b, w) == Orientation::Ccw
            }),
            Orientation::Cw => self.right.is_some_and(|w| {
                k.orient(a, w, y) != Orientation::Cw
                    && k.orient(w, b, y) != Orientation::Cw
                    && k.orient(a, b, w) == Orientation::Cw
            }),
            Orientation::Collinear => false,
        }
    }
}

/// A sample vertex of one polygon inside the other polygon, from the LP's last step:
/// `z` (of polygon `z.0`) beyond `chord` (two vertices of the other polygon `of`'s
/// sample) is tested in the quadrilateral of that sample on the chord, then the rest
/// of z's sample (already read: no draw, no arena read) in the same quadrilateral,
/// then the chord's sample in the quadrilateral of z's sample ([`Quad::spread`]),
/// unless `quads` (P's, Q's) holds that one already: then the prefix test
/// ([`prefix_inside`]) has done that test. Each sample is tested on its first
/// [`PREFIX`] points. Else `None`, with the two quadrilaterals (P's, Q's) in `quads`,
/// for the draws.
pub(super) fn sample_quads<K: Kernel>(
    k: K,
    (z_of, z): (Which, Point),
    (of, chord): (Which, (Point, Point)),
    (rp, rq): (&[Point], &[Point]),
    quads: &mut (Option<Quad>, Option<Quad>),
) -> Option<Certificate> {
    let (chord_sample, own) = if of == Which::P { (rp, rq) } else { (rq, rp) };
    let quad = Quad::new(chord, chord_sample);
    if quad.contains(k, z) {
        return Some(Certificate::VertexInside { of: z_of, point: z });
    }
    if let Some(&y) = own.iter().take(PREFIX).find(|&&y| y != z && quad.contains(k, y)) {
        return Some(Certificate::VertexInside { of: z_of, point: y });
    }
    let tested = if of == Which::P { quads.1 } else { quads.0 };
    let own_quad = tested.unwrap_or_else(|| Quad::spread(own));
    if tested.is_none()
        && let Some(&y) = chord_sample
            .iter()
            .take(PREFIX)
            .find(|&&y| own_quad.contains(k, y))
    {
        return Some(Certificate::VertexInside { of, point: y });
    }
    *quads = if of == Which::P {
        (Some(quad), Some(own_quad))
    } else {
        (Some(own_quad), Some(quad))
    };
    None
}

/// A vertex of Q in P's quadrilateral (made by `quads.0`) or a vertex of P in Q's
/// (`quads.1`), sample vertices inside their polygon, so a vertex inside, from up to
/// `rounds` rounds of one uniform draw on each polygon (`below`, as the samples are
/// drawn), each tested in O(1); Q's quadrilateral is made only if the first draw
/// misses. Where the sample hulls cross, a fair part of each boundary usually lies in
/// the other's quadrilateral, so the expected number of rounds is O(1) on such pairs;
/// on others the rounds cost O(`rounds`) and the caller goes on.
pub(super) fn drawn_witness<K: Kernel, R: Rng + ?Sized>(
    k: K,
    (p, q): (&LinkedPolygon, &LinkedPolygon),
    quads: (impl FnOnce() -> Quad, impl FnOnce() -> Quad),
    rounds: u32,
    rng: &mut R,
) -> Option<Certificate> {
    if rounds == 0 {
        return None;
    }
    let (n, m) = (p.len() as u32, q.len() as u32);
    let draw_q = |rng: &mut R| q.point_at(below(rng, m) as usize);
    let draw_p = |rng: &mut R| p.point_at(below(rng, n) as usize);
    let inside = |of, point| Some(Certificate::VertexInside { of, point });
    let qp = quads.0();
    let y = draw_q(rng);
    if qp.contains(k, y) {
        return inside(Which::Q, y);
    }
    let qq = quads.1();
    for round in 0..rounds {
        if round > 0 {
            let y = draw_q(rng);
            if qp.contains(k, y) {
                return inside(Which::Q, y);
            }
        }
        let x = draw_p(rng);
        if qq.contains(k, x) {
            return inside(Which::P, x);
        }
    }
    None
}

/// A point of `a` (points of P's sample) in `qb` (a quadrilateral of Q's sample,
/// [`Quad::spread`]), or of `b` (Q's) in `qa` (P's), taken alternately: how many points
/// were tested, and the point found with the polygon it is a vertex of. Each
/// quadrilateral has sample vertices for corners, so it lies inside its polygon and a
/// point in it is a vertex inside, an intersection with its certificate. O(|a| + |b|);
/// each test computes `f64` signs, then (only for a point they put inside) exact
/// orientations ([`Quad::contains`]). A miss (a point rounding puts outside, or on the
/// chord's line) only leaves the query to the LP.
#[inline(never)]
pub(super) fn prefix_inside<K: Kernel>(
    k: K,
    (a, qa): (&[Point], &Quad),
    (b, qb): (&[Point], &Quad),
) -> (u64, Option<(Which, Point)>) {
    for i in 0..a.len().max(b.len()) {
        if let Some(&y) = b.get(i)
            && qa.contains(k, y)
        {
            return (2 * i as u64 + 1, Some((Which::Q, y)));
        }
        if let Some(&x) = a.get(i)
            && qb.contains(k, x)
        {
            return (2 * i as u64 + 2, Some((Which::P, x)));
        }
    }
    ((a.len() + b.len()) as u64, None)
}
