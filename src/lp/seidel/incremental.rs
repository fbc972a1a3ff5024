//! The incremental loop of [`separating_line`](super::separating_line): its
//! one-dimensional steps and the final certification of the line it finds.

use super::points::{Item, Load};
use super::workspace::{Witness, WitnessPoint};
use super::{B_BIT, Bitangent, LOOKAHEAD, Separation};
use crate::kernel::{DirectedLine, Kernel, Orientation, Point, Sign};

/// A directed line through two input points, with its direction for
/// [`Kernel::orient_line`] (the loops test many points against one line).
#[derive(Clone, Copy, Debug)]
pub(super) struct Line {
    pub(super) s: Point,
    pub(super) e: Point,
    pub(super) d: DirectedLine,
}

impl Line {
    #[inline]
    pub(super) fn new(s: Point, e: Point) -> Self {
        Line {
            s,
            e,
            d: DirectedLine::new(s, e),
        }
    }

    /// `orient(s, e, x)`. A point that defines the line gives two equal products (an
    /// exact zero), which no filter certifies: such points cost a slow path, where
    /// [`ExactWithin`](crate::ExactWithin) answers them by comparing points, and the
    /// decided calls pay no comparison.
    #[inline]
    pub(super) fn side<K: Kernel>(self, k: K, x: Point) -> Orientation {
        k.orient_line(&self.d, x)
    }
}

/// The outcome of a one-dimensional step.
pub(super) enum Step {
    /// The new optimum, tight on the violating point and on `partner`; under an exact
    /// kernel also the extremes along it of the earlier points found on it.
    Line(Line, Item, Collinear),
    /// The constraints seen so far admit no separator: the hulls intersect. No line
    /// through the violating point satisfies these one or two earlier points.
    Infeasible(Item, Item),
    /// The kernel contradicted itself (fast kernel only).
    Inconsistent,
}

/// The outcome of the incremental loop.
pub(super) enum StepOut {
    Line {
        line: Line,
        ta: u32,
        tb: u32,
        on_line: OnLine,
        last_change: usize,
    },
    /// The hulls intersect (the witness is recorded if asked for).
    Infeasible,
    Inconsistent,
}

/// The extreme points, along the current line, of each set's points found on it.
#[derive(Clone, Copy, Debug)]
pub(super) struct OnLine {
    pub(super) a_min: Point,
    pub(super) a_max: Point,
    pub(super) b_min: Point,
    pub(super) b_max: Point,
}

impl OnLine {
    pub(super) fn at(pa: Point, pb: Point) -> Self {
        OnLine {
            a_min: pa,
            a_max: pa,
            b_min: pb,
            b_max: pb,
        }
    }

    /// Adds `x`, a point on the directed line (s, e), to its set's extremes.
    #[inline]
    pub(super) fn add<K: Kernel>(&mut self, k: K, s: Point, e: Point, x: Point, in_b: bool) {
        let (min, max) = if in_b {
            (&mut self.b_min, &mut self.b_max)
        } else {
            (&mut self.a_min, &mut self.a_max)
        };
        if x == *min || x == *max {
            return; // known, and an exact zero would take the kernel's slow path
        }
        if k.dot(s, e, *min, x) == Sign::Negative {
            *min = x;
        } else if k.dot(s, e, *max, x) == Sign::Positive {
            *max = x;
        }
    }
}

/// Points of each set found on a line, by their extremes along it (`None`: none yet):
/// what [`step`] collects of the earlier points for the line it returns, so that under
/// an exact kernel they need no second test.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Collinear {
    pub(super) a: Option<(Point, Point)>,
    pub(super) b: Option<(Point, Point)>,
}

impl Collinear {
    /// Adds `x`, a point on the directed line (s, e). Out of line: points on the line
    /// are rare, and the loops that find them are the LP's hottest.
    #[cold]
    #[inline(never)]
    pub(super) fn add<K: Kernel>(&mut self, k: K, s: Point, e: Point, x: Point, in_b: bool) {
        let slot = if in_b { &mut self.b } else { &mut self.a };
        match slot {
            None => *slot = Some((x, x)),
            Some((min, max)) => {
                if x == *min || x == *max {
                    return;
                }
                if k.dot(s, e, *min, x) == Sign::Negative {
                    *min = x;
                } else if k.dot(s, e, *max, x) == Sign::Positive {
                    *max = x;
                }
            }
        }
    }

    /// Adds the extremes to `on_line` (points on the same line).
    pub(super) fn merge_into<K: Kernel>(self, k: K, on_line: &mut OnLine, s: Point, e: Point) {
        for (set, in_b) in [(self.a, false), (self.b, true)] {
            if let Some((min, max)) = set {
                on_line.add(k, s, e, min, in_b);
                on_line.add(k, s, e, max, in_b);
            }
        }
    }
}

/// Seidel's loop: `items[0]` and `items[1]` are the bounding constraints (`al` ∈ A
/// strictly x′-left of `br` ∈ B), whose optimum is `line`; the rest is in random order.
/// Returns the final line, its encoded tangent points, the index of the last point that
/// changed the line, and the on-line extremes of the points after it (each of which was
/// tested against the final line).
#[allow(clippy::too_many_arguments)]
pub(super) fn incremental<K: Kernel, S: Load, const RECORD: bool>(
    k: K,
    src: &S,
    mut line: Line,
    al: Item,
    br: Item,
    a0: Point,
    b0: Point,
    items: &mut [Item],
    work: &mut u64,
    witness: &mut Witness,
) -> StepOut {
    let (mut ta, mut tb) = ((al.enc, al.p), (br.enc, br.p));
    let mut on_line = OnLine::at(al.p, br.p);
    let mut last_change = 1;
    let mut w = 0u64;
    for t in 2..items.len() {
        // Read a point a few items ahead: its cache miss overlaps with this iteration.
        if S::LAZY
            && let Some(ahead) = items.get_mut(t + LOOKAHEAD)
        {
            src.load(ahead);
        }
        let p = src.load(&mut items[t]);
        let enc = items[t].enc;
        let in_b = enc & B_BIT != 0;
        let o = line.side(k, p);
        w += 1;
        let violated = if in_b {
            o == Orientation::Cw
        } else {
            o == Orientation::Ccw
        };
        if !violated {
            if o == Orientation::Collinear {
                on_line.add(k, line.s, line.e, p, in_b);
            }
            continue;
        }
        w += t as u64;
        let guess = if in_b { ta } else { tb };
        let guess = Item {
            p: guess.1,
            enc: guess.0,
            loaded: true,
        };
        match step(k, p, in_b, &items[..t], a0, b0, guess, &mut w) {
            Step::Line(l, partner, collinear) => {
                line = l;
                let partner_in_b = partner.enc & B_BIT != 0;
                if in_b {
                    tb = (enc, p);
                    if !partner_in_b {
                        ta = (partner.enc, partner.p);
                    }
                } else {
                    ta = (enc, p);
                    if partner_in_b {
                        tb = (partner.enc, partner.p);
                    }
                }
                on_line = OnLine::at(ta.1, tb.1);
                if K::EXACT {
                    collinear.merge_into(k, &mut on_line, line.s, line.e);
                }
                last_change = t;
            }
            Step::Infeasible(q, q2) => {
                *work += w;
                if RECORD {
                    witness.record([items[t], q, q2], [ta, tb], [a0, b0], [al, br], t + 1);
                }
                return StepOut::Infeasible;
            }
            Step::Inconsistent => {
                *work += w;
                return StepOut::Inconsistent;
            }
        }
    }
    *work += w;
    StepOut::Line {
        line,
        ta: ta.0,
        tb: tb.0,
        on_line,
        last_change,
    }
}

/// Where an earlier point q puts the slope of a line through the violating point p
/// (see [`step`]).
pub(super) enum Bound {
    /// An upper bound: the line through p and q, directed into H (`from` x′-left).
    Upper(Point, Point),
    /// A lower bound (q ∈ A x′-right of p, or q ∈ B x′-left of p).
    Lower,
    /// No bound: q and p have the same x′ and q is on its side of every such line.
    Free,
    /// q and p have the same x′ and q is on the wrong side of every such line.
    Blocked,
}

/// Classifies an earlier point `q` (≠ `p`) for the one-dimensional LP through `p`.
#[inline(always)]
pub(super) fn bound<K: Kernel>(k: K, p: Point, q: Point, q_in_b: bool, a0: Point, b0: Point) -> Bound {
    // Sign of x′(q − p); q − p = ±d₀ (p, q = a₀, b₀) is answered without the kernel.
    let sx = if (p == a0 && q == b0) || (p == b0 && q == a0) {
        Orientation::Collinear
    } else {
        k.cross(a0, b0, p, q)
    };
    // u × (q − p) must be ≥ 0 for q in B, ≤ 0 for q in A; with u = (1, s) that is
    // y′(q − p) − s·x′(q − p): upper bounds are B's points x′-right of p and A's
    // points x′-left of it.
    match sx {
        Orientation::Collinear => {
            let sy = k.dot(a0, b0, p, q);
            let ok = if q_in_b {
                sy != Sign::Negative
            } else {
                sy != Sign::Positive
            };
            if ok { Bound::Free } else { Bound::Blocked }
        }
        // x′(q − p) > 0
        Orientation::Cw if q_in_b => Bound::Upper(p, q),
        Orientation::Ccw if !q_in_b => Bound::Upper(q, p),
        _ => Bound::Lower,
    }
}

/// Whether `q` (of B if `q_in_b`) is strictly on the wrong side of the directed line
/// (`from`, `to`), and whether it is on the line.
#[inline(always)]
pub(super) fn violates<K: Kernel>(k: K, line: &DirectedLine, q: Point, q_in_b: bool) -> (bool, bool) {
    let o = k.orient_line(line, q);
    let wrong = if q_in_b { Orientation::Cw } else { Orientation::Ccw };
    (o == wrong, o == Orientation::Collinear)
}

/// The one-dimensional LP: the most counter-clockwise direction in H of a line through
/// `p` that keeps every earlier point on its side. (Inlined into each instance of the
/// incremental loop.)
///
/// The optimum is the tightest upper bound, i.e. the line through p and the earlier
/// point it first meets when turned clockwise from the previous optimum's direction.
/// Rather than classifying every earlier point (upper or lower bound: one `cross`) and
/// comparing it with the tightest bound of its kind (a second one), each point is
/// tested against the line through p and the tightest upper bound so far, one
/// `orient`, which almost every point satisfies: only a violating point is
/// classified, and it is either a tighter upper bound (the line turns) or a lower
/// bound above the tightest upper bound (infeasible). A lower bound satisfied by an
/// earlier, steeper line may violate the final one, so the points before the last
/// turn are tested once more against the final line. `guess`, the previous optimum's
/// tangent point in the other set than p's, is usually the final bound or close to
/// it, so that pass is short. Adds the points tested again to `work`. Among points on
/// the final line, one of the other set than p is preferred as the partner (the
/// tangent points must be one of each set).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(super) fn step<K: Kernel>(
    k: K,
    p: Point,
    p_in_b: bool,
    earlier: &[Item],
    a0: Point,
    b0: Point,
    guess: Item,
    work: &mut u64,
) -> Step {
    // The tightest upper bound so far: its line and the point; plain locals
    // keep the hot loop free of memory traffic.
    let mut best: Option<(DirectedLine, Item)> = None;
    let g_in_b = guess.enc & B_BIT != 0;
    if guess.p != p
        && let Bound::Upper(from, to) = bound(k, p, guess.p, g_in_b, a0, b0)
    {
        best = Some((DirectedLine::new(from, to), guess));
    }
    // A point of the other set than the bound's on the current line, if any.
    let mut partner: Option<Item> = None;
    // Under an exact kernel, the points on the current line (for `certify`).
    let mut collinear = Collinear::default();
    // The points before this index were tested against an older line, or none.
    let mut recheck = 0;
    for (i, it) in earlier.iter().enumerate() {
        let q = it.p;
        let q_in_b = it.enc & B_BIT != 0;
        let opposite = q_in_b != p_in_b;
        if let Some((line, b)) = best {
            if it.enc == b.enc {
                continue; // the bound itself: on its line, and an exact zero is slow
            }
            // The line passes through p: a copy of p is on it, not a violator, and
            // is compared with p only there (the decided calls pay no comparison).
            let (wrong, on) = violates(k, &line, q, q_in_b);
            if !wrong {
                if on {
                    if K::EXACT {
                        collinear.add(k, line.from(), line.to(), q, q_in_b);
                    }
                    if q == p {
                        if opposite {
                            return Step::Infeasible(*it, *it); // a point of both sets
                        }
                    } else if opposite && partner.is_none() && (b.enc & B_BIT != 0) == p_in_b {
                        partner = Some(*it);
                    }
                }
                continue;
            }
        } else if q == p {
            if opposite {
                return Step::Infeasible(*it, *it); // a point of both sets
            }
            continue;
        }
        match bound(k, p, q, q_in_b, a0, b0) {
            Bound::Upper(from, to) => {
                best = Some((DirectedLine::new(from, to), *it));
                partner = None;
                collinear = Collinear::default();
                recheck = i;
            }
            Bound::Lower => {
                if let Some((_, b)) = best {
                    // Its slope exceeds the tightest upper bound's.
                    return Step::Infeasible(b, *it);
                }
                // Before any upper bound: tested in the second pass.
            }
            // Only an inconsistent kernel gets here with a bound violated.
            Bound::Free => {}
            Bound::Blocked => return Step::Infeasible(*it, *it),
        }
    }
    let Some((line, b)) = best else {
        // The bounding constraints always give an upper bound; only an inconsistent
        // kernel loses it.
        return Step::Inconsistent;
    };
    let b_opposite = (b.enc & B_BIT != 0) != p_in_b;
    *work += recheck as u64;
    for it in &earlier[..recheck] {
        let q = it.p;
        let q_in_b = it.enc & B_BIT != 0;
        if it.enc == b.enc {
            continue; // the bound
        }
        // A copy of p is on the line (of p's set: one of the other set returned
        // above), so it neither violates nor becomes the partner.
        let (wrong, on) = violates(k, &line, q, q_in_b);
        if !wrong {
            if on {
                if K::EXACT {
                    collinear.add(k, line.from(), line.to(), q, q_in_b);
                }
                if !b_opposite && partner.is_none() && q_in_b != p_in_b {
                    partner = Some(*it);
                }
            }
            continue;
        }
        return match bound(k, p, q, q_in_b, a0, b0) {
            Bound::Lower => Step::Infeasible(b, *it),
            Bound::Blocked => Step::Infeasible(*it, *it),
            // A tighter upper bound than the tightest: an inconsistent kernel.
            Bound::Upper(..) | Bound::Free => Step::Inconsistent,
        };
    }
    let partner = if b_opposite { b } else { partner.unwrap_or(b) };
    if K::EXACT {
        // The bound's own point, on its line, was skipped by the tests.
        collinear.add(k, line.from(), line.to(), b.p, b.enc & B_BIT != 0);
    }
    Step::Line(
        Line {
            s: line.from(),
            e: line.to(),
            d: line,
        },
        partner,
        collinear,
    )
}

/// Checks `items` against the line (the points not yet tested against it), adds those
/// on it to `on_line`, and compares the parts of the two sets on the line; overlapping
/// parts are the witness of intersecting hulls.
#[allow(clippy::too_many_arguments)]
pub(super) fn certify<K: Kernel, const RECORD: bool>(
    k: K,
    line: Line,
    ta: u32,
    tb: u32,
    mut on_line: OnLine,
    items: &[Item],
    work: &mut u64,
    witness: &mut Witness,
) -> Option<Separation> {
    let Line { s, e, d } = line;
    // The tangent points are on the line (this fails only under an inconsistent kernel).
    if k.orient(s, e, on_line.a_min) != Orientation::Collinear
        || k.orient(s, e, on_line.b_min) != Orientation::Collinear
    {
        return None;
    }
    for &Item { p: x, enc, .. } in items {
        let in_b = enc & B_BIT != 0;
        match (k.orient_line(&d, x), in_b) {
            (Orientation::Ccw, false) | (Orientation::Cw, true) => return None,
            (Orientation::Collinear, _) => on_line.add(k, s, e, x, in_b),
            _ => {}
        }
    }
    *work += items.len() as u64;
    let OnLine {
        a_min,
        a_max,
        b_min,
        b_max,
    } = on_line;
    let overlap = k.dot(s, e, a_min, b_max) != Sign::Negative && k.dot(s, e, b_min, a_max) != Sign::Negative;
    Some(if overlap {
        if RECORD {
            let on = |point, in_b| WitnessPoint {
                point,
                in_b,
                index: None,
            };
            witness.set(
                &[
                    on(a_min, false),
                    on(a_max, false),
                    on(b_min, true),
                    on(b_max, true),
                ],
                0,
            );
        }
        Separation::Intersecting
    } else {
        Separation::Separated(Bitangent {
            start: s,
            end: e,
            a: ta as usize,
            b: (tb & !B_BIT) as usize,
        })
    })
}
