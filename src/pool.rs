//! The worker threads of a run: the solver loop runs inside a rayon pool, where the flow step
//! splits its u and v halves between the workers (`flow::momentum::explicit_rhs`,
//! `FlowSolver::advance`). Starting the loop inside the pool matters: work handed to a pool from
//! outside goes through its injector queue, which allocates; from a worker it does not, so the
//! step keeps allocating nothing (`tests/no_alloc.rs`). Results do not depend on the number of
//! threads.
use anyhow::Context;

/// A pool of `threads` workers (0: one per core, or `RAYON_NUM_THREADS`).
pub(crate) fn pool(threads: usize) -> anyhow::Result<rayon::ThreadPool> {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .thread_name(|i| format!("platefall-solver-{i}"))
        .build()
        .context("starting the solver's worker threads")
}
