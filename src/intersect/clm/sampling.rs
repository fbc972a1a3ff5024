//! Drawing the samples: uniform vertex positions, the generator's integers, shuffles,
//! and the prefixes of a sample that a first LP tries.

use crate::kernel::Point;
use crate::lp::ArenaPoints;
use crate::polygon::{LinkedPolygon, SampleWorkspace};
use rand::Rng;

/// Appends `r` random vertex positions of `poly` to `out`: all of them when r ≥ n; r
/// independent uniform draws (with replacement) when r ≤ n/16, where repeats are rare
/// and skipping the distinctness marks saves a cache miss per draw on large polygons;
/// otherwise r distinct positions ([`LinkedPolygon::sample_positions`]). Repeats are
/// harmless: the LP accepts duplicate points, and the chain bounds of the analysis hold
/// for samples drawn with replacement.
pub(super) fn sample<R: Rng + ?Sized>(
    poly: &LinkedPolygon,
    r: usize,
    rng: &mut R,
    marks: &mut SampleWorkspace,
    out: &mut Vec<u32>,
) {
    let n = poly.len();
    if r.saturating_mul(16) <= n {
        draw_below(rng, n as u32, r, out);
    } else {
        poly.sample_positions(r, rng, marks, out);
    }
}

/// Replaces `out` by the points of `poly` at `positions`, in order.
pub(super) fn gather(poly: &LinkedPolygon, positions: &[u32], out: &mut Vec<Point>) {
    out.clear();
    out.extend(positions.iter().map(|&i| poly.point_at(i as usize)));
}

/// A uniform integer in `0..n` (`n > 0`) from 32 random bits, by Lemire's
/// multiply-and-reject method: one multiplication, and a division only in the rare
/// round that may need a rejection. (`Rng::random_range` does the same with more
/// bookkeeping; this runs for every sampled vertex and every chain vertex.)
#[inline]
pub(super) fn below<R: Rng + ?Sized>(rng: &mut R, n: u32) -> u32 {
    below_from(rng.next_u32(), rng, n)
}

/// [`below`] with the first 32 random bits given (`bits`, uniform and independent of
/// `rng`'s further output); a rejection draws from `rng`.
#[inline]
pub(super) fn below_from<R: Rng + ?Sized>(bits: u32, rng: &mut R, n: u32) -> u32 {
    let mut m = u64::from(bits) * u64::from(n);
    if (m as u32) < n {
        let threshold = n.wrapping_neg() % n;
        while (m as u32) < threshold {
            m = u64::from(rng.next_u32()) * u64::from(n);
        }
    }
    (m >> 32) as u32
}

/// Appends `count` independent uniform integers in `0..n` (`n > 0`) to `out`, two from
/// each 64-bit draw (its halves are independent uniform 32-bit words, as in
/// [`shuffle`]): half the generator's steps of [`below`] for each.
pub(super) fn draw_below<R: Rng + ?Sized>(rng: &mut R, n: u32, count: usize, out: &mut Vec<u32>) {
    let start = out.len();
    out.resize(start + count, 0);
    let mut pairs = out[start..].chunks_exact_mut(2);
    for pair in &mut pairs {
        let bits = rng.next_u64();
        pair[0] = below_from(bits as u32, rng, n);
        pair[1] = below_from((bits >> 32) as u32, rng, n);
    }
    if let [last] = pairs.into_remainder() {
        *last = below(rng, n);
    }
}

/// Shuffles `positions` uniformly (Fisher–Yates), and `points` the same way when it is
/// not empty (then it has the same length). Each 64-bit draw serves two swaps (its
/// halves are independent uniform 32-bit words).
pub(super) fn shuffle<R: Rng + ?Sized>(positions: &mut [u32], points: &mut [Point], rng: &mut R) {
    let with_points = !points.is_empty();
    debug_assert!(!with_points || points.len() == positions.len());
    let mut i = positions.len().saturating_sub(1);
    let mut swap = |i: usize, j: u32| {
        positions.swap(i, j as usize);
        if with_points {
            points.swap(i, j as usize);
        }
    };
    while i >= 2 {
        let bits = rng.next_u64();
        swap(i, below_from(bits as u32, rng, i as u32 + 1));
        swap(i - 1, below_from((bits >> 32) as u32, rng, i as u32));
        i -= 2;
    }
    if i == 1 {
        swap(1, below(rng, 2));
    }
}

/// Appends min(r, n) distinct random positions of a polygon of `n` vertices to `out`
/// by a partial Fisher–Yates shuffle of `perm` (the identity before and after: the
/// swaps are undone in reverse order). [`Sampling::FisherYates`].
pub(super) fn fisher_yates<R: Rng + ?Sized>(
    n: usize,
    r: usize,
    rng: &mut R,
    perm: &mut Vec<u32>,
    swaps: &mut Vec<u32>,
    out: &mut Vec<u32>,
) {
    // The identity on 0..len, of which 0..n is the identity on 0..n: one array serves
    // polygons of every size, built once for the largest.
    if perm.len() < n {
        perm.clear();
        perm.extend(0..n as u32);
    }
    let perm = &mut perm[..n];
    swaps.clear();
    for last in (n - r.min(n)..n).rev() {
        let j = rng.random_range(0..=last);
        perm.swap(j, last);
        swaps.push(j as u32);
        out.push(perm[last]);
    }
    for (last, &j) in (n - swaps.len()..n).zip(swaps.iter().rev()) {
        perm.swap(j as usize, last);
    }
}

/// With the samples in boundary order ([`ClmVariant::sample_walk`]), the points of each
/// sample that a first LP tries before they are put in order.
pub(super) const PREFIX: usize = 12;

/// How many points of each sample after its prefix are tested in the prefixes'
/// quadrilaterals when the prefix LP finds the prefixes' hulls disjoint.
pub(super) const NEXT: usize = 12;

/// The first [`PREFIX`] entries of a sample's points or positions (fewer if it has
/// fewer).
pub(super) fn prefix_of<T>(sample: &[T]) -> &[T] {
    &sample[..PREFIX.min(sample.len())]
}

/// The points of `polygon` at `positions`, as LPs and probe reports take them.
pub(super) fn arena<'a>(polygon: &'a LinkedPolygon, positions: &'a [u32]) -> ArenaPoints<'a> {
    ArenaPoints { polygon, positions }
}

/// The [`NEXT`] points of a sample after its prefix (fewer if it has fewer).
pub(super) fn next_points(sample: &[Point]) -> &[Point] {
    &sample[PREFIX.min(sample.len())..(PREFIX + NEXT).min(sample.len())]
}

/// ⌈c·√n⌉, at least 3.
pub(super) fn sample_size(c: f64, n: usize) -> usize {
    let r = (c * (n as f64).sqrt()).ceil();
    if r.is_finite() && r >= 3.0 { r as usize } else { 3 }
}
