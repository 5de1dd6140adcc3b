//! iTerm2's inline images (OSC 1337): a PNG in base64, shown from the cursor over a given cell
//! area, stretched to it.

use base64::Engine;

/// The escape sequence that shows `rgb` (`width` × `height` pixels, 3 bytes each) over `cols`
/// × `rows` cells from the cursor.
pub fn image(rgb: &[u8], width: u32, height: u32, cols: u16, rows: u16) -> Vec<u8> {
    let png = png_bytes(rgb, width, height);
    let payload = base64::engine::general_purpose::STANDARD.encode(&png);
    let mut out = format!(
        "\x1b]1337;File=inline=1;size={};width={cols};height={rows};preserveAspectRatio=0:",
        png.len()
    )
    .into_bytes();
    out.extend_from_slice(payload.as_bytes());
    out.push(0x07);
    out
}

/// `rgb` as a PNG, fast to make rather than small.
fn png_bytes(rgb: &[u8], width: u32, height: u32) -> Vec<u8> {
    let mut png = Vec::new();
    let mut encoder = png::Encoder::new(&mut png, width, height);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_compression(png::Compression::Fast);
    let mut writer = encoder.write_header().expect("writing to memory");
    writer.write_image_data(rgb).expect("writing to memory");
    writer.finish().expect("writing to memory");
    png
}
