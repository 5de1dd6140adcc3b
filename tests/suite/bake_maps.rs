//! `bumpwork bake`: maps that tile where the pattern's period divides the tile, a height map and
//! a normal map (both conventions) that shade a plane as the pattern itself does, the recipe in
//! every map, and bad input told in one line.

use crate::cli_support::{assert_user_error, bumpwork, decode_png, run_ok, stderr, temp_dir};
use crate::graphics_support::psnr;
use std::path::Path;

/// The lecture's 400 × 400 plane facing the camera, with `bump` (a scene file's inline table).
fn plane_scene(bump: &str) -> String {
    format!(
        "name = \"baked\"\n\
         [camera]\neye = [0, 0, 780]\ntarget = [0, 0, 0]\nup = [0, 1, 0]\nfov = 30\n\
         [[light]]\npoint = {{ position = [-350, 350, 500], color = [0.9, 0.9, 0.9] }}\n\
         [[object]]\n\
         surface = {{ plane = {{ origin = [-200, -200, 0], normal = [0, 0, 1], u-axis = [1, 0, 0], size = [400, 400] }} }}\n\
         material = {{ color = [0.72, 0.72, 0.78] }}\nbump = {bump}\n"
    )
}

/// The plane with `bump`, rendered at 1024 × 1024 from a scene file in `dir`, 16 samples a
/// pixel: at one, a rim's pixel is all in or all out, and the test would weigh aliasing.
fn render_plane(dir: &Path, name: &str, bump: &str) -> Vec<u8> {
    let scene = dir.join(format!("{name}.toml"));
    std::fs::write(&scene, plane_scene(bump)).unwrap();
    let still = dir.join(format!("{name}.png"));
    let (scene, still_arg) = (scene.to_str().unwrap(), still.to_str().unwrap());
    let samples = "quality.samples=16";
    run_ok(&[
        "render",
        scene,
        "--size",
        "1024x1024",
        "--set",
        samples,
        "-o",
        still_arg,
    ]);
    decode_png(&still).2
}

#[test]
fn baked_height_and_normal_maps_shade_the_plane_as_the_pattern_does() {
    let dir = temp_dir("bake-proof");
    let out = dir.to_str().unwrap();
    // The dimples' rims are slope discontinuities: a height map, read through a Catmull-Rom
    // filter and its mip chain, needs about ten texels per pattern unit to draw them as sharply.
    let heights = &format!("{out}/fine");
    let said = stderr(&run_ok(&[
        "bake", "dimples", "-o", heights, "--size", "4096",
    ]));
    let strength: f32 = said
        .split("strength = ")
        .nth(1)
        .and_then(|s| s.trim().parse().ok())
        .unwrap_or_else(|| panic!("the height range is printed: {said}"));
    run_ok(&["bake", "dimples", "-o", out, "--size", "2048"]);
    let directx = ["--normal-convention", "directx"];
    let dx = &format!("{out}/dx");
    run_ok(
        &[
            &["bake", "dimples", "-o", dx, "--size", "2048"][..],
            &directx,
        ]
        .concat(),
    );
    let pattern = render_plane(&dir, "pattern", "{ pattern = \"dimples\" }");
    let height = format!("{{ image = \"fine/dimples-height.png\", strength = {strength} }}");
    let from_height = render_plane(&dir, "height", &height);
    let from_normal = render_plane(&dir, "normal", "{ normal-map = \"dimples-normal.png\" }");
    let directx = "{ normal-map = \"dx/dimples-normal.png\", convention = \"directx\" }";
    let from_directx = render_plane(&dir, "directx", directx);
    let wrong_way = "{ normal-map = \"dx/dimples-normal.png\" }";
    let read_wrong_way = render_plane(&dir, "wrong-way", wrong_way);
    let db = |picture: &[u8]| psnr(&pattern, picture);
    let (h, n, d, w) = (
        db(&from_height),
        db(&from_normal),
        db(&from_directx),
        db(&read_wrong_way),
    );
    eprintln!("height map {h:.1} dB, normal map {n:.1} dB, directx {d:.1} dB, misread {w:.1} dB");
    assert!(
        h >= 40.0,
        "the baked height map is {h:.1} dB from the pattern"
    );
    assert!(
        n >= 40.0,
        "the baked normal map is {n:.1} dB from the pattern"
    );
    assert!(
        d >= 40.0,
        "the DirectX normal map is {d:.1} dB from the pattern"
    );
    assert!(
        w < n - 5.0,
        "a DirectX map read as OpenGL should look wrong: {w:.1} dB"
    );
}

/// Whether the first and last columns (or rows) of `grey16` continue each other: the step across
/// the seam is no larger than the largest step between neighbours inside, plus one 8-bit step.
fn tiles(levels: &[u16], (width, height): (usize, usize)) -> (bool, bool) {
    let at = |x: usize, y: usize| i32::from(levels[y * width + x]);
    let eight_bit = 257;
    let inner_u = (0..height)
        .flat_map(|y| (1..width).map(move |x| (x, y)))
        .map(|(x, y)| (at(x, y) - at(x - 1, y)).abs())
        .max()
        .unwrap();
    let inner_v = (1..height)
        .flat_map(|y| (0..width).map(move |x| (x, y)))
        .map(|(x, y)| (at(x, y) - at(x, y - 1)).abs())
        .max()
        .unwrap();
    let seam_u = (0..height)
        .map(|y| (at(0, y) - at(width - 1, y)).abs())
        .max()
        .unwrap();
    let seam_v = (0..width)
        .map(|x| (at(x, 0) - at(x, height - 1)).abs())
        .max()
        .unwrap();
    (seam_u <= inner_u + eight_bit, seam_v <= inner_v + eight_bit)
}

fn grey16(path: &Path) -> (Vec<u16>, (usize, usize)) {
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
    let mut reader = decoder.read_info().unwrap();
    let info = reader.info().clone();
    assert_eq!(
        (info.color_type, info.bit_depth),
        (png::ColorType::Grayscale, png::BitDepth::Sixteen)
    );
    let mut bytes = vec![0; reader.output_buffer_size().unwrap()];
    reader.next_frame(&mut bytes).unwrap();
    let levels = bytes
        .chunks(2)
        .map(|b| u16::from_be_bytes([b[0], b[1]]))
        .collect();
    (levels, (info.width as usize, info.height as usize))
}

#[test]
fn a_period_that_divides_the_tile_bakes_seamlessly_and_the_recipe_bakes_again() {
    let dir = temp_dir("bake-tile");
    let out = dir.to_str().unwrap();
    run_ok(&[
        "bake",
        "ripples",
        "-o",
        out,
        "--size",
        "128",
        "--tile",
        "0..60,0..60",
    ]);
    run_ok(&[
        "bake", "dimples", "-o", out, "--size", "150", "--tile", "30,30",
    ]);
    let (levels, size) = grey16(&dir.join("dimples-height.png"));
    assert_eq!(
        tiles(&levels, size),
        (true, true),
        "one period of dimples tiles"
    );
    // A tile that cuts a period is not seamless: the test can tell.
    run_ok(&[
        "bake",
        "dimples",
        "-o",
        out,
        "--size",
        "150",
        "--tile",
        "0..20,0..30",
    ]);
    let (levels, size) = grey16(&dir.join("dimples-height.png"));
    assert!(
        !tiles(&levels, size).0,
        "two thirds of a period tiled along u"
    );
    // Every map carries the recipe; --from bakes the same maps again.
    let map = dir.join("dimples-normal.png");
    let texts = bumpwork::export::read_png_text(&map).unwrap();
    let recipe = &texts.iter().find(|(k, _)| k == "bumpwork-bake").unwrap().1;
    assert!(recipe.contains("source = \"dimples\""), "{recipe}");
    let first = decode_png(&map).2;
    let again = dir.join("again");
    let again_arg = again.to_str().unwrap();
    run_ok(&["bake", "--from", map.to_str().unwrap(), "-o", again_arg]);
    assert_eq!(decode_png(&again.join("dimples-normal.png")).2, first);
    let height_texts = bumpwork::export::read_png_text(&dir.join("dimples-height.png")).unwrap();
    let range = height_texts
        .iter()
        .find(|(k, _)| k == "bumpwork-height-range");
    assert!(
        range.is_some_and(|(_, v)| v.contains("..")),
        "the height map keeps its range: {height_texts:?}"
    );
}

#[test]
fn colour_patterns_bake_a_colour_map_and_bad_input_is_one_line() {
    let dir = temp_dir("bake-bad");
    let out = dir.to_str().unwrap();
    run_ok(&["bake", "checks", "-o", out, "--size", "64"]);
    assert_eq!(decode_png(&dir.join("checks-color.png")).0, 64);
    assert!(!dir.join("checks-normal.png").exists());
    assert_user_error(
        &bumpwork(&["bake", "nothere", "-o", out]),
        "unknown scene 'nothere'",
    );
    assert_user_error(
        &bumpwork(&["bake", "sphere-on-plane-dimples:3", "-o", out]),
        "the scene has 2 objects",
    );
    assert_user_error(
        &bumpwork(&["bake", "dimples", "-o", out, "--tile", "1..0,0..1"]),
        "a tile needs U0 < U1",
    );
    assert_user_error(
        &bumpwork(&["bake", "dimples", "-o", out, "--size", "0"]),
        "expected N or WIDTHxHEIGHT",
    );
    let budget = bumpwork_with_budget(&["bake", "dimples", "-o", out, "--size", "16384"], "64");
    assert_user_error(&budget, "more than the memory budget");
    let not_a_bake = dir.join("not-a-bake.png");
    std::fs::write(
        &not_a_bake,
        std::fs::read(dir.join("checks-color.png")).unwrap(),
    )
    .unwrap();
    let plain = bumpwork(&[
        "render",
        "plane-dimples",
        "--size",
        "8x8",
        "-o",
        not_a_bake.to_str().unwrap(),
    ]);
    assert!(plain.status.success());
    assert_user_error(
        &bumpwork(&["bake", "--from", not_a_bake.to_str().unwrap(), "-o", out]),
        "holds no bake recipe",
    );
}

fn bumpwork_with_budget(args: &[&str], mib: &str) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_bumpwork"))
        .args(args)
        .env("BUMPWORK_MEMORY_MIB", mib)
        .output()
        .unwrap()
}

/// A floor seen from above at an angle, lit by one point light, diffuse only, so that our
/// shading and POV-Ray's are the same Lambert term; `bump` as a scene file's inline table.
fn floor_scene(bump: &str) -> String {
    format!(
        "name = \"floor\"\nbackground = [0, 0, 0]\nambient = [0, 0, 0]\n\
         [camera]\neye = [0, 420, 300]\ntarget = [0, 0, 0]\nfov = 40\n\
         [[light]]\npoint = {{ position = [-300, 500, 200], color = [1, 1, 1] }}\n\
         [[object]]\n\
         surface = {{ plane = {{ origin = [-200, 0, 200], normal = [0, 1, 0], u-axis = [1, 0, 0], size = [400, 400] }} }}\n\
         material = {{ color = [0.8, 0.8, 0.8], specular = 0 }}\n{bump}"
    )
}

/// The `--format pov` export bakes the bump into a height map that POV-Ray reads as a
/// `bump_map`: POV-Ray's picture of the floor's dimples matches ours about as well as two
/// antialiased renders of one scene can, and far better than a floor without them would.
#[test]
#[ignore = "needs povray; bash .ci/run installs it and runs the ignored tests"]
fn pov_ray_shades_the_baked_height_map_as_we_shade_the_pattern() {
    let dir = temp_dir("bake-pov");
    let size = (320, 240);
    let render = |name: &str, bump: &str, to: &str| {
        let scene = dir.join(format!("{name}.toml"));
        std::fs::write(&scene, floor_scene(bump)).unwrap();
        let out = dir.join(format!("{name}.{to}"));
        run_ok(&[
            "render",
            scene.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
            "--size",
            "320x240",
            "--samples",
            "16",
        ]);
        out
    };
    let dimples = "bump = { pattern = \"dimples\", params = { period = 40 } }\n";
    let ours = decode_png(&render("ours", dimples, "png")).2;
    let flat = decode_png(&render("flat", "", "png")).2;
    let pov = render("theirs", dimples, "pov");
    let theirs = crate::pov_support::pov_ray(&pov, size, &["+A0.0", "+R3"]);
    let (width, height, theirs) = decode_png(&theirs);
    assert_eq!((width, height), size);
    let agreement = psnr(&ours, &theirs);
    let without_bumps = psnr(&flat, &theirs);
    assert!(
        agreement > 30.0 && agreement > without_bumps + 10.0,
        "POV-Ray's bumped floor is {agreement:.1} dB from ours, {without_bumps:.1} dB from a flat one"
    );
}
