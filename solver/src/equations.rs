//! The one interface of a model's equations, for models of any number of
//! unknowns: the closure's residuals r(x; ρ, δ̄) in the model's unknowns x
//! at fixed (ρ, δ̄) with their Jacobian side by side, ∂r/∂δ̄, F̄ with its
//! gradient, ā, the domain and what makes a state a contact. The dimension
//! is the model's: static `U2` for the ellipse models (x = (ā, s); every
//! generated [`Model`] has it through a blanket implementation), `Dyn` for
//! `conformal:K` (x = c₁ … c_K).
//!
//! Written once against it: [`Branch`], a model's solution curve at fixed ρ
//! as a family of the continuation engine in u = (x, δ̄) (one dimension
//! more: static `U3` for the ellipse models); the curve of every model, the
//! pull-off across folds of `conformal:K` and its arms are traced through
//! it. [`held`]: the state equations under a control (δ̄, F̄ or ā), the
//! bordered system every model's state at given δ̄, F̄ or ā solves. Newton's
//! method is [`crate::newton::damped`], also written once for any
//! dimension.
//!
//! Owns: [`Equations`], [`Linearised`], [`Branch`], [`held`]. May use: `generated` (`ModelId`), `control`, `fold`, `model`, `continuation`,
//! `error`, `contact` and `conformal` (the two kinds of model it is
//! implemented for), nalgebra.

use crate::continuation::{Family, Linear};
use crate::control::Hold;
use crate::error::{short, Error, Result};
use crate::model::Model;
use nalgebra::allocator::Allocator;
use nalgebra::{
    DefaultAllocator, Dim, DimAdd, DimMin, DimName, DimSum, OMatrix, OVector, Vector2, U1, U2,
};

/// A model's equations at fixed (ρ, δ̄) in its unknowns x.
pub(crate) trait Equations
where
    DefaultAllocator: Allocator<Self::Dim> + Allocator<Self::Dim, Self::Dim>,
{
    /// The number of unknowns.
    type Dim: Dim + DimMin<Self::Dim, Output = Self::Dim> + DimAdd<U1>;
    /// Its value (for dynamic dimensions, the model's K).
    fn dim(&self) -> Self::Dim;
    /// The model's name, for messages.
    fn label(&self) -> String;
    /// The residuals and their Jacobian ∂r/∂x, side by side.
    fn residuals_and_jacobian(
        &self,
        x: &OVector<f64, Self::Dim>,
        rho: f64,
        delta_bar: f64,
    ) -> (OVector<f64, Self::Dim>, OMatrix<f64, Self::Dim, Self::Dim>);
    /// ∂r/∂δ̄.
    fn residuals_d_delta(
        &self,
        x: &OVector<f64, Self::Dim>,
        rho: f64,
        delta_bar: f64,
    ) -> OVector<f64, Self::Dim>;
    /// F̄ and its gradient (∂F̄/∂x, ∂F̄/∂δ̄).
    fn force_bar(
        &self,
        x: &OVector<f64, Self::Dim>,
        rho: f64,
        delta_bar: f64,
    ) -> (f64, OVector<f64, Self::Dim>, f64);
    /// Everything at once (a model whose quantities share their work, such
    /// as `conformal:K`'s one evaluation of Π̄ and its derivatives,
    /// overrides this).
    fn linearised(
        &self,
        x: &OVector<f64, Self::Dim>,
        rho: f64,
        delta_bar: f64,
    ) -> Linearised<Self::Dim> {
        let (r, j) = self.residuals_and_jacobian(x, rho, delta_bar);
        let (force, force_x, force_delta) = self.force_bar(x, rho, delta_bar);
        Linearised {
            r,
            j,
            r_delta: self.residuals_d_delta(x, rho, delta_bar),
            force,
            force_x,
            force_delta,
        }
    }
    /// ā = g·x: the constant gradient g.
    fn a_bar_gradient(&self) -> OVector<f64, Self::Dim>;
    /// The residuals' magnitude at x: their convergence test is ‖r‖/scale.
    fn residual_scale(&self, x: &OVector<f64, Self::Dim>, delta_bar: f64) -> f64;
    /// Whether the equations are defined at x.
    fn in_domain(&self, _x: &OVector<f64, Self::Dim>) -> bool {
        true
    }
    /// Whether the state at x is a contact (for `conformal:K`: the map is
    /// one-to-one); the error says why not.
    fn admissible(&self, _x: &OVector<f64, Self::Dim>) -> Result<()> {
        Ok(())
    }
    /// ā and s at x, for messages.
    fn size_and_shape(&self, x: &OVector<f64, Self::Dim>) -> (f64, f64);
}

/// A model's equations and F̄ with their derivatives at one point.
pub(crate) struct Linearised<D: Dim>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    /// r.
    pub r: OVector<f64, D>,
    /// ∂r/∂x.
    pub j: OMatrix<f64, D, D>,
    /// ∂r/∂δ̄.
    pub r_delta: OVector<f64, D>,
    /// F̄.
    pub force: f64,
    /// ∂F̄/∂x.
    pub force_x: OVector<f64, D>,
    /// ∂F̄/∂δ̄.
    pub force_delta: f64,
}

/// Every generated model of the ellipse: x = (ā, s), static `U2`.
impl<M: Model + ?Sized> Equations for M {
    type Dim = U2;
    fn dim(&self) -> U2 {
        U2::name()
    }
    fn label(&self) -> String {
        self.info().name.to_string()
    }
    fn residuals_and_jacobian(
        &self,
        x: &Vector2<f64>,
        rho: f64,
        delta_bar: f64,
    ) -> (Vector2<f64>, nalgebra::Matrix2<f64>) {
        Model::residuals_and_jacobian(self, *x, rho, delta_bar)
    }
    fn residuals_d_delta(&self, x: &Vector2<f64>, rho: f64, delta_bar: f64) -> Vector2<f64> {
        Model::residuals_d_delta(self, *x, rho, delta_bar)
    }
    fn force_bar(&self, x: &Vector2<f64>, rho: f64, delta_bar: f64) -> (f64, Vector2<f64>, f64) {
        let g = Model::force_bar_gradient(self, *x, rho, delta_bar);
        (
            Model::force_bar(self, *x, rho, delta_bar),
            Vector2::new(g[0], g[1]),
            g[2],
        )
    }
    fn a_bar_gradient(&self) -> Vector2<f64> {
        Vector2::new(1.0, 0.0)
    }
    fn residual_scale(&self, x: &Vector2<f64>, delta_bar: f64) -> f64 {
        Model::residual_scale(self, x[0], delta_bar)
    }
    fn in_domain(&self, x: &Vector2<f64>) -> bool {
        x[0] > 0.0 && x[1] > 0.0 && x[1] <= 1.0
    }
    fn size_and_shape(&self, x: &Vector2<f64>) -> (f64, f64) {
        (x[0], x[1])
    }
}

/// The dimension of u = (x, δ̄).
pub(crate) type WithDelta<E> = DimSum<<E as Equations>::Dim, U1>;

/// A model's solution curve at fixed ρ as a family of the continuation
/// engine: the equations r(x; ρ, δ̄) = 0 in u = (x, δ̄), each unknown
/// divided by its `scale` (so that a unit step means a comparable change).
pub(crate) struct Branch<'a, E: Equations + ?Sized>
where
    DefaultAllocator: Allocator<E::Dim> + Allocator<E::Dim, E::Dim> + Allocator<WithDelta<E>>,
{
    /// The model.
    pub equations: &'a E,
    /// ρ.
    pub rho: f64,
    /// The scale of each unknown of u.
    pub scale: OVector<f64, WithDelta<E>>,
    /// Whether a state that is not a contact ([`Equations::admissible`])
    /// ends the trace with an error (`false`: the caller checks).
    pub strict: bool,
}

impl<E: Equations + ?Sized> Branch<'_, E>
where
    DefaultAllocator: Allocator<E::Dim> + Allocator<E::Dim, E::Dim> + Allocator<WithDelta<E>>,
{
    /// (x, δ̄) of the scaled u.
    pub(crate) fn split(&self, u: &OVector<f64, WithDelta<E>>) -> (OVector<f64, E::Dim>, f64) {
        let k = self.equations.dim();
        let n = k.value();
        let x = OVector::<f64, E::Dim>::from_fn_generic(k, U1, |i, _| u[i] * self.scale[i]);
        (x, u[n] * self.scale[n])
    }

    /// The scaled u of (x, δ̄).
    pub(crate) fn join(
        &self,
        x: &OVector<f64, E::Dim>,
        delta_bar: f64,
    ) -> OVector<f64, WithDelta<E>> {
        let n = x.len();
        let dim = self.scale.shape_generic().0;
        OVector::<f64, WithDelta<E>>::from_fn_generic(dim, U1, |i, _| {
            if i < n {
                x[i] / self.scale[i]
            } else {
                delta_bar / self.scale[n]
            }
        })
    }
}

/// Unit scales for u = (x, δ̄).
pub(crate) fn unit_scale<E: Equations + ?Sized>(e: &E) -> OVector<f64, WithDelta<E>>
where
    DefaultAllocator: Allocator<E::Dim> + Allocator<E::Dim, E::Dim> + Allocator<WithDelta<E>>,
{
    let dim = e.dim().add(U1);
    OVector::<f64, WithDelta<E>>::from_element_generic(dim, U1, 1.0)
}

impl<E: Equations + ?Sized> Family<WithDelta<E>> for Branch<'_, E>
where
    WithDelta<E>: DimMin<WithDelta<E>, Output = WithDelta<E>>,
    DefaultAllocator: Allocator<E::Dim>
        + Allocator<E::Dim, E::Dim>
        + Allocator<WithDelta<E>>
        + Allocator<WithDelta<E>, WithDelta<E>>,
{
    fn linearise(&self, u: &OVector<f64, WithDelta<E>>) -> Option<Linear<WithDelta<E>>> {
        let (x, d) = self.split(u);
        let n = x.len();
        let Linearised {
            r,
            j,
            r_delta: rd,
            force,
            force_x: gx,
            force_delta: gd,
        } = self.equations.linearised(&x, self.rho, d);
        let dim = self.scale.shape_generic().0;
        let sc = &self.scale;
        let rr =
            OVector::<f64, WithDelta<E>>::from_fn_generic(
                dim,
                U1,
                |i, _| {
                    if i < n {
                        r[i]
                    } else {
                        0.0
                    }
                },
            );
        let jj = OMatrix::<f64, WithDelta<E>, WithDelta<E>>::from_fn_generic(dim, dim, |i, k| {
            if i >= n {
                0.0
            } else if k < n {
                j[(i, k)] * sc[k]
            } else {
                rd[i] * sc[n]
            }
        });
        let grad = OVector::<f64, WithDelta<E>>::from_fn_generic(dim, U1, |k, _| {
            if k < n {
                gx[k] * sc[k]
            } else {
                gd * sc[n]
            }
        });
        let finite = rr.iter().chain(jj.iter()).all(|v| v.is_finite()) && force.is_finite();
        finite.then_some(Linear {
            r: rr,
            j: jj,
            force,
            force_grad: grad,
        })
    }

    fn converged(&self, u: &OVector<f64, WithDelta<E>>, r: &OVector<f64, WithDelta<E>>) -> bool {
        let (x, d) = self.split(u);
        let n = x.len();
        r.rows(0, n).norm() / self.equations.residual_scale(&x, d) < 1e-10
    }

    fn in_domain(&self, u: &OVector<f64, WithDelta<E>>) -> bool {
        self.equations.in_domain(&self.split(u).0)
    }

    fn admissible(&self, u: &OVector<f64, WithDelta<E>>) -> Result<()> {
        if self.strict {
            self.equations.admissible(&self.split(u).0)
        } else {
            Ok(())
        }
    }

    fn a_bar_gradient(&self) -> OVector<f64, WithDelta<E>> {
        let g = self.equations.a_bar_gradient();
        let n = g.len();
        let dim = self.scale.shape_generic().0;
        OVector::<f64, WithDelta<E>>::from_fn_generic(dim, U1, |i, _| {
            if i < n {
                g[i] * self.scale[i]
            } else {
                0.0
            }
        })
    }

    fn delta_bar_gradient(&self) -> OVector<f64, WithDelta<E>> {
        let n = self.scale.len() - 1;
        let dim = self.scale.shape_generic().0;
        OVector::<f64, WithDelta<E>>::from_fn_generic(dim, U1, |i, _| {
            if i == n {
                self.scale[n]
            } else {
                0.0
            }
        })
    }

    fn stuck(&self, u: &OVector<f64, WithDelta<E>>, why: &str) -> Error {
        let (x, d) = self.split(u);
        let (a, s) = self.equations.size_and_shape(&x);
        Error::NoState(format!(
            "the {} branch at rho = {} stopped at a_bar = {:.4}, s = {:.4}, delta_bar = {}: {why}",
            self.equations.label(),
            short(self.rho),
            a,
            s,
            crate::error::rounded(d)
        ))
    }
}

/// The state equations at u = (x, δ̄) (unscaled) under a control: the
/// model's residuals r(x; ρ, δ̄) and the control equation (δ̄, F̄ or ā minus
/// its target), with their Jacobian in u (the bordered system
/// [∂r/∂x ∂r/∂δ̄; ∇ control]); and the residuals' scale. Written once for
/// every model: the state at given δ̄, F̄ or ā solves this.
#[allow(clippy::type_complexity)]
pub(crate) fn held<E: Equations + ?Sized>(
    e: &E,
    u: &OVector<f64, WithDelta<E>>,
    rho: f64,
    hold: Hold,
) -> (
    OVector<f64, WithDelta<E>>,
    OMatrix<f64, WithDelta<E>, WithDelta<E>>,
    f64,
)
where
    DefaultAllocator: Allocator<E::Dim>
        + Allocator<E::Dim, E::Dim>
        + Allocator<WithDelta<E>>
        + Allocator<WithDelta<E>, WithDelta<E>>,
{
    let k = e.dim();
    let n = k.value();
    let x = OVector::<f64, E::Dim>::from_fn_generic(k, U1, |i, _| u[i]);
    let d = u[n];
    let l = e.linearised(&x, rho, d);
    let ga = e.a_bar_gradient();
    let dim = u.shape_generic().0;
    let r = OVector::<f64, WithDelta<E>>::from_fn_generic(dim, U1, |i, _| {
        if i < n {
            l.r[i]
        } else {
            match hold {
                Hold::Delta(t) => d - t,
                Hold::Force(t) => l.force - t,
                Hold::Size(t) => ga.dot(&x) - t,
            }
        }
    });
    let j = OMatrix::<f64, WithDelta<E>, WithDelta<E>>::from_fn_generic(dim, dim, |i, c| {
        match (i < n, c < n) {
            (true, true) => l.j[(i, c)],
            (true, false) => l.r_delta[i],
            (false, col_x) => match hold {
                Hold::Delta(_) => f64::from(u8::from(!col_x)),
                Hold::Force(_) if col_x => l.force_x[c],
                Hold::Force(_) => l.force_delta,
                Hold::Size(_) if col_x => ga[c],
                Hold::Size(_) => 0.0,
            },
        }
    });
    (r, j, e.residual_scale(&x, d))
}

#[cfg(test)]
mod tests {
    //! The interface's Jacobians against central differences of its own
    //! residuals, for a static (the paper's model) and a dynamic
    //! (`conformal:4`) member; the branch's scaling round-trips.

    use super::*;
    use crate::conformal::Conformal;
    use crate::contact::Contact;
    use crate::generated::ModelId;
    use nalgebra::{DVector, Vector3};

    /// max |J − J_fd| / (1 + |J|) over the entries, J_fd by central
    /// differences of `held`'s residuals.
    fn mismatch<E: Equations + ?Sized>(
        e: &E,
        u: &OVector<f64, WithDelta<E>>,
        rho: f64,
        hold: Hold,
    ) -> f64
    where
        DefaultAllocator: Allocator<E::Dim>
            + Allocator<E::Dim, E::Dim>
            + Allocator<WithDelta<E>>
            + Allocator<WithDelta<E>, WithDelta<E>>,
    {
        let (_, j, _) = held(e, u, rho, hold);
        let n = u.len();
        let mut worst: f64 = 0.0;
        for c in 0..n {
            let h = 1e-6 * (1.0 + u[c].abs());
            let (mut up, mut um) = (u.clone(), u.clone());
            up[c] += h;
            um[c] -= h;
            let (rp, _, _) = held(e, &up, rho, hold);
            let (rm, _, _) = held(e, &um, rho, hold);
            for i in 0..n {
                let fd = (rp[i] - rm[i]) / (2.0 * h);
                worst = worst.max((j[(i, c)] - fd).abs() / (1.0 + j[(i, c)].abs()));
            }
        }
        worst
    }

    #[test]
    fn held_jacobians_match_central_differences() {
        let st = Contact::new(0.8).unwrap().at_displacement(2.0).unwrap();
        let model = ModelId::Max.model();
        let u = Vector3::new(st.a_bar, st.s, st.delta_bar);
        for hold in [Hold::Delta(2.0), Hold::Force(8.0), Hold::Size(3.0)] {
            let m = mismatch(model, &u, 0.8, hold);
            assert!(m < 1e-6, "max, {hold:?}: {m:e}");
        }
        let c4 = Conformal::member("conformal", 4).unwrap();
        let st = c4.solve(0.8, Hold::Force(1.0)).unwrap();
        let u = DVector::from_vec(st.coefficients.clone()).push(st.delta_bar);
        for hold in [Hold::Delta(1.0), Hold::Force(1.0), Hold::Size(3.0)] {
            let m = mismatch(&c4, &u, 0.8, hold);
            assert!(m < 1e-6, "conformal:4, {hold:?}: {m:e}");
        }
        // the state solves its own held system
        let (r, _, scale) = held(&c4, &u, 0.8, Hold::Force(1.0));
        assert!(r.norm() / scale < 1e-10, "{}", r.norm());
    }

    #[test]
    fn the_branch_scaling_round_trips() {
        let model = ModelId::Max.model();
        let b = Branch {
            equations: model,
            rho: 0.8,
            scale: Vector3::new(3.0, 0.1, 2.0),
            strict: true,
        };
        let u = b.join(&nalgebra::Vector2::new(3.2, 0.9), 2.5);
        assert_eq!(u, Vector3::new(3.2 / 3.0, 0.9 / 0.1, 1.25));
        let (x, d) = b.split(&u);
        assert!(
            (x[0] - 3.2).abs() < 1e-15 && (x[1] - 0.9).abs() < 1e-15 && (d - 2.5).abs() < 1e-15
        );
    }

    /// The same few lines of the one engine find the load-controlled
    /// pull-off of the paper's model (u = (ā, s, δ̄), static) and of
    /// `conformal:4` (u = (c₁ … c₄, δ̄), dynamic), each where the model's
    /// own pull-off search puts it.
    #[test]
    fn one_engine_finds_the_pull_off_of_a_static_and_a_dynamic_model() {
        use crate::continuation::{trace, EventKind, On, Settings, Watch};
        use crate::fold::FoldCondition;
        use nalgebra::Vector2;
        let watch = Watch {
            force_minimum: On::Stop,
            ..Watch::default()
        };
        let settings = Settings {
            step: 0.01,
            max_step: 0.02,
            ..Settings::default()
        };

        // the paper's model, from its state at δ̄ = 2
        let st = Contact::new(0.8).unwrap().at_displacement(2.0).unwrap();
        let branch = Branch {
            equations: ModelId::Max.model(),
            rho: 0.8,
            scale: Vector3::new(1.0, 1.0, 1.0),
            strict: true,
        };
        let u0 = branch.join(&Vector2::new(st.a_bar, st.s), st.delta_bar);
        let t = trace(
            &branch,
            u0,
            &Vector3::new(0.0, 0.0, -1.0),
            settings,
            watch,
            |_| false,
        )
        .unwrap();
        let u = t.located(EventKind::ForceMinimum).expect("the pull-off");
        let (x, delta) = branch.split(u);
        let pull = Contact::new(0.8).unwrap().pull_off_load().unwrap().state;
        assert!((x[0] - pull.a_bar).abs() < 1e-7 && (delta - pull.delta_bar).abs() < 1e-7);

        // conformal:4, from its state at ā = 2.6, towards smaller ā
        let m = Conformal::member("conformal", 4).unwrap();
        let st = m.solve(0.8, Hold::Size(2.6)).unwrap();
        let branch = Branch {
            equations: &m,
            rho: 0.8,
            scale: unit_scale(&m),
            strict: true,
        };
        let u0 = DVector::from_vec(st.coefficients.clone()).push(st.delta_bar);
        let towards = DVector::from_fn(5, |i, _| if i < 4 { -1.0 } else { 0.0 });
        let t = trace(&branch, u0, &towards, settings, watch, |_| false).unwrap();
        let u = t.located(EventKind::ForceMinimum).expect("the pull-off");
        let (pull, _) = m.pull_off(0.8, FoldCondition::Load).unwrap();
        assert!((u[4] - pull.delta_bar).abs() < 1e-7);
    }
}
