//! The layer of finite thickness at any ρ, on a grid (issue 71): adhesive
//! contact of two coatings on crossed cylinders, the gap
//! φ̄ = (X² + Y²/ρ)/2 of (1) in the units (17), solved as a
//! boundary-element problem on n × n square cells with a cohesive law of
//! range ρ₀ (`law`) in place of JKR's sharp edge; the JKR limit is
//! ρ₀ → 0 (and the cells → 0), taken by extrapolation.
//!
//! A state at approach δ̄ solves, for the gaps g of the cells,
//! g = φ̄ − δ̄ + A p(g) (A the pair's compliance, `kernel`; p the law), by
//! Newton's method with GMRES for its steps (`gmres`), each product of A
//! two zero-padded FFTs. Its force is F̄ = Δ²Σp. Under displacement
//! control the states from a loaded contact down to the pull-off under
//! displacement control are stable, and F̄(δ̄) has its least value on
//! them at the pull-off under load control, where dF̄/dδ̄ = 0; dF̄/dδ̄
//! comes with each state from one more linear solve.
//!
//! Owns: `Sheet`, `SheetState`, `Work`, `Rung`, `Target`. May use: `layer` (the pair), `error`,
//! `quadrature`, `newton` (the stop request, between rungs), and its own
//! `kernel`, `law`, `gmres`, `bessel0`, `edge`, `bench`, `stability` (a
//! state's least eigenvalues).

#[cfg(feature = "bench-internals")]
pub(crate) mod bench;
mod bessel0;
mod edge;
mod gmres;
pub(crate) mod kernel;
mod law;
pub(crate) mod stability;

use super::Layers;
use crate::error::{rounded, Error, Result};
use kernel::Kernel;
use law::Law;

/// The grid solver of one pair of coatings at one ρ.
pub(crate) struct Sheet {
    n: usize,
    dx: f64,
    law: Law,
    kernel: Kernel,
    /// φ̄ at the cells' centres.
    phi: Vec<f64>,
    /// The work of the states solved on this grid so far.
    work: std::cell::Cell<Work>,
}

/// The work of the states a grid has solved: how many, their Newton steps
/// and their products with the compliance (each GMRES iteration one, and
/// each residual); attempts that failed are not counted.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Work {
    pub(crate) states: usize,
    pub(crate) steps: usize,
    pub(crate) products: usize,
}

impl std::ops::Add for Work {
    type Output = Work;
    fn add(self, o: Work) -> Work {
        Work {
            states: self.states + o.states,
            steps: self.steps + o.steps,
            products: self.products + o.products,
        }
    }
}

/// A state of the grid solver.
#[derive(Clone, Debug)]
pub(crate) struct SheetState {
    pub(crate) delta_bar: f64,
    pub(crate) force_bar: f64,
    /// dF̄/dδ̄ along the branch.
    pub(crate) force_slope: f64,
    /// The gaps of the cells.
    pub(crate) gap: Vec<f64>,
    /// dg/dδ̄ of the cells.
    pub(crate) gap_slope: Vec<f64>,
    /// The contact's half widths along X and Y: where the gap, interpolated
    /// linearly between the cells' centres on the axes' nearest rows,
    /// reaches the law's range ρ₀, where the tension is greatest (the
    /// cohesive zone's counterpart of JKR's edge; the gap is zero further
    /// in, where the pressure changes sign); none where the grid holds no
    /// such point.
    pub(crate) half_widths: (Option<f64>, Option<f64>),
    /// The least gap on the grid's edge, over the range ρ₀: the cohesive
    /// law's tension there is (g/ρ₀)e^(−g/ρ₀) of its scale, which the
    /// grid cuts off (2e-8 at 20 ranges).
    pub(crate) edge_gap: f64,
    /// Newton steps taken.
    pub(crate) steps: usize,
    /// Products with the compliance.
    pub(crate) products: usize,
}

/// The residual each cell's gap equation is solved to, over ρ₀.
const GAP_TOL: f64 = 1e-10;

impl Sheet {
    /// `layers` at `rho` on n × n cells of side `dx` (the grid's half
    /// width n·dx/2), cohesive range `range`.
    pub(crate) fn new(layers: &Layers, rho: f64, n: usize, dx: f64, range: f64) -> Sheet {
        Sheet::on(Kernel::new(layers, n, dx), rho, n, dx, range)
    }

    /// The grid of `kernel` (n × n cells of side `dx`) at `rho`, cohesive
    /// range `range`.
    fn on(kernel: Kernel, rho: f64, n: usize, dx: f64, range: f64) -> Sheet {
        let centre = |i: usize| (i as f64 + 0.5 - 0.5 * n as f64) * dx;
        let mut phi = vec![0.0; n * n];
        for i in 0..n {
            for j in 0..n {
                let (x, y) = (centre(i), centre(j));
                phi[i * n + j] = 0.5 * (x * x + y * y / rho);
            }
        }
        Sheet {
            n,
            dx,
            law: Law { range },
            kernel,
            phi,
            work: Default::default(),
        }
    }

    /// The state at approach δ̄ by Newton's method from the gaps `guess`.
    pub(crate) fn state(&self, delta: f64, guess: &[f64]) -> Result<SheetState> {
        self.solve(self.law, delta, guess)
    }

    /// The state at δ̄ under `law` by Newton's method from `guess`.
    fn solve(&self, law: Law, delta: f64, guess: &[f64]) -> Result<SheetState> {
        let Solved {
            gap,
            p,
            dp,
            steps,
            mut products,
        } = newton(&self.kernel, &self.phi, law, delta, guess)?;
        let ones = vec![-1.0; gap.len()];
        let gap_slope = jacobian_solve(&self.kernel, law, &dp, &ones, 1e-10, &mut products)?;
        let area = self.dx * self.dx;
        let force_bar = area * p.iter().sum::<f64>();
        let force_slope = area * dp.iter().zip(&gap_slope).map(|(d, s)| d * s).sum::<f64>();
        let half_widths = (
            self.crossing(&gap, true, law.range),
            self.crossing(&gap, false, law.range),
        );
        self.work.set(
            self.work.get()
                + Work {
                    states: 1,
                    steps,
                    products,
                },
        );
        let n = self.n;
        let edge_gap = (0..n)
            .flat_map(|k| [gap[k], gap[(n - 1) * n + k], gap[k * n], gap[k * n + n - 1]])
            .fold(f64::INFINITY, f64::min)
            / law.range;
        Ok(SheetState {
            delta_bar: delta,
            force_bar,
            force_slope,
            half_widths,
            edge_gap,
            gap,
            gap_slope,
            steps,
            products,
        })
    }

    /// Where `gap` first rises through `level` going out from the centre
    /// along X (`along_x`) or Y, on the row of cells next to the axis,
    /// interpolated linearly; none within the grid.
    fn crossing(&self, gap: &[f64], along_x: bool, level: f64) -> Option<f64> {
        let n = self.n;
        let at = |k: usize| {
            let (i, j) = if along_x { (k, n / 2) } else { (n / 2, k) };
            gap[i * n + j] - level
        };
        (n / 2..n - 1).find_map(|k| {
            let (g0, g1) = (at(k), at(k + 1));
            (g0 <= 0.0 && g1 > 0.0).then(|| self.centre(k) + self.dx * g0 / (g0 - g1))
        })
    }

    /// The centre of cell k along either axis.
    fn centre(&self, k: usize) -> f64 {
        (k as f64 + 0.5 - 0.5 * self.n as f64) * self.dx
    }

    /// The distance from the centre along X at which the gap of `state`
    /// reaches `gap`: its crossing, or extrapolated from the last two
    /// cells beyond the grid.
    fn reach(&self, state: &SheetState, gap: f64) -> f64 {
        self.crossing(&state.gap, true, gap).unwrap_or_else(|| {
            let n = self.n;
            let at = |k: usize| state.gap[k * n + n / 2];
            let slope = ((at(n - 1) - at(n - 2)) / self.dx).max(1e-300);
            self.centre(n - 1) + (gap - at(n - 1)).max(0.0) / slope
        })
    }

    /// A first guess of the gaps at δ̄: the rigid gap where it is open,
    /// half the range where the bodies overlap.
    pub(crate) fn cold_guess(&self, delta: f64) -> Vec<f64> {
        let r = self.law.range;
        self.phi.iter().map(|f| (f - delta).max(-0.5 * r)).collect()
    }

    /// The state at δ̄ from no guess: solved first with a range 16 times
    /// longer (a wide process zone, an easy Newton), then with the range
    /// halved four times, each from the last.
    pub(crate) fn cold_state(&self, delta: f64) -> Result<SheetState> {
        let mut guess = self.cold_guess(delta);
        for k in (1..=4).rev() {
            let wide = Law {
                range: self.law.range * f64::powi(2.0, k),
            };
            guess = self.solve(wide, delta, &guess)?.gap;
        }
        self.state(delta, &guess)
    }

    /// The gaps of `state`, solved on `coarse`, interpolated bilinearly
    /// onto this grid (the same width): a first guess for this grid's state.
    pub(crate) fn prolong(&self, coarse: &Sheet, state: &SheetState) -> Vec<f64> {
        let (nc, nf) = (coarse.n, self.n);
        let index = |i: usize| {
            let t =
                (self.centre(i) / coarse.dx + 0.5 * nc as f64 - 0.5).clamp(0.0, (nc - 1) as f64);
            let i0 = (t.floor() as usize).min(nc - 2);
            (i0, t - i0 as f64)
        };
        let lerp = |v: &[f64], i: usize, j: usize| {
            let ((i0, u), (j0, w)) = (index(i), index(j));
            let at = |a: usize, b: usize| v[a * nc + b];
            (1.0 - u) * ((1.0 - w) * at(i0, j0) + w * at(i0, j0 + 1))
                + u * ((1.0 - w) * at(i0 + 1, j0) + w * at(i0 + 1, j0 + 1))
        };
        (0..nf * nf)
            .map(|c| lerp(&state.gap, c / nf, c % nf))
            .collect()
    }

    /// The state `target` asks for, from the state `first` on the branch
    /// stable under displacement control: steps of `step` in δ̄, then the
    /// secant to `tol` in δ̄ where a root is sought.
    pub(crate) fn find(
        &self,
        target: Target,
        first: SheetState,
        step: f64,
        tol: f64,
    ) -> Result<SheetState> {
        match target {
            Target::PullOff => self.pull_off_from(first, step, tol),
            Target::Delta(d) => self.to_delta(first, d, step),
            Target::Force(f) => self.to_force(first, f, step, tol),
        }
    }

    /// The first guess of the gaps at `d` from the state `s`: its gaps
    /// moved along their slope in δ̄.
    fn predict(s: &SheetState, d: f64) -> Vec<f64> {
        s.gap
            .iter()
            .zip(&s.gap_slope)
            .map(|(g, v)| g + (d - s.delta_bar) * v)
            .collect()
    }

    /// The state at approach `d` from `first`, in steps of at most `step`
    /// in δ̄ (halved where Newton fails, down to a thousandth), each from
    /// the last one's prediction: the branch stable under displacement
    /// control, which ends at its pull-off in δ̄.
    fn to_delta(&self, first: SheetState, d: f64, step: f64) -> Result<SheetState> {
        let from = first.delta_bar;
        let mut state = first;
        let mut h = step;
        while state.delta_bar != d {
            let next = if (d - state.delta_bar).abs() <= h {
                d
            } else {
                state.delta_bar + h * (d - state.delta_bar).signum()
            };
            match self.state(next, &Self::predict(&state, next)) {
                Ok(s) => state = s,
                Err(_) if h > step * 1e-3 => h *= 0.5,
                Err(e) => {
                    return Err(Error::NoState(format!(
                        "the grid solver: the branch stable under displacement control from delta_bar = {} ends before delta_bar = {} (Newton fails beyond delta_bar = {}: {})",
                        rounded(from),
                        rounded(d),
                        rounded(state.delta_bar),
                        e.detail()
                    )))
                }
            }
        }
        Ok(state)
    }

    /// The state at force `f` from `first` on the branch stable under
    /// load control (dF̄/dδ̄ > 0): steps of `step` in δ̄ towards it until F̄
    /// passes `f`, then the secant (Illinois) on F̄ − f to `tol` in δ̄. A
    /// force below the branch's least, the pull-off's, has none.
    fn to_force(&self, first: SheetState, f: f64, step: f64, tol: f64) -> Result<SheetState> {
        let below = |s: &SheetState| s.force_bar < f;
        if first.force_slope <= 0.0 {
            return Err(Error::NoState(format!(
                "the grid solver: the state at delta_bar = {} is not on the branch stable under load control",
                rounded(first.delta_bar)
            )));
        }
        let up = below(&first);
        let mut state = first;
        let mut h = if up { step } else { -step };
        let mut prev;
        loop {
            let d = state.delta_bar + h;
            match self.state(d, &Self::predict(&state, d)) {
                Ok(next) if next.force_slope <= 0.0 => {
                    return Err(Error::NoState(format!(
                        "the force {} is below the layer's pull-off force in the plane (about {})",
                        rounded(f),
                        rounded(state.force_bar.min(next.force_bar))
                    )))
                }
                Ok(next) => {
                    prev = state;
                    state = next;
                    if below(&state) != up {
                        break;
                    }
                }
                Err(_) if h.abs() > step * 1e-3 => h *= 0.5,
                Err(e) => return Err(e),
            }
        }
        self.secant(prev, state, |s| s.force_bar - f, tol, "F - F0")
    }

    /// The pull-off under load control from `first`: steps of `step` in
    /// δ̄ (down while dF̄/dδ̄ > 0, up while it is not) until dF̄/dδ̄ changes
    /// sign, then the secant on dF̄/dδ̄ to `tol` in δ̄.
    fn pull_off_from(&self, first: SheetState, step: f64, tol: f64) -> Result<SheetState> {
        let down = first.force_slope > 0.0;
        let mut state = first;
        let mut h = if down { step } else { -step };
        let mut prev;
        loop {
            let d = state.delta_bar - h;
            match self.state(d, &Self::predict(&state, d)) {
                Ok(next) => {
                    prev = state;
                    state = next;
                    if (state.force_slope > 0.0) != down {
                        break;
                    }
                }
                Err(_) if h.abs() > step * 1e-3 => h *= 0.5,
                Err(e) => return Err(e),
            }
        }
        self.secant(prev, state, |s| s.force_slope, tol, "dF/d(delta)")
    }

    /// The root in δ̄ of `g` between the states `x` and `y` (where `g`
    /// has opposite signs) by the secant's Illinois variant, to `tol` in
    /// δ̄; `what` names `g` in the error where it does not settle.
    fn secant(
        &self,
        x: SheetState,
        y: SheetState,
        g: impl Fn(&SheetState) -> f64,
        tol: f64,
        what: &str,
    ) -> Result<SheetState> {
        // a: the end where g > 0, b: where it is not
        let (mut a, mut b) = if g(&x) > 0.0 { (x, y) } else { (y, x) };
        // the end replaced last time (true: a), and whether the other end
        // has now been kept twice running
        let mut last: Option<bool> = None;
        let mut kept_twice = false;
        for _ in 0..60 {
            let (fa, fb) = (g(&a), g(&b));
            let (wa, wb) = match (last, kept_twice) {
                (Some(true), true) => (fa, 0.5 * fb),
                (Some(false), true) => (0.5 * fa, fb),
                _ => (fa, fb),
            };
            let d = (a.delta_bar * wb - b.delta_bar * wa) / (wb - wa);
            let near = if (d - a.delta_bar).abs() < (d - b.delta_bar).abs() {
                &a
            } else {
                &b
            };
            let c = self.state(d, &Self::predict(near, d))?;
            if (a.delta_bar - b.delta_bar).abs() < tol || g(&c) == 0.0 {
                return Ok(c);
            }
            // Illinois: halve the weight of the end kept twice running
            let replaces_a = g(&c) > 0.0;
            kept_twice = last == Some(replaces_a);
            last = Some(replaces_a);
            if replaces_a {
                a = c;
            } else {
                b = c;
            }
        }
        Err(Error::Unresolved {
            what: format!("the grid solver: the secant on {what} did not settle in 60 steps"),
            residual: f64::NAN,
        })
    }
}

/// The gaps of a state with the pressures and their slopes, and the
/// work it took.
pub(crate) struct Solved {
    pub(crate) gap: Vec<f64>,
    pub(crate) p: Vec<f64>,
    pub(crate) dp: Vec<f64>,
    pub(crate) steps: usize,
    pub(crate) products: usize,
}

/// The residual R(g) = g − φ̄ + δ̄ − A p(g) for `compliance`,
/// with p and dp/dg.
fn residual(
    compliance: &dyn Compliance,
    phi: &[f64],
    law: Law,
    gap: &[f64],
    delta: f64,
) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let (p, dp): (Vec<f64>, Vec<f64>) = gap.iter().map(|&g| law.pressure(g)).unzip();
    let mut w = vec![0.0; gap.len()];
    compliance.apply(&p, &mut w);
    let r = gap
        .iter()
        .zip(phi)
        .zip(&w)
        .map(|((g, f), w)| g - f + delta - w)
        .collect();
    (r, p, dp)
}

/// A compliance on a row or a grid of cells: its product with the
/// pressures, and its approximate inverse, the stiffness, for the linear
/// steps' preconditioner.
pub(crate) trait Compliance {
    /// The displacements A p.
    fn apply(&self, p: &[f64], out: &mut [f64]);
    /// About A⁻¹ w: the stiffness's product with a displacement.
    fn stiffen(&self, w: &[f64], out: &mut [f64]);
}

/// Solves J v = b, J v = v − A(p′ ⊙ v), by GMRES to the relative residual
/// `tol` (a tenfold miss is an error), preconditioned on the right.
///
/// Where the law is stiff, −p′ ≥ s/2 (s its stiffness at g = 0: the cells
/// in contact and the first of the cohesive zone), the unknown is the
/// pressure's change q = p′v instead of v, and the block there,
/// −(A + diag(1/p′)), a first-kind operator on the contact, is
/// preconditioned by −A⁻¹, the stiffness restricted to those cells (its
/// square-root edges make the product's spectrum cluster, as the
/// Calderón identities say); elsewhere the unknown is v and the
/// preconditioner the identity.
pub(crate) fn jacobian_solve(
    compliance: &dyn Compliance,
    law: Law,
    dp: &[f64],
    b: &[f64],
    tol: f64,
    products: &mut usize,
) -> Result<Vec<f64>> {
    let stiff = 0.5 * law.pressure(0.0).1.abs();
    let in_contact: Vec<bool> = dp.iter().map(|d| -d >= stiff).collect();
    let n = b.len();
    let mut masked = vec![0.0; n];
    let mut y = vec![0.0; n];
    // y = M⁻¹u: −A⁻¹ restricted on the contact, the identity elsewhere
    let precondition = |u: &[f64], masked: &mut [f64], y: &mut [f64]| {
        masked
            .iter_mut()
            .zip(u.iter().zip(&in_contact))
            .for_each(|(m, (u, &c))| *m = if c { *u } else { 0.0 });
        compliance.stiffen(masked, y);
        y.iter_mut()
            .zip(u.iter().zip(&in_contact))
            .for_each(|(y, (u, &c))| *y = if c { -*y } else { *u });
    };
    // v = T y: q/p′ on the contact, y elsewhere
    let to_gap = |y: &[f64], v: &mut [f64]| {
        v.iter_mut()
            .zip(y.iter().zip(dp.iter().zip(&in_contact)))
            .for_each(|(v, (y, (d, &c)))| *v = if c { y / d } else { *y });
    };
    let mut v = vec![0.0; n];
    let mut scaled = vec![0.0; n];
    let mut product = |u: &[f64], out: &mut [f64]| {
        precondition(u, &mut masked, &mut y);
        to_gap(&y, &mut v);
        scaled
            .iter_mut()
            .zip(v.iter().zip(dp))
            .for_each(|(s, (v, d))| *s = v * d);
        compliance.apply(&scaled, out);
        out.iter_mut().zip(&v).for_each(|(o, v)| *o = v - *o);
    };
    let (u, rel, used) = gmres::gmres(&mut product, b, tol, 150, 3000);
    *products += used;
    if rel > 10.0 * tol {
        return Err(Error::Unresolved {
            what: format!(
                "the grid solver's linear step: GMRES reached a relative residual of {} ({} asked)",
                rounded(rel),
                rounded(tol)
            ),
            residual: rel,
        });
    }
    let (mut masked, mut y) = (vec![0.0; n], vec![0.0; n]);
    precondition(&u, &mut masked, &mut y);
    let mut x = vec![0.0; n];
    to_gap(&y, &mut x);
    Ok(x)
}

/// The gap equations g = φ̄ − δ̄ + A p(g) at approach δ̄ for the
/// `compliance` and the rigid gap `phi`, by Newton's method from
/// `guess`, each step by GMRES and a backtracking line search (a step that
/// lowers ‖R‖ by no fraction of itself down to 1e-6 of its length is an
/// error, not a state), until every residual is below 1e-10 of the law's
/// range.
pub(crate) fn newton(
    compliance: &dyn Compliance,
    phi: &[f64],
    law: Law,
    delta: f64,
    guess: &[f64],
) -> Result<Solved> {
    let mut gap = guess.to_vec();
    let tol = GAP_TOL * law.range;
    let mut products = 0;
    let (mut r, mut p, mut dp) = residual(compliance, phi, law, &gap, delta);
    let inf = |v: &[f64]| v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let l2 = |v: &[f64]| v.iter().map(|x| x * x).sum::<f64>().sqrt();
    let mut steps = 0;
    // where Newton stops short: `why`, and the residual left
    let stalled = |why: &str, r: &[f64]| Error::Unresolved {
        what: format!(
            "the grid solver at delta_bar = {}: {why} (the gap residual is {} of the range)",
            rounded(delta),
            rounded(inf(r) / law.range)
        ),
        residual: inf(r) / law.range,
    };
    while inf(&r) > tol {
        if steps == 60 {
            return Err(stalled("60 Newton steps do not converge", &r));
        }
        steps += 1;
        let minus_r: Vec<f64> = r.iter().map(|x| -x).collect();
        let forcing = (1e-3f64).min(l2(&r).sqrt()).max(1e-12);
        let s = jacobian_solve(compliance, law, &dp, &minus_r, forcing, &mut products)?;
        let norm0 = l2(&r);
        let mut lambda = 1.0;
        loop {
            let trial: Vec<f64> = gap.iter().zip(&s).map(|(g, s)| g + lambda * s).collect();
            let (r1, p1, dp1) = residual(compliance, phi, law, &trial, delta);
            if l2(&r1) < (1.0 - 1e-4 * lambda) * norm0 {
                gap = trial;
                r = r1;
                p = p1;
                dp = dp1;
                break;
            }
            lambda *= 0.5;
            if lambda < 1e-6 {
                return Err(stalled(
                    "Newton's step lowers the residual by no fraction of itself down to a millionth of its length",
                    &r,
                ));
            }
        }
    }
    Ok(Solved {
        gap,
        p,
        dp,
        steps,
        products,
    })
}

/// The most cells per side a grid may have (a grid of 2048² cells holds
/// 4M unknowns and pads to 4096², 270 MB per complex array).
pub(crate) const MAX_CELLS: usize = 2048;
/// The least gap on a grid's edge, in ranges, that a state may have: the
/// law's tension beyond it, cut off by the grid, is below 4e-8 of its peak.
pub(crate) const EDGE_GAP: f64 = 20.0;
/// The gap, in ranges, at which a grid's edge is placed from the last
/// rung's state.
const EDGE_AIM: f64 = 24.0;

/// One pull-off of a ladder: the process zone ε (a fraction of the contact
/// size scale, the smaller of the two limits' pull-off radii), the cells
/// across it, the grid's cells per side and half width, the state, and
/// the seconds it took.
#[derive(Clone, Debug)]
pub(crate) struct Rung {
    pub(crate) eps: f64,
    pub(crate) cells_per_zone: f64,
    pub(crate) n: usize,
    pub(crate) width: f64,
    pub(crate) state: SheetState,
    /// The work of the rung's whole search, on every grid it tried.
    pub(crate) work: Work,
    pub(crate) seconds: f64,
}

/// What a ladder finds on each of its grids.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Target {
    /// The pull-off under load control.
    PullOff,
    /// The state at approach δ̄ on the branch stable under displacement
    /// control.
    Delta(f64),
    /// The state at force F̄ on the branch stable under load control.
    Force(f64),
}

/// The pull-offs under load control of `layers` at `rho` on a ladder of
/// (process zone ε, cells across it): [`ladder`] for [`Target::PullOff`].
pub(crate) fn pull_off_ladder(
    layers: &Layers,
    rho: f64,
    rungs: &[(f64, f64)],
    tell: &mut dyn FnMut(&Rung),
) -> Result<Vec<Rung>> {
    ladder(layers, rho, Target::PullOff, rungs, tell)
}

/// The states `target` asks for of `layers` at `rho` on a ladder of
/// (process zone ε, cells across it), each from the last one's state (its
/// gaps interpolated onto the next grid, solved at its δ̄), the first from
/// a loaded state. Each grid's edge is placed where the last state's gap
/// reaches 24 of the next range (the first grid's at 1.9 size scales); a
/// state whose edge gap is below 20 ranges is solved again on a grid a
/// fifth wider. `tell` hears each rung as it is found.
pub(crate) fn ladder(
    layers: &Layers,
    rho: f64,
    target: Target,
    rungs: &[(f64, f64)],
    tell: &mut dyn FnMut(&Rung),
) -> Result<Vec<Rung>> {
    let a = layers.radius_guess();
    let mut out: Vec<Rung> = Vec::new();
    let mut last: Option<(Sheet, SheetState)> = None;
    for &(eps, cells_per_zone) in rungs {
        crate::newton::check_stop()?;
        let t = std::time::Instant::now();
        let (range, dx) = scales(layers, eps, cells_per_zone);
        let mut width = match &last {
            None => 1.9 * a,
            Some((s, st)) => {
                let reach = s.reach(st, EDGE_AIM * range);
                st.half_widths.0.map_or(reach, |a| reach.max(1.05 * a))
            }
        };
        let mut work = Work::default();
        let found = loop {
            let n = 2 * (width / dx).ceil() as usize;
            if n > MAX_CELLS {
                return Err(Error::Unsupported {
                    name: "cells",
                    value: n as f64,
                    supported: format!("at most {MAX_CELLS} per side (process zone {eps}, {cells_per_zone} cells across it)").into(),
                });
            }
            let sheet = Sheet::new(layers, rho, n, dx, range);
            let (first, step) = match &last {
                None => {
                    let first = sheet.cold_state(START * a * a)?;
                    if first.force_slope <= 0.0 {
                        return Err(Error::NoState(format!(
                            "the grid solver: the state at delta_bar = {} is not above the pull-off",
                            rounded(START * a * a)
                        )));
                    }
                    (first, 0.05 * a * a)
                }
                Some((s, st)) => (
                    sheet.state(st.delta_bar, &sheet.prolong(s, st))?,
                    0.01 * a * a,
                ),
            };
            let st = sheet.find(target, first, step, 1e-7 * a * a)?;
            work = work + sheet.work.get();
            if st.edge_gap >= EDGE_GAP {
                break (sheet, st, n);
            }
            if width > 4.0 * a {
                return Err(Error::Unresolved {
                    what: format!(
                        "the grid solver's pull-off: the gap at the grid's edge is {} ranges at a half width of {} size scales",
                        rounded(st.edge_gap),
                        rounded(width / a)
                    ),
                    residual: st.edge_gap,
                });
            }
            width *= 1.2;
        };
        let (sheet, st, n) = found;
        out.push(Rung {
            eps,
            cells_per_zone,
            n,
            width: sheet.dx * n as f64 / 2.0,
            state: st.clone(),
            work,
            seconds: t.elapsed().as_secs_f64(),
        });
        tell(out.last().expect("pushed"));
        last = Some((sheet, st));
    }
    Ok(out)
}

/// The law's range and the cells' side of a rung: a process zone ε of the
/// size scale a, ℓ = 4βe²ρ₀² (about E*Δγ/σ²max), `cells_per_zone` cells
/// across it.
fn scales(layers: &Layers, eps: f64, cells_per_zone: f64) -> (f64, f64) {
    let zone = eps * layers.radius_guess();
    let range = (zone / (4.0 * layers.beta() * std::f64::consts::E.powi(2))).sqrt();
    (range, zone / cells_per_zone)
}

impl Rung {
    /// The grid this rung's state was solved on, for `layers` at `rho`.
    pub(crate) fn sheet(&self, layers: &Layers, rho: f64) -> Sheet {
        let (range, dx) = scales(layers, self.eps, self.cells_per_zone);
        Sheet::new(layers, rho, self.n, dx, range)
    }
}

/// Where a ladder's first pull-off search starts, in δ̄ over the size
/// scale squared: above the pull-off of both limits.
const START: f64 = 0.35;

/// The JKR limit of three pull-offs (ε, F̄) at process zones ε (any order,
/// distinct): the F̄₀ of F̄ = F̄₀ + Aε + Bε ln ε through them. The form is
/// measured, not derived: at ρ = 1 and h/L = 1 the errors of the pull-offs
/// at ε = 0.2 … 0.0125 against the axisymmetric reference fall as it says
/// (docs/thickness.md), and through ε = 0.05, 0.025, 0.0125 it meets the
/// reference to 2.5e-4. Three process zones that are not distinct and
/// positive have no limit.
pub(crate) fn jkr_limit(points: [(f64, f64); 3]) -> Result<f64> {
    let row = |(e, _): (f64, f64)| [1.0, e, e * e.ln()];
    let m = nalgebra::Matrix3::from_rows(&points.map(|p| nalgebra::RowVector3::from(row(p))));
    let f = nalgebra::Vector3::from(points.map(|p| p.1));
    m.lu()
        .solve(&f)
        .filter(|c| c[0].is_finite())
        .map(|c| c[0])
        .ok_or_else(|| {
            Error::Usage("the JKR limit needs three distinct positive process zones".into())
        })
}

#[cfg(test)]
pub(crate) mod tables;
#[cfg(test)]
mod tests;
