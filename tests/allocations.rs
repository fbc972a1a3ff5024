//! What the library allocates, counted by this test binary's allocator (exact, so the
//! bounds cannot flake): the queries allocate nothing per call (the array tests never,
//! the sampled test once its workspace has grown), which is why no small-buffer type is
//! needed on their paths (docs/design.md, "Dependencies"); and `scene`'s `pairs` reply
//! is streamed, so the memory it allocates is bounded by the scene, not by the number
//! of pairs.

use polysect::intersect::{Algorithm, Clm, ClmWorkspace, LinkedIntersection};
use polysect::protocol::scene::{SceneOptions, SceneSession};
use polysect::{ConvexPolygon, Exact, Fast, LinkedPolygon};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::io;

thread_local! {
    /// Bytes this thread has allocated and not freed, and the most since the last
    /// reset: per thread, so the tests running beside one another do not count into
    /// each other's bounds.
    static LIVE: Cell<isize> = const { Cell::new(0) };
    static PEAK: Cell<isize> = const { Cell::new(0) };
    /// Allocations (and reallocations) made by this thread: the query tests count their
    /// own calls, whatever the other tests do meanwhile.
    static CALLS: Cell<usize> = const { Cell::new(0) };
}

struct Counting;

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            let now = LIVE.with(|l| {
                l.set(l.get() + layout.size() as isize);
                l.get()
            });
            PEAK.with(|p| p.set(p.get().max(now)));
            CALLS.with(|c| c.set(c.get() + 1));
        }
        p
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) };
        LIVE.with(|l| l.set(l.get() - layout.size() as isize));
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// The allocations `f` makes on this thread, and its result.
fn counted<T>(f: impl FnOnce() -> T) -> (usize, T) {
    let before = CALLS.with(Cell::get);
    let out = f();
    (CALLS.with(Cell::get) - before, out)
}

/// A polygon of `n` vertices at random angles on a circle of radius 1 about `centre`:
/// generic position, so no predicate of a query is exactly degenerate (those go on to
/// the exact kernel's big-integer layer, which allocates; docs/design.md).
fn random_polygon(rng: &mut SmallRng, n: usize, centre: [f64; 2]) -> ConvexPolygon {
    let points = (0..n).map(|_| {
        let t = rng.random_range(0.0..std::f64::consts::TAU);
        [centre[0] + t.cos(), centre[1] + t.sin()]
    });
    ConvexPolygon::hull_of(points).unwrap()
}

/// Pairs of random polygons of 3 to 4,096 vertices, overlapping, nearly touching and
/// apart, each way round.
fn pairs() -> Vec<(ConvexPolygon, ConvexPolygon)> {
    let mut rng = SmallRng::seed_from_u64(3);
    let sizes = [3, 16, 256, 4096];
    let mut out = Vec::new();
    for (i, &n) in sizes.iter().enumerate() {
        for &m in &sizes[i..] {
            for dx in [0.3, 1.9, 1.999, 2.0001, 5.0] {
                let p = random_polygon(&mut rng, n, [0.0, 0.0]);
                let q = random_polygon(&mut rng, m, [dx, 0.25]);
                out.push((p.clone(), q.clone()));
                out.push((q, p));
            }
        }
    }
    out
}

#[test]
fn array_queries_allocate_nothing() {
    let pairs = pairs();
    let mut seen = [0usize; 2];
    // A thread's first call seeds the thread's generator (`Algorithm` draws one for
    // its randomized members): once per thread, not per query.
    Algorithm::Linear.intersects_with(Exact, &pairs[0].0, &pairs[0].1);
    for alg in [
        Algorithm::Linear,
        Algorithm::Barba,
        Algorithm::Dobkin,
        Algorithm::ChazelleDobkin,
    ] {
        for (p, q) in &pairs {
            let (calls, answer) = counted(|| alg.intersects_with(Exact, p, q));
            assert_eq!(
                calls,
                0,
                "{alg:?} allocated {calls} times on {} × {}",
                p.len(),
                q.len()
            );
            seen[answer as usize] += 1;
            let (calls, _) = counted(|| alg.intersects_with(Fast, p, q));
            assert_eq!(
                calls,
                0,
                "{alg:?} (fast) allocated {calls} times on {} × {}",
                p.len(),
                q.len()
            );
            let (calls, cert) = counted(|| alg.certified_with(Exact, p, q));
            assert_eq!(
                calls,
                0,
                "{alg:?} (certified) allocated {calls} times on {} × {}",
                p.len(),
                q.len()
            );
            assert_eq!(cert.intersects(), answer);
        }
    }
    // Both answers were asked for.
    assert!(seen[0] > 0 && seen[1] > 0, "{seen:?}");
}

#[test]
fn the_sampled_test_allocates_nothing_once_its_workspace_has_grown() {
    let pairs: Vec<(LinkedPolygon, LinkedPolygon)> = pairs()
        .into_iter()
        .map(|(p, q)| (LinkedPolygon::from_convex(&p), LinkedPolygon::from_convex(&q)))
        .collect();
    let mut ws = ClmWorkspace::default();
    let mut rng = SmallRng::seed_from_u64(11);
    // Grow the workspace first: the draws decide how long the walked chains are, so
    // on many draws (seeded, so the counts below are the same on every run).
    for _ in 0..20 {
        for (p, q) in &pairs {
            Clm.intersects_with_workspace(Exact, p, q, &mut rng, &mut ws);
        }
    }
    for (p, q) in &pairs {
        let (calls, _) = counted(|| Clm.intersects_with_workspace(Exact, p, q, &mut rng, &mut ws));
        assert_eq!(
            calls,
            0,
            "the sampled test allocated {calls} times on {} × {}",
            p.len(),
            q.len()
        );
        // The certified call completes an answer it found without a witness on the
        // walked arrays (two of them, O(n + m), whatever the sizes).
        let (calls, _) = counted(|| Clm.certified_with_workspace(Exact, p, q, &mut rng, &mut ws));
        assert!(
            calls <= 2,
            "the certified sampled test allocated {calls} times on {} × {}",
            p.len(),
            q.len()
        );
    }
}

#[test]
fn pairs_of_an_all_overlapping_scene_allocate_a_bounded_amount() {
    // 2,000 triangles around the origin, so all 1,999,000 pairs intersect; the reply is
    // about 30 MB, which the held reply kept several times over.
    const N: usize = 2_000;
    let mut input = String::new();
    for i in 0..N {
        let d = i as f64 * 1e-3;
        input.push_str(&format!(
            "{{\"op\":\"add\",\"name\":\"p{i:04}\",\"points\":[[{},-1],[1,{d}],[-1,1]]}}\n",
            -1.0 - d
        ));
    }
    let mut session = SceneSession::new(SceneOptions::default());
    session.run(input.as_bytes(), io::sink()).unwrap();
    drop(input);

    // Count the reply's bytes, and the memory allocated while answering.
    struct Count(usize);
    impl io::Write for Count {
        fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
            self.0 += buf.len();
            Ok(buf.len())
        }
        fn flush(&mut self) -> io::Result<()> {
            Ok(())
        }
    }
    let mut out = io::BufWriter::new(Count(0));
    let base = LIVE.with(Cell::get);
    PEAK.with(|p| p.set(base));
    session.run(&b"{\"op\":\"pairs\"}\n"[..], &mut out).unwrap();
    let extra = PEAK.with(Cell::get) - base;
    let written = out.into_inner().map_err(|e| e.into_error()).unwrap().0;
    let pairs = N * (N - 1) / 2;
    assert_eq!(
        written,
        "{\"pairs\": []}\n".len() + pairs * "[\"p0000\",\"p0001\"]".len() + pairs - 1
    );
    assert!(
        extra < 8 << 20,
        "answering {pairs} pairs allocated {extra} bytes beyond the scene"
    );
}
