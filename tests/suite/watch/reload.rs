//! Hot reload in-process: a scene in a temporary directory, edited the ways editors save, with
//! broken saves in between; after each step the loaded scene is the expected one.

use crate::watch::support::*;
use bumpwork::scene::parse_scene;
use bumpwork::watch::{FileSetSource, Reloader, SceneFileSource};
use std::fs;
use std::io::Write;

fn start_with_pattern(dir: &TempDir) -> (Reloader, Shown) {
    fs::write(dir.join("ridges.pat"), pattern_source(1)).unwrap();
    fs::write(
        dir.join("scene.toml"),
        scene_toml("pattern = \"ridges.pat\""),
    )
    .unwrap();
    let (reloader, first) = Reloader::start(SceneFileSource::new(dir.join("scene.toml"))).unwrap();
    let shown = Shown::new(first);
    assert_eq!(shown.k(), Some(1.0));
    (reloader, shown)
}

#[test]
fn every_way_of_saving_is_seen_and_a_broken_save_keeps_the_last_good_scene() {
    let dir = TempDir::new("saves");
    let (reloader, mut shown) = start_with_pattern(&dir);
    let pattern = dir.join("ridges.pat");

    fs::write(&pattern, pattern_source(2)).unwrap();
    shown.wait_for_k(&reloader, 2);

    let temporary = dir.join(".ridges.pat.tmp");
    fs::write(&temporary, pattern_source(3)).unwrap();
    fs::rename(&temporary, &pattern).unwrap();
    shown.wait_for_k(&reloader, 3);

    let mut file = fs::File::create(&pattern).unwrap();
    file.flush().unwrap();
    file.write_all(pattern_source(4).as_bytes()).unwrap();
    drop(file);
    shown.wait_for_k(&reloader, 4);

    fs::remove_file(&pattern).unwrap();
    shown.wait_for_error(&reloader, "cannot read", 4);
    fs::write(&pattern, pattern_source(5)).unwrap();
    shown.wait_for_k(&reloader, 5);

    fs::write(&pattern, BROKEN_PATTERN).unwrap();
    shown.wait_for_error(&reloader, "ridges.pat:4:1", 5);
    fs::write(&pattern, [0xff, 0xfe, 0x00, 0x13, 0x37]).unwrap();
    shown.wait_for_error(&reloader, "ridges.pat:1:1", 5);
    fs::write(&pattern, pattern_source(6)).unwrap();
    shown.wait_for_k(&reloader, 6);

    // vim with `nobackupcopy`: the old file is renamed to a backup and a new one written.
    fs::rename(&pattern, dir.join("ridges.pat~")).unwrap();
    fs::write(&pattern, pattern_source(7)).unwrap();
    shown.wait_for_k(&reloader, 7);
}

#[test]
fn a_save_of_the_same_bytes_does_not_reload() {
    let dir = TempDir::new("same-bytes");
    let (reloader, mut shown) = start_with_pattern(&dir);
    fs::write(dir.join("ridges.pat"), pattern_source(1)).unwrap();
    shown.wait_until(&reloader, "an unchanged outcome", |s| s.unchanged > 0);
    assert_eq!(shown.reloads, 0);
    fs::write(dir.join("unrelated.txt"), "x").unwrap();
    fs::write(dir.join("ridges.pat"), pattern_source(2)).unwrap();
    shown.wait_for_k(&reloader, 2);
    assert_eq!(shown.reloads, 1);
}

#[test]
fn a_scene_edit_that_names_a_new_pattern_file_gets_it_watched() {
    let dir = TempDir::new("new-dependency");
    let (reloader, mut shown) = start_with_pattern(&dir);
    fs::create_dir(dir.join("more")).unwrap();
    fs::write(dir.join("more/waves.pat"), pattern_source(10)).unwrap();
    let scene = scene_toml("pattern = \"more/waves.pat\"");
    fs::write(dir.join("scene.toml"), scene).unwrap();
    shown.wait_for_k(&reloader, 10);
    fs::write(dir.join("more/waves.pat"), pattern_source(11)).unwrap();
    shown.wait_for_k(&reloader, 11);
}

#[test]
fn a_broken_scene_file_reports_its_line_and_column_and_the_next_good_save_recovers() {
    let dir = TempDir::new("scene-file");
    let (reloader, mut shown) = start_with_pattern(&dir);
    let good = scene_toml("pattern = \"ridges.pat\"");
    let broken = good.replace("radius = 100", "radius = -1");
    fs::write(dir.join("scene.toml"), &broken).unwrap();
    shown.wait_for_error(&reloader, "scene.toml:9:55", 1);
    fs::write(dir.join("ridges.pat"), pattern_source(2)).unwrap();
    fs::write(dir.join("scene.toml"), &good).unwrap();
    shown.wait_for_k(&reloader, 2);
}

#[test]
fn a_first_load_that_fails_is_reported_and_a_good_save_recovers() {
    let dir = TempDir::new("first-fails");
    fs::write(dir.join("ridges.pat"), BROKEN_PATTERN).unwrap();
    fs::write(
        dir.join("scene.toml"),
        scene_toml("pattern = \"ridges.pat\""),
    )
    .unwrap();
    let (reloader, first) = Reloader::start(SceneFileSource::new(dir.join("scene.toml"))).unwrap();
    let mut shown = Shown::new(first);
    assert!(
        shown.error_line().contains("ridges.pat:4:1"),
        "{}",
        shown.error_line()
    );
    fs::write(dir.join("ridges.pat"), pattern_source(3)).unwrap();
    shown.wait_for_k(&reloader, 3);
}

#[test]
fn a_broken_image_keeps_the_last_good_scene() {
    let dir = TempDir::new("image");
    let image = dir.join("bumps.pgm");
    fs::write(&image, "P2\n2 2\n255\n0 255\n255 0\n").unwrap();
    fs::write(dir.join("scene.toml"), scene_toml("image = \"bumps.pgm\"")).unwrap();
    let (reloader, first) = Reloader::start(SceneFileSource::new(dir.join("scene.toml"))).unwrap();
    let mut shown = Shown::new(first);
    assert!(shown.scene.is_some(), "{}", shown.error_line());
    fs::write(&image, "P2\n2 2\n255\n0 2").unwrap();
    shown.wait_until(&reloader, "the image error", |s| {
        s.error_line().contains("bumps.pgm")
    });
    assert!(shown.scene.is_some());
    fs::write(&image, "P2\n3 1\n255\n0 128 255\n").unwrap();
    shown.wait_until(&reloader, "the good image", |s| {
        s.error.is_none() && s.reloads == 1
    });
}

#[test]
fn a_live_parameter_value_survives_a_reload_of_its_pattern() {
    let dir = TempDir::new("live-params");
    let pattern = dir.join("ridges.pat");
    fs::write(
        &pattern,
        "param k = 1 in 0..100\nparam gone = 1 in 0..9\nheight = k * gone * u\n",
    )
    .unwrap();
    fs::write(
        dir.join("scene.toml"),
        scene_toml("pattern = \"ridges.pat\""),
    )
    .unwrap();
    let (reloader, first) = Reloader::start(SceneFileSource::new(dir.join("scene.toml"))).unwrap();
    let mut shown = Shown::new(first);
    set_bump_params(&mut shown, &[42.0, 5.0]);
    fs::write(
        &pattern,
        "param new = 3 in 0..9\nparam k = 2 in 0..100\nheight = k * new * u\n",
    )
    .unwrap();
    shown.wait_until(&reloader, "the new pattern", |s| s.reloads == 1);
    assert_eq!(bump_params(&shown), vec![3.0, 42.0]);
}

fn bump_binding(shown: &mut Shown) -> &mut bumpwork::scene::PatternBinding {
    let bump = shown.scene.as_mut().unwrap().objects[0]
        .material
        .bump
        .as_mut()
        .unwrap();
    match &mut bump.source {
        bumpwork::scene::BumpSource::Pattern(binding) => binding,
        _ => panic!("a pattern bump"),
    }
}

fn set_bump_params(shown: &mut Shown, values: &[f32]) {
    bump_binding(shown).params = values.to_vec();
}

fn bump_params(shown: &Shown) -> Vec<f32> {
    let bump = shown.scene.as_ref().unwrap().objects[0]
        .material
        .bump
        .as_ref()
        .unwrap();
    match &bump.source {
        bumpwork::scene::BumpSource::Pattern(binding) => binding.params.clone(),
        _ => panic!("a pattern bump"),
    }
}

#[test]
fn a_reload_does_not_schedule_another_by_reading_the_files() {
    let dir = TempDir::new("quiet");
    let (reloader, mut shown) = start_with_pattern(&dir);
    fs::write(dir.join("ridges.pat"), pattern_source(2)).unwrap();
    shown.wait_for_k(&reloader, 2);
    // Reads are events too (inotify reports opens); were they not ignored, every reload would
    // be followed by another batch each debounce period, forever.
    let window = std::time::Instant::now() + std::time::Duration::from_millis(500);
    let mut later = 0;
    while let Some(left) = window.checked_duration_since(std::time::Instant::now()) {
        later += usize::from(reloader.wait(left).is_some());
    }
    assert!(later <= 1, "{later} outcomes after one save");
}

#[test]
fn a_bare_pattern_file_on_a_built_in_scene_is_reloaded() {
    let dir = TempDir::new("bare-pattern");
    let pattern = dir.join("ridges.pat");
    fs::write(&pattern, pattern_source(1)).unwrap();
    let origin = dir.join("default.toml").display().to_string();
    let build = move || parse_scene(&scene_toml("pattern = \"ridges.pat\""), &origin);
    let source = FileSetSource::new(vec![pattern.clone()], build);
    let (reloader, first) = Reloader::start(source).unwrap();
    let mut shown = Shown::new(first);
    assert_eq!(shown.k(), Some(1.0));
    fs::write(&pattern, pattern_source(2)).unwrap();
    shown.wait_for_k(&reloader, 2);
}
