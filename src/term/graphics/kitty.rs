//! The kitty graphics protocol: an image sent inline (`t=d`, so it works over SSH), zlib
//! compressed (`o=z`), 24-bit RGB (`f=24`), in base64 chunks of at most 4096 bytes, always under
//! one image id so each picture replaces the last; placed at the cursor over a given cell area,
//! under the text and under cells with a background of their own (so overlays cover it), without
//! moving the cursor (`C=1`) and without replies (`q=2`).

use base64::Engine;
use std::io::Write;
use std::sync::atomic::{AtomicU8, Ordering};

/// The id of the workbench's one image.
pub const IMAGE_ID: u32 = 31;

/// Base64 bytes in one escape sequence at most, as the protocol asks.
const CHUNK: usize = 4096;

/// Below this z-index an image is drawn under cells' own backgrounds, not only under text.
const UNDER_BACKGROUNDS: i64 = -1_073_741_825;

/// The escape sequences, one a chunk, that show `rgb` (`width` × `height` pixels, 3 bytes each,
/// row-major) scaled over `cols` × `rows` cells from the cursor.
pub fn image(rgb: &[u8], width: u32, height: u32, cols: u16, rows: u16) -> Vec<Vec<u8>> {
    assert_eq!(rgb.len(), (width * height * 3) as usize, "3 bytes a pixel");
    let mut compressor = flate2::write::ZlibEncoder::new(Vec::new(), flate2::Compression::fast());
    compressor.write_all(rgb).expect("writing to memory");
    let compressed = compressor.finish().expect("writing to memory");
    let payload = base64::engine::general_purpose::STANDARD.encode(compressed);
    let chunks: Vec<&[u8]> = payload.as_bytes().chunks(CHUNK).collect();
    let mut sequences = Vec::with_capacity(chunks.len());
    for (index, chunk) in chunks.iter().enumerate() {
        let more = u8::from(index + 1 < chunks.len());
        let mut out = Vec::with_capacity(chunk.len() + 160);
        out.extend_from_slice(b"\x1b_G");
        if index == 0 {
            let keys = format!(
                "a=T,f=24,o=z,t=d,s={width},v={height},i={IMAGE_ID},p=1,c={cols},r={rows},\
                 C=1,z={UNDER_BACKGROUNDS},q=2,"
            );
            out.extend_from_slice(keys.as_bytes());
        }
        out.extend_from_slice(format!("m={more};").as_bytes());
        out.extend_from_slice(chunk);
        out.extend_from_slice(b"\x1b\\");
        sequences.push(out);
    }
    sequences
}

/// Deletes the image and frees its data.
pub fn delete() -> Vec<u8> {
    format!("\x1b_Ga=d,d=I,i={IMAGE_ID},q=2\x1b\\").into_bytes()
}

/// The query that asks whether the terminal speaks the protocol: a 1×1 image it answers `OK` to
/// (with the query's own id) and does not show.
pub fn query() -> Vec<u8> {
    b"\x1b_Gi=32,s=1,v=1,a=q,t=d,f=24;AAAA\x1b\\".to_vec()
}

/// Whether `replies` hold the terminal's `OK` to `query`.
pub fn answered(replies: &[u8]) -> bool {
    let text = String::from_utf8_lossy(replies);
    text.split("\x1b_G")
        .skip(1)
        .any(|reply| reply.starts_with("i=32") && reply.contains(";OK"))
}

/// Whether an image is on the screen, so that restoring the terminal deletes it: 0 none, 1 sent
/// directly, 2 through tmux.
static SHOWN: AtomicU8 = AtomicU8::new(0);

/// Records that the image is shown (`Some`, and whether through tmux) or is gone (`None`).
pub fn note_image(shown: Option<bool>) {
    let state = match shown {
        None => 0,
        Some(false) => 1,
        Some(true) => 2,
    };
    SHOWN.store(state, Ordering::SeqCst);
}

/// Deletes the image if one is shown (once, however often this is called): for the paths that
/// give the terminal back.
pub fn delete_if_shown(out: &mut impl Write) -> std::io::Result<()> {
    match SHOWN.swap(0, Ordering::SeqCst) {
        1 => out.write_all(&delete()),
        2 => out.write_all(&super::tmux_passthrough(&delete())),
        _ => Ok(()),
    }
}
