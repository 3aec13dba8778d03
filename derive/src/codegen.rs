//! Code generation: derived expressions become straight-line Rust functions
//! on `f64` for the solver crate (`solver/src/generated/`), built with
//! `quote!`, formatted by prettyplease. Shared subexpressions are computed
//! once (`let tN = …;`), integer powers become `powi`, half-integer powers
//! go through `sqrt`, thirds through `cbrt`. Functions and their Jacobians
//! are generated side by side, as CasADi does.
//!
//! Always from the derived expressions (including where the checker found
//! that the paper differs), never from printed forms.
//!
//! Owns: the generated modules and the `Model` implementations in them.
//! May use: `ir`, `model`, `sym`.

use crate::accuracy::{Chart, Failure, Scale, SHIFTABLE, SHIFT_PREFIX};
use crate::ansatz::Closure;
use crate::energy::EnergyDerivation;
use crate::generate::Output;
use crate::ir::Ir;
use crate::model::{Derivation, ModelDerivation};
use crate::nondimensional::ratio_branch;
use crate::sym::{diff, ex, rationalize, simplify, subs, subs_all};
use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::quote;
use std::collections::HashMap;
use symbolica::atom::{Atom, AtomCore};

/// Rust identifier for a derivation symbol.
fn rust_name(sym: &str) -> String {
    match sym {
        s if s.len() == 1 && s.chars().all(|c| c.is_ascii_uppercase()) => {
            format!("shape_{}", s.to_lowercase())
        }
        "R1" => "r1".into(),
        "R2" => "r2".into(),
        "eta_s" => "eta_s".into(),
        other => other.to_lowercase(),
    }
}

fn ident(s: &str) -> Ident {
    Ident::new(s, Span::call_site())
}

fn lit(v: f64) -> TokenStream {
    let l = Literal::f64_unsuffixed(v);
    quote!(#l)
}

/// Emission context: common subexpressions bound to `let` statements.
struct Emitter {
    counts: HashMap<String, usize>,
    bound: HashMap<String, Ident>,
    lets: Vec<TokenStream>,
}

fn key(e: &Ir) -> String {
    format!("{e:?}")
}

fn count(e: &Ir, counts: &mut HashMap<String, usize>) {
    let trivial = matches!(e, Ir::Rational(..) | Ir::Var(_) | Ir::Pi);
    if !trivial {
        *counts.entry(key(e)).or_default() += 1;
        if counts[&key(e)] > 1 {
            return; // children already counted with the first occurrence
        }
    }
    match e {
        Ir::Mul(v) => {
            v.iter().for_each(|t| count(t, counts));
            // a product's denominator is a candidate for sharing as a whole
            if let Some(d) = denominator(v) {
                count(&d, counts);
            }
        }
        Ir::Add(v) => v.iter().for_each(|t| count(t, counts)),
        Ir::Pow(b, _, _) => count(b, counts),
        _ => {}
    }
}

impl Emitter {
    fn new(outputs: &[&Ir]) -> Emitter {
        let mut counts = HashMap::new();
        for o in outputs {
            count(o, &mut counts);
        }
        Emitter {
            counts,
            bound: HashMap::new(),
            lets: Vec::new(),
        }
    }

    fn emit(&mut self, e: &Ir) -> TokenStream {
        let k = key(e);
        if let Some(id) = self.bound.get(&k) {
            return quote!(#id);
        }
        let tokens = self.emit_raw(e);
        if self.counts.get(&k).copied().unwrap_or(0) > 1 {
            let id = ident(&format!("t{}", self.lets.len()));
            self.lets.push(quote!(let #id = #tokens;));
            self.bound.insert(k, id.clone());
            quote!(#id)
        } else {
            tokens
        }
    }

    fn emit_raw(&mut self, e: &Ir) -> TokenStream {
        match e {
            Ir::Rational(p, q) => lit(*p as f64 / *q as f64),
            Ir::Pi => quote!(::core::f64::consts::PI),
            Ir::Var(n) => {
                let id = ident(&rust_name(n));
                quote!(#id)
            }
            Ir::Add(terms) => {
                let mut out = TokenStream::new();
                for (i, t) in terms.iter().enumerate() {
                    let (neg, mag) = split_sign(t);
                    let body = self.emit(&mag);
                    out = match (i, neg) {
                        (0, false) => quote!(#body),
                        (0, true) => quote!(-#body),
                        (_, false) => quote!(#out + #body),
                        (_, true) => quote!(#out - #body),
                    };
                }
                quote!((#out))
            }
            Ir::Mul(factors) => {
                let (num, den): (Vec<&Ir>, Vec<&Ir>) =
                    factors.iter().partition(|f| !is_reciprocal(f));
                let mut n = TokenStream::new();
                for (i, f) in num.iter().enumerate() {
                    let t = self.emit(f);
                    n = if i == 0 { quote!(#t) } else { quote!(#n * #t) };
                }
                if num.is_empty() {
                    n = quote!(1.0);
                }
                if den.is_empty() {
                    return quote!((#n));
                }
                let d = self.emit(&denominator(factors).expect("non-empty denominator"));
                quote!((#n / (#d)))
            }
            Ir::Pow(b, p, q) if matches!(**b, Ir::Rational(..)) => {
                // constant folding: a numeric radical becomes one literal
                let x = b.eval(&Default::default()).expect("a number");
                let v = match q {
                    1 => x.powi(*p as i32),
                    2 => x.sqrt().powi(*p as i32),
                    3 => x.cbrt().powi(*p as i32),
                    q => x.powf(*p as f64 / *q as f64),
                };
                lit(v)
            }
            Ir::Pow(b, p, q) => {
                let base = self.emit(b);
                let p = *p;
                match *q {
                    1 => match p {
                        1 => base,
                        -1 => quote!((1.0 / #base)),
                        _ => {
                            let p32 = Literal::i32_unsuffixed(p as i32);
                            quote!(#base.powi(#p32))
                        }
                    },
                    2 => {
                        let root = quote!(#base.sqrt());
                        match p {
                            1 => root,
                            -1 => quote!((1.0 / #root)),
                            _ if p > 0 => {
                                let k = (p - 1) / 2;
                                if k == 1 {
                                    quote!((#root * #base))
                                } else {
                                    let k = Literal::i32_unsuffixed(k as i32);
                                    quote!((#root * #base.powi(#k)))
                                }
                            }
                            _ => {
                                let k = (-p - 1) / 2;
                                if k == 1 {
                                    quote!((1.0 / (#root * #base)))
                                } else {
                                    let k = Literal::i32_unsuffixed(k as i32);
                                    quote!((1.0 / (#root * #base.powi(#k))))
                                }
                            }
                        }
                    }
                    3 if p == 1 => quote!(#base.cbrt()),
                    3 => {
                        let p32 = Literal::i32_unsuffixed(p as i32);
                        quote!(#base.cbrt().powi(#p32))
                    }
                    q => {
                        let x = lit(p as f64 / q as f64);
                        quote!(#base.powf(#x))
                    }
                }
            }
        }
    }
}

/// Split a term into (negative?, magnitude).
fn split_sign(t: &Ir) -> (bool, Ir) {
    match t {
        Ir::Rational(p, q) if *p < 0 => (true, Ir::Rational(-p, *q)),
        Ir::Mul(f) => {
            if let Some(Ir::Rational(p, q)) = f.first() {
                if *p < 0 {
                    let mut g = f.clone();
                    if *p == -1 && *q == 1 {
                        g.remove(0);
                    } else {
                        g[0] = Ir::Rational(-p, *q);
                    }
                    let mag = if g.len() == 1 {
                        g.pop().expect("one")
                    } else {
                        Ir::Mul(g)
                    };
                    return (true, mag);
                }
            }
            (false, t.clone())
        }
        _ => (false, t.clone()),
    }
}

/// The product of the reciprocal factors of a product, inverted (`None` if
/// there are none); a single factor stands alone.
fn denominator(factors: &[Ir]) -> Option<Ir> {
    let mut d: Vec<Ir> = factors
        .iter()
        .filter(|f| is_reciprocal(f))
        .map(reciprocal)
        .collect();
    match d.len() {
        0 => None,
        1 => d.pop(),
        _ => Some(Ir::Mul(d)),
    }
}

fn is_reciprocal(f: &Ir) -> bool {
    matches!(f, Ir::Pow(_, p, _) if *p < 0)
}

fn reciprocal(f: &Ir) -> Ir {
    match f {
        Ir::Pow(b, p, q) if *p == -*q => (**b).clone(),
        Ir::Pow(b, p, q) => Ir::Pow(b.clone(), -p, *q),
        other => other.clone(),
    }
}

/// One generated function: name, doc, parameters, and its outputs.
struct Function {
    name: &'static str,
    doc: String,
    params: Vec<&'static str>,
    outputs: Vec<Atom>,
}

/// Where a function is used, when narrower than the declared domain of its
/// parameters (see `accuracy`): the explicit branch is used for ρ < 1 only
/// (at ρ = 1 it degenerates to 0/0 and the axisymmetric solution is used).
/// A point inside every parameter's domain, near s = 1 and ρ = 1, where
/// `rationalize` judges which sums cancel.
fn probe(params: &[&str]) -> Vec<(&'static str, Atom)> {
    const VALUES: &[(&str, i64, i64)] = &[
        ("s", 999, 1000),
        ("rho", 999, 1000),
        ("abar", 2, 1),
        ("a", 2, 1),
        ("abar0", 2, 1),
        ("dbar", 1, 1),
        ("eta", 1, 1),
        ("eta_s", 1, 2),
        ("xi", 1, 1),
        ("p0", 1, 1),
        ("u", 1, 2),
        ("x", 1, 10),
        ("y", 1, 10),
        ("t", 1, 10),
        ("m", 1, 1),
        ("delta", 1, 1),
        ("R1", 1, 1),
        ("R2", 1, 2),
        ("A", 1, 2),
        ("B", 1, 2),
        ("b", 1, 2),
    ];
    VALUES
        .iter()
        .filter(|(n, _, _)| params.contains(n))
        .map(|(n, p, q)| (*n, crate::sym::rat(*p, *q)))
        .collect()
}

fn domain_of(name: &str) -> &'static [(&'static str, &'static [f64])] {
    match name {
        "branch_eta" | "branch_poly" | "branch_x_pow" => {
            &[("rho", &[0.05, 0.3, 0.8, 0.99, 0.999999])]
        }
        _ => &[],
    }
}

/// A function's outputs rewritten in one chart's variables.
type Charted = Vec<(Chart, Vec<Atom>)>;

/// Every chart of `f`: one per subset of its shiftable parameters.
fn charts_for(f: &Function) -> Charted {
    let shiftable: Vec<&'static str> = SHIFTABLE
        .iter()
        .copied()
        .filter(|x| f.params.contains(x))
        .collect();
    (0..(1usize << shiftable.len()))
        .rev()
        .map(|mask| {
            let shifted: Vec<&'static str> = shiftable
                .iter()
                .enumerate()
                .filter(|(k, _)| mask & (1 << k) != 0)
                .map(|(_, x)| *x)
                .collect();
            let rules: Vec<(&str, Atom)> = shifted
                .iter()
                .map(|x| (*x, ex(&format!("1 - {SHIFT_PREFIX}{x}"))))
                .collect();
            let outs = f
                .outputs
                .iter()
                .map(|o| simplify(&subs_all(o, &rules)))
                .collect();
            (Chart { shifted }, outs)
        })
        .collect()
}

/// The straight-line body of one chart (or of the whole function): its
/// `let` statements and its value.
fn render_body(
    name: &str,
    params: &[&str],
    outputs: &[Atom],
    shifted: &[&str],
) -> Result<TokenStream, String> {
    let irs: Vec<Ir> = outputs
        .iter()
        .map(Ir::from_atom)
        .collect::<Result<_, _>>()?;
    for ir in &irs {
        for v in ir.variables() {
            let ok = params.contains(&v.as_str())
                || shifted.iter().any(|x| v == format!("{SHIFT_PREFIX}{x}"));
            if !ok {
                return Err(format!("{name}: unbound variable {v}"));
            }
        }
    }
    let mut em = Emitter::new(&irs.iter().collect::<Vec<_>>());
    let values: Vec<TokenStream> = irs.iter().map(|e| em.emit(e)).collect();
    let lets = &em.lets;
    let prelude: Vec<TokenStream> = shifted
        .iter()
        .map(|x| {
            let v = ident(&rust_name(x));
            let id = ident(&format!("{SHIFT_PREFIX}{}", rust_name(x)));
            quote!(let #id = 1.0 - #v;)
        })
        .collect();
    let body = if values.len() == 1 {
        let v = &values[0];
        quote!(#v)
    } else {
        quote!([#(#values),*])
    };
    Ok(quote!(#(#prelude)* #(#lets)* #body))
}

/// One straight-line function of the given outputs, as derived (no charts):
/// for generators of other kinds of model (the slender limit), which check
/// their functions themselves.
pub fn plain_function(
    name: &'static str,
    doc: &str,
    params: Vec<&'static str>,
    outputs: Vec<Atom>,
) -> Result<TokenStream, String> {
    render_function(
        &Function {
            name,
            doc: doc.to_string(),
            params,
            outputs,
        },
        None,
    )
}

fn render_function(f: &Function, charts: Option<&Charted>) -> Result<TokenStream, String> {
    let name = ident(f.name);
    let params: Vec<TokenStream> = f
        .params
        .iter()
        .map(|p| {
            let id = ident(&rust_name(p));
            quote!(#id: f64)
        })
        .collect();
    let ret = if f.outputs.len() == 1 {
        quote!(f64)
    } else {
        let n = Literal::usize_unsuffixed(f.outputs.len());
        quote!([f64; #n])
    };
    let (doc, body) = match charts {
        None => (
            format!(" {}", f.doc),
            render_body(f.name, &f.params, &f.outputs, &[])?,
        ),
        Some(charts) => {
            let shiftable: Vec<&str> = SHIFTABLE
                .iter()
                .copied()
                .filter(|x| f.params.contains(x))
                .collect();
            let mut chain = TokenStream::new();
            for (k, (chart, outs)) in charts.iter().enumerate() {
                let b = render_body(f.name, &f.params, outs, &chart.shifted)?;
                let conds: Vec<TokenStream> = shiftable
                    .iter()
                    .map(|x| {
                        let v = ident(&rust_name(x));
                        if chart.shifted.contains(x) {
                            quote!(#v >= 0.5)
                        } else {
                            quote!(#v < 0.5)
                        }
                    })
                    .collect();
                chain = if k + 1 == charts.len() {
                    quote!(#chain { #b })
                } else {
                    quote!(#chain if #(#conds)&&* { #b } else)
                };
            }
            (
                format!(
                    " {}\n\n Rewritten by the generator's accuracy check so that nothing cancels near s = 1 or ρ = 1: cancelling sums A + B√Q rationalised to (A² − B²Q)/(A − B√Q) where that was needed, and, with {} chart(s), where a parameter among ({}) is ≥ 1/2 the expression written in 1 − that parameter (computed exactly).",
                    f.doc,
                    charts.len(),
                    shiftable.join(", ")
                ),
                chain,
            )
        }
    };
    Ok(quote! {
        #[doc = #doc]
        #[inline]
        #[allow(clippy::all, unused_parens, unused_variables)]
        pub fn #name(#(#params),*) -> #ret {
            #body
        }
    })
}

/// Functions that must be computed without cancellation: their error is
/// measured against their own value, also where it tends to 0 (the
/// quantity (14) and η − 1 vanish at s = 1).
const CANCELLATION_FREE: &[&str] = &["bc_error", "eta_minus_one"];

/// Appended to the documentation of a function in [`CANCELLATION_FREE`]
/// for which no form passes the check against its own value.
const NOT_CANCELLATION_FREE: &str = "\n\nNot cancellation-free near s = 1 for this model: no generated form has a relative error ≤ 1e-12 against its own value there; its error is within 1e-12 of the size of the terms that cancel (see `docs/codegen-accuracy.md`).";

fn scale_of(name: &str) -> Scale {
    if CANCELLATION_FREE.contains(&name) {
        Scale::Value
    } else {
        Scale::Terms
    }
}

/// The parameters of the residual functions.
const STATE: [&str; 6] = ["abar", "s", "rho", "dbar", "eta", "eta_s"];

/// `[r₁ … r_m, ∂r₁/∂ā, ∂r₁/∂s, …]` with each residual collected in η:
/// r = Σ_k η^k R_k (k from −m, where the rational normal form's
/// denominator holds η^m and its numerator is a polynomial in η), each R_k
/// free of η in its own rational normal form; ∂r/∂ā = Σ η^k ∂R_k/∂ā,
/// ∂r/∂s = Σ η^k ∂R_k/∂s + k η^(k−1) η' R_k. `None` when a residual is not
/// of that form (η under a radical, or a denominator not a power of η
/// times a factor free of it).
fn eta_collected(r: &[Atom]) -> Option<Vec<Atom>> {
    let eta = ex("eta");
    let free = |e: &Atom| crate::sym::is_zero(&diff(e, "eta"));
    let mut values = Vec::new();
    let mut derivatives = Vec::new();
    for res in r {
        let (n, d) = crate::sym::num_den(&simplify(res));
        // d = η^m d̃
        let m = crate::sym::degree_in(&d, "eta", 4)?;
        let d_rest = simplify(&(&d / &eta.pow(&Atom::num(m as i64))));
        if !free(&d_rest) {
            return None;
        }
        let degree = crate::sym::degree_in(&n, "eta", 6)?;
        let (mut value, mut d_a, mut d_s) = (Atom::num(0), Atom::num(0), Atom::num(0));
        let mut coefficient = n.expand();
        let mut factorial = 1i64;
        for k in 0..=degree {
            // N_k = (1/k!) ∂^k N/∂η^k at η = 0
            let n_k = subs(&coefficient, "eta", &Atom::num(0)) / Atom::num(factorial);
            coefficient = diff(&coefficient, "eta");
            factorial *= k as i64 + 1;
            let r_k = simplify(&(n_k / &d_rest));
            if crate::sym::is_zero(&r_k) {
                continue;
            }
            if !free(&r_k) {
                return None;
            }
            let power = k as i64 - m as i64;
            let eta_power = eta.pow(&Atom::num(power));
            value = value + &eta_power * &r_k;
            d_a = d_a + &eta_power * simplify(&diff(&r_k, "abar"));
            d_s = d_s
                + &eta_power * simplify(&diff(&r_k, "s"))
                + Atom::num(power) * eta.pow(&Atom::num(power - 1)) * ex("eta_s") * &r_k;
        }
        values.push(value);
        derivatives.push(d_a);
        derivatives.push(d_s);
    }
    values.extend(derivatives);
    Some(values)
}

/// The functions generated for one derivation.
fn functions(d: &Derivation) -> Result<Vec<Function>, String> {
    let (eta, eta_s) = eta_forms(d);
    let d_eta = &eta;
    // (14) likewise: as derived (the form search below rationalises it
    // when needed), or max/min − 1 from the rationalised extrema
    let strict = |e: &Atom| {
        let (r, v) = (rationalize(e, &probe(&["s"])), Scale::Value);
        crate::accuracy::check_scaled("bc_error", &["s"], &[e.clone()], &[], None, v).is_ok()
            || crate::accuracy::check_scaled("bc_error", &["s"], &[r], &[], None, v).is_ok()
    };
    let bc_error = if strict(&d.bc_error) {
        d.bc_error.clone()
    } else {
        let pr = probe(&["s", "p0", "a", "xi"]);
        rationalize(&d.extrema.max, &pr) / rationalize(&d.extrema.min, &pr) - Atom::num(1)
    };
    // Residuals with η and η' as inputs; the chain rule is applied symbolically.
    let r = &d.residuals;
    let jac = |res: &Atom| -> Vec<Atom> {
        vec![
            diff(res, "abar"),
            diff(res, "s") + diff(res, "eta") * ex("eta_s"),
        ]
    };
    let mut rj = r.clone();
    for res in r {
        rj.extend(jac(res));
    }
    // The same collected in η where that passes the accuracy check: each
    // residual as Σ η^k R_k with R_k free of η (far shorter than the
    // fraction over the common denominator, and computed while η is), its
    // derivatives part by part.
    let rj = eta_collected(r)
        .filter(|q| {
            crate::accuracy::check(
                "residuals_and_jacobian_eta",
                &STATE,
                q,
                domain_of("residuals_and_jacobian_eta"),
                None,
            )
            .is_ok()
        })
        .unwrap_or(rj);
    let state = STATE.to_vec();
    // Dimensional functions take the ansatz's own shape parameters.
    let with_shape = |head: &[&'static str], tail: &[&'static str]| -> Vec<&'static str> {
        head.iter()
            .chain(d.ansatz.shape_params.iter())
            .chain(tail.iter())
            .copied()
            .collect()
    };
    let mut fs = vec![
        Function { name: "eta", doc: "η(s) of Eq. (16): the maximum of ∂p/∂ν on the contour over its apex value.".into(), params: vec!["s"], outputs: vec![d_eta.clone()] },
        Function { name: "eta_s", doc: "dη/ds, derivative of Eq. (16).".into(), params: vec!["s"], outputs: vec![eta_s.clone()] },
        Function { name: "eta_and_eta_s", doc: "`[η, dη/ds]` of Eq. (16), side by side (shared subexpressions computed once).".into(), params: vec!["s"], outputs: vec![d_eta.clone(), eta_s] },
        Function { name: "bc_error", doc: "Quantity (14) as a fraction: (max − min)/min of ∂p/∂ν on the contour Γ₀.".into(), params: vec!["s"], outputs: vec![bc_error] },
        Function { name: "residuals_eta", doc: "Residuals (19), (20) with η = η(s) and η' = dη/ds passed in.".into(), params: state.clone(), outputs: r.clone() },
        Function { name: "residuals_and_jacobian_eta", doc: "Residuals (19), (20) and their Jacobian with respect to (ā, s), side by side: `[r1, r2, ∂r1/∂ā, ∂r1/∂s, ∂r2/∂ā, ∂r2/∂s]`; η and η' passed in.".into(), params: state.clone(), outputs: rj },
        Function { name: "residuals_d_dbar_eta", doc: "∂(19)/∂δ̄, ∂(20)/∂δ̄ (for continuation and load control); η passed in.".into(), params: state.clone(), outputs: r.iter().map(|x| diff(x, "dbar")).collect() },
        Function { name: "xi", doc: "ξ from the first line of Eq. (15).".into(), params: vec!["abar", "s", "dbar", "eta"], outputs: vec![d.xi[0].clone()] },
        Function { name: "force_bar", doc: "F̄ of Eq. (18) in its derived form (the printed (18) lacks η(s); see docs/errata.md).".into(), params: vec!["abar", "s", "dbar", "eta"], outputs: vec![d.fbar_reduced.clone()] },
        Function { name: "force_bar_gradient_eta", doc: "∂F̄/∂(ā, s, δ̄) of the derived (18), the chain rule through η(s) applied symbolically; η and η' passed in.".into(), params: vec!["abar", "s", "dbar", "eta", "eta_s"], outputs: vec![diff(&d.fbar_reduced, "abar"), diff(&d.fbar_reduced, "s") + diff(&d.fbar_reduced, "eta") * ex("eta_s"), diff(&d.fbar_reduced, "dbar")] },
        Function { name: "force_bar_xi", doc: "F̄ in terms of ξ: Eq. (8) with (10), (13), (17).".into(), params: vec!["abar", "s", "xi", "eta"], outputs: vec![d.fbar.clone()] },
        Function { name: "p0_bar", doc: "p₀/(√(2mΔγ) L) with L = (2R₁²Δγ/m)^(1/6): Section 6's p₀ = √(2mΔγ) a ξ/(2η).".into(), params: vec!["abar", "xi", "eta"], outputs: vec![simplify(&subs(&subs(&d.p0, "a", &ex("abar")), "g", &Atom::num(1)))] },
        Function { name: "laplace_system", doc: format!("System (6): the coefficients of {} in Δp − m(φ − δ), in the dimensional unknowns.", d.laplace.iter().map(|l| format!("x^{} y^{}", l.monomial.0, l.monomial.1)).collect::<Vec<_>>().join(", ")), params: with_shape(&["p0", "a", "b"], &["m", "delta", "R1", "R2"]), outputs: d.laplace.iter().map(|l| l.residual.clone()).collect() },
        Function { name: "force", doc: "The force (8): ∫∫ p over the ellipse (7), shape parameters free.".into(), params: with_shape(&["p0", "a", "b"], &[]), outputs: vec![d.force.clone()] },
        Function { name: "normal_derivative", doc: "∂p/∂ν on Γ₀, Eq. (9), at u = sin²t, shape parameters free.".into(), params: with_shape(&["p0", "a", "b"], &["u"]), outputs: vec![d.normal_derivative.value()] },
        Function { name: "normal_derivative_collocated", doc: "∂p/∂ν on Γ₀ after collocation, Eq. (11), at u = sin²t.".into(), params: vec!["p0", "a", "s", "xi", "u"], outputs: vec![d.normal_derivative_collocated.value()] },
        Function { name: "shape", doc: format!("The shape parameters ({}) from the collocation, Eq. (10).", d.ansatz.shape_params.join(", ")), params: vec!["a", "s", "xi"], outputs: d.collocation.iter().map(|(_, v)| v.clone()).collect() },
        Function { name: "pressure", doc: "The pressure (5) with the collocation (10): Section 6's p(x, y).".into(), params: vec!["x", "y", "p0", "a", "s", "xi"], outputs: vec![d.pressure_collocated.clone()] },
    ];
    if let Some(b) = &d.branch {
        fs.push(Function { name: "branch_eta", doc: "The solution curve at fixed ρ, explicit in s: `[ā³, δ̄ ā]` (both residuals are linear in these); η passed in.".into(), params: vec!["s", "rho", "eta"], outputs: vec![b.abar_cubed.clone(), b.dbar_abar.clone()] });
    }
    if let Ok(l) = &d.limits {
        fs.extend(limit_functions(l));
    }
    Ok(fs)
}

/// η(s) and η′(s) in the forms that pass the accuracy check, the shortest
/// first: η factored with η′ as η times its logarithmic derivative, else
/// as derived (or rationalised) with η′ by differentiating that form.
fn eta_forms(d: &Derivation) -> (Atom, Atom) {
    // η in the form that passes the accuracy check: as derived, or with its
    // cancelling radicals rationalised; η' by differentiating that form
    // (product rule, not re-expanded, so that no cancellation returns).
    let (eta, eta_s) = if crate::accuracy::check("eta", &["s"], &[d.eta.clone()], &[], None).is_ok()
    {
        (d.eta.clone(), simplify(&diff(&d.eta, "s")))
    } else {
        let r = rationalize(&d.eta, &probe(&["s"]));
        (r.clone(), diff(&r, "s"))
    };
    let d_eta = &eta;
    // η factored into powers of irreducible polynomials and η' as η times
    // its logarithmic derivative (a short rational function), where both
    // pass the accuracy check: the radicals of η are then shared by the two
    let (eta, eta_s) = {
        let f = crate::sym::factored(d_eta);
        let candidate = (f.clone(), &f * &crate::sym::log_derivative(&f, "s"));
        let passes = crate::accuracy::check(
            "eta_and_eta_s",
            &["s"],
            &[candidate.0.clone(), candidate.1.clone()],
            &[],
            None,
        )
        .is_ok();
        if passes {
            candidate
        } else {
            (eta.clone(), eta_s)
        }
    };
    (eta, eta_s)
}

/// The functions of the limits (25)–(29) and (35)–(36), where derived.
fn limit_functions(l: &crate::model::Limits) -> Vec<Function> {
    let mut fs = Vec::new();
    fs.push(Function {
        name: "non_adhesive_rho",
        doc: "ρ(s) in the non-adhesive limit; its root in s is (29).".into(),
        params: vec!["s"],
        outputs: vec![l.non_adhesive_rho.clone()],
    });
    fs.push(Function {
        name: "zero_force_rho",
        doc: "ρ(s) at zero force: Eq. (28).".into(),
        params: vec!["s"],
        outputs: vec![l.zero_force.rho.clone()],
    });
    fs.push(Function {
        name: "zero_force_abar_cubed",
        doc: "ā³ at zero force, derived form of Eq. (27) (with η; the printed (27) lacks it)."
            .into(),
        params: vec!["s", "eta"],
        outputs: vec![l.zero_force.abar_cubed.clone()],
    });
    fs.push(Function { name: "axisymmetric_dbar", doc: "δ̄(ā) for ρ = 1, derived form of Eq. (25)₁ (δ̄ = ā²/4 − 2/ā; the printed 2^(4/3)/ā differs).".into(), params: vec!["abar"], outputs: vec![l.axisymmetric.dbar.clone()] });
    fs.push(Function {
        name: "axisymmetric_force_bar",
        doc: "F̄(ā) for ρ = 1, Eq. (25)₂.".into(),
        params: vec!["abar"],
        outputs: vec![l.axisymmetric.fbar.clone()],
    });
    fs.push(Function {
        name: "axisymmetric_critical",
        doc: "The minimum of F̄(ā) at ρ = 1 (Section 4): `[ā_c, F̄_c, δ̄_c]`.".into(),
        params: vec![],
        outputs: vec![
            l.axisymmetric.critical.0.clone(),
            l.axisymmetric.critical.1.clone(),
            l.axisymmetric.critical.2.clone(),
        ],
    });
    fs.push(Function { name: "near_circular_ds_dmu", doc: "ds/dμ at μ = 0 and fixed δ for ρ = (1 − μ)/(1 + μ): by (35) equal to −2a₂/a₀ with a₂ from (36).".into(), params: vec!["abar0"], outputs: vec![l.near_circular_model.s1.clone()] });
    fs
}

/// The functions generated for an energy (Ritz) model.
fn functions_energy(e: &EnergyDerivation) -> Result<Vec<Function>, String> {
    let st = vec!["abar", "s", "dbar", "rho"];
    let r = &e.residuals;
    let mut rj = r.clone();
    for res in r {
        rj.push(diff(res, "abar"));
        rj.push(diff(res, "s"));
    }
    let branch = ratio_branch(&e.residuals)?;
    let mut fs = vec![
        Function { name: "residuals_and_jacobian", doc: "Equilibrium residuals (∂Π̄/∂ā)/(∂W̄/∂ā), (∂Π̄/∂s)/(∂W̄/∂s) (W̄ = πsā²/2 the adhesion term) and their Jacobian with respect to (ā, s), side by side: `[r1, r2, ∂r1/∂ā, ∂r1/∂s, ∂r2/∂ā, ∂r2/∂s]`.".into(), params: st.clone(), outputs: rj },
        Function { name: "residuals_d_dbar", doc: "∂r/∂δ̄ of the equilibrium residuals.".into(), params: st.clone(), outputs: r.iter().map(|x| diff(x, "dbar")).collect() },
        Function { name: "force_bar", doc: "F̄ = ∂Π̄/∂δ̄ (identical to ∫p dA of (8), checked in the derivation).".into(), params: st.clone(), outputs: vec![e.fbar.clone()] },
        Function { name: "force_bar_gradient", doc: "∂F̄/∂(ā, s, δ̄).".into(), params: st.clone(), outputs: crate::energy::UNKNOWNS.iter().map(|q| diff(&e.fbar, q)).collect() },
        Function { name: "potential", doc: "Π̄ = Π R₁²/(m L⁸), Π = U − Δγ·πab, U = ½∫p(δ − φ) dA.".into(), params: st.clone(), outputs: vec![e.potential.clone()] },
        Function { name: "potential_hessian", doc: "The Hessian of Π̄ in (ā, s, δ̄), row-major.".into(), params: st.clone(), outputs: e.hessian.clone() },
        Function { name: "normal_derivative", doc: "∂p̄/∂ν on Γ₀ at u = sin²t, in units of √(2mΔγ).".into(), params: vec!["abar", "s", "dbar", "rho", "u"], outputs: vec![e.normal_derivative.clone()] },
        Function { name: "pressure_parameters", doc: "`[p̄₀, shape parameters × L², ξ]` from (6).".into(), params: st.clone(), outputs: e.pressure_parameters.clone() },
        Function { name: "pressure", doc: "p̄(x̄, ȳ): the ansatz with its parameters from (6).".into(), params: vec!["x", "y", "abar", "s", "dbar", "rho"], outputs: vec![e.pressure_bar.clone()] },
        Function { name: "branch_poly", doc: "Coefficients (constant first) of P(t), t = δ̄ā/ā³, whose roots are the solutions at fixed (s, ρ).".into(), params: vec!["s", "rho"], outputs: branch.poly_t.clone() },
        Function { name: "branch_x_pow", doc: "(ā³)^d at the root t of P, d the residuals' degree.".into(), params: vec!["t", "s", "rho"], outputs: vec![branch.x_pow.clone()] },
    ];
    if let Ok((dbar, fbar)) = crate::energy::axisymmetric(e) {
        if let Some((a_c, f_c, d_c)) = crate::limits::critical_point(&fbar, &dbar) {
            fs.push(Function {
                name: "axisymmetric_critical",
                doc: "The minimum of F̄(ā) at ρ = 1 (Section 4): `[ā_c, F̄_c, δ̄_c]`.".into(),
                params: vec![],
                outputs: vec![a_c, f_c, d_c],
            });
        }
        fs.push(Function {
            name: "axisymmetric_dbar",
            doc: "δ̄(ā) for ρ = 1 (the adhesive factor of the residual at s = 1): (25)₁.".into(),
            params: vec!["abar"],
            outputs: vec![dbar],
        });
        fs.push(Function {
            name: "axisymmetric_force_bar",
            doc: "F̄(ā) for ρ = 1: (25)₂.".into(),
            params: vec!["abar"],
            outputs: vec![fbar],
        });
    }
    Ok(fs)
}

fn camel(id: &str) -> String {
    let mut out = String::new();
    let mut up = true;
    for c in id.chars() {
        if c == '_' {
            up = true;
        } else if up {
            out.extend(c.to_uppercase());
            up = false;
        } else {
            out.push(c);
        }
    }
    out
}

fn has(fs: &[Function], name: &str) -> bool {
    fs.iter().any(|f| f.name == name)
}

/// The model value and its implementation of the solver's `Model` trait:
/// the glue between the generated functions and the one interface: its
/// [`model_info`], the methods its closure's kind of derivation gives
/// ([`collocation_methods`], [`energy_methods`]) and the limits it has.
fn model_impl(md: &ModelDerivation, fs: &[Function]) -> TokenStream {
    let a = md.ansatz();
    let ty = ident(&camel(a.id));
    let info = model_info(md, fs);
    let opt = |present: bool, body: TokenStream| {
        if present {
            quote!(Some(#body))
        } else {
            quote!(None)
        }
    };
    let non_adhesive_body = opt(has(fs, "non_adhesive_rho"), quote!(non_adhesive_rho(s)));
    let zero_force_body = opt(has(fs, "zero_force_rho"), quote!(zero_force_rho(s)));
    let near_circular_body = opt(
        has(fs, "near_circular_ds_dmu"),
        quote!(near_circular_ds_dmu(a0)),
    );
    let critical_body = opt(
        has(fs, "axisymmetric_critical"),
        quote!(axisymmetric_critical()[0]),
    );
    let axisymmetric_body = opt(
        has(fs, "axisymmetric_dbar"),
        quote!((axisymmetric_dbar(a_bar), axisymmetric_force_bar(a_bar))),
    );
    let body = match md {
        ModelDerivation::Collocation(_) => collocation_methods(),
        ModelDerivation::Energy(_) => energy_methods(),
    };
    let doc = format!(" The model `{}`: {}.", a.id, a.title);
    quote! {
        use crate::model::{BranchPoints, ClosureKind, Model, ModelInfo, PressureParameters};
        use nalgebra::{Matrix2, Matrix3, Vector2, Vector3};
        #info
        #[doc = #doc]
        #[derive(Clone, Copy, Debug, Default)]
        pub struct #ty;
        #[allow(unused_variables)]
        impl Model for #ty {
            fn info(&self) -> &'static ModelInfo {
                &INFO
            }
            #body
            fn non_adhesive_rho(&self, s: f64) -> Option<f64> {
                #non_adhesive_body
            }
            fn axisymmetric(&self, a_bar: f64) -> Option<(f64, f64)> {
                #axisymmetric_body
            }
            fn zero_force_rho(&self, s: f64) -> Option<f64> {
                #zero_force_body
            }
            fn near_circular_ds_dmu(&self, a0: f64) -> Option<f64> {
                #near_circular_body
            }
            fn axisymmetric_critical_a(&self) -> Option<f64> {
                #critical_body
            }
        }
    }
}

/// The static `INFO` of one model: its name, title, closure, and which
/// limits it has (and why one is missing).
fn model_info(md: &ModelDerivation, fs: &[Function]) -> TokenStream {
    let a = md.ansatz();
    let model_name = a.id;
    let title = a.title;
    let note = a.closure.describe();
    let (closure, degree) = match a.closure {
        Closure::Max => (quote!(ClosureKind::Max), 1u32),
        Closure::AtPoint(_) => (quote!(ClosureKind::AtPoint), 1),
        Closure::Energy => (quote!(ClosureKind::Energy), 2),
    };
    let degree = Literal::u32_unsuffixed(degree);
    let non_adhesive = has(fs, "non_adhesive_rho");
    let axisymmetric = has(fs, "axisymmetric_dbar");
    let zero_force = has(fs, "zero_force_rho");
    let near_circular = has(fs, "near_circular_ds_dmu");
    let missing = match md {
        ModelDerivation::Collocation(d) => match &d.limits {
            Ok(_) => String::new(),
            Err(e) => format!("limits not derived: {e}"),
        },
        ModelDerivation::Energy(e) => {
            let mut m = vec!["the non-adhesive, zero-force and near-circular relations are not derived for the energy closure (its residuals are quadratic in dbar); the solver finds the non-adhesive end of the branch numerically".to_string()];
            if let Err(x) = crate::energy::axisymmetric(e) {
                m.push(format!("axisymmetric limit: {x}"));
            }
            m.join("; ")
        }
    };
    quote! {
        /// What this model is and has.
        pub static INFO: ModelInfo = ModelInfo {
            name: #model_name,
            title: #title,
            closure: #closure,
            closure_note: #note,
            residual_degree: #degree,
            has_non_adhesive_limit: #non_adhesive,
            has_axisymmetric_limit: #axisymmetric,
            has_zero_force_limit: #zero_force,
            has_near_circular_limit: #near_circular,
            missing_limits: #missing,
        };
    }
}

/// The methods of `impl Model` a collocation closure's derivation gives
/// (residuals through η(s), the collocated normal derivative).
fn collocation_methods() -> TokenStream {
    quote! {
        fn residuals_and_jacobian(&self, x: Vector2<f64>, rho: f64, delta_bar: f64) -> (Vector2<f64>, Matrix2<f64>) {
            let [eta, eta_s] = eta_and_eta_s(x[1]);
            let v = residuals_and_jacobian_eta(x[0], x[1], rho, delta_bar, eta, eta_s);
            (Vector2::new(v[0], v[1]), Matrix2::new(v[2], v[3], v[4], v[5]))
        }
        fn residuals_d_delta(&self, x: Vector2<f64>, rho: f64, delta_bar: f64) -> Vector2<f64> {
            let [eta, eta_s] = eta_and_eta_s(x[1]);
            Vector2::from(residuals_d_dbar_eta(x[0], x[1], rho, delta_bar, eta, eta_s))
        }
        fn force_bar(&self, x: Vector2<f64>, _rho: f64, delta_bar: f64) -> f64 {
            force_bar(x[0], x[1], delta_bar, eta(x[1]))
        }
        fn force_bar_gradient(&self, x: Vector2<f64>, _rho: f64, delta_bar: f64) -> Vector3<f64> {
            let [eta, eta_s] = eta_and_eta_s(x[1]);
            Vector3::from(force_bar_gradient_eta(x[0], x[1], delta_bar, eta, eta_s))
        }
        fn branch(&self, s: f64, rho: f64) -> BranchPoints {
            let [x, y] = branch_eta(s, rho, eta(s));
            if x.is_finite() && x > 0.0 && y.is_finite() {
                let a = x.cbrt();
                [Some((a, y / a)), None]
            } else {
                [None, None]
            }
        }
        fn normal_derivative(&self, x: Vector2<f64>, _rho: f64, delta_bar: f64, u: f64) -> f64 {
            let e = eta(x[1]);
            let xi = xi(x[0], x[1], delta_bar, e);
            normal_derivative_collocated(p0_bar(x[0], xi, e), x[0], x[1], xi, u)
        }
        fn edge_slopes(&self, x: Vector2<f64>, _rho: f64, delta_bar: f64) -> [f64; 2] {
            let e = eta(x[1]);
            let xi = xi(x[0], x[1], delta_bar, e);
            let p0 = p0_bar(x[0], xi, e);
            [
                normal_derivative_collocated(p0, x[0], x[1], xi, 0.0),
                normal_derivative_collocated(p0, x[0], x[1], xi, 1.0),
            ]
        }
        fn pressure_parameters(&self, x: Vector2<f64>, _rho: f64, delta_bar: f64) -> PressureParameters {
            let e = eta(x[1]);
            let xi = xi(x[0], x[1], delta_bar, e);
            PressureParameters { p0: p0_bar(x[0], xi, e), shape: shape(x[0], x[1], xi), xi }
        }
        fn pressure(&self, px: f64, py: f64, x: Vector2<f64>, rho: f64, delta_bar: f64) -> f64 {
            let p = self.pressure_parameters(x, rho, delta_bar);
            pressure(px, py, p.p0, x[0], x[1], p.xi)
        }
        fn bc_error(&self, x: Vector2<f64>, _rho: f64, _delta_bar: f64) -> f64 {
            bc_error(x[1])
        }
        fn potential(&self, _x: Vector2<f64>, _rho: f64, _delta_bar: f64) -> Option<f64> {
            None
        }
        fn potential_hessian(&self, _x: Vector2<f64>, _rho: f64, _delta_bar: f64) -> Option<Matrix3<f64>> {
            None
        }
    }
}

/// The methods of `impl Model` the energy closure's derivation gives
/// (quadratic residuals, a branch from a polynomial's roots, a potential).
fn energy_methods() -> TokenStream {
    quote! {
        fn residuals_and_jacobian(&self, x: Vector2<f64>, rho: f64, delta_bar: f64) -> (Vector2<f64>, Matrix2<f64>) {
            let v = residuals_and_jacobian(x[0], x[1], delta_bar, rho);
            (Vector2::new(v[0], v[1]), Matrix2::new(v[2], v[3], v[4], v[5]))
        }
        fn residuals_d_delta(&self, x: Vector2<f64>, rho: f64, delta_bar: f64) -> Vector2<f64> {
            Vector2::from(residuals_d_dbar(x[0], x[1], delta_bar, rho))
        }
        fn force_bar(&self, x: Vector2<f64>, rho: f64, delta_bar: f64) -> f64 {
            force_bar(x[0], x[1], delta_bar, rho)
        }
        fn force_bar_gradient(&self, x: Vector2<f64>, rho: f64, delta_bar: f64) -> Vector3<f64> {
            Vector3::from(force_bar_gradient(x[0], x[1], delta_bar, rho))
        }
        fn branch(&self, s: f64, rho: f64) -> BranchPoints {
            let mut out = [None, None];
            let roots = crate::model::real_roots(&branch_poly(s, rho));
            let d = INFO.residual_degree as f64;
            let mut k = 0;
            for t in roots.into_iter().flatten() {
                let xd = branch_x_pow(t, s, rho);
                if xd.is_finite() && xd > 0.0 {
                    let x = xd.powf(1.0 / d);
                    let a = x.cbrt();
                    out[k] = Some((a, t * x / a));
                    k += 1;
                }
            }
            out
        }
        fn normal_derivative(&self, x: Vector2<f64>, rho: f64, delta_bar: f64, u: f64) -> f64 {
            normal_derivative(x[0], x[1], delta_bar, rho, u)
        }
        fn pressure_parameters(&self, x: Vector2<f64>, rho: f64, delta_bar: f64) -> PressureParameters {
            let [p0, a, b, xi] = pressure_parameters(x[0], x[1], delta_bar, rho);
            PressureParameters { p0, shape: [a, b], xi }
        }
        fn pressure(&self, px: f64, py: f64, x: Vector2<f64>, rho: f64, delta_bar: f64) -> f64 {
            pressure(px, py, x[0], x[1], delta_bar, rho)
        }
        fn bc_error(&self, x: Vector2<f64>, rho: f64, delta_bar: f64) -> f64 {
            crate::model::contour_spread(|u| normal_derivative(x[0], x[1], delta_bar, rho, u))
        }
        fn potential(&self, x: Vector2<f64>, rho: f64, delta_bar: f64) -> Option<f64> {
            Some(potential(x[0], x[1], delta_bar, rho))
        }
        fn potential_hessian(&self, x: Vector2<f64>, rho: f64, delta_bar: f64) -> Option<Matrix3<f64>> {
            Some(Matrix3::from_row_slice(&potential_hessian(x[0], x[1], delta_bar, rho)))
        }
    }
}

/// The Rust source of one model's module.
/// The form of `f` that passes the accuracy check with errors measured
/// against `scale`: as derived (`None`), charts in 1 − s, 1 − ρ, with
/// cancelling radicals rationalised, or charts of that; else the failures
/// of the last form tried.
fn search_form(
    f: &Function,
    scale: Scale,
) -> Result<(Option<Charted>, f64, &'static str), Vec<Failure>> {
    let domain = domain_of(f.name);
    let check = |outs: &[Atom], chart: Option<&Chart>| {
        crate::accuracy::check_scaled(f.name, &f.params, outs, domain, chart, scale)
    };
    // the worst error over every chart, or the failures
    let all_charts = |charts: &Charted| -> Result<f64, Vec<Failure>> {
        let (mut worst, mut failures) = (0.0_f64, Vec::new());
        for (chart, outs) in charts {
            match check(outs, Some(chart)) {
                Ok(w) => worst = worst.max(w),
                Err(mut v) => failures.append(&mut v),
            }
        }
        if failures.is_empty() {
            Ok(worst)
        } else {
            Err(failures)
        }
    };
    if let Ok(w) = check(&f.outputs, None) {
        return Ok((None, w, "as derived"));
    }
    // the single expression fails: try charts in 1 − s, 1 − ρ
    let charts = charts_for(f);
    if charts.len() > 1 {
        if let Ok(w) = all_charts(&charts) {
            return Ok((Some(charts), w, "charts in 1 − s, 1 − ρ"));
        }
    }
    // then with cancelling radicals rationalised (one chart, or charts)
    let pr = probe(&f.params);
    let rationalized = Function {
        name: f.name,
        doc: f.doc.clone(),
        params: f.params.clone(),
        outputs: f.outputs.iter().map(|o| rationalize(o, &pr)).collect(),
    };
    if let Ok(w) = check(&rationalized.outputs, None) {
        let one = vec![(Chart { shifted: vec![] }, rationalized.outputs)];
        return Ok((Some(one), w, "radicals rationalised"));
    }
    let charts = charts_for(&rationalized);
    match all_charts(&charts) {
        Ok(w) if charts.len() > 1 => Ok((
            Some(charts),
            w,
            "radicals rationalised, charts in 1 − s, 1 − ρ",
        )),
        Ok(_) => Err(Vec::new()),
        Err(v) => Err(v),
    }
}

/// What the accuracy check found for one generated function.
pub struct FormReport {
    /// The function's name.
    pub function: &'static str,
    /// The form written: as derived, charts, rationalised.
    pub form: &'static str,
    /// What the error was measured against.
    pub scale: Scale,
    /// The worst relative error over the sample points.
    pub worst: f64,
}

/// The Rust source of one model's module.
pub fn module_source(md: &ModelDerivation) -> Result<String, String> {
    module(md).map(|(src, _)| src)
}

/// The Rust source of one model's module and what its accuracy check found.
pub fn module(md: &ModelDerivation) -> Result<(String, Vec<FormReport>), String> {
    let mut fs = match md {
        ModelDerivation::Collocation(d) => functions(d)?,
        ModelDerivation::Energy(e) => functions_energy(e)?,
    };
    let mut failures = Vec::new();
    let mut reports = Vec::new();
    let mut charted: HashMap<&str, Charted> = HashMap::new();
    for f in &mut fs {
        let mut scale = scale_of(f.name);
        let found = match search_form(f, scale) {
            Err(_) if scale == Scale::Value => {
                // no cancellation-free form: accept the default measure and
                // say so in the function's documentation
                scale = Scale::Terms;
                let r = search_form(f, scale);
                if r.is_ok() {
                    f.doc.push_str(NOT_CANCELLATION_FREE);
                }
                r
            }
            r => r,
        };
        match found {
            Ok((c, worst, form)) => {
                reports.push(FormReport {
                    function: f.name,
                    form,
                    scale,
                    worst,
                });
                if let Some(c) = c {
                    charted.insert(f.name, c);
                }
            }
            Err(mut v) => failures.append(&mut v),
        }
    }
    if !failures.is_empty() {
        let shown: Vec<String> = failures.iter().take(12).map(|f| f.to_string()).collect();
        return Err(format!(
            "model {}: the accuracy check of the generated code failed at {} points:\n{}",
            md.ansatz().id,
            failures.len(),
            shown.join("\n")
        ));
    }
    let mut items = Vec::new();
    for f in &fs {
        items.push(render_function(f, charted.get(f.name))?);
    }
    items.push(model_impl(md, &fs));
    let a = md.ansatz();
    let file = quote! { #(#items)* };
    let ast: syn::File =
        syn::parse2(file).map_err(|e| format!("generated code does not parse: {e}"))?;
    let body = prettyplease::unparse(&ast);
    let header = format!(
        "//! @generated by `cargo run --release -p thinjkr-derive -- generate` (thinjkr-derive codegen); do not edit.\n//!\n//! Model `{}`: {}.\n//! Pressure: `{}`; collocation: {}; closure: {}.\n\n",
        a.id, a.title, a.pressure, a.collocation_note, a.closure.describe()
    );
    Ok((format!("{header}{body}"), reports))
}

/// `generated/mod.rs`: the module list and [`ModelId`], the run-time choice
/// of a model.
fn mod_source(all: &[&ModelDerivation], families: &[&str]) -> Result<String, String> {
    let family_mods: Vec<Ident> = families.iter().map(|f| ident(f)).collect();
    let mods: Vec<Ident> = all.iter().map(|m| ident(m.ansatz().id)).collect();
    let variants: Vec<Ident> = all.iter().map(|m| ident(&camel(m.ansatz().id))).collect();
    let names: Vec<&str> = all.iter().map(|m| m.ansatz().id).collect();
    let docs: Vec<String> = all
        .iter()
        .map(|m| format!(" `{}`: {}.", m.ansatz().id, m.ansatz().title))
        .collect();
    let n = Literal::usize_unsuffixed(all.len());
    let list = names.join(", ");
    let err = format!("unknown model (allowed: {list})");
    let file = quote! {
        #(pub mod #mods;)*
        #(pub mod #family_mods;)*
        pub mod registry;
        /// A generated model, chosen at run time.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
        #[serde(rename_all = "snake_case")]
        #[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
        #[non_exhaustive]
        pub enum ModelId {
            #(#[doc = #docs] #variants,)*
        }
        impl ModelId {
            /// Every generated model, the paper's first.
            pub const ALL: [ModelId; #n] = [#(ModelId::#variants),*];
            /// The model's name (its ansatz identifier).
            pub fn name(self) -> &'static str {
                match self { #(ModelId::#variants => #names,)* }
            }
            /// The model as one value behind the solver's interface.
            pub fn model(self) -> &'static dyn crate::model::Model {
                match self { #(ModelId::#variants => &#mods::#variants,)* }
            }
        }
        impl ::core::fmt::Display for ModelId {
            fn fmt(&self, f: &mut ::core::fmt::Formatter<'_>) -> ::core::fmt::Result {
                f.write_str(self.name())
            }
        }
        impl ::core::str::FromStr for ModelId {
            type Err = String;
            fn from_str(s: &str) -> Result<ModelId, String> {
                match s {
                    #(#names => Ok(ModelId::#variants),)*
                    other => Err(format!("{}: {}", #err, other)),
                }
            }
        }
    };
    let ast: syn::File =
        syn::parse2(file).map_err(|e| format!("generated mod.rs does not parse: {e}"))?;
    Ok(format!(
        "//! @generated by `cargo run --release -p thinjkr-derive -- generate`; do not edit.\n//!\n//! One module per model, each a set of straight-line `f64` functions derived\n//! symbolically by thinjkr-derive and one value implementing `crate::model::Model`.\n\n{}",
        prettyplease::unparse(&ast)
    ))
}

/// The generated modules and their `mod.rs`.
/// `families` names the contour families' modules (each written by
/// `codegen_conformal`), declared beside the models' and the registry.
pub fn outputs(all: &[&ModelDerivation], families: &[&str]) -> Result<Vec<Output>, String> {
    let mut out = Vec::new();
    let mut reports = Vec::new();
    for md in all {
        let (src, r) = module(md)?;
        out.push(Output {
            path: format!("solver/src/generated/{}.rs", md.ansatz().id).into(),
            contents: src,
        });
        reports.push((md.ansatz(), r));
    }
    out.push(Output {
        path: "docs/codegen-accuracy.md".into(),
        contents: accuracy_md(&reports),
    });
    out.push(Output {
        path: "solver/src/generated/mod.rs".into(),
        contents: mod_source(all, families)?,
    });
    Ok(out)
}

/// `docs/codegen-accuracy.md`: what the generator's accuracy check measured for
/// every generated function of every model.
fn accuracy_md(reports: &[(&crate::ansatz::Ansatz, Vec<FormReport>)]) -> String {
    let mut o = String::new();
    o.push_str(
        "<!-- @generated by `cargo run --release -p thinjkr-derive -- generate`; do not edit. -->\n\n",
    );
    o.push_str("# Accuracy of the generated code\n\n");
    o.push_str(&format!(
        "Every function under `solver/src/generated/` is checked by the generator before it is written \
         (`derive/src/accuracy.rs`): it is evaluated in `f64` with the emitted code's expression tree and \
         division structure, and in 192- and 384-bit binary floating point (astro-float) at the exact `f64` inputs, \
         at sample points across its domain (s from 0.05 to 1 including 1 − 1e-6 and 1; ρ from 0.05 to 1; \
         ā and δ̄ over the physical range). Generation fails, naming the function and the point, \
         when an error exceeds {:e}.\n\n\
         *Against the terms*: the error is relative to max(|value|, 1e-3 · M), M the value with every term \
         replaced by its magnitude (a value near 0 is judged against the terms that cancel to it). \
         *Against the value*: relative to |value| alone, also where the value tends to 0; required of \
         the quantity (14), which vanishes at s = 1, and reported where no form meets it.\n\n\
         The form is the first that passes, in this order: as derived; in charts where s or ρ ≥ 1/2 is \
         written through 1 − s, 1 − ρ; with cancelling sums A + B√Q rationalised to (A² − B²Q)/(A − B√Q); both. \
         \"As derived\" is the derived expression in the layout chosen before that search, each where it \
         passes the same check (else the plain derived form): η factored into powers of irreducible \
         polynomials and η' written as η · d ln η/ds (η's radicals then serve both); the residuals and their \
         Jacobian collected in η, r = Σ η^k R_k with each R_k free of η, differentiated part by part (far \
         shorter than the fraction over a common denominator: the paper's model's warm solve went from \
         1.23 to 1.08 times the hand-written one, `docs/performance.md`).\n",
        crate::accuracy::TOLERANCE
    ));
    for (a, rs) in reports {
        o.push_str(&format!("\n## Model `{}`: {}\n\n", a.id, a.title));
        o.push_str("| function | form | error measured against | worst relative error |\n|---|---|---|---|\n");
        for r in rs {
            let scale = match r.scale {
                Scale::Terms if CANCELLATION_FREE.contains(&r.function) => {
                    "the terms (**no cancellation-free form found**)"
                }
                Scale::Terms => "the terms",
                Scale::Value => "the value",
            };
            o.push_str(&format!(
                "| `{}` | {} | {} | {:.1e} |\n",
                r.function, r.form, scale, r.worst
            ));
        }
    }
    o
}
