//! Rules of the source tree a newcomer relies on: every file says what it holds, and neither the
//! top-level modules of the library nor the files of one folder form an import cycle.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

#[test]
fn every_source_file_opens_with_a_module_doc() {
    let mut files = Vec::new();
    rust_files(&src(), &mut files);
    let undocumented: Vec<_> = files
        .iter()
        .filter(|f| !std::fs::read_to_string(f).unwrap().starts_with("//!"))
        .collect();
    assert!(undocumented.is_empty(), "no module doc: {undocumented:#?}");
}

/// The top-level module a library file belongs to (`raster` for `src/raster/tile.rs` and for
/// `src/raster.rs`), or `None` for the crate roots and the binary's `commands`.
fn top_module(file: &Path) -> Option<String> {
    let relative = file.strip_prefix(src()).unwrap();
    let first = relative.components().next()?.as_os_str().to_str()?;
    let name = first.trim_end_matches(".rs");
    (!matches!(name, "lib" | "main" | "commands")).then(|| name.to_string())
}

/// `crate::NAME` paths outside the file's test module.
fn crate_paths(code: &str) -> BTreeSet<String> {
    let code = code.split("#[cfg(test)]").next().unwrap();
    code.match_indices("crate::")
        .map(|(at, _)| {
            code[at + 7..]
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                .collect()
        })
        .collect()
}

#[test]
fn top_level_modules_import_no_cycle() {
    let mut files = Vec::new();
    rust_files(&src(), &mut files);
    let mut uses: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for file in &files {
        if let Some(module) = top_module(file) {
            let used = crate_paths(&std::fs::read_to_string(file).unwrap());
            uses.entry(module).or_default().extend(used);
        }
    }
    let modules: BTreeSet<String> = uses.keys().cloned().collect();
    for module in &modules {
        uses.get_mut(module)
            .unwrap()
            .retain(|m| m != module && modules.contains(m));
    }
    // A module that reaches itself through the others is in a cycle.
    for start in &modules {
        let mut seen = BTreeSet::new();
        let mut frontier: Vec<&String> = uses[start].iter().collect();
        while let Some(module) = frontier.pop() {
            assert_ne!(module, start, "{start} imports itself through {seen:?}");
            if seen.insert(module.clone()) {
                frontier.extend(uses[module].iter());
            }
        }
    }
}

/// A file's module path: `["raster", "tile"]` for `src/raster/tile.rs`, `["raster"]` for
/// `src/raster/mod.rs`.
fn module_path(file: &Path) -> Vec<String> {
    let relative = file.strip_prefix(src()).unwrap().with_extension("");
    let mut parts: Vec<String> = relative
        .components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect();
    if parts.last().is_some_and(|p| p == "mod") {
        parts.pop();
    }
    parts
}

/// The modules a file's code outside its tests names through `super::` or `crate::`, each as
/// the longest path in `modules` the name starts with.
fn modules_named(
    file: &Path,
    module: &[String],
    modules: &BTreeSet<Vec<String>>,
) -> BTreeSet<Vec<String>> {
    let text = std::fs::read_to_string(file).unwrap();
    let code = text.split("#[cfg(test)]").next().unwrap();
    let mut named = BTreeSet::new();
    for (root, base) in [
        ("super::", &module[..module.len().saturating_sub(1)]),
        ("crate::", &[][..]),
    ] {
        for (at, _) in code.match_indices(root) {
            let before = code[..at].chars().next_back();
            if before.is_some_and(|c| c.is_ascii_alphanumeric() || c == '_' || c == ':') {
                continue;
            }
            let path: Vec<String> = code[at + root.len()..]
                .split(|c: char| !(c.is_ascii_alphanumeric() || c == '_' || c == ':'))
                .next()
                .unwrap()
                .split("::")
                .filter(|p| !p.is_empty())
                .map(str::to_string)
                .collect();
            let full: Vec<String> = base.iter().cloned().chain(path).collect();
            if let Some(k) = (1..=full.len())
                .rev()
                .find(|&k| modules.contains(&full[..k]))
            {
                named.insert(full[..k].to_vec());
            }
        }
    }
    named
}

#[test]
fn the_files_of_a_folder_import_no_cycle() {
    let mut files = Vec::new();
    rust_files(&src(), &mut files);
    let is_folder = |f: &PathBuf| f.file_name().is_some_and(|n| n == "mod.rs");
    let modules: BTreeSet<Vec<String>> = files.iter().map(|f| module_path(f)).collect();
    let mut uses: BTreeMap<Vec<String>, BTreeSet<Vec<String>>> = BTreeMap::new();
    for file in files.iter().filter(|f| !is_folder(f)) {
        let module = module_path(file);
        let parent = &module[..module.len() - 1];
        let siblings = modules_named(file, &module, &modules)
            .into_iter()
            .filter(|m| m.len() == module.len() && m[..m.len() - 1] == *parent && *m != module)
            .filter(|m| !files.iter().any(|f| is_folder(f) && module_path(f) == *m));
        uses.entry(module.clone()).or_default().extend(siblings);
    }
    for start in uses.keys() {
        let mut seen = BTreeSet::new();
        let mut frontier: Vec<&Vec<String>> = uses[start].iter().collect();
        while let Some(module) = frontier.pop() {
            assert_ne!(module, start, "{start:?} imports itself through {seen:?}");
            if seen.insert(module.clone()) {
                frontier.extend(uses.get(module).into_iter().flatten());
            }
        }
    }
}
