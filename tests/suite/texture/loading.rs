//! Loading every supported format into linear texels, and the error for each way a
//! file can be bad.

use crate::test_dir::TestDir;
use std::path::{Path, PathBuf};

use bumpwork::texture::{
    Encoding, Limits, LoadedImage, Reason, Texel, TextureError, check_image, load_image,
};

/// A fresh directory for one test's files.
fn scratch_dir(test: &str) -> TestDir {
    TestDir::new(&format!("texture-{test}"))
}

fn write(dir: &Path, name: &str, bytes: &[u8]) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, bytes).expect("write test file");
    path
}

fn load_raw(path: &Path) -> Result<LoadedImage, TextureError> {
    load_image(path, &Limits::default(), Encoding::Linear)
}

fn assert_rgb(texel: Texel, rgb: [f32; 3], tolerance: f32) {
    let expected = Texel::new(rgb[0], rgb[1], rgb[2], 1.0);
    assert!(
        (texel - expected).abs().max_element() <= tolerance,
        "{texel} vs {expected}"
    );
}

#[test]
fn ascii_ppm_with_comments_and_16_bit_maxval() {
    let dir = scratch_dir("p3");
    let text = "P3\n# made by hand\n2 1 # width height\n# maxval next\n65535\n\
                0 32768 65535\n# a comment between samples\n65535 1 4660\n";
    let image = load_raw(&write(&dir, "a.ppm", text.as_bytes())).unwrap();
    assert_eq!((image.info.width, image.info.height), (2, 1));
    assert_eq!(image.info.bits_per_channel, 16);
    assert_rgb(image.texels.at(0, 0), [0.0, 32768.0 / 65535.0, 1.0], 1e-6);
    assert_rgb(
        image.texels.at(1, 0),
        [1.0, 1.0 / 65535.0, 4660.0 / 65535.0],
        1e-6,
    );
}

#[test]
fn binary_ppm_with_comment_and_16_bit_big_endian_samples() {
    let dir = scratch_dir("p6");
    let mut bytes = b"P6\n# comment\n1 2\n65535\n".to_vec();
    for sample in [0x1234u16, 0xffff, 0x0001, 0x8000, 0x0000, 0xabcd] {
        bytes.extend_from_slice(&sample.to_be_bytes());
    }
    let image = load_raw(&write(&dir, "b.ppm", &bytes)).unwrap();
    let unit = |v: u16| f32::from(v) / 65535.0;
    assert_rgb(image.texels.at(0, 0), [unit(0x1234), 1.0, unit(1)], 1e-6);
    assert_rgb(
        image.texels.at(0, 1),
        [unit(0x8000), 0.0, unit(0xabcd)],
        1e-6,
    );
}

#[test]
fn binary_ppm_8_bit_is_srgb_decoded_for_colour() {
    let dir = scratch_dir("p6-8");
    let path = write(&dir, "c.ppm", b"P6 1 1 255\n\xff\x80\x00");
    let image = load_image(&path, &Limits::default(), Encoding::Srgb).unwrap();
    assert_rgb(image.texels.at(0, 0), [1.0, 0.2158605, 0.0], 1e-5);
}

#[test]
fn grey_pgm_ascii_and_binary_with_odd_maxval() {
    let dir = scratch_dir("pgm");
    let ascii = load_raw(&write(&dir, "a.pgm", b"P2\n# c\n3 1\n1000\n0 500 1000\n")).unwrap();
    for (x, v) in [(0, 0.0), (1, 0.5), (2, 1.0)] {
        assert_rgb(ascii.texels.at(x, 0), [v; 3], 1e-4);
    }
    assert!(ascii.info.is_grey());
    let binary = load_raw(&write(&dir, "b.pgm", b"P5 2 1 15\n\x00\x0f")).unwrap();
    assert_rgb(binary.texels.at(0, 0), [0.0; 3], 1e-6);
    assert_rgb(binary.texels.at(1, 0), [1.0; 3], 1e-6);
}

/// BMP, TGA (no signature: found by extension) and JPEG, written by the image crate.
#[test]
fn bmp_tga_and_jpeg_round_trip() {
    let dir = scratch_dir("formats");
    let picture =
        image::RgbImage::from_fn(8, 4, |x, y| image::Rgb([x as u8 * 30, y as u8 * 60, 90]));
    for (extension, tolerance) in [("bmp", 1e-6), ("tga", 1e-6), ("jpg", 0.06)] {
        let path = dir.join(format!("picture.{extension}"));
        picture.save(&path).expect("encode");
        let image = load_raw(&path).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!((image.info.width, image.info.height), (8, 4), "{extension}");
        for (x, y) in [(0, 0), (7, 0), (3, 3)] {
            let [r, g, b] = picture.get_pixel(x, y).0.map(|c| f32::from(c) / 255.0);
            assert_rgb(image.texels.at(x, y), [r, g, b], tolerance);
        }
    }
}

fn reason_for(path: &Path) -> Reason {
    check_image(path).expect_err("must fail").reason
}

#[test]
fn missing_file_and_directory() {
    let dir = scratch_dir("missing");
    let missing = dir.join("nope.png");
    let error = check_image(&missing).unwrap_err();
    assert_eq!(error.reason, Reason::Missing);
    assert!(error.to_string().contains("nope.png"));
    assert!(matches!(reason_for(&dir), Reason::Unreadable(_)));
}

#[test]
fn unsupported_corrupt_truncated_and_zero_size() {
    let dir = scratch_dir("bad");
    let text = write(&dir, "notes.txt", b"just some text, not an image");
    assert!(matches!(reason_for(&text), Reason::Unsupported(_)));
    let misnamed = write(&dir, "notes.png", b"just some text, not an image");
    assert!(matches!(reason_for(&misnamed), Reason::Corrupt(_)));
    let gif = write(&dir, "anim.gif", b"GIF89a\x01\x00\x01\x00\x00\x00\x00;");
    assert!(matches!(reason_for(&gif), Reason::Unsupported(_)));

    let png = std::fs::read(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/pngsuite/basn2c08.png"),
    )
    .expect("PngSuite must sit beside the repository");
    let cut = write(&dir, "cut.png", &png[..png.len() / 2]);
    assert_eq!(reason_for(&cut), Reason::Truncated);
    let empty = write(&dir, "empty.png", b"");
    assert_eq!(reason_for(&empty), Reason::Truncated);

    let bad_digit = write(&dir, "bad.ppm", b"P3 1 1 255\n1 x 3\n");
    assert!(matches!(reason_for(&bad_digit), Reason::Corrupt(_)));
    let zero = write(&dir, "zero.pgm", b"P5 0 7 255\n");
    assert_eq!(
        reason_for(&zero),
        Reason::ZeroSize {
            width: 0,
            height: 7
        }
    );
}

#[test]
fn control_characters_in_the_name_are_escaped_in_the_message() {
    let dir = scratch_dir("names");
    let path = write(&dir, "bad\u{1b}[31mname\n.ppm", b"P6 1 1 255\n");
    let message = check_image(&path).unwrap_err().to_string();
    assert!(message.contains("bad\\e[31mname\\n.ppm"), "{message}");
    assert!(!message.chars().any(char::is_control), "{message}");
}

#[test]
fn configured_limits_reject_a_file_the_defaults_accept() {
    let dir = scratch_dir("limits");
    let path = write(&dir, "wide.pgm", b"P5 64 1 255\n");
    let path = {
        let mut bytes = std::fs::read(&path).unwrap();
        bytes.extend([0u8; 64]);
        write(&dir, "wide.pgm", &bytes)
    };
    assert!(load_raw(&path).is_ok());
    let narrow = Limits {
        max_width: 32,
        ..Limits::default()
    };
    let error = load_image(&path, &narrow, Encoding::Linear).unwrap_err();
    assert!(matches!(error.reason, Reason::Oversized { .. }), "{error}");
    let small_memory = Limits {
        max_bytes: 512,
        ..Limits::default()
    };
    let error = load_image(&path, &small_memory, Encoding::Linear).unwrap_err();
    assert!(matches!(error.reason, Reason::Oversized { .. }), "{error}");
}

#[test]
fn a_device_and_a_pipe_are_refused_without_reading() {
    let zero = Path::new("/dev/zero");
    if !zero.exists() {
        return; // not a Unix system: nothing to check
    }
    let limits = Limits {
        max_bytes: 1 << 20,
        ..Limits::default()
    };
    let error = load_image(zero, &limits, Encoding::Srgb).unwrap_err();
    assert!(error.to_string().contains("it is a device"), "{error}");

    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("endless.png");
    let made = std::process::Command::new("mkfifo").arg(&fifo).status();
    if !made.is_ok_and(|s| s.success()) {
        return; // no mkfifo: the device case above is the check
    }
    // No writer ever opens the pipe: a blocking open would wait here forever.
    let error = load_image(&fifo, &limits, Encoding::Srgb).unwrap_err();
    assert!(error.to_string().contains("named pipe"), "{error}");
}
