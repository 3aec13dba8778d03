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

use crate::generate::Output;
use crate::ir::Ir;
use crate::model::Derivation;
use crate::sym::{diff, ex, simplify, subs};
use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::quote;
use std::collections::HashMap;
use symbolica::atom::Atom;

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

fn render_function(f: &Function) -> Result<TokenStream, String> {
    let irs: Vec<Ir> = f
        .outputs
        .iter()
        .map(Ir::from_atom)
        .collect::<Result<_, _>>()?;
    for ir in &irs {
        for v in ir.variables() {
            if !f.params.contains(&v.as_str()) {
                return Err(format!("{}: unbound variable {v}", f.name));
            }
        }
    }
    let mut em = Emitter::new(&irs.iter().collect::<Vec<_>>());
    let values: Vec<TokenStream> = irs.iter().map(|e| em.emit(e)).collect();
    let lets = &em.lets;
    let name = ident(f.name);
    let params: Vec<TokenStream> = f
        .params
        .iter()
        .map(|p| {
            let id = ident(&rust_name(p));
            quote!(#id: f64)
        })
        .collect();
    let doc = format!(" {}", f.doc);
    let (ret, body) = if values.len() == 1 {
        let v = &values[0];
        (quote!(f64), quote!(#v))
    } else {
        let n = Literal::usize_unsuffixed(values.len());
        (quote!([f64; #n]), quote!([#(#values),*]))
    };
    Ok(quote! {
        #[doc = #doc]
        #[inline]
        #[allow(clippy::all, unused_parens, unused_variables)]
        pub fn #name(#(#params),*) -> #ret {
            #(#lets)*
            #body
        }
    })
}

/// The functions generated for one derivation.
fn functions(d: &Derivation) -> Result<Vec<Function>, String> {
    let eta_s = simplify(&diff(&d.eta, "s"));
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
    let state = vec!["abar", "s", "rho", "dbar", "eta", "eta_s"];
    // Dimensional functions take the ansatz's own shape parameters.
    let with_shape = |head: &[&'static str], tail: &[&'static str]| -> Vec<&'static str> {
        head.iter()
            .chain(d.ansatz.shape_params.iter())
            .chain(tail.iter())
            .copied()
            .collect()
    };
    let mut fs = vec![
        Function { name: "eta", doc: "η(s) of Eq. (16): the maximum of ∂p/∂ν on the contour over its apex value.".into(), params: vec!["s"], outputs: vec![d.eta.clone()] },
        Function { name: "eta_s", doc: "dη/ds, derivative of Eq. (16).".into(), params: vec!["s"], outputs: vec![eta_s.clone()] },
        Function { name: "eta_and_eta_s", doc: "`[η, dη/ds]` of Eq. (16), side by side (shared subexpressions computed once).".into(), params: vec!["s"], outputs: vec![d.eta.clone(), eta_s] },
        Function { name: "bc_error", doc: "Quantity (14) as a fraction: (max − min)/min of ∂p/∂ν on the contour Γ₀.".into(), params: vec!["s"], outputs: vec![d.bc_error.clone()] },
        Function { name: "residuals_eta", doc: "Residuals (19), (20) with η = η(s) and η' = dη/ds passed in.".into(), params: state.clone(), outputs: r.clone() },
        Function { name: "residuals_and_jacobian_eta", doc: "Residuals (19), (20) and their Jacobian with respect to (ā, s), side by side: `[r1, r2, ∂r1/∂ā, ∂r1/∂s, ∂r2/∂ā, ∂r2/∂s]`; η and η' passed in.".into(), params: state.clone(), outputs: rj },
        Function { name: "residuals_d_dbar_eta", doc: "∂(19)/∂δ̄, ∂(20)/∂δ̄ (for continuation and load control); η passed in.".into(), params: state.clone(), outputs: r.iter().map(|x| diff(x, "dbar")).collect() },
        Function { name: "xi", doc: "ξ from the first line of Eq. (15).".into(), params: vec!["abar", "s", "dbar", "eta"], outputs: vec![d.xi[0].clone()] },
        Function { name: "force_bar", doc: "F̄ of Eq. (18) in its derived form (the printed (18) lacks η(s); see docs/errata.md).".into(), params: vec!["abar", "s", "dbar", "eta"], outputs: vec![d.fbar_reduced.clone()] },
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
        fs.push(Function { name: "near_circular_ds_dmu", doc: "ds/dμ at μ = 0 and fixed δ for ρ = (1 − μ)/(1 + μ): by (35) equal to −2a₂/a₀ with a₂ from (36).".into(), params: vec!["abar0"], outputs: vec![l.near_circular_model.s1.clone()] });
    }
    Ok(fs)
}

/// The names of the functions every generated module provides (for the
/// solver's `Model` trait).
pub fn module_source(d: &Derivation) -> Result<String, String> {
    let mut items = Vec::new();
    for f in functions(d)? {
        items.push(render_function(&f)?);
    }
    let id = d.ansatz.id;
    let file = quote! { #(#items)* };
    let ast: syn::File =
        syn::parse2(file).map_err(|e| format!("generated code does not parse: {e}"))?;
    let body = prettyplease::unparse(&ast);
    let header = format!(
        "//! @generated by `cargo run -p thinjkr-derive -- generate` (thinjkr-derive codegen); do not edit.\n//!\n//! Ansatz `{id}`: {}.\n//! Pressure: `{}`; collocation: {}.\n\n",
        d.ansatz.title, d.ansatz.pressure, d.ansatz.collocation_note
    );
    Ok(format!("{header}{body}"))
}

/// The generated modules and their `mod.rs`.
pub fn outputs(all: &[&Derivation]) -> Result<Vec<Output>, String> {
    let mut out = Vec::new();
    let mut mods = String::from("//! @generated by `cargo run -p thinjkr-derive -- generate`; do not edit.\n//!\n//! One module per ansatz, each a set of straight-line `f64` functions derived\n//! symbolically by thinjkr-derive.\n\n");
    for d in all {
        out.push(Output {
            path: format!("solver/src/generated/{}.rs", d.ansatz.id).into(),
            contents: module_source(d)?,
        });
        mods.push_str(&format!("pub mod {};\n", d.ansatz.id));
    }
    out.push(Output {
        path: "solver/src/generated/mod.rs".into(),
        contents: mods,
    });
    Ok(out)
}
