//! What lies outside the image: repeat it, clamp to its edge, or mirror it.

/// Wrap mode for one texture axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Wrap {
    /// Floored modulo: period 1, correct across negative coordinates (unlike C's `%`).
    #[default]
    Repeat,
    /// The edge texels extend forever.
    Clamp,
    /// Every other copy flipped: period 2, continuous at every edge.
    Mirror,
}

impl Wrap {
    /// Maps a coordinate to a small range that looks up the same texels, so texel
    /// indices fit an `i32` whatever the input; non-finite coordinates become 0.
    /// Repeat gives `[0, 1]`, Mirror `[0, 2]`, Clamp `[-1, 2]`.
    #[inline(always)]
    pub fn reduce(self, s: f32) -> f32 {
        if !s.is_finite() {
            return 0.0;
        }
        match self {
            Wrap::Repeat => s - s.floor(),
            Wrap::Mirror => s - 2.0 * (0.5 * s).floor(),
            Wrap::Clamp => s.clamp(-1.0, 2.0),
        }
    }

    /// The texel index `i` lands on in an axis of `n` texels, for `i` from a reduced
    /// coordinate (`-n - 1 ..= 2n`); always `< n`, so lookups never go out of bounds.
    #[inline(always)]
    pub fn index(self, i: i32, n: u32) -> u32 {
        let n = n as i32;
        if (0..n).contains(&i) {
            return i as u32; // the common case; skips a division
        }
        let wrapped = match self {
            Wrap::Repeat => i.rem_euclid(n),
            Wrap::Clamp => i.clamp(0, n - 1),
            Wrap::Mirror => {
                let m = i.rem_euclid(2 * n);
                if m < n { m } else { 2 * n - 1 - m }
            }
        };
        wrapped as u32
    }

    /// The texel containing coordinate `s` (`[0, 1)` spans the `n` texels).
    #[inline(always)]
    pub fn texel(self, s: f32, n: u32) -> u32 {
        self.index((self.reduce(s) * n as f32).floor() as i32, n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn repeat_is_floored_modulo() {
        assert_eq!(Wrap::Repeat.index(-1, 4), 3);
        assert_eq!(Wrap::Repeat.index(-5, 4), 3);
        assert_eq!(Wrap::Repeat.texel(-0.1, 10), 9);
        assert_eq!(Wrap::Repeat.texel(-1e-9, 10), 0);
    }

    #[test]
    fn mirror_reflects_at_both_edges() {
        let indices: Vec<u32> = (-4..8).map(|i| Wrap::Mirror.index(i, 3)).collect();
        assert_eq!(indices, [2, 2, 1, 0, 0, 1, 2, 2, 1, 0, 0, 1]);
    }

    #[test]
    fn clamp_holds_the_edges() {
        assert_eq!(Wrap::Clamp.texel(-7.0, 5), 0);
        assert_eq!(Wrap::Clamp.texel(7.0, 5), 4);
        assert_eq!(Wrap::Clamp.texel(f32::NAN, 5), 0);
    }

    #[test]
    fn huge_and_non_finite_coordinates_stay_in_range() {
        for wrap in [Wrap::Repeat, Wrap::Clamp, Wrap::Mirror] {
            for s in [
                1e30,
                -1e30,
                f32::INFINITY,
                f32::NEG_INFINITY,
                f32::NAN,
                -0.0,
            ] {
                assert!(wrap.texel(s, 7) < 7);
            }
        }
    }
}
