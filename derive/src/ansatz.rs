//! The ansatz as data: the approximate pressure p(x, y) and the collocation
//! conditions that close it. Everything after this module is generic over an
//! [`Ansatz`]; nothing downstream may refer to Eq. (5) or (10) directly.
//!
//! Owns: the definitions of the paper's ansatz (5) with collocation (10), and
//! of a second ansatz used to prove that regeneration works.
//! May use: nothing else in the crate.

/// A contour point of the ellipse x = a cos t, y = b sin t, given by
/// u = sin² t (0 at the apex (a, 0), 1 at the co-vertex (0, b)), written in
/// symbolica syntax; it may depend on `s` = b/a.
pub type ContourPoint = &'static str;

/// An approximate pressure distribution and its closure.
#[derive(Clone, Debug)]
pub struct Ansatz {
    /// Short identifier, used for generated module and file names.
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
    /// pair fixes one of the remaining shape parameters, in order.
    pub equal_normal_derivative: &'static [(ContourPoint, ContourPoint)],
    /// Where the collocation is described, for reports.
    pub collocation_note: &'static str,
}

/// The paper's ansatz: pressure (5), collocation (10) (equal ∂p/∂ν at the
/// apexes t = 0 and t = π/2 of the ellipse).
pub const PAPER: Ansatz = Ansatz {
    id: "paper",
    title: "Eq. (5) with collocation (10): equal normal derivative at both apexes",
    pressure: "p0*(1 - x^2/a^2 - y^2/b^2)*(1 - A*x^2 - B*y^2)",
    shape_params: &["A", "B"],
    xi_definition: ("A", "(1 + 1/xi)/a^2"),
    equal_normal_derivative: &[("0", "1")],
    collocation_note: "∂p/∂ν equal at t = 0 and t = π/2 (Eq. (10))",
};

/// A second ansatz to exercise regeneration: the same pressure (5), but the
/// collocation equates ∂p/∂ν at the apex t = 0 and at t = π/4 (u = 1/2)
/// instead of at the two apexes.
pub const APEX_45: Ansatz = Ansatz {
    id: "apex45",
    title: "Eq. (5) with ∂p/∂ν equal at t = 0 and t = π/4",
    pressure: "p0*(1 - x^2/a^2 - y^2/b^2)*(1 - A*x^2 - B*y^2)",
    shape_params: &["A", "B"],
    xi_definition: ("A", "(1 + 1/xi)/a^2"),
    equal_normal_derivative: &[("0", "1/2")],
    collocation_note: "∂p/∂ν equal at t = 0 and t = π/4",
};

/// All ansätze known to the generator, the paper's first.
pub const ALL: &[Ansatz] = &[PAPER, APEX_45];
