//! Cursor movement: the shortest sequence from where the cursor is (as far as the writer knows) to a cell.

use super::sgr::push_decimal;

/// Where the writer knows the cursor to be. `col` is `None` after drawing into a grid's last column:
/// if that column is the screen's last, the terminal holds a pending wrap and the column is ambiguous.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Cursor {
    pub row: u16,
    pub col: Option<u16>,
}

/// Appends the shortest move from `from` (`None`: position unknown) to screen cell (`row`, `col`), 0-based.
pub fn move_to(from: Option<Cursor>, row: u16, col: u16, out: &mut Vec<u8>) {
    let start = out.len();
    write_absolute(row, col, out);
    let Some(from) = from else { return };
    let mut candidate = Vec::with_capacity(16);
    let applies = write_relative(from, row, col, &mut candidate);
    if applies && candidate.len() < out.len() - start {
        out.truncate(start);
        out.extend_from_slice(&candidate);
    }
}

/// Bytes of [`move_to`]'s sequence.
pub fn move_cost(from: Option<Cursor>, row: u16, col: u16) -> usize {
    let mut out = Vec::with_capacity(16);
    move_to(from, row, col, &mut out);
    out.len()
}

/// CUP, leaving out parameters that are 1.
fn write_absolute(row: u16, col: u16, out: &mut Vec<u8>) {
    out.extend_from_slice(b"\x1b[");
    if row > 0 || col > 0 {
        push_decimal(row as u32 + 1, out);
    }
    if col > 0 {
        out.push(b';');
        push_decimal(col as u32 + 1, out);
    }
    out.push(b'H');
}

/// A move relative to a known position; false if none applies.
fn write_relative(from: Cursor, row: u16, col: u16, out: &mut Vec<u8>) -> bool {
    let same_col = from.col == Some(col);
    match (row.checked_sub(from.row), from.col) {
        (Some(0), Some(c)) if c < col => write_csi(col - c, b'C', out),
        (Some(0), Some(c)) if c > col => write_csi(c - col, b'D', out),
        (Some(0), Some(_)) => {} // already there
        (Some(down), _) if down > 0 && same_col => write_csi(down, b'B', out),
        // CR then LF: LF never scrolls here (the target row is on screen) and with or without output
        // post-processing (raw or cooked mode) the cursor ends in column 0.
        (Some(down), _) if down > 0 && down <= 4 => {
            out.push(b'\r');
            out.extend(std::iter::repeat_n(b'\n', down as usize));
            if col > 0 {
                write_csi(col, b'C', out);
            }
        }
        (Some(0), None) => {
            out.push(b'\r');
            if col > 0 {
                write_csi(col, b'C', out);
            }
        }
        _ => return false,
    }
    true
}

fn write_csi(n: u16, command: u8, out: &mut Vec<u8>) {
    out.extend_from_slice(b"\x1b[");
    if n != 1 {
        push_decimal(n as u32, out);
    }
    out.push(command);
}

#[cfg(test)]
mod tests {
    use super::*;

    fn moved(from: Option<Cursor>, row: u16, col: u16) -> String {
        let mut out = Vec::new();
        move_to(from, row, col, &mut out);
        String::from_utf8(out).unwrap()
    }

    #[test]
    fn picks_the_shortest_move() {
        assert_eq!(moved(None, 0, 0), "\x1b[H");
        assert_eq!(moved(None, 4, 0), "\x1b[5H");
        assert_eq!(moved(None, 4, 9), "\x1b[5;10H");
        let at = |row, col| Some(Cursor { row, col });
        assert_eq!(moved(at(4, Some(3)), 4, 4), "\x1b[C");
        assert_eq!(moved(at(4, Some(3)), 4, 20), "\x1b[17C");
        assert_eq!(moved(at(4, None), 5, 0), "\r\n");
        assert_eq!(moved(at(4, Some(7)), 6, 7), "\x1b[2B");
        assert_eq!(moved(at(4, Some(3)), 4, 3), "");
        assert_eq!(moved(at(40, Some(3)), 2, 3), "\x1b[3;4H");
    }
}
