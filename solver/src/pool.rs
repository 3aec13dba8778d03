//! The thread pool every parallel step runs on (a batch, the accuracy
//! table, the exact bands, the Python package's array calls), built so
//! that no setting of the environment or the system makes it panic, as
//! rayon's own global pool does at its first parallel step: the threads
//! RAYON_NUM_THREADS asks for are capped, fitted into a limit on the
//! address space (`ulimit -v`), and halved down to one (then the calling
//! thread) where the system cannot start them, each step with a warning
//! handed to the caller.
//!
//! Owns: [`thread_pool`]. May use: nothing else in the crate; rayon, libc.

/// The most threads a run starts per core, whatever RAYON_NUM_THREADS asks
/// for: the work is arithmetic, and more threads than cores only cost
/// memory.
pub(crate) const MAX_THREADS_PER_CORE: usize = 4;

/// Each worker thread's stack (Rust's default for spawned threads).
const THREAD_STACK_BYTES: usize = 2 << 20;

/// How many worker threads fit in half of the address space the process
/// may still map, where a limit is set (`ulimit -v`); `None` without one.
fn threads_that_fit() -> Option<usize> {
    #[cfg(target_os = "linux")]
    {
        let mut lim = libc::rlimit {
            rlim_cur: 0,
            rlim_max: 0,
        };
        // SAFETY: getrlimit writes into the struct we own.
        if unsafe { libc::getrlimit(libc::RLIMIT_AS, &mut lim) } != 0
            || lim.rlim_cur == libc::RLIM_INFINITY
        {
            return None;
        }
        // the address space mapped now: the first field of statm, in pages
        let pages: u64 = std::fs::read_to_string("/proc/self/statm")
            .ok()
            .and_then(|t| t.split_whitespace().next()?.parse().ok())
            .unwrap_or(0);
        // SAFETY: sysconf only reads a constant of the system.
        let page = unsafe { libc::sysconf(libc::_SC_PAGESIZE) }.max(4096) as u64;
        let free = (lim.rlim_cur as u64).saturating_sub(pages * page);
        // a stack, its guard, the signal stack, and the 64 MiB the C
        // allocator reserves for a thread's own arena
        let per_thread = THREAD_STACK_BYTES as u64 + (65 << 20);
        Some(((free / 2) / per_thread).max(1) as usize)
    }
    #[cfg(not(target_os = "linux"))]
    {
        None
    }
}

/// The thread pool every parallel step of a run (batch, accuracy, the
/// exact bands) runs on: as many threads as RAYON_NUM_THREADS asks for (up
/// to [`MAX_THREADS_PER_CORE`] per core), else one per core. Where the system cannot start
/// that many (a memory cap), half as many are tried, down to one, with a
/// warning; rayon's own global pool would instead panic at the first
/// parallel step.
pub fn thread_pool(mut warn: impl FnMut(String)) -> rayon::ThreadPool {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let asked = std::env::var("RAYON_NUM_THREADS")
        .ok()
        .and_then(|v| v.trim().parse::<usize>().ok())
        .filter(|&n| n > 0);
    let mut n = asked.unwrap_or(cores);
    let most = MAX_THREADS_PER_CORE * cores;
    if n > most {
        warn(format!("RAYON_NUM_THREADS = {n} is more than {most} threads ({MAX_THREADS_PER_CORE} per core); using {most}"));
        n = most;
    }
    // under a cap on the address space, at most the threads whose stacks
    // fill half of what is left: a thread that starts but cannot map its
    // signal stack afterwards aborts the run, which no fallback can catch
    if let Some(fit) = threads_that_fit() {
        if n > fit {
            warn(format!(
                "{n} threads do not fit in the memory limit; using {fit}"
            ));
            n = fit;
        }
    }
    loop {
        let built = rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .stack_size(THREAD_STACK_BYTES)
            .build();
        match built {
            Ok(pool) => return pool,
            Err(e) if n > 1 => {
                warn(format!(
                    "could not start {n} threads ({e}); trying {}",
                    n / 2
                ));
                n /= 2;
            }
            Err(e) => {
                // not even one thread: the work runs on this one
                warn(format!(
                    "could not start a thread ({e}); running on the main thread"
                ));
                return rayon::ThreadPoolBuilder::new()
                    .num_threads(1)
                    .use_current_thread()
                    .build()
                    .expect("a pool of the current thread starts no thread");
            }
        }
    }
}
