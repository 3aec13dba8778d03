//! Every module of the solver opens with a charter, "Owns: … May use: …";
//! this test holds each charter to the module's code: every other module of
//! the crate the code names (`crate::x`, `super::x`) must be among those its
//! "May use:" names. The command line's modules (`cli/`) may name each other.
//! A new dependency is then a decision written down, not a drift. Above
//! the charters, the top-level modules are ranked ([`RANKS`]): a module
//! imports only modules ranked below it, and defines no inherent impl of
//! another module's type, so that no import hides.

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
    ("ModelId", "generated"),
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
/// messages in 300 characters, as the command line's are), then 219 for
/// `report`'s re-export of `SlenderState`, which `slender` owns since
/// issue 69 (the slender model no longer imports `report`, which kept it
/// in the import cycle; its public path is unchanged), then 223 for the
/// layer in the plane (issue 71: `PlaneState`, `PlaneRung` and `Held`,
/// which `AnyState::LayerPlane` holds, and `layer`'s re-export of them from
/// the crate-private grid solver), then 225 for the exact solver on a gap
/// named by the user (issue 73: `conformal::exact_pull_off_on_gap` and
/// `exact_state_on_gap`, which the command line's and Python's `--gap`
/// call; the re-export of the two is the third), then 226 for `layer::Method`
/// (issue 71: whether a state in the plane is the sharp edge's or the
/// grid's, which `PlaneState` now says), then 228 for `layer::Verdict`
/// and `layer::Verdicts` (issue 71: a layer state's stability on its
/// branch under each control, which its JSON, the command line and
/// Python's repr now share), then 230 for `report::LayerEstimate` and
/// `EstimateBy` (issue 71: `physical`'s best estimate of the layer's
/// pull-off as data, beside the warning that says it). The benches' hooks
/// (`bench_internals` and the module it re-exports, built only with the
/// `bench-internals` feature, hidden from the docs) are not a user's API and
/// are not counted.
#[test]
fn the_public_api_stays_small() {
    const MAX_PUBLIC_ITEMS: usize = 230;
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    sources(&root, &mut files);
    let kinds = [
        "fn ", "struct ", "enum ", "const ", "static ", "type ", "trait ", "mod ", "use ",
    ];
    let mut public = Vec::new();
    let hooks = [
        "bench_internals.rs",
        "layer/grid/bench.rs",
        "layer/sharp_bench.rs",
    ];
    for f in &files {
        if hooks.iter().any(|h| f.ends_with(h)) {
            continue;
        }
        let text = std::fs::read_to_string(f).unwrap();
        for (i, line) in text.lines().enumerate() {
            if line.contains("pub mod bench_internals") || line.contains("pub mod sharp_bench") {
                continue;
            }
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

/// The solver's top-level modules by rank, lowest first (issue 69): a
/// module may import (by `crate::` paths, `use` groups included, or an
/// item the crate's root re-exports) only modules of a lower rank. Test
/// code (`#[cfg(test)] mod tests`) is not held to it. `generated` is
/// ranked like any module.
const RANKS: &[&[&str]] = &[
    &["error", "model", "progress", "quadrature"],
    &["control", "cutoff", "fold", "newton"],
    &["continuation", "contour_modes"],
    &["equations", "exact"],
    &["ansatz"],
    &["generated"],
    &["contact", "layer", "slender"],
    &["bench_internals", "curve", "limits", "units"],
    &["conformal"],
    &["batch", "report"],
    &["accuracy", "registry"],
    &["studies"],
    &["figures"],
    &["cli"],
];

/// The modules that still import each other, all of one rank: none since
/// issue 69 broke the last cycle (the generator's types moved to `ansatz`,
/// below `generated`; `ModelId` is `generated`'s alone). A cycle that
/// comes back must be named here, with why, or the test fails.
const CYCLE: &[&str] = &[];

/// Inherent impls outside their type's own top-level module, each with
/// why it is there still: (file, type). The one left hides an import: the
/// exact solver calls `Gap::cylinders()`, defined in conformal/seed.rs
/// (the cylinders' gap with `conformal:8` as its seed), so `exact` reaches
/// `conformal` without a path naming it (issue 69).
const FOREIGN_IMPLS: &[(&str, &str)] = &[("conformal/seed.rs", "Gap")];

/// A source tree: (path under src/, text), every .rs file, generated/
/// included.
fn tree(root: &Path) -> Vec<(String, String)> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|x| x == "rs") {
                out.push(p);
            }
        }
    }
    let mut files = Vec::new();
    walk(root, &mut files);
    files.sort();
    files
        .iter()
        .map(|f| {
            let rel = f
                .strip_prefix(root)
                .unwrap()
                .to_string_lossy()
                .replace('\\', "/");
            (rel, std::fs::read_to_string(f).unwrap())
        })
        .collect()
}

/// The top-level module a file belongs to (`exact/resolve.rs` → `exact`);
/// `None` for the crate's root and the binary.
fn top_module(rel: &str) -> Option<String> {
    let first = rel.split('/').next().unwrap_or(rel);
    let name = first.strip_suffix(".rs").unwrap_or(first);
    (name != "lib" && name != "main").then(|| name.to_string())
}

/// A file's code without its comments and its test module.
fn code_of(text: &str) -> String {
    let before_tests = text.split("#[cfg(test)]\nmod tests").next().unwrap_or(text);
    before_tests
        .lines()
        .filter(|l| !l.trim_start().starts_with("//"))
        .collect::<Vec<_>>()
        .join("\n")
}

/// Which top-level modules each top-level module imports.
fn imports(files: &[(String, String)]) -> std::collections::BTreeMap<String, BTreeSet<String>> {
    let modules: BTreeSet<String> = files.iter().filter_map(|(r, _)| top_module(r)).collect();
    let mut out: std::collections::BTreeMap<String, BTreeSet<String>> = modules
        .iter()
        .map(|m| (m.clone(), BTreeSet::new()))
        .collect();
    for (rel, text) in files {
        let Some(m) = top_module(rel) else { continue };
        for name in segments(&code_of(text), "crate::") {
            let t = module_of(&name);
            if t != m && modules.contains(&t) {
                out.get_mut(&m).unwrap().insert(t);
            }
        }
    }
    out
}

/// Every import that breaks `ranks` (upward, or sideways outside
/// `cycle`), every module `ranks` misses, and every module of `cycle` no
/// longer in a cycle, in words.
fn rank_violations(files: &[(String, String)], ranks: &[&[&str]], cycle: &[&str]) -> Vec<String> {
    let graph = imports(files);
    let rank = |m: &str| ranks.iter().position(|r| r.contains(&m));
    let mut out = Vec::new();
    for (m, used) in &graph {
        let Some(rm) = rank(m) else {
            out.push(format!("{m} has no rank"));
            continue;
        };
        for t in used {
            match rank(t) {
                Some(rt) if rt < rm => {}
                Some(rt)
                    if rt == rm && cycle.contains(&m.as_str()) && cycle.contains(&t.as_str()) => {}
                Some(rt) if rt == rm => out.push(format!("{m} imports {t}, of its own rank")),
                Some(_) => out.push(format!("{m} imports {t}, ranked above it")),
                None => {}
            }
        }
    }
    for r in ranks.iter().flat_map(|r| r.iter()) {
        if !graph.contains_key(*r) {
            out.push(format!("{r} is ranked but no module"));
        }
    }
    // every module of the cycle still reaches another and is reached back
    let reaches = |from: &str| {
        let mut seen = BTreeSet::new();
        let mut todo = vec![from.to_string()];
        while let Some(m) = todo.pop() {
            for t in graph.get(&m).into_iter().flatten() {
                if seen.insert(t.clone()) {
                    todo.push(t.clone());
                }
            }
        }
        seen
    };
    for m in cycle {
        if !reaches(m).contains(*m) {
            out.push(format!("{m} is in no cycle now: take it off CYCLE"));
        }
    }
    out
}

/// The inherent impls (`impl Name {`, no trait) whose type is defined in
/// another top-level module: (file, type).
fn foreign_impls(files: &[(String, String)]) -> Vec<(String, String)> {
    let name_after = |s: &str| -> String {
        s.chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect()
    };
    let mut defined: std::collections::BTreeMap<String, BTreeSet<String>> = Default::default();
    let mut impls = Vec::new();
    for (rel, text) in files {
        let Some(m) = top_module(rel) else { continue };
        for line in code_of(text).lines() {
            let l = line.trim_start();
            let l = l
                .strip_prefix("pub(crate) ")
                .or_else(|| l.strip_prefix("pub "))
                .unwrap_or(l);
            for kind in ["struct ", "enum ", "trait ", "type "] {
                if let Some(rest) = l.strip_prefix(kind) {
                    defined
                        .entry(name_after(rest))
                        .or_default()
                        .insert(m.clone());
                }
            }
            if let Some(rest) = l.strip_prefix("impl") {
                if rest.contains(" for ") || !rest.trim_end().ends_with('{') {
                    continue;
                }
                // skip the generics of `impl<…>`
                let rest = match rest.strip_prefix('<') {
                    Some(g) => g.split_once("> ").map_or("", |(_, t)| t),
                    None => rest.trim_start(),
                };
                let path = rest.split(['<', ' ', '{']).next().unwrap_or("");
                let name = path.rsplit("::").next().unwrap_or(path);
                if !name.is_empty() {
                    impls.push((rel.clone(), m.clone(), name.to_string()));
                }
            }
        }
    }
    impls
        .into_iter()
        .filter(|(_, m, name)| {
            defined
                .get(name)
                .is_some_and(|at| at.len() == 1 && !at.contains(m))
        })
        .map(|(rel, _, name)| (rel, name))
        .collect()
}

#[test]
fn the_modules_import_downward_only() {
    let files = tree(&Path::new(env!("CARGO_MANIFEST_DIR")).join("src"));
    assert!(
        files.iter().any(|(r, _)| r.starts_with("generated/")),
        "generated/ is read"
    );
    let broken = rank_violations(&files, RANKS, CYCLE);
    assert!(
        broken.is_empty(),
        "imports out of rank:\n{}",
        broken.join("\n")
    );
    let foreign: Vec<(String, String)> = foreign_impls(&files);
    let known: Vec<(String, String)> = FOREIGN_IMPLS
        .iter()
        .map(|(f, t)| (f.to_string(), t.to_string()))
        .collect();
    assert_eq!(
        foreign, known,
        "inherent impls outside their type's module (each hides an import); a new one is refused, one gone leaves FOREIGN_IMPLS"
    );
}

/// The ranking's own check on a tree made for it: an upward import, a
/// sideways one, a module without a rank, a cycle member no longer in a
/// cycle and an inherent impl in another module are each found.
#[test]
fn the_ranking_finds_what_breaks_it() {
    let file = |rel: &str, text: &str| (rel.to_string(), text.to_string());
    let files = vec![
        file("lib.rs", "pub mod low; pub mod high;"),
        file(
            "low.rs",
            "//! Owns: X.\nuse crate::high::Y;\npub struct X;\n",
        ),
        file(
            "high.rs",
            "use crate::low::X;\npub struct Y;\nimpl X {\n    fn f() {}\n}\n",
        ),
        file("side.rs", "use crate::{high::Y};\n"),
        file(
            "more/mod.rs",
            "pub(crate) fn g() -> crate::Result<()> { Ok(()) }\n",
        ),
        // test code may import anything
        file(
            "error.rs",
            "pub struct E;\n#[cfg(test)]\nmod tests {\n    use crate::high::Y;\n}\n",
        ),
    ];
    let broken = rank_violations(
        &files,
        &[&["error"], &["low", "more"], &["high", "side"]],
        &["more"],
    );
    assert!(
        broken.contains(&"low imports high, ranked above it".to_string()),
        "{broken:?}"
    );
    assert!(
        broken.contains(&"side imports high, of its own rank".to_string()),
        "{broken:?}"
    );
    assert!(
        broken.contains(&"more is in no cycle now: take it off CYCLE".to_string()),
        "{broken:?}"
    );
    assert!(
        !broken.iter().any(|b| b.starts_with("error ")),
        "{broken:?}"
    );
    assert!(!broken.iter().any(|b| b.starts_with("high ")), "{broken:?}");
    assert_eq!(broken.len(), 3, "{broken:?}");
    let unranked = rank_violations(&files, &[&["error", "low", "high", "more"]], &[]);
    assert!(
        unranked.contains(&"side has no rank".to_string()),
        "{unranked:?}"
    );
    assert_eq!(
        foreign_impls(&files),
        vec![("high.rs".to_string(), "X".to_string())]
    );
}

/// The longest a hand-written function may be (issue 69), in lines from its
/// `fn` to its closing brace: a longer one is split into steps that say
/// what they do.
const LONGEST_FUNCTION: usize = 120;

/// The hand-written functions of `text` (the file's test module and its
/// test-only files left out by the caller) longer than `longest` lines:
/// (first line, name, lines). A function's body ends at the first line
/// that is its indentation and `}` (as rustfmt writes it).
fn long_functions(text: &str, longest: usize) -> Vec<(usize, String, usize)> {
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        let trimmed = line.trim_start();
        let mut rest = trimmed;
        for prefix in [
            "pub(crate) ",
            "pub(super) ",
            "pub ",
            "const ",
            "async ",
            "unsafe ",
        ] {
            rest = rest.strip_prefix(prefix).unwrap_or(rest);
        }
        let Some(signature) = rest.strip_prefix("fn ") else {
            continue;
        };
        let name: String = signature
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        let indent = &line[..line.len() - trimmed.len()];
        // the body's opening line, or none for a declaration (`;`)
        let Some(open) = (i..lines.len()).find(|&j| {
            let l = lines[j].trim_end();
            l.ends_with('{') || l.ends_with(';') || (j == i && l.ends_with('}'))
        }) else {
            continue;
        };
        if lines[open].trim_end().ends_with(';') || lines[open].trim_end().ends_with('}') {
            continue;
        }
        let close = format!("{indent}}}");
        let Some(end) = (open + 1..lines.len()).find(|&k| lines[k].trim_end() == close) else {
            continue;
        };
        if end - i + 1 > longest {
            out.push((i + 1, name, end - i + 1));
        }
    }
    out
}

/// The files of `files` (paths under src/) that a `#[cfg(test)] mod x;`
/// (or `pub(crate) mod x;`) declares: test-only files.
fn test_only_files(files: &[(String, String)]) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for (rel, text) in files {
        let lines: Vec<&str> = text.lines().collect();
        for pair in lines.windows(2) {
            let declared = pair[1].trim();
            let declared = declared.strip_prefix("pub(crate) ").unwrap_or(declared);
            let Some(name) = declared
                .strip_prefix("mod ")
                .and_then(|m| m.strip_suffix(';'))
            else {
                continue;
            };
            if pair[0].trim() != "#[cfg(test)]" {
                continue;
            }
            let dir = match rel.rsplit_once('/') {
                Some((d, f)) if f == "mod.rs" || f == "lib.rs" || f == "main.rs" => format!("{d}/"),
                Some((d, f)) => format!("{d}/{}/", f.trim_end_matches(".rs")),
                None if rel == "lib.rs" || rel == "main.rs" => String::new(),
                None => format!("{}/", rel.trim_end_matches(".rs")),
            };
            out.insert(format!("{dir}{name}.rs"));
            out.insert(format!("{dir}{name}/mod.rs"));
        }
    }
    out
}

#[test]
fn no_hand_written_function_is_over_120_lines() {
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut long = Vec::new();
    for (crate_dir, root) in [
        ("solver", manifest.join("src")),
        ("derive", manifest.join("../derive/src")),
    ] {
        let files: Vec<(String, String)> = tree(&root)
            .into_iter()
            .filter(|(rel, _)| !rel.starts_with("generated/"))
            .collect();
        let test_only = test_only_files(&files);
        for (rel, text) in &files {
            if test_only.contains(rel) {
                continue;
            }
            let before_tests = text.split("\n#[cfg(test)]\nmod ").next().unwrap_or(text);
            for (line, name, lines) in long_functions(before_tests, LONGEST_FUNCTION) {
                long.push(format!(
                    "{crate_dir}/src/{rel}:{line} {name}: {lines} lines"
                ));
            }
        }
    }
    assert!(
        long.is_empty(),
        "hand-written functions over {LONGEST_FUNCTION} lines (split them into named steps):\n  {}",
        long.join("\n  ")
    );
}

#[test]
fn the_length_check_finds_a_long_function_and_passes_a_short_one() {
    let body = |n: usize| {
        (0..n)
            .map(|k| format!("    let x{k} = {k};\n"))
            .collect::<String>()
    };
    let text = format!(
        "pub(crate) fn long(\n    a: u8,\n) -> u8 {{\n{}    a\n}}\n\nfn short() {{\n{}}}\n\ntrait T {{\n    fn declared(&self);\n}}\n",
        body(130),
        body(10)
    );
    let found = long_functions(&text, LONGEST_FUNCTION);
    assert_eq!(found, vec![(1, "long".to_string(), 135)]);
    let files = vec![(
        "layer/grid/mod.rs".to_string(),
        "#[cfg(test)]\nmod tables;\nmod plane;\n".to_string(),
    )];
    let test_only = test_only_files(&files);
    assert!(test_only.contains("layer/grid/tables.rs"));
    assert!(!test_only.contains("layer/grid/plane.rs"));
}
