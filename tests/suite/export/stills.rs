//! Stills as a user makes them: valid PNGs carrying their recipe, `--from` making the same
//! pixels again, sequences, PPM, and failures that leave no file behind.

use crate::cli_support::*;
use bumpwork::export::metadata::{RECIPE, SCENE, read_png_text};
use bumpwork::still::Recipe;
use std::path::Path;
use std::process::Command;
use std::time::{Duration, Instant};

fn recipe_of(path: &Path) -> Recipe {
    let texts = read_png_text(path).unwrap();
    let text = &texts.iter().find(|(k, _)| k == RECIPE).unwrap().1;
    Recipe::parse(text, "test").unwrap()
}

/// Files in `dir` other than those named.
fn leftovers(dir: &Path, expected: &[&str]) -> Vec<String> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| !expected.contains(&n.as_str()))
        .collect()
}

#[test]
fn a_still_carries_its_recipe_and_from_makes_the_same_pixels() {
    let dir = temp_dir("still-from");
    let first = dir.join("first.png");
    let again = dir.join("again.png");
    let out = bumpwork(&[
        "render",
        "sphere-on-plane-dimples",
        "-o",
        first.to_str().unwrap(),
        "--size",
        "96x64",
        "--samples",
        "4",
        "--time",
        "1.5",
        "--tessellation",
        "24",
        "--quality",
        "high",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let (w, h, pixels) = decode_png(&first);
    assert_eq!((w, h), (96, 64));
    let recipe = recipe_of(&first);
    assert_eq!((recipe.width, recipe.height), (96, 64));
    // The preset's shading knobs, with the explicit options over it.
    let high = bumpwork::quality::Quality::high();
    let expected = bumpwork::quality::Quality {
        samples: 4,
        tessellation: 24,
        adaptive_tolerance_px: None,
        adaptive_samples: None,
        ..high
    };
    assert_eq!(recipe.quality, expected);
    assert_eq!(recipe.time, 1.5);
    assert_eq!(recipe.source, "sphere-on-plane-dimples");
    assert!(recipe.program.starts_with("bumpwork "));
    let texts = read_png_text(&first).unwrap();
    assert!(
        texts
            .iter()
            .any(|(k, t)| k == SCENE && t.contains("[[object]]"))
    );

    let out = bumpwork(&[
        "render",
        "--from",
        first.to_str().unwrap(),
        "-o",
        again.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(
        decode_png(&again).2,
        pixels,
        "--from must reproduce the pixels"
    );
    assert_eq!(recipe_of(&again), recipe);
}

#[test]
fn from_applies_pattern_parameters_and_warns_when_a_pattern_file_changed() {
    let dir = temp_dir("still-pattern");
    let pattern = dir.join("rings.pat");
    std::fs::write(
        &pattern,
        "param period = 20 in 2..100\nheight = sin(u / period) * 4\n",
    )
    .unwrap();
    let scene = dir.join("scene.toml");
    std::fs::write(
        &scene,
        "[camera]\neye = [0, 200, 300]\ntarget = [0, 0, 0]\n\
         [[light]]\npoint = { position = [100, 300, 200] }\n\
         [[object]]\nsurface = { plane = { origin = [-200, 0, 200], normal = [0, 1, 0], u-axis = [1, 0, 0], size = [400, 400] } }\n\
         bump = { pattern = \"rings.pat\", params = { period = 7 } }\n",
    )
    .unwrap();
    let still = dir.join("still.png");
    let again = dir.join("again.png");
    let args = [
        "render",
        scene.to_str().unwrap(),
        "-o",
        still.to_str().unwrap(),
        "--size",
        "64x48",
    ];
    assert!(bumpwork(&args).status.success());
    let recipe = recipe_of(&still);
    let bump = recipe.objects[0].bump.as_ref().unwrap();
    assert_eq!(bump.params.get("period"), Some(&7.0));
    assert_eq!(recipe.files.len(), 1);
    assert!(Path::new(&recipe.files[0].path).is_absolute());

    // Rendered again from elsewhere, the scene's relative pattern path still resolves.
    let elsewhere = tempfile::tempdir().expect("a temporary directory");
    let out = Command::new(env!("CARGO_BIN_EXE_bumpwork"))
        .args([
            "render",
            "--from",
            still.to_str().unwrap(),
            "-o",
            again.to_str().unwrap(),
        ])
        .current_dir(elsewhere.path())
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(!stderr(&out).contains("warning"), "{}", stderr(&out));
    assert_eq!(decode_png(&again).2, decode_png(&still).2);

    std::fs::write(
        &pattern,
        "param period = 20 in 2..100\nheight = cos(v / period) * 4\n",
    )
    .unwrap();
    let out = bumpwork(&[
        "render",
        "--from",
        still.to_str().unwrap(),
        "-o",
        again.to_str().unwrap(),
    ]);
    assert!(out.status.success());
    assert!(
        stderr(&out).contains("rings.pat has changed"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn a_time_range_writes_a_numbered_sequence() {
    let dir = temp_dir("still-sequence");
    let out = bumpwork(&[
        "render",
        "image-scroll",
        "-o",
        dir.join("wave.png").to_str().unwrap(),
        "--size",
        "32x24",
        "--time-range",
        "0..0.3",
        "--fps",
        "10",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let mut names = leftovers(&dir, &[]);
    names.sort();
    assert_eq!(names, ["wave-0000.png", "wave-0001.png", "wave-0002.png"]);
    let times: Vec<f64> = names.iter().map(|n| recipe_of(&dir.join(n)).time).collect();
    assert!(
        (times[1] - 0.1).abs() < 1e-12 && (times[2] - 0.2).abs() < 1e-12,
        "{times:?}"
    );
    let first = decode_png(&dir.join(&names[0])).2;
    assert_ne!(
        first,
        decode_png(&dir.join(&names[1])).2,
        "the image scrolls between frames"
    );
}

#[test]
fn ppm_holds_the_same_pixels_as_png() {
    let dir = temp_dir("still-ppm");
    let (png, ppm) = (dir.join("a.png"), dir.join("a.ppm"));
    for (path, format) in [(&png, "png"), (&ppm, "ppm")] {
        let out = bumpwork(&[
            "render",
            "big-sphere-squares",
            "-o",
            path.to_str().unwrap(),
            "--size",
            "40x30",
            "--format",
            format,
        ]);
        assert!(out.status.success(), "{}", stderr(&out));
    }
    let bytes = std::fs::read(&ppm).unwrap();
    let header = b"P6\n40 30\n255\n";
    assert_eq!(&bytes[..header.len()], header);
    assert_eq!(&bytes[header.len()..], decode_png(&png).2.as_slice());
}

#[test]
fn failed_renders_leave_no_file_and_say_why() {
    let dir = temp_dir("still-fail");
    let out_path = dir.join("out.png");
    let out = out_path.to_str().unwrap();
    let bad_scene = dir.join("bad.toml");
    std::fs::write(
        &bad_scene,
        "[camera]\neye = [0, 0, 1]\ntarget = [0, 0, 1]\n[[object]]\n",
    )
    .unwrap();
    assert_user_error(
        &bumpwork(&["render", bad_scene.to_str().unwrap(), "-o", out]),
        "bad.toml",
    );
    let missing_dir = bumpwork(&["render", "plane-ripple", "-o", "/nonexistent-dir/x.png"]);
    assert_user_error(
        &missing_dir,
        "cannot write /nonexistent-dir/x.png: the directory /nonexistent-dir does not exist",
    );
    assert!(
        !stderr(&missing_dir).contains(".tmp"),
        "{}",
        stderr(&missing_dir)
    );
    let file_as_dir = dir.join("plain-file");
    std::fs::write(&file_as_dir, "not a directory").unwrap();
    let inside_a_file = file_as_dir.join("x.png");
    assert_user_error(
        &bumpwork(&[
            "render",
            "plane-ripple",
            "-o",
            inside_a_file.to_str().unwrap(),
        ]),
        "plain-file is not a directory",
    );
    std::fs::remove_file(&file_as_dir).unwrap();
    assert_user_error(
        &bumpwork(&["render", "plane-ripple", "-o", out, "--size", "20000x10"]),
        "1..=16384",
    );
    let plain = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/pngsuite/basn2c08.png");
    assert_user_error(
        &bumpwork(&["render", "--from", plain.to_str().unwrap(), "-o", out]),
        "not a still bumpwork can make again",
    );
    let broken = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/pngsuite/xcrn0g04.png");
    assert_user_error(
        &bumpwork(&["render", "--from", broken.to_str().unwrap(), "-o", out]),
        "PNG",
    );
    // An image whose header asks for more memory than the texture limit allows.
    std::fs::write(
        dir.join("huge.ppm"),
        b"P6\n100000 100000\n255\n\x00\x00\x00",
    )
    .unwrap();
    let greedy = dir.join("greedy.toml");
    std::fs::write(
        &greedy,
        "[camera]\neye = [0, 0, 5]\ntarget = [0, 0, 0]\n\
         [[object]]\nsurface = { sphere = { center = [0, 0, 0], radius = 1 } }\n\
         texture = { image = \"huge.ppm\", mapping = \"spherical\" }\n",
    )
    .unwrap();
    assert_user_error(
        &bumpwork(&["render", greedy.to_str().unwrap(), "-o", out]),
        "huge.ppm",
    );
    assert_eq!(
        leftovers(&dir, &["bad.toml", "huge.ppm", "greedy.toml"]),
        Vec::<String>::new()
    );
}

#[test]
fn an_interrupted_export_leaves_no_partial_file() {
    let signals = [
        ("INT", 2),
        ("TERM", 15),
        ("HUP", 1),
        ("QUIT", 3),
        ("USR1", 10),
        ("USR2", 12),
        ("ALRM", 14),
    ];
    for (name, number) in signals {
        interrupt_export(name, number);
    }
}

fn interrupt_export(signal: &str, number: i32) {
    let dir = temp_dir(&format!("still-interrupt-{signal}"));
    let out = dir.join("big.png");
    let child = Command::new(env!("CARGO_BIN_EXE_bumpwork"))
        .args([
            "render",
            "sphere-on-plane-dimples",
            "-o",
            out.to_str().unwrap(),
        ])
        .args(["--size", "4000x3000", "--samples", "64"])
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    // Wait until the render has started writing (its temporary file exists), then interrupt.
    let started = Instant::now();
    while leftovers(&dir, &[]).is_empty() && started.elapsed() < Duration::from_secs(20) {
        std::thread::sleep(Duration::from_millis(20));
    }
    assert!(
        !leftovers(&dir, &[]).is_empty(),
        "the render never started its file"
    );
    let pid = child.id().to_string();
    assert!(
        Command::new("kill")
            .args([&format!("-{signal}"), &pid])
            .status()
            .unwrap()
            .success()
    );
    let output = child.wait_with_output().unwrap();
    assert_eq!(
        output.status.code(),
        Some(128 + number),
        "SIG{signal}: {}",
        stderr(&output)
    );
    assert!(
        stderr(&output).contains("interrupted"),
        "{}",
        stderr(&output)
    );
    assert_eq!(leftovers(&dir, &[]), Vec::<String>::new());
}

#[test]
fn the_gallery_writes_each_scene_and_a_contact_sheet_of_them() {
    let dir = temp_dir("gallery");
    let out = bumpwork(&[
        "gallery",
        "-o",
        dir.to_str().unwrap(),
        "--scenes",
        "plane-dimples,textured-sphere",
        "--size",
        "64x48",
        "--samples",
        "1",
        "--thumbnail",
        "32x24",
        "--columns",
        "2",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let mut names = leftovers(&dir, &[]);
    names.sort();
    assert_eq!(
        names,
        [
            "contact-sheet.png",
            "plane-dimples.png",
            "textured-sphere.png"
        ]
    );
    assert_eq!(
        recipe_of(&dir.join("textured-sphere.png")).source,
        "textured-sphere"
    );
    // Two 32-wide cells with 8-pixel gaps; one row of 24 + a label of two 18-pixel lines.
    let (w, h, sheet) = decode_png(&dir.join("contact-sheet.png"));
    assert_eq!((w, h), (2 * 40 + 8, 24 + 40 + 8 + 8));
    // The first thumbnail's middle is the first still's middle, scaled down by 2.
    let (sw, _, still) = decode_png(&dir.join("plane-dimples.png"));
    let at =
        |pixels: &[u8], width: u32, x: u32, y: u32| pixels[3 * (y * width + x) as usize] as i32;
    assert!((at(&sheet, w, 8 + 16, 8 + 12) - at(&still, sw, 32, 24)).abs() < 40);
    assert_user_error(
        &bumpwork(&[
            "gallery",
            "-o",
            dir.to_str().unwrap(),
            "--scenes",
            "no-such-scene",
        ]),
        "unknown scene 'no-such-scene'",
    );
}

#[test]
#[ignore = "needs povray; bash .ci/run installs it and runs the ignored tests"]
fn a_pov_ray_scene_carries_every_object_and_its_baked_maps() {
    let dir = temp_dir("still-pov");
    let pov = dir.join("scene.pov");
    let out = bumpwork(&[
        "render",
        "sphere-on-plane-waffle",
        "-o",
        pov.to_str().unwrap(),
        "--size",
        "64x36",
        "--format",
        "pov",
        "--tessellation",
        "8",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let sdl = std::fs::read_to_string(&pov).unwrap();
    assert_eq!(sdl.matches("mesh2 {").count(), 2);
    assert!(sdl.contains("camera {") && sdl.contains("light_source {"));
    // POV-Ray's lights cast shadows, as the scene's do; without shadows, none does.
    assert!(!sdl.contains("shadowless"), "the scene has shadows");
    let flat = dir.join("flat.pov");
    let args = [
        "render",
        "sphere-on-plane-waffle",
        "-o",
        flat.to_str().unwrap(),
    ];
    let out = bumpwork(&[&args[..], &["--format", "pov", "--set", "shadows=false"]].concat());
    assert!(out.status.success(), "{}", stderr(&out));
    let flat = std::fs::read_to_string(&flat).unwrap();
    let lights = flat.matches("light_source {").count();
    assert!(lights > 0);
    assert_eq!(
        flat.matches("shadowless").count(),
        lights,
        "every light is shadowless"
    );
    for map in ["scene-1-bump.png", "scene-2-bump.png"] {
        assert!(sdl.contains(map), "{map} is referenced");
        let decoder = png::Decoder::new(std::io::BufReader::new(
            std::fs::File::open(dir.join(map)).unwrap(),
        ));
        let info = decoder.read_info().unwrap().info().clone();
        assert_eq!((info.width, info.bit_depth), (1024, png::BitDepth::Sixteen));
    }
    // The seed's dimples are slopes, with no height to bake: said, not silently dropped.
    let out = bumpwork(&[
        "render",
        "plane-dimples",
        "-o",
        dir.join("d.pov").to_str().unwrap(),
        "--format",
        "pov",
    ]);
    assert!(out.status.success());
    assert!(stderr(&out).contains("slope pattern"), "{}", stderr(&out));
    let povray = Command::new("povray")
        .args(["+W64", "+H36", "-D", "-GA", "+Oscene.png", "scene.pov"])
        .current_dir(&dir)
        .output()
        .expect("povray is not installed (bash .ci/run installs it)");
    assert!(
        povray.status.success(),
        "{}",
        String::from_utf8_lossy(&povray.stderr)
    );
    assert_eq!(decode_png(&dir.join("scene.png")).0, 64);
}

#[test]
fn a_recipe_from_another_version_that_cannot_be_read_says_which_version_made_it() {
    let dir = temp_dir("still-old-recipe");
    let first = dir.join("first.png");
    let old = dir.join("old.png");
    let out = bumpwork(&[
        "render",
        "big-sphere-squares",
        "-o",
        first.to_str().unwrap(),
        "--size",
        "16x16",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let texts = read_png_text(&first).unwrap();
    let text_of = |key: &str| texts.iter().find(|(k, _)| k == key).unwrap().1.clone();
    let recipe = text_of(RECIPE)
        .replace(bumpwork::PROGRAM, "bumpwork 0.0.1")
        .replace("[quality]", "[quality]\naffine = true");
    let framebuffer = bumpwork::raster::Framebuffer::new(16, 16, glam::Vec3::ZERO);
    bumpwork::export::write_png_with_text(
        &framebuffer,
        &old,
        &[(SCENE, text_of(SCENE)), (RECIPE, recipe)],
    )
    .unwrap();

    let out = bumpwork(&[
        "render",
        "--from",
        old.to_str().unwrap(),
        "-o",
        dir.join("again.png").to_str().unwrap(),
    ]);
    assert_user_error(&out, "unknown field `affine`");
    assert_user_error(&out, "made by bumpwork 0.0.1, this is bumpwork ");
    assert_eq!(
        leftovers(&dir, &["first.png", "old.png"]),
        Vec::<String>::new()
    );
}

/// A scene's name and the output's own name reach the .pov file only as a one-line comment and
/// as escaped string literals: neither can add a directive such as `#fopen`.
#[test]
fn names_cannot_inject_pov_ray_directives() {
    let dir = temp_dir("still-pov-injection");
    let scene = dir.join("inj.toml");
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/sphere-on-plane.toml"),
    )
    .unwrap();
    let hostile = "name = \"x\\n#fopen F \\\"pwned.txt\\\" write\\n#write (F, \\\"1\\\")\"\n";
    std::fs::write(&scene, format!("{hostile}{}", strip_name(&text))).unwrap();
    let pov = dir.join("a\" + #fopen.pov");
    let out = bumpwork(&[
        "render",
        scene.to_str().unwrap(),
        "-o",
        pov.to_str().unwrap(),
        "--format",
        "pov",
        "--tessellation",
        "4",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let sdl = std::fs::read_to_string(&pov).unwrap();
    let first = sdl.lines().next().unwrap();
    assert!(first.starts_with("// x #fopen"), "{first}");
    for line in sdl.lines().skip(1) {
        assert!(
            !line.contains("#fopen") || line.contains("png \"a\\\" + #fopen"),
            "{line}"
        );
        assert!(
            !line.trim_start().starts_with("#fopen") && !line.contains("#write"),
            "{line}"
        );
    }
}

fn strip_name(scene: &str) -> String {
    scene
        .lines()
        .filter(|l| !l.starts_with("name"))
        .map(|l| format!("{l}\n"))
        .collect()
}
