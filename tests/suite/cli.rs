//! The command line as a user meets it: exit status, messages, files written or not.

use crate::cli_support::*;
use std::path::Path;

#[test]
fn list_prints_every_built_in_scene() {
    let output = bumpwork(&["render", "--list"]);
    assert!(output.status.success());
    let names: Vec<String> = String::from_utf8(output.stdout)
        .unwrap()
        .lines()
        .map(String::from)
        .collect();
    assert_eq!(names, bumpwork::scene::PRESET_NAMES);
}

#[test]
fn render_writes_a_png_of_the_requested_size() {
    let dir = temp_dir("render");
    let out = dir.join("still.png");
    let output = bumpwork(&[
        "render",
        "big-sphere-mesh",
        "-o",
        out.to_str().unwrap(),
        "--size",
        "120x90",
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let (width, height, pixels) = decode_png(&out);
    assert_eq!((width, height), (120, 90));
    // The sphere is lit: the centre is brighter than the corner background.
    let at = |x: usize, y: usize| pixels[(y * 120 + x) * 3] as u32;
    assert!(at(60, 45) > at(2, 2) + 50);
    let leftovers: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(leftovers.len(), 1, "no temporary files left: {leftovers:?}");
}

#[test]
fn a_scene_file_renders_wherever_a_name_does() {
    let dir = temp_dir("file");
    let scene = dir.join("mine.toml");
    std::fs::write(
        &scene,
        "[camera]\neye = [0, 0, 5]\ntarget = [0, 0, 0]\n\n[[light]]\ndirectional = { towards = [0, 0, 1] }\n\n\
         [[object]]\nsurface = { sphere = { center = [0, 0, 0], radius = 1 } }\n",
    )
    .unwrap();
    let out = dir.join("mine.png");
    let output = bumpwork(&[
        "render",
        scene.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--size",
        "32x32",
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!(decode_png(&out).0, 32);
}

#[test]
fn unknown_scene_names_are_a_user_error_with_a_suggestion() {
    let dir = temp_dir("unknown");
    let out = dir.join("x.png");
    let output = bumpwork(&["render", "plane-dimple", "-o", out.to_str().unwrap()]);
    assert_user_error(&output, "unknown scene 'plane-dimple'");
    assert!(stderr(&output).contains("did you mean 'plane-dimples'"));
    assert!(!out.exists());
}

#[test]
fn a_missing_export_dir_is_a_user_error_before_the_workbench_starts() {
    let dir = temp_dir("export-dir");
    let missing = dir.join("not-here");
    let output = bumpwork(&["view", "--export-dir", missing.to_str().unwrap()]);
    assert_user_error(&output, "--export-dir: not a directory");
}

#[test]
fn malformed_scene_files_point_at_line_and_column() {
    let dir = temp_dir("malformed");
    let out = dir.join("x.png");
    let cases = [
        (
            "[camera]\neye = [0, 0, 5]\ntarget = [0, 0, 0]\n[[object]]\nsurface = { sphere = { center = [0, 0, 0], radius = -1 } }\n",
            ":5:",
            "expected a positive number",
        ),
        ("[camera]\neye = [0, 0, 5\n", ":2:", "error"),
        (
            "[camera]\neye = [0, 0, 5]\ntarget = [0, 0, 0]\nfov = 200\n[[object]]\nsurface = { sphere = { center = [0, 0, 0], radius = 1 } }\n",
            ":4:7",
            "between 0 and 180",
        ),
        (
            "[camera]\neye = [0, 0, 5]\ntarget = [0, 0, 0]\n[[object]]\nsurface = { klein-bottle = {} }\n",
            ":5:",
            "unknown variant",
        ),
        (
            "[camera]\neye = [0, 0, 5]\ntarget = [0, 0, 0]\n[[object]]\nsurface = { torus = { center = [0, 0, 0], major-radius = 1, minor-radius = 2 } }\n",
            ":5:",
            "minor-radius (2) must be less than major-radius (1)",
        ),
        (
            "[camera]\neye = [0, 0, 5]\ntarget = [0, 0, 0]\nzoom = 3\n",
            ":4:1",
            "unknown field",
        ),
    ];
    for (i, (text, location, what)) in cases.iter().enumerate() {
        let scene = dir.join(format!("bad{i}.toml"));
        std::fs::write(&scene, text).unwrap();
        let output = bumpwork(&[
            "render",
            scene.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
        ]);
        assert_user_error(&output, what);
        let message = stderr(&output);
        assert!(
            message.contains(&format!("bad{i}.toml{location}")),
            "case {i} location: {message}"
        );
        assert!(message.contains('^'), "case {i} has a caret: {message}");
        assert!(!out.exists());
    }
}

#[test]
fn control_characters_in_file_names_are_escaped() {
    let dir = temp_dir("escaped-names");
    let out = dir.join("x.png");
    let output = bumpwork(&["render", "evil\x1b[31m.toml", "-o", out.to_str().unwrap()]);
    assert_user_error(&output, "evil\\e[31m.toml");
    assert!(!stderr(&output).contains('\x1b'));
    let nowhere = dir.join("evil\x1b[31m/x.png");
    let output = bumpwork(&["render", "plane-dimples", "-o", nowhere.to_str().unwrap()]);
    assert_user_error(&output, "evil\\e[31m does not exist");
    assert!(!stderr(&output).contains('\x1b'));
}

#[test]
fn bad_sizes_are_refused() {
    for size in ["0x10", "10x0", "100000x100", "abc", "10x", "-5x5"] {
        let output = bumpwork(&[
            "render",
            "plane-mesh",
            "-o",
            "/tmp/never.png",
            &format!("--size={size}"),
        ]);
        assert_user_error(&output, "WIDTHxHEIGHT");
    }
}

#[test]
fn an_unwritable_destination_is_a_user_error_and_leaves_nothing() {
    let dir = temp_dir("unwritable");
    let out = dir.join("missing-dir").join("x.png");
    let output = bumpwork(&[
        "render",
        "plane-mesh",
        "-o",
        out.to_str().unwrap(),
        "--size",
        "8x8",
    ]);
    assert_user_error(&output, "cannot write");
    assert!(!out.exists());
}

#[test]
fn check_accepts_good_files_and_reports_each_bad_one() {
    let dir = temp_dir("check");
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let good = [
        root.join("patterns/dimples.pat"),
        root.join("textures/brick.png"),
        root.join("scenes/sphere-on-plane.toml"),
    ];
    let args: Vec<&str> = std::iter::once("check")
        .chain(good.iter().map(|p| p.to_str().unwrap()))
        .collect();
    let output = bumpwork(&args);
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!(
        String::from_utf8_lossy(&output.stdout)
            .matches(": ok: ")
            .count(),
        3
    );

    let pattern = dir.join("bad.pat");
    std::fs::write(
        &pattern,
        "param period = 30 in 5..100\nheight = sin(u / period) + wobble(v)\n",
    )
    .unwrap();
    let image = dir.join("bad.png");
    std::fs::write(&image, b"\x89PNG\r\n\x1a\nthis is not a png").unwrap();
    let other = dir.join("notes.txt");
    std::fs::write(&other, "hello").unwrap();
    let output = bumpwork(&[
        "check",
        pattern.to_str().unwrap(),
        image.to_str().unwrap(),
        other.to_str().unwrap(),
    ]);
    assert_user_error(&output, "3 of 3 files failed");
    let message = stderr(&output);
    assert!(
        message.contains("bad.pat:2:28") && message.contains("wobble") && message.contains('^'),
        "{message}"
    );
    assert!(message.contains("bad.png"), "{message}");
    assert!(message.contains("notes.txt: not a pattern"), "{message}");
}

#[test]
fn help_fits_100_columns_and_shells_and_man_get_their_files() {
    for command in [
        &["--help"][..],
        &["render", "--help"],
        &["view", "--help"],
        &["gallery", "--help"],
        &["check", "--help"],
        &["bench", "--help"],
    ] {
        let output = bumpwork(command);
        assert!(output.status.success(), "{command:?}");
        let help = String::from_utf8(output.stdout).unwrap();
        let widest = help.lines().map(|l| l.chars().count()).max().unwrap_or(0);
        assert!(widest <= 100, "{command:?}: a line of {widest} columns");
    }
    let version = bumpwork(&["--version"]);
    assert_eq!(
        String::from_utf8_lossy(&version.stdout).trim(),
        format!("bumpwork {}", env!("CARGO_PKG_VERSION"))
    );
    for shell in ["bash", "zsh", "fish"] {
        let script = bumpwork(&["completions", shell]);
        assert!(script.status.success(), "{shell}");
        let text = String::from_utf8_lossy(&script.stdout);
        assert!(
            text.contains("render") && text.contains("tessellation"),
            "{shell}"
        );
    }
    let man = bumpwork(&["man"]);
    let page = String::from_utf8_lossy(&man.stdout);
    assert!(page.contains(".TH bumpwork 1"), "{page}");
    assert!(page.contains("render"), "{page}");
    assert_user_error(
        &bumpwork(&["completions", "cmd.exe"]),
        "invalid value 'cmd.exe'",
    );
}

#[test]
fn patterns_lists_every_shipped_pattern_and_prints_one() {
    let output = bumpwork(&["patterns"]);
    assert!(output.status.success());
    let list = String::from_utf8(output.stdout).unwrap();
    for (name, source) in bumpwork::pattern::BUILTINS {
        let pattern = bumpwork::pattern::Pattern::compile(source, name).unwrap();
        let line = list
            .lines()
            .find(|l| l.starts_with(&format!("{name} (")))
            .unwrap_or_else(|| panic!("{name} missing from:\n{list}"));
        let kind = match pattern.output() {
            bumpwork::pattern::OutputKind::Color => "(colour)",
            bumpwork::pattern::OutputKind::Slope => "(slope)",
            bumpwork::pattern::OutputKind::Height => "(height)",
        };
        assert!(line.contains(kind), "{line}");
        for param in pattern.params() {
            assert!(
                list.contains(&format!("{}={}", param.name, param.default)),
                "{name}"
            );
        }
        // The description is whole sentences, however many lines it takes; no line is wide.
        let start = list.find(line).unwrap();
        let first_param = match pattern.params().first() {
            Some(param) => format!("    {}={}", param.name, param.default),
            None => "    no parameters".to_string(),
        };
        let block: Vec<&str> = list[start..]
            .lines()
            .take_while(|l| !l.starts_with(&first_param))
            .collect();
        let description = block.join(" ");
        assert!(description.ends_with('.'), "{name}: {description}");
        assert!(block.iter().all(|l| l.chars().count() <= 100), "{block:?}");
    }
    let dimples = list.find("dimples (height)").unwrap();
    assert!(
        list[dimples..].contains("without its integer steps."),
        "the whole first sentence:\n{list}"
    );
    let file = bumpwork(&["patterns", "dimples"]);
    assert!(file.status.success());
    let shipped = std::fs::read(Path::new(env!("CARGO_MANIFEST_DIR")).join("patterns/dimples.pat"));
    assert_eq!(file.stdout, shipped.unwrap());
    assert_user_error(
        &bumpwork(&["patterns", "dimpels"]),
        "no shipped pattern is called 'dimpels'",
    );
}

#[test]
fn the_output_format_follows_the_extension_and_a_mismatch_is_refused() {
    let dir = temp_dir("format-by-extension");
    let render = |name: &str, format: Option<&str>| {
        let path = dir.join(name);
        let mut args = vec![
            "render",
            "plane-dimples",
            "--size",
            "8x6",
            "-o",
            path.to_str().unwrap(),
        ];
        args.extend(format.iter().flat_map(|f| ["--format", f]));
        let output = bumpwork(&args);
        (output, std::fs::read(&path).ok())
    };
    let (output, ppm) = render("a.ppm", None);
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(ppm.unwrap().starts_with(b"P6"), "a .ppm name gives a PPM");
    let (_, png) = render("b.still", None);
    assert!(
        png.unwrap().starts_with(b"\x89PNG"),
        "no extension to go by: PNG"
    );
    let (_, ppm) = render("c.still", Some("ppm"));
    assert!(
        ppm.unwrap().starts_with(b"P6"),
        "--format where the extension says nothing"
    );
    let (output, written) = render("d.png", Some("ppm"));
    assert_user_error(&output, "names a png file but --format says ppm");
    assert!(written.is_none());
    let (output, written) = render("e.jpg", None);
    assert_user_error(&output, "not written as JPEG");
    assert!(written.is_none());
}
