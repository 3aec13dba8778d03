//! Physical units: a contact given by cylinder radii r₁, r₂, the crossing
//! angle θ of their axes, coating thicknesses h₁, h₂, out-of-plane shear
//! moduli G'₁, G'₂ and the work of adhesion Δγ, in SI units. Converted to the
//! model's variables by (1) (R₁, R₂ from r₁, r₂, θ), (4) (m) and (17).
//!
//! Owns: [`Cylinders`], [`PhysicalState`], [`Si`]. May use: `contact`, `error`.

use crate::contact::{Contact, State};
use crate::error::{check_range, Error, Result};
use serde::{Deserialize, Serialize};

/// Two coated cylinders in SI units (as a TOML file: these keys, no others).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct Cylinders {
    /// Radius r₁ of cylinder 1 (m).
    pub r1: f64,
    /// Radius r₂ of cylinder 2 (m).
    pub r2: f64,
    /// Crossing angle θ between the axes (degrees), in (0, 90].
    pub theta_deg: f64,
    /// Coating thickness h₁ (m).
    pub h1: f64,
    /// Coating thickness h₂ (m).
    pub h2: f64,
    /// Out-of-plane shear modulus G'₁ (Pa).
    pub g1: f64,
    /// Out-of-plane shear modulus G'₂ (Pa).
    pub g2: f64,
    /// Work of adhesion Δγ (J/m²).
    pub work_of_adhesion: f64,
    /// Poisson's ratio ν₁ of coating 1, in [0, 0.5] (default 0.5,
    /// incompressible): the layer of finite thickness reads it; the
    /// thin-layer equation (2) assumes 0.5.
    #[serde(default = "incompressible")]
    pub nu1: f64,
    /// Poisson's ratio ν₂ of coating 2, as `nu1`.
    #[serde(default = "incompressible")]
    pub nu2: f64,
}

/// The Poisson's ratio of an incompressible coating, the paper's.
fn incompressible() -> f64 {
    0.5
}

/// The derived model parameters of a [`Cylinders`] contact.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct Scales {
    /// Principal radius R₁ ≥ R₂ of the gap (1) (m).
    pub big_r1: f64,
    /// Principal radius R₂ (m).
    pub big_r2: f64,
    /// ρ = R₂/R₁ (21).
    pub rho: f64,
    /// m of (4) (Pa/m³).
    pub m: f64,
    /// Length scale L = (2R₁²Δγ/m)^(1/6) of (17) (m).
    pub length: f64,
    /// Approach scale (2Δγ/(mR₁))^(1/3) of (17) (m).
    pub approach: f64,
    /// Force scale 2R₁Δγ of (17) (N).
    pub force: f64,
    /// Pressure scale √(2mΔγ) L (Pa).
    pub pressure: f64,
}

/// A state in SI units.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct PhysicalState {
    /// The dimensionless state.
    pub state: State,
    /// Major semi-axis a (m).
    pub a: f64,
    /// Minor semi-axis b (m).
    pub b: f64,
    /// Approach δ (m).
    pub delta: f64,
    /// Force F (N).
    pub force: f64,
    /// Maximum pressure p₀ (Pa).
    pub p0: f64,
    /// max(h₁, h₂)/a: the asymptotic model's small parameter.
    pub h_over_a: f64,
}

/// A state in SI units (`physical`).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct Si {
    /// Major semi-axis a (m).
    pub a: f64,
    /// Minor semi-axis b (m).
    pub b: f64,
    /// Approach δ (m).
    pub delta: f64,
    /// Force F (N).
    pub force: f64,
    /// max(h₁, h₂)/a, the thin-layer model's small parameter.
    pub h_over_a: f64,
}

fn finite_si(name: &str, v: f64) -> Result<f64> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(Error::Usage(format!(
            "the result {name} in SI units is not a finite number for these inputs (their magnitudes are at the ends of f64)"
        )))
    }
}

/// `limit` where `v` lies beyond it by less than the six significant
/// digits a message prints: a limit is checked after the rounding that
/// prints it (theta_deg = 90.0000001 had been refused as "theta_deg = 90
/// is outside its allowed range (0, 90]").
fn at_limit(v: f64, limit: f64) -> f64 {
    if v != limit && crate::error::short(v) == crate::error::short(limit) {
        limit
    } else {
        v
    }
}

fn positive(name: &'static str, v: f64) -> Result<f64> {
    check_range(name, v, v > 0.0, "finite and > 0")
}

impl Cylinders {
    /// Poisson's ratios (ν₁, ν₂), each in [0, 0.5] after the rounding that
    /// prints it (ν = 0.5000001 is 0.5: it had been refused as "nu1 = 0.5 is
    /// outside its allowed range [0, 0.5]").
    pub(crate) fn poisson(&self) -> Result<(f64, f64)> {
        let nu = |name: &'static str, v: f64| {
            let v = at_limit(v, 0.5);
            check_range(name, v, (0.0..=0.5).contains(&v), "[0, 0.5]")
        };
        Ok((nu("nu1", self.nu1)?, nu("nu2", self.nu2)?))
    }

    /// Validate the inputs and compute R₁, R₂, ρ, m and the scales of (17).
    /// 1/R₁ + 1/R₂ = 1/r₁ + 1/r₂ and R₁R₂ = r₁r₂/sin²θ, with R₂ ≤ R₁.
    pub fn scales(&self) -> Result<Scales> {
        let r1 = positive("r1", self.r1)?;
        let r2 = positive("r2", self.r2)?;
        let theta = at_limit(self.theta_deg, 90.0);
        let th = check_range(
            "theta_deg",
            theta,
            theta > 0.0 && theta <= 90.0,
            "(0, 90] degrees",
        )?;
        let h1 = positive("h1", self.h1)?;
        let h2 = positive("h2", self.h2)?;
        let g1 = positive("g1", self.g1)?;
        let g2 = positive("g2", self.g2)?;
        let dg = positive("work_of_adhesion", self.work_of_adhesion)?;
        self.poisson()?;
        let sin2 = th.to_radians().sin().powi(2);
        // curvatures k = 1/R are the roots of k² − (1/r1 + 1/r2) k + sin²θ/(r1 r2) = 0
        let sum = 1.0 / r1 + 1.0 / r2;
        let prod = sin2 / (r1 * r2);
        let disc = (sum * sum - 4.0 * prod).max(0.0).sqrt();
        let (k_small, k_big) = (0.5 * (sum - disc), 0.5 * (sum + disc));
        let big_r1 = 1.0 / k_small;
        let big_r2 = 1.0 / k_big;
        let m = 1.0 / (h1.powi(3) / (3.0 * g1) + h2.powi(3) / (3.0 * g2));
        let length = (2.0 * big_r1 * big_r1 * dg / m).powf(1.0 / 6.0);
        let sc = Scales {
            big_r1,
            big_r2,
            rho: (big_r2 / big_r1).min(1.0),
            m,
            length,
            approach: (2.0 * dg / (m * big_r1)).cbrt(),
            force: 2.0 * big_r1 * dg,
            pressure: (2.0 * m * dg).sqrt() * length,
        };
        // every scale must be a positive f64: inputs at the ends of f64
        // can overflow or underflow them
        for (value, name, from) in [
            (sc.big_r1, "R1", "r1, r2, theta_deg"),
            (sc.big_r2, "R2", "r1, r2, theta_deg"),
            (sc.m, "m", "h1, h2, g1, g2"),
            (sc.length, "L", "every input"),
            (sc.approach, "the approach scale", "every input"),
            (
                sc.force,
                "the force scale",
                "r1, r2, theta_deg, work_of_adhesion",
            ),
            (sc.pressure, "the pressure scale", "every input"),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(Error::Usage(format!(
                    "{name} computed from {from} is not a finite positive number in f64: the inputs are too large or too small together"
                )));
            }
        }
        Ok(sc)
    }

    /// The dimensionless model for this contact.
    pub(crate) fn contact(&self) -> Result<(Contact, Scales)> {
        let sc = self.scales()?;
        Ok((Contact::new(sc.rho)?, sc))
    }

    /// Convert a dimensionless state to SI units; a value that is not a
    /// finite f64 is an error naming it.
    pub(crate) fn to_physical(&self, sc: &Scales, st: State) -> Result<PhysicalState> {
        let si = self.si(sc, st.a_bar, st.b_bar, st.delta_bar, st.force_bar)?;
        let p0 = finite_si("p0", st.p0 * sc.pressure)?;
        Ok(PhysicalState {
            state: st,
            a: si.a,
            b: si.b,
            delta: si.delta,
            force: si.force,
            p0,
            h_over_a: si.h_over_a,
        })
    }

    /// The semi-axes, approach and force of any model's state (ā, b̄, δ̄, F̄
    /// of (17)) in SI units, and h/a; a value that is not a finite f64 is
    /// an error naming it.
    pub(crate) fn si(
        &self,
        sc: &Scales,
        a_bar: f64,
        b_bar: f64,
        delta_bar: f64,
        force_bar: f64,
    ) -> Result<Si> {
        Ok(Si {
            a: finite_si("a", a_bar * sc.length)?,
            b: finite_si("b", b_bar * sc.length)?,
            delta: finite_si("delta", delta_bar * sc.approach)?,
            force: finite_si("force", force_bar * sc.force)?,
            h_over_a: finite_si("h/a", self.h1.max(self.h2) / (a_bar * sc.length))?,
        })
    }

    /// The state at approach `delta` (m).
    pub fn at_displacement(&self, delta: f64) -> Result<PhysicalState> {
        let (c, sc) = self.contact()?;
        self.to_physical(
            &sc,
            c.at_displacement(check_range("delta", delta, true, "finite")? / sc.approach)?,
        )
    }

    /// The stable state at force `force` (N).
    pub fn at_load(&self, force: f64) -> Result<PhysicalState> {
        let (c, sc) = self.contact()?;
        self.to_physical(
            &sc,
            c.at_load(check_range("force", force, true, "finite")? / sc.force)?,
        )
    }

    /// Pull-off under load control.
    pub fn pull_off(&self) -> Result<PhysicalState> {
        let (c, sc) = self.contact()?;
        self.to_physical(&sc, c.pull_off_load()?.state)
    }
}
