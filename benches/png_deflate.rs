//! PNG encoders and deflate backends on the POV-Ray peer's 1920×1080 one-sample still: the
//! png crate's settings (filter and deflate, each one-filter choice with fdeflate too) on the
//! still's rows, bumpwork's stills (the png crate's stream writer, adaptive filter and fast
//! compression, written as a still is, to a file in memory where the system has /dev/shm), and the deflate backends alone on the same rows Up-filtered:
//! fdeflate (what `Compression::Fast` uses), miniz_oxide and zlib-rs (flate2's two Rust
//! backends; this bench builds flate2 with zlib-rs, so the png crate's levels run on zlib-rs
//! here and on miniz_oxide in the program). One thread, medians of BUMPWORK_BENCH_RUNS (7)
//! runs, and the bytes each writes.
//!
//! Run: `cargo bench --bench png_deflate`.

mod bench_support;

use bench_support::{PeerStill, pov_peer_files, pov_peer_settings};
use bumpwork::export::StillFormat;
use bumpwork::measure::Timing;
use std::io::Write;

const SIZE: (u32, u32) = (1920, 1080);

fn runs() -> usize {
    bench_support::runs_or(7)
}

/// The peer's still, as 8-bit RGB rows.
fn still_rows() -> Vec<u8> {
    let temp = tempfile::tempdir().expect("a temporary directory");
    let dir = temp.path().to_path_buf();
    let (_, text, scene) = pov_peer_files(&dir);
    let out = dir.join("still.png");
    PeerStill::new(scene, text, pov_peer_settings(1, None)).write(&out, StillFormat::Png);

    image::open(&out).expect("still").to_rgb8().into_raw()
}

fn png(rows: &[u8], filter: png::Filter, deflate: png::DeflateCompression) -> Vec<u8> {
    let mut out = Vec::new();
    let mut encoder = png::Encoder::new(&mut out, SIZE.0, SIZE.1);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_filter(filter);
    encoder.set_deflate_compression(deflate);
    let mut writer = encoder.write_header().expect("header");
    writer.write_image_data(rows).expect("rows");
    writer.finish().expect("finish");
    out
}

/// PNG's Up filter on every row (a filter-type byte, then each byte less the one above).
fn up_filtered(rows: &[u8]) -> Vec<u8> {
    let stride = SIZE.0 as usize * 3;
    let mut out = Vec::with_capacity(rows.len() + SIZE.1 as usize);
    let mut above = vec![0u8; stride];
    for row in rows.chunks(stride) {
        out.push(2);
        out.extend(row.iter().zip(&above).map(|(a, b)| a.wrapping_sub(*b)));
        above.copy_from_slice(row);
    }
    out
}

fn zlib_rs(data: &[u8], level: u32) -> Vec<u8> {
    let mut encoder = flate2::write::ZlibEncoder::new(Vec::new(), flate2::Compression::new(level));
    encoder.write_all(data).expect("in memory");
    encoder.finish().expect("in memory")
}

fn main() {
    let rows = still_rows();
    println!(
        "{}x{} peer still, {} bytes of RGB; one thread, medians of {} runs",
        SIZE.0,
        SIZE.1,
        rows.len(),
        runs()
    );
    use png::{DeflateCompression as Deflate, Filter};
    let settings: [(&str, Filter, Deflate); 9] = [
        ("no compression", Filter::NoFilter, Deflate::NoCompression),
        (
            "Up + fdeflate (Fastest)",
            Filter::Up,
            Deflate::FdeflateUltraFast,
        ),
        (
            "adaptive + fdeflate (Fast)",
            Filter::Adaptive,
            Deflate::FdeflateUltraFast,
        ),
        ("Sub + fdeflate", Filter::Sub, Deflate::FdeflateUltraFast),
        ("Avg + fdeflate", Filter::Avg, Deflate::FdeflateUltraFast),
        (
            "Paeth + fdeflate",
            Filter::Paeth,
            Deflate::FdeflateUltraFast,
        ),
        ("Up + zlib-rs level 1", Filter::Up, Deflate::Level(1)),
        (
            "adaptive + zlib-rs level 1",
            Filter::Adaptive,
            Deflate::Level(1),
        ),
        (
            "adaptive + zlib-rs level 6 (Balanced)",
            Filter::Adaptive,
            Deflate::Level(6),
        ),
    ];
    println!("  png crate, whole file:");
    for (label, filter, deflate) in settings {
        let mut bytes = 0;
        let timing = Timing::measure(1, runs(), || bytes = png(&rows, filter, deflate).len());
        println!("    {label:<40} {}  {bytes:>9} B", timing.summary_ms());
    }
    // In memory where the system has it (tmpfs), as the png crate's files above are.
    let shm = std::path::Path::new("/dev/shm");
    let temp = match shm.is_dir() {
        true => tempfile::tempdir_in(shm),
        false => tempfile::tempdir(),
    };
    let temp = temp.expect("a temporary directory");
    let out = temp.path().join("still.png");
    let timing = Timing::measure(1, runs(), || {
        let mut png = bumpwork::export::PngStill::create(&out, SIZE, &[]).expect("create");
        bumpwork::still::RowSink::write_rows(&mut png, &rows).expect("rows");
        png.finish().expect("finish");
    });
    let bytes = std::fs::metadata(&out).expect("written").len();
    println!(
        "  {:<42} {}  {bytes:>9} B",
        "bumpwork's stills (a file in /dev/shm)",
        timing.summary_ms()
    );
    let filtered = up_filtered(&rows);
    type Backend = Box<dyn Fn(&[u8]) -> Vec<u8>>;
    let backends: [(&str, Backend); 5] = [
        ("fdeflate", Box::new(fdeflate::compress_to_vec)),
        (
            "miniz_oxide level 1",
            Box::new(|d| miniz_oxide::deflate::compress_to_vec_zlib(d, 1)),
        ),
        (
            "miniz_oxide level 6",
            Box::new(|d| miniz_oxide::deflate::compress_to_vec_zlib(d, 6)),
        ),
        ("zlib-rs level 1", Box::new(|d| zlib_rs(d, 1))),
        ("zlib-rs level 6", Box::new(|d| zlib_rs(d, 6))),
    ];
    println!(
        "  deflate alone, the rows Up-filtered ({} bytes):",
        filtered.len()
    );
    for (label, compress) in backends {
        let mut bytes = 0;
        let timing = Timing::measure(1, runs(), || bytes = compress(&filtered).len());
        println!("    {label:<40} {}  {bytes:>9} B", timing.summary_ms());
    }
}
