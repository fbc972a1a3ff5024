//! Adversarial pairs of simple polygons for the crossings algorithms: the inputs on
//! which a sweep with unordered lists of pierced edges degrades to O(n·m), and the
//! degenerate configurations (vertical edges, many events on one vertical line,
//! edges on lines through one point, collinear overlaps) on which a sweep's ordering
//! predicates are tested hardest.
//!
//! | [`HardFamily`] | P and Q | points reported |
//! |---|---|---|
//! | `zigzag` | two zigzag chains whose every edge spans x ∈ [0, 1], Q shifted up by a random fraction of a tooth; P closed on the left, Q on the right | about n, every one a proper crossing |
//! | `stacked-zigzag` | the same P, and Q = P moved above P's top: same x-range, no contact | none |
//! | `needles` | two combs of long needles (1 long and rising by ½, period 10⁻⁶, so that every needle's x- and y-range overlaps every other's), Q = P shifted by less than 10⁻⁶ in x and y | about n, proper crossings at angles near 10⁻⁶ |
//! | `vertical` | a skyline on integer x standing on y = 0 and one hanging from y = H, random integer heights, Q shifted by 0, ½ or 1 | crossings, touchings and overlaps on shared vertical lines |
//! | `fan` | two crenellated stars whose radial edges lie on lines through the origin along the same primitive integer directions, at radii 2–5 and a random other pair | overlap ends and touchings on every ray |
//! | `collinear` | two square waves on y ∈ {0, 1}, Q shifted by ¼, ½, 1 or 2 | overlap ends, touchings and shared vertices |
//!
//! `n` is the number of vertices of each polygon, approximately: the families round it
//! to their period (3 per needle, 4 per square-wave tooth, 2 per ray or skyline step)
//! and cleaning may drop a straight vertex. The RNG chooses the free parameters
//! (offsets, heights, radii), so a seed reproduces a pair; every pair is validated.

use crate::kernel::Point;
use crate::polygon::SimplePolygon;
use rand::Rng;
use std::fmt;
use std::str::FromStr;

/// An adversarial family of simple-polygon pairs; see the [module docs](self).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum HardFamily {
    /// Two zigzag chains crossing about n times (`zigzag`).
    Zigzag,
    /// The same chains stacked apart: overlapping x-ranges, no contact (`stacked-zigzag`).
    StackedZigzag,
    /// Two combs of long needles crossing at tiny angles (`needles`).
    Needles,
    /// Two skylines sharing vertical lines (`vertical`).
    Vertical,
    /// Two crenellated stars with radial edges on shared rays (`fan`).
    Fan,
    /// Two square waves with collinear overlaps (`collinear`).
    Collinear,
}

impl HardFamily {
    /// Every family, in the order tables list them.
    pub const ALL: &'static [HardFamily] = &[
        HardFamily::Zigzag,
        HardFamily::StackedZigzag,
        HardFamily::Needles,
        HardFamily::Vertical,
        HardFamily::Fan,
        HardFamily::Collinear,
    ];

    /// The family's name in the CLI and the module docs' table.
    pub fn name(self) -> &'static str {
        match self {
            HardFamily::Zigzag => "zigzag",
            HardFamily::StackedZigzag => "stacked-zigzag",
            HardFamily::Needles => "needles",
            HardFamily::Vertical => "vertical",
            HardFamily::Fan => "fan",
            HardFamily::Collinear => "collinear",
        }
    }
}

impl fmt::Display for HardFamily {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for HardFamily {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        HardFamily::ALL
            .iter()
            .copied()
            .find(|f| f.name() == s)
            .ok_or_else(|| {
                let names: Vec<&str> = HardFamily::ALL.iter().map(|f| f.name()).collect();
                format!("unknown family '{s}' (valid: {})", names.join(", "))
            })
    }
}

/// The period of the needle combs (the distance between neighbouring teeth).
pub const NEEDLE_PERIOD: f64 = 1e-6;

/// A pair of `family` with about `n` vertices per polygon (at least the family's
/// minimum: a few teeth or rays).
///
/// # Panics
/// Never for the families' own parameters; a construction that failed validation
/// would be a bug in this module (the tests build every family at many sizes).
///
/// ```
/// use polysect::crossings::{Crossings, Sweep};
/// use polysect::generate::hard::{hard_pair, HardFamily};
/// use rand::SeedableRng;
/// let mut rng = rand::rngs::SmallRng::seed_from_u64(1);
/// let (p, q) = hard_pair(HardFamily::StackedZigzag, 1000, &mut rng);
/// assert_eq!(p.len(), 1000);
/// assert!(Sweep.crossings(&p, &q).is_empty());
/// ```
pub fn hard_pair<R: Rng + ?Sized>(
    family: HardFamily,
    n: usize,
    rng: &mut R,
) -> (SimplePolygon, SimplePolygon) {
    let (p, q) = match family {
        HardFamily::Zigzag => {
            let k = n.max(6) - 2;
            let h = rng.random_range(0.5..2.0);
            let f = rng.random_range(0.2..0.8);
            (zigzag(k, h, 0.0, false), zigzag(k, h, f * h, true))
        }
        HardFamily::StackedZigzag => {
            let k = n.max(6) - 2;
            let h = rng.random_range(0.5..2.0);
            let lift = (k as f64 + rng.random_range(0.5..4.0)) * h;
            (zigzag(k, h, 0.0, false), zigzag(k, h, lift, false))
        }
        HardFamily::Needles => {
            let teeth = (n.max(8) - 2) / 3;
            let tip = rng.random_range(0.3..0.6);
            let back = rng.random_range(0.7..0.9);
            let p = comb(teeth, tip, back);
            let (dx, dy) = (
                rng.random_range(0.1..0.9) * NEEDLE_PERIOD,
                rng.random_range(0.1..0.9) * NEEDLE_PERIOD,
            );
            let q = p.iter().map(|v| Point::new(v.x + dx, v.y + dy)).collect();
            (p, q)
        }
        HardFamily::Vertical => {
            let steps = (n.max(6) - 2) / 2;
            let height = rng.random_range(3..9u32);
            let shift = [0.0, 0.5, 1.0][rng.random_range(0..3)];
            let heights = |rng: &mut R| -> Vec<f64> {
                (0..steps).map(|_| rng.random_range(1..height) as f64).collect()
            };
            let (a, b) = (heights(rng), heights(rng));
            (
                skyline(&a, 0.0, 0.0, false),
                skyline(&b, shift, height as f64, true),
            )
        }
        HardFamily::Fan => {
            let rays = (n.max(8) / 2) & !1;
            let dirs = directions(rays);
            let (lo, hi) = [(1.0, 4.0), (3.0, 6.0), (5.0, 7.0), (2.0, 5.0)][rng.random_range(0..4)];
            let phase = rng.random_range(0..2);
            (
                crenellation(&dirs, 2.0, 5.0, 0),
                crenellation(&dirs, lo, hi, phase),
            )
        }
        HardFamily::Collinear => {
            let teeth = (n.max(10) - 2) / 4;
            let shift = [0.25, 0.5, 1.0, 2.0][rng.random_range(0..4)];
            (square_wave(teeth, 0.0), square_wave(teeth, shift))
        }
    };
    let make = |v: Vec<Point>| {
        SimplePolygon::new(v).unwrap_or_else(|e| panic!("{family} generator built an invalid polygon: {e}"))
    };
    (make(p), make(q))
}

/// A zigzag chain of `k` vertices (i mod 2, y0 + i·h) closed by three edges on the
/// left (x = −1) or on the right (x = 2).
fn zigzag(k: usize, h: f64, y0: f64, right: bool) -> Vec<Point> {
    let mut v: Vec<Point> = (0..k)
        .map(|i| Point::new((i % 2) as f64, y0 + i as f64 * h))
        .collect();
    let (top, side) = (v[k - 1].y, if right { 2.0 } else { -1.0 });
    v.push(Point::new(side, top));
    v.push(Point::new(side, y0));
    v
}

/// How far a needle rises over its length of 1.
const NEEDLE_RISE: f64 = 0.5;

/// A comb of `teeth` needles with period d = [`NEEDLE_PERIOD`] on the spine x = 0:
/// tooth j runs from (0, j·d) to its tip (1, (j + tip)·d + [`NEEDLE_RISE`]) and back
/// to (0, (j + back)·d); the comb is closed behind its spine, at x = −1.
fn comb(teeth: usize, tip: f64, back: f64) -> Vec<Point> {
    let d = NEEDLE_PERIOD;
    let mut v = Vec::with_capacity(3 * teeth + 2);
    for j in 0..teeth {
        let j = j as f64;
        v.push(Point::new(0.0, j * d));
        v.push(Point::new(1.0, (j + tip) * d + NEEDLE_RISE));
        v.push(Point::new(0.0, (j + back) * d));
    }
    let top = v[v.len() - 1].y;
    v.push(Point::new(-1.0, top));
    v.push(Point::new(-1.0, 0.0));
    v
}

/// A skyline: step i spans x ∈ [i + shift, i + 1 + shift] at height `heights[i]`,
/// standing on y = `base` (or hanging from it, `hanging`, with the steps measured
/// downwards).
fn skyline(heights: &[f64], shift: f64, base: f64, hanging: bool) -> Vec<Point> {
    let y = |h: f64| if hanging { base - h } else { base + h };
    let mut v = vec![Point::new(shift, base)];
    for (i, &h) in heights.iter().enumerate() {
        let x = i as f64 + shift;
        v.push(Point::new(x, y(h)));
        v.push(Point::new(x + 1.0, y(h)));
    }
    v.push(Point::new(heights.len() as f64 + shift, base));
    v
}

/// `count` distinct primitive integer directions sorted by angle over the full circle,
/// spread so that every angular gap is below π.
fn directions(count: usize) -> Vec<(i64, i64)> {
    let count = count.max(4);
    // All primitive vectors with max(|a|, |b|) ≤ m: 8m of them on the square of radius m
    // alone, so m = count / 8 + 1 gives enough.
    let m = (count / 8 + 1) as i64;
    let gcd = |mut a: i64, mut b: i64| {
        (a, b) = (a.abs(), b.abs());
        while b != 0 {
            (a, b) = (b, a % b);
        }
        a
    };
    let mut all: Vec<(i64, i64)> = (-m..=m)
        .flat_map(|a| (-m..=m).map(move |b| (a, b)))
        .filter(|&(a, b)| (a, b) != (0, 0) && gcd(a, b) == 1)
        .collect();
    all.sort_by(|&(a1, b1), &(a2, b2)| {
        (b1 as f64)
            .atan2(a1 as f64)
            .partial_cmp(&(b2 as f64).atan2(a2 as f64))
            .expect("finite angles")
    });
    // Take `count` of them at even steps through the sorted list.
    (0..count).map(|i| all[i * all.len() / count]).collect()
}

/// A crenellated star: along each direction a radial edge from `lo`·d to `hi`·d,
/// alternately outwards and inwards (starting inwards on even rays when `phase` is 1),
/// joined by chords between neighbouring rays.
fn crenellation(dirs: &[(i64, i64)], lo: f64, hi: f64, phase: usize) -> Vec<Point> {
    let mut v = Vec::with_capacity(2 * dirs.len());
    for (i, &(a, b)) in dirs.iter().enumerate() {
        let at = |r: f64| Point::new(r * a as f64, r * b as f64);
        if (i + phase).is_multiple_of(2) {
            v.extend([at(lo), at(hi)]);
        } else {
            v.extend([at(hi), at(lo)]);
        }
    }
    v
}

/// A square wave of `teeth` unit teeth on y ∈ [0, 1] with period 2, starting at x =
/// `shift`, closed below by y = −1.
fn square_wave(teeth: usize, shift: f64) -> Vec<Point> {
    let mut v = Vec::with_capacity(4 * teeth + 3);
    for i in 0..teeth {
        let x = 2.0 * i as f64 + shift;
        v.extend([
            Point::new(x, 0.0),
            Point::new(x, 1.0),
            Point::new(x + 1.0, 1.0),
            Point::new(x + 1.0, 0.0),
        ]);
    }
    let end = 2.0 * teeth as f64 + shift;
    v.extend([
        Point::new(end, 0.0),
        Point::new(end, -1.0),
        Point::new(shift, -1.0),
    ]);
    v
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;
    use rand::rngs::SmallRng;

    #[test]
    fn every_family_builds_valid_pairs_at_many_sizes() {
        let mut rng = SmallRng::seed_from_u64(0x4a4d);
        for &family in HardFamily::ALL {
            for n in [3, 8, 9, 10, 17, 64, 100, 513, 2000] {
                for _ in 0..4 {
                    let (p, q) = hard_pair(family, n, &mut rng);
                    assert!(p.debug_validate().is_ok() && q.debug_validate().is_ok());
                    if n >= 64 {
                        // Equal neighbouring skyline heights leave straight vertices out.
                        let least = if family == HardFamily::Vertical { 0.25 } else { 0.6 };
                        let size = p.len().max(q.len()) as f64;
                        assert!(
                            size > least * n as f64 && size < 1.1 * n as f64 + 4.0,
                            "{family} {n}: {size}"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn names_round_trip() {
        for &f in HardFamily::ALL {
            assert_eq!(f.name().parse::<HardFamily>(), Ok(f));
        }
        assert!("spiral".parse::<HardFamily>().unwrap_err().contains("needles"));
    }

    #[test]
    fn directions_are_distinct_and_sorted() {
        for count in [4, 8, 30, 100, 1000] {
            let d = directions(count);
            assert_eq!(d.len(), count);
            let mut s = d.clone();
            s.dedup();
            assert_eq!(s.len(), count);
        }
    }
}
