//! The ansatz as data: the approximate pressure p(x, y), the collocation
//! conditions that tie its shape parameters, and the closure that imposes
//! the second boundary condition (3)₂. Everything after this module is
//! generic over an [`Ansatz`]; nothing downstream may refer to Eq. (5),
//! (10) or (13) directly.
//!
//! On the ellipse (7) the polynomial pressure (5) with (6) is the exact
//! solution of (2) with p = 0 on Γ₀; the models differ only in how (3)₂ is
//! imposed. That choice is the [`Closure`].
//!
//! Owns: the definitions of the models `max` (the paper's (5), (10), (13)),
//! `apexes`, `energy` and `apex45`. May use: nothing else in the crate.

/// A contour point of the ellipse x = a cos t, y = b sin t, given by
/// u = sin² t (0 at the apex (a, 0), 1 at the co-vertex (0, b)), written in
/// symbolica syntax; it may depend on `s` = b/a.
pub type ContourPoint = &'static str;

/// How the second boundary condition (3)₂, ∂p/∂ν = √(2mΔγ) on Γ₀, is
/// imposed on the ansatz.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Closure {
    /// The maximum of ∂p/∂ν along Γ₀ equals √(2mΔγ): the paper's (13).
    /// The collocation pairs fix the remaining shape parameters.
    Max,
    /// ∂p/∂ν equals √(2mΔγ) at the given contour point; with a collocation
    /// pair that ties it to another point, the condition holds at both
    /// (Johnson & Greenwood's choice of imposing Griffith's criterion at the
    /// ends of the axes: K. L. Johnson and J. A. Greenwood, J. Phys. D: Appl. Phys. 38 (2005) 1042, the paper's reference
    /// for the elliptical JKR approximation).
    AtPoint(ContourPoint),
    /// Ritz: the shape parameters come from (6) alone (the exact pressure on
    /// the ellipse), and the semi-axes make the total potential energy
    /// Π = U − Δγ·πab stationary, U = ½∫ω p (δ − φ) dA: ∂Π/∂a = ∂Π/∂b = 0.
    /// This satisfies (3)₂ in the mean along the variations of a and b.
    Energy,
}

impl Closure {
    /// One line for reports and generated code.
    pub fn describe(&self) -> String {
        match self {
            Closure::Max => "max ∂p/∂ν on Γ₀ = √(2mΔγ) (Eq. (13))".into(),
            Closure::AtPoint(u) => format!("∂p/∂ν = √(2mΔγ) at sin²t = {u}"),
            Closure::Energy => {
                "energy (Ritz): ∂Π/∂a = ∂Π/∂b = 0, Π = U − Δγ·πab, U = ½∫p(δ − φ) dA".into()
            }
        }
    }
}

/// An approximate pressure distribution and its closure.
#[derive(Clone, Debug)]
pub struct Ansatz {
    /// Short identifier, used for the model's name and for generated module
    /// and file names.
    pub id: &'static str,
    /// One line for reports.
    pub title: &'static str,
    /// p(x, y) in symbolica syntax, in the symbols `x`, `y`, `p0`, `a`, `b`
    /// and the shape parameters. It must vanish on the ellipse (7), so that
    /// the first boundary condition (3) holds on Γ₀.
    pub pressure: &'static str,
    /// The free shape parameters (for (5): `A`, `B`).
    pub shape_params: &'static [&'static str],
    /// The definition of the collocation parameter ξ through one shape
    /// parameter: `(name, value)`. For (10), `A = (1 + 1/ξ)/a²`, which makes
    /// the apex value of ∂p/∂ν equal to 2 p0/(a ξ).
    pub xi_definition: (&'static str, &'static str),
    /// Pairs of contour points at which ∂p/∂ν must take equal values; each
    /// pair fixes one of the remaining shape parameters, in order. Empty for
    /// the energy closure, where (6) fixes them.
    pub equal_normal_derivative: &'static [(ContourPoint, ContourPoint)],
    /// The closure of (3)₂.
    pub closure: Closure,
    /// Where the collocation is described, for reports.
    pub collocation_note: &'static str,
}

/// The paper's pressure (5).
const PRESSURE_5: &str = "p0*(1 - x^2/a^2 - y^2/b^2)*(1 - A*x^2 - B*y^2)";

/// The paper's model `max`: pressure (5), collocation (10) (equal ∂p/∂ν at
/// the apexes t = 0 and t = π/2 of the ellipse), closure (13).
pub const PAPER: Ansatz = Ansatz {
    id: "max",
    title: "Eq. (5) with collocation (10) and closure (13): the paper's model",
    pressure: PRESSURE_5,
    shape_params: &["A", "B"],
    xi_definition: ("A", "(1 + 1/xi)/a^2"),
    equal_normal_derivative: &[("0", "1")],
    closure: Closure::Max,
    collocation_note: "∂p/∂ν equal at t = 0 and t = π/2 (Eq. (10))",
};

/// `apexes`: pressure (5), ∂p/∂ν = √(2mΔγ) at both apexes t = 0 and
/// t = π/2 (the pair ties them, the closure sets the value).
pub const APEXES: Ansatz = Ansatz {
    id: "apexes",
    title: "Eq. (5) with ∂p/∂ν = √(2mΔγ) at both apexes (Johnson–Greenwood type)",
    pressure: PRESSURE_5,
    shape_params: &["A", "B"],
    xi_definition: ("A", "(1 + 1/xi)/a^2"),
    equal_normal_derivative: &[("0", "1")],
    closure: Closure::AtPoint("0"),
    collocation_note: "∂p/∂ν equal at t = 0 and t = π/2, and equal to √(2mΔγ) there",
};

/// `energy`: pressure (5) with A, B from (6), semi-axes from the
/// stationarity of Π = U − Δγ·πab (Ritz).
pub const ENERGY: Ansatz = Ansatz {
    id: "energy",
    title: "Eq. (5) with (6) exact on the ellipse, semi-axes from ∂Π/∂a = ∂Π/∂b = 0 (Ritz)",
    pressure: PRESSURE_5,
    shape_params: &["A", "B"],
    xi_definition: ("A", "(1 + 1/xi)/a^2"),
    equal_normal_derivative: &[],
    closure: Closure::Energy,
    collocation_note: "no collocation: (6) fixes A and B",
};

/// A second collocation, to exercise regeneration: the same pressure (5),
/// ∂p/∂ν equal at the apex t = 0 and at t = π/4 (u = 1/2), closure (13).
pub const APEX_45: Ansatz = Ansatz {
    id: "apex45",
    title: "Eq. (5) with ∂p/∂ν equal at t = 0 and t = π/4, closure (13)",
    pressure: PRESSURE_5,
    shape_params: &["A", "B"],
    xi_definition: ("A", "(1 + 1/xi)/a^2"),
    equal_normal_derivative: &[("0", "1/2")],
    closure: Closure::Max,
    collocation_note: "∂p/∂ν equal at t = 0 and t = π/4",
};

/// All models known to the generator, the paper's first.
pub const ALL: &[Ansatz] = &[PAPER, APEXES, ENERGY, APEX_45];
