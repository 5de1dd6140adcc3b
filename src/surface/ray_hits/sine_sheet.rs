//! Where a ray first meets the sheet y = A·sin(k·x) within a box: the wave surface's exact hit.

use super::ray::Ray;
use super::root::{bisect_sign_change, safeguarded_root};
use glam::DVec3;
use std::f64::consts::FRAC_PI_2;
use std::ops::RangeInclusive;

/// A ray crossing more quarter-waves than this is given up on (a wavelength far below a pixel
/// would alias anyway); it bounds the work per ray.
const MAX_QUARTER_WAVES: f64 = 1e6;

/// The sheet y = amplitude·sin(2π·x / wavelength) for x in [0, width] and z in [−depth, 0].
#[derive(Clone, Copy, Debug)]
pub struct SineSheet {
    pub amplitude: f64,
    pub wavelength: f64,
    pub width: f64,
    pub depth: f64,
}

impl SineSheet {
    /// The first root of f(t) = y(t) − A·sin(k·x(t)) inside the sheet's box, for t in `range`.
    /// The ray is first clipped to the box (x in [0, width], z in [−depth, 0], |y| ≤ |A|), then
    /// cut where k·x(t) crosses a multiple of π/2: on each piece f is convex or concave
    /// (f'' = A·k²·dx²·sin(k·x) keeps its sign), so it has at most two roots, found exactly:
    /// bracketed at the ends, or on either side of the piece's single extremum. Safeguarded
    /// Newton then refines each bracket.
    pub fn first_hit(&self, ray: &Ray, range: &RangeInclusive<f64>) -> Option<f64> {
        let curve = WaveAlongRay::new(self, ray);
        let (lo, hi) = self.clip_to_box(ray, *range.start(), *range.end())?;
        curve.first_root(lo, hi)
    }

    /// The ray's parameter interval inside the sheet's bounding box, within [lo, hi].
    fn clip_to_box(&self, ray: &Ray, lo: f64, hi: f64) -> Option<(f64, f64)> {
        let amplitude = self.amplitude.abs();
        let slabs = [
            (ray.origin.x, ray.direction.x, 0.0, self.width),
            (ray.origin.y, ray.direction.y, -amplitude, amplitude),
            (ray.origin.z, ray.direction.z, -self.depth, 0.0),
        ];
        let (mut lo, mut hi) = (lo, hi);
        for (origin, direction, min, max) in slabs {
            if direction == 0.0 {
                if origin < min || origin > max {
                    return None;
                }
                continue;
            }
            let (a, b) = ((min - origin) / direction, (max - origin) / direction);
            lo = lo.max(a.min(b));
            hi = hi.min(a.max(b));
        }
        (lo <= hi).then_some((lo, hi))
    }
}

struct WaveAlongRay {
    origin: DVec3,
    direction: DVec3,
    amplitude: f64,
    wavenumber: f64,
}

impl WaveAlongRay {
    fn new(sheet: &SineSheet, ray: &Ray) -> WaveAlongRay {
        WaveAlongRay {
            origin: ray.origin,
            direction: ray.direction,
            amplitude: sheet.amplitude,
            wavenumber: std::f64::consts::TAU / sheet.wavelength,
        }
    }

    fn phase(&self, t: f64) -> f64 {
        self.wavenumber * (self.origin.x + t * self.direction.x)
    }

    fn f(&self, t: f64) -> f64 {
        self.origin.y + t * self.direction.y - self.amplitude * self.phase(t).sin()
    }

    fn df(&self, t: f64) -> f64 {
        self.direction.y - self.amplitude * self.wavenumber * self.direction.x * self.phase(t).cos()
    }

    fn first_root(&self, lo: f64, hi: f64) -> Option<f64> {
        let cuts = self.quarter_wave_cuts(lo, hi)?;
        let mut start = lo;
        for end in cuts.chain([hi]) {
            // Rounding may put a cut a hair outside the interval.
            let end = end.clamp(start, hi);
            if let Some(t) = self.root_in_piece(start, end) {
                return Some(t);
            }
            start = end;
        }
        None
    }

    /// The t in (lo, hi) where the phase crosses a multiple of π/2, in increasing order.
    fn quarter_wave_cuts(&self, lo: f64, hi: f64) -> Option<impl Iterator<Item = f64> + use<>> {
        let rate = self.wavenumber * self.direction.x;
        let (p_lo, p_hi) = (self.phase(lo) / FRAC_PI_2, self.phase(hi) / FRAC_PI_2);
        let (first, last) = (p_lo.min(p_hi).floor() + 1.0, p_lo.max(p_hi).ceil() - 1.0);
        let count = if rate != 0.0 && last >= first {
            last - first + 1.0
        } else {
            0.0
        };
        if !count.is_finite() || count > MAX_QUARTER_WAVES {
            return None;
        }
        let start_phase = if rate > 0.0 { first } else { last };
        let step = rate.signum();
        let (x0, k, dx) = (self.origin.x, self.wavenumber, self.direction.x);
        Some((0..count as u64).map(move |i| {
            let phase = (start_phase + step * i as f64) * FRAC_PI_2;
            (phase / k - x0) / dx
        }))
    }

    /// The first root in [lo, hi], where f is convex or concave.
    fn root_in_piece(&self, lo: f64, hi: f64) -> Option<f64> {
        let (f_lo, f_hi) = (self.f(lo), self.f(hi));
        if f_lo == 0.0 {
            return Some(lo);
        }
        if (f_lo < 0.0) != (f_hi < 0.0) || f_hi == 0.0 {
            return Some(self.refine(lo, hi));
        }
        // Same sign at both ends: two roots or none, around the extremum (where f' changes sign).
        let (d_lo, d_hi) = (self.df(lo), self.df(hi));
        if (d_lo < 0.0) == (d_hi < 0.0) {
            return None;
        }
        let extremum = bisect_sign_change(|t| self.df(t), lo, hi);
        let f_extremum = self.f(extremum);
        ((f_extremum < 0.0) != (f_lo < 0.0) || f_extremum == 0.0).then(|| self.refine(lo, extremum))
    }

    fn refine(&self, lo: f64, hi: f64) -> f64 {
        safeguarded_root(|t| self.f(t), |t| self.df(t), lo, hi)
    }
}
