//! The extension module `thinjkr._thinjkr`: the solver crate `thinjkr`
//! (without its command line) behind a few functions that the pure-Python
//! package `thinjkr` wraps into its API. Every solve releases the GIL
//! (`Python::detach`), so Python threads run side by side and a batch
//! runs on all cores (rayon, on `thinjkr::batch::thread_pool`: never its global
//! pool, which panics on a RAYON_NUM_THREADS it cannot start).
//!
//! Results cross as JSON text of the solver's own serde types (the same
//! serialisation as the command line's `--json`), or, for batches and
//! curves, as numpy arrays. Errors cross as `RawError(kind, message)`,
//! which the Python side maps onto its exception classes.
//!
//! Owns: the extension module. May use: `thinjkr` (no symbolica).

use numpy::{IntoPyArray, PyArray1, PyReadonlyArray1};
use pyo3::exceptions::PyException;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rayon::prelude::*;
use thinjkr::batch::{solve_all, Item};
use thinjkr::control::Hold;
use thinjkr::fold::FoldCondition;
use thinjkr::registry::Choice;
use thinjkr::Error;

/// The extension's thread pool (`thinjkr::batch::thread_pool`: RAYON_NUM_THREADS capped
/// and fitted to the system, never a panic), built at the first call that
/// needs it; what building it had to say (a cap applied, a memory limit)
/// is a Python RuntimeWarning of that call.
static POOL: std::sync::OnceLock<rayon::ThreadPool> = std::sync::OnceLock::new();

fn pool(py: Python<'_>) -> PyResult<&'static rayon::ThreadPool> {
    let mut said = Vec::new();
    let pool = POOL.get_or_init(|| thinjkr::batch::thread_pool(|w| said.push(w)));
    for w in said {
        let text = std::ffi::CString::new(format!("thinjkr: {w}"))
            .map_err(|e| PyException::new_err(e.to_string()))?;
        PyErr::warn(
            py,
            &py.get_type::<pyo3::exceptions::PyRuntimeWarning>(),
            &text,
            1,
        )?;
    }
    Ok(pool)
}

/// `f` without the GIL, on the extension's pool.
/// While it runs, the calling thread checks for signals every 20 ms: on
/// Ctrl-C it raises the computation's stop flag
/// (`thinjkr::newton::stoppable`), waits the moments the computation takes
/// to unwind, discards what it returns and raises KeyboardInterrupt (issue
/// 33, item 6), so one slow exact solve is interrupted within its
/// current Newton iteration, not when it ends.
fn detached<T: Send>(py: Python<'_>, f: impl FnOnce() -> T + Send) -> PyResult<T> {
    use std::sync::atomic::{AtomicBool, Ordering};
    use std::sync::mpsc::RecvTimeoutError;
    let pool = pool(py)?;
    let stop = std::sync::Arc::new(AtomicBool::new(false));
    let (tx, rx) = std::sync::mpsc::channel();
    pool.in_place_scope(|scope| {
        let flag = stop.clone();
        scope.spawn(move |_| {
            let _ = tx.send(thinjkr::newton::stoppable(&flag, f));
        });
        let mut rx = rx;
        loop {
            let (got, back) = py.detach(move || {
                let got = rx.recv_timeout(std::time::Duration::from_millis(20));
                (got, rx)
            });
            rx = back;
            match got {
                Ok(answer) => return Ok(answer),
                Err(RecvTimeoutError::Timeout) => {
                    if let Err(interrupt) = py.check_signals() {
                        stop.store(true, Ordering::Relaxed);
                        // the computation unwinds; its answer is discarded
                        py.detach(move || drop(rx.recv()));
                        return Err(interrupt);
                    }
                }
                // the computation panicked: the scope raises it as it ends
                Err(RecvTimeoutError::Disconnected) => {
                    return Err(PyException::new_err(
                        "the solver's computation ended without an answer",
                    ))
                }
            }
        }
    })
}

pyo3::create_exception!(
    _thinjkr,
    RawError,
    PyException,
    "A solver error: args (kind, message, record)."
);

/// What a shortened message ends with in Python: where the whole is.
const MORE: &str = " … (its .record: the whole)";

/// A solver error as Python receives it: its kind, the message in at most
/// 300 characters and the whole record.
fn raw(e: Error) -> PyErr {
    RawError::new_err((e.kind(), e.brief_ending(MORE), e.to_string()))
}

fn usage(message: String) -> PyErr {
    raw(Error::Usage(message))
}

/// A model chosen by name, from the registry (`thinjkr::registry`).
fn choice(name: &str) -> PyResult<Choice> {
    thinjkr::registry::parse(name).map_err(usage)
}

/// The model named `name`, for the model layer with two equal coatings of
/// thinness h/L `thinness` and Poisson's ratio `nu` (their defaults where
/// not given; a usage error for another model given either).
fn coated(name: &str, thinness: Option<f64>, nu: Option<f64>) -> PyResult<Choice> {
    choice(name)?.with_coatings(thinness, nu).map_err(|e| match e {
        Error::Usage(why) => usage(why),
        other => raw(other),
    })
}

fn json<T: serde::Serialize>(v: &T) -> String {
    serde_json::to_string(v).expect("the solver's types serialise")
}

/// Every model the solver has: (name, one-line description).
#[pyfunction]
fn models() -> Vec<(String, String)> {
    thinjkr::registry::entries()
        .into_iter()
        .map(|m| (m.name, m.description))
        .collect()
}

/// One state at `control` in {"delta", "force", "a"} = `value`, as JSON
/// (the model layer, `thinjkr::registry`; at a given ā the state before
/// the contact-size fold).
fn solve_one(model: Choice, rho: f64, control: &str, value: f64) -> thinjkr::Result<String> {
    Ok(json(&model.state(rho, Hold::named(control, value)?)?))
}

fn check_control(control: &str) -> PyResult<()> {
    match control {
        "delta" | "force" | "a" => Ok(()),
        other => Err(usage(format!(
            "control must be delta, force or a (got '{other}')"
        ))),
    }
}

/// The batch items of points (ρ, value) under `control` ("delta" or
/// "force").
fn items_of(rho: &[f64], value: &[f64], control: &str) -> Vec<Item> {
    rho.iter()
        .zip(value)
        .map(|(&rho, &v)| Item {
            rho,
            given: if control == "delta" {
                Hold::Delta(v)
            } else {
                Hold::Force(v)
            },
        })
        .collect()
}

/// Every item solved by the one batch of the solver (`batch::solve_all`),
/// as (a_bar, b_bar, s, delta_bar, force_bar, bc_error) with the state's
/// warning ('' for none) or the error.
fn rows_of<S>(
    model: &S,
    items: &[Item],
    err: impl Fn(Error) -> (String, String),
) -> Vec<Row>
where
    S: thinjkr::batch::Solves,
    for<'a> thinjkr::batch::Row: From<&'a S::State>,
{
    solve_all(model, items)
        .into_iter()
        .map(|r| {
            r.map(|st| {
                let row = thinjkr::batch::Row::from(&st);
                Point {
                    values: [
                        row.a_bar,
                        row.b_bar,
                        row.s,
                        row.delta_bar,
                        row.force_bar,
                        row.bc_error,
                    ],
                    warning: row.warning,
                    departure: row.departure.unwrap_or(f64::NAN),
                    route: row.route.unwrap_or_default(),
                }
            })
            .map_err(&err)
        })
        .collect()
}

/// The state of `model` at `rho` with `control` = `value`, as JSON.
#[pyfunction]
#[pyo3(signature = (model, rho, control, value, thinness=None, nu=None))]
fn solve(
    py: Python<'_>,
    model: &str,
    rho: f64,
    control: &str,
    value: f64,
    thinness: Option<f64>,
    nu: Option<f64>,
) -> PyResult<String> {
    let m = coated(model, thinness, nu)?;
    check_control(control)?;
    let control = control.to_string();
    detached(py, move || solve_one(m, rho, &control, value))?.map_err(raw)
}

/// Every state of `model` at `rho` with `control` = `value`, the one
/// [`solve`] gives first, as a JSON array (the model layer's
/// `Choice::states`, what `thinjkr solve --all` lists).
#[pyfunction]
#[pyo3(signature = (model, rho, control, value, thinness=None, nu=None))]
fn states(
    py: Python<'_>,
    model: &str,
    rho: f64,
    control: &str,
    value: f64,
    thinness: Option<f64>,
    nu: Option<f64>,
) -> PyResult<String> {
    let m = coated(model, thinness, nu)?;
    check_control(control)?;
    let control = control.to_string();
    detached(py, move || -> thinjkr::Result<String> {
        Ok(json(&m.states(rho, Hold::named(&control, value)?)?))
    })?
    .map_err(raw)
}

/// One point's state: (a_bar, b_bar, s, delta_bar, force_bar, bc_error),
/// its warnings joined by "; " ('' for none), and for an exact state its
/// departure from the ellipse and route (NaN and '' otherwise).
struct Point {
    values: [f64; 6],
    warning: String,
    departure: f64,
    route: String,
}

/// A point's state or its error (kind, message).
type Row = Result<Point, (String, String)>;

/// Points per chunk of an array call of an ellipse model ([`solve_many`]).
const ELLIPSE_CHUNK: usize = 16_384;

/// One chunk of [`solve_many`]'s points, in parallel.
fn chunk_rows(
    m: Choice,
    rho: &[f64],
    control: &str,
    value: &[f64],
    err: impl Fn(Error) -> (String, String) + Sync + Send + Copy,
) -> Vec<Row> {
    match (m, control) {
        // the ellipse models' batch without the layer's wrapping: the array
        // call is held to the Rust batch's speed (python/benchmarks)
        (Choice::Ellipse(id), "delta" | "force") => {
            rows_of(&id, &items_of(rho, value, control), err)
        }
        (_, "delta" | "force") => rows_of(&m, &items_of(rho, value, control), err),
        _ => rho
            .par_iter()
            .zip(value.par_iter())
            .map(|(&r, &v)| {
                let text = solve_one(m, r, &control, v).map_err(err)?;
                let j: serde_json::Value = serde_json::from_str(&text).expect("own JSON");
                // every state of every model carries these (bc_defect is
                // the boundary error of conformal:K); a missing one is an
                // error of that point, never a NaN
                let g = |keys: &[&str]| {
                    keys.iter()
                        .find_map(|k| j.get(*k).and_then(|x| x.as_f64()))
                        .ok_or_else(|| {
                            ("usage".to_string(), format!("the state has no {}", keys[0]))
                        })
                };
                let warning = j
                    .get("warnings")
                    .and_then(|w| w.as_array())
                    .map(|w| {
                        w.iter()
                            .filter_map(|x| x.as_str())
                            .collect::<Vec<_>>()
                            .join("; ")
                    })
                    .unwrap_or_default();
                Ok(Point {
                    values: [
                        g(&["a_bar"])?,
                        g(&["b_bar"])?,
                        g(&["s"])?,
                        g(&["delta_bar"])?,
                        g(&["force_bar"])?,
                        g(&["bc_error", "bc_defect"])?,
                    ],
                    warning,
                    departure: j
                        .get("deviation_from_ellipse")
                        .and_then(|x| x.as_f64())
                        .unwrap_or(f64::NAN),
                    route: j
                        .get("route")
                        .and_then(|x| x.as_str())
                        .unwrap_or_default()
                        .to_string(),
                })
            })
            .collect(),
    }
}

/// Many states on all cores: arrays (a_bar, b_bar, s, delta_bar,
/// force_bar, bc_error) with NaN where a point has no state, for each
/// point its error (kind, message) or None, and the warnings (index, why)
/// of the points whose state is doubtful (as the command line prints them;
/// only those, so that a million sound states cost no strings).
#[pyfunction]
#[pyo3(signature = (model, rho, control, value, thinness=None, nu=None))]
#[allow(clippy::type_complexity)]
fn solve_many<'py>(
    py: Python<'py>,
    model: &str,
    rho: PyReadonlyArray1<'py, f64>,
    control: &str,
    value: PyReadonlyArray1<'py, f64>,
    thinness: Option<f64>,
    nu: Option<f64>,
) -> PyResult<(
    Bound<'py, PyDict>,
    Vec<Option<(String, String)>>,
    Vec<(usize, String)>,
    Vec<(usize, String)>,
)> {
    let m = coated(model, thinness, nu)?;
    check_control(control)?;
    let rho = rho.as_slice()?.to_vec();
    let value = value.as_slice()?.to_vec();
    if rho.len() != value.len() {
        return Err(usage(format!(
            "rho and the control have {} and {} points after broadcasting",
            rho.len(),
            value.len()
        )));
    }
    let control = control.to_string();
    let err = |e: Error| (e.kind().to_string(), e.brief_ending(MORE));
    // in chunks: between them the call takes the GIL back and checks for
    // signals, so that Ctrl-C raises KeyboardInterrupt within a chunk's
    // time (no partial result); a chunk of the ellipse models is about
    // 0.3 s of the energy model on one core, of the others a few points a
    // thread
    let chunk = match m {
        Choice::Ellipse(_) => ELLIPSE_CHUNK,
        _ => 2 * pool(py)?.current_num_threads(),
    };
    let mut rows: Vec<Row> = Vec::with_capacity(rho.len());
    for (rho, value) in rho.chunks(chunk).zip(value.chunks(chunk)) {
        py.check_signals()?;
        rows.extend(detached(py, || chunk_rows(m, rho, &control, value, err))?);
    }
    py.check_signals()?;

    let n = rows.len();
    let names = [
        "a_bar",
        "b_bar",
        "s",
        "delta_bar",
        "force_bar",
        "bc_error",
        "departure",
    ];
    let mut cols = vec![Vec::with_capacity(n); names.len()];
    let mut errors = Vec::with_capacity(n);
    let mut warnings = Vec::new();
    let mut routes = Vec::new();
    for (i, r) in rows.into_iter().enumerate() {
        match r {
            Ok(p) => {
                for (c, x) in cols.iter_mut().zip(p.values.into_iter().chain([p.departure])) {
                    c.push(x);
                }
                errors.push(None);
                if !p.warning.is_empty() {
                    warnings.push((i, p.warning));
                }
                if !p.route.is_empty() {
                    routes.push((i, p.route));
                }
            }
            Err(e) => {
                for c in cols.iter_mut() {
                    c.push(f64::NAN);
                }
                errors.push(Some(e));
            }
        }
    }
    let d = PyDict::new(py);
    for (name, c) in names.iter().zip(cols) {
        d.set_item(name, c.into_pyarray(py))?;
    }
    Ok((d, errors, warnings, routes))
}

/// The pull-off under `control` ("load" or "displacement"), as JSON: the
/// state and what ends the branch there.
#[pyfunction]
#[pyo3(signature = (model, rho, control, thinness=None, nu=None))]
fn pull_off(
    py: Python<'_>,
    model: &str,
    rho: f64,
    control: &str,
    thinness: Option<f64>,
    nu: Option<f64>,
) -> PyResult<String> {
    let m = coated(model, thinness, nu)?;
    let load = match control {
        "load" => true,
        "displacement" => false,
        other => {
            return Err(usage(format!(
                "control must be load or displacement (got '{other}')"
            )))
        }
    };
    detached(py, move || -> thinjkr::Result<String> {
        let control = if load {
            FoldCondition::Load
        } else {
            FoldCondition::Displacement
        };
        let p = m.pull_off(rho, control)?;
        Ok(json(&match p.basis {
            Some(basis) => serde_json::json!({
                "state": p.state,
                "basis": basis,
                "basis_words": basis.describe(),
            }),
            None => serde_json::json!({ "state": p.state }),
        }))
    })?
    .map_err(raw)
}

/// The exact state at `what` in {"delta", "force"} = `value`, or its
/// load-controlled pull-off (`what` = "pull_off"), as JSON; with `modes`
/// contour modes (8 quadrature points each) instead of the default
/// escalation (12 to 96 modes, `thinjkr::exact::default_tries`); its
/// stability judged with the short-wave cutoff of `thinness` h/L (default
/// `thinjkr::cutoff::Cutoff::DEFAULT_THINNESS`); on the gap named `gap`
/// (`cylinders`, the default, or a contour family's own: issue 73).
#[pyfunction]
#[pyo3(signature = (rho, what, value, modes=None, thinness=None, gap="cylinders"))]
fn exact(
    py: Python<'_>,
    rho: f64,
    what: &str,
    value: f64,
    modes: Option<usize>,
    thinness: Option<f64>,
    gap: &str,
) -> PyResult<String> {
    let cutoff = match thinness {
        None => thinjkr::cutoff::Cutoff::default(),
        Some(t) => thinjkr::cutoff::Cutoff::for_thinness(t).map_err(raw)?,
    };
    let judged = move |st: thinjkr::exact::ExactState| json(&st.judged(cutoff));
    use thinjkr::conformal::{exact_pull_off_on_gap, exact_state_on_gap};
    use thinjkr::exact::{Truncation, MAX_USER_MODES};
    let tries = match modes {
        None => None,
        Some(m) if (1..=MAX_USER_MODES).contains(&m) => Some(vec![Truncation::with_modes(m)]),
        Some(m) => {
            return Err(raw(Error::OutOfRange {
                name: "modes",
                value: m as f64,
                range: format!("1 ..= {MAX_USER_MODES}").into(),
            }))
        }
    };
    let (what, gap) = (what.to_string(), gap.to_string());
    detached(py, move || -> thinjkr::Result<String> {
        match what.as_str() {
            "pull_off" => {
                let (st, _) = exact_pull_off_on_gap(&gap, rho, tries.as_deref())?;
                Ok(judged(st))
            }
            "delta" | "force" => {
                let control = if what == "delta" {
                    Hold::Delta(value)
                } else {
                    Hold::Force(value)
                };
                // the default escalation as the command line: a value in a
                // band says so, and one no start reaches is continued in rho
                Ok(judged(exact_state_on_gap(&gap, rho, control, tries.as_deref())?))
            }
            other => Err(Error::Usage(format!(
                "what must be delta, force or pull_off (got '{other}')"
            ))),
        }
    })?
    .map_err(raw)
}

/// The contour of an exact state (JSON of its `contour`) at `n` points
/// of θ ∈ [0, 2π): x and y arrays.
#[pyfunction]
fn exact_contour<'py>(
    py: Python<'py>,
    contour_json: &str,
    n: usize,
) -> PyResult<(Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<f64>>)> {
    if !(3..=100_000).contains(&n) {
        return Err(raw(Error::OutOfRange {
            name: "points",
            value: n as f64,
            range: "3 ..= 100000".into(),
        }));
    }
    let c: thinjkr::exact::Contour =
        serde_json::from_str(contour_json).map_err(|e| usage(format!("not a contour: {e}")))?;
    let (mut x, mut y) = (Vec::with_capacity(n), Vec::with_capacity(n));
    for k in 0..n {
        let z = c.at(2.0 * std::f64::consts::PI * k as f64 / n as f64)[0];
        x.push(z.re);
        y.push(z.im);
    }
    Ok((x.into_pyarray(py), y.into_pyarray(py)))
}

/// The curve of a model at `rho` from δ̄ = `delta_start` past pull-off:
/// JSON of its states and folds (for `conformal:K` also each state's arm
/// and how the arms end).
#[pyfunction]
#[pyo3(signature = (model, rho, points, delta_start, thinness=None, nu=None))]
fn curve(
    py: Python<'_>,
    model: &str,
    rho: f64,
    points: usize,
    delta_start: f64,
    thinness: Option<f64>,
    nu: Option<f64>,
) -> PyResult<String> {
    let m = coated(model, thinness, nu)?;
    detached(py, move || -> thinjkr::Result<String> {
        let cv = m.curve(rho, points, delta_start)?;
        Ok(json(&match cv.arms {
            // a contour family's curve also says each state's arm
            Some(a) => serde_json::json!({
                "states": cv.states, "folds": cv.folds, "arm": a.arm,
                "beyond_size_fold": a.beyond_size_fold, "end": a.end
            }),
            None => serde_json::json!({ "states": cv.states, "folds": cv.folds }),
        }))
    })?
    .map_err(raw)
}

/// A contact in SI units (JSON of `thinjkr::units::Cylinders`) answered
/// by `model` through the model layer (`Choice::physical`, as the command
/// line's `physical`) at the approach `delta` (m) or the force `force`
/// (N), or its pull-off when both are None: JSON of the SI values (a, b,
/// delta, force, h_over_a; p0 for a model of the ellipse), the state and
/// the warnings.
#[pyfunction]
#[pyo3(signature = (cylinders_json, delta=None, force=None, model=None))]
fn physical(
    py: Python<'_>,
    cylinders_json: &str,
    delta: Option<f64>,
    force: Option<f64>,
    model: Option<&str>,
) -> PyResult<String> {
    let m = model.map(choice).transpose()?;
    let cyl: thinjkr::units::Cylinders =
        serde_json::from_str(cylinders_json).map_err(|e| usage(format!("{e}")))?;
    if delta.is_some() && force.is_some() {
        return Err(raw(Error::Usage("give delta or force, not both".into())));
    }
    detached(py, move || -> thinjkr::Result<String> {
        let answer = thinjkr::registry::physical(m, &cyl, force, delta)?;
        let si = answer.si;
        let mut out = serde_json::json!({
            "a": si.a,
            "b": si.b,
            "delta": si.delta,
            "force": si.force,
            "h_over_a": si.h_over_a,
            "state": answer.state,
            "warnings": answer.warnings,
            "model": answer.model,
            "chosen_because": answer.chosen_because,
            "paper_model": answer.paper_model,
            "thin_layer": answer.thin_layer,
            "layer_estimate": answer.layer_estimate,
        });
        if let thinjkr::report::AnyState::Ellipse(st) = &answer.state {
            let p0 = st.p0 * answer.scales.pressure;
            if !p0.is_finite() {
                return Err(Error::Usage(
                    "the result p0 in SI units is not a finite number for these inputs (their magnitudes are at the ends of f64)".into(),
                ));
            }
            out["p0"] = serde_json::json!(p0);
        }
        Ok(out.to_string())
    })?
    .map_err(raw)
}

/// For the benchmark (python/benchmarks/bench.py): seconds that
/// `thinjkr::batch::solve_all` takes in Rust for these points, the work
/// `solve` with arrays does, without building Python arrays.
#[pyfunction]
fn _batch_api_seconds(
    py: Python<'_>,
    model: &str,
    rho: PyReadonlyArray1<'_, f64>,
    control: &str,
    value: PyReadonlyArray1<'_, f64>,
) -> PyResult<f64> {
    let Choice::Ellipse(id) = choice(model)? else {
        return Err(usage(
            "the batch API serves the models of the ellipse".into(),
        ));
    };
    let items = items_of(rho.as_slice()?, value.as_slice()?, control);
    Ok(detached(py, move || {
        let t = std::time::Instant::now();
        let out = solve_all(&id, &items);
        let secs = t.elapsed().as_secs_f64();
        drop(std::hint::black_box(out));
        secs
    })?)
}

/// For the benchmark: seconds per call of one solve in Rust (the work of
/// one scalar `solve`), over `repeat` calls.
#[pyfunction]
fn _scalar_seconds(
    py: Python<'_>,
    model: &str,
    rho: f64,
    control: &str,
    value: f64,
    repeat: usize,
) -> PyResult<f64> {
    let m = choice(model)?;
    check_control(control)?;
    let control = control.to_string();
    let repeat = repeat.clamp(1, 1_000_000);
    detached(py, move || {
        let t = std::time::Instant::now();
        for _ in 0..repeat {
            std::hint::black_box(solve_one(m, rho, &control, value)).map_err(raw)?;
        }
        Ok(t.elapsed().as_secs_f64() / repeat as f64)
    })?
}

/// The extension module.
#[pymodule]
fn _thinjkr(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("RawError", m.py().get_type::<RawError>())?;
    // the bounds of the counts a user gives, for the wrapper's checks
    m.add("MAX_CURVE_POINTS", thinjkr::curve::MAX_POINTS)?;
    m.add("MAX_USER_MODES", thinjkr::exact::MAX_USER_MODES)?;
    m.add_function(wrap_pyfunction!(models, m)?)?;
    m.add_function(wrap_pyfunction!(solve, m)?)?;
    m.add_function(wrap_pyfunction!(states, m)?)?;
    m.add_function(wrap_pyfunction!(solve_many, m)?)?;
    m.add_function(wrap_pyfunction!(pull_off, m)?)?;
    m.add_function(wrap_pyfunction!(exact_contour, m)?)?;
    m.add_function(wrap_pyfunction!(exact, m)?)?;
    m.add_function(wrap_pyfunction!(curve, m)?)?;
    m.add_function(wrap_pyfunction!(physical, m)?)?;
    m.add_function(wrap_pyfunction!(_batch_api_seconds, m)?)?;
    m.add_function(wrap_pyfunction!(_scalar_seconds, m)?)?;
    Ok(())
}
