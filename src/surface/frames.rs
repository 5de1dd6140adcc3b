//! A batch's surface frames as structure-of-arrays: one array per coordinate of each of the
//! frame's vectors. Loops over fragments then read and write contiguous floats, which the
//! compiler turns into SIMD; an array of `Frame`s compiled to shuffles and scalar stores
//! instead, on every stage that wrote or read one.

use super::Frame;
use glam::Vec3;
use std::ops::Range;

/// Vectors of a batch, one array per coordinate, all the same length.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Vectors {
    x: Vec<f32>,
    y: Vec<f32>,
    z: Vec<f32>,
}

impl Vectors {
    pub fn len(&self) -> usize {
        self.x.len()
    }

    pub fn is_empty(&self) -> bool {
        self.x.is_empty()
    }

    #[inline(always)]
    pub fn at(&self, k: usize) -> Vec3 {
        Vec3::new(self.x[k], self.y[k], self.z[k])
    }

    #[inline(always)]
    pub fn set(&mut self, k: usize, v: Vec3) {
        (self.x[k], self.y[k], self.z[k]) = (v.x, v.y, v.z);
    }

    /// The vectors of `range`, in order.
    pub fn range(&self, range: Range<usize>) -> impl Iterator<Item = Vec3> + '_ {
        let (x, y, z) = (
            &self.x[range.clone()],
            &self.y[range.clone()],
            &self.z[range],
        );
        x.iter()
            .zip(y)
            .zip(z)
            .map(|((&x, &y), &z)| Vec3::new(x, y, z))
    }

    /// The three coordinate arrays, each `len` long (for lane loops).
    #[inline(always)]
    pub fn coordinates(&self) -> [&[f32]; 3] {
        let n = self.len();
        [&self.x[..n], &self.y[..n], &self.z[..n]]
    }

    /// The three coordinate arrays for writing, each `len` long.
    #[inline(always)]
    pub fn coordinates_mut(&mut self) -> [&mut [f32]; 3] {
        let n = self.len();
        [&mut self.x[..n], &mut self.y[..n], &mut self.z[..n]]
    }

    fn clear(&mut self) {
        self.x.clear();
        self.y.clear();
        self.z.clear();
    }

    fn resize(&mut self, len: usize, v: Vec3) {
        self.x.resize(len, v.x);
        self.y.resize(len, v.y);
        self.z.resize(len, v.z);
    }

    fn reserve(&mut self, more: usize) {
        self.x.reserve(more);
        self.y.reserve(more);
        self.z.reserve(more);
    }

    #[inline(always)]
    fn push(&mut self, v: Vec3) {
        self.x.push(v.x);
        self.y.push(v.y);
        self.z.push(v.z);
    }
}

/// The frames of a batch of fragments, by position in the batch.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Frames {
    pub p: Vectors,
    pub pu: Vectors,
    pub pv: Vectors,
    pub n: Vectors,
}

impl Frames {
    pub fn len(&self) -> usize {
        self.p.len()
    }

    pub fn is_empty(&self) -> bool {
        self.p.is_empty()
    }

    pub fn clear(&mut self) {
        self.vectors_mut().into_iter().for_each(Vectors::clear);
    }

    pub fn reserve(&mut self, more: usize) {
        self.vectors_mut().into_iter().for_each(|v| v.reserve(more));
    }

    /// Grows (or shrinks) to `len` frames, new ones `frame`.
    pub fn resize(&mut self, len: usize, frame: Frame) {
        self.p.resize(len, frame.p);
        self.pu.resize(len, frame.pu);
        self.pv.resize(len, frame.pv);
        self.n.resize(len, frame.n);
    }

    #[inline(always)]
    pub fn push(&mut self, frame: Frame) {
        self.p.push(frame.p);
        self.pu.push(frame.pu);
        self.pv.push(frame.pv);
        self.n.push(frame.n);
    }

    #[inline(always)]
    pub fn at(&self, k: usize) -> Frame {
        Frame {
            p: self.p.at(k),
            pu: self.pu.at(k),
            pv: self.pv.at(k),
            n: self.n.at(k),
        }
    }

    #[inline(always)]
    pub fn set(&mut self, k: usize, frame: Frame) {
        self.p.set(k, frame.p);
        self.pu.set(k, frame.pu);
        self.pv.set(k, frame.pv);
        self.n.set(k, frame.n);
    }

    pub fn first(&self) -> Option<Frame> {
        (!self.is_empty()).then(|| self.at(0))
    }

    /// Every frame, in order. Zipped with a slice's iterator, each frame is read through an
    /// out-of-line call: hot loops index `slices` instead.
    pub fn iter(&self) -> impl ExactSizeIterator<Item = Frame> + Clone + '_ {
        let slices = self.slices();
        (0..slices.len).map(
            #[inline(always)]
            move |k| slices.at(k),
        )
    }

    /// The coordinate arrays, each cut to the batch's length: indexed below that length in the
    /// function that cut them, their bounds checks (and unread loads) compile away.
    #[inline(always)]
    pub fn slices(&self) -> FrameSlices<'_> {
        FrameSlices {
            p: self.p.coordinates(),
            pu: self.pu.coordinates(),
            pv: self.pv.coordinates(),
            n: self.n.coordinates(),
            len: self.len(),
        }
    }

    /// Appends the first `len` frames of a chunk given as lanes of coordinates: p, Pu, Pv and
    /// n, each as x, y and z.
    pub fn extend_from_lanes<const LANES: usize>(
        &mut self,
        lanes: &[[f32; LANES]; 12],
        len: usize,
    ) {
        let arrays = self
            .vectors_mut()
            .into_iter()
            .flat_map(|v| [&mut v.x, &mut v.y, &mut v.z]);
        for (array, lane) in arrays.zip(lanes) {
            array.extend_from_slice(&lane[..len]);
        }
    }

    fn vectors_mut(&mut self) -> [&mut Vectors; 4] {
        [&mut self.p, &mut self.pu, &mut self.pv, &mut self.n]
    }
}

/// A batch's frames as coordinate arrays of one length (`Frames::slices`).
#[derive(Clone, Copy)]
pub struct FrameSlices<'a> {
    p: [&'a [f32]; 3],
    pu: [&'a [f32]; 3],
    pv: [&'a [f32]; 3],
    n: [&'a [f32]; 3],
    pub len: usize,
}

impl FrameSlices<'_> {
    /// The k-th frame. One check of `k` against the length; the arrays' own checks against
    /// it do not depend on `k`, so in a loop they are made once, before it.
    #[inline(always)]
    pub fn at(&self, k: usize) -> Frame {
        assert!(k < self.len, "frame {k} of {}", self.len);
        let len = self.len;
        let vector = |[x, y, z]: [&[f32]; 3]| Vec3::new(x[..len][k], y[..len][k], z[..len][k]);
        Frame {
            p: vector(self.p),
            pu: vector(self.pu),
            pv: vector(self.pv),
            n: vector(self.n),
        }
    }
}

impl Extend<Frame> for Frames {
    fn extend<I: IntoIterator<Item = Frame>>(&mut self, frames: I) {
        let frames = frames.into_iter();
        self.reserve(frames.size_hint().0);
        frames.for_each(|frame| self.push(frame));
    }
}

impl FromIterator<Frame> for Frames {
    fn from_iter<I: IntoIterator<Item = Frame>>(frames: I) -> Frames {
        let mut out = Frames::default();
        out.extend(frames);
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frame(i: f32) -> Frame {
        Frame {
            p: Vec3::new(i, 2.0 * i, 3.0 * i),
            pu: Vec3::new(-i, 0.5, 1.0),
            pv: Vec3::new(0.0, i, -2.0),
            n: Vec3::new(1.0, 0.0, i),
        }
    }

    #[test]
    fn frames_read_back_as_written() {
        let mut frames: Frames = (0..5).map(|i| frame(i as f32)).collect();
        assert_eq!(frames.len(), 5);
        frames.set(2, frame(9.0));
        frames.resize(7, frame(-1.0));
        let expected = [0.0, 1.0, 9.0, 3.0, 4.0, -1.0, -1.0].map(frame);
        assert!(frames.iter().eq(expected));
        assert_eq!(frames.first(), Some(frame(0.0)));
        let normals: Vec<Vec3> = frames.n.range(1..3).collect();
        let mut lanes = [[0.0f32; 4]; 12];
        for (c, lane) in lanes.iter_mut().enumerate() {
            *lane = [c as f32, 10.0 + c as f32, 20.0 + c as f32, -1.0];
        }
        frames.extend_from_lanes(&lanes, 3);
        let lane_frame = |k: f32| Frame {
            p: Vec3::new(k, k + 1.0, k + 2.0),
            pu: Vec3::new(k + 3.0, k + 4.0, k + 5.0),
            pv: Vec3::new(k + 6.0, k + 7.0, k + 8.0),
            n: Vec3::new(k + 9.0, k + 10.0, k + 11.0),
        };
        assert_eq!(frames.len(), 10);
        assert!(frames.iter().skip(7).eq([0.0, 10.0, 20.0].map(lane_frame)));
        assert_eq!(normals, [frame(1.0).n, frame(9.0).n]);
        frames.clear();
        assert!(frames.is_empty() && frames.first().is_none());
        assert!(frames.pu.is_empty() && frames.n.is_empty());
    }
}
