use super::{CrossingOptions, Crossings, edge_pair_points, sort_dedup};
use crate::kernel::{Kernel, Point};
use crate::polygon::SimplePolygon;

/// [`Brute`]: every edge of P against every edge of Q, the reference for [`Sweep`](super::Sweep).
///
/// # Complexity
/// Exactly n·m pair tests for polygons of n and m vertices (each a bounding-box
/// rejection and, when the boxes meet, [`segment_contact`](crate::kernel::segment_contact)),
/// then O(c log c) to sort the c reported points. Memory O(c).
///
/// # Degeneracies and precision
/// As for the [module](super): touchings and overlap ends are input vertices,
/// crossings are constructed by [`crossing_point`](super::crossing_point).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Brute;

impl Crossings for Brute {
    const NAME: &'static str = "brute";

    fn crossings_with_options<K: Kernel>(
        &self,
        k: K,
        p: &SimplePolygon,
        q: &SimplePolygon,
        options: CrossingOptions,
    ) -> Vec<Point> {
        let mut out = Vec::new();
        for i in 0..p.len() {
            let (p1, p2) = p.edge(i);
            for j in 0..q.len() {
                let (q1, q2) = q.edge(j);
                edge_pair_points(k, p1, p2, q1, q2, options, &mut out);
            }
        }
        sort_dedup(&mut out);
        out
    }
}
