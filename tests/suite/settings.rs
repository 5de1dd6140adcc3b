//! `--set KEY=VALUE` on render and gallery: each key does what the same setting does elsewhere,
//! the recipe keeps it, and every bad key or value is one line naming what is valid.

use crate::cli_support::{assert_user_error, bumpwork, decode_png, stderr, temp_dir};

fn render(dir: &crate::cli_support::TestDir, name: &str, extra: &[&str]) -> Vec<u8> {
    let path = dir.join(name);
    let mut args = vec![
        "render",
        "plane-dimples",
        "--size",
        "48x32",
        "-o",
        path.to_str().unwrap(),
    ];
    args.extend(extra);
    let output = bumpwork(&args);
    assert!(output.status.success(), "{extra:?}: {}", stderr(&output));
    decode_png(&path).2
}

#[test]
fn settings_do_what_the_same_setting_does_elsewhere_and_the_recipe_keeps_them() {
    let dir = temp_dir("settings-effect");
    let plain = render(&dir, "plain.png", &[]);
    // The scene's own value changes nothing; another changes the picture.
    assert_eq!(
        render(&dir, "same.png", &["--set", "bump.strength=1"]),
        plain
    );
    let flat = render(&dir, "flat.png", &["--set", "bump.strength=0"]);
    assert_ne!(flat, plain);
    let deeper = render(&dir, "deeper.png", &["--set", "1.bump.params.strength=3"]);
    assert_ne!(deeper, plain);
    // A quality knob set by key is the same as its own option.
    assert_eq!(
        render(&dir, "knob.png", &["--set", "quality.samples=4"]),
        render(&dir, "option.png", &["--samples", "4"])
    );
    // render --from makes the still made with settings again.
    let again = dir.join("again.png");
    let output = bumpwork(&[
        "render",
        "--from",
        dir.join("deeper.png").to_str().unwrap(),
        "-o",
        again.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!(decode_png(&again).2, deeper);
}

#[test]
fn every_bad_setting_is_one_line_naming_what_is_valid() {
    let dir = temp_dir("settings-errors");
    let out = dir.join("x.png");
    for (setting, expected) in [
        ("quality.smaples=4", "the knobs are adaptive-samples"),
        (
            "quality.normal-form=wild",
            "expected one of `blinn`, `seed`, `full`",
        ),
        ("quality.samples=0", "samples 0 is outside 1..=1024"),
        ("quality.samples=many", "expected a whole number"),
        (
            "bump.nope=1",
            "no such parameter; the parameters there are strength",
        ),
        (
            "bump.params.strength=99",
            "99 is outside strength's range 0..4",
        ),
        ("bump.strength=deep", "expected a number"),
        ("3.bump.strength=1", "the scene has 1 objects"),
        ("0.bump.strength=1", "an object is counted from 1"),
        ("lights.1=2", "unknown setting"),
        ("samples", "expected KEY=VALUE"),
    ] {
        let output = bumpwork(&[
            "render",
            "plane-dimples",
            "-o",
            out.to_str().unwrap(),
            "--set",
            setting,
        ]);
        assert_user_error(&output, expected);
        let message = stderr(&output);
        assert!(
            message
                .lines()
                .next()
                .unwrap()
                .starts_with("bumpwork: error:"),
            "{message}"
        );
        assert!(!out.exists(), "{setting} wrote a still");
    }
}

#[test]
fn gallery_settings_apply_where_the_scene_has_them() {
    let dir = temp_dir("settings-gallery");
    let gallery = dir.join("g");
    let args = |setting: &str| {
        bumpwork(&[
            "gallery",
            "-o",
            gallery.to_str().unwrap(),
            "--size",
            "16x12",
            "--samples",
            "1",
            "--scenes",
            "plane-dimples,textured-sphere",
            "--set",
            setting,
        ])
    };
    let output = args("bump.params.strength=2");
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(gallery.join("textured-sphere.png").exists());
    let wrong = dir.join("never");
    let output = bumpwork(&[
        "gallery",
        "-o",
        wrong.to_str().unwrap(),
        "--scenes",
        "plane-dimples",
        "--set",
        "bump.nope=1",
    ]);
    assert_user_error(&output, "no scene of the gallery has that parameter");
    assert!(!wrong.exists(), "checked before anything is made");
}

#[test]
fn the_camera_can_be_set_from_the_command_line_and_is_checked_as_a_scene_files() {
    let dir = temp_dir("settings-camera");
    let plain = render(&dir, "plain.png", &[]);
    let scene = bumpwork::scene::preset("plane-dimples").unwrap();
    let [x, y, z] = scene.camera.eye.to_array();
    let own = format!("{x},{y},{z}");
    assert_eq!(
        render(&dir, "own.png", &["--eye", &own]),
        plain,
        "the scene's own eye"
    );
    let moved = render(&dir, "moved.png", &["--eye", "0,-300,300", "--fov", "60"]);
    assert_ne!(moved, plain);
    // The recipe records the camera used.
    let again = dir.join("again.png");
    let output = bumpwork(&[
        "render",
        "--from",
        dir.join("moved.png").to_str().unwrap(),
        "-o",
        again.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!(decode_png(&again).2, moved);
    let out = dir.join("bad.png");
    for (args, expected) in [
        (&["--eye", "1,2"][..], "expected three numbers X,Y,Z"),
        (
            &["--eye", "0,0,0", "--target", "0,0,0"],
            "eye and target are the same point",
        ),
        (&["--fov", "200"], "an angle in degrees between 0 and 180"),
        (
            &["--eye=-5,0,1e13"],
            "expected a point: three finite numbers",
        ),
    ] {
        let mut all = vec!["render", "plane-dimples", "-o", out.to_str().unwrap()];
        all.extend(args);
        assert_user_error(&bumpwork(&all), expected);
        assert!(!out.exists());
    }
}

/// `--set bump.pattern=…` and `texture.image=…` are not numbers: one line says how to choose a
/// pattern or image instead.
#[test]
fn a_pattern_or_image_given_to_set_says_how_to_choose_one() {
    for (setting, says) in [
        ("bump.pattern=stucco", "bump = { pattern = \"stucco\" }"),
        ("texture.image=a.png", "PHOTO.png"),
    ] {
        let run = bumpwork(&["render", "plane-dimples", "-o", "x.png", "--set", setting]);
        assert_user_error(&run, says);
    }
}

/// `--bump` and `--texture` put a shipped pattern or image, or a file, on every object; the
/// still's recipe keeps them, so `render --from` makes the same picture; a wrong kind or an
/// unknown name is one line and no file.
#[test]
fn bump_and_texture_choose_a_pattern_or_image_and_the_recipe_keeps_them() {
    let dir = temp_dir("bump-texture");
    let still = dir.join("chosen.png");
    let plain = dir.join("plain.png");
    let again = dir.join("again.png");
    let path = |p: &std::path::Path| p.to_str().unwrap().to_string();
    let render = |extra: &[&str], out: &str| {
        let mut args = vec!["render", "plane-dimples", "--size=64x48", "-o", out];
        args.extend(extra);
        let run = bumpwork(&args);
        assert!(run.status.success(), "{}", stderr(&run));
        decode_png(std::path::Path::new(out)).2
    };
    let chosen = render(&["--bump", "gravel", "--texture", "chelsea"], &path(&still));
    assert_ne!(
        chosen,
        render(&[], &path(&plain)),
        "the choice changed nothing"
    );
    let run = bumpwork(&["render", "--from", &path(&still), "-o", &path(&again)]);
    assert!(run.status.success(), "{}", stderr(&run));
    assert_eq!(decode_png(&again).2, chosen, "--from lost the choice");
    let refused = dir.join("refused.png");
    for (option, name, says) in [
        (
            "--texture",
            "stucco",
            "--texture stucco: a height or slope pattern is a bump",
        ),
        (
            "--bump",
            "checks",
            "--bump checks: a colour pattern is a texture",
        ),
        (
            "--bump",
            "no-such-thing",
            "--bump no-such-thing: expected a shipped pattern",
        ),
    ] {
        let run = bumpwork(&[
            "render",
            "plane-dimples",
            "-o",
            &path(&refused),
            option,
            name,
        ]);
        assert_user_error(&run, says);
        assert!(!refused.exists());
    }
}
