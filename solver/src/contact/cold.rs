//! Cold solves: the states of a model at one ρ < 1 found without walking
//! the branch ([`Search::Cold`], the default).
//!
//! The branch is explicit in s (the generated `branch`; for the paper's
//! model (19)–(20) solved for ā³ and δ̄ā). The scan samples it at some of
//! the walk's 4000 points (the same s values), from s∞ towards s → 0,
//! lazily: a solve stops as soon as it has its answer. The stride starts
//! at 160 walk indices and doubles up to 640 while ā, δ̄ and F̄ follow a
//! power law of s∞ − s; it is capped where s would move by more than 4 % of
//! s∞, and where the branch ends between two samples every walk index in
//! between is read. A sample costs one explicit evaluation (ā, δ̄, F̄ and
//! the apex slopes that pick the adhesive root), no state and no Newton.
//!
//! Owns: the cold scan. May use: `control`, its parent `contact`, `model`, `error`.
//! - A crossing of the controlled quantity between two samples is refined
//!   by the Illinois method in u = ln(s∞ − s).
//! - An extremum among three samples is refined by Brent's method in u;
//!   if the controlled quantity there is across the target, the two
//!   crossings it brackets are found the same way (so a pair of crossings
//!   between two samples is not missed).
//! - The start is then solved to round-off by the same Newton iterations
//!   as the walk's: the residuals with the control equation (for the
//!   zero-force state, F̄ = 0), or the fold condition ([`crate::fold`]).
//! - Loads beyond the scan's first sample go to the walk's samples before
//!   it and its large-load continuation ([`Contact::tail`]), from the
//!   walk's first two samples.
//!
//! The walk ([`Search::Walk`]) is kept as the reference: a test compares
//! the two over grids of (ρ, δ̄, ā, F̄) for every model.
//!
//! Owns: [`Scan`] and the cold forms of the searches of [`Contact`]. May
//! use: its parent `contact`, `fold`, `error`.

use super::{value_at, Contact, State, WalkSample, WALK_POINTS};
use crate::control::Quantity;
use crate::error::{Error, Result};
use crate::model::brent_minimum;
use nalgebra::Vector3;

/// Walk samples between two scan samples (at most, where s changes fast,
/// fewer).
const STRIDE: usize = 160;

/// The stride where the branch follows a power law of s∞ − s.
const MAX_STRIDE: usize = 640;

/// One explicit point of the adhesive branch.
#[derive(Clone, Copy, Debug)]
pub(super) struct Point {
    s: f64,
    a: f64,
    delta: f64,
    force: f64,
}

/// ± ln(1 + |v|): a power law of s∞ − s is a straight line in it (`ln`
/// of 1 + |v| rather than `ln_1p`, which costs twice as much; only the
/// shape matters here).
fn signed_log(v: f64) -> f64 {
    (1.0 + v.abs()).ln().copysign(v)
}

impl Point {
    fn key(&self, control: Quantity) -> f64 {
        match control {
            Quantity::Delta => self.delta,
            Quantity::ABar => self.a,
            Quantity::Force => self.force,
        }
    }

    fn z(&self) -> Vector3<f64> {
        Vector3::new(self.a, self.s, self.delta)
    }
}

/// The lazily extended scan of one contact's branch.
pub(super) struct Scan<'c> {
    contact: &'c Contact,
    s_inf: f64,
    /// The next walk index to sample.
    next: usize,
    points: Vec<Point>,
    /// `signed_log` of ā, δ̄, F̄ at each of `points`.
    logs: Vec<[f64; 3]>,
    /// The walk indices of `points`.
    walk_index: Vec<usize>,
    /// The current stride in walk indices.
    stride: usize,
    /// The walk index of the last valid sample.
    last_valid: usize,
    /// Walk indices below this are all sampled (a gap being filled).
    fine_until: usize,
    /// s at the first fold of ā, once it has been refined.
    size_fold: Option<f64>,
}

impl<'c> Scan<'c> {
    pub(super) fn new(contact: &'c Contact) -> Result<Self> {
        Ok(Scan {
            contact,
            s_inf: contact.s_infinity()?,
            next: 1,
            points: Vec::with_capacity(72),
            walk_index: Vec::with_capacity(72),
            logs: Vec::with_capacity(72),
            stride: STRIDE,
            last_valid: 0,
            fine_until: 0,
            size_fold: None,
        })
    }

    /// The i-th sample, extending the scan as needed: from the walk's
    /// first index, every `stride`-th walk index (doubling up to
    /// `MAX_STRIDE` while the branch is steady) while that moves s by less
    /// than 4 % of s∞, closer where s changes faster (towards s → 0, where
    /// the walk's logarithmic spacing in s∞ − s stretches), and the walk's
    /// last index; every index where the branch ends between two samples.
    fn get(&mut self, i: usize) -> Option<Point> {
        while self.points.len() <= i && self.next < WALK_POINTS {
            let k = self.next;
            let sample = self.contact.walk_sample_why(self.s_inf, k);
            let filled = self.last_valid.max(self.fine_until);
            if matches!(sample, WalkSample::NoAdhesivePoint)
                && self.points.len() >= 2
                && k > filled + 1
            {
                // the branch ends (or has a gap) between two samples: every
                // walk index in between, as the walk has them (not where
                // the two roots of a quadratic branch are too close to be
                // told apart, which the walk skips too)
                self.fine_until = k;
                self.next = filled + 1;
                continue;
            }
            if let WalkSample::Point(s, a, delta) = sample {
                let p = self.contact.point(s, a, delta);
                self.points.push(p);
                self.logs
                    .push([signed_log(p.a), signed_log(p.delta), signed_log(p.force)]);
                self.walk_index.push(k);
                self.last_valid = k;
                self.stride = if self.steady() {
                    (2 * self.stride).min(MAX_STRIDE)
                } else {
                    STRIDE
                };
            }
            self.next = if k + 1 < self.fine_until {
                k + 1
            } else {
                // s∞ − s = s∞ d, d = 10^(−c (1 − k/n)): m walk steps move s
                // by s∞ d (10^(c m/n) − 1), at most 4 % of s∞ for
                // m = n/c log10(1 + 0.04/d)
                let d = (self.s_inf - self.contact.walk_s(self.s_inf, k)) / self.s_inf;
                let m = WALK_POINTS as f64 / self.contact.walk_decades() * (0.04 / d).ln_1p()
                    / std::f64::consts::LN_10;
                let stride = (m.floor() as usize).clamp(1, self.stride);
                match k.max(self.fine_until) {
                    k if k + stride < WALK_POINTS => k + stride,
                    k if k < WALK_POINTS - 1 => WALK_POINTS - 1,
                    _ => WALK_POINTS,
                }
            };
        }
        self.points.get(i).copied()
    }

    /// Whether ā, δ̄ and F̄ have changed at a steady rate over the last
    /// three samples: the slopes of ± ln(1 + |value|) in the walk index
    /// agree to 5 %. Near s∞, where the branch follows its
    /// non-adhesive asymptotics over many decades, the stride then doubles.
    fn steady(&self) -> bool {
        let n = self.points.len();
        if n < 3 {
            return false;
        }
        let (y, k) = (&self.logs[n - 3..], &self.walk_index[n - 3..]);
        let (h1, h2) = ((k[1] - k[0]) as f64, (k[2] - k[1]) as f64);
        (0..3).all(|c| {
            let (m1, m2) = ((y[1][c] - y[0][c]) / h1, (y[2][c] - y[1][c]) / h2);
            m1.signum() == m2.signum() && (m2 - m1).abs() <= 0.05 * m1.abs().max(m2.abs())
        })
    }

    /// Every sample.
    fn all(&mut self) -> &[Point] {
        while self.get(self.points.len()).is_some() {}
        &self.points
    }

    /// Whether sample `i` is a local minimum of `sign`·key (below its
    /// predecessor, not above its successor).
    fn is_extremum(&mut self, i: usize, control: Quantity, sign: f64) -> bool {
        if i == 0 {
            return false;
        }
        let (Some(r), Some(q), Some(p)) = (self.get(i - 1), self.get(i), self.get(i + 1)) else {
            return false;
        };
        let (kr, kq, kp) = (
            sign * r.key(control),
            sign * q.key(control),
            sign * p.key(control),
        );
        kq < kr && kq <= kp
    }

    /// The extremum of `sign`·key bracketed by samples i − 1 and i + 1,
    /// refined by Brent's method in u = ln(s∞ − s) to 1e-10 in u.
    fn refine_extremum(&mut self, i: usize, control: Quantity, sign: f64) -> Option<Point> {
        let (lo, hi) = (self.get(i + 1)?.s, self.get(i - 1)?.s);
        let (c, s_inf) = (self.contact, self.s_inf);
        let u = |s: f64| (s_inf - s).max(f64::MIN_POSITIVE).ln();
        let best = brent_minimum(
            |u| {
                c.point_at(s_inf - u.exp())
                    .map(|p| sign * p.key(control))
                    .unwrap_or(f64::INFINITY)
            },
            u(hi),
            u(lo),
            1e-10,
        );
        c.point_at(s_inf - best.exp())
    }

    /// Whether a state at `s`, found at or before sample `i`, lies beyond
    /// the first fold of ā (its first minimum along the branch): false if
    /// no fold is among the samples up to i + 1 or the fold's bracket lies
    /// below `s`; otherwise decided against the fold refined by Brent's
    /// method (computed once per scan).
    fn beyond_size_fold(&mut self, s: f64, i: usize) -> bool {
        if let Some(fold) = self.size_fold {
            return s < fold;
        }
        for j in 1..=i {
            if self.is_extremum(j, Quantity::ABar, 1.0) {
                if self.points[j - 1].s < s {
                    return false;
                }
                // where Brent's point is off the branch, the sample at the
                // minimum stands for the fold
                let fold = self
                    .refine_extremum(j, Quantity::ABar, 1.0)
                    .map_or(self.points[j].s, |p| p.s);
                self.size_fold = Some(fold);
                return s < fold;
            }
        }
        false
    }
}

impl Contact {
    /// The branch point at `s` with ā and δ̄ from the explicit branch.
    fn point(&self, s: f64, a: f64, delta: f64) -> Point {
        let force = self
            .model
            .force_bar(nalgebra::Vector2::new(a, s), self.rho, delta);
        Point { s, a, delta, force }
    }

    /// The adhesive branch point at `s`, if there is one.
    fn point_at(&self, s: f64) -> Option<Point> {
        self.adhesive_point(s).map(|(a, d)| self.point(s, a, d))
    }

    /// The crossing of `control` = `target` between the branch points `lo`
    /// and `hi` (opposite signs), by the Illinois method in u = ln(s∞ − s)
    /// on ± ln(1 + |key|) (near s∞ the branch is a power law of s∞ − s, a
    /// straight line in these variables), to 1e-9 in u: a start for Newton,
    /// which brings it to round-off.
    fn refine_crossing(
        &self,
        s_inf: f64,
        control: Quantity,
        target: f64,
        lo: Point,
        hi: Point,
    ) -> Point {
        let g = |p: &Point| signed_log(p.key(control)) - signed_log(target);
        let u = |s: f64| (s_inf - s).max(f64::MIN_POSITIVE).ln();
        let (mut a, mut fa, mut pa) = (u(lo.s), g(&lo), lo);
        let (mut b, mut fb, mut pb) = (u(hi.s), g(&hi), hi);
        let mut side = 0;
        for _ in 0..100 {
            let mut x = (a * fb - b * fa) / (fb - fa);
            if !(x > a.min(b) && x < a.max(b)) {
                x = 0.5 * (a + b);
            }
            let Some(p) = self.point_at(s_inf - x.exp()).filter(|p| g(p).is_finite()) else {
                // off the branch inside the bracket: the nearer end
                break;
            };
            let fx = g(&p);
            if fx == 0.0 {
                return p;
            }
            let moved = if fx.signum() == fb.signum() {
                let m = (b - x).abs();
                (b, fb, pb) = (x, fx, p);
                if side == -1 {
                    fa *= 0.5;
                }
                side = -1;
                m
            } else {
                let m = (a - x).abs();
                (a, fa, pa) = (x, fx, p);
                if side == 1 {
                    fb *= 0.5;
                }
                side = 1;
                m
            };
            if moved <= 1e-9 * (1.0 + x.abs()) || (b - a).abs() <= 1e-9 * (1.0 + x.abs()) {
                break;
            }
        }
        if fa.abs() <= fb.abs() {
            pa
        } else {
            pb
        }
    }

    /// Solve from the crossing between `lo` and `hi` and flag it.
    fn crossing_state(
        &self,
        scan: &mut Scan,
        i: usize,
        (control, target, what): (Quantity, f64, &str),
        lo: Point,
        hi: Point,
    ) -> Result<State> {
        let start = self.refine_crossing(scan.s_inf, control, target, lo, hi);
        let mut st = self.solve_controlled(start.z(), control, target, what)?;
        st.beyond_size_fold = scan.beyond_size_fold(st.s, i);
        Ok(st)
    }

    /// The crossings of `control` = `target` along the branch from s∞, in
    /// that order: all of them, or only the first. With `stop_at_minimum`
    /// (load control), the search ends at the first minimum of the
    /// controlled quantity, and a target below it is out of range.
    pub(super) fn cold_crossings(
        &self,
        control: Quantity,
        target: f64,
        what: &str,
        first_only: bool,
        stop_at_minimum: bool,
    ) -> Result<Vec<State>> {
        let mut scan = Scan::new(self)?;
        let mut out = Vec::new();
        let Some(p0) = scan.get(0) else {
            return Err(self.no_branch(scan.s_inf));
        };
        // large loads: the walk's samples before the scan's first (where
        // a quadratic branch is mostly ill-conditioned: one by one, as the
        // walk has them) and its continuation from the first two of them
        let mut tail_reach = Vec::new();
        if target > p0.key(control) {
            let first = scan.walk_index[0];
            let state = |(s, a, d): (f64, f64, f64)| self.state_with(a, s, d, false);
            let seq: Vec<State> = (1..first)
                .filter_map(|k| self.walk_sample(scan.s_inf, k))
                .chain(std::iter::once((p0.s, p0.a, p0.delta)))
                .map(state)
                .collect();
            // the continuation starts from the walk's first two samples
            let start: Vec<State> = seq
                .iter()
                .copied()
                .chain(
                    (first + 1..WALK_POINTS)
                        .filter_map(|k| self.walk_sample(scan.s_inf, k))
                        .map(state),
                )
                .take(2)
                .collect();
            let mut all = self.tail(&start);
            let n_tail = all.len();
            all.reverse();
            all.extend(seq.iter().copied());
            for (k, w) in all.windows(2).enumerate() {
                let (f0, f1) = (
                    value_at(control, &w[0]) - target,
                    value_at(control, &w[1]) - target,
                );
                if f0.signum() == f1.signum() || !f0.is_finite() || !f1.is_finite() {
                    continue;
                }
                let z = if k < n_tail {
                    let g = self.tail_guess(&w[0], &w[1], control, target);
                    Vector3::new(g.a_bar, g.s, g.delta_bar)
                } else {
                    let (lo, hi) = (w[1], w[0]);
                    let point = |st: State| self.point(st.s, st.a_bar, st.delta_bar);
                    self.refine_crossing(scan.s_inf, control, target, point(lo), point(hi))
                        .z()
                };
                out.push(self.solve_controlled(z, control, target, what)?);
                if first_only {
                    return Ok(out);
                }
            }
            tail_reach = all
                .iter()
                .map(|st| (value_at(control, st), st.a_bar))
                .collect();
        }
        let io = (control, target, what);
        let mut minimum_seen = false;
        let mut i = 1;
        while let (Some(q), Some(p)) = (scan.get(i - 1), scan.get(i)) {
            let (f0, f1) = (q.key(control) - target, p.key(control) - target);
            if f0.is_finite() && f1.is_finite() && f0.signum() != f1.signum() {
                out.push(self.crossing_state(&mut scan, i, io, p, q)?);
                if first_only {
                    return Ok(out);
                }
            } else if f0.is_finite() && i >= 2 {
                // sample i − 1 an extremum on the far side of the target:
                // two crossings may lie between samples i − 2 and i
                let sign = if f0 > 0.0 { 1.0 } else { -1.0 };
                if scan.is_extremum(i - 1, control, sign) {
                    if let (Some(e), Some(r)) =
                        (scan.refine_extremum(i - 1, control, sign), scan.get(i - 2))
                    {
                        let fe = e.key(control) - target;
                        if fe.is_finite() && fe.signum() != f0.signum() {
                            for (lo, hi) in [(e, r), (p, e)] {
                                out.push(self.crossing_state(&mut scan, i, io, lo, hi)?);
                                if first_only {
                                    return Ok(out);
                                }
                            }
                        } else if stop_at_minimum && sign > 0.0 && !minimum_seen && out.is_empty() {
                            // the first minimum (pull-off) lies above the target
                            return Err(Error::OutOfRange {
                                name: "force",
                                value: target,
                                range: "[pull-off force, ∞) for this rho and model".into(),
                            });
                        }
                    }
                }
            }
            if i >= 2 && scan.is_extremum(i - 1, control, 1.0) {
                minimum_seen = true;
            }
            i += 1;
        }
        if scan.all().len() < 3 {
            return Err(self.no_branch(scan.s_inf));
        }
        if out.is_empty() {
            let reached = scan.all().iter().map(|p| (p.key(control), p.a));
            self.within_reach(control, target, what, reached.chain(tail_reach))?;
        }
        Ok(out)
    }

    /// The first minimum of `control` along the branch from s∞, refined by
    /// Brent's method in ln(s∞ − s): a start for the fold Newton, flagged if it lies
    /// beyond the fold of ā.
    pub(super) fn cold_minimum(&self, control: Quantity, what: &str) -> Result<State> {
        let mut scan = Scan::new(self)?;
        let mut i = 1;
        while scan.get(i + 1).is_some() {
            if scan.is_extremum(i, control, 1.0) {
                let p = scan.refine_extremum(i, control, 1.0).ok_or_else(|| {
                    Error::NoState(format!(
                        "{what}: off the branch near s = {}",
                        scan.points[i].s
                    ))
                })?;
                let mut st = self.state_with(p.a, p.s, p.delta, false);
                st.beyond_size_fold = control != Quantity::ABar && scan.beyond_size_fold(p.s, i);
                return Ok(st);
            }
            i += 1;
        }
        if scan.all().len() < 3 {
            return Err(self.no_branch(scan.s_inf));
        }
        Err(Error::NoState(format!(
            "{what}: no minimum along the branch at rho = {}",
            crate::error::short(self.rho)
        )))
    }

    /// For a model with an energy: the last stable state under
    /// displacement control before the first unstable one along the branch
    /// (bisection in s between two samples, to 1e-12 in s): the start for
    /// the fold Newton.
    pub(super) fn cold_first_unstable(&self) -> Result<State> {
        let stable = |p: &Point| {
            let st = self.state_with(p.a, p.s, p.delta, false).stability;
            st.stable_displacement.is_none() || st.strictly_stable_displacement
        };
        let mut scan = Scan::new(self)?;
        let mut i = 0;
        while let Some(p) = scan.get(i) {
            if !stable(&p) {
                let Some(q) = i.checked_sub(1).and_then(|j| scan.get(j)) else {
                    return Ok(self.state_with(p.a, p.s, p.delta, false));
                };
                let (mut lo, mut hi) = (p, q);
                while hi.s - lo.s > 1e-12 * hi.s {
                    let Some(m) = self.point_at(0.5 * (lo.s + hi.s)) else {
                        break;
                    };
                    if stable(&m) {
                        hi = m;
                    } else {
                        lo = m;
                    }
                }
                return Ok(self.state_with(hi.a, hi.s, hi.delta, false));
            }
            i += 1;
        }
        let all = scan.all();
        if all.len() < 3 {
            return Err(self.no_branch(scan.s_inf));
        }
        Err(self.stable_throughout(all.last().map(|p| p.s)))
    }
}

#[cfg(test)]
mod tests {
    use crate::model::brent_minimum;

    #[test]
    fn brent_finds_a_parabolic_and_a_kinked_minimum() {
        let x = brent_minimum(|x| (x - 0.3).powi(2) + 1.0, -2.0, 5.0, 1e-12);
        assert!((x - 0.3).abs() < 1e-8, "{x}");
        let x = brent_minimum(|x| (x - 1.7).abs(), 0.0, 2.0, 1e-12);
        assert!((x - 1.7).abs() < 1e-10, "{x}");
    }
}
