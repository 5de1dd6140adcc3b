//! A scene file's `[quality]` table and `time`: the knobs apply over whichever preset is chosen,
//! single options and `--set` over them, a still made from the file keeps what it was made at,
//! and a bad knob is one message at its own line and column.

use crate::cli_support::*;
use bumpwork::export::metadata::{RECIPE, read_png_text};
use bumpwork::still::Recipe;
use std::path::{Path, PathBuf};

const SCENE: &str = include_str!("../../../scenes/sphere-on-plane.toml");

fn scene_with(dir: &TestDir, name: &str, top: &str, quality: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, format!("{top}\n{SCENE}\n[quality]\n{quality}\n")).unwrap();
    path
}

fn render(scene: &Path, output: &Path, extra: &[&str]) -> std::process::Output {
    let mut args = vec![
        "render",
        scene.to_str().unwrap(),
        "--size",
        "40x30",
        "-o",
        output.to_str().unwrap(),
    ];
    args.extend(extra);
    bumpwork(&args)
}

fn recipe_of(path: &Path) -> Recipe {
    let texts = read_png_text(path).unwrap();
    let text = &texts.iter().find(|(k, _)| k == RECIPE).unwrap().1;
    Recipe::parse(text, "test").unwrap()
}

#[test]
fn the_table_sets_knobs_over_the_preset_and_options_set_them_over_the_table() {
    let dir = temp_dir("scene-quality");
    let scene = scene_with(
        &dir,
        "s.toml",
        "time = 2.5",
        "samples = 4\nnormal-form = \"full\"",
    );
    let out = dir.join("a.png");
    let made = |extra: &[&str]| {
        let output = render(&scene, &out, extra);
        assert!(output.status.success(), "{extra:?}: {}", stderr(&output));
        recipe_of(&out)
    };
    let plain = made(&[]);
    assert_eq!(plain.quality.samples, 4);
    assert_eq!(plain.quality.tessellation, 64, "interactive's, untouched");
    assert_eq!(plain.time, 2.5, "the scene's time");
    // A preset from the command line takes the table over it.
    let draft = made(&["--quality", "draft"]);
    assert_eq!(draft.quality.samples, 4);
    assert_eq!(draft.quality.tessellation, 16);
    assert_eq!(draft.quality.normal_form, bumpwork::shade::NormalForm::Full);
    // Single options and --set win over the table, and --time over the scene's.
    let options = made(&["--samples", "1", "--time", "0"]);
    assert_eq!((options.quality.samples, options.time), (1, 0.0));
    let set = made(&["--set", "quality.normal-form=seed"]);
    assert_eq!(set.quality.normal_form, bumpwork::shade::NormalForm::Seed);
    // A still made again from its recipe keeps the option over the table it carries.
    made(&["--samples", "9"]);
    let again = dir.join("again.png");
    let output = bumpwork(
        &["render", "--from", out.to_str().unwrap(), "-o"]
            .into_iter()
            .chain([again.to_str().unwrap()])
            .collect::<Vec<_>>(),
    );
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!(recipe_of(&again).quality.samples, 9);
}

#[test]
fn a_bad_knob_is_one_message_at_its_place_and_writes_nothing() {
    let dir = temp_dir("scene-quality-errors");
    let out = dir.join("x.png");
    let lines = SCENE.lines().count() + 4;
    for (setting, expected) in [
        ("samples = 0", "samples 0 is outside 1..=1024"),
        ("samplez = 4", "no quality knob 'samplez'; the knobs are"),
        (
            "normal-form = \"wild\"",
            "expected one of `blinn`, `seed`, `full`",
        ),
        ("samples = \"many\"", "expected a whole number"),
        ("adaptive-samples = 3", "contrast must be from 0 to 1"),
        ("tessellation = 1e9", "expected a whole number"),
    ] {
        let scene = scene_with(&dir, "bad.toml", "", setting);
        let output = render(&scene, &out, &[]);
        assert_user_error(&output, expected);
        let column = setting.find('=').unwrap() + 3;
        assert_user_error(&output, &format!("bad.toml:{lines}:{column}: quality."));
        assert!(!out.exists(), "{setting} wrote a still");
        assert_user_error(&bumpwork(&["check", scene.to_str().unwrap()]), expected);
    }
    let scene = dir.join("late.toml");
    std::fs::write(&scene, format!("time = 1e12\n{SCENE}")).unwrap();
    assert_user_error(&render(&scene, &out, &[]), "late.toml:1:8: expected a time");
}

#[test]
fn the_workbench_takes_the_table_and_quality_settings_over_its_presets() {
    use bumpwork::term::ColorMode;
    use bumpwork::tui::{Action, App, WorkbenchOptions};
    let dir = temp_dir("scene-quality-workbench");
    let scene = scene_with(&dir, "w.toml", "", "samples = 4\ntessellation = 24");
    let options = |settings: &[&str]| WorkbenchOptions {
        scenes: vec![scene.to_str().unwrap().to_string()],
        watch: false,
        settings: settings
            .iter()
            .map(|s| bumpwork::overrides::Override::parse(s).unwrap())
            .collect(),
        ..WorkbenchOptions::default()
    };
    let mut app = App::new(
        &options(&["quality.normal-form=full"]),
        ColorMode::TrueColor,
    )
    .unwrap();
    assert_eq!(app.quality_in_use().samples, 4);
    assert_eq!(app.quality_in_use().tessellation, 24);
    assert_eq!(
        app.quality_in_use().normal_form,
        bumpwork::shade::NormalForm::Full
    );
    app.apply(Action::NextQuality);
    assert_eq!(app.quality_preset().name(), "high");
    assert_eq!(app.quality_in_use().tessellation, 24, "the table over high");
    assert_eq!(
        app.quality_in_use().adaptive_tolerance_px,
        Some(0.5),
        "high's own"
    );
    let refused = App::new(&options(&["quality.samples=0"]), ColorMode::TrueColor);
    assert!(refused.is_err_and(|e| e.to_string().contains("--set quality.samples=0")));
}

#[test]
fn the_workbench_tells_a_bad_setting_before_it_asks_for_a_terminal() {
    let output = bumpwork(&["view", "plane-dimples", "--set", "quality.samplez=2"]);
    assert_user_error(
        &output,
        "--set quality.samplez=2: no quality knob 'samplez'",
    );
    let output = bumpwork(&["view", "plane-dimples"]);
    assert_user_error(&output, "the workbench needs a terminal");
}
