//! Every file of Willem van Schaik's PngSuite: valid ones load with the right size and
//! pixels, broken ones (`x*.png`) fail with a clear error naming the file.

use std::path::{Path, PathBuf};

use bumpwork::texture::{Encoding, Limits, LoadedImage, Reason, Texel, check_image, load_image};

fn suite_dir() -> PathBuf {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/pngsuite");
    assert!(dir.is_dir(), "PngSuite not found at {} ", dir.display());
    dir
}

fn suite_files(broken: bool) -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(suite_dir())
        .expect("PngSuite directory is readable")
        .map(|entry| entry.expect("directory entry").path())
        .filter(|path| path.extension().is_some_and(|e| e == "png"))
        .filter(|path| file_name(path).starts_with('x') == broken)
        .collect();
    files.sort();
    files
}

fn file_name(path: &Path) -> String {
    path.file_name().unwrap().to_string_lossy().into_owned()
}

/// Raw stored values (no sRGB decoding), so 8-bit codes compare exactly.
fn load(name: &str) -> LoadedImage {
    let path = suite_dir().join(format!("{name}.png"));
    load_image(&path, &Limits::default(), Encoding::Linear).unwrap_or_else(|e| panic!("{e}"))
}

/// PngSuite files are 32×32 except the size tests `sNN…` (NN×NN) and the pHYs tests
/// `cd?n` (flat, high, square).
fn expected_size(name: &str) -> Option<(u32, u32)> {
    match &name[..name.len().min(4)] {
        "PngS" => None,
        "cdfn" => Some((8, 32)),
        "cdhn" => Some((32, 8)),
        "cdsn" => Some((8, 8)),
        _ => match name.strip_prefix('s') {
            Some(rest) => rest[..2].parse().ok().map(|side| (side, side)),
            None => Some((32, 32)),
        },
    }
}

fn close(a: Texel, b: Texel) -> bool {
    (a - b).abs().max_element() < 1e-6
}

#[test]
fn every_valid_file_loads_with_its_size() {
    let files = suite_files(false);
    assert!(files.len() > 150, "only {} valid files found", files.len());
    for path in files {
        let name = file_name(&path);
        let info = check_image(&path).unwrap_or_else(|e| panic!("{e}"));
        if let Some(size) = expected_size(&name) {
            assert_eq!((info.width, info.height), size, "{name}");
        }
    }
}

#[test]
fn every_broken_file_gives_a_clear_error() {
    let files = suite_files(true);
    assert!(files.len() >= 14, "only {} broken files found", files.len());
    for path in files {
        let name = file_name(&path);
        let error = check_image(&path).expect_err(&name);
        let message = error.to_string();
        assert!(
            message.contains(&name),
            "message must name the file: {message}"
        );
        assert!(
            matches!(
                error.reason,
                Reason::Corrupt(_) | Reason::Truncated | Reason::Unsupported(_)
            ),
            "{message}"
        );
    }
}

#[test]
fn greyscale_ramp_rows_count_up_by_one() {
    let image = load("basn0g08");
    for x in 0..32 {
        let expected = x as f32 / 255.0;
        assert!(close(
            image.texels.at(x, 0),
            Texel::new(expected, expected, expected, 1.0)
        ));
    }
    let next_row = image.texels.at(0, 1).x * 255.0;
    assert!((next_row - 32.0).abs() < 1e-3);
}

#[test]
fn sixteen_bit_colour_corners_are_yellow_green_red_blue() {
    let image = load("basn2c16");
    assert_eq!(image.info.bits_per_channel, 16);
    let corner = |x, y| image.texels.at(x, y);
    assert!(close(corner(0, 0), Texel::new(1.0, 1.0, 0.0, 1.0)));
    assert!(close(corner(31, 0), Texel::new(0.0, 1.0, 0.0, 1.0)));
    assert!(close(corner(0, 31), Texel::new(1.0, 0.0, 0.0, 1.0)));
    assert!(close(corner(31, 31), Texel::new(0.0, 0.0, 1.0, 1.0)));
}

#[test]
fn sixteen_bit_grey_keeps_more_than_eight_bits() {
    let image = load("basn0g16");
    let finer_than_8_bit = image.texels.texels().iter().any(|t| {
        let code = t.x * 65535.0;
        !(code.round() as u32).is_multiple_of(257)
    });
    assert!(finer_than_8_bit, "16-bit samples were rounded to 8 bits");
}

#[test]
fn eight_bit_colour_goes_from_white_to_black() {
    let image = load("basn2c08");
    assert!(close(image.texels.at(0, 0), Texel::ONE));
    assert!(close(
        image.texels.at(31, 31),
        Texel::new(0.0, 0.0, 0.0, 1.0)
    ));
}

#[test]
fn palette_transparency_becomes_premultiplied_alpha() {
    let image = load("tbbn3p08");
    assert!(image.info.has_alpha());
    assert_eq!(image.texels.at(0, 0), Texel::ZERO);
    assert_eq!(image.texels.at(16, 16).w, 1.0);
}

#[test]
fn srgb_decoding_darkens_mid_grey() {
    let path = suite_dir().join("basn0g08.png");
    let srgb = load_image(&path, &Limits::default(), Encoding::Srgb).unwrap();
    let raw = load("basn0g08");
    let (x, y) = (0, 4); // code 128
    assert!((raw.texels.at(x, y).x * 255.0 - 128.0).abs() < 1e-3);
    assert!((srgb.texels.at(x, y).x - 0.2158).abs() < 1e-3);
}

#[test]
fn interlaced_and_progressive_files_have_identical_pixels() {
    let mut pairs = 0;
    for path in suite_files(false) {
        let name = file_name(&path);
        let Some(progressive) = interlaced_twin(&name) else {
            continue;
        };
        let a = load(name.trim_end_matches(".png"));
        let b = load(progressive.trim_end_matches(".png"));
        assert_eq!(a.texels, b.texels, "{name} vs {progressive}");
        pairs += 1;
    }
    assert!(pairs >= 30, "only {pairs} interlaced pairs compared");
}

/// `basi0g08.png` → `basn0g08.png`, `s05i3p02.png` → `s05n3p02.png`.
fn interlaced_twin(name: &str) -> Option<String> {
    let (prefix, rest) = name.split_at(3);
    let twin = format!("{prefix}{}", rest.strip_prefix('i')?.to_owned());
    let twin = format!("{}n{}", &twin[..3], &twin[3..]);
    suite_dir().join(&twin).is_file().then_some(twin)
}
