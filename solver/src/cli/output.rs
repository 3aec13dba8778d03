//! Everything the command line writes to standard output goes through
//! here, so that no write can panic: a closed pipe (`thinjkr curve … | head`)
//! ends the program quietly with the status a shell gives a process ended
//! by SIGPIPE (141), and any other write error (a full disk) is an I/O error
//! in words with a nonzero status. Standard output that is closed before
//! the program starts is refused up front.
//!
//! Standard error gets the same care ([`err_line`], `errln!`): a line that
//! cannot be written there never panics and never stops the output.
//!
//! A person reads the answer on the first line and at most two more lines on
//! how far to trust it; `--explain` asks for every line ([`explain`]: each
//! command chooses its brief lines and its whole text by it).
//!
//! Owns: [`line`], [`text`], [`finish`], [`err_line`], [`explain`], the `outln!`/`out!`/
//! `errln!` macros, `Spinner`. May use:
//! `crate::Error`, `progress` (the stage a spinner shows).

use std::io::Write;
use std::sync::atomic::{AtomicBool, Ordering};

static BROKEN_PIPE: AtomicBool = AtomicBool::new(false);
static EXPLAIN: AtomicBool = AtomicBool::new(false);

/// Whether the run prints every line (`--explain`), not the brief text.
pub(crate) fn explain() -> bool {
    EXPLAIN.load(Ordering::Relaxed)
}

/// Set by `--explain` once, before the command runs.
pub(crate) fn set_explain(on: bool) {
    EXPLAIN.store(on, Ordering::Relaxed);
}

/// The exit status after a closed pipe (128 + SIGPIPE).
pub(crate) const BROKEN_PIPE_STATUS: u8 = 141;

fn io(e: std::io::Error) -> crate::Error {
    if e.kind() == std::io::ErrorKind::BrokenPipe {
        BROKEN_PIPE.store(true, Ordering::Relaxed);
    }
    crate::Error::Io(format!("cannot write the output: {e}"))
}

/// Standard output behind one buffer: a write per 8 kB instead of a
/// write per line (Rust's standard output is line-buffered, which cost
/// `batch` 12 s of system calls per 10⁶ rows). On a terminal each line is
/// flushed at once, so that a person sees it when it is ready.
struct Out {
    buf: std::io::BufWriter<std::io::Stdout>,
    terminal: bool,
}

fn with_out<T>(f: impl FnOnce(&mut Out) -> std::io::Result<T>) -> std::io::Result<T> {
    use std::io::IsTerminal;
    static OUT: std::sync::Mutex<Option<Out>> = std::sync::Mutex::new(None);
    // a panic elsewhere while holding the lock leaves the buffer usable
    let mut guard = OUT.lock().unwrap_or_else(|p| p.into_inner());
    let out = guard.get_or_insert_with(|| Out {
        buf: std::io::BufWriter::with_capacity(1 << 16, std::io::stdout()),
        terminal: std::io::stdout().is_terminal(),
    });
    f(out)
}

/// Write one line.
pub(crate) fn line(args: std::fmt::Arguments<'_>) -> crate::Result<()> {
    with_out(|o| {
        o.buf.write_fmt(args)?;
        o.buf.write_all(b"\n")?;
        if o.terminal {
            o.buf.flush()?;
        }
        Ok(())
    })
    .map_err(io)
}

/// Write text as it is.
pub(crate) fn text(args: std::fmt::Arguments<'_>) -> crate::Result<()> {
    with_out(|o| {
        o.buf.write_fmt(args)?;
        if o.terminal {
            o.buf.flush()?;
        }
        Ok(())
    })
    .map_err(io)
}

/// Flush standard output (a write error may surface only here).
pub(crate) fn finish() -> crate::Result<()> {
    with_out(|o| o.buf.flush()).map_err(io)
}

/// Whether the last error came from a closed pipe.
pub(crate) fn broken_pipe() -> bool {
    BROKEN_PIPE.load(Ordering::Relaxed)
}

/// Whether the standard descriptor `fd` was closed when the program
/// started. The Rust runtime reopens a closed standard descriptor on
/// /dev/null for reading and writing before `main`, so every read would see
/// an empty input and every write would vanish without an error; a shell's
/// `</dev/null` or `>/dev/null` opens it for one direction only, which is
/// left alone.
#[cfg(unix)]
fn closed_at_start(fd: std::os::fd::RawFd) -> bool {
    use std::os::unix::fs::MetadataExt;
    // SAFETY: fcntl with F_GETFL only queries the descriptor's flags.
    let flags = unsafe { libc::fcntl(fd, libc::F_GETFL) };
    flags == -1
        || (flags & libc::O_ACCMODE == libc::O_RDWR && {
            let null = std::fs::metadata("/dev/null").map(|m| m.rdev()).ok();
            // SAFETY: fstat writes into the zeroed struct we own.
            let mut st: libc::stat = unsafe { std::mem::zeroed() };
            let ok = unsafe { libc::fstat(fd, &mut st) } == 0;
            ok && null == Some(st.st_rdev as u64)
        })
}

/// Refuse to start when standard output was closed (`>&-`): the output
/// would be lost without an error.
pub(crate) fn check_open() -> crate::Result<()> {
    #[cfg(unix)]
    {
        use std::os::fd::AsRawFd;
        if closed_at_start(std::io::stdout().as_raw_fd()) {
            return Err(crate::Error::Io(
                "standard output is closed: nothing could be written".into(),
            ));
        }
    }
    Ok(())
}

/// Refuse to read standard input when it was closed (`<&-`): it would read
/// as an empty input, and an empty answer would look like a success.
pub(crate) fn check_input_open() -> crate::Result<()> {
    #[cfg(unix)]
    {
        use std::os::fd::AsRawFd;
        if closed_at_start(std::io::stdin().as_raw_fd()) {
            return Err(crate::Error::Io(
                "standard input is closed: there are no lines to read (give them on standard input, e.g. < in.csv)".into(),
            ));
        }
    }
    Ok(())
}

static STDERR_FAILED: AtomicBool = AtomicBool::new(false);

/// Write one line to standard error (a warning, a line's error, the final
/// error). It never panics and never stops the work: what goes to standard
/// output still matters. A closed pipe there is the reader's choice and
/// ignored; any other failure (a full disk) is remembered, and the program
/// then ends with a nonzero status ([`stderr_failed`]).
pub(crate) fn err_line(args: std::fmt::Arguments<'_>) {
    let mut e = std::io::stderr().lock();
    if let Err(w) = e.write_fmt(args).and_then(|()| e.write_all(b"\n")) {
        if w.kind() != std::io::ErrorKind::BrokenPipe {
            STDERR_FAILED.store(true, Ordering::Relaxed);
        }
    }
}

/// Whether a line for standard error could not be written (not counting a
/// closed pipe).
pub(crate) fn stderr_failed() -> bool {
    STDERR_FAILED.load(Ordering::Relaxed)
}

/// `eprintln!` that cannot panic ([`err_line`]).
macro_rules! errln {
    ($($t:tt)*) => { $crate::cli::output::err_line(format_args!($($t)*)) };
}

/// `println!` that returns an I/O error instead of panicking.
macro_rules! outln {
    ($($t:tt)*) => { $crate::cli::output::line(format_args!($($t)*))? };
}

/// `print!` that returns an I/O error instead of panicking.
macro_rules! out {
    ($($t:tt)*) => { $crate::cli::output::text(format_args!($($t)*))? };
}

/// A spinner on standard error while long work runs, when that is a
/// terminal, with the stage the computation says it is in
/// (`crate::progress`); cleared when dropped (before the results are
/// printed).
pub(crate) struct Spinner(Option<indicatif::ProgressBar>);

impl Spinner {
    /// Start one that says `what`.
    pub(crate) fn start(what: &str) -> Spinner {
        use std::io::IsTerminal;
        Spinner(std::io::stderr().is_terminal().then(|| {
            let b = indicatif::ProgressBar::new_spinner();
            // the computation's own stage and count, read at each tick
            let stage = |_: &indicatif::ProgressState, w: &mut dyn std::fmt::Write| {
                let now = crate::progress::now();
                if !now.is_empty() {
                    let _ = write!(w, ": {now}");
                }
            };
            b.set_style(
                indicatif::ProgressStyle::with_template("{spinner} {msg}{stage}, {elapsed}")
                    .expect("template")
                    .with_key("stage", stage),
            );
            b.set_message(what.to_string());
            b.enable_steady_tick(std::time::Duration::from_millis(200));
            b
        }))
    }
}

impl Drop for Spinner {
    fn drop(&mut self) {
        if let Some(b) = &self.0 {
            b.finish_and_clear();
        }
    }
}

/// A number for a person: six decimals (a round-off residue below 1e-10,
/// such as the force 1e-15 of a zero-force state, reads 0.000000, without a
/// sign), six significant digits in scientific notation from 1e7 up (no
/// `100000000000000016384.000000`) and below 1e-3 (a pull-off force of
/// -1.2e-7 at rho = 1e-8 is not 0.000000). `--json` carries every digit.
pub(crate) fn num(x: f64) -> String {
    /// Below this a quantity of the units (17), of order one, is zero to
    /// the solvers' round-off.
    const ROUND_OFF: f64 = 1e-10;
    let a = x.abs();
    let s = if a >= 1e7 || (ROUND_OFF..1e-3).contains(&a) {
        format!("{x:.5e}")
    } else {
        format!("{x:.6}")
    };
    match s.strip_prefix('-') {
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => rest.to_string(),
        _ => s,
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn numbers_for_a_person() {
        assert_eq!(super::num(-1e-12), "0.000000");
        assert_eq!(super::num(-0.0), "0.000000");
        assert_eq!(super::num(1.76806e-15), "0.000000");
        assert_eq!(super::num(-0.0000016), "-1.60000e-6");
        assert_eq!(super::num(-1.193028736578389e-7), "-1.19303e-7");
        assert_eq!(super::num(0.000999), "9.99000e-4");
        assert_eq!(super::num(0.001), "0.001000");
        assert_eq!(super::num(1e20), "1.00000e20");
        assert_eq!(super::num(2.5), "2.500000");
        assert_eq!(super::num(-4.1976054), "-4.197605");
    }
}
