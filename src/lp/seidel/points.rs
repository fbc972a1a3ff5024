//! The input point sets of [`separating_line`](super::separating_line) and their copy
//! into the workspace, with each point's origin.

use super::B_BIT;
use crate::kernel::Point;
use crate::polygon::LinkedPolygon;

/// A finite indexed set of points: a slice, or arena positions of a [`LinkedPolygon`].
pub trait PointSet {
    /// The number of points.
    fn len(&self) -> usize;
    /// Point `i`, for `i < len()`.
    fn point(&self, i: usize) -> Point;
    /// Whether the set has no points.
    fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// The points as one contiguous slice, when they are stored so (then the LP copies
    /// them all at once instead of reading each on first use).
    fn as_slice(&self) -> Option<&[Point]> {
        None
    }
}

impl PointSet for [Point] {
    #[inline]
    fn len(&self) -> usize {
        <[Point]>::len(self)
    }
    #[inline]
    fn point(&self, i: usize) -> Point {
        self[i]
    }
    #[inline]
    fn as_slice(&self) -> Option<&[Point]> {
        Some(self)
    }
}

impl PointSet for Vec<Point> {
    #[inline]
    fn len(&self) -> usize {
        Vec::len(self)
    }
    #[inline]
    fn point(&self, i: usize) -> Point {
        self[i]
    }
    #[inline]
    fn as_slice(&self) -> Option<&[Point]> {
        Some(self)
    }
}

impl<T: PointSet + ?Sized> PointSet for &T {
    #[inline]
    fn len(&self) -> usize {
        (**self).len()
    }
    #[inline]
    fn point(&self, i: usize) -> Point {
        (**self).point(i)
    }
    #[inline]
    fn as_slice(&self) -> Option<&[Point]> {
        (**self).as_slice()
    }
}

/// The vertices of `polygon` stored at `positions` (arena positions, `0..len`), read in
/// place: point `i` of the set is `polygon.point_at(positions[i])`.
#[derive(Clone, Copy, Debug)]
pub struct ArenaPoints<'a> {
    /// The polygon whose arena holds the points.
    pub polygon: &'a LinkedPolygon,
    /// Arena positions of the points, each below `polygon.len()`.
    pub positions: &'a [u32],
}

impl PointSet for ArenaPoints<'_> {
    #[inline]
    fn len(&self) -> usize {
        self.positions.len()
    }
    #[inline]
    fn point(&self, i: usize) -> Point {
        self.polygon.point_at(self.positions[i] as usize)
    }
}

/// A point copied into the workspace with its origin: index in A, or index in B | `B_BIT`.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Item {
    pub(super) p: Point,
    pub(super) enc: u32,
    /// Whether `p` has been read from the input yet.
    pub(super) loaded: bool,
}

/// Where [`list_items`] puts the points of A and B: A's `na` first, then B's `nb`; or,
/// for a kept order ([`LpWorkspace::keep_order`]), alternately (a₀ b₀ a₁ b₁ …, then
/// the longer set's tail), so that the LP takes them alternately without moving them
/// again.
#[derive(Clone, Copy, Debug)]
pub(super) struct Layout {
    pub(super) na: usize,
    pub(super) nb: usize,
    pub(super) interleaved: bool,
}

impl Layout {
    /// The slot of A's point `i`.
    #[inline]
    pub(super) fn a(self, i: usize) -> usize {
        if !self.interleaved {
            i
        } else {
            let m = self.na.min(self.nb);
            if i < m { 2 * i } else { m + i }
        }
    }

    /// The slot of B's point `j`.
    #[inline]
    pub(super) fn b(self, j: usize) -> usize {
        if !self.interleaved {
            self.na + j
        } else {
            let m = self.na.min(self.nb);
            if j < m { 2 * j + 1 } else { m + j }
        }
    }
}

/// Lists A and B in `items` as `lay` says. Contiguous inputs (`slices`) are copied
/// at once. Otherwise no point is read yet: each is copied into its item when the LP
/// first reaches it, so the repeated passes read contiguous memory, and an LP that
/// stops early (intersecting hulls are usually found within a few dozen points) never
/// touches the rest of the input.
pub(super) fn list_items(lay: Layout, items: &mut Vec<Item>, slices: Option<(&[Point], &[Point])>) {
    let (na, nb) = (lay.na as u32, lay.nb as u32);
    items.clear();
    items.reserve(lay.na + lay.nb);
    if let Some((a, b)) = slices {
        // Written in place (no per-item capacity check): pairs first when
        // interleaved, then A's rest, then B's rest.
        let loaded = |p, enc| Item { p, enc, loaded: true };
        items.resize(lay.na + lay.nb, Item::default());
        let m = if lay.interleaved { lay.na.min(lay.nb) } else { 0 };
        let (pairs, rest) = items.split_at_mut(2 * m);
        for ((pair, (&pa, &pb)), i) in pairs.chunks_exact_mut(2).zip(a.iter().zip(b)).zip(0..) {
            pair[0] = loaded(pa, i);
            pair[1] = loaded(pb, i | B_BIT);
        }
        let (rest_a, rest_b) = rest.split_at_mut(lay.na - m);
        for ((slot, &p), i) in rest_a.iter_mut().zip(&a[m..]).zip(m as u32..) {
            *slot = loaded(p, i);
        }
        for ((slot, &p), j) in rest_b.iter_mut().zip(&b[m..]).zip(m as u32..) {
            *slot = loaded(p, j | B_BIT);
        }
        return;
    }
    let item = |enc| Item {
        p: Point::new(0.0, 0.0),
        enc,
        loaded: false,
    };
    if lay.interleaved {
        let m = na.min(nb);
        for i in 0..m {
            items.push(item(i));
            items.push(item(i | B_BIT));
        }
        items.extend((m..na).map(item));
        items.extend((m..nb).map(|j| item(j | B_BIT)));
    } else {
        items.extend((0..na).map(item));
        items.extend((0..nb).map(|j| item(j | B_BIT)));
    }
}

/// Where the loops get an item's point.
pub(super) trait Load {
    /// Whether points are read on first use (else every item holds its point).
    const LAZY: bool;
    /// The point of `it`, read now if it has not been.
    fn load(&self, it: &mut Item) -> Point;
}

/// Items listed with their points.
pub(super) struct Loaded;

impl Load for Loaded {
    const LAZY: bool = false;
    #[inline(always)]
    fn load(&self, it: &mut Item) -> Point {
        it.p
    }
}

/// Reads items' points from the two input sets on first use.
pub(super) struct Source<'s, A: ?Sized, B: ?Sized> {
    pub(super) a: &'s A,
    pub(super) b: &'s B,
}

impl<A: PointSet + ?Sized, B: PointSet + ?Sized> Load for Source<'_, A, B> {
    const LAZY: bool = true;
    #[inline]
    fn load(&self, it: &mut Item) -> Point {
        if !it.loaded {
            it.p = if it.enc & B_BIT == 0 {
                self.a.point(it.enc as usize)
            } else {
                self.b.point((it.enc & !B_BIT) as usize)
            };
            it.loaded = true;
        }
        it.p
    }
}
