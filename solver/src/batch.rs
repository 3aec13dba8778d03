//! Batch solves: a slice of (ρ, control value) solved on all cores
//! (rayon), results in input order with a typed error per item, written
//! once for every model through [`Solves`]; and the CSV reading and
//! writing of `thinjkr batch`, streamed in blocks so that inputs of any
//! length run in bounded memory; and the thread pool every parallel step
//! of the crate and its front ends runs on ([`thread_pool`]).
//!
//! Owns: [`Item`], [`Solves`], [`solve_all`], [`thread_pool`], [`parse_line`],
//! `csv_row_values`, `CSV_HEADER`. May use: `generated` (`ModelId`), `contact`, `conformal`, `control`, `error`,
//! `model`.

use crate::contact::{Contact, State};
use crate::control::Hold;
use crate::error::{Error, Result};
use crate::generated::ModelId;
use rayon::prelude::*;

/// One input of a batch.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Item {
    /// Radii ratio ρ.
    pub rho: f64,
    /// The control and its value (a batch file's lines give δ̄ or F̄; at a
    /// given F̄ the stable state, at a given ā the state before the
    /// contact-size fold).
    pub given: Hold,
}

/// A model a batch runs: the state at a control for a given ρ, with what
/// is made once per ρ (an ellipse model's [`Contact`], which may find s∞
/// numerically) shared by every item at that ρ. [`solve_all`] is written
/// once against it; the ellipse models ([`ModelId`]) and the members of
/// `conformal:K` implement it.
pub trait Solves: Sync {
    /// What is made once per ρ.
    type AtRho: Send + Sync;
    /// A state.
    type State: Send;
    /// Make what the items at `rho` share (or the error every one of them
    /// gets).
    fn at_rho(&self, rho: f64) -> Result<Self::AtRho>;
    /// The state under `given`.
    fn solve(&self, at: &Self::AtRho, given: Hold) -> Result<Self::State>;
}

impl Solves for ModelId {
    type AtRho = Contact;
    type State = State;
    fn at_rho(&self, rho: f64) -> Result<Contact> {
        Contact::with_model(*self, rho)
    }
    fn solve(&self, c: &Contact, given: Hold) -> Result<State> {
        match given {
            Hold::Delta(d) => c.at_displacement(d),
            Hold::Force(f) => c.at_load(f),
            Hold::Size(a) => c.at_contact_size(a)?.into_iter().next().ok_or_else(|| {
                Error::NoState(format!(
                    "no state with a = {} at rho = {}",
                    crate::error::short(a),
                    crate::error::short(c.rho())
                ))
            }),
        }
    }
}

impl Solves for crate::conformal::Conformal {
    type AtRho = f64;
    type State = crate::conformal::ConformalState;
    fn at_rho(&self, rho: f64) -> Result<f64> {
        Ok(rho)
    }
    fn solve(&self, rho: &f64, given: Hold) -> Result<Self::State> {
        // each from the circle, continued in ρ
        self.solve(*rho, given)
    }
}

/// Solve one item with `model`.
pub fn solve_one<S: Solves + ?Sized>(model: &S, item: &Item) -> Result<S::State> {
    model.solve(&model.at_rho(item.rho)?, item.given)
}

/// Solve every item with `model` on all cores; the results are in the
/// order of `items`, each a state or the typed error for that item.
pub fn solve_all<S: Solves + ?Sized>(model: &S, items: &[Item]) -> Vec<Result<S::State>> {
    // what the items share, once per distinct ρ
    let mut rhos: Vec<f64> = items.iter().map(|it| it.rho).collect();
    rhos.sort_by(f64::total_cmp);
    rhos.dedup_by(|a, b| a.to_bits() == b.to_bits());
    let shared: std::collections::HashMap<u64, Result<S::AtRho>> = rhos
        .par_iter()
        .map(|&rho| (rho.to_bits(), model.at_rho(rho)))
        .collect();
    items
        .par_iter()
        .map(|it| match &shared[&it.rho.to_bits()] {
            Ok(at) => model.solve(at, it.given),
            Err(e) => Err(e.clone()),
        })
        .collect()
}

/// The header of the output CSV.
#[cfg(feature = "cli")]
pub(crate) const CSV_HEADER: &str =
    "line,rho,control,value,a,b,s,delta,force,xi,p0,bc_error,error,warning";

/// Parse one input line `rho,control,value` (control `delta` or `force`).
/// Only the first line may be skipped (`None`), and only when it is the
/// header `rho,control,value`; every other line, blank ones included, is
/// an item or an [`Error::Usage`] that names the line (and quotes at most
/// its first 40 characters).
pub fn parse_line(number: usize, line: &str) -> Option<Result<Item>> {
    let t = line.trim();
    let f: Vec<&str> = t.split(',').map(str::trim).collect();
    if number == 1
        && f.len() == 3
        && f.iter()
            .zip(["rho", "control", "value"])
            .all(|(a, b)| a.eq_ignore_ascii_case(b))
    {
        return None;
    }
    let shown = crate::error::quote_start(t);
    let bad = |why: String| Some(Err(Error::Usage(format!("line {number}: {why}: {shown}"))));
    if t.is_empty() {
        return bad("empty line, expected rho,control,value".into());
    }
    if f.len() != 3 {
        return bad(format!(
            "expected 3 fields rho,control,value, found {}",
            f.len()
        ));
    }
    let num = |s: &str, name: &str| {
        s.parse::<f64>()
            .map_err(|_| format!("{name} {} is not a number", crate::error::quote_start(s)))
    };
    let rho = match num(f[0], "rho") {
        Ok(v) => v,
        Err(e) => return bad(e),
    };
    let value = match num(f[2], "value") {
        Ok(v) => v,
        Err(e) => return bad(e),
    };
    let given = match f[1] {
        "delta" => Hold::Delta(value),
        "force" => Hold::Force(value),
        other => {
            return bad(format!(
                "control {} is not delta or force",
                crate::error::quote_start(other)
            ))
        }
    };
    Some(Ok(Item { rho, given }))
}

/// One raw input line as text: the UTF-8 byte-order mark that spreadsheet
/// programs write is dropped from the first line, a trailing carriage
/// return from every line; bytes that are not UTF-8 are an error for that
/// line alone.
pub fn decode_line(number: usize, raw: &[u8]) -> std::result::Result<&str, Error> {
    let mut raw = raw.strip_suffix(b"\r").unwrap_or(raw);
    if number == 1 {
        raw = raw.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(raw);
    }
    std::str::from_utf8(raw).map_err(|e| {
        Error::Usage(format!(
            "line {number}: not UTF-8 text (invalid byte at position {})",
            e.valid_up_to() + 1
        ))
    })
}

/// The numbers of one output row: the state's, with ξ and p₀ where the
/// model has them (the models of the ellipse), and its boundary error:
/// (14) for the ellipse, max |∂p̄/∂ν − 1| on the contour for `conformal:K`.
#[derive(Clone, Debug)]
pub struct Row {
    /// ā.
    pub a_bar: f64,
    /// b̄.
    pub b_bar: f64,
    /// s.
    pub s: f64,
    /// δ̄.
    pub delta_bar: f64,
    /// F̄.
    pub force_bar: f64,
    /// ξ (the ellipse models).
    pub xi: Option<f64>,
    /// p₀ (the ellipse models).
    pub p0: Option<f64>,
    /// The boundary error.
    pub bc_error: f64,
    /// Why the state is doubtful, in words joined by "; " (empty when it
    /// is not): a model of the ellipse's flags (ρ below the paper's range,
    /// beyond the contact-size fold), a contour member's
    /// [`crate::conformal::ConformalState::warnings`].
    pub warning: String,
    /// The exact solver's: how far the contour is from the ellipse with
    /// the same half-widths (relative to ā), and the route that found the
    /// state (its JSON name, e.g. `past_fold`).
    pub departure: Option<f64>,
    /// See [`Row::departure`].
    pub route: Option<String>,
}

impl From<&State> for Row {
    fn from(s: &State) -> Row {
        Row {
            a_bar: s.a_bar,
            b_bar: s.b_bar,
            s: s.s,
            delta_bar: s.delta_bar,
            force_bar: s.force_bar,
            xi: Some(s.xi),
            p0: Some(s.p0),
            bc_error: s.bc_error,
            warning: s.warning_words().join("; "),
            departure: None,
            route: None,
        }
    }
}

impl From<&crate::conformal::ConformalState> for Row {
    fn from(s: &crate::conformal::ConformalState) -> Row {
        Row {
            a_bar: s.a_bar,
            b_bar: s.b_bar,
            s: s.s,
            delta_bar: s.delta_bar,
            force_bar: s.force_bar,
            xi: None,
            p0: None,
            bc_error: s.bc_defect,
            warning: s.warnings.join("; "),
            departure: None,
            route: None,
        }
    }
}

/// A CSV field: empty, or the text in double quotes (its own double quotes
/// made single).
#[cfg(feature = "cli")]
pub(crate) fn quoted(text: &str) -> String {
    if text.is_empty() {
        String::new()
    } else {
        format!("\"{}\"", text.replace('"', "'"))
    }
}

/// One output row: the input echoed, the state's numbers (the shortest
/// form that reads back to the same f64, e.g. `1e-300`) or empty fields and
/// the error, quoted.
#[cfg(feature = "cli")]
pub(crate) fn csv_row_values(number: usize, item: Option<&Item>, result: &Result<Row>) -> String {
    let (rho, control, value) = match item {
        Some(it) => match it.given {
            Hold::Delta(v) => (format!("{:?}", it.rho), "delta", format!("{v:?}")),
            Hold::Force(v) => (format!("{:?}", it.rho), "force", format!("{v:?}")),
            Hold::Size(v) => (format!("{:?}", it.rho), "a", format!("{v:?}")),
        },
        None => (String::new(), "", String::new()),
    };
    let opt = |v: Option<f64>| v.map(|x| format!("{x:?}")).unwrap_or_default();
    match result {
        Ok(s) => format!(
            "{number},{rho},{control},{value},{:?},{:?},{:?},{:?},{:?},{},{},{:?},,{}",
            s.a_bar,
            s.b_bar,
            s.s,
            s.delta_bar,
            s.force_bar,
            opt(s.xi),
            opt(s.p0),
            s.bc_error,
            quoted(&s.warning)
        ),
        Err(e) => format!(
            "{number},{rho},{control},{value},,,,,,,,,{},",
            quoted(&e.to_string())
        ),
    }
}

// The thread pool every parallel step runs on (a batch, the accuracy
// table, the exact bands, the Python package's array calls), built so
// that no setting of the environment or the system makes it panic, as
// rayon's own global pool does at its first parallel step: the threads
// RAYON_NUM_THREADS asks for are capped, fitted into a limit on the
// address space (`ulimit -v`), and halved down to one (then the calling
// thread) where the system cannot start them, each step with a warning
// handed to the caller.

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
        // rlim_t is 32 bits wide on 32-bit Linux
        #[allow(clippy::useless_conversion)]
        let free = u64::from(lim.rlim_cur).saturating_sub(pages * page);
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
/// to `MAX_THREADS_PER_CORE` per core), else one per core. Where the system cannot start
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
