//! Rules of the source tree a newcomer relies on: every file says what it holds, and the
//! top-level modules of the library form no import cycle.

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
