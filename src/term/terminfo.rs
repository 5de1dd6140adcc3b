//! One fact from the terminal's terminfo entry: whether it declares 24-bit colour, by the
//! extended booleans `RGB` (ncurses) or `Tc` (tmux's). Read from the compiled entry files,
//! bounded, and never trusted for more than that.

use std::path::{Path, PathBuf};

/// Compiled entries are a few KiB; anything larger is not one.
const MAX_ENTRY_BYTES: u64 = 64 << 10;
/// ncurses' magic numbers: 16-bit numbers, and (ncurses 6.1+) 32-bit ones.
const MAGIC_16: u16 = 0o432;
const MAGIC_32: u16 = 0o1036;
/// The extended booleans that declare 24-bit colour.
const DIRECT_COLOUR_FLAGS: [&str; 2] = ["RGB", "Tc"];

/// The flag (`RGB` or `Tc`) the entry for `term` sets, if its file is found and sets one; `var`
/// reads the environment (`TERMINFO`, `HOME`, `TERMINFO_DIRS`).
pub fn direct_colour_flag(
    term: &str,
    var: impl Fn(&str) -> Option<String>,
) -> Option<&'static str> {
    if term.is_empty() || term.contains('/') || term.starts_with('.') {
        return None;
    }
    let entry = entry_paths(term, &var)
        .into_iter()
        .find_map(|path| crate::bounded_read::read_bounded(&path, MAX_ENTRY_BYTES).ok())?;
    let set = extended_booleans(&entry)?;
    DIRECT_COLOUR_FLAGS
        .into_iter()
        .find(|flag| set.iter().any(|name| name == flag))
}

/// Where ncurses looks for the entry, in its order: `$TERMINFO`, `~/.terminfo`, each of
/// `$TERMINFO_DIRS` (an empty one meaning the system's), then the system directories; in each,
/// under the name's first letter or its hex code.
fn entry_paths(term: &str, var: &impl Fn(&str) -> Option<String>) -> Vec<PathBuf> {
    const SYSTEM: [&str; 4] = [
        "/etc/terminfo",
        "/lib/terminfo",
        "/usr/share/terminfo",
        "/usr/lib/terminfo",
    ];
    let mut directories: Vec<PathBuf> = Vec::new();
    directories.extend(var("TERMINFO").map(PathBuf::from));
    directories.extend(var("HOME").map(|home| Path::new(&home).join(".terminfo")));
    for dir in var("TERMINFO_DIRS").unwrap_or_default().split(':') {
        match dir {
            "" => directories.extend(SYSTEM.map(PathBuf::from)),
            dir => directories.push(PathBuf::from(dir)),
        }
    }
    directories.extend(SYSTEM.map(PathBuf::from));
    let first = term.chars().next().expect("a non-empty name");
    directories
        .into_iter()
        .flat_map(|dir| {
            [
                dir.join(first.to_string()).join(term),
                dir.join(format!("{:x}", first as u32)).join(term),
            ]
        })
        .collect()
}

/// The names of the extended booleans a compiled entry sets, or `None` if it is not one (or has
/// no extended part).
fn extended_booleans(entry: &[u8]) -> Option<Vec<String>> {
    let mut reader = Reader {
        bytes: entry,
        at: 0,
    };
    let magic = reader.u16()?;
    let number_size = match magic {
        MAGIC_16 => 2,
        MAGIC_32 => 4,
        _ => return None,
    };
    let [names, booleans, numbers, strings, table] = [(); 5].map(|()| reader.count());
    let standard = names? + booleans?;
    reader.skip(standard)?;
    reader.align();
    reader.skip(numbers? * number_size + strings? * 2 + table?)?;
    reader.align();
    let [ext_booleans, ext_numbers, ext_strings, offsets, ext_table] =
        [(); 5].map(|()| reader.count());
    let (ext_booleans, ext_numbers, ext_strings) = (ext_booleans?, ext_numbers?, ext_strings?);
    let values: Vec<bool> = reader.take(ext_booleans)?.iter().map(|&b| b == 1).collect();
    reader.align();
    reader.skip(ext_numbers * number_size)?;
    let offsets: Vec<Option<usize>> = (0..offsets?)
        .map(|_| reader.offset())
        .collect::<Option<_>>()?;
    let table = reader.take(ext_table?)?;
    // The names follow the string values in the table; name offsets count from their start.
    let (value_offsets, name_offsets) = offsets.split_at(ext_strings.min(offsets.len()));
    let names_start = value_offsets
        .iter()
        .flatten()
        .filter_map(|&start| Some(start + c_string(table.get(start..)?)?.len() + 1))
        .max()
        .unwrap_or(0);
    let name = |i: usize| {
        let start = names_start + name_offsets.get(i).copied().flatten()?;
        c_string(table.get(start..)?)
    };
    Some(
        values
            .iter()
            .enumerate()
            .filter(|&(_, &set)| set)
            .filter_map(|(i, _)| name(i))
            .collect(),
    )
}

/// The text up to the first NUL.
fn c_string(bytes: &[u8]) -> Option<String> {
    let end = bytes.iter().position(|&b| b == 0)?;
    String::from_utf8(bytes[..end].to_vec()).ok()
}

struct Reader<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl<'a> Reader<'a> {
    fn u16(&mut self) -> Option<u16> {
        let pair = self.take(2)?;
        Some(u16::from_le_bytes([pair[0], pair[1]]))
    }

    /// A count or size: a non-negative 16-bit number.
    fn count(&mut self) -> Option<usize> {
        let value = self.u16()? as i16;
        usize::try_from(value).ok()
    }

    /// An offset into the string table; -1 (absent) reads as `None` inside.
    fn offset(&mut self) -> Option<Option<usize>> {
        let value = self.u16()? as i16;
        Some(usize::try_from(value).ok())
    }

    fn take(&mut self, n: usize) -> Option<&'a [u8]> {
        let bytes = self.bytes.get(self.at..self.at.checked_add(n)?)?;
        self.at += n;
        Some(bytes)
    }

    fn skip(&mut self, n: usize) -> Option<()> {
        self.take(n).map(|_| ())
    }

    /// Sections start on even offsets.
    fn align(&mut self) {
        self.at += self.at % 2;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A compiled entry with no standard capabilities and the extended booleans `flags`
    /// (name, set), as ncurses writes one.
    fn entry(flags: &[(&str, bool)]) -> Vec<u8> {
        let mut bytes = Vec::new();
        let short = |bytes: &mut Vec<u8>, v: u16| bytes.extend(v.to_le_bytes());
        short(&mut bytes, MAGIC_16);
        // names "x\0" (2 bytes), no booleans, numbers, strings or table.
        for v in [2, 0, 0, 0, 0] {
            short(&mut bytes, v);
        }
        bytes.extend(b"x\0");
        let names: Vec<u8> = flags
            .iter()
            .flat_map(|(name, _)| name.bytes().chain([0]))
            .collect();
        for v in [
            flags.len() as u16,
            0,
            0,
            flags.len() as u16,
            names.len() as u16,
        ] {
            short(&mut bytes, v);
        }
        bytes.extend(flags.iter().map(|&(_, set)| set as u8));
        if bytes.len() % 2 == 1 {
            bytes.push(0);
        }
        let mut offset = 0;
        for (name, _) in flags {
            short(&mut bytes, offset);
            offset += name.len() as u16 + 1;
        }
        bytes.extend(names);
        bytes
    }

    #[test]
    fn the_set_extended_booleans_are_read_by_name() {
        let bytes = entry(&[("AX", true), ("RGB", true), ("XT", false)]);
        assert_eq!(
            extended_booleans(&bytes),
            Some(vec!["AX".to_string(), "RGB".to_string()])
        );
    }

    #[test]
    fn an_entry_declaring_rgb_or_tc_is_found_in_terminfo_dirs() {
        let dir = tempfile::tempdir().unwrap();
        let home = dir.path().join("home");
        for (term, flag) in [("newterm", "Tc"), ("plainterm", "XT")] {
            let file = home.join(".terminfo").join(&term[..1]).join(term);
            std::fs::create_dir_all(file.parent().unwrap()).unwrap();
            std::fs::write(&file, entry(&[(flag, true)])).unwrap();
        }
        let home_var = home.display().to_string();
        let var = |name: &str| (name == "HOME").then(|| home_var.clone());
        assert_eq!(direct_colour_flag("newterm", var), Some("Tc"));
        assert_eq!(direct_colour_flag("plainterm", var), None);
        assert_eq!(direct_colour_flag("no-such-term-here", var), None);
        assert_eq!(direct_colour_flag("../etc/passwd", var), None);
    }

    #[test]
    fn anything_else_is_no_entry() {
        assert_eq!(extended_booleans(b""), None);
        assert_eq!(extended_booleans(b"\x1a\x01"), None);
        let mut truncated = entry(&[("RGB", true)]);
        truncated.truncate(truncated.len() - 3);
        assert!(extended_booleans(&truncated).is_none_or(|names| names.is_empty()));
        // A legacy entry with no extended part.
        let legacy = &entry(&[])[..14];
        assert_eq!(extended_booleans(legacy), None);
    }
}
