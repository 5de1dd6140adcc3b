//! Comments inside the samples of plain (ASCII) PNM files.
//!
//! Netpbm's own reader skips `#` comments anywhere in a plain P1/P2/P3 file, and
//! hand-written files (the seed's format) use them between samples; the image crate
//! only skips them in the header. Blanking them first makes both agree.

use std::borrow::Cow;

/// The file with every `#…` comment of a plain PNM turned into spaces (line breaks
/// kept, so tokens stay separated); other files are returned untouched.
pub fn strip_comments(bytes: &[u8]) -> Cow<'_, [u8]> {
    let is_plain_pnm = matches!(bytes, [b'P', b'1'..=b'3', ..]);
    if !is_plain_pnm || !bytes.contains(&b'#') {
        return Cow::Borrowed(bytes);
    }
    let mut in_comment = false;
    let stripped = bytes
        .iter()
        .map(|&b| {
            if b == b'\n' || b == b'\r' {
                in_comment = false;
                return b;
            }
            in_comment |= b == b'#';
            if in_comment { b' ' } else { b }
        })
        .collect();
    Cow::Owned(stripped)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn comments_become_spaces_and_binary_files_are_untouched() {
        assert_eq!(&*strip_comments(b"P2 1 1#x\n9 #y\n5"), b"P2 1 1  \n9   \n5");
        let binary = b"P5 1 1 255\n#";
        assert!(matches!(strip_comments(binary), Cow::Borrowed(_)));
    }
}
