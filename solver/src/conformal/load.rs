//! Contour families loaded at run time: where the environment variable
//! [`ENV`] names a folder that `cargo run -p thinjkr-derive -- generate`
//! wrote (a checkout's `solver/src/generated/`), every family its
//! `registry.json` lists that this build was not compiled with is read from
//! its `tables.json` and joins the built-in families, so that a family added
//! as a data file needs no rebuild of the solver (the command line, the
//! library and the Python package alike). Its members use the table
//! evaluator; the built-in families keep their compiled tables.
//!
//! A file is checked before it is used: it must match the digest
//! `generate` wrote of it (the registry's entries, each family's tables), be
//! a regular file inside
//! the folder once its links are resolved, with no key the generator does
//! not write; its size is bounded before it is read, and so is the folder's
//! in all ([`MAX_FAMILIES`] families, [`MAX_FOLDER_BYTES`] bytes read,
//! [`MAX_MEMBERS`] members: each limit named when it refuses), a family may not take
//! a built-in model's name, its texts are printed with their control
//! characters escaped, the packing must be the solver's, every member's rows must be a
//! prefix of the family's tables in the generator's order, with no exponent
//! of a map coefficient the member does not have, and the map's powers must
//! be odd and distinct; then its algebra is checked by numbers
//! ([`super::algebra`]: the gap's text against the particular solution,
//! each member's tables against a quadrature). A family that fails is left out, and the reason is
//! kept ([`super::load_problems`]) for every front end to show.
//!
//! Owns: reading `registry.json` and `tables.json`. May use: `generated` (`ModelId`), `conformal`
//! (`Family`, `Tables`, `poly`'s packing, `algebra`'s check), `exact` (the gap's terms, checked
//! as the exact solver checks them), `model` and `slender` (the built-in
//! models' names), serde_json.

use super::poly::{BITS, DBAR_SHIFT, MAX_UNKNOWNS, MU_SHIFT};
use super::{Family, Tables};
use crate::exact::gap::Term;
use serde::Deserialize;
use std::path::Path;

/// The environment variable naming the folder of generated families.
pub(crate) const ENV: &str = "THINJKR_FAMILIES";

/// The largest `registry.json` read.
const MAX_REGISTRY_BYTES: u64 = 1 << 20;

/// The largest `tables.json` read (the built-in `conformal`'s is 0.6 MB).
const MAX_TABLES_BYTES: u64 = 64 << 20;

/// The folder's budget, whatever its files say: the most families its
/// registry may list (each one file read), the bytes read in all (a table
/// named by several families counts each time), and the members in all.
const MAX_FAMILIES: usize = 32;
const MAX_FOLDER_BYTES: u64 = 128 << 20;
const MAX_MEMBERS: usize = 128;

/// What the folder has spent of its budget so far.
#[derive(Default)]
struct Spent {
    bytes: u64,
    members: usize,
}

// every file is read whole by its schema: a key the generator does not
// write is an error, as in `generate` (a misspelt key would be ignored)
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Registry {
    families: Vec<Entry>,
    /// The digest of `families` as compact JSON ([`digest`], checked on
    /// the text before the entries are read).
    #[serde(rename = "digest")]
    _digest: String,
    /// The generator's note (not used).
    #[serde(default, rename = "generated")]
    _generated: Option<String>,
}

/// The digest `generate` writes of a file's bytes (derive's
/// `codegen_conformal::digest`): 64-bit FNV-1a in 16 hexadecimal digits. A
/// file whose digest differs was edited by hand or damaged, and is refused.
fn digest(bytes: &[u8]) -> String {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for &b in bytes {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    format!("{h:016x}")
}

/// What a file that does not match its digest is told.
const EDITED: &str = "does not match the digest `generate` wrote (edited by hand or damaged: regenerate it with `cargo run -p thinjkr-derive -- generate`)";

/// The names a family may not take: the built-in models', and those of
/// the generated modules (as `generate` refuses them).
fn taken(name: &str) -> bool {
    crate::ModelId::ALL.iter().any(|m| m.name() == name)
        || crate::slender::Slender::parse(name).is_some()
        || [
            "exact",
            "layer",
            "slender",
            "registry",
            "mod",
            "table",
            "families",
            "slender_registry",
        ]
        .contains(&name)
}

/// A text of the file as it is printed: its control characters (an ANSI
/// escape, a bell) written as escapes, never reaching a terminal raw.
fn printable(text: String) -> String {
    if !text.chars().any(char::is_control) {
        return text;
    }
    text.chars()
        .map(|c| {
            if c.is_control() {
                c.escape_default().to_string()
            } else {
                c.to_string()
            }
        })
        .collect()
}

/// The longest `rho_min_why` a family may give: the generator's limit
/// (derive's `family::MAX_WHY_CHARS`), which keeps docs/accuracy.md's
/// rows of it within their 400 characters.
const MAX_WHY_CHARS: usize = 72;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Entry {
    name: String,
    kind: String,
    title: String,
    gap: String,
    particular: String,
    source: String,
    rho_min: f64,
    #[serde(default)]
    rho_min_why: String,
    #[serde(default)]
    trace_start_a: Option<f64>,
    on_exact_gap: bool,
    #[serde(default)]
    seeds_exact: bool,
    #[serde(default)]
    doubtful_defects: Vec<f64>,
    particular_terms: Vec<[i64; 6]>,
    tables: String,
    /// The digest of the bytes of `tables`.
    tables_digest: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Packing {
    bits: u32,
    dbar_shift: u32,
    mu_shift: u32,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Member {
    terms: usize,
    powers: Vec<u16>,
    potential_rows: usize,
    slope_rows: Vec<(u16, usize)>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct TablesFile {
    /// The generator's note (not used).
    #[serde(default, rename = "generated")]
    _generated: Option<String>,
    packing: Packing,
    members: Vec<Member>,
    potential: Vec<(u64, f64)>,
    slope: Vec<(u16, Vec<(u64, f64)>)>,
}

fn leak(s: String) -> &'static str {
    Box::leak(s.into_boxed_str())
}

/// The file at `path` as text, read only where it is a regular file inside
/// the folder `dir` once every symbolic link is resolved, and of at most
/// `max` bytes.
fn read_bounded(dir: &Path, path: &Path, max: u64) -> Result<String, String> {
    let at = path.display();
    let inside = std::fs::canonicalize(dir)
        .and_then(|d| Ok((d, std::fs::canonicalize(path)?)))
        .map_err(|e| format!("{at}: {e}"))?;
    if !inside.1.starts_with(&inside.0) {
        return Err(format!(
            "{at}: a link to {}, outside the folder",
            inside.1.display()
        ));
    }
    let meta = std::fs::metadata(path).map_err(|e| format!("{at}: {e}"))?;
    // a FIFO or a device would block the read (or never end): regular files only
    if !meta.is_file() {
        return Err(format!("{at}: not a regular file"));
    }
    let size = meta.len();
    if size > max {
        return Err(format!("{at}: {size} bytes, more than the {max} read"));
    }
    // bounded by the bytes read too: a file that grows while it is read
    // is cut at one byte over, and refused
    let mut text = String::new();
    std::fs::File::open(path)
        .and_then(|f| {
            std::io::Read::read_to_string(&mut std::io::Read::take(f, max + 1), &mut text)
        })
        .map_err(|e| format!("{at}: {e}"))?;
    if text.len() as u64 > max {
        return Err(format!("{at}: more than the {max} bytes read"));
    }
    Ok(text)
}

/// The families in `dir`'s `registry.json` that `compiled` lacks, each
/// loaded and checked, and the reasons of those left out.
pub(crate) fn load(dir: &Path, compiled: &[Family]) -> (Vec<&'static Family>, Vec<String>) {
    let (mut out, mut problems) = (Vec::new(), Vec::new());
    let path = dir.join("registry.json");
    let registry: Registry = match read_bounded(dir, &path, MAX_REGISTRY_BYTES).and_then(|t| {
        let at = path.display();
        let value: serde_json::Value =
            serde_json::from_str(&t).map_err(|e| format!("{at}: {e}"))?;
        // the entries' digest over their compact JSON, as written
        let entries =
            serde_json::to_string(&value["families"]).map_err(|e| format!("{at}: {e}"))?;
        if value["digest"].as_str() != Some(digest(entries.as_bytes()).as_str()) {
            return Err(format!("{at}: its families {EDITED}"));
        }
        serde_json::from_value(value).map_err(|e| format!("{at}: {e}"))
    }) {
        Ok(r) => r,
        Err(why) => {
            problems.push(format!("{ENV}: {why}"));
            return (out, problems);
        }
    };
    if registry.families.len() > MAX_FAMILIES {
        problems.push(format!(
            "{ENV}: {} lists {} families, more than the {MAX_FAMILIES} a folder may hold; none was read",
            path.display(),
            registry.families.len()
        ));
        return (out, problems);
    }
    let mut spent = Spent::default();
    for entry in registry.families {
        if compiled.iter().any(|f| f.name == entry.name) {
            // a built-in family: this build's tables serve
            continue;
        }
        let name = entry.name.clone();
        match family(dir, entry, &mut spent) {
            Ok(f) if out.iter().any(|g: &&Family| g.name == f.name) => {
                problems.push(format!("{ENV}: family {name} is listed twice"))
            }
            Ok(f) => {
                let seeded = |g: &Family| g.seeds_exact && g.unseeded_gap() == f.unseeded_gap();
                if f.seeds_exact && (compiled.iter().any(seeded) || out.iter().any(|g| seeded(g))) {
                    // the family already there seeds the exact solver of this gap
                    let mut g = Family { ..*f };
                    g.seeds_exact = false;
                    out.push(Box::leak(Box::new(g)));
                } else {
                    out.push(f)
                }
            }
            Err(why) => problems.push(format!("{ENV}: family {name} left out: {why}")),
        }
    }
    (out, problems)
}

fn family(dir: &Path, e: Entry, spent: &mut Spent) -> Result<&'static Family, String> {
    let ident = !e.name.is_empty()
        && e.name.len() <= 32
        && e.name
            .chars()
            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_');
    if !ident {
        return Err("its name is not a lower-case identifier".into());
    }
    if taken(&e.name) {
        return Err("its name is taken (by a built-in model or a generated module)".into());
    }
    if e.title.trim().is_empty() || e.title.chars().count() > 200 || e.title.contains('\n') {
        return Err("its title is not one line of 1 to 200 characters".into());
    }
    if e.kind != "conformal" {
        return Err(format!("kind {:?} is not one this solver knows", e.kind));
    }
    // written so that a NaN is out of range too
    #[allow(clippy::nonminimal_bool)]
    let out_of_range = !(e.rho_min > 0.0 && e.rho_min <= 1.0)
        || e.trace_start_a.is_some_and(|a| !(a > 0.0 && a <= 100.0));
    if out_of_range {
        return Err("rho_min or trace_start_a out of range".into());
    }
    if e.rho_min_why.chars().count() > MAX_WHY_CHARS || e.rho_min_why.contains('\n') {
        return Err(format!(
            "rho_min_why is not one line of at most {MAX_WHY_CHARS} characters"
        ));
    }
    if e.tables.contains("..") || Path::new(&e.tables).is_absolute() {
        return Err(format!("its tables path {:?} leaves the folder", e.tables));
    }
    let particular_terms = gap_terms(&e.particular_terms)?;
    let path = dir.join(&e.tables);
    let left = MAX_FOLDER_BYTES - spent.bytes;
    let text = read_bounded(dir, &path, MAX_TABLES_BYTES.min(left)).map_err(|why| {
        if left < MAX_TABLES_BYTES {
            format!("{why} (the folder's families may read {MAX_FOLDER_BYTES} bytes in all, and {} were read)", spent.bytes)
        } else {
            why
        }
    })?;
    spent.bytes += text.len() as u64;
    if digest(text.as_bytes()) != e.tables_digest {
        return Err(format!("{}: {EDITED}", path.display()));
    }
    let t: TablesFile =
        serde_json::from_str(&text).map_err(|err| format!("{}: {err}", path.display()))?;
    let members = tables(t).map_err(|why| format!("{}: {why}", path.display()))?;
    if spent.members + members.len() > MAX_MEMBERS {
        return Err(format!(
            "its {} members would make more than the {MAX_MEMBERS} a folder's families may have in all",
            members.len()
        ));
    }
    spent.members += members.len();
    // the algebra, whatever the digest says (a table sealed again after an
    // edit, or written by another tool)
    super::algebra::check(&e.gap, &e.particular, particular_terms, members)?;
    let lines = &e.doubtful_defects;
    if !(lines.is_empty() || lines.len() == members.len())
        || lines.iter().any(|v| !(*v > 0.0 && *v <= 1.0))
    {
        return Err(format!(
            "doubtful_defects must give one boundary defect in (0, 1] per member ({}), or none",
            members.len()
        ));
    }
    Ok(Box::leak(Box::new(Family {
        name: leak(e.name),
        kind: leak(e.kind),
        title: leak(printable(e.title)),
        gap: leak(printable(e.gap)),
        particular: leak(printable(e.particular)),
        source: leak(printable(e.source)),
        rho_min: e.rho_min,
        rho_min_why: leak(printable(e.rho_min_why)),
        trace_start_a: e.trace_start_a,
        on_exact_gap: e.on_exact_gap,
        // whether it seeds the exact solver of its gap: decided by the
        // caller against the families already there
        seeds_exact: e.seeds_exact,
        doubtful_defects: Box::leak(e.doubtful_defects.into_boxed_slice()),
        members,
        particular_terms,
    })))
}

/// The particular solution's monomials, checked as the exact solver
/// checks a gap ([`crate::exact::Gap`]: even powers, linear in δ̄, ΔP₁ = −1).
fn gap_terms(raw: &[[i64; 6]]) -> Result<&'static [Term], String> {
    if raw.is_empty() || raw.len() > 1000 {
        return Err("its particular solution has no terms, or more than 1000".into());
    }
    let mut terms = Vec::with_capacity(raw.len());
    for &[x, y, mu, dbar, num, den] in raw {
        let small = |v: i64| u8::try_from(v).ok().filter(|v| *v <= 24);
        match (small(x), small(y), small(mu), small(dbar)) {
            (Some(x), Some(y), Some(mu), Some(dbar)) if den > 0 => terms.push(Term {
                x,
                y,
                mu,
                dbar,
                num,
                den,
            }),
            _ => {
                return Err(format!(
                    "its particular solution's term {:?} is out of range",
                    [x, y, mu, dbar, num, den]
                ))
            }
        }
    }
    let terms: &'static [Term] = Box::leak(terms.into_boxed_slice());
    crate::exact::Gap {
        name: "loaded",
        particular: terms,
        seed: None,
    }
    .at(1.0)
    .map_err(|e| e.to_string())?;
    Ok(terms)
}

/// The packed row's fields: each must fit, none above μ's.
fn row_ok(p: u64, terms: usize) -> bool {
    let c_bits = BITS * terms as u32;
    let c_used = if c_bits >= 64 {
        u64::MAX
    } else {
        (1u64 << c_bits) - 1
    };
    let c_mask = (1u64 << DBAR_SHIFT) - 1;
    p >> (MU_SHIFT + BITS) == 0 && (p & c_mask) & !c_used == 0
}

/// The rows in the generator's order: by c-exponents, then whole.
fn sorted(rows: &[(u64, f64)]) -> bool {
    let c_mask = (1u64 << DBAR_SHIFT) - 1;
    rows.windows(2)
        .all(|w| (w[0].0 & c_mask, w[0].0) <= (w[1].0 & c_mask, w[1].0))
}

fn tables(t: TablesFile) -> Result<&'static [Tables], String> {
    if (t.packing.bits, t.packing.dbar_shift, t.packing.mu_shift) != (BITS, DBAR_SHIFT, MU_SHIFT) {
        return Err("its packing is not this solver's".into());
    }
    if t.members.is_empty() || t.members.len() >= MAX_UNKNOWNS {
        return Err(format!("1 to {} members expected", MAX_UNKNOWNS - 1));
    }
    let largest = t.members.iter().map(|m| m.terms).max().unwrap_or(0);
    if t.potential
        .iter()
        .any(|&(p, c)| !row_ok(p, largest) || !c.is_finite())
        || !sorted(&t.potential)
    {
        return Err("a row of the potential is not one the generator writes".into());
    }
    for (n, rows) in &t.slope {
        if rows
            .iter()
            .any(|&(p, c)| !row_ok(p, largest) || !c.is_finite())
            || !sorted(rows)
        {
            return Err(format!(
                "a row of the boundary slope's mode {n} is not one the generator writes"
            ));
        }
    }
    for m in &t.members {
        let k = m.terms;
        let powers_ok = m.powers.len() == k
            && m.powers.first() == Some(&1)
            && m.powers.iter().all(|&n| n % 2 == 1 && n <= 31)
            && (1..k).all(|i| !m.powers[..i].contains(&m.powers[i]));
        if !(1..MAX_UNKNOWNS).contains(&k) || !powers_ok {
            return Err(format!(
                "member {k}: its K or its map's powers are not valid"
            ));
        }
        let prefix_ok = |rows: &[(u64, f64)], n: usize| {
            n <= rows.len() && rows[..n].iter().all(|&(p, _)| row_ok(p, k))
        };
        if !prefix_ok(&t.potential, m.potential_rows) {
            return Err(format!(
                "member {k}: its rows of the potential are not a prefix of the family's"
            ));
        }
        for &(n, len) in &m.slope_rows {
            let rows = t
                .slope
                .iter()
                .find(|(j, _)| *j == n)
                .map(|(_, r)| r.as_slice());
            if !rows.is_some_and(|r| prefix_ok(r, len)) {
                return Err(format!(
                    "member {k}: its boundary slope's mode {n} is not a prefix of the family's"
                ));
            }
        }
        if t.members.iter().filter(|o| o.terms == k).count() > 1 {
            return Err(format!("member {k} is listed twice"));
        }
    }
    let potential: &'static [(u64, f64)] = Box::leak(t.potential.into_boxed_slice());
    let slope: Vec<(u16, &'static [(u64, f64)])> = t
        .slope
        .into_iter()
        .map(|(n, rows)| (n, &*Box::leak(rows.into_boxed_slice())))
        .collect();
    let slope: &'static [(u16, &'static [(u64, f64)])] = Box::leak(slope.into_boxed_slice());
    let members: Vec<Tables> = t
        .members
        .into_iter()
        .map(|m| Tables {
            terms: m.terms,
            powers: Box::leak(m.powers.into_boxed_slice()),
            potential,
            potential_rows: m.potential_rows,
            slope,
            slope_rows: Box::leak(m.slope_rows.into_boxed_slice()),
            second: None,
        })
        .collect();
    Ok(Box::leak(members.into_boxed_slice()))
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;
    use std::path::{Path, PathBuf};

    /// The digest is FNV-1a 64, as `generate` writes it: the reference
    /// implementation's vectors (Fowler, Noll and Vo's test suite).
    #[test]
    fn the_digest_is_fnv_1a_64() {
        assert_eq!(super::digest(b""), "cbf29ce484222325");
        assert_eq!(super::digest(b"a"), "af63dc4c8601ec8c");
        assert_eq!(super::digest(b"foobar"), "85944171f73967e8");
    }

    fn generated(name: &str) -> String {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/generated");
        std::fs::read_to_string(root.join(name)).unwrap()
    }

    /// A folder holding the committed registry and tables of `conformal`,
    /// with `registry` and `tables` in their place.
    fn folder(tag: &str, registry: &str, tables: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("thinjkr-load-{tag}-{}", std::process::id()));
        std::fs::create_dir_all(dir.join("conformal")).unwrap();
        std::fs::write(dir.join("registry.json"), registry).unwrap();
        std::fs::write(dir.join("conformal/tables.json"), tables).unwrap();
        dir
    }

    /// The families loaded from a folder (none compiled in, so that
    /// `conformal` is read from the files), each in full as Debug prints
    /// it, and the problems.
    fn loaded(dir: &Path) -> (Vec<String>, Vec<String>) {
        let (families, problems) = super::load(dir, &[]);
        (
            families.iter().map(|f| format!("{f:?}")).collect(),
            problems,
        )
    }

    /// One corruption of a file's bytes: cut at a point, a digit turned
    /// into another, or two lines swapped.
    #[derive(Clone, Debug)]
    enum Corruption {
        Truncate(f64),
        Digit(f64, u8),
        Swap(f64, f64),
    }

    fn corrupt(text: &str, c: &Corruption) -> String {
        let at = |x: f64, n: usize| ((x * n as f64) as usize).min(n.saturating_sub(1));
        match *c {
            Corruption::Truncate(x) => text[..at(x, text.len())].to_string(),
            Corruption::Digit(x, d) => {
                let digits: Vec<usize> = text
                    .bytes()
                    .enumerate()
                    .filter(|(_, b)| b.is_ascii_digit())
                    .map(|(i, _)| i)
                    .collect();
                let i = digits[at(x, digits.len())];
                let mut bytes = text.as_bytes().to_vec();
                let old = bytes[i] - b'0';
                bytes[i] = b'0' + (old + 1 + d % 9) % 10;
                String::from_utf8(bytes).unwrap()
            }
            Corruption::Swap(x, y) => {
                let mut lines: Vec<&str> = text.lines().collect();
                let (i, j) = (at(x, lines.len()), at(y, lines.len()));
                lines.swap(i, j);
                lines.join("\n") + "\n"
            }
        }
    }

    fn corruption() -> impl Strategy<Value = Corruption> {
        prop_oneof![
            (0.0..1.0f64).prop_map(Corruption::Truncate),
            (0.0..1.0f64, any::<u8>()).prop_map(|(x, d)| Corruption::Digit(x, d)),
            (0.0..1.0f64, 0.0..1.0f64).prop_map(|(x, y)| Corruption::Swap(x, y)),
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 24, failure_persistence: None, ..ProptestConfig::default() })]

        /// Issue 72: a corrupted tables.json or registry.json (cut, a digit
        /// changed, two lines swapped) is refused with its reason, or gives
        /// the family exactly as the clean files do; never another family.
        #[test]
        fn a_corrupted_file_is_refused_or_changes_nothing(c in corruption(), registry_file in any::<bool>()) {
            let (registry, tables) = (generated("registry.json"), generated("conformal/tables.json"));
            let clean = loaded(&folder("clean", &registry, &tables));
            prop_assert!(clean.1.is_empty() && clean.0.len() == 1, "{:?}", clean.1);
            let dir = if registry_file {
                folder("bad-registry", &corrupt(&registry, &c), &tables)
            } else {
                folder("bad-tables", &registry, &corrupt(&tables, &c))
            };
            let (families, problems) = loaded(&dir);
            prop_assert!(
                (families.is_empty() && !problems.is_empty()) || (families == clean.0 && problems.is_empty()),
                "{c:?} in {}: loaded {} families, problems {problems:?}",
                if registry_file { "registry.json" } else { "tables.json" },
                families.len()
            );
        }

        /// Issue 72, without the digest: a corrupted tables.json sealed
        /// again (its digests recomputed, as a tool that rewrites it
        /// might) is refused by the loader's other checks, its algebra's
        /// among them, or its members answer as the clean file's do: Π̄
        /// and its gradient at a contact's point to 1e-8 of their terms'
        /// sizes (a digit changed far down a coefficient moves them by
        /// less; the check lets through only what moves its own two points
        /// by less than 1e-9).
        #[test]
        fn a_corrupted_file_sealed_again_is_refused_or_answers_alike(c in corruption()) {
            let (registry, tables) = (generated("registry.json"), generated("conformal/tables.json"));
            let bad = corrupt(&tables, &c);
            let mut r: serde_json::Value = serde_json::from_str(&registry).unwrap();
            r["families"][0]["tables_digest"] = super::digest(bad.as_bytes()).into();
            r["digest"] = super::digest(r["families"].to_string().as_bytes()).into();
            let dir = folder("resealed", &r.to_string(), &bad);
            let (families, problems) = super::load(&dir, &[]);
            static CLEAN: std::sync::OnceLock<Vec<&'static crate::conformal::Family>> = std::sync::OnceLock::new();
            let clean = CLEAN.get_or_init(|| super::load(&folder("clean-for-reseal", &registry, &tables), &[]).0);
            if families.is_empty() {
                prop_assert!(!problems.is_empty());
            } else {
                prop_assert!(problems.is_empty() && families.len() == 1, "{problems:?}");
                prop_assert_eq!(families[0].members.len(), clean[0].members.len());
                for (got, want) in families[0].members.iter().zip(clean[0].members) {
                    let k = want.terms;
                    prop_assert_eq!(got.terms, k);
                    let cs: Vec<f64> = (0..k).map(|j| if j == 0 { 2.4 } else { 0.05 / j as f64 }).collect();
                    let at = |t: &crate::conformal::Tables, abs: bool| {
                        let rows: Vec<(u64, f64)> = t.potential[..t.potential_rows]
                            .iter()
                            .map(|&(p, v)| (p, if abs { v.abs() } else { v }))
                            .collect();
                        crate::conformal::poly::evaluate(&crate::conformal::poly::Decoded::new(&rows, k), &cs, 0.5, 1.25, 1)
                    };
                    let (g, w, size) = (at(got, false), at(want, false), at(want, true));
                    prop_assert!((g.value - w.value).abs() <= 1e-8 * size.value, "{c:?}: K = {k}, {} vs {}", g.value, w.value);
                    for i in 0..=k {
                        prop_assert!((g.grad[i] - w.grad[i]).abs() <= 1e-8 * size.grad[i].abs().max(size.value), "{c:?}: K = {k}, gradient {i}");
                    }
                }
            }
        }
    }
}
