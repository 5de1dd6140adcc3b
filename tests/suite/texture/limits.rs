//! A small file that claims a huge image is refused from its header, before any
//! large allocation. A counting allocator records the largest single allocation.

use std::alloc::{GlobalAlloc, Layout, System};
use std::path::Path;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

use bumpwork::texture::{Encoding, Limits, Reason, decode_image};

struct LargestAllocation;

static LARGEST: AtomicUsize = AtomicUsize::new(0);
/// Tests in this file run one at a time so each sees only its own allocations.
static SERIAL: Mutex<()> = Mutex::new(());

// SAFETY: forwards to the system allocator unchanged; only records the size.
unsafe impl GlobalAlloc for LargestAllocation {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        LARGEST.fetch_max(layout.size(), Ordering::Relaxed);
        // SAFETY: same contract as our caller's.
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: `ptr` came from `System.alloc` with this layout.
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static ALLOCATOR: LargestAllocation = LargestAllocation;

const ONE_MIB: usize = 1 << 20;

/// Decodes `bytes` and returns the reason it failed and the largest allocation made.
fn refuse(bytes: &[u8], name: &str) -> (Reason, usize) {
    let _serial = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
    LARGEST.store(0, Ordering::Relaxed);
    let result = decode_image(bytes, Path::new(name), &Limits::default(), Encoding::Srgb);
    let largest = LARGEST.load(Ordering::Relaxed);
    (result.expect_err("must be refused").reason, largest)
}

#[test]
fn ppm_claiming_100000_squared_is_oversized_without_allocating_it() {
    let (reason, largest) = refuse(b"P6\n100000 100000\n255\n\x00\x00\x00", "huge.ppm");
    assert!(matches!(reason, Reason::Oversized { .. }), "{reason}");
    assert!(largest < ONE_MIB, "allocated {largest} bytes");
    assert!(reason.to_string().contains("100000×100000"), "{reason}");
}

#[test]
fn within_side_limits_but_over_the_memory_budget() {
    let (reason, largest) = refuse(b"P6 16000 16000 255\n", "big.ppm");
    assert!(reason.to_string().contains("memory budget"), "{reason}");
    assert!(largest < ONE_MIB, "allocated {largest} bytes");
}

#[test]
fn png_claiming_100000_squared_is_oversized_without_allocating_it() {
    let (reason, largest) = refuse(&png_header_only(100_000, 100_000), "huge.png");
    assert!(matches!(reason, Reason::Oversized { .. }), "{reason}");
    assert!(largest < ONE_MIB, "allocated {largest} bytes");
}

/// A PNG with a valid IHDR for `width`×`height` RGB, an empty IDAT and IEND.
fn png_header_only(width: u32, height: u32) -> Vec<u8> {
    let mut ihdr = Vec::new();
    ihdr.extend(width.to_be_bytes());
    ihdr.extend(height.to_be_bytes());
    ihdr.extend([8, 2, 0, 0, 0]);
    let mut png = b"\x89PNG\r\n\x1a\n".to_vec();
    for (kind, data) in [
        (b"IHDR", &ihdr[..]),
        (
            b"IDAT",
            &[0x78, 0x9c, 0x03, 0x00, 0x00, 0x00, 0x00, 0x01][..],
        ),
        (b"IEND", &[][..]),
    ] {
        png.extend((data.len() as u32).to_be_bytes());
        let start = png.len();
        png.extend(kind);
        png.extend(data);
        let crc = crc32(&png[start..]);
        png.extend(crc.to_be_bytes());
    }
    png
}

fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = !0u32;
    for &byte in bytes {
        crc ^= u32::from(byte);
        for _ in 0..8 {
            crc = if crc & 1 == 1 {
                (crc >> 1) ^ 0xedb8_8320
            } else {
                crc >> 1
            };
        }
    }
    !crc
}
