//! Shared by the LP test files: the exact brute-force answer the LPs are checked against.

use polysect::kernel::{Kernel, segments_intersect};
use polysect::{Exact, Orientation, Point};

/// CH(A) ∩ CH(B) ≠ ∅, exactly: two closed segments (zero-length allowed) between points of
/// each set meet, or a point of one set lies in a non-degenerate triangle of the other
/// (Carathéodory). O(|A|²|B|² + |A|³|B| + |A||B|³).
pub fn hulls_intersect(a: &[Point], b: &[Point]) -> bool {
    let k = Exact;
    for i in 0..a.len() {
        for j in i..a.len() {
            for s in 0..b.len() {
                for t in s..b.len() {
                    if segments_intersect(k, a[i], a[j], b[s], b[t]) {
                        return true;
                    }
                }
            }
        }
    }
    let in_triangle = |x: Point, t: &[Point]| {
        for i in 0..t.len() {
            for j in i + 1..t.len() {
                for l in j + 1..t.len() {
                    let o = k.orient(t[i], t[j], t[l]);
                    if o == Orientation::Collinear {
                        continue;
                    }
                    if k.orient(t[i], t[j], x) != o.reverse()
                        && k.orient(t[j], t[l], x) != o.reverse()
                        && k.orient(t[l], t[i], x) != o.reverse()
                    {
                        return true;
                    }
                }
            }
        }
        false
    };
    a.iter().any(|&x| in_triangle(x, b)) || b.iter().any(|&x| in_triangle(x, a))
}
