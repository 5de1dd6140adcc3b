//! `--shard K/N`: a deterministic share of a batch's stills (a sequence's frames, a sweep's
//! combinations, a gallery's scenes), so N processes on any scheduler together render the whole
//! batch, each writing only its own files.

/// Shard `index` of `count` (from 1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shard {
    pub index: u64,
    pub count: u64,
}

/// The most shards a batch may be split into.
pub const MAX_SHARDS: u64 = 100_000;

impl Shard {
    /// The whole batch: one shard of one.
    pub const WHOLE: Shard = Shard { index: 1, count: 1 };

    /// Whether item `item` (from 0) is this shard's: every `count`-th from `index` − 1.
    pub fn takes(self, item: u64) -> bool {
        item % self.count == self.index - 1
    }

    pub fn is_whole(self) -> bool {
        self.count == 1
    }
}

/// `K/N` (a command-line value parser).
pub fn parse_shard(text: &str) -> Result<Shard, String> {
    let expected = || {
        format!(
            "expected K/N, shard K of N with 1 ≤ K ≤ N ≤ {MAX_SHARDS} (K counted from 1), got '{}'",
            bumpwork::diagnostic::shown_input(text)
        )
    };
    let (k, n) = text.split_once('/').ok_or_else(expected)?;
    let number = |s: &str| s.trim().parse::<u64>().ok();
    match (number(k), number(n)) {
        (Some(index), Some(count)) if 1 <= index && index <= count && count <= MAX_SHARDS => {
            Ok(Shard { index, count })
        }
        _ => Err(expected()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shards_split_every_item_once() {
        for count in 1..6 {
            for item in 0..40 {
                let takers = (1..=count)
                    .filter(|&index| Shard { index, count }.takes(item))
                    .count();
                assert_eq!(takers, 1, "item {item} of {count} shards");
            }
        }
        assert_eq!(parse_shard("2/8"), Ok(Shard { index: 2, count: 8 }));
        for bad in ["0/4", "5/4", "1/0", "a/b", "3", "1/100001"] {
            assert!(parse_shard(bad).is_err(), "{bad}");
        }
    }
}
