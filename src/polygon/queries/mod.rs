//! Everyday queries on one polygon, as methods of the polygon types: closed point
//! containment, the extreme vertex in a direction, area and centroid. One file per
//! query; this page is their index.
//!
//! | query | [`ConvexPolygon`](crate::ConvexPolygon) | [`LinkedPolygon`](crate::LinkedPolygon) | [`SimplePolygon`](crate::SimplePolygon) | precision |
//! |---|---|---|---|---|
//! | point containment (closed) | `contains_point`: O(log n) | `contains_point`: expected O(√n) | `contains_point`: O(n) | exact (a predicate) |
//! | extreme vertex in a direction | `extreme_vertex`: O(log n) | `extreme_vertex`: expected O(√n) | | exact (a predicate) |
//! | area, centroid | `area`, `centroid`: O(n) | `area`, `centroid`: O(n) | `area`, `signed_area`, `centroid`: O(n) | constructed: compensated sums |
//!
//! # Predicates and constructions
//! Containment and the extreme vertex answer a yes/no or which-one question, so they are
//! decided by [`Kernel`](crate::Kernel) predicates on the input coordinates (and the
//! query's own point or direction): exact under [`Exact`](crate::Exact), the default,
//! for every finite input. Each has a `*_with` variant taking the kernel, so
//! [`Fast`](crate::Fast) can be chosen, as for the intersection tests.
//!
//! Area and centroid are *values*: they are constructed in floating point and cannot be
//! exact in general (the exact area of a polygon with `f64` vertices needs up to about
//! 2,100 bits). They are computed relative to the first vertex v₀, with every
//! difference dᵢ = vᵢ − v₀ and every leading product kept exactly as a sum of two
//! `f64` (two-sum, Dekker's two-product) and a compensated sum of the fan cross
//! products cᵢ = dᵢ × dᵢ₊₁ (as in Ogita, Rump and Oishi's `Sum2`):
//! * area: |A′ − A| ≤ 2^−53·A + 4n²·2^−106·P, with P = Σ |dᵢ.x·dᵢ₊₁.y| + |dᵢ.y·dᵢ₊₁.x|
//!   (P/A is a condition number: about n for a regular polygon, large for needles);
//!   every area in the tests came out as the exact area rounded to nearest;
//! * centroid: per coordinate within 4·2^−53·D·Q + ½ ulp, with D the largest
//!   coordinate difference from v₀ and Q = Σ|cᵢ| / |Σcᵢ| (1 for convex polygons);
//! * the sign of a simple polygon's [`signed_area`](crate::SimplePolygon::signed_area)
//!   is exact (its orientation, an exact predicate).
//!
//! Every finite input is accepted: differences are scaled by a power of two, so
//! nothing overflows on the way; only the area itself can exceed `f64::MAX` (`+∞`)
//! or fall into the subnormals. The centroid is always finite.
//!
//! # Sampling on linked polygons
//! A linked polygon has no index to search, but it can draw a uniformly random vertex
//! in O(1). The two sublinear queries draw r = ⌈√n⌉ vertices (independent uniform
//! draws), keep the one closest to the answer in the order the query needs, and walk
//! the boundary from it. Between two consecutive drawn vertices (in boundary order)
//! lie O(n/r) vertices in expectation, so the walk is expected O(n/r) and the whole
//! query expected O(r + n/r) = O(√n) for every polygon: the expectation is over the
//! draws only, never over the input. The answer never depends on the draws under the
//! exact kernel. This is Chazelle–Liu–Magen's idea (sample, then walk a short chain);
//! their full machinery (an LP over the sample) is not needed for one point or one
//! direction, because the vertices closest to the answer can be recognised one by one
//! with a single predicate each (see the two files for the orders used).
//!
//! The one-off methods (`contains_point`, `extreme_vertex`) draw from a generator
//! seeded by the operating system, so no input can be prepared to make the walk long;
//! the `*_with` methods take the caller's generator (seeded for reproducible runs).

mod area;
mod contains;
mod extreme;

/// The number of vertices a sampled query draws from a polygon of `n` vertices: ⌈√n⌉.
pub(crate) fn sample_count(n: usize) -> usize {
    (n as f64).sqrt().ceil() as usize
}
