//! The status of [`TreeSweep`](super::TreeSweep): a sequence of edges of two colours
//! (P's and Q's) kept in a treap with implicit keys (positions), so that a range of
//! positions can be cut out and put back in O(log n) expected time.
//!
//! Every node stores, for its subtree, the last node of each colour. That is what
//! lets a search run along the edges of one colour only, although the
//! two colours are interleaved: the sequence restricted to one colour is sorted
//! (the edges of one simple polygon never cross), so a predicate that is monotone
//! along that colour can be binary-searched by testing, at each node, the last node
//! of that colour in its left subtree.
//!
//! The structure knows topology only: the caller passes the predicates. Nodes are
//! edge ids (P's edges first, then Q's); the colour of an id is whether it is below
//! the number of P's edges. Priorities come from a fixed-seed xorshift, so runs are
//! reproducible.

pub(crate) const NIL: u32 = u32::MAX;

#[derive(Clone, Copy, Debug)]
struct Node {
    left: u32,
    right: u32,
    prio: u32,
    size: u32,
    /// The last node of each colour in the subtree (NIL when none).
    last: [u32; 2],
}

const EMPTY: Node = Node {
    left: NIL,
    right: NIL,
    prio: 0,
    size: 0,
    last: [NIL; 2],
};

/// The sequence; see the [module docs](self).
#[derive(Clone, Debug, Default)]
pub(crate) struct Status {
    nodes: Vec<Node>,
    /// Ids below this are colour 0 (P), the others colour 1 (Q).
    split_color: u32,
    root: u32,
    /// The part after a [`Status::cut`], until [`Status::paste`].
    rest: u32,
    seed: u32,
}

impl Status {
    /// Empties the sequence and makes room for ids below `ids`, the first `reds` of
    /// them of colour 0.
    pub(crate) fn reset(&mut self, ids: usize, reds: usize) {
        self.nodes.clear();
        self.nodes.resize(ids, EMPTY);
        self.split_color = reds as u32;
        self.root = NIL;
        self.rest = NIL;
        self.seed = 0x9e37_79b9;
    }

    #[inline]
    pub(crate) fn color(&self, id: u32) -> usize {
        (id >= self.split_color) as usize
    }

    #[inline]
    pub(crate) fn len(&self) -> usize {
        self.size(self.root) as usize
    }

    #[inline]
    fn size(&self, t: u32) -> u32 {
        if t == NIL { 0 } else { self.nodes[t as usize].size }
    }

    #[inline]
    fn last(&self, t: u32, c: usize) -> u32 {
        if t == NIL {
            NIL
        } else {
            self.nodes[t as usize].last[c]
        }
    }

    /// Recomputes the size and the last node of each colour of `t` from its children.
    #[inline]
    fn pull(&mut self, t: u32) {
        let Node { left, right, .. } = self.nodes[t as usize];
        let (l, r) = (self.node(left), self.node(right));
        let mut last = r.last;
        let mine = self.color(t);
        if last[mine] == NIL {
            last[mine] = t;
        }
        let other = 1 - mine;
        if last[other] == NIL {
            last[other] = l.last[other];
        }
        let n = &mut self.nodes[t as usize];
        n.size = 1 + l.size + r.size;
        n.last = last;
    }

    /// The node `t`, or an empty one for NIL.
    #[inline]
    fn node(&self, t: u32) -> Node {
        if t == NIL { EMPTY } else { self.nodes[t as usize] }
    }

    /// A fresh single-node tree for `id`.
    fn single(&mut self, id: u32) -> u32 {
        // xorshift32
        let mut x = self.seed;
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        self.seed = x;
        self.nodes[id as usize] = Node {
            left: NIL,
            right: NIL,
            prio: x,
            size: 0,
            last: [NIL; 2],
        };
        self.pull(id);
        id
    }

    fn merge(&mut self, a: u32, b: u32) -> u32 {
        if a == NIL {
            return b;
        }
        if b == NIL {
            return a;
        }
        if self.nodes[a as usize].prio > self.nodes[b as usize].prio {
            let r = self.nodes[a as usize].right;
            let m = self.merge(r, b);
            self.nodes[a as usize].right = m;
            self.pull(a);
            a
        } else {
            let l = self.nodes[b as usize].left;
            let m = self.merge(a, l);
            self.nodes[b as usize].left = m;
            self.pull(b);
            b
        }
    }

    /// Splits `t` into its first `k` nodes and the rest.
    fn split(&mut self, t: u32, k: u32) -> (u32, u32) {
        if t == NIL {
            return (NIL, NIL);
        }
        let Node { left, right, .. } = self.nodes[t as usize];
        let ls = self.size(left);
        if k <= ls {
            let (a, b) = self.split(left, k);
            self.nodes[t as usize].left = b;
            self.pull(t);
            (a, t)
        } else {
            let (a, b) = self.split(right, k - ls - 1);
            self.nodes[t as usize].right = a;
            self.pull(t);
            (t, b)
        }
    }

    fn collect(&self, t: u32, out: &mut Vec<u32>) {
        if t == NIL {
            return;
        }
        let Node { left, right, .. } = self.nodes[t as usize];
        self.collect(left, out);
        out.push(t);
        self.collect(right, out);
    }

    /// Cuts out the positions `lo..hi`, appending their ids in order to `out`; the
    /// sequence is incomplete until [`Status::paste`] puts a stretch back there.
    pub(crate) fn cut(&mut self, lo: usize, hi: usize, out: &mut Vec<u32>) {
        let (a, bc) = self.split(self.root, lo as u32);
        let (b, c) = if hi > lo {
            self.split(bc, (hi - lo) as u32)
        } else {
            (NIL, bc)
        };
        self.collect(b, out);
        self.root = a;
        self.rest = c;
    }

    /// Puts `ids` (not in the sequence) where the last [`Status::cut`] took its stretch.
    pub(crate) fn paste(&mut self, ids: &[u32]) {
        let mut b = NIL;
        for &id in ids {
            let s = self.single(id);
            b = self.merge(b, s);
        }
        let ab = self.merge(self.root, b);
        let rest = std::mem::replace(&mut self.rest, NIL);
        self.root = self.merge(ab, rest);
    }

    /// The first node of colour `c` for which `pred` holds, and its position, where
    /// `pred` is false then true along the nodes of colour `c`; `None` when it holds
    /// for none of them. `pred` is called O(log n) times (expected).
    pub(crate) fn first_where(&self, c: usize, mut pred: impl FnMut(u32) -> bool) -> Option<(u32, usize)> {
        let mut t = self.root;
        let mut base = 0usize;
        while t != NIL {
            let Node { left, right, .. } = self.nodes[t as usize];
            let lc = self.last(left, c);
            if lc != NIL && pred(lc) {
                t = left;
                continue;
            }
            let at = base + self.size(left) as usize;
            if self.color(t) == c && pred(t) {
                return Some((t, at));
            }
            base = at + 1;
            t = right;
        }
        None
    }

    /// The position of the last node of colour `c` before position `r`, if any.
    pub(crate) fn last_before(&self, c: usize, r: usize) -> Option<usize> {
        // Descend by position, remembering the best candidate: a node of colour c, or
        // a left subtree holding one, entirely before r.
        let mut t = self.root;
        let mut base = 0usize;
        let mut best: Option<(u32, usize, bool)> = None; // (node or subtree, base, is_subtree)
        while t != NIL {
            let Node { left, right, .. } = self.nodes[t as usize];
            let at = base + self.size(left) as usize;
            if at < r {
                if self.color(t) == c {
                    best = Some((t, at, false));
                } else if self.last(left, c) != NIL {
                    best = Some((left, base, true));
                }
                base = at + 1;
                t = right;
            } else {
                t = left;
            }
        }
        let (mut s, mut base, subtree) = best?;
        if !subtree {
            return Some(base);
        }
        // The last node of colour c inside subtree s, whose first position is `base`.
        loop {
            let Node { left, right, .. } = self.nodes[s as usize];
            if self.last(right, c) != NIL {
                base += self.size(left) as usize + 1;
                s = right;
            } else if self.color(s) == c {
                return Some(base + self.size(left) as usize);
            } else {
                s = left;
            }
        }
    }

    /// Every id in order (tests and debugging).
    #[cfg(test)]
    pub(crate) fn ids(&self) -> Vec<u32> {
        let mut out = Vec::new();
        self.collect(self.root, &mut out);
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::rngs::SmallRng;
    use rand::{Rng, SeedableRng};

    /// Random puts and takes against a plain vector; searches against linear scans.
    #[test]
    fn matches_a_vector() {
        let mut rng = SmallRng::seed_from_u64(5);
        for round in 0..200 {
            let ids = rng.random_range(1..60usize);
            let reds = rng.random_range(0..=ids);
            let mut s = Status::default();
            s.reset(ids, reds);
            let mut v: Vec<u32> = Vec::new();
            let mut free: Vec<u32> = (0..ids as u32).collect();
            for _ in 0..200 {
                if !free.is_empty() && rng.random_bool(0.6) {
                    let k = rng.random_range(1..=free.len().min(4));
                    let put: Vec<u32> = (0..k)
                        .map(|_| free.swap_remove(rng.random_range(0..free.len())))
                        .collect();
                    let at = rng.random_range(0..=v.len());
                    let mut none = Vec::new();
                    s.cut(at, at, &mut none);
                    assert!(none.is_empty());
                    s.paste(&put);
                    v.splice(at..at, put);
                } else if !v.is_empty() {
                    let lo = rng.random_range(0..v.len());
                    let hi = rng.random_range(lo..=v.len());
                    let mut got = Vec::new();
                    s.cut(lo, hi, &mut got);
                    s.paste(&[]);
                    let want: Vec<u32> = v.drain(lo..hi).collect();
                    assert_eq!(got, want);
                    free.extend(want);
                }
                assert_eq!(s.ids(), v, "round {round}");
                assert_eq!(s.len(), v.len());
                for c in 0..2 {
                    // A monotone predicate along colour c: true from the t-th node of colour c.
                    let of_c: Vec<usize> = (0..v.len()).filter(|&i| s.color(v[i]) == c).collect();
                    let t = rng.random_range(0..=of_c.len());
                    let from: Vec<u32> = of_c[t..].iter().map(|&i| v[i]).collect();
                    let got = s.first_where(c, |id| from.contains(&id));
                    assert_eq!(got, of_c.get(t).map(|&i| (v[i], i)));
                    let r = rng.random_range(0..=v.len());
                    assert_eq!(s.last_before(c, r), of_c.iter().copied().rfind(|&i| i < r));
                }
            }
        }
    }
}
