//! `scene`'s `pairs` reply is streamed: the memory it allocates is bounded by the
//! scene, not by the number of pairs. Counted by this test binary's allocator (exact,
//! so the bound cannot flake), on a scene where every pair intersects.

use polysect::protocol::scene::{SceneOptions, SceneSession};
use std::alloc::{GlobalAlloc, Layout, System};
use std::io;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Bytes allocated now, and the most since the last reset.
static LIVE: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);

struct Counting;

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            let now = LIVE.fetch_add(layout.size(), Ordering::Relaxed) + layout.size();
            PEAK.fetch_max(now, Ordering::Relaxed);
        }
        p
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) };
        LIVE.fetch_sub(layout.size(), Ordering::Relaxed);
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

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
    let base = LIVE.load(Ordering::Relaxed);
    PEAK.store(base, Ordering::Relaxed);
    session.run(&b"{\"op\":\"pairs\"}\n"[..], &mut out).unwrap();
    let extra = PEAK.load(Ordering::Relaxed) - base;
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
