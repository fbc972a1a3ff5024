//! The distance and closest pair of a certified feature, correctly rounded without big
//! integers: double-double arithmetic that carries a rigorous bound on its error, and a
//! rounding that is answered only when the bound decides it.
//!
//! A value is `hi + lo` (normalised: `hi` is `hi + lo` rounded) with `err` bounding
//! its distance to the exact value. Differences of input doubles are exact (`err = 0`);
//! `+`, `×`, `÷` and `√` add their own rounding error, bounded term by term (each
//! operation below says how), and propagate their operands' errors. The exact value
//! then lies in `[hi + lo − err, hi + lo + err]`; when that interval lies strictly
//! inside the rounding interval of `hi` (half an ulp on either side), `hi` is the
//! correctly rounded value. Otherwise — the exact value within about 2^-100 relative of a
//! midpoint between doubles, a near-cancellation, or inputs outside the safe range —
//! the caller rounds the exact rationals instead.
//!
//! # Range
//! Every input coordinate must be zero or of magnitude in [2^-250, 2^250]: then no
//! product overflows (degree 2 in the input is at most 2^502, Dekker's split needs
//! below 2^996) and every bound adds `f64::MIN_POSITIVE` per operation, which covers
//! whatever underflows. Error bounds are multiplied by `1 + 2^-40`, which covers the
//! rounding of their own few dozen operations.
//!
//! # Cost
//! A few dozen floating-point operations per value, no allocation.

use super::walk::Feature;
use crate::kernel::Point;

const U: f64 = f64::EPSILON / 2.0;
/// Covers the rounding of the error bounds' own arithmetic.
const SAFETY: f64 = 1.0 + 1.0 / (1u64 << 40) as f64;
const TINY: f64 = f64::MIN_POSITIVE;

/// `hi + lo`, within `err` of the exact value.
#[derive(Clone, Copy, Debug)]
struct Dd {
    hi: f64,
    lo: f64,
    err: f64,
}

#[inline(always)]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// Dekker's split: `a = h + l`, each with at most 26 significant bits (|a| < 2^996).
#[inline(always)]
fn split(a: f64) -> (f64, f64) {
    let c = 134_217_729.0 * a; // 2^27 + 1
    let h = c - (c - a);
    (h, a - h)
}

/// `a · b = p + e` exactly (no overflow or underflow).
#[inline(always)]
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
}

impl Dd {
    /// The exact difference `a − b` of two doubles.
    #[inline(always)]
    fn diff(a: f64, b: f64) -> Dd {
        let (hi, lo) = two_sum(a, -b);
        Dd { hi, lo, err: 0.0 }
    }

    #[inline(always)]
    fn exact(a: f64) -> Dd {
        Dd {
            hi: a,
            lo: 0.0,
            err: 0.0,
        }
    }

    /// An upper bound on the magnitude of the computed value.
    #[inline(always)]
    fn mag(self) -> f64 {
        self.hi.abs() + self.lo.abs()
    }

    /// Exact value `X + Y` against the computed `fl(fl(xl + yl) + e) + s`: two roundings,
    /// each at most `u` of its result, `|t₁| ≤ |xl| + |yl|` and `|t₂| ≤ |t₁|(1 + u) + |e|`.
    #[inline(always)]
    fn add(self, y: Dd) -> Dd {
        let (s, e) = two_sum(self.hi, y.hi);
        let t = (self.lo + y.lo) + e;
        let (hi, lo) = two_sum(s, t);
        let own = 3.0 * U * (self.lo.abs() + y.lo.abs() + e.abs());
        Dd {
            hi,
            lo,
            err: (self.err + y.err + own + TINY) * SAFETY,
        }
    }

    #[inline(always)]
    fn neg(self) -> Dd {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
            err: self.err,
        }
    }

    /// `(xh + xl)(yh + yl)` is `ph + pl + xh·yl + xl·yh + xl·yl`; computed without
    /// `xl·yl` and with three roundings (`xh·yl`, `xl·yh`, their sum, the sum with
    /// `pl`), each at most `u` of its result: at most `|xl·yl| + 4u(A + |pl|)`,
    /// `A = |xh·yl| + |xl·yh|`. The operands' errors add `|x|·e_y + |y|·e_x + e_x·e_y`.
    #[inline(always)]
    fn mul(self, y: Dd) -> Dd {
        let (ph, pl) = two_prod(self.hi, y.hi);
        let (a, b) = (self.hi * y.lo, self.lo * y.hi);
        let t = pl + (a + b);
        let (hi, lo) = two_sum(ph, t);
        let own = (self.lo * y.lo).abs() + 4.0 * U * (a.abs() + b.abs() + pl.abs());
        let carried = self.mag() * y.err + y.mag() * self.err + self.err * y.err;
        Dd {
            hi,
            lo,
            err: (own + carried + 2.0 * TINY) * SAFETY,
        }
    }

    /// A lower bound on the magnitude of the exact value (may be ≤ 0: unknown sign).
    #[inline(always)]
    fn low(self) -> f64 {
        (self.hi.abs() - self.lo.abs() - self.err) * (1.0 - 4.0 * U)
    }

    /// `x / y` for `y` of certain sign: `q₁ = xh / yh`, the residual `r = x − q₁·y` in
    /// double-double (with its bound `e_r`), `q₂ = rh / yh`. Against the computed `x̃/ỹ`
    /// the error is at most `(e_r + |rl|)/|ỹ| + |rh|·|yl|/(|ỹ|·|yh|) + u|q₂|`; the
    /// operands' errors add `(e_x + |x/y|·e_y)/(|ỹ| − e_y)`.
    fn div(self, y: Dd) -> Option<Dd> {
        let low = y.low();
        if low.is_nan() || low <= 0.0 {
            return None;
        }
        let q1 = self.hi / y.hi;
        let r = self.add(Dd::exact(q1).mul(Dd { err: 0.0, ..y }).neg());
        let q2 = r.hi / y.hi;
        let (hi, lo) = two_sum(q1, q2);
        let yt = (y.hi.abs() - y.lo.abs()) * (1.0 - 4.0 * U);
        if yt.is_nan() || yt <= 0.0 {
            return None;
        }
        let own =
            (r.err + r.lo.abs()) / yt + r.hi.abs() * y.lo.abs() / (yt * y.hi.abs()) + 2.0 * U * q2.abs();
        let quotient = (hi.abs() + lo.abs()) * (1.0 + 4.0 * U);
        let carried = (self.err + quotient * y.err) / low;
        Some(Dd {
            hi,
            lo,
            err: (own + carried + 2.0 * TINY) * SAFETY,
        })
    }

    /// `√x` for `x` certainly positive: `s₁ = √xh`, the residual `r = x − s₁²` in
    /// double-double, `s₂ = rh/(2s₁)`. With `s = √x̃`: `s − s₁ = r/(s + s₁)`, so
    /// `|s − s₁ − s₂| ≤ r²/(2s₁(s + s₁)²) + (e_r + |rl|)/(s + s₁) + |rh|·|s − s₁|/(2s₁(s + s₁)) + u|s₂|`,
    /// bounded with `s ≥ s₁(1 − 2^-40)`; the operand's error adds `e_x/√(x̃ − e_x)`.
    fn sqrt(self) -> Option<Dd> {
        let low = self.low();
        if low.is_nan() || low <= 0.0 || self.hi <= 0.0 {
            return None;
        }
        let s1 = self.hi.sqrt();
        let (sq, se) = two_prod(s1, s1);
        let r = self.add(Dd {
            hi: -sq,
            lo: -se,
            err: 0.0,
        });
        let s2 = r.hi / (2.0 * s1);
        let (hi, lo) = two_sum(s1, s2);
        let sum = s1 * (2.0 - 1e-12);
        let gap = (r.mag() + r.err) / sum;
        let own = (r.mag() + r.err) * (r.mag() + r.err) / (2.0 * s1 * sum * sum)
            + (r.err + r.lo.abs()) / sum
            + r.hi.abs() * gap / (2.0 * s1 * sum)
            + 2.0 * U * s2.abs();
        let carried = self.err / (low.sqrt() * (1.0 - 4.0 * U));
        Some(Dd {
            hi,
            lo,
            err: (own + carried + 2.0 * TINY) * SAFETY,
        })
    }

    /// The correctly rounded value, when the error bound decides it.
    fn rounded(self) -> Option<f64> {
        let h = self.hi;
        if !h.is_finite() || !self.err.is_finite() || !self.lo.is_finite() {
            return None;
        }
        if self.err == 0.0 && self.lo == 0.0 {
            return Some(h);
        }
        if h == 0.0 || h.abs() < 1e-290 {
            return None;
        }
        let up = (h.next_up() - h) * 0.5;
        let down = (h - h.next_down()) * 0.5;
        let margin = self.err * SAFETY;
        (self.lo + margin < up && self.lo - margin > -down).then_some(h)
    }
}

/// Whether a coordinate is in the safe range (module docs).
#[inline(always)]
fn safe(x: f64) -> bool {
    const LOW: f64 = 5.527147875260445e-76; // 2^-250
    const HIGH: f64 = 1.8092513943330656e75; // 2^250
    x == 0.0 || (LOW..=HIGH).contains(&x.abs())
}

fn all_safe(points: &[Point]) -> bool {
    points.iter().all(|p| safe(p.x) && safe(p.y))
}

/// The correctly rounded distance and closest pair (on P, then on Q) of a nearest
/// feature of two disjoint polygons, or `None` when the bounds do not decide a rounding
/// (the caller then rounds the exact construction).
pub(crate) fn separation(p: &[Point], q: &[Point], feature: Feature) -> Option<(f64, [Point; 2])> {
    let (n, m) = (p.len(), q.len());
    match feature {
        Feature::Vertices { p: i, q: j } => {
            let (a, b) = (p[i], q[j]);
            if !all_safe(&[a, b]) {
                return None;
            }
            let (dx, dy) = (Dd::diff(b.x, a.x), Dd::diff(b.y, a.y));
            let d = dx.mul(dx).add(dy.mul(dy)).sqrt()?.rounded()?;
            Some((d, [a, b]))
        }
        Feature::EdgeOfQ { q: j, p: i } => {
            let (d, on) = edge(q[j], q[(j + 1) % m], p[i])?;
            Some((d, [p[i], on]))
        }
        Feature::EdgeOfP { p: i, q: j } => {
            let (d, on) = edge(p[i], p[(i + 1) % n], q[j])?;
            Some((d, [on, q[j]]))
        }
    }
}

/// The distance from `v` to the line of the edge `a → b` and its projection on it,
/// `|e × w| / |e|` and `a + e·(w·e)/|e|²` with `e = b − a`, `w = v − a`.
fn edge(a: Point, b: Point, v: Point) -> Option<(f64, Point)> {
    if !all_safe(&[a, b, v]) {
        return None;
    }
    let (ex, ey) = (Dd::diff(b.x, a.x), Dd::diff(b.y, a.y));
    let (wx, wy) = (Dd::diff(v.x, a.x), Dd::diff(v.y, a.y));
    let l = ex.mul(ex).add(ey.mul(ey));
    let c = ex.mul(wy).add(ey.mul(wx).neg());
    let t = wx.mul(ex).add(wy.mul(ey));
    let c = if c.hi < 0.0 { c.neg() } else { c };
    let d = c.div(l.sqrt()?)?.rounded()?;
    let k = t.div(l)?;
    let x = Dd::exact(a.x).add(ex.mul(k)).rounded()?;
    let y = Dd::exact(a.y).add(ey.mul(k)).rounded()?;
    Some((d, Point::new(x, y)))
}

/// The correctly rounded depth `|o|/√l` and unit normal `(±e_y, ∓e_x)/√l` of the
/// D-edge of edge `a → b` with vertex `v` (`[a, b, v]`; `of_q`: the edge is Q's), as
/// `construct::depth_and_normal` rounds them (`o = e × (v − a)`, `l = |e|²`), or
/// `None` when a bound does not decide (a depth of 0 among them: touching pairs round
/// the exact rationals).
pub(crate) fn depth_and_normal([a, b, v]: [Point; 3], of_q: bool) -> Option<(f64, [f64; 2])> {
    if !all_safe(&[a, b, v]) {
        return None;
    }
    let (ex, ey) = (Dd::diff(b.x, a.x), Dd::diff(b.y, a.y));
    let (wx, wy) = (Dd::diff(v.x, a.x), Dd::diff(v.y, a.y));
    let root = ex.mul(ex).add(ey.mul(ey)).sqrt()?;
    let o = ex.mul(wy).add(ey.mul(wx).neg());
    let o = if o.hi < 0.0 { o.neg() } else { o };
    let depth = o.div(root)?.rounded()?;
    // An exact difference is zero iff its high part is: that component is +0, as the
    // exact rounding gives (never −0).
    let component = |x: Dd| {
        if x.hi == 0.0 {
            Some(0.0)
        } else {
            x.div(root)?.rounded()
        }
    };
    let direction = if of_q { [ey.neg(), ex] } else { [ey, ex.neg()] };
    Some((depth, [component(direction[0])?, component(direction[1])?]))
}

#[cfg(test)]
mod tests {
    use super::super::{construct, walk};
    use super::*;
    use crate::generate::{Density, ellipse_polygon};
    use crate::kernel::Exact;
    use rand::rngs::SmallRng;
    use rand::{Rng, SeedableRng};

    /// Whenever the certified rounding answers, it equals the exact construction's
    /// rounding; and it answers on nearly every random pair.
    #[test]
    fn certified_roundings_equal_the_exact_ones() {
        let mut rng = SmallRng::seed_from_u64(41);
        let (mut answered, mut total) = (0, 0);
        for case in 0..3000 {
            let (n, m) = (rng.random_range(3..40), rng.random_range(3..40));
            let p = ellipse_polygon(&mut rng, n, &Density::Uniform, true);
            let q0 = ellipse_polygon(&mut rng, m, &Density::Uniform, true);
            let a: f64 = rng.random_range(0.0..std::f64::consts::TAU);
            let r = rng.random_range(2.0..5.0);
            let scale = [1.0, 1e-30, 1e30, 3.0][case % 4];
            let (pv, qv): (Vec<Point>, Vec<Point>) = (
                p.vertices()
                    .iter()
                    .map(|v| Point::new(v.x * scale, v.y * scale))
                    .collect(),
                q0.vertices()
                    .iter()
                    .map(|v| Point::new((v.x + r * a.cos()) * scale, (v.y + r * a.sin()) * scale))
                    .collect(),
            );
            let Some(f) = walk::nearest_feature(Exact, &pv, &qv) else {
                continue;
            };
            total += 1;
            let exact = construct::separation(&pv, &qv, f);
            if let Some((d, closest)) = separation(&pv, &qv, f) {
                answered += 1;
                assert_eq!(Some(d), exact.distance, "case {case}: distance");
                assert_eq!(closest, exact.closest, "case {case}: closest pair");
            }
        }
        assert!(total > 2000, "{total} disjoint pairs");
        assert!(answered * 100 >= total * 95, "answered {answered} of {total}");
    }

    /// Whenever the certified depth and normal answer, they equal the exact
    /// construction's roundings; and they answer on nearly every random D-edge.
    #[test]
    fn certified_depths_and_normals_equal_the_exact_ones() {
        let mut rng = SmallRng::seed_from_u64(43);
        let (mut answered, mut total) = (0, 0);
        for case in 0..20000 {
            let scale = [1.0, 1e-30, 1e30, 3.0, 2f64.powi(-260), 2f64.powi(260)][case % 6];
            let mut pt = || {
                let (x, y): (f64, f64) = (rng.random_range(-4.0..4.0), rng.random_range(-4.0..4.0));
                // Some coordinates on the grid, so that components and depths are exactly 0.
                if case % 5 == 0 {
                    Point::new(x.round() * scale, y.round() * scale)
                } else {
                    Point::new(x * scale, y * scale)
                }
            };
            let (a, b, v) = (pt(), pt(), pt());
            if a == b {
                continue;
            }
            let of_q = case % 2 == 0;
            total += 1;
            let (squared, normal) = construct::depth_and_normal([a, b, v], of_q);
            if let Some((d, n)) = depth_and_normal([a, b, v], of_q) {
                answered += 1;
                assert_eq!(d, squared.sqrt_to_f64(), "case {case}: depth");
                assert_eq!(
                    n.map(f64::to_bits),
                    normal.map(f64::to_bits),
                    "case {case}: normal"
                );
            }
        }
        assert!(answered * 100 >= total * 60, "answered {answered} of {total}");
    }

    /// Adversarial roundings: exact squares, halfway-looking values, one-ulp gaps,
    /// values at the ends of the safe range and beyond it.
    #[test]
    fn certified_roundings_on_hard_values() {
        let pts = |v: &[[f64; 2]]| v.iter().map(|&[x, y]| Point::new(x, y)).collect::<Vec<_>>();
        let one = 1.0f64;
        let cases: Vec<(Vec<Point>, Vec<Point>)> = vec![
            (
                pts(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]),
                pts(&[[4.0, 4.0], [5.0, 4.0], [4.0, 5.0]]),
            ),
            (
                pts(&[[0.0, 0.0], [3.0, 0.0], [0.0, 3.0]]),
                pts(&[[3.0, 4.0], [9.0, 4.0], [3.0, 9.0]]),
            ),
            (
                pts(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]),
                pts(&[[one.next_up(), 0.5], [2.0, 0.0], [2.0, 1.0]]),
            ),
            (
                pts(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]),
                pts(&[[0.1, 0.9], [2.0, 2.0], [0.5, 2.0]]),
            ),
            (
                pts(&[[0.0, 0.0], [1e200, 0.0], [0.0, 1e200]]),
                pts(&[[2e200, 2e200], [3e200, 2e200], [2e200, 3e200]]),
            ),
            (
                pts(&[[0.0, 0.0], [1e-200, 0.0], [0.0, 1e-200]]),
                pts(&[[2e-200, 2e-200], [3e-200, 2e-200], [2e-200, 3e-200]]),
            ),
            (
                pts(&[[0.0, 0.0], [1e300, 0.0], [0.0, 1e300]]),
                pts(&[[2e300, 2e300], [3e300, 2e300], [2e300, 3e300]]),
            ),
            (
                pts(&[[0.0, 0.0], [1e-310, 0.0], [0.0, 1e-310]]),
                pts(&[[2e-310, 2e-310], [3e-310, 2e-310], [2e-310, 3e-310]]),
            ),
            (
                pts(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]),
                pts(&[[0.5 + 2f64.powi(-52), 0.5], [2.0, 2.0], [0.5, 2.0]]),
            ),
        ];
        for (k, (p, q)) in cases.iter().enumerate() {
            let f = walk::nearest_feature(Exact, p, q).expect("apart");
            let exact = construct::separation(p, q, f);
            if let Some((d, closest)) = separation(p, q, f) {
                assert_eq!(Some(d), exact.distance, "case {k}");
                assert_eq!(closest, exact.closest, "case {k}");
            }
        }
        // Outside the safe range nothing is answered.
        let (p, q) = &cases[6];
        let f = walk::nearest_feature(Exact, p, q).expect("apart");
        assert_eq!(separation(p, q, f), None);
    }
}
