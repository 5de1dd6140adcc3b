//! The two-colour approximation of a cell: which sub-pixels take the foreground and which the background,
//! each group shown as its mean colour, choosing the split with the least squared error (as chafa does).

/// A chosen split: sub-pixels with their bit set in `mask` show `fg`, the others `bg`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Split {
    pub mask: u8,
    pub fg: [u8; 3],
    pub bg: [u8; 3],
}

/// The split of `pixels` (at most 8) with the least squared error. Only masks that leave the last
/// sub-pixel in the background are tried: the others are the same splits with fg and bg swapped.
pub fn best_split(pixels: &[[u8; 3]]) -> Split {
    let n = pixels.len();
    assert!((1..=8).contains(&n), "a cell has 1 to 8 sub-pixels");
    let total = channel_sums(pixels, u8::MAX);
    let mut best = (0u8, f64::MIN);
    for mask in 0..(1u16 << (n - 1)) as u8 {
        let score = between_group_score(pixels, mask, total);
        if score > best.1 {
            best = (mask, score);
        }
    }
    let mask = best.0;
    let fg_sums = channel_sums(pixels, mask);
    let bg_sums = [0, 1, 2].map(|c| total[c] - fg_sums[c]);
    let fg_count = mask.count_ones();
    let bg = mean(bg_sums, n as u32 - fg_count);
    let fg = if fg_count == 0 {
        bg
    } else {
        mean(fg_sums, fg_count)
    };
    Split { mask, fg, bg }
}

/// Sum of |group sum|² / group size over both groups. The squared error of a split is the total
/// Σ|p|² minus this, so the best split maximises it, and no second pass over the pixels is needed.
fn between_group_score(pixels: &[[u8; 3]], mask: u8, total: [u32; 3]) -> f64 {
    let fg = channel_sums(pixels, mask);
    let fg_count = mask.count_ones() as f64;
    let bg_count = pixels.len() as f64 - fg_count;
    let norm2 = |s: [u32; 3]| s.iter().map(|&v| (v as f64) * (v as f64)).sum::<f64>();
    let bg = [0, 1, 2].map(|c| total[c] - fg[c]);
    let fg_term = if fg_count > 0.0 {
        norm2(fg) / fg_count
    } else {
        0.0
    };
    fg_term + norm2(bg) / bg_count
}

fn channel_sums(pixels: &[[u8; 3]], mask: u8) -> [u32; 3] {
    let mut sums = [0u32; 3];
    for (i, p) in pixels.iter().enumerate() {
        if mask & (1 << i) != 0 {
            for c in 0..3 {
                sums[c] += p[c] as u32;
            }
        }
    }
    sums
}

fn mean(sums: [u32; 3], count: u32) -> [u8; 3] {
    sums.map(|s| ((s + count / 2) / count) as u8)
}

/// The squared error of showing each group of `pixels` (split by `mask`) as its exact mean: the quantity
/// [`best_split`] minimises, computed directly as a check.
pub fn split_error(pixels: &[[u8; 3]], mask: u8) -> f64 {
    let group_error = |in_fg: bool| {
        let members: Vec<[f64; 3]> = pixels
            .iter()
            .enumerate()
            .filter(|(i, _)| (mask & (1 << i) != 0) == in_fg)
            .map(|(_, p)| p.map(f64::from))
            .collect();
        if members.is_empty() {
            return 0.0;
        }
        let count = members.len() as f64;
        let centre = [0, 1, 2].map(|c| members.iter().map(|p| p[c]).sum::<f64>() / count);
        members
            .iter()
            .map(|p| (0..3).map(|c| (p[c] - centre[c]).powi(2)).sum::<f64>())
            .sum::<f64>()
    };
    group_error(true) + group_error(false)
}
