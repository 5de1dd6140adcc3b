//! Every input the fuzzers kept (their minimised corpora in `fuzz/corpus/TARGET`) and every crash
//! they found (`fuzz/regressions/TARGET`) goes through the fuzz targets' own entry points, which
//! assert no panic, a printable error or finite output. The fuzzing itself: `fuzz/run TARGET
//! SECONDS` (see RELIABILITY.md).

use crate::fuzz_entry as entry;

use std::path::{Path, PathBuf};

fn inputs(target: &str) -> Vec<PathBuf> {
    let fuzz = Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz");
    let mut files: Vec<PathBuf> = ["corpus", "regressions"]
        .iter()
        .filter_map(|kind| std::fs::read_dir(fuzz.join(kind).join(target)).ok())
        .flatten()
        .map(|entry| entry.unwrap().path())
        .collect();
    files.sort();
    files
}

/// Runs `entry` on every kept input of `target`, naming the file that fails.
fn replay(target: &str, entry: fn(&[u8])) {
    let files = inputs(target);
    assert!(!files.is_empty(), "no inputs kept for {target}");
    for file in files {
        let data = std::fs::read(&file).unwrap();
        let outcome = std::panic::catch_unwind(|| entry(&data));
        assert!(outcome.is_ok(), "{} fails", file.display());
    }
}

#[test]
fn pattern_inputs() {
    replay("pattern", entry::pattern);
}

#[test]
fn scene_inputs() {
    replay("scene", entry::scene);
}

#[test]
fn image_inputs() {
    replay("image", entry::image);
}

#[test]
fn obj_inputs() {
    replay("obj", entry::obj);
}

#[test]
fn gltf_inputs() {
    replay("gltf", entry::gltf);
}

#[test]
fn png_metadata_inputs() {
    replay("png_metadata", entry::png_metadata);
}

/// The properties the entry points check can fail: a message with a raw escape is caught.
#[test]
#[should_panic(expected = "raw control character")]
fn a_raw_escape_in_a_message_is_caught() {
    entry::assert_printable("bad \x1b]0;title\x07 file");
}
