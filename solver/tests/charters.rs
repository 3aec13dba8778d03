//! Every module of the solver opens with a charter, "Owns: … May use: …";
//! this test holds each charter to the module's code: every other module of
//! the crate the code names (`crate::x`, `super::x`) must be among those its
//! "May use:" names. The command line's modules (`cli/`) may name each other.
//! A new dependency is then a decision written down, not a drift.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

/// Names at the crate's root that stand for a module's item.
const ROOT_ITEMS: &[(&str, &str)] = &[
    ("Contact", "contact"),
    ("FoldBasis", "contact"),
    ("PullOff", "contact"),
    ("Search", "contact"),
    ("Stability", "contact"),
    ("State", "contact"),
    ("Error", "error"),
    ("Result", "error"),
    ("Model", "model"),
    ("ModelId", "model"),
];

fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            if !p.ends_with("generated") {
                sources(&p, out);
            }
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// The first segments of the paths after `prefix` in `code`, braces of a
/// `use` group included (`crate::{a, b::c}` gives a and b).
fn segments(code: &str, prefix: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    let mut rest = code;
    while let Some(i) = rest.find(prefix) {
        let before = rest[..i].chars().last();
        rest = &rest[i + prefix.len()..];
        if before.is_some_and(|c| c.is_alphanumeric() || c == '_') {
            continue;
        }
        if let Some(group) = rest.strip_prefix('{') {
            let end = group.find('}').unwrap_or(group.len());
            for item in group[..end].split(',') {
                let name: String = item
                    .trim()
                    .chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect();
                if !name.is_empty() {
                    out.insert(name);
                }
            }
        } else {
            let name: String = rest
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            if !name.is_empty() {
                out.insert(name);
            }
        }
    }
    out
}

fn module_of(name: &str) -> String {
    ROOT_ITEMS
        .iter()
        .find(|(item, _)| *item == name)
        .map(|(_, m)| m.to_string())
        .unwrap_or_else(|| name.to_string())
}

#[test]
fn every_module_uses_only_what_its_charter_names() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    sources(&root, &mut files);
    files.sort();
    let mut broken = BTreeSet::new();
    let mut checked = 0;
    for f in &files {
        let rel = f.strip_prefix(&root).unwrap();
        let parts: Vec<String> = rel
            .with_extension("")
            .iter()
            .map(|s| s.to_string_lossy().into_owned())
            .collect();
        let name = parts[0].clone();
        if name == "lib" || name == "main" {
            continue;
        }
        let text = std::fs::read_to_string(f).unwrap();
        let doc: String = text
            .lines()
            .filter_map(|l| l.strip_prefix("//!"))
            .collect::<Vec<_>>()
            .join(" ");
        let Some((_, charter)) = doc.split_once("May use:") else {
            broken.insert(format!(
                "{}: no \"May use:\" in its opening doc",
                rel.display()
            ));
            continue;
        };
        let mut allowed: BTreeSet<String> = BTreeSet::new();
        for (k, quoted) in charter.split('`').enumerate() {
            if k % 2 == 1 {
                let path = quoted
                    .trim_start_matches("thinjkr::")
                    .trim_start_matches("crate::");
                let first = path.split("::").next().unwrap_or("");
                allowed.insert(module_of(first));
            }
        }
        let parent_named = charter.contains("parent");
        let code: String = text
            .lines()
            .filter(|l| !l.trim_start().starts_with("//"))
            .collect::<Vec<_>>()
            .join("\n");
        // a submodule (a file beside its parent's mod.rs)
        let is_sub = parts.len() == 2 && parts[1] != "mod";
        // a path to the module itself through its parent is the module
        let code = if is_sub {
            code.replace(&format!("crate::{name}::{}::", parts[1]), "self::")
        } else {
            code
        };
        let mut used = segments(&code, "crate::");
        // a submodule may name its parent's items through `super::` (in
        // its code before the tests, whose `super::` is the file's module)
        let before_tests = code.split("#[cfg(test)]").next().unwrap_or("");
        if is_sub && !segments(before_tests, "super::").is_empty() && !parent_named {
            used.insert(name.clone());
        }
        let own = if is_sub { &parts[1] } else { &name };
        for u in used {
            let m = module_of(&u);
            // a module may use itself; a submodule its parent only where
            // its charter names the parent
            let fine =
                (m == name && (!is_sub || parent_named)) || &m == own || allowed.contains(&m);
            if !fine {
                broken.insert(format!(
                    "{}: uses `{m}`, which its charter does not name (May use: {})",
                    rel.display(),
                    allowed.iter().cloned().collect::<Vec<_>>().join(", ")
                ));
            }
        }
        checked += 1;
    }
    assert!(
        checked >= 25,
        "the charters of {checked} modules were checked"
    );
    let broken: Vec<String> = broken.into_iter().collect();
    assert!(
        broken.is_empty(),
        "charters out of date:\n{}",
        broken.join("\n")
    );
}

/// The public API is what a library user needs (issue 34): at most 200
/// hand-written public items (the lines `pub fn|struct|enum|const|static|
/// type|trait|mod|use` of solver/src, generated code aside; an item of a
/// crate-private module is written `pub(crate)` so that the count is what
/// is reachable). A new public item is then a decision, not a default:
/// 200 until issue 70's layer of finite thickness added eleven (`layer`,
/// `Coating`, `Layers`, `Route`, `LayerState`, `LayerPullOff`, `new`,
/// `equal`, `state`, `pull_off`, and `report::ThinLayer`, (2)'s answer
/// beside the layer's in `physical`), then 217 for the crate root's way in
/// (issue 69): `solve`, `pull_off` and the four types they take and give,
/// re-exported there (`Hold`, `FoldCondition`, `AnyState`, `PullOffAnswer`),
/// then 218 for `Error::brief_ending` (issue 72: the Python package's
/// messages in 300 characters, as the command line's are).
#[test]
fn the_public_api_stays_small() {
    const MAX_PUBLIC_ITEMS: usize = 218;
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    sources(&root, &mut files);
    let kinds = [
        "fn ", "struct ", "enum ", "const ", "static ", "type ", "trait ", "mod ", "use ",
    ];
    let mut public = Vec::new();
    for f in &files {
        let text = std::fs::read_to_string(f).unwrap();
        for (i, line) in text.lines().enumerate() {
            if let Some(rest) = line.trim_start().strip_prefix("pub ") {
                if kinds.iter().any(|k| rest.starts_with(k)) {
                    public.push(format!("{}:{}", f.display(), i + 1));
                }
            }
        }
    }
    assert!(
        public.len() > 100,
        "only {} public items found: the count does not see the sources",
        public.len()
    );
    assert!(
        public.len() <= MAX_PUBLIC_ITEMS,
        "{} public items (at most {MAX_PUBLIC_ITEMS}); make internals pub(crate)",
        public.len()
    );
}
