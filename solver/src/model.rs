//! The model equations as a trait, implemented by each generated module
//! (`crate::generated::*`): residuals (19)–(20) and their Jacobian side by
//! side, ∂/∂δ̄, ξ (15)₁, F̄ (18, derived form), η (16), the error measure (14)
//! and the explicit branch. Nothing here is written by hand: every method
//! forwards to generated code.
//!
//! Owns: [`Model`], [`Paper`], [`Apex45`]. May use: `generated`.

use crate::generated;

/// One ansatz's generated equations, in the dimensionless variables of (17).
pub trait Model {
    /// The ansatz identifier.
    const NAME: &'static str;
    /// η(s), Eq. (16).
    fn eta(s: f64) -> f64;
    /// dη/ds.
    fn eta_s(s: f64) -> f64;
    /// Quantity (14) as a fraction.
    fn bc_error(s: f64) -> f64;
    /// Residuals (19), (20) and the Jacobian ∂(r1, r2)/∂(ā, s).
    fn residuals_and_jacobian(
        a_bar: f64,
        s: f64,
        rho: f64,
        delta_bar: f64,
    ) -> ([f64; 2], [[f64; 2]; 2]);
    /// ∂(r1, r2)/∂δ̄.
    fn residuals_d_delta(a_bar: f64, s: f64, rho: f64, delta_bar: f64) -> [f64; 2];
    /// ξ, first line of (15).
    fn xi(a_bar: f64, s: f64, delta_bar: f64) -> f64;
    /// F̄, derived form of (18).
    fn force_bar(a_bar: f64, s: f64, delta_bar: f64) -> f64;
    /// p̄₀ = p₀/(√(2mΔγ) L).
    fn p0_bar(a_bar: f64, xi: f64, s: f64) -> f64;
    /// The branch at fixed ρ, explicit in s: (ā³, δ̄ā).
    fn branch(s: f64, rho: f64) -> [f64; 2];
    /// The shape parameters of the ansatz from the collocation (10).
    fn shape(a: f64, s: f64, xi: f64) -> [f64; 2];
    /// The pressure field (5) with (10).
    fn pressure(x: f64, y: f64, p0: f64, a: f64, s: f64, xi: f64) -> f64;
}

macro_rules! impl_model {
    ($ty:ident, $m:ident, $doc:literal) => {
        #[doc = $doc]
        #[derive(Clone, Copy, Debug, Default)]
        pub struct $ty;
        impl Model for $ty {
            const NAME: &'static str = stringify!($m);
            fn eta(s: f64) -> f64 {
                generated::$m::eta(s)
            }
            fn eta_s(s: f64) -> f64 {
                generated::$m::eta_s(s)
            }
            fn bc_error(s: f64) -> f64 {
                generated::$m::bc_error(s)
            }
            fn residuals_and_jacobian(
                a_bar: f64,
                s: f64,
                rho: f64,
                delta_bar: f64,
            ) -> ([f64; 2], [[f64; 2]; 2]) {
                let [eta, eta_s] = generated::$m::eta_and_eta_s(s);
                let v =
                    generated::$m::residuals_and_jacobian_eta(a_bar, s, rho, delta_bar, eta, eta_s);
                ([v[0], v[1]], [[v[2], v[3]], [v[4], v[5]]])
            }
            fn residuals_d_delta(a_bar: f64, s: f64, rho: f64, delta_bar: f64) -> [f64; 2] {
                generated::$m::residuals_d_dbar_eta(
                    a_bar,
                    s,
                    rho,
                    delta_bar,
                    Self::eta(s),
                    Self::eta_s(s),
                )
            }
            fn xi(a_bar: f64, s: f64, delta_bar: f64) -> f64 {
                generated::$m::xi(a_bar, s, delta_bar, Self::eta(s))
            }
            fn force_bar(a_bar: f64, s: f64, delta_bar: f64) -> f64 {
                generated::$m::force_bar(a_bar, s, delta_bar, Self::eta(s))
            }
            fn p0_bar(a_bar: f64, xi: f64, s: f64) -> f64 {
                generated::$m::p0_bar(a_bar, xi, Self::eta(s))
            }
            fn branch(s: f64, rho: f64) -> [f64; 2] {
                generated::$m::branch_eta(s, rho, Self::eta(s))
            }
            fn shape(a: f64, s: f64, xi: f64) -> [f64; 2] {
                generated::$m::shape(a, s, xi)
            }
            fn pressure(x: f64, y: f64, p0: f64, a: f64, s: f64, xi: f64) -> f64 {
                generated::$m::pressure(x, y, p0, a, s, xi)
            }
        }
    };
}

impl_model!(
    Paper,
    paper,
    "The paper's ansatz (5) with collocation (10)."
);
impl_model!(
    Apex45,
    apex45,
    "Ansatz (5) with ∂p/∂ν equal at t = 0 and t = π/4 (a second ansatz, to show regeneration)."
);
