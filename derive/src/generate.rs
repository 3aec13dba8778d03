//! Everything the derivation writes into the repository, produced in memory
//! by one function so that the `generate` command and the freshness test
//! (rust-analyzer's `ensure_file_contents` pattern) share it.
//!
//! Owns: the list of generated files. May use: every other module.

use crate::model::{Derivation, ModelDerivation};
use crate::{ansatz, claims, report};
use std::path::{Path, PathBuf};

/// One generated file: path relative to the workspace root, and contents.
pub struct Output {
    /// Path relative to the workspace root.
    pub path: PathBuf,
    /// Full contents.
    pub contents: String,
}

/// Derive every model and every family of `derive/families/` in this
/// workspace, check the paper's claims, and render every file.
pub fn outputs() -> Result<Vec<Output>, String> {
    outputs_in(&workspace_root())
}

/// [`outputs`] for the workspace at `root`: its family files are read from
/// `root/derive/families/` (the built-in ellipse models are this crate's).
pub fn outputs_in(root: &Path) -> Result<Vec<Output>, String> {
    let paper = Derivation::new(&ansatz::PAPER)?;
    let models = ansatz::ALL
        .iter()
        .map(ModelDerivation::new)
        .collect::<Result<Vec<_>, _>>()?;
    let others: Vec<&ModelDerivation> = models
        .iter()
        .filter(|m| m.ansatz().id != ansatz::PAPER.id)
        .collect();
    let results = claims::check_all(&paper)?;
    // the same claims against every other closure of the ellipse
    let closures: Vec<report::ClosureCheck> = ansatz::ALL
        .iter()
        .filter(|a| a.id != ansatz::PAPER.id)
        .map(|a| report::ClosureCheck {
            name: a.id.to_string(),
            results: Derivation::new(a)
                .map_err(|e| format!("the claims are stated for a collocated ansatz; {e}"))
                .and_then(|d| claims::check_all(&d)),
        })
        .collect();
    let mut out = vec![
        Output {
            path: "docs/derivation.md".into(),
            contents: report::derivation_md(&paper, &others, &results),
        },
        Output {
            path: "docs/errata.md".into(),
            contents: report::errata_md(&results, &closures),
        },
    ];
    let all: Vec<&ModelDerivation> = models.iter().collect();
    // the family files are read (and their expressions parsed) after the
    // ellipse models are derived: symbolica orders terms by when their
    // symbols were first seen, and the generated code must not depend on
    // which families exist
    let kinds = crate::family::read_kinds(root)?;
    let families = kinds.conformal;
    if families.is_empty() {
        return Err(format!(
            "{}: no contour family file (*.toml of kind conformal)",
            root.join(crate::family::FOLDER).display()
        ));
    }
    let modules: Vec<&str> = families
        .iter()
        .map(|f| f.name.as_str())
        .chain(kinds.slender.iter().map(|f| f.name.as_str()))
        .chain([crate::slender::REGISTRY_MODULE, crate::layer::MODULE])
        .collect();
    out.extend(crate::codegen::outputs(&all, &modules)?);
    let mut exact_gap = Vec::new();
    let mut tables_digests = Vec::new();
    for f in &families {
        let members = crate::codegen_conformal::derive_family(f)?;
        let generated = crate::codegen_conformal::outputs(&members)?;
        let tables = generated
            .iter()
            .find(|o| o.path.ends_with("tables.json"))
            .ok_or_else(|| format!("{}: no tables.json was generated", f.name))?;
        tables_digests.push(crate::codegen_conformal::digest(tables.contents.as_bytes()));
        out[0]
            .contents
            .push_str(&crate::codegen_conformal::derivation_section(f, &members));
        if let Some(acc) = out
            .iter_mut()
            .find(|o| o.path.as_os_str() == "docs/codegen-accuracy.md")
        {
            acc.contents
                .push_str(&crate::codegen_conformal::accuracy_section(
                    &members, &generated,
                ));
        }
        out.extend(generated);
        exact_gap.push(crate::family::same_gap(&f.gap, crate::family::EXACT_GAP));
    }
    out.extend(crate::codegen_conformal::registry_outputs(
        &families,
        &exact_gap,
        &tables_digests,
    )?);
    // the slender models (issue 32, milestone (c)) and their registry
    out.push(Output {
        path: format!(
            "solver/src/generated/{}.rs",
            crate::slender::REGISTRY_MODULE
        )
        .into(),
        contents: crate::slender::registry_source(&kinds.slender)?,
    });
    for f in &kinds.slender {
        let derived = crate::slender::derive(f)?;
        out[0].contents.push_str(&derived.derivation_section());
        out.push(Output {
            path: format!("solver/src/generated/{}.rs", f.name).into(),
            contents: derived.module_source()?,
        });
    }
    // the layer of finite thickness: its kernel's Φ as Rust (issue 70)
    let (layer_source, layer_worst) = crate::layer::module_source()?;
    out.push(Output {
        path: format!("solver/src/generated/{}.rs", crate::layer::MODULE).into(),
        contents: layer_source,
    });
    if let Some(acc) = out
        .iter_mut()
        .find(|o| o.path.as_os_str() == "docs/codegen-accuracy.md")
    {
        acc.contents
            .push_str(&crate::layer::accuracy_section(layer_worst));
    }
    // no line of a document longer than 400 characters (issue 32)
    for o in out.iter_mut() {
        if o.path.extension().is_some_and(|e| e == "md") {
            o.contents = crate::markdown::tidy(&o.contents);
        }
    }
    Ok(out)
}

/// The workspace root (the parent of this crate's directory).
pub fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("derive/ has a parent")
        .to_path_buf()
}

/// The thinjkr checkout that holds `dir`: the nearest of `dir` and its
/// parents with `derive/families/`, `solver/` and a `Cargo.toml`; `None`
/// outside one.
pub fn repository_of(dir: &Path) -> Option<PathBuf> {
    dir.ancestors()
        .find(|d| {
            d.join("derive/families").is_dir()
                && d.join("solver").is_dir()
                && d.join("Cargo.toml").is_file()
        })
        .map(Path::to_path_buf)
}

/// Write every output under `root`; returns the paths that changed.
pub fn write_all(root: &Path, outputs: &[Output]) -> std::io::Result<Vec<PathBuf>> {
    let mut changed = Vec::new();
    for o in outputs {
        let p = root.join(&o.path);
        if std::fs::read_to_string(&p).ok().as_deref() != Some(o.contents.as_str()) {
            if let Some(dir) = p.parent() {
                std::fs::create_dir_all(dir)?;
            }
            std::fs::write(&p, &o.contents)?;
            changed.push(o.path.clone());
        }
    }
    Ok(changed)
}

/// The generated folder: every file in it is written by [`outputs`].
pub const GENERATED_DIR: &str = "solver/src/generated";

/// Files under `root`'s [`GENERATED_DIR`] that [`outputs`] no longer writes
/// (left by a family whose data file was removed or renamed), sorted.
pub fn stale_files(root: &Path, outputs: &[Output]) -> std::io::Result<Vec<PathBuf>> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) -> std::io::Result<()> {
        for e in std::fs::read_dir(dir)? {
            let p = e?.path();
            if p.is_dir() {
                walk(&p, out)?;
            } else {
                out.push(p);
            }
        }
        Ok(())
    }
    let mut found = Vec::new();
    walk(&root.join(GENERATED_DIR), &mut found)?;
    let mut stale: Vec<PathBuf> = found
        .into_iter()
        .filter_map(|p| p.strip_prefix(root).ok().map(Path::to_path_buf))
        .filter(|rel| !outputs.iter().any(|o| &o.path == rel))
        .collect();
    stale.sort();
    Ok(stale)
}

/// Remove the [`stale_files`] under `root`, and the folders they leave
/// empty; returns what was removed.
pub fn remove_stale(root: &Path, outputs: &[Output]) -> std::io::Result<Vec<PathBuf>> {
    let stale = stale_files(root, outputs)?;
    for rel in &stale {
        let p = root.join(rel);
        std::fs::remove_file(&p)?;
        if let Some(dir) = p.parent() {
            // a folder is removed only once empty
            let _ = std::fs::remove_dir(dir);
        }
    }
    Ok(stale)
}
