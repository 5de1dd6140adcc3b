//! Decoders for what the workbench sends as pixels: kitty graphics payloads and sixel images,
//! back to RGB, to compare with what was rendered.

use base64::Engine;
use std::io::Read;

/// An RGB picture, 3 bytes a pixel.
#[derive(Clone, Debug, PartialEq)]
pub struct Rgb {
    pub width: usize,
    pub height: usize,
    pub pixels: Vec<u8>,
}

/// Every kitty image transmitted in `bytes` (`a=T`, chunked, zlib, 24-bit), in order.
pub fn kitty_images(bytes: &[u8]) -> Vec<Rgb> {
    let text = String::from_utf8_lossy(bytes);
    let mut images = Vec::new();
    let mut current: Option<(usize, usize, String)> = None;
    for command in text.split("\x1b_G").skip(1) {
        // A command still being written is left for the next look.
        let Some((command, _)) = command.split_once("\x1b\\") else {
            break;
        };
        let (keys, payload) = command.split_once(';').unwrap_or((command, ""));
        let key = |name: &str| {
            keys.split(',')
                .find_map(|kv| kv.strip_prefix(&format!("{name}=")))
                .map(str::to_string)
        };
        if key("a").as_deref() == Some("T") {
            let number = |name| key(name).unwrap().parse::<usize>().unwrap();
            assert_eq!(key("f").as_deref(), Some("24"));
            assert_eq!(key("o").as_deref(), Some("z"));
            current = Some((number("s"), number("v"), String::new()));
        }
        if let Some((_, _, data)) = &mut current {
            assert!(payload.len() <= 4096, "a chunk of {} bytes", payload.len());
            data.push_str(payload);
        }
        if key("m").as_deref() == Some("0")
            && let Some((width, height, data)) = current.take()
        {
            let compressed = base64::engine::general_purpose::STANDARD
                .decode(data)
                .unwrap();
            let mut pixels = Vec::new();
            flate2::read::ZlibDecoder::new(&compressed[..])
                .read_to_end(&mut pixels)
                .unwrap();
            assert_eq!(pixels.len(), width * height * 3);
            images.push(Rgb {
                width,
                height,
                pixels,
            });
        }
    }
    images
}

/// Every whole sixel image in `bytes`, decoded (colour registers in percent, raster attributes
/// for the size, `!` repeats, `$` and `-`); one still being written is left out.
pub fn sixel_images(bytes: &[u8]) -> Vec<Rgb> {
    let mut images = Vec::new();
    let mut rest = bytes;
    while let Some(start) = find(rest, b"\x1bP") {
        let body = &rest[start + 2..];
        let Some(end) = find(body, b"\x1b\\") else {
            break;
        };
        if let Some(q) = body[..end].iter().position(|&b| b == b'q') {
            images.push(decode_sixel(&body[q + 1..end]));
        }
        rest = &body[end..];
    }
    images
}

fn find(haystack: &[u8], needle: &[u8]) -> Option<usize> {
    haystack.windows(needle.len()).position(|w| w == needle)
}

fn decode_sixel(data: &[u8]) -> Rgb {
    let mut palette = vec![[0u8; 3]; 256];
    let (mut width, mut height) = (0, 0);
    let mut pixels = Vec::new();
    let (mut x, mut band, mut colour) = (0usize, 0usize, 0usize);
    let mut i = 0;
    let number = |i: &mut usize| {
        let start = *i;
        while *i < data.len() && data[*i].is_ascii_digit() {
            *i += 1;
        }
        std::str::from_utf8(&data[start..*i])
            .unwrap()
            .parse::<usize>()
            .unwrap_or(0)
    };
    let numbers = |i: &mut usize| {
        let mut list = vec![number(i)];
        while *i < data.len() && data[*i] == b';' {
            *i += 1;
            list.push(number(i));
        }
        list
    };
    while i < data.len() {
        match data[i] {
            b'"' => {
                i += 1;
                let attributes = numbers(&mut i);
                (width, height) = (attributes[2], attributes[3]);
                pixels = vec![0u8; width * height * 3];
            }
            b'#' => {
                i += 1;
                let register = numbers(&mut i);
                colour = register[0];
                if register.len() == 5 {
                    assert_eq!(register[1], 2, "RGB colour registers");
                    let level = |p: usize| ((p * 255 + 50) / 100) as u8;
                    palette[colour] = [level(register[2]), level(register[3]), level(register[4])];
                }
            }
            b'!' => {
                i += 1;
                let count = number(&mut i);
                let sixel = data[i];
                i += 1;
                for _ in 0..count {
                    put(&mut pixels, width, height, x, band, sixel, palette[colour]);
                    x += 1;
                }
            }
            b'$' => {
                x = 0;
                i += 1;
            }
            b'-' => {
                x = 0;
                band += 1;
                i += 1;
            }
            sixel @ b'?'..=b'~' => {
                put(&mut pixels, width, height, x, band, sixel, palette[colour]);
                x += 1;
                i += 1;
            }
            _ => i += 1,
        }
    }
    Rgb {
        width,
        height,
        pixels,
    }
}

fn put(
    pixels: &mut [u8],
    width: usize,
    height: usize,
    x: usize,
    band: usize,
    sixel: u8,
    rgb: [u8; 3],
) {
    let bits = sixel - b'?';
    for row in 0..6 {
        let y = band * 6 + row;
        if bits >> row & 1 == 1 && x < width && y < height {
            let at = (y * width + x) * 3;
            pixels[at..at + 3].copy_from_slice(&rgb);
        }
    }
}

/// PSNR of `b` against `a`, in dB (infinite when equal).
pub fn psnr(a: &[u8], b: &[u8]) -> f64 {
    assert_eq!(a.len(), b.len());
    let mse = a
        .iter()
        .zip(b)
        .map(|(&x, &y)| (f64::from(x) - f64::from(y)).powi(2))
        .sum::<f64>()
        / a.len() as f64;
    10.0 * (255.0f64.powi(2) / mse).log10()
}

/// A still of `scene`'s own view at `size`, 64 samples box-filtered: what a settled picture of
/// that size should show.
pub fn settled_still(scene: &str, (width, height): (usize, usize)) -> Vec<u8> {
    let dir = crate::cli_support::temp_dir("settled-still");
    let path = dir.join("still.png");
    let size = format!("{width}x{height}");
    let output = crate::cli_support::bumpwork(&[
        "render",
        scene,
        "--size",
        &size,
        "--samples",
        "64",
        "--filter",
        "box",
        "-o",
        path.to_str().unwrap(),
    ]);
    assert!(
        output.status.success(),
        "{}",
        crate::cli_support::stderr(&output)
    );
    crate::cli_support::decode_png(&path).2
}
