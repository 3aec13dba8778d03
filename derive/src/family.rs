//! Families of contour ansätze as data files: every `derive/families/*.toml`
//! is one family, found by `generate` without any edit of Rust code. A file
//! names its kind (today `conformal`: a polynomial map of the unit disk, the
//! pressure exact in (2), the Ritz closure of (3)₂), its name and title, the
//! scaled gap φ̄ and a particular solution of (2) in symbolica syntax, the
//! powers of the map (member K takes the first K), the smallest ρ the solver
//! accepts, where its pull-off trace starts, and whether its largest member
//! seeds the exact solver of its gap.
//!
//! Reading a file checks what can be checked without deriving: unknown or
//! missing keys, a name that is an identifier and no other model's, powers
//! that are distinct positive odd numbers (the map must keep both symmetries
//! of the problem) and at most [`MAX_TERMS`], ranges of the numbers, and
//! that the expressions parse. The derivation then checks the mathematics
//! (`conformal::derive`).
//!
//! Owns: [`Family`], reading and checking the family files. May use:
//! `conformal`, `sym`, `ansatz` (the names already taken).

use crate::conformal::{ConformalAnsatz, MAX_TERMS};
use serde::Deserialize;
use std::path::{Path, PathBuf};

/// The folder of the family files, relative to the workspace root.
pub const FOLDER: &str = "derive/families";

/// The gap the exact solver (`thinjkr::exact`) solves today: the quadratic
/// gap of the cylinders (1) in the units (17). A family on it is measured
/// against the exact solution; one of them seeds the exact solver.
pub const EXACT_GAP: &str = "X^2/2 + mu*Y^2/2";

/// The largest family data file read (a family file is a few lines).
const MAX_FILE_BYTES: u64 = 64 * 1024;

/// The kinds of family the generator knows.
pub const KINDS: &[&str] = &["conformal"];

/// Names no family may take: the ellipse models', `exact`, and the
/// registry's own module names.
const RESERVED: &[&str] = &["exact", "registry", "mod", "table", "families"];

/// A family file as written.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Raw {
    kind: String,
    name: String,
    title: String,
    gap: String,
    particular: String,
    powers: Vec<u16>,
    rho_min: f64,
    trace_start_a: f64,
    #[serde(default)]
    seeds_exact: bool,
}

/// One family, read and checked.
#[derive(Clone, Debug, PartialEq)]
pub struct Family {
    /// Its kind (one of [`KINDS`]).
    pub kind: String,
    /// Its name; members are `name:K`.
    pub name: String,
    /// One line for reports.
    pub title: String,
    /// The scaled gap φ̄(X, Y), symbolica syntax in `X`, `Y`, `mu`.
    pub gap: String,
    /// A particular solution of ΔP = φ̄ − δ̄ (2), in `X`, `Y`, `dbar`, `mu`.
    pub particular: String,
    /// The powers of ζ in the map; members K = 1 … `powers.len()`.
    pub powers: Vec<u16>,
    /// The smallest ρ the solver accepts for the family.
    pub rho_min: f64,
    /// ā at which the pull-off trace starts.
    pub trace_start_a: f64,
    /// Whether its largest member seeds the exact solver of its gap.
    pub seeds_exact: bool,
    /// The data file, relative to the workspace root.
    pub source: PathBuf,
}

impl Family {
    /// The largest K generated.
    pub fn largest(&self) -> usize {
        self.powers.len()
    }

    /// Member K of the family.
    pub fn member(&self, terms: usize) -> ConformalAnsatz {
        ConformalAnsatz {
            family: self.name.clone(),
            terms,
            title: self.title.clone(),
            particular: self.particular.clone(),
            gap: self.gap.clone(),
            family_powers: self.powers.clone(),
        }
    }

    /// Every member, K = 1 … [`Family::largest`].
    pub fn members(&self) -> Vec<ConformalAnsatz> {
        (1..=self.largest()).map(|k| self.member(k)).collect()
    }
}

/// Parse and check one family file's text; `source` names it in errors.
pub fn parse(text: &str, source: &Path) -> Result<Family, String> {
    let at = source.display();
    let raw: Raw = toml::from_str(text).map_err(|e| format!("{at}: {}", e.message()))?;
    if !KINDS.contains(&raw.kind.as_str()) {
        return Err(format!(
            "{at}: kind = {:?} is not a kind the generator knows (one of: {})",
            short(&raw.kind),
            KINDS.join(", ")
        ));
    }
    let ident = raw.name.len() <= 32
        && raw.name.starts_with(|c: char| c.is_ascii_lowercase())
        && raw
            .name
            .chars()
            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_');
    if !ident {
        return Err(format!(
            "{at}: name = {:?} must be a lower-case identifier of at most 32 characters (a-z, 0-9, _; a letter first)",
            short(&raw.name)
        ));
    }
    let taken = RESERVED.contains(&raw.name.as_str())
        || crate::ansatz::ALL.iter().any(|a| a.id == raw.name);
    if taken {
        return Err(format!(
            "{at}: name = {:?} is taken (by an ellipse model, `exact` or a generated module)",
            raw.name
        ));
    }
    if raw.title.trim().is_empty() || raw.title.len() > 200 || raw.title.contains('\n') {
        return Err(format!(
            "{at}: title must be one line of 1 to 200 characters"
        ));
    }
    if raw.powers.is_empty() || raw.powers.len() > MAX_TERMS {
        return Err(format!(
            "{at}: powers must list 1 to {MAX_TERMS} powers of the map (it lists {})",
            raw.powers.len()
        ));
    }
    for (k, &n) in raw.powers.iter().enumerate() {
        if n % 2 == 0 || n > 31 {
            return Err(format!(
                "{at}: powers[{k}] = {n}: every power must be odd (the map keeps both symmetries of the problem) and at most 31"
            ));
        }
        if raw.powers[..k].contains(&n) {
            return Err(format!("{at}: powers[{k}] = {n} is listed twice"));
        }
    }
    if raw.powers[0] != 1 {
        return Err(format!(
            "{at}: powers[0] = {}: the first power must be 1 (member 1 is then the circle, where every member starts)",
            raw.powers[0]
        ));
    }
    if !(raw.rho_min > 0.0 && raw.rho_min <= 1.0) {
        return Err(format!(
            "{at}: rho_min = {} must lie in (0, 1]",
            raw.rho_min
        ));
    }
    if !(raw.trace_start_a > 0.0 && raw.trace_start_a <= 100.0) {
        return Err(format!(
            "{at}: trace_start_a = {} must lie in (0, 100]",
            raw.trace_start_a
        ));
    }
    for (key, e) in [("gap", &raw.gap), ("particular", &raw.particular)] {
        crate::sym::try_ex(e)
            .map(drop)
            .map_err(|why| format!("{at}: {key} does not parse: {why}"))?;
    }
    Ok(Family {
        kind: raw.kind,
        name: raw.name,
        title: raw.title,
        gap: raw.gap,
        particular: raw.particular,
        powers: raw.powers,
        rho_min: raw.rho_min,
        trace_start_a: raw.trace_start_a,
        seeds_exact: raw.seeds_exact,
        source: source.to_path_buf(),
    })
}

/// At most 40 characters of a value, for messages.
fn short(s: &str) -> String {
    match s.char_indices().nth(40) {
        Some((i, _)) => format!("{}…", &s[..i]),
        None => s.to_string(),
    }
}

/// Every family file under `root`'s [`FOLDER`], sorted by file name, read
/// and checked; no two may share a name, and at most one per gap may seed
/// the exact solver.
pub fn read_all(root: &Path) -> Result<Vec<Family>, String> {
    let dir = root.join(FOLDER);
    let entries = std::fs::read_dir(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let mut paths: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    paths.sort();
    let mut out: Vec<Family> = Vec::new();
    for p in paths {
        let rel = p.strip_prefix(root).unwrap_or(&p).to_path_buf();
        let size = std::fs::metadata(&p)
            .map_err(|e| format!("{}: {e}", rel.display()))?
            .len();
        if size > MAX_FILE_BYTES {
            return Err(format!(
                "{}: {size} bytes, more than a family file may have ({MAX_FILE_BYTES})",
                rel.display()
            ));
        }
        let text = std::fs::read_to_string(&p).map_err(|e| format!("{}: {e}", rel.display()))?;
        let f = parse(&text, &rel)?;
        if let Some(other) = out.iter().find(|o| o.name == f.name) {
            return Err(format!(
                "{}: name = {:?} is the name of {} too",
                rel.display(),
                f.name,
                other.source.display()
            ));
        }
        if f.seeds_exact {
            if let Some(other) = out
                .iter()
                .find(|o| o.seeds_exact && same_gap(&o.gap, &f.gap))
            {
                return Err(format!(
                    "{}: seeds_exact: {} seeds the exact solver of the same gap already",
                    rel.display(),
                    other.source.display()
                ));
            }
        }
        out.push(f);
    }
    if out.is_empty() {
        return Err(format!("{}: no family file (*.toml)", dir.display()));
    }
    Ok(out)
}

/// Whether two gaps are the same expression (their difference expands to 0).
pub fn same_gap(a: &str, b: &str) -> bool {
    match (crate::sym::try_ex(a), crate::sym::try_ex(b)) {
        (Ok(x), Ok(y)) => crate::sym::is_zero(&(x - y)),
        _ => false,
    }
}
