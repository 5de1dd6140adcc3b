//! Never panic on any input: thousands of deterministic mutations (flipped bytes,
//! truncations, splices) of valid files in every supported format must each give an
//! image or an error, and any error must name the file.

use std::io::Cursor;
use std::panic;
use std::path::Path;

use bumpwork::texture::{Encoding, Limits, Reason, decode_image};

struct Numbers(u64);

impl Numbers {
    fn below(&mut self, n: usize) -> usize {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 % n.max(1) as u64) as usize
    }
}

fn encoded(format: image::ImageFormat) -> Vec<u8> {
    let picture = image::RgbaImage::from_fn(9, 7, |x, y| {
        image::Rgba([x as u8 * 25, y as u8 * 30, 77, 200])
    });
    let picture = image::DynamicImage::ImageRgba8(picture);
    let picture = match format {
        image::ImageFormat::Jpeg | image::ImageFormat::Pnm => {
            image::DynamicImage::ImageRgb8(picture.to_rgb8())
        }
        _ => picture,
    };
    let mut bytes = Vec::new();
    picture
        .write_to(&mut Cursor::new(&mut bytes), format)
        .expect("encode");
    bytes
}

fn seeds() -> Vec<(&'static str, Vec<u8>)> {
    let suite = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/pngsuite");
    let png = |name: &str| {
        std::fs::read(suite.join(name)).expect("PngSuite must sit beside the repository")
    };
    vec![
        ("seed.png", png("basn2c08.png")),
        ("seed-interlaced.png", png("basi3p02.png")),
        ("seed-16.png", png("basn6a16.png")),
        ("seed.jpg", encoded(image::ImageFormat::Jpeg)),
        ("seed.bmp", encoded(image::ImageFormat::Bmp)),
        ("seed.tga", encoded(image::ImageFormat::Tga)),
        ("seed.ppm", encoded(image::ImageFormat::Pnm)),
        (
            "seed-ascii.ppm",
            b"P3\n# c\n3 2\n255\n1 2 3 4 5 6 7 8 9\n10 11 12 13 14 15 16 17 18\n".to_vec(),
        ),
    ]
}

fn mutate(bytes: &[u8], numbers: &mut Numbers) -> Vec<u8> {
    let mut out = bytes.to_vec();
    match numbers.below(4) {
        0 => {
            for _ in 0..=numbers.below(4) {
                let at = numbers.below(out.len());
                out[at] = numbers.below(256) as u8;
            }
        }
        1 => out.truncate(numbers.below(bytes.len())),
        2 => {
            // Header fields (sizes, depths) live near the start: hit them hardest.
            let at = numbers.below(out.len().min(40));
            out[at] ^= 1 << numbers.below(8);
        }
        _ => {
            let at = numbers.below(out.len());
            let junk: Vec<u8> = (0..numbers.below(64))
                .map(|_| numbers.below(256) as u8)
                .collect();
            out.splice(at..at, junk);
        }
    }
    out
}

#[test]
fn mutated_files_never_panic() {
    let limits = Limits {
        max_bytes: 32 << 20,
        ..Limits::default()
    };
    let mut numbers = Numbers(0x5eed);
    let (mut loaded, mut refused, mut backstopped) = (0, 0, 0);
    for (name, seed) in seeds() {
        decode_image(&seed, Path::new(name), &limits, Encoding::Srgb)
            .unwrap_or_else(|e| panic!("unmutated seed must load: {e}"));
        for _ in 0..400 {
            let bytes = mutate(&seed, &mut numbers);
            let outcome = panic::catch_unwind(|| {
                decode_image(&bytes, Path::new(name), &limits, Encoding::Srgb)
            });
            match outcome
                .unwrap_or_else(|_| panic!("panic escaped on a mutation of {name}: {bytes:?}"))
            {
                Ok(image) => {
                    assert!(image.texels.texels().iter().all(|t| t.is_finite()));
                    loaded += 1;
                }
                Err(error) => {
                    assert!(error.to_string().starts_with(name), "{error}");
                    if error.reason == Reason::Corrupt("the decoder failed on this data".into()) {
                        backstopped += 1;
                    }
                    refused += 1;
                }
            }
        }
    }
    eprintln!(
        "{loaded} mutations loaded, {refused} refused, {backstopped} of them by the panic backstop"
    );
    assert!(
        refused > 100 && loaded > 100,
        "mutations too mild or too harsh to test anything"
    );
}
