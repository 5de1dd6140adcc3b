//! Nothing lost: pattern and scene files are never written by bumpwork. Every file it writes goes
//! through `export::OutputFile` (whole or absent: see `export_stills` for interrupted, failed and
//! concurrent exports), the workbench's exports take new names, and a still never replaces a
//! pattern or scene file.

use crate::cli_support::{assert_user_error, bumpwork, temp_dir};
use std::path::Path;

/// The calls that create or change files. Only `src/export/output_file.rs` may make them (and
/// `src/unfinished_files.rs` may remove the temporary files it registers); tests (the
/// `#[cfg(test)]` module that ends a file) may do as they like.
const WRITES: &[&str] = &[
    "fs::write",
    "File::create",
    "OpenOptions",
    "fs::rename",
    "fs::copy",
    "remove_file",
    "set_len",
    ".persist(",
];

fn sources(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            sources(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// Whether `code` calls `call` itself (`File::create`, not `OutputFile::create`).
fn calls(code: &str, call: &str) -> bool {
    code.match_indices(call).any(|(at, _)| {
        !code[..at]
            .chars()
            .next_back()
            .is_some_and(|c| c.is_alphanumeric() || c == '_')
    })
}

#[test]
fn only_the_atomic_file_writes_files() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    sources(&src, &mut files);
    assert!(files.len() > 50, "found the sources");
    let mut writers = Vec::new();
    for file in &files {
        let text = std::fs::read_to_string(file).unwrap();
        let code = text.split("#[cfg(test)]").next().unwrap();
        for call in WRITES {
            let reads_only = file.ends_with("bounded_read.rs")
                && *call == "OpenOptions"
                && !code.contains(".write(");
            let removes_unfinished =
                file.ends_with("unfinished_files.rs") && *call == "remove_file";
            let allowed =
                file.ends_with("export/output_file.rs") || reads_only || removes_unfinished;
            if calls(code, call) && !allowed {
                writers.push(format!("{}: {call}", file.display()));
            }
        }
    }
    assert!(
        writers.is_empty(),
        "files written outside OutputFile: {writers:#?}"
    );
    let atomic = std::fs::read_to_string(src.join("export/output_file.rs")).unwrap();
    assert!(
        atomic.contains(".persist("),
        "the atomic file still commits by rename"
    );
}

#[test]
fn a_still_never_replaces_a_pattern_or_scene_file() {
    let dir = temp_dir("nothing-lost");
    for name in ["work.pat", "work.toml", "WORK.TOML"] {
        let path = dir.join(name);
        std::fs::write(&path, "precious\n").unwrap();
        let output = bumpwork(&[
            "render",
            "plane-dimples",
            "-o",
            path.to_str().unwrap(),
            "--size",
            "4x4",
        ]);
        assert_user_error(&output, "never overwritten");
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "precious\n");
    }
}

/// A crash mid-export (SIGKILL: no handler runs) never leaves a partial file under the
/// destination's name; what it can leave is the hidden temporary file it was writing.
#[test]
fn a_killed_export_leaves_no_partial_file_at_the_destination() {
    let dir = temp_dir("nothing-lost-kill");
    let out = dir.join("big.png");
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_bumpwork"))
        .args(["render", "sphere-on-plane-dimples", "-o"])
        .arg(&out)
        .args(["--size", "4000x3000", "--samples", "64"])
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let names = || -> Vec<String> {
        std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect()
    };
    // Generous: the temporary file appears as soon as the render starts.
    let started = std::time::Instant::now();
    while names().is_empty() && started.elapsed() < std::time::Duration::from_secs(60) {
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    let left = names();
    assert!(!out.exists(), "a partial still under its own name");
    assert!(
        left.iter()
            .all(|n| n.starts_with(".big.png.") && n.ends_with(".tmp")),
        "{left:?}"
    );
}
