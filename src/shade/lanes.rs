//! Structure-of-arrays vectors for lane loops: a batch of fragments' vectors held one array per
//! coordinate, so a loop over the lanes that works on `Vec3`s compiles to SIMD over fragments
//! (an array of `Vec3`s or of frames compiled to shuffles instead: measured).

use crate::surface::Vectors;
use glam::Vec3;
use std::ops::Range;

/// Fragments a lane loop takes at once.
pub const LANES: usize = 64;

/// Vectors for a lane of fragments, one array per coordinate.
pub struct Lanes {
    x: [f32; LANES],
    y: [f32; LANES],
    z: [f32; LANES],
}

impl Lanes {
    #[inline(always)]
    pub fn splat(v: Vec3) -> Lanes {
        Lanes {
            x: [v.x; LANES],
            y: [v.y; LANES],
            z: [v.z; LANES],
        }
    }

    /// Sets the first lanes of `first` and `second` from up to `LANES` pairs of vectors (in
    /// place: returning the pair of 768-byte lane sets cost a memcpy of each per chunk).
    #[inline(always)]
    pub fn set_pairs(
        first: &mut Lanes,
        second: &mut Lanes,
        pairs: impl Iterator<Item = (Vec3, Vec3)>,
    ) {
        for (k, (a, b)) in pairs.take(LANES).enumerate() {
            first.set(k, a);
            second.set(k, b);
        }
    }

    /// Sets the first lanes to `vectors[range]` (at most `LANES` of them).
    #[inline(always)]
    pub fn load(&mut self, vectors: &Vectors, range: Range<usize>) {
        let n = range.len();
        let [x, y, z] = vectors.coordinates();
        self.x[..n].copy_from_slice(&x[range.clone()]);
        self.y[..n].copy_from_slice(&y[range.clone()]);
        self.z[..n].copy_from_slice(&z[range]);
    }

    #[inline(always)]
    pub fn from_fn(f: impl Fn(usize) -> Vec3) -> Lanes {
        let mut lanes = Lanes::splat(Vec3::ZERO);
        for k in 0..LANES {
            lanes.set(k, f(k));
        }
        lanes
    }

    #[inline(always)]
    pub fn at(&self, k: usize) -> Vec3 {
        Vec3::new(self.x[k], self.y[k], self.z[k])
    }

    #[inline(always)]
    pub fn set(&mut self, k: usize, v: Vec3) {
        (self.x[k], self.y[k], self.z[k]) = (v.x, v.y, v.z);
    }

    /// Writes the first `out.len()` lanes.
    #[inline(always)]
    pub fn write(&self, out: &mut [Vec3]) {
        for (k, out) in out.iter_mut().take(LANES).enumerate() {
            *out = self.at(k);
        }
    }
}
