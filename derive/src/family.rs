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
pub use crate::slender::SlenderFamily;
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
pub const KINDS: &[&str] = &["conformal", "slender"];

/// Names no family may take: the ellipse models', `exact`, and the
/// registry's own module names.
const RESERVED: &[&str] = &[
    "exact",
    "registry",
    "mod",
    "table",
    "families",
    crate::slender::REGISTRY_MODULE,
];

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
    #[serde(default)]
    rho_min_why: String,
    #[serde(default)]
    trace_start_a: Option<f64>,
    #[serde(default)]
    seeds_exact: bool,
    #[serde(default)]
    doubtful_defects: Vec<f64>,
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
    /// Why a smaller ρ is refused, in one sentence (empty: not said).
    pub rho_min_why: String,
    /// ā at which the pull-off trace starts, where the file says: on a gap
    /// radial at ρ = 1, between two neutral points of its circle (omitted:
    /// halfway between those of modes 4 and 6); on another gap not used
    /// (the solver starts between the cylinders' neutral points of modes
    /// 2 and 4).
    pub trace_start_a: Option<f64>,
    /// Whether its largest member seeds the exact solver of its gap.
    pub seeds_exact: bool,
    /// For each member K (in order), the boundary defect max |∂p̄/∂ν − 1|
    /// above which its state is warned as doubtful, measured against the
    /// exact solution (docs/accuracy.md); empty: not measured (the
    /// solver's default line).
    pub doubtful_defects: Vec<f64>,
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

/// A slender family file as written.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSlender {
    #[allow(dead_code)]
    kind: String,
    name: String,
    title: String,
    gap: String,
}

/// A family file of any kind.
#[derive(Clone, Debug, PartialEq)]
pub enum AnyFamily {
    /// A contour family (`kind = "conformal"`).
    Conformal(Family),
    /// The slender limit (`kind = "slender"`).
    Slender(SlenderFamily),
}

impl AnyFamily {
    fn name(&self) -> &str {
        match self {
            AnyFamily::Conformal(f) => &f.name,
            AnyFamily::Slender(f) => &f.name,
        }
    }
    fn source(&self) -> &Path {
        match self {
            AnyFamily::Conformal(f) => &f.source,
            AnyFamily::Slender(f) => &f.source,
        }
    }
}

/// The families of every kind, in the order of their files' names.
#[derive(Clone, Debug, Default)]
pub struct Families {
    /// The contour families.
    pub conformal: Vec<Family>,
    /// The slender models.
    pub slender: Vec<SlenderFamily>,
}

/// The name and title checks every kind shares.
fn check_name_title(at: &std::path::Display<'_>, name: &str, title: &str) -> Result<(), String> {
    let ident = name.len() <= 32
        && name.starts_with(|c: char| c.is_ascii_lowercase())
        && name
            .chars()
            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_');
    if !ident {
        return Err(format!(
            "{at}: name = {:?} must be a lower-case identifier of at most 32 characters (a-z, 0-9, _; a letter first)",
            short(name)
        ));
    }
    let taken = RESERVED.contains(&name) || crate::ansatz::ALL.iter().any(|a| a.id == name);
    if taken {
        return Err(format!(
            "{at}: name = {:?} is taken (by an ellipse model, `exact` or a generated module)",
            name
        ));
    }
    if title.trim().is_empty() || title.len() > 200 || title.contains('\n') {
        return Err(format!(
            "{at}: title must be one line of 1 to 200 characters"
        ));
    }
    Ok(())
}

/// Parse and check one family file of any kind; `source` names it in
/// errors.
pub fn parse_any(text: &str, source: &Path) -> Result<AnyFamily, String> {
    let at = source.display();
    let table: toml::Table = toml::from_str(text).map_err(|e| format!("{at}: {}", e.message()))?;
    match table.get("kind").and_then(|k| k.as_str()) {
        Some("slender") => {
            let raw: RawSlender =
                toml::from_str(text).map_err(|e| format!("{at}: {}", e.message()))?;
            check_name_title(&at, &raw.name, &raw.title)?;
            crate::sym::try_ex(&raw.gap)
                .map(drop)
                .map_err(|why| format!("{at}: gap does not parse: {why}"))?;
            Ok(AnyFamily::Slender(SlenderFamily {
                name: raw.name,
                title: raw.title,
                gap: raw.gap,
                source: source.to_path_buf(),
            }))
        }
        _ => parse(text, source).map(AnyFamily::Conformal),
    }
}

/// Parse and check one contour family file's text; `source` names it in
/// errors.
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
    if raw.kind != "conformal" {
        return Err(format!(
            "{at}: kind = {:?} is not a contour family",
            short(&raw.kind)
        ));
    }
    check_name_title(&at, &raw.name, &raw.title)?;
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
    let why = &raw.rho_min_why;
    if why.chars().count() > MAX_WHY_CHARS || why.contains('\n') {
        return Err(format!(
            "{at}: rho_min_why must be one line of at most {MAX_WHY_CHARS} characters (it is part of an error message)"
        ));
    }
    if let Some(a) = raw.trace_start_a.filter(|a| !(*a > 0.0 && *a <= 100.0)) {
        return Err(format!("{at}: trace_start_a = {a} must lie in (0, 100]"));
    }
    let lines = &raw.doubtful_defects;
    if !lines.is_empty() && lines.len() != raw.powers.len() {
        return Err(format!(
            "{at}: doubtful_defects gives {} lines; it must give one per member ({}), or none",
            lines.len(),
            raw.powers.len()
        ));
    }
    if let Some((k, v)) = lines
        .iter()
        .enumerate()
        .find(|(_, v)| !(**v > 0.0 && **v <= 1.0))
    {
        return Err(format!(
            "{at}: doubtful_defects[{k}] = {v} must lie in (0, 1] (a boundary defect max |dp/dnu - 1|)"
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
        rho_min_why: raw.rho_min_why,
        trace_start_a: raw.trace_start_a,
        seeds_exact: raw.seeds_exact,
        doubtful_defects: raw.doubtful_defects,
        source: source.to_path_buf(),
    })
}

/// The longest `rho_min_why` a family file may give.
///
/// docs/accuracy.md gives it in a cell, four to a row of at most 400
/// characters.
const MAX_WHY_CHARS: usize = 72;

/// At most 40 characters of a value, for messages.
fn short(s: &str) -> String {
    match s.char_indices().nth(40) {
        Some((i, _)) => format!("{}…", &s[..i]),
        None => s.to_string(),
    }
}

/// Every contour family file under `root`'s [`FOLDER`] ([`read_kinds`]'s
/// contour families); there must be at least one.
pub fn read_all(root: &Path) -> Result<Vec<Family>, String> {
    let all = read_kinds(root)?;
    if all.conformal.is_empty() {
        return Err(format!(
            "{}: no contour family file (*.toml of kind conformal)",
            root.join(FOLDER).display()
        ));
    }
    Ok(all.conformal)
}

/// Every family file under `root`'s [`FOLDER`], sorted by file name, read
/// and checked; no two may share a name, and at most one per gap may seed
/// the exact solver.
pub fn read_kinds(root: &Path) -> Result<Families, String> {
    let dir = root.join(FOLDER);
    let entries = std::fs::read_dir(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let mut paths: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    paths.sort();
    let mut out: Vec<AnyFamily> = Vec::new();
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
        let f = parse_any(&text, &rel)?;
        if let Some(other) = out.iter().find(|o| o.name() == f.name()) {
            return Err(format!(
                "{}: name = {:?} is the name of {} too",
                rel.display(),
                f.name(),
                other.source().display()
            ));
        }
        if let AnyFamily::Conformal(f) = &f {
            if f.seeds_exact {
                let twin = out.iter().find_map(|o| match o {
                    AnyFamily::Conformal(o) if o.seeds_exact && same_gap(&o.gap, &f.gap) => Some(o),
                    _ => None,
                });
                if let Some(other) = twin {
                    return Err(format!(
                        "{}: seeds_exact: {} seeds the exact solver of the same gap already",
                        rel.display(),
                        other.source.display()
                    ));
                }
            }
        }
        out.push(f);
    }
    if out.is_empty() {
        return Err(format!("{}: no family file (*.toml)", dir.display()));
    }
    let mut families = Families::default();
    for f in out {
        match f {
            AnyFamily::Conformal(f) => families.conformal.push(f),
            AnyFamily::Slender(f) => families.slender.push(f),
        }
    }
    Ok(families)
}

/// Whether two gaps are the same expression (their difference expands to 0).
pub fn same_gap(a: &str, b: &str) -> bool {
    match (crate::sym::try_ex(a), crate::sym::try_ex(b)) {
        (Ok(x), Ok(y)) => crate::sym::is_zero(&(x - y)),
        _ => false,
    }
}
