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
//! 384-bit evaluations of the symbolic derivatives. For the small members
//! (K ≤ [`UNROLLED_MAX_TERMS`]) the member's module also holds `second`, the
//! table evaluator unrolled over its rows: the same operations in the same
//! order (bit for bit the same results), 1.6× faster for K = 4.
//!
//! Exponents are packed four bits each: c₁ … c_K from the lowest bits,
//! then δ̄ at bit 32 and μ = 1/ρ at bit 36. Rows are sorted by their
//! c-exponents so that the evaluator can merge rows that differ only in δ̄
//! and μ.
//!
//! Owns: the generated modules of the contour families and their registry.
//! May use: `conformal`, `family`, `generate`.

use crate::conformal::{self, ConformalDerivation, Poly};
use crate::family::Family;
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

/// The largest K whose module also gets `second`, the table evaluator
/// unrolled over its rows. Above it the unrolled source would grow from
/// 0.3 MB (K = 4) to 0.9 MB (K = 5) and 12.7 MB (K = 8), and the table
/// evaluator serves alone.
pub const UNROLLED_MAX_TERMS: usize = 4;

/// `second(c, dbar, mu)`: Π̄, its gradient and its Hessian in (c, δ̄) from
/// the member's rows, the operations of `thinjkr::conformal::poly::evaluate`
/// at order 2 in the same order with every index, exponent and coefficient
/// a constant, so that the results are the table evaluator's bit for bit
/// (the solver's tests compare them) at about 1.7× its speed. Products by
/// an exact 1 and sums of an exact 0 are left to the compiler, which drops
/// them without changing a bit; the one term the evaluator adds that is
/// always an exact 0 (∂²/∂c_i² of a factor of exponent 1) is not emitted.
fn unrolled_second(k: usize, rows: &[(u64, f64)]) -> TokenStream {
    let field = |p: u64, shift: u32| ((p >> shift) & ((1 << BITS) - 1)) as usize;
    let c_mask = (1u64 << DBAR_SHIFT) - 1;
    let mut groups: Vec<(u64, Vec<(usize, usize, f64)>)> = Vec::new();
    for &(p, kappa) in rows {
        let key = p & c_mask;
        if groups.last().map(|g| g.0) != Some(key) {
            groups.push((key, Vec::new()));
        }
        if let Some(g) = groups.last_mut() {
            g.1.push((field(p, DBAR_SHIFT), field(p, MU_SHIFT), kappa));
        }
    }
    let top = rows
        .iter()
        .flat_map(|&(p, _)| (0..=MU_SHIFT / BITS).map(move |f| field(p, BITS * f)))
        .max()
        .unwrap_or(0);
    let pw = |name: &str, e: usize| format_ident!("{name}_{e}");
    let g_id = |i: usize| format_ident!("g{i}");
    let h_id = |i: usize, j: usize| format_ident!("h{}_{}", i.min(j), i.max(j));
    let n = k + 1;
    let mut body = Vec::new();
    // the powers, each the previous times the base (as the evaluator's)
    let bases = (0..k).map(|i| (format!("c{i}"), quote!(c[#i]))).chain([
        ("d".to_string(), quote!(dbar)),
        ("m".to_string(), quote!(mu)),
    ]);
    for (name, value) in bases {
        let (zero, one) = (pw(&name, 0), pw(&name, 1));
        body.push(quote!(let #zero = 1.0f64; let #one = #value;));
        for e in 2..=top {
            let (now, before) = (pw(&name, e), pw(&name, e - 1));
            body.push(quote!(let #now = #before * #one;));
        }
    }
    body.push(quote!(let mut value = 0.0f64;));
    for i in 0..n {
        let g = g_id(i);
        body.push(quote!(let mut #g = 0.0f64;));
        for j in i..n {
            let h = h_id(i, j);
            body.push(quote!(let mut #h = 0.0f64;));
        }
    }
    for (key, group) in &groups {
        let g = unrolled_group(k, *key, group);
        body.push(quote!({ #(#g)* }));
    }
    let grads: Vec<_> = (0..n).map(g_id).collect();
    let hess: Vec<TokenStream> = (0..n)
        .map(|i| {
            let row: Vec<_> = (0..n).map(|j| h_id(i, j)).collect();
            let pad = (n..9).map(|_| quote!(0.0));
            quote!([#(#row,)* #(#pad),*])
        })
        .collect();
    let pad_rows = (n..9).map(|_| quote!([0.0; 9]));
    let pad_grad = (n..9).map(|_| quote!(0.0));
    quote! {
        /// Π̄ with its gradient and Hessian in (c, δ̄) at μ = 1/ρ: the table
        /// evaluator (`crate::ansatz::poly::evaluate`, order 2) unrolled
        /// over this member's rows, the same operations in the same order.
        /// `c` holds the K map coefficients.
        #[allow(clippy::all, unused_parens, unused_variables, unused_mut)]
        pub fn second(c: &[f64], dbar: f64, mu: f64) -> crate::ansatz::poly::Second {
            assert_eq!(c.len(), #k, "one value per map coefficient");
            #(#body)*
            crate::ansatz::poly::Second {
                n: #n,
                value,
                grad: [#(#grads,)* #(#pad_grad),*],
                hess: [#(#hess,)* #(#pad_rows),*],
            }
        }
    }
}

/// One group of [`unrolled_second`]'s rows, those of one monomial in the
/// map coefficients (`key`, their exponents): the group's polynomial in δ̄
/// and μ with its first two δ̄-derivatives, times the monomial, added to
/// the value, gradient and Hessian, the monomial's derivatives by prefix
/// and suffix products of its factors.
fn unrolled_group(k: usize, key: u64, group: &[(usize, usize, f64)]) -> Vec<TokenStream> {
    let field = |p: u64, shift: u32| ((p >> shift) & ((1 << BITS) - 1)) as usize;
    let f = |v: f64| Literal::f64_unsuffixed(v);
    let pw = |name: &str, e: usize| format_ident!("{name}_{e}");
    let c_pw = |i: usize, e: usize| pw(&format!("c{i}"), e);
    let g_id = |i: usize| format_ident!("g{i}");
    let h_id = |i: usize, j: usize| format_ident!("h{}_{}", i.min(j), i.max(j));
    let (gd, hdd) = (g_id(k), h_id(k, k));
    let factors: Vec<(usize, usize)> = (0..k)
        .map(|i| (i, field(key, BITS * i as u32)))
        .filter(|&(_, e)| e > 0)
        .collect();
    let m = factors.len();
    let mut g = vec![quote!(let (mut a0, mut a1, mut a2) = (0.0f64, 0.0f64, 0.0f64);)];
    for &(dp, q, kappa) in group {
        let (kappa, mq) = (f(kappa), pw("m", q));
        g.push(quote!(let coef = #kappa * #mq;));
        let d0 = pw("d", dp);
        g.push(quote!(a0 += coef * #d0;));
        if dp >= 1 {
            let (e, d1) = (f(dp as f64), pw("d", dp - 1));
            g.push(quote!(a1 += coef * #e * #d1;));
        }
        if dp >= 2 {
            let (e, d2) = (f((dp * (dp - 1)) as f64), pw("d", dp - 2));
            g.push(quote!(a2 += coef * #e * #d2;));
        }
    }
    let f0 = |x: usize| format_ident!("f0_{x}");
    let f1 = |x: usize| format_ident!("f1_{x}");
    let pre = |x: usize| format_ident!("pre_{x}");
    let suf = |x: usize| format_ident!("suf_{x}");
    for (x, &(i, e)) in factors.iter().enumerate() {
        let (a, b, p, q) = (f0(x), f1(x), c_pw(i, e), c_pw(i, e - 1));
        let ef = f(e as f64);
        g.push(quote!(let #a = #p; let #b = #ef * #q;));
    }
    let p0 = pre(0);
    g.push(quote!(let #p0 = 1.0f64;));
    for x in 0..m {
        let (now, before, fx) = (pre(x + 1), pre(x), f0(x));
        g.push(quote!(let #now = #before * #fx;));
    }
    let sm = suf(m);
    g.push(quote!(let #sm = 1.0f64;));
    for x in (0..m).rev() {
        let (now, after, fx) = (suf(x), suf(x + 1), f0(x));
        g.push(quote!(let #now = #after * #fx;));
    }
    let pm = pre(m);
    g.push(quote!(
        let mono = #pm;
        value += a0 * mono;
        #gd += a1 * mono;
        #hdd += a2 * mono;
    ));
    for (x, &(i, e)) in factors.iter().enumerate() {
        let (px, sx1, f1x) = (pre(x), suf(x + 1), f1(x));
        let (gi, hik, hii) = (g_id(i), h_id(i, k), h_id(i, i));
        g.push(quote!(
            let others = #px * #sx1;
            let d_i = #f1x * others;
            #gi += a0 * d_i;
            #hik += a1 * d_i;
        ));
        if e >= 2 {
            let (c2, p2) = (f((e * (e - 1)) as f64), c_pw(i, e - 2));
            g.push(quote!(#hii += a0 * (#c2 * #p2) * others;));
        }
        if x + 1 < m {
            g.push(quote!(let a_fx_pre = a0 * #f1x * #px;));
            // the product of the factors strictly between x and y
            let mut between = quote!(1.0f64);
            for y in x + 1..m {
                let (j, f1y, sy1, f0y) = (factors[y].0, f1(y), suf(y + 1), f0(y));
                let hij = h_id(i, j);
                g.push(quote!(#hij += a_fx_pre * #f1y * (#between) * #sy1;));
                between = quote!((#between) * #f0y);
            }
        }
    }
    g
}

/// The module of one member: the map's powers and how many leading rows
/// of the family's tables are its own.
fn member_source(
    d: &ConformalDerivation,
    potential: &[(u64, f64)],
    slope_rows: &[(u16, usize)],
) -> Result<String, String> {
    let potential_rows = potential.len();
    let second = if d.ansatz.terms <= UNROLLED_MAX_TERMS {
        unrolled_second(d.ansatz.terms, potential)
    } else {
        TokenStream::new()
    };
    let k = Literal::usize_unsuffixed(d.ansatz.terms);
    let powers: Vec<Literal> = d
        .ansatz
        .powers()
        .iter()
        .map(|p| Literal::u16_unsuffixed(*p))
        .collect();
    let n_pot = Literal::usize_unsuffixed(potential_rows);
    let slope: Vec<TokenStream> = slope_rows
        .iter()
        .map(|(n, r)| {
            let (n, r) = (Literal::u16_unsuffixed(*n), Literal::usize_unsuffixed(*r));
            quote!((#n, #r))
        })
        .collect();
    let doc_pot = format!(
        " Π̄(c, δ̄; μ) of `{}`: the first {potential_rows} rows of `table::POTENTIAL`.",
        d.ansatz.name()
    );
    let file = quote! {
        /// The powers of ζ in the map w(ζ) = Σ c_k ζ^(n_k).
        pub const POWERS: [u16; #k] = [#(#powers),*];
        #[doc = #doc_pot]
        pub const POTENTIAL_ROWS: usize = #n_pot;
        /// The boundary slope's modes n and how many leading rows of `table::SLOPE`'s mode n are this member's.
        pub const SLOPE_ROWS: &[(u16, usize)] = &[#(#slope),*];
        #second
    };
    let ast: syn::File =
        syn::parse2(file).map_err(|e| format!("generated conformal code does not parse: {e}"))?;
    Ok(format!(
        "//! @generated by `cargo run --release -p thinjkr-derive -- generate` (thinjkr-derive codegen_conformal); do not edit.\n//!\n//! Model `{}`: {}.\n//! Particular solution: `{}`; gap: `{}`.\n\n{}",
        d.ansatz.name(),
        d.ansatz.title,
        d.ansatz.particular,
        d.ansatz.gap,
        prettyplease::unparse(&ast)
    ))
}

/// The family's tables, those of its largest member: every smaller member's
/// rows are a prefix of them (setting c_(K+1) = 0 in Π̄ of K + 1 terms gives
/// Π̄ of K terms, and rows are sorted with c₁'s exponent in the lowest bits),
/// which the generator checks row by row.
fn table_source(
    d: &ConformalDerivation,
    potential: &[(u64, f64)],
    slope: &[(u16, Vec<(u64, f64)>)],
) -> Result<String, String> {
    let pot = table(potential);
    let modes: Vec<TokenStream> = slope
        .iter()
        .map(|(n, rows)| {
            let n = Literal::u16_unsuffixed(*n);
            let t = table(rows);
            quote!((#n, #t))
        })
        .collect();
    let doc = format!(
        " Π̄(c, δ̄; μ) of `{}`, {} monomials, coefficients rounded from the exact rationals times π.",
        d.ansatz.name(),
        potential.len()
    );
    // Some coefficients are the rationals 1/2, 1/4, … times π, rounded:
    // clippy takes them for hand-typed approximations of the constants.
    let file = quote! {
        #![allow(clippy::approx_constant)]
        #[doc = #doc]
        pub static POTENTIAL: &[(u64, f64)] = #pot;
        /// ∂p̄/∂r at |ζ| = 1 as Σ g_n(c, δ̄; μ) cos(nθ): (n, rows of g_n).
        pub static SLOPE: &[(u16, &[(u64, f64)])] = &[#(#modes),*];
    };
    let ast: syn::File =
        syn::parse2(file).map_err(|e| format!("generated conformal table does not parse: {e}"))?;
    Ok(format!(
        "//! @generated by `cargo run --release -p thinjkr-derive -- generate` (thinjkr-derive codegen_conformal); do not edit.\n//!\n//! The tables of `{}`; every member of the family uses a prefix of them (see each member's module).\n\n{}",
        d.ansatz.name(),
        prettyplease::unparse(&ast)
    ))
}

/// The generated files of the family: the tables, one module per member
/// and their `mod.rs`. Fails unless every member's rows are a prefix of
/// the largest member's.
pub fn outputs(all: &[ConformalDerivation]) -> Result<Vec<Output>, String> {
    let largest = all
        .iter()
        .max_by_key(|d| d.ansatz.terms)
        .ok_or("no member of the family to generate")?;
    let big_pot = rows(largest, &largest.potential, true)?;
    let big_slope: Vec<(u16, Vec<(u64, f64)>)> = largest
        .boundary_slope
        .iter()
        .map(|(n, g)| rows(largest, g, false).map(|r| (*n, r)))
        .collect::<Result<_, _>>()?;
    let dir = format!("solver/src/generated/{}", largest.ansatz.family);
    let mut out = vec![Output {
        path: format!("{dir}/table.rs").into(),
        contents: table_source(largest, &big_pot, &big_slope)?,
    }];
    let mut layout = Vec::new();
    for d in all {
        let name = d.ansatz.name();
        let pot = rows(d, &d.potential, true)?;
        if big_pot.get(..pot.len()) != Some(&pot[..]) {
            return Err(format!("{name}: its rows of Π̄ are not a prefix of the largest member's (the family does not nest)"));
        }
        let mut slope_rows = Vec::new();
        for (n, g) in &d.boundary_slope {
            let r = rows(d, g, false)?;
            let big = big_slope
                .iter()
                .find(|(m, _)| m == n)
                .map(|(_, b)| b)
                .ok_or_else(|| {
                    format!(
                        "{name}: mode {n} of the boundary slope is missing in the largest member"
                    )
                })?;
            if big.get(..r.len()) != Some(&r[..]) {
                return Err(format!(
                    "{name}: its boundary slope's mode {n} is not a prefix of the largest member's"
                ));
            }
            slope_rows.push((*n, r.len()));
        }
        out.push(Output {
            path: format!("{dir}/k{}.rs", d.ansatz.terms).into(),
            contents: member_source(d, &pot, &slope_rows)?,
        });
        layout.push((d.ansatz.terms, d.ansatz.powers(), pot.len(), slope_rows));
    }
    out.push(Output {
        path: format!("{dir}/tables.json").into(),
        contents: tables_json(&largest.ansatz.name(), &big_pot, &big_slope, &layout),
    });
    let mods: Vec<_> = all
        .iter()
        .map(|d| format_ident!("k{}", d.ansatz.terms))
        .collect();
    let terms: Vec<Literal> = all
        .iter()
        .map(|d| Literal::usize_unsuffixed(d.ansatz.terms))
        .collect();
    let seconds: Vec<TokenStream> = all
        .iter()
        .zip(&mods)
        .map(|(d, m)| match d.ansatz.terms <= UNROLLED_MAX_TERMS {
            true => quote!(Some(#m::second)),
            false => quote!(None),
        })
        .collect();
    let n = Literal::usize_unsuffixed(all.len());
    let family = &largest.ansatz.family;
    let file = quote! {
        pub mod table;
        #(pub mod #mods;)*
        /// Every generated member, by K.
        pub static MEMBERS: [crate::ansatz::Tables; #n] = [
            #(crate::ansatz::Tables {
                terms: #terms,
                powers: &#mods::POWERS,
                potential: table::POTENTIAL,
                potential_rows: #mods::POTENTIAL_ROWS,
                slope: table::SLOPE,
                slope_rows: #mods::SLOPE_ROWS,
                second: #seconds,
            }),*
        ];
    };
    let ast: syn::File =
        syn::parse2(file).map_err(|e| format!("generated conformal mod.rs does not parse: {e}"))?;
    out.push(Output {
        path: format!("{dir}/mod.rs").into(),
        contents: format!(
            "//! @generated by `cargo run --release -p thinjkr-derive -- generate`; do not edit.\n//!\n//! The family `{family}:K`, K = 1 … {}: Π̄ and the boundary slope as monomial tables (`table`, those of the\n//! largest member; each member uses a prefix of them), exponents packed {BITS} bits each: c₁ … c_K from bit 0,\n//! δ̄ at bit {DBAR_SHIFT}, μ at bit {MU_SHIFT}.\n\n{}",
            all.len(),
            prettyplease::unparse(&ast)
        ),
    });
    Ok(out)
}

/// One member's layout in the family's tables: K, the map's powers, its
/// rows of Π̄ and its boundary slope's modes with their rows.
type MemberLayout = (usize, Vec<u16>, usize, Vec<(u16, usize)>);

/// `tables.json`: the family's tables and every member's layout as data,
/// for the solver to load at run time (`THINJKR_FAMILIES`), so that a
/// family added as a data file needs no rebuild of the solver. The same
/// rows as `table.rs`, one per line; every `f64` written in its shortest
/// form that reads back to the same bits.
fn tables_json(
    largest: &str,
    potential: &[(u64, f64)],
    slope: &[(u16, Vec<(u64, f64)>)],
    layout: &[MemberLayout],
) -> String {
    let num = |c: f64| serde_json::to_string(&c).expect("finite coefficients");
    let rows = |rs: &[(u64, f64)], indent: &str| -> String {
        rs.iter()
            .map(|(p, c)| format!("{indent}[{p}, {}]", num(*c)))
            .collect::<Vec<_>>()
            .join(",\n")
    };
    let mut o = String::new();
    o.push_str("{\n");
    o.push_str(&format!(
        "  \"generated\": \"by `cargo run --release -p thinjkr-derive -- generate`; do not edit: the tables of {largest}\",\n"
    ));
    o.push_str(&format!(
        "  \"packing\": {{\"bits\": {BITS}, \"dbar_shift\": {DBAR_SHIFT}, \"mu_shift\": {MU_SHIFT}}},\n"
    ));
    o.push_str("  \"members\": [\n");
    let members: Vec<String> = layout
        .iter()
        .map(|(k, powers, pot, slope_rows)| {
            format!(
                "    {{\"terms\": {k}, \"powers\": {}, \"potential_rows\": {pot}, \"slope_rows\": {}}}",
                serde_json::to_string(powers).expect("integers"),
                serde_json::to_string(slope_rows).expect("integers")
            )
        })
        .collect();
    o.push_str(&members.join(",\n"));
    o.push_str("\n  ],\n  \"potential\": [\n");
    o.push_str(&rows(potential, "    "));
    o.push_str("\n  ],\n  \"slope\": [\n");
    let modes: Vec<String> = slope
        .iter()
        .map(|(n, rs)| format!("    [{n}, [\n{}\n    ]]", rows(rs, "      ")))
        .collect();
    o.push_str(&modes.join(",\n"));
    o.push_str("\n  ]\n}\n");
    o
}

/// Derive every member K = 1 … of a family, each checked as it is derived;
/// an error names the family's data file and the member.
pub fn derive_family(family: &Family) -> Result<Vec<ConformalDerivation>, String> {
    family
        .members()
        .iter()
        .map(|m| {
            conformal::derive(m)
                .map_err(|e| format!("{} ({}): {e}", m.name(), family.source.display()))
        })
        .collect()
}

/// `solver/src/generated/registry.rs`: every contour family, in the order
/// of their data files, with what the solver needs to know of it besides
/// its tables. `exact_gap[i]` says whether family i's gap is the one the
/// exact solver solves ([`crate::family::EXACT_GAP`]).
/// Beside it, `registry.json`: the same entries as data, which the solver
/// reads at run time to load the families it was not built with
/// (`THINJKR_FAMILIES`).
///
/// Each entry carries the digest of its family's `tables.json`
/// (`tables_digests`, in the families' order), and the registry the digest
/// of its entries, so that the solver refuses a file edited by hand
/// ([`digest`]).
pub fn registry_outputs(
    families: &[Family],
    exact_gap: &[bool],
    tables_digests: &[String],
) -> Result<Vec<Output>, String> {
    let entries: Vec<serde_json::Value> = families
        .iter()
        .zip(exact_gap)
        .zip(tables_digests)
        .map(|((f, &on_exact_gap), tables_digest)| {
            Ok(serde_json::json!({
                "name": f.name,
                "kind": f.kind,
                "title": f.title,
                "gap": f.gap,
                "particular": f.particular,
                "particular_terms": conformal::particular_terms(&f.particular)?,
                "source": f.source.display().to_string().replace('\\', "/"),
                "rho_min": f.rho_min,
                "rho_min_why": f.rho_min_why,
                "trace_start_a": f.trace_start_a,
                "on_exact_gap": on_exact_gap,
                "seeds_exact": f.seeds_exact,
                "doubtful_defects": f.doubtful_defects,
                "tables": format!("{}/tables.json", f.name),
                "tables_digest": tables_digest,
            }))
        })
        .collect::<Result<_, String>>()?;
    // the entries' digest, over their compact JSON (as the solver reads it
    // back from this file)
    let entries = serde_json::Value::Array(entries);
    let entries_digest = digest(
        serde_json::to_string(&entries)
            .map_err(|e| e.to_string())?
            .as_bytes(),
    );
    let json = serde_json::to_string_pretty(&serde_json::json!({
        "generated": "by `cargo run --release -p thinjkr-derive -- generate` from derive/families/*.toml; do not edit",
        "digest": entries_digest,
        "families": entries,
    }))
    .map_err(|e| e.to_string())?;
    Ok(vec![
        registry_output(families, exact_gap)?,
        Output {
            path: "solver/src/generated/registry.json".into(),
            contents: json + "\n",
        },
    ])
}

/// The digest of a generated file's bytes that the solver checks before it
/// loads the file: 64-bit FNV-1a in 16 hexadecimal digits. It catches a file
/// edited by hand or damaged (it is not a defence against a forger).
pub fn digest(bytes: &[u8]) -> String {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for &b in bytes {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    format!("{h:016x}")
}

fn registry_output(families: &[Family], exact_gap: &[bool]) -> Result<Output, String> {
    let entries: Vec<TokenStream> = families
        .iter()
        .zip(exact_gap)
        .map(|(f, &on_exact_gap)| {
            let (name, kind, title, gap, particular) =
                (&f.name, &f.kind, &f.title, &f.gap, &f.particular);
            let source = f.source.display().to_string().replace('\\', "/");
            let module = format_ident!("{}", f.name);
            let rho_min = Literal::f64_unsuffixed(f.rho_min);
            let rho_min_why = &f.rho_min_why;
            let trace = match f.trace_start_a {
                Some(a) => {
                    let a = Literal::f64_unsuffixed(a);
                    quote! { Some(#a) }
                }
                None => quote! { None },
            };
            let seeds = f.seeds_exact;
            let lines = f.doubtful_defects.iter().map(|v| Literal::f64_unsuffixed(*v));
            let terms = conformal::particular_terms(&f.particular)?;
            let terms = terms.iter().map(|[x, y, mu, dbar, num, den]| {
                let [x, y, mu, dbar] = [x, y, mu, dbar].map(|v| Literal::u8_unsuffixed(*v as u8));
                let (num, den) = (Literal::i64_unsuffixed(*num), Literal::i64_unsuffixed(*den));
                quote! {
                    crate::exact::gap::Term { x: #x, y: #y, mu: #mu, dbar: #dbar, num: #num, den: #den }
                }
            });
            Ok(quote! {
                crate::ansatz::Family {
                    name: #name,
                    kind: #kind,
                    title: #title,
                    gap: #gap,
                    particular: #particular,
                    source: #source,
                    rho_min: #rho_min,
                    rho_min_why: #rho_min_why,
                    trace_start_a: #trace,
                    on_exact_gap: #on_exact_gap,
                    seeds_exact: #seeds,
                    doubtful_defects: &[#(#lines),*],
                    members: &super::#module::MEMBERS,
                    particular_terms: &[#(#terms),*],
                }
            })
        })
        .collect::<Result<_, String>>()?;
    let n = Literal::usize_unsuffixed(families.len());
    let file = quote! {
        /// Every contour family, in the order of their data files' names.
        pub static CONTOUR_FAMILIES: [crate::ansatz::Family; #n] = [#(#entries),*];
    };
    let ast: syn::File =
        syn::parse2(file).map_err(|e| format!("generated registry.rs does not parse: {e}"))?;
    Ok(Output {
        path: "solver/src/generated/registry.rs".into(),
        contents: format!(
            "//! @generated by `cargo run --release -p thinjkr-derive -- generate` from `{}/*.toml`; do not edit.\n//!\n//! The registry of the contour families: one entry per data file, read by the solver, the command line\n//! and the Python package (`thinjkr::registry`).\n\n{}",
            crate::family::FOLDER,
            prettyplease::unparse(&ast)
        ),
    })
}

/// The section of `docs/derivation.md` on the family: its data, the steps
/// and checks of [`conformal::derive`], Π̄ for K = 1 and K = 2 in full, and
/// for every K what was derived (sizes of Π̄, its Hessian, the boundary
/// slope and the generated module).
pub fn derivation_section(family: &Family, all: &[ConformalDerivation]) -> String {
    crate::markdown::wrap_prose(&derivation_prose(family, all), crate::markdown::WIDTH)
}

fn derivation_prose(family: &Family, all: &[ConformalDerivation]) -> String {
    let mut o = String::new();
    let Some(first) = all.first() else {
        return o;
    };
    let a = &first.ansatz;
    o.push_str(&format!(
        "\n## The family `{}:K`\n\n\
         Beyond the ellipse (7) (data file `{}`: {}): the contact domain is the image of the unit disk under the odd polynomial map \
         $w(\\zeta) = \\sum_{{k=1}}^{{K}} c_k \\zeta^{{n_k}}$ with $n_k$ = {} (real $c_k$, so both symmetries of the problem hold), \
         $\\bar a = w(1)$, $\\bar b = |w(i)|$. In the units (17), (2) reads $\\Delta\\bar p = \\bar\\varphi - \\bar\\delta$ with \
         $\\bar\\varphi$ = `{}` ($\\mu = 1/\\rho$), and the data give the particular solution $P$ = `{}`. \
         The pressure is $\\bar p = P + h$ with $h$ harmonic and $h = -P$ on the contour; the closure of (3)₂ is the Ritz \
         method on $\\bar\\Pi = \\tfrac12\\int_\\omega \\bar p(\\bar\\delta - \\bar\\varphi)\\,dA - \\tfrac12|\\omega|$ (the energy model's \
         potential, whose constant factors `energy` checks against $U - \\Delta\\gamma|\\omega|$): the state makes $\\bar\\Pi$ \
         stationary in $c_1 \\dots c_K$ at fixed $\\bar\\delta$, and $\\bar F = \\partial\\bar\\Pi/\\partial\\bar\\delta$.\n\n\
         Derived with symbolica's polynomials over the rationals (`derive/src/conformal.rs`), each step checked as it is taken \
         (the derivation fails otherwise):\n\n\
         1. $\\Delta P = \\bar\\varphi - \\bar\\delta$ (symbolic Laplacian);\n\
         2. $X + iY = w$, $X - iY = \\bar w$ turn $P$ into a polynomial in $\\zeta, \\bar\\zeta$ (the $i$ cancels: $P$ is even in $Y$);\n\
         3. on $|\\zeta| = 1$, $\\bar\\zeta = 1/\\zeta$: each term $\\kappa\\zeta^a\\bar\\zeta^b$ of $P$ gets the correction \
         $-\\kappa\\zeta^{{a-m}}\\bar\\zeta^{{b-m}}$, $m = \\min(a, b)$ (harmonic, equal to the term on the circle); checked: \
         $\\bar p = 0$ on $|\\zeta| = 1$, and $4\\partial_\\zeta\\partial_{{\\bar\\zeta}}\\bar p = (\\bar\\varphi - \\bar\\delta)|w'|^2$ inside, i.e. (2) on $\\omega$;\n\
         4. $\\int_\\omega f\\,dA = \\int_{{|\\zeta|<1}} f |w'|^2\\,dA$ and $\\int \\zeta^j\\bar\\zeta^k dA = \\pi\\delta_{{jk}}/(j+1)$ give \
         $\\bar\\Pi/\\pi$ exactly; checked: $\\partial\\bar\\Pi/\\partial\\bar\\delta = \\int_\\omega\\bar p\\,dA$ computed separately (the force identity);\n\
         5. the boundary slope $\\partial\\bar p/\\partial r$ at $|\\zeta| = 1$, $\\sum_n g_n \\cos n\\theta$ (checked real), gives \
         $\\partial\\bar p/\\partial\\nu = (\\partial\\bar p/\\partial r)/|w'|$, whose distance from 1 is the defect of (3)₂ the Ritz closure leaves.\n\n\
         Beside these, `tests/tests/conformal.rs` holds $\\bar\\Pi$ against a quadrature of its definition whose harmonic \
         correction comes from a discrete Fourier transform (no polynomial algebra), `conformal:1` against the energy model \
         at $s = 1$ (the same circle by a separate derivation), and the generated tables against 256-bit evaluations of the \
         symbolic derivatives; `solver/tests/conformal.rs` holds the solved family against the exact solution.\n",
        a.family,
        family.source.display(),
        a.title,
        family
            .powers
            .iter()
            .map(|n| n.to_string())
            .collect::<Vec<_>>()
            .join(", "),
        a.gap,
        a.particular
    ));
    let latex = |p: &Poly| crate::sym::latex(&p.to_expression());
    o.push_str(&format!(
        "\n### K = 1 (the circle)\n\n$$\\bar\\Pi/\\pi = {}$$\n",
        latex(&first.potential)
    ));
    if let Some(d2) = all.iter().find(|d| d.ansatz.terms == 2) {
        o.push_str(
            "\n### K = 2\n\n$\\bar\\Pi/\\pi = \\sum_{p,q} \\bar\\delta^p\\mu^q\\,Q_{pq}(c_1, c_2)$ with\n\n| p | q | $Q_{pq}$ |\n|---|---|---|\n",
        );
        let (_, dbar, mu) = d2.layout();
        let mut groups: std::collections::BTreeMap<
            (u16, u16),
            Vec<(Vec<u16>, symbolica::domains::rational::Rational)>,
        > = Default::default();
        for t in d2.potential.into_iter() {
            let mut e = t.exponents.to_vec();
            let key = (e[dbar], e[mu]);
            e[dbar] = 0;
            e[mu] = 0;
            groups
                .entry(key)
                .or_default()
                .push((e, t.coefficient.clone()));
        }
        for ((p, q), terms) in groups {
            let mut poly = d2.potential.zero();
            for (e, c) in terms {
                poly.append_monomial(c, &e);
            }
            o.push_str(&format!("| {p} | {q} | ${}$ |\n", latex(&poly)));
        }
    }
    let (degree_c, degree_dbar, degree_mu) = all.last().map(|d| d.degrees()).unwrap_or((0, 0, 0));
    o.push_str(&format!(
        "\n### Every member of `{}:K`: what was derived and generated\n\n\
         Π̄ is a polynomial of degree {degree_c} in c (degree {degree_dbar} in δ̄ and {degree_mu} in μ). The residuals ∇_c Π̄ and F̄ are its gradient, their \
         Jacobian its Hessian in (c, δ̄); the solver evaluates all three from the one table of Π̄'s monomials \
         (`solver/src/generated/{}/kK.rs`, [codegen-accuracy.md](codegen-accuracy.md)).\n\n\
         | K | monomials of Π̄ | of F̄ | upper triangle of the Hessian in (c, δ̄) | in c alone | boundary-slope modes (rows) |\n\
         |---|---|---|---|---|---|\n",
        a.family, a.family
    ));
    for d in all {
        let (n_pot, n_hess) = d.sizes();
        let k = d.ansatz.terms;
        let mut hess_c = 0;
        for i in 0..k {
            for j in i..k {
                hess_c += d.potential_derivative(&[i, j]).nterms();
            }
        }
        let slope_rows: usize = d.boundary_slope.iter().map(|(_, g)| g.nterms()).sum();
        o.push_str(&format!(
            "| {k} | {n_pot} | {} | {n_hess} | {hess_c} | {} ({slope_rows}) |\n",
            d.force.nterms(),
            d.boundary_slope.len()
        ));
    }
    o
}

/// The section of `docs/codegen-accuracy.md` on the family's tables: their
/// size, and how their accuracy is measured.
pub fn accuracy_section(all: &[ConformalDerivation], outputs: &[Output]) -> String {
    crate::markdown::wrap_prose(&accuracy_prose(all, outputs), crate::markdown::WIDTH)
}

fn accuracy_prose(all: &[ConformalDerivation], outputs: &[Output]) -> String {
    let family = all.first().map(|d| d.ansatz.family.as_str()).unwrap_or("?");
    let mut o = format!(
        "\n## The family `{family}:K`: monomial tables\n\n\
         Π̄ of each member is emitted as a table of monomials (exponents packed 4 bits each, coefficient the exact \
         rational times π rounded once to f64), from which `thinjkr::conformal::poly` evaluates Π̄, its gradient and \
         its Hessian in (c, δ̄) side by side: a monomial's derivatives are exact in its integer exponents, so the only \
         roundings are the coefficients' (half an ulp each) and those of the sums. Expanded residuals and Jacobians \
         would hold the Hessian's monomials instead (counted in the table of derivation.md). \
         `tests/tests/conformal.rs` measures the f64 evaluation against 256-bit evaluations of the symbolic Π̄, ∂Π̄ and \
         ∂²Π̄ at four points across the domain (ρ = 1, 0.8, 0.5, 0.3; c₁ from 0.3 to 8 with higher coefficients \
         decaying by 0.02 to 0.15 per term; δ̄ from −5 to 20), relative to max(|value|, 1e-3 M) with M the sum of the terms' \
         magnitudes, and fails above 1e-12 (it prints the worst error per K).\n\n\
         Every member's rows are a prefix of the largest member's (Π̄ of K + 1 terms at c_(K+1) = 0 is Π̄ of K terms), \
         which the generator checks row by row; so one table (`solver/src/generated/{family}/table.rs`) serves the \
         whole family, and each member's module holds its row counts.\n\n\
         | K | rows of Π̄ | rows of the boundary slope |\n|---|---|---|\n",
    );
    for d in all {
        let slope: usize = d.boundary_slope.iter().map(|(_, g)| g.nterms()).sum();
        o.push_str(&format!(
            "| {} | {} | {slope} |\n",
            d.ansatz.terms,
            d.potential.nterms()
        ));
    }
    let size: usize = outputs
        .iter()
        .filter(|o| {
            o.path
                .starts_with(format!("solver/src/generated/{family}/"))
        })
        .map(|o| o.contents.len())
        .sum();
    let unrolled: Vec<String> = outputs
        .iter()
        .filter(|o| o.contents.contains("pub fn second("))
        .map(|o| {
            let name = o.path.file_stem().and_then(|s| s.to_str()).unwrap_or("?");
            format!("{name} {:.0} kB", o.contents.len() as f64 / 1000.0)
        })
        .collect();
    o.push_str(&format!(
        "\nThe family's generated source: {:.0} kB. For K ≤ {UNROLLED_MAX_TERMS} each member's module also holds \
         `second`, the table evaluator unrolled over the member's rows (module sizes: {}): the same floating-point \
         operations in the same order with every index, exponent and coefficient a constant, so it returns the table \
         evaluator's results bit for bit (a property test in `thinjkr::conformal` compares them at random points and \
         on the circle) and its accuracy is the table's; it takes 2.5 µs against the table evaluator's 4.0 µs for \
         K = 4 (docs/performance.md). Larger members use the table evaluator alone: unrolled, K = 5 would add 0.9 MB \
         of source and K = 8 12.7 MB (measured by generating them).\n",
        size as f64 / 1000.0,
        unrolled.join(", ")
    ));
    o
}

#[cfg(test)]
mod tests {
    /// The digest is FNV-1a 64: the reference implementation's vectors
    /// (Fowler, Noll and Vo's test suite).
    #[test]
    fn the_digest_is_fnv_1a_64() {
        assert_eq!(super::digest(b""), "cbf29ce484222325");
        assert_eq!(super::digest(b"a"), "af63dc4c8601ec8c");
        assert_eq!(super::digest(b"foobar"), "85944171f73967e8");
    }
}
