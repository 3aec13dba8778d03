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

/// Derive every model, check the paper's claims, and render every file.
pub fn outputs() -> Result<Vec<Output>, String> {
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
    out.extend(crate::codegen::outputs(&all)?);
    let family = crate::codegen_conformal::derive_all()?;
    let generated = crate::codegen_conformal::outputs(&family)?;
    out[0]
        .contents
        .push_str(&crate::codegen_conformal::derivation_section(&family));
    if let Some(acc) = out
        .iter_mut()
        .find(|o| o.path.as_os_str() == "docs/codegen-accuracy.md")
    {
        acc.contents
            .push_str(&crate::codegen_conformal::accuracy_section(
                &family, &generated,
            ));
    }
    out.extend(generated);
    Ok(out)
}

/// The workspace root (the parent of this crate's directory).
pub fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("derive/ has a parent")
        .to_path_buf()
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
