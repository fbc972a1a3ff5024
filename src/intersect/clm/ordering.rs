//! Putting a sample in boundary order: angle keys, bucket passes and exact settling
//! of near-ties.

use crate::kernel::{Kernel, Orientation, Point};

/// Scratch memory of [`boundary_order`]: the keyed entries, the bucket counts, the
/// entries in key order, and the sorted copy of the sample.
#[derive(Clone, Debug, Default)]
pub(super) struct OrderScratch {
    entries: Vec<u64>,
    counts: Vec<u32>,
    sorted: Vec<u64>,
    positions: Vec<u32>,
    points: Vec<Point>,
}

/// Puts a sample of a strictly convex polygon's vertices (`positions` and `points`,
/// index for index) in counter-clockwise boundary order from its lowest point (the
/// leftmost of those), repeats dropped: the vertices of a convex polygon in cyclic
/// order, as [`separate_chains`] takes them. Every point lies in the half-turn [0, π)
/// of directions seen from the lowest point o, so "a before b" is `orient(o, a, b) =
/// Ccw`, and no two distinct vertices of a strictly convex polygon tie: under an exact
/// kernel the order is exact.
///
/// Each point gets a 32-bit key, an `f64` pseudo-angle about o scaled by 2³¹
/// ([`angle_key`]), and keys two or more apart are in the exact order (the error bound
/// is proved there). So the points are sorted by key alone (key and index in one
/// `u64`: one counting pass into r–2r buckets by the top bits, then an insertion sort
/// whose first step per entry is branchless, a minimum and a maximum with its
/// predecessor (most entries move by one place or none, and a loop exit there was
/// mispredicted about as often as it moved), and which falls back to a full sort after
/// 4r moves when the angles crowd), gathered in
/// that order, and only the runs of near-ties (consecutive keys at most one apart:
/// repeats, o's neighbours, angles within about 2⁻³¹) are sorted again with `orient`
/// ([`settle_near_ties`]), which also drops the repeats. Returns `false` when a
/// difference overflows (the keys are then unsound) or the near-ties need more than
/// 4r + 16 moves; the sample is then unchanged and the caller runs the LP.
pub(super) fn boundary_order<K: Kernel>(
    k: K,
    positions: &mut Vec<u32>,
    points: &mut Vec<Point>,
    scratch: &mut OrderScratch,
) -> bool {
    let n = points.len();
    debug_assert_eq!(n, positions.len());
    let Some(&first) = points.first() else {
        return true;
    };
    // The lowest point, the leftmost of those (the first such in the sample): the lowest
    // height by four running minima (no branch to mispredict, no chain of dependent
    // comparisons), then the leftmost point at that height, on a branch that is rarely
    // taken. (One pass testing x first on ties compiled to a branch on x's order,
    // taken half the time.)
    let mut low = [first.y; 4];
    let mut quads = points.chunks_exact(4);
    for quad in &mut quads {
        for (low, x) in low.iter_mut().zip(quad) {
            if x.y < *low {
                *low = x.y;
            }
        }
    }
    for x in quads.remainder() {
        if x.y < low[0] {
            low[0] = x.y;
        }
    }
    let lowest = low.into_iter().fold(first.y, |m, y| if y < m { y } else { m });
    let mut o = first;
    let mut found = false;
    for &x in points.iter().filter(|x| x.y == lowest) {
        if !found || x.x < o.x {
            (o, found) = (x, true);
        }
    }
    let OrderScratch {
        entries,
        counts,
        sorted,
        positions: sorted_positions,
        points: sorted_points,
    } = scratch;
    // Each point's key above its index, counted in its bucket (the key's top bits) as
    // it is made; and the largest |dx| + dy (infinite if a difference overflowed).
    let bits = n.next_power_of_two().trailing_zeros().clamp(1, 24);
    let bucket = |entry: u64| (entry >> (64 - bits)) as usize;
    counts.clear();
    counts.resize(1 << bits, 0);
    let mut widest = 0.0f64;
    entries.clear();
    entries.resize(n, 0);
    for ((entry, &x), i) in entries.iter_mut().zip(points.iter()).zip(0u32..) {
        let (key, width) = angle_key(o, x);
        if width > widest {
            widest = width;
        }
        *entry = u64::from(key) << 32 | u64::from(i);
        counts[bucket(*entry)] += 1;
    }
    if widest == f64::INFINITY {
        return false;
    }
    // Counting sort on the keys' top bits, then insertion sort on the whole entries.
    let mut sum = 0;
    for count in counts.iter_mut() {
        (*count, sum) = (sum, sum + *count);
    }
    sorted.clear();
    sorted.resize(n, 0);
    for &entry in entries.iter() {
        let slot = &mut counts[bucket(entry)];
        sorted[*slot as usize] = entry;
        *slot += 1;
    }
    // Each insertion's first step is branchless (the entry and its predecessor as their
    // minimum and maximum): most entries move by at most one place, which a loop's exit
    // branch mispredicts about as often as it happens. Only an entry that moves further
    // loops, on a branch rarely taken.
    let mut moves = 0;
    for i in 1..n {
        let (prev, entry) = (sorted[i - 1], sorted[i]);
        let low = prev.min(entry);
        (sorted[i - 1], sorted[i]) = (low, prev.max(entry));
        moves += usize::from(entry < prev);
        if i >= 2 && sorted[i - 2] > low {
            let mut j = i - 1;
            while j > 0 && sorted[j - 1] > low {
                sorted[j] = sorted[j - 1];
                j -= 1;
            }
            sorted[j] = low;
            moves += i - 1 - j;
        }
        if moves > 4 * n {
            // Crowded buckets.
            sorted.sort_unstable();
            break;
        }
    }
    sorted_positions.clear();
    sorted_positions.extend(sorted.iter().map(|&e| positions[e as u32 as usize]));
    sorted_points.clear();
    sorted_points.extend(sorted.iter().map(|&e| points[e as u32 as usize]));
    // Every `orient` of the near-ties is on three points of the sample: rare enough
    // that the kernel's static filter does (no box to compute for a semi-static one).
    if !settle_near_ties(k, o, sorted, sorted_positions, sorted_points) {
        return false;
    }
    std::mem::swap(positions, sorted_positions);
    std::mem::swap(points, sorted_points);
    true
}

/// The key of `x` in [`boundary_order`] about the lowest point `o`, and |dx| + dy as
/// computed (infinite when a difference overflowed; the key is then unsound).
///
/// The key is ⌊2³¹·v⌋ (saturating; 0 for o itself, whose 0/0 is NaN) for the `f64`
/// value v of the pseudo-angle 1 − dx/(|dx| + dy), (dx, dy) = x − o: exactly, it lies in
/// [0, 2] and increases strictly with the angle of x − o in [0, π]. **Keys two or more
/// apart are in the exact order.** Proof: unless |dx| + dy overflows, dx and dy are
/// computed with relative error at most u = 2⁻⁵³ (exactly when subnormal), then
/// |dx| + dy (no cancellation: dy ≥ 0) and the quotient t = dx/(|dx| + dy) with relative
/// error u each (or absolute error 2⁻¹⁰⁷⁵ when subnormal); so the computed t is
/// t·(1 + δ) with |δ| < 4.1u, within 4.1u of t as |t| ≤ 1, and 1 − t rounds once more
/// (error ≤ u): the computed v is within 5.2u of the exact one. If key(b) ≥ key(a) + 2,
/// then with the computed values 2³¹·v(b) ≥ key(b) ≥ key(a) + 2 > 2³¹·v(a) + 1 (the
/// floor gives key ≤ 2³¹·v < key + 1; saturation at 2³² − 1 lowers only a key that
/// cannot be the smaller, and v ≥ 0 as |dx| ≤ |dx| + dy survives rounding), so the
/// exact values differ by more than 2⁻³¹ − 10.4u > 0 and the angle of a is smaller.
/// o comes before every other point, and its key 0 is the smallest: right as well.
#[inline]
pub(super) fn angle_key(o: Point, x: Point) -> (u32, f64) {
    let (dx, dy) = (x.x - o.x, x.y - o.y);
    let width = dx.abs() + dy;
    let v = 1.0 - dx / width;
    ((v * 2_147_483_648.0) as u32, width)
}

/// The last step of [`boundary_order`], in place on the sample gathered in key order
/// (`sorted`, its entries, gives the keys): each run of near-ties (consecutive keys at
/// most one apart) is sorted by insertion with `orient` about `o`, and repeats (equal
/// points, which have equal keys and end up adjacent) are dropped. Keys two or more
/// apart are in the exact order ([`angle_key`]), so every point of a run is rightly
/// placed against every point outside it. `false` after 4r + 16 moves (the contents
/// are then scrambled).
pub(super) fn settle_near_ties<K: Kernel>(
    k: K,
    o: Point,
    sorted: &[u64],
    positions: &mut Vec<u32>,
    points: &mut Vec<Point>,
) -> bool {
    let n = points.len();
    let before = |a: Point, b: Point| b != o && (a == o || k.orient(o, a, b) == Orientation::Ccw);
    let mut budget = 4 * n + 16;
    // The first index whose point repeats its predecessor's (n: none).
    let mut first_repeat = n;
    let near_tie = |w: &[u64]| (w[1] >> 32) - (w[0] >> 32) <= 1;
    // A near-tie's entries (key above index) differ by less than 2 · 2^32: a cheap
    // filter for the scan, which a pair two keys apart may also pass (checked next).
    let close = |(&a, &b): (&u64, &u64)| b - a < 2 << 32;
    let mut from = 0;
    while let Some(at) = sorted[from..]
        .iter()
        .zip(&sorted[from.min(n - 1) + 1..])
        .position(close)
    {
        let start = from + at;
        if !near_tie(&sorted[start..start + 2]) {
            from = start + 1;
            continue;
        }
        // The run start..end.
        let mut end = start + 2;
        while end < n && near_tie(&sorted[end - 1..=end]) {
            end += 1;
        }
        for i in start + 1..end {
            let (x, at) = (points[i], positions[i]);
            let mut j = i;
            while j > start && before(x, points[j - 1]) {
                if budget == 0 {
                    return false;
                }
                budget -= 1;
                points[j] = points[j - 1];
                positions[j] = positions[j - 1];
                j -= 1;
            }
            (points[j], positions[j]) = (x, at);
            if j > start && points[j - 1] == x {
                // Later insertions only move this pair right: no repeat lies before
                // the first one recorded.
                first_repeat = first_repeat.min(j);
            }
        }
        from = end;
    }
    if first_repeat < n {
        let mut len = first_repeat;
        for i in first_repeat..n {
            if points[i] != points[len - 1] {
                (points[len], positions[len]) = (points[i], positions[i]);
                len += 1;
            }
        }
        points.truncate(len);
        positions.truncate(len);
    }
    true
}
