use super::engine::*;
use super::*;
use crate::Point;
use crate::intersect::{Iterations, Linear, brute_force};
use crate::kernel::Orientation::Cw;
use crate::kernel::Sign;
use crate::{Exact, Fast};

fn poly(pts: &[[f64; 2]]) -> ConvexPolygon {
    ConvexPolygon::new(pts.iter().copied()).unwrap()
}

/// The slope formula against an explicit projective map in floating point.
#[test]
fn slope_comparison_matches_the_explicit_frame() {
    let a = Point::new(0.0, 0.0);
    let (ql, qr) = (Point::new(3.0, -1.0), Point::new(1.0, 3.0));
    let c = Point::new(qr.x - ql.x, qr.y - ql.y);
    let nvec = Point::new(c.y, -c.x); // c × n = −|c|² < 0
    let dcn = c.x * nvec.y - c.y * nvec.x;
    let tau = |z: Point| {
        let (u, v) = (z.x - a.x, z.y - a.y);
        let s = (u * nvec.y - v * nvec.x) / dcn;
        let t = (c.x * v - c.y * u) / dcn;
        assert!(t > 0.0, "{z:?} not in the frame's half plane");
        (s / t, -1.0 / t)
    };
    let fr = Frame { k: Exact, a, ql, qr };
    let pts = [
        Point::new(2.0, 0.5),
        Point::new(2.5, 1.5),
        Point::new(1.0, 2.0),
        Point::new(3.0, 0.0),
        Point::new(1.5, 1.0),
        Point::new(4.0, 2.0),
    ];
    for &u1 in &pts {
        for &u2 in &pts {
            for &v1 in &pts {
                for &v2 in &pts {
                    if !fr.before(u1, u2) || !fr.before(v1, v2) {
                        continue;
                    }
                    let slope = |p: Point, q: Point| {
                        let (tp, tq) = (tau(p), tau(q));
                        (tq.1 - tp.1) / (tq.0 - tp.0)
                    };
                    let (su, sv) = (slope(u1, u2), slope(v1, v2));
                    if (su - sv).abs() < 1e-9 {
                        continue;
                    }
                    assert_eq!(fr.slope_cmp((u1, u2), (v1, v2)), Sign::of(su - sv));
                }
            }
        }
    }
    // x grows counter-clockwise, y away from A.
    assert!(tau(Point::new(3.0, 0.0)).0 < tau(Point::new(1.0, 2.0)).0);
    assert!(tau(Point::new(1.0, 1.0)).1 < tau(Point::new(2.0, 2.0)).1);
}

#[test]
fn pencil_finds_the_tangent_points() {
    let sq = poly(&[[0., 0.], [1., 0.], [1., 1.], [0., 1.]]);
    // Below the bottom edge: only edge 0 visible.
    assert_eq!(pencil(Exact, sq.vertices(), Point::new(0.5, -1.0)), Some((0, 0)));
    // Beyond the corner (1, 1): edges 1 and 2 visible.
    assert_eq!(pencil(Exact, sq.vertices(), Point::new(2.0, 2.0)), Some((1, 2)));
    // On the extension of the bottom edge: edge 0 is collinear, not visible.
    assert_eq!(pencil(Exact, sq.vertices(), Point::new(-1.0, 0.0)), Some((3, 3)));
    // Inside and on the boundary.
    assert_eq!(pencil(Exact, sq.vertices(), Point::new(0.5, 0.5)), None);
    assert_eq!(pencil(Exact, sq.vertices(), Point::new(1.0, 0.5)), None);
    assert_eq!(pencil(Exact, sq.vertices(), Point::new(0.0, 0.0)), None);
    // Every start vertex, every outside point on a grid: the block is exactly the visible edges.
    for start in 0..4 {
        let r = sq.starting_at(start);
        let v = r.vertices();
        for x in -4..=8 {
            for y in -4..=8 {
                let a = Point::new(x as f64 * 0.25, y as f64 * 0.25);
                let vis: Vec<bool> = (0..4)
                    .map(|i| Exact.orient(v[i], v[(i + 1) % 4], a) == Cw)
                    .collect();
                match pencil(Exact, v, a) {
                    None => assert!(vis.iter().all(|b| !b), "{a:?}"),
                    Some((s, t)) => {
                        let mut i = s;
                        loop {
                            assert!(vis[i], "{a:?} start {start}");
                            if i == t {
                                break;
                            }
                            i = (i + 1) % 4;
                        }
                        let count = vis.iter().filter(|b| **b).count();
                        assert_eq!((t + 4 - s) % 4 + 1, count, "{a:?}");
                    }
                }
            }
        }
    }
}

#[test]
fn hand_cases_and_degenerate_pencils() {
    let sq = poly(&[[0., 0.], [2., 0.], [2., 2.], [0., 2.]]);
    let cases: &[(&[[f64; 2]], bool)] = &[
        (&[[1., 1.], [1.5, 1.], [1., 1.5]], true),             // contained
        (&[[-1., -1.], [3., -1.], [3., 3.], [-1., 3.]], true), // contains
        (&[[2., 2.], [3., 2.], [3., 3.]], true),               // shared vertex
        (&[[2., 0.5], [3., 0.], [3., 1.]], true),              // vertex on edge
        (&[[2., 0.], [3., 0.], [3., 2.], [2., 2.]], true),     // shared edge
        (&[[2., 1.], [3., 1.], [3., 3.], [2., 3.]], true),     // overlapping edges
        (&[[2.5, 0.], [3., 0.], [3., 2.]], false),
        (&[[3., 3.], [4., 3.], [4., 4.]], false),
        (&[[1.5, 3.], [3., 1.5], [3., 3.]], false),
        // pencil lines along an edge of P (window of one direction)
        (&[[3., 0.], [4., 0.], [4., 1.]], false),
        (&[[2., 0.], [4., 0.], [4., 1.]], true),
        (&[[-3., 0.], [-1., 0.], [-2., -1.]], false),
        (&[[-3., 0.], [0., 0.], [-2., -1.]], true),
        (&[[0., 3.], [0., 4.], [-1., 4.]], false),
    ];
    for (q, want) in cases {
        let q = poly(q);
        for s in 0..sq.len() {
            let p = sq.starting_at(s);
            for t in 0..q.len() {
                let qq = q.starting_at(t);
                assert_eq!(ChazelleDobkin.intersects(&p, &qq), *want, "{p:?} {qq:?}");
                assert_eq!(ChazelleDobkin.intersects(&qq, &p), *want, "{qq:?} {p:?}");
                assert_eq!(brute_force(Exact, &p, &qq), *want);
            }
        }
    }
}

#[test]
fn integer_grid_triangles_and_quads_agree_with_linear() {
    // Every small lattice polygon against a fixed set: heavy on collinear and touching cases.
    let tris: Vec<ConvexPolygon> = {
        let mut v = Vec::new();
        let pts: Vec<[f64; 2]> = (0..4)
            .flat_map(|x| (0..4).map(move |y| [x as f64, y as f64]))
            .collect();
        for i in 0..pts.len() {
            for j in i + 1..pts.len() {
                for l in j + 1..pts.len() {
                    if let Ok(t) = ConvexPolygon::new([pts[i], pts[j], pts[l]]) {
                        v.push(t);
                    }
                }
            }
        }
        v
    };
    let others = [
        poly(&[[1., 1.], [2., 1.], [2., 2.], [1., 2.]]),
        poly(&[[0., 0.], [3., 0.], [3., 1.], [1., 3.], [0., 2.]]),
        poly(&[[1., 0.], [2., 1.], [1., 2.], [0., 1.]]),
        poly(&[[4., 0.], [5., 1.], [4., 3.]]),
    ];
    let mut count = 0;
    for t in tris.iter().step_by(3) {
        for o in &others {
            for s in 0..o.len() {
                let o = o.starting_at(s);
                let want = Linear.intersects(t, &o);
                assert_eq!(ChazelleDobkin.intersects(t, &o), want, "{t:?} {o:?}");
                assert_eq!(ChazelleDobkin.intersects(&o, t), want, "{o:?} {t:?}");
                count += 1;
            }
        }
    }
    assert!(count > 500);
}

#[test]
fn iterations_are_counted_and_fast_kernel_terminates() {
    let p = crate::generate::regular_polygon(1000, 1.0);
    for (dx, want) in [(-1.4, true), (-1.6, false)] {
        let q = crate::generate::regular_polygon(1000, 0.5)
            .map(|v| Point::new(v.x + dx, v.y))
            .unwrap();
        let mut it = Iterations::default();
        assert_eq!(ChazelleDobkin.intersects_probed(Exact, &p, &q, &mut it), want);
        assert!(it.0 > 0 && it.0 < 60, "{it:?}");
        assert_eq!(ChazelleDobkin.intersects_with(Fast, &p, &q), want);
    }
}
