//! The 3-D pressure solve allocates nothing after construction: counted with a global allocator
//! wrapper around the system allocator, on one thread and inside a two-worker rayon pool.
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

use platefall_core::poisson3::{plate_axis, FaceCoefs3, Poisson3};

struct Counting;
static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn solves_allocate_nothing() {
    // Large enough (> 16k cells) that the finest levels run in parallel; periodic z with a plate
    // (singular pieces to project).
    let n = 8;
    let h = 1.0 / n as f64;
    let dx = plate_axis(n, h, 4.0, 1.1);
    let dy = plate_axis(3, h, 4.0, 1.1);
    let mut coefs = FaceCoefs3::open(dx, dy, vec![h; 2 * n], true).unwrap();
    let (sx, sy) = ((coefs.dx.len() - n) / 2, coefs.dy.len() / 2);
    for k in 0..2 * n {
        for i in sx..sx + n {
            coefs.decouple(i, sy, k);
        }
    }
    let mut solver = Poisson3::new(&coefs).unwrap();
    assert!(solver.cells() > 16_384, "{} cells", solver.cells());
    let b: Vec<f64> = (0..solver.cells())
        .map(|p| (p as f64 * 0.37).sin())
        .collect();
    let mut x = vec![0.0; solver.cells()];
    for threads in [1, 2] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        // Each worker's first steal registers it with the work-stealing deque's epoch collector
        // (a one-time allocation inside rayon); a broadcast makes every worker take that step now.
        pool.broadcast(|_| ());
        let during = pool.install(|| {
            solver.solve(&b, &mut x, 1e-10).unwrap();
            let before = ALLOCATIONS.load(Ordering::SeqCst);
            for _ in 0..3 {
                x.iter_mut().for_each(|v| *v = 0.0);
                let stats = solver.solve(&b, &mut x, 1e-10).unwrap();
                assert!(stats.iterations > 5);
            }
            ALLOCATIONS.load(Ordering::SeqCst) - before
        });
        assert_eq!(
            during, 0,
            "{threads} thread(s): {during} allocations in 3 solves"
        );
    }
}
