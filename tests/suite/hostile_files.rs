//! Hostile files through the command line as a user meets them: names, contents and error
//! messages holding terminal escapes and control characters are shown escaped; huge, endless,
//! deeply nested and lying files give one clear error quickly with bounded memory.
//! (Library-level cousins: `pattern_errors` (10⁶ nested parentheses), `texture_limits` (lying
//! PNG and PPM headers allocate nothing), `fuzz_regressions`.)

use crate::cli_support::{
    assert_user_error, bumpwork, bumpwork_bounded, raw_control, stderr, temp_dir,
};
use std::ffi::{OsStr, OsString};
use std::os::unix::ffi::{OsStrExt, OsStringExt};
use std::path::{Path, PathBuf};
use std::process::Output;

/// Address space the binary may use for a hostile file: far less than the files claim.
const MEMORY_MIB: u64 = 384;
/// Generous: each of these answers in well under a second.
const SECONDS: u64 = 60;

fn run(args: &[&OsStr]) -> Output {
    bumpwork_bounded(args, MEMORY_MIB, SECONDS)
}

/// Status 1, no panic, and nothing on stderr that could steer the terminal.
fn assert_clean_error(output: &Output, expected: &str) {
    assert_user_error(output, expected);
    assert_eq!(
        raw_control(&output.stderr),
        None,
        "raw control character in: {}",
        stderr(output)
    );
}

/// The camera and light every scene file needs, before its objects.
const SCENE_HEAD: &str = "[camera]\neye = [0, 0, 500]\ntarget = [0, 0, 0]\n\
                          [[light]]\npoint = { position = [0, 500, 500] }\n";

/// A scene of one sphere with the given bump binding (TOML inline table).
fn sphere_scene(bump: &str) -> String {
    format!(
        "{SCENE_HEAD}[[object]]\nsurface = {{ sphere = {{ center = [0, 0, 0], radius = 100 }} }}\n\
         bump = {bump}\n"
    )
}

fn write(dir: &Path, name: impl Into<OsString>, content: &[u8]) -> PathBuf {
    let path = dir.join(name.into());
    std::fs::write(&path, content).unwrap();
    path
}

#[test]
fn escapes_in_names_and_contents_are_shown_escaped() {
    let dir = temp_dir("hostile-names");
    let cases: Vec<(PathBuf, &str)> = vec![
        // Set the window title, then ring the bell.
        (
            write(&dir, "title\x1b]0;pwned\x07.pat", b"height = u +\n"),
            "title\\e]0;pwned\\x07.pat:2:1: expected an expression",
        ),
        // Clear the screen from inside the pattern text.
        (
            write(&dir, "clear.pat", b"height = u \x1b[2J\x1b[31m\n"),
            "\\e[2J",
        ),
        (
            write(&dir, "line\nbreak\r\x08.toml", b"[camera\n"),
            "line\\nbreak\\r\\x08.toml",
        ),
        // A C1 CSI (U+009B) in the name and, decoded from a TOML escape, in a key.
        (
            write(
                &dir,
                "c1\u{9b}31m.toml",
                b"[camera]\neye = [0, 1, 2]\ntarget = [0, 0, 0]\n\"\\u001b]0;x\\u0007\" = 1\n",
            ),
            "c1\\u{9b}31m.toml",
        ),
        // A name that is not UTF-8 at all (a raw 0x9b byte).
        (
            write(
                &dir,
                OsString::from_vec(b"raw\x9b2J.pat".to_vec()),
                b"height = (\n",
            ),
            "error",
        ),
        // An image that is not one.
        (
            write(&dir, "bell\x07\x1b[5m.png", b"\x1b[2Jnot a png"),
            "bell\\x07\\e[5m.png",
        ),
    ];
    let scene_naming_a_hostile_pattern = write(
        &dir,
        "names.toml",
        sphere_scene(r#"{ pattern = "\u001b[2J\u009b31m" }"#).as_bytes(),
    );
    for (path, expected) in &cases {
        for args in [
            vec![OsStr::new("check"), path.as_os_str()],
            vec![
                OsStr::new("render"),
                path.as_os_str(),
                OsStr::new("-o"),
                dir.join("out.png").as_os_str(),
            ],
        ] {
            assert_clean_error(&run(&args), expected);
        }
    }
    let output = run(&[
        OsStr::new("check"),
        scene_naming_a_hostile_pattern.as_os_str(),
    ]);
    assert_clean_error(&output, "\\e[2J");
    assert!(!dir.join("out.png").exists());
}

#[test]
fn escapes_in_arguments_are_shown_escaped() {
    for args in [
        &[
            "render",
            "plane-dimples",
            "-o",
            "x.png",
            "--size",
            "\x1b[31m9x9",
        ][..],
        &["render", "\x1b]0;pwned\x07", "-o", "x.png"],
        &["render", "plane-dimples", "--frobnicate\x1b[2J"],
        &["render", "plane-dimples", "-o", "/nonexistent\x1b[2J/x.png"],
        &["render", "--from", "\x1b[2J.png", "-o", "x.png"],
        &["view", "--colors", "\u{9b}0m"],
    ] {
        let output = bumpwork(args);
        assert_ne!(output.status.code(), Some(0), "{args:?}");
        assert_eq!(
            raw_control(&output.stderr),
            None,
            "{args:?}: {}",
            stderr(&output)
        );
        assert!(!stderr(&output).contains("panicked"), "{}", stderr(&output));
    }
}

#[test]
fn a_one_gigabyte_file_is_refused_by_its_size() {
    let dir = temp_dir("hostile-huge");
    for name in ["huge.pat", "huge.toml", "huge.png"] {
        let path = dir.join(name);
        // Sparse: a gigabyte long, nothing written.
        std::fs::File::create(&path)
            .unwrap()
            .set_len(1 << 30)
            .unwrap();
        let output = run(&[OsStr::new("check"), path.as_os_str()]);
        assert_clean_error(&output, name);
        let message = stderr(&output);
        assert!(
            message.contains("limit") || message.contains("too large"),
            "{name}: {message}"
        );
    }
}

#[test]
fn devices_are_not_read_forever() {
    let dir = temp_dir("hostile-devices");
    for name in ["zero.pat", "zero.toml", "zero.png"] {
        let link = dir.join(name);
        std::os::unix::fs::symlink("/dev/zero", &link).unwrap();
        assert_clean_error(&run(&[OsStr::new("check"), link.as_os_str()]), name);
    }
    let scene = write(
        &dir,
        "scene.toml",
        sphere_scene(r#"{ image = "/dev/zero" }"#).as_bytes(),
    );
    let output = run(&[OsStr::new("check"), scene.as_os_str()]);
    assert_clean_error(&output, "/dev/zero: cannot read the file: it is a device");
}

#[test]
fn a_million_nested_brackets_in_a_scene_is_an_error_not_a_crash() {
    let dir = temp_dir("hostile-nesting");
    for (name, text) in [
        ("arrays.toml", format!("eye = {}", "[".repeat(1_000_000))),
        ("tables.toml", format!("eye = {}", "{a = ".repeat(200_000))),
        ("parens.pat", format!("height = {}u", "(".repeat(1_000_000))),
    ] {
        let path = write(&dir, name, text.as_bytes());
        let output = run(&[OsStr::new("check"), path.as_os_str()]);
        assert_clean_error(&output, name);
        // The offending line is shown as a window, not a megabyte of brackets.
        assert!(output.stderr.len() < 2048, "{} bytes", output.stderr.len());
    }
}

#[test]
fn image_headers_that_lie_about_their_size_are_refused() {
    let dir = temp_dir("hostile-headers");
    let bmp = {
        let mut header = b"BM".to_vec();
        header.extend(70u32.to_le_bytes()); // file size
        header.extend([0; 4]);
        header.extend(54u32.to_le_bytes()); // pixel offset
        header.extend(40u32.to_le_bytes()); // info header size
        header.extend(30_000i32.to_le_bytes()); // width
        header.extend(30_000i32.to_le_bytes()); // height
        header.extend(1u16.to_le_bytes());
        header.extend(24u16.to_le_bytes());
        header.extend([0; 24]);
        header.extend([0; 16]); // a few pixels, nowhere near 10¹⁰
        header
    };
    let tga = {
        let mut header = vec![0, 0, 2];
        header.extend([0; 9]);
        header.extend(65_535u16.to_le_bytes());
        header.extend(65_535u16.to_le_bytes());
        header.extend([24, 0]);
        header.extend([0; 12]);
        header
    };
    let cases: [(&str, &[u8], &str); 4] = [
        ("huge.bmp", &bmp, "30000×30000 exceeds"),
        ("huge.tga", &tga, "65535×65535"),
        ("huge.ppm", b"P6 99999999 99999999 255\n\0\0\0", "limit"),
        // Plausible dimensions, but 3 bytes where 12 MB were promised.
        ("short.ppm", b"P6 2000 2000 255\n\0\0\0", "short.ppm"),
    ];
    for (name, bytes, expected) in cases {
        let path = write(&dir, name, bytes);
        assert_clean_error(&run(&[OsStr::new("check"), path.as_os_str()]), expected);
    }
}

/// A still's recipe is anyone's text: one naming `/dev/zero` as a file to hash must not hang
/// `render --from` (it did, reading zeros forever).
#[test]
fn a_recipe_naming_a_device_does_not_hang_render_from() {
    let dir = temp_dir("hostile-recipe");
    write(&dir, "p.pat", b"height = sin(u / 10)\n");
    let scene = write(
        &dir,
        "s.toml",
        sphere_scene(r#"{ pattern = "p.pat" }"#).as_bytes(),
    );
    let still = dir.join("still.png");
    let output = bumpwork(&[
        "render",
        scene.to_str().unwrap(),
        "-o",
        still.to_str().unwrap(),
        "--size",
        "8x8",
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let pattern_path = dir.join("p.pat").canonicalize().unwrap();
    // Only the list of hashed files: the scene still reads the real pattern.
    let hashed = format!("path = \"{}\"", pattern_path.display());
    doctored(&still, &dir.join("doctored.png"), |_, text| {
        text.replace(&hashed, "path = \"/dev/zero\"")
    });
    let doctored = dir.join("doctored.png");
    let again = dir.join("again.png");
    let output = run(&[
        OsStr::new("render"),
        OsStr::new("--from"),
        doctored.as_os_str(),
        OsStr::new("-o"),
        again.as_os_str(),
    ]);
    let message = stderr(&output);
    assert!(output.status.success(), "{message}");
    assert!(
        message.contains("/dev/zero cannot be read"),
        "warns: {message}"
    );
    assert!(again.exists());
}

/// Raw 0x9b bytes in a name that is not UTF-8 are shown as a replacement character.
#[test]
fn a_name_that_is_not_utf8_is_shown_lossily() {
    let dir = temp_dir("hostile-bytes");
    let path = write(&dir, OsStr::from_bytes(b"x\x9b\x1b.pat"), b"height = $\n");
    let output = run(&[OsStr::new("check"), path.as_os_str()]);
    assert_clean_error(&output, "x\u{fffd}\\e.pat");
}

/// The one limit a user sets: the memory a render may take (`BUMPWORK_MEMORY_MIB`).
#[test]
fn the_memory_budget_is_the_users_to_set_and_checked() {
    let brick = Path::new(env!("CARGO_MANIFEST_DIR")).join("textures/brick.png");
    let with_budget = |value: &str| {
        std::process::Command::new(env!("CARGO_BIN_EXE_bumpwork"))
            .arg("check")
            .arg(&brick)
            .env("BUMPWORK_MEMORY_MIB", value)
            .output()
            .unwrap()
    };
    assert!(with_budget("512").status.success());
    // The shipped brick (decoded, in linear texels, with its mip chain) needs more than 1 MiB.
    assert_clean_error(&with_budget("1"), "over the 1 MiB of the memory budget");
    for bad in ["0", "lots", "-5", "\x1b[2J"] {
        assert_clean_error(
            &with_budget(bad),
            "BUMPWORK_MEMORY_MIB must be a whole number",
        );
    }
}

#[test]
fn fifos_are_refused_at_once_wherever_they_are_named() {
    let dir = temp_dir("hostile-fifos");
    for name in ["p.pat", "s.toml", "i.png"] {
        crate::cli_support::make_fifo(&dir.join(name));
    }
    let scene = write(
        &dir,
        "binds.toml",
        sphere_scene(&format!(
            "{{ image = \"{}\" }}",
            dir.join("i.png").display()
        ))
        .as_bytes(),
    );
    let out = dir.join("out.png");
    let (pattern, scene_fifo) = (dir.join("p.pat"), dir.join("s.toml"));
    let cases: [Vec<&OsStr>; 5] = [
        vec!["check".as_ref(), pattern.as_os_str()],
        vec![
            "render".as_ref(),
            pattern.as_os_str(),
            "-o".as_ref(),
            out.as_os_str(),
        ],
        vec!["check".as_ref(), scene_fifo.as_os_str()],
        vec![
            "render".as_ref(),
            scene_fifo.as_os_str(),
            "-o".as_ref(),
            out.as_os_str(),
        ],
        vec![
            "render".as_ref(),
            scene.as_os_str(),
            "-o".as_ref(),
            out.as_os_str(),
        ],
    ];
    for args in cases {
        // No writer ever opens these pipes: a blocking open would hang until the time-out.
        assert_clean_error(&run(&args), "named pipe (FIFO), not a regular file");
        assert!(!out.exists(), "{args:?} left a still");
    }
}

/// A copy of `still` whose text chunks went through `edit` (compressed iTXt, as stills carry).
fn doctored(still: &Path, out: &Path, edit: impl Fn(&str, &str) -> String) {
    let texts = bumpwork::export::metadata::read_png_text(still).unwrap();
    let mut encoder = png::Encoder::new(std::fs::File::create(out).unwrap(), 1, 1);
    encoder.set_color(png::ColorType::Rgb);
    for (keyword, text) in &texts {
        encoder
            .add_itxt_chunk(keyword.clone(), edit(keyword, text))
            .unwrap();
    }
    let mut writer = encoder.write_header().unwrap();
    writer.write_image_data(&[0, 0, 0]).unwrap();
    writer.finish().unwrap();
}

fn render_from(still: &Path, extra: &[&str]) -> Output {
    let again = still.with_file_name("again.png");
    let mut args = vec![
        OsStr::new("render"),
        OsStr::new("--from"),
        still.as_os_str(),
        OsStr::new("-o"),
        again.as_os_str(),
    ];
    args.extend(extra.iter().map(OsStr::new));
    run(&args)
}

#[test]
fn a_crafted_still_reads_nothing_outside_its_directory_and_bad_values_are_refused() {
    let dir = temp_dir("hostile-recipe");
    let still = dir.join("still.png");
    let output = bumpwork(&[
        "render",
        "plane-dimples",
        "--size",
        "8x8",
        "-o",
        still.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));

    // The scene text names a file outside the still's directory as its bump pattern.
    let outside = temp_dir("hostile-recipe-outside");
    let secret = write(&outside, "secret.pat", b"TOP SECRET first line\n");
    let reads_secret = dir.join("reads-secret.png");
    doctored(&still, &reads_secret, |_, text| {
        let named = format!("pattern = \"{}\"", secret.display());
        text.replace("pattern = \"dimples-seed\"", &named)
    });
    let refused = render_from(&reads_secret, &[]);
    assert_clean_error(&refused, "outside its directory");
    assert!(
        !stderr(&refused).contains("TOP SECRET"),
        "{}",
        stderr(&refused)
    );
    let allowed = render_from(&reads_secret, &["--read-outside"]);
    assert!(
        stderr(&allowed).contains("secret.pat"),
        "{}",
        stderr(&allowed)
    );

    // Values a scene file refuses are refused in a recipe too.
    let cases = [
        ("up = [", "up = [0.0, 0.0, 0.0]\n#", "a direction"),
        ("fov = ", "fov = 0.0\n#", "an angle in degrees"),
        ("near = ", "near = 1e-45\n#", "the camera's near"),
        ("time = ", "time = 1e300\n#", "time 1e300 is outside"),
    ];
    for (key, replacement, expected) in cases {
        let bad = dir.join("bad.png");
        doctored(&still, &bad, |keyword, text| {
            if keyword != "bumpwork-recipe" {
                return text.to_string();
            }
            text.lines()
                .map(|l| {
                    if l.starts_with(key) {
                        format!("{replacement}{l}")
                    } else {
                        l.to_string()
                    }
                })
                .collect::<Vec<_>>()
                .join("\n")
        });
        assert_clean_error(&render_from(&bad, &[]), expected);
    }
}

/// A few kilobytes of compressed recipe that would inflate to 16 MiB: refused at the scene
/// file's limit, within a small memory cap.
#[test]
fn a_compressed_recipe_bomb_is_refused_at_the_limit() {
    use png::text_metadata::ITXtChunk;
    let dir = temp_dir("hostile-bomb");
    let bomb = dir.join("bomb.png");
    let mut encoder = png::Encoder::new(std::fs::File::create(&bomb).unwrap(), 1, 1);
    encoder.set_color(png::ColorType::Rgb);
    let mut writer = encoder.write_header().unwrap();
    let mut chunk = ITXtChunk::new("bumpwork-recipe", "#".repeat(16 << 20));
    chunk.compressed = true;
    writer.write_text_chunk(&chunk).unwrap();
    writer.write_image_data(&[0, 0, 0]).unwrap();
    writer.finish().unwrap();
    let size = std::fs::metadata(&bomb).unwrap().len();
    assert!(size < 256 << 10, "{size} bytes");
    assert_clean_error(&render_from(&bomb, &[]), "longer than the limit of 1 MiB");
}

/// A recipe's relative names are read beside the still, whatever directory its `source` claims;
/// `--read-outside` reads them where the scene was.
#[test]
fn a_stills_relative_names_are_read_from_its_own_directory() {
    let made_in = temp_dir("hostile-recipe-made-in");
    let moved_to = temp_dir("hostile-recipe-moved-to");
    std::fs::write(made_in.join("bumps.pat"), "height = 0\n").unwrap();
    let scene = write(
        &made_in,
        "scene.toml",
        sphere_scene("{ pattern = \"bumps.pat\" }").as_bytes(),
    );
    let still = moved_to.join("still.png");
    let output = bumpwork(&[
        "render",
        scene.to_str().unwrap(),
        "--size",
        "8x8",
        "-o",
        still.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    // Nothing beside the still: the name is looked for there, not where the recipe says.
    let output = render_from(&still, &[]);
    assert_clean_error(&output, "bumps.pat");
    let beside = moved_to.join("bumps.pat").display().to_string();
    assert!(stderr(&output).contains(&beside), "{}", stderr(&output));
    // A pattern beside the still is the one read.
    std::fs::write(moved_to.join("bumps.pat"), "height = 0.5 * u\n").unwrap();
    let output = render_from(&still, &[]);
    assert!(output.status.success(), "{}", stderr(&output));
    // With --read-outside, the file where the scene was.
    std::fs::remove_file(moved_to.join("bumps.pat")).unwrap();
    let output = render_from(&still, &["--read-outside"]);
    assert!(output.status.success(), "{}", stderr(&output));
}
