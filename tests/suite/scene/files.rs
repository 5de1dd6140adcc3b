//! The shipped example scene files load, and a preset printed as a file reads back the same.

use bumpwork::scene::{PRESET_NAMES, load_scene_file, parse_scene, preset_file};

#[test]
fn shipped_scene_files_load() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let mut loaded = 0;
    for entry in std::fs::read_dir(&dir).expect("scenes/ exists") {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "toml") {
            let scene = load_scene_file(&path).unwrap_or_else(|e| panic!("{e}"));
            assert!(!scene.objects.is_empty());
            loaded += 1;
        }
    }
    assert!(loaded > 0, "no scene files found in {}", dir.display());
}

#[test]
fn presets_print_as_files_that_read_back_identically() {
    for name in PRESET_NAMES {
        let text = preset_file(name).unwrap().to_toml();
        let again = parse_scene(&text, "p.toml").unwrap();
        assert_eq!(again, bumpwork::scene::preset(name).unwrap(), "{name}");
    }
}

#[test]
fn oversized_scene_files_are_refused_before_parsing() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let path = dir.path().join("huge.toml");
    std::fs::write(
        &path,
        vec![b'#'; (bumpwork::scene::MAX_SCENE_FILE_BYTES + 10) as usize],
    )
    .unwrap();
    let error = load_scene_file(&path).unwrap_err().to_string();
    assert!(error.contains("larger than the limit"), "{error}");
}
