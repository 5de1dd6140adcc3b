//! One memory budget per render, held to in child processes whose address space is capped
//! (`ulimit -v`): an image bound many times is decoded once, and what would not fit is refused
//! with one line before it is allocated. (A child's peak resident size from `wait4` is no
//! measure here: Linux folds the test process's own peak into it at `exec`.)

use crate::cli_support::{TestDir, assert_user_error, bumpwork, bumpwork_bounded_with, temp_dir};
use std::ffi::OsStr;
use std::path::{Path, PathBuf};

const SECONDS: u64 = 120;

/// A `side`×`side` grey PNG (a gradient: small on disk, `side`² × 16 bytes as linear texels).
fn write_grey_png(path: &Path, side: u32) {
    let file = std::io::BufWriter::new(std::fs::File::create(path).unwrap());
    let mut encoder = png::Encoder::new(file, side, side);
    encoder.set_color(png::ColorType::Grayscale);
    let row: Vec<u8> = (0..side).map(|x| (x * 255 / side) as u8).collect();
    let pixels = row.repeat(side as usize);
    encoder
        .write_header()
        .unwrap()
        .write_image_data(&pixels)
        .unwrap();
}

/// A scene of `images.len()` small spheres in a row, each textured with its image.
fn spheres_scene(dir: &TestDir, name: &str, images: &[&str]) -> PathBuf {
    let mut text = String::from(
        "[camera]\neye = [0, 0, 60]\ntarget = [0, 0, 0]\n\n\
         [[light]]\npoint = { position = [0, 10, 60] }\n",
    );
    for (i, image) in images.iter().enumerate() {
        text += &format!(
            "\n[[object]]\nsurface.sphere = {{ center = [{}, 0, 0], radius = 1 }}\n\
             texture = {{ image = \"{image}\" }}\n",
            i as f64 * 2.5 - 50.0
        );
    }
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

/// Renders `scene` at 64×48 with `extra` arguments, `env` set and at most `cap_mib` MiB of
/// address space.
fn render_capped(
    scene: &Path,
    extra: &[&str],
    env: &[(&str, &str)],
    cap_mib: u64,
) -> std::process::Output {
    let out = scene.with_extension("png");
    let mut args = vec![
        OsStr::new("render"),
        scene.as_os_str(),
        OsStr::new("--size"),
        OsStr::new("64x48"),
        OsStr::new("-o"),
        out.as_os_str(),
    ];
    args.extend(extra.iter().map(OsStr::new));
    bumpwork_bounded_with(&args, env, cap_mib, SECONDS)
}

#[test]
fn an_image_bound_forty_times_is_decoded_once() {
    let dir = temp_dir("memory-shared-image");
    // 1500² linear texels with their mip chain: 48 MB a copy, 1.9 GB for forty.
    write_grey_png(&dir.join("a.png"), 1500);
    std::fs::copy(dir.join("a.png"), dir.join("same-bytes.png")).unwrap();
    let names: Vec<&str> = (0..40)
        .map(|i| {
            if i % 2 == 0 {
                "a.png"
            } else {
                "same-bytes.png"
            }
        })
        .collect();
    let forty = spheres_scene(&dir, "forty.toml", &names);
    // Decoded once per binding, forty copies would not fit the cap.
    let output = render_capped(&forty, &[], &[], 768);
    assert!(output.status.success(), "{output:?}");
    // Counted once too: 46 MiB of images and 20 MiB of triangles fit a 96 MiB budget.
    let output = render_capped(&forty, &[], &[("BUMPWORK_MEMORY_MIB", "96")], 768);
    assert!(output.status.success(), "{output:?}");
}

#[test]
fn triangles_over_the_budget_are_refused_before_tessellating() {
    let dir = temp_dir("memory-triangles");
    let scene = spheres_scene(&dir, "one.toml", &["brick"]);
    // Density 2048: 16.8 million triangles, about 512 MiB, refused within a 384 MiB cap.
    let budget = [("BUMPWORK_MEMORY_MIB", "64")];
    let output = render_capped(&scene, &["--tessellation", "2048"], &budget, 384);
    assert_user_error(&output, "million triangles take");
    let message = crate::cli_support::stderr(&output);
    assert!(message.contains("over the 64 MiB budget"), "{message}");
    assert!(message.contains("BUMPWORK_MEMORY_MIB"), "{message}");
    assert_eq!(message.lines().count(), 1, "{message}");
    assert!(!scene.with_extension("png").exists(), "nothing is written");
    // The same render fits a budget that holds it.
    let output = render_capped(&scene, &["--tessellation", "256"], &budget, 384);
    assert!(output.status.success(), "{output:?}");
}

#[test]
fn shadow_maps_over_the_budget_are_refused_before_any_is_drawn() {
    let dir = temp_dir("memory-shadow-maps");
    let scene = spheres_scene(&dir, "two.toml", &["brick", "brick"]);
    // An 8192² map of 4-byte depths for the one light: 256 MiB, refused by a 64 MiB budget
    // within a 384 MiB cap.
    // (Filtered edges: with exact ones, spheres and planes are shadowed by rays alone.)
    let budget = [("BUMPWORK_MEMORY_MIB", "64")];
    let filtered = ["--set", "quality.shadow-edges=filtered"];
    let huge = [&["--set", "quality.shadow-map=8192"][..], &filtered].concat();
    let output = render_capped(&scene, &huge, &budget, 384);
    assert_user_error(&output, "shadow maps take");
    assert!(!scene.with_extension("png").exists(), "nothing is written");
    // Without shadows, or with rays alone, no map is drawn, so nothing is counted.
    let off = [&huge[..], &["--set", "shadows=false"]].concat();
    let output = render_capped(&scene, &off, &budget, 384);
    assert!(output.status.success(), "{output:?}");
    let by_rays = ["--set", "quality.shadow-map=8192"];
    let output = render_capped(&scene, &by_rays, &budget, 384);
    assert!(output.status.success(), "{output:?}");
}

#[test]
fn a_scene_file_of_thousands_of_spheres_is_refused_by_the_default_budget() {
    let dir = temp_dir("memory-many-objects");
    let mut text = String::from("[camera]\neye = [0, 0, 300]\ntarget = [0, 0, 0]\n");
    let mut i = 0;
    while text.len() < 1_000_000 {
        text += &format!(
            "[[object]]\nsurface.sphere={{center=[{},{},0],radius=1}}\n",
            i % 100,
            i / 100
        );
        i += 1;
    }
    let scene = dir.join("many.toml");
    std::fs::write(&scene, text).unwrap();
    // 18 000 spheres at density 64: 300 million triangles, 9 GiB, over the default 4 GiB.
    let output = render_capped(&scene, &[], &[], 512);
    assert_user_error(&output, "million triangles take");
}

#[test]
fn images_share_the_budget_and_are_refused_from_their_header() {
    let dir = temp_dir("memory-images");
    write_grey_png(&dir.join("a.png"), 1500);
    let scene = spheres_scene(&dir, "one.toml", &["a.png"]);
    let output = render_capped(&scene, &[], &[("BUMPWORK_MEMORY_MIB", "32")], 384);
    assert_user_error(&output, "a.png: image too large: 1500×1500 needs about");
    let message = crate::cli_support::stderr(&output);
    assert!(message.contains("BUMPWORK_MEMORY_MIB"), "{message}");
}

#[test]
fn a_contact_sheet_past_the_size_limit_is_refused_before_any_still() {
    let dir = temp_dir("memory-sheet");
    let gallery = dir.join("gallery");
    let output = bumpwork(&[
        "gallery",
        "-o",
        gallery.to_str().unwrap(),
        "--thumbnail",
        "16384x16384",
        "--columns",
        "10",
    ]);
    assert_user_error(&output, "over the 16384×16384 limit");
    assert!(
        !gallery.exists(),
        "nothing is made for a gallery that cannot be finished"
    );
}

#[test]
fn a_gallery_whose_sheet_and_still_would_not_fit_is_refused_before_any_still() {
    let dir = temp_dir("memory-sheet-budget");
    let gallery = dir.join("gallery");
    let args = [
        "gallery",
        "-o",
        gallery.to_str().unwrap(),
        "--size",
        "2048x2048",
        "--scenes",
        "plane-dimples",
    ]
    .map(OsStr::new);
    // A 2048² still read back as RGB and RGBA alone takes 28 MiB.
    let output = bumpwork_bounded_with(&args, &[("BUMPWORK_MEMORY_MIB", "16")], 384, SECONDS);
    assert_user_error(&output, "the contact sheet and a still read back onto it");
    assert!(!gallery.exists());
}
