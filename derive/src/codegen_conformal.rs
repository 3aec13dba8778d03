//! Code generation for the family `conformal:K`: Π̄ and the boundary slope
//! of each member become tables of monomials (packed exponents, correctly
//! rounded `f64` coefficient) in `solver/src/generated/conformal/`.
//!
//! Why tables and not expanded expressions: for K = 8, Π̄ has 14 084
//! monomials and the upper triangle of its Hessian in (c, δ̄) 149 075; the
//! residuals and their Jacobian written out would be megabytes. A monomial's
//! derivatives are exact in its integer exponents, so the solver evaluates
//! Π̄, its gradient (the residuals and F̄ = ∂Π̄/∂δ̄) and its Hessian (their
//! Jacobian) side by side from the one table (`thinjkr::conformal::poly`),
//! with no approximation beyond the rounding of each coefficient (half an
//! ulp) and of the sums; `tests/tests/conformal.rs` holds them against
//! 384-bit evaluations of the symbolic derivatives.
//!
//! Exponents are packed four bits each: c₁ … c_K from the lowest bits,
//! then δ̄ at bit 32 and μ = 1/ρ at bit 36. Rows are sorted by their
//! c-exponents so that the evaluator can merge rows that differ only in δ̄
//! and μ.
//!
//! Owns: the generated conformal modules. May use: `conformal`, `generate`.

use crate::conformal::{self, ConformalDerivation, Poly};
use crate::generate::Output;
use astro_float::{BigFloat, Consts, RoundingMode};
use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};

/// Bits per exponent in a packed row.
pub const BITS: u32 = 4;
/// Bit offset of δ̄'s exponent.
pub const DBAR_SHIFT: u32 = 32;
/// Bit offset of μ's exponent.
pub const MU_SHIFT: u32 = 36;

/// The correctly rounded `f64` of `num/den · (π if with_pi)`.
fn rounded(num: &str, den: &str, with_pi: bool) -> Result<f64, String> {
    let p = 320;
    let rm = RoundingMode::ToEven;
    let mut cc = Consts::new().map_err(|e| format!("{e:?}"))?;
    let parse = |s: &str, cc: &mut Consts| BigFloat::parse(s, astro_float::Radix::Dec, p, rm, cc);
    let mut v = parse(num, &mut cc).div(&parse(den, &mut cc), p, rm);
    if with_pi {
        v = v.mul(&cc.pi(p, rm), p, rm);
    }
    let x: f64 = v
        .to_string()
        .parse()
        .map_err(|e| format!("coefficient {num}/{den}: {e}"))?;
    if !x.is_finite() {
        return Err(format!("coefficient {num}/{den} is not a finite f64"));
    }
    Ok(x)
}

/// The rows of a polynomial in (c, δ̄, μ): packed exponents and coefficient.
pub fn rows(d: &ConformalDerivation, p: &Poly, with_pi: bool) -> Result<Vec<(u64, f64)>, String> {
    let (cs, dbar, mu) = d.layout();
    let mut out = Vec::with_capacity(p.nterms());
    for t in p.into_iter() {
        let e = t.exponents;
        let mut packed = 0u64;
        for (k, &v) in cs.iter().enumerate() {
            packed |= pack(e[v], BITS * k as u32)?;
        }
        packed |= pack(e[dbar], DBAR_SHIFT)?;
        packed |= pack(e[mu], MU_SHIFT)?;
        let others: u32 = e.iter().map(|&x| x as u32).sum::<u32>()
            - cs.iter().map(|&v| e[v] as u32).sum::<u32>()
            - e[dbar] as u32
            - e[mu] as u32;
        if others != 0 {
            return Err("a table polynomial still contains ζ, ζ̄ or I".into());
        }
        let c = t.coefficient;
        out.push((
            packed,
            rounded(
                &c.numerator().to_string(),
                &c.denominator().to_string(),
                with_pi,
            )?,
        ));
    }
    let c_mask = (1u64 << DBAR_SHIFT) - 1;
    out.sort_by_key(|(p, _)| (p & c_mask, *p));
    Ok(out)
}

fn pack(e: u16, shift: u32) -> Result<u64, String> {
    if e as u32 >= 1 << BITS {
        return Err(format!("exponent {e} does not fit in {BITS} bits"));
    }
    Ok((e as u64) << shift)
}

fn table(rows: &[(u64, f64)]) -> TokenStream {
    let items = rows.iter().map(|(p, c)| {
        let p = Literal::u64_unsuffixed(*p);
        let c = Literal::f64_unsuffixed(*c);
        quote!((#p, #c))
    });
    quote!(&[#(#items),*])
}

/// The module of one member.
fn member_source(d: &ConformalDerivation) -> Result<String, String> {
    let k = Literal::usize_unsuffixed(d.ansatz.terms);
    let potential = table(&rows(d, &d.potential, true)?);
    let mut modes = Vec::new();
    for (n, g) in &d.boundary_slope {
        let n = Literal::u16_unsuffixed(*n);
        let t = table(&rows(d, g, false)?);
        modes.push(quote!((#n, #t)));
    }
    let powers: Vec<Literal> = d
        .ansatz
        .powers()
        .iter()
        .map(|p| Literal::u16_unsuffixed(*p))
        .collect();
    let (n_pot, _) = (d.potential.nterms(), ());
    let doc_pot = format!(
        " Π̄(c, δ̄; μ) of `{}`: {} monomials, coefficients rounded from the exact rationals times π.",
        d.ansatz.name(),
        n_pot
    );
    let file = quote! {
        /// The powers of ζ in the map w(ζ) = Σ c_k ζ^(n_k).
        pub const POWERS: [u16; #k] = [#(#powers),*];
        #[doc = #doc_pot]
        pub static POTENTIAL: &[(u64, f64)] = #potential;
        /// ∂p̄/∂r at |ζ| = 1 as Σ g_n(c, δ̄; μ) cos(nθ): (n, rows of g_n).
        pub static SLOPE: &[(u16, &[(u64, f64)])] = &[#(#modes),*];
    };
    let ast: syn::File =
        syn::parse2(file).map_err(|e| format!("generated conformal code does not parse: {e}"))?;
    Ok(format!(
        "//! @generated by `cargo run -p thinjkr-derive -- generate` (thinjkr-derive codegen_conformal); do not edit.\n//!\n//! Model `{}`: {}.\n//! Particular solution: `{}`; gap: `{}`.\n\n{}",
        d.ansatz.name(),
        d.ansatz.title,
        d.ansatz.particular,
        d.ansatz.gap,
        prettyplease::unparse(&ast)
    ))
}

/// The generated files of the family: one module per member and their `mod.rs`.
pub fn outputs(all: &[ConformalDerivation]) -> Result<Vec<Output>, String> {
    let mut out = Vec::new();
    for d in all {
        out.push(Output {
            path: format!("solver/src/generated/conformal/k{}.rs", d.ansatz.terms).into(),
            contents: member_source(d)?,
        });
    }
    let mods: Vec<_> = all
        .iter()
        .map(|d| format_ident!("k{}", d.ansatz.terms))
        .collect();
    let terms: Vec<Literal> = all
        .iter()
        .map(|d| Literal::usize_unsuffixed(d.ansatz.terms))
        .collect();
    let n = Literal::usize_unsuffixed(all.len());
    let family = all.first().map(|d| d.ansatz.family).unwrap_or("conformal");
    let title = all.first().map(|d| d.ansatz.title).unwrap_or("");
    let file = quote! {
        #(pub mod #mods;)*
        /// The family's name.
        pub const FAMILY: &str = #family;
        /// The family in one line.
        pub const TITLE: &str = #title;
        /// Every generated member, by K.
        pub static MEMBERS: [crate::conformal::Tables; #n] = [
            #(crate::conformal::Tables {
                terms: #terms,
                powers: &#mods::POWERS,
                potential: #mods::POTENTIAL,
                slope: #mods::SLOPE,
            }),*
        ];
    };
    let ast: syn::File =
        syn::parse2(file).map_err(|e| format!("generated conformal mod.rs does not parse: {e}"))?;
    out.push(Output {
        path: "solver/src/generated/conformal/mod.rs".into(),
        contents: format!(
            "//! @generated by `cargo run -p thinjkr-derive -- generate`; do not edit.\n//!\n//! The family `{family}:K`, K = 1 … {}: Π̄ and the boundary slope of each member as monomial tables\n//! (exponents packed {BITS} bits each: c₁ … c_K from bit 0, δ̄ at bit {DBAR_SHIFT}, μ at bit {MU_SHIFT}).\n\n{}",
            all.len(),
            prettyplease::unparse(&ast)
        ),
    });
    Ok(out)
}

/// Derive every member K = 1 … [`conformal::MAX_TERMS`].
pub fn derive_all() -> Result<Vec<ConformalDerivation>, String> {
    (1..=conformal::MAX_TERMS)
        .map(|k| conformal::derive(&conformal::conformal(k)))
        .collect()
}
