//! The wave surface (a corrugated sheet): P(u,v), its partial derivatives and normal.

use super::{Domain, Frame, normalize_or};
use glam::{DVec3, Vec2, Vec3};
use std::f32::consts::PI;

/// A corrugated sheet, height = amplitude·sin(k·x) with k = 2π/wavelength, in world axes: u runs
/// along +X, v along −Z (away from the default camera), the height along +Y.
/// Domain: u ∈ [0, width], v ∈ [0, depth] in world units. The normal points up.
#[derive(Clone, Debug, PartialEq)]
pub struct Wave {
    pub origin: DVec3,
    pub size: Vec2,
    pub amplitude: f32,
    pub wavelength: f32,
}

impl Wave {
    pub fn domain(&self) -> Domain {
        Domain {
            min: Vec2::ZERO,
            max: self.size,
        }
    }

    fn wavenumber(&self) -> f32 {
        2.0 * PI / self.wavelength
    }

    #[inline]
    pub fn frame(&self, u: f32, v: f32) -> Frame {
        let k = self.wavenumber();
        let (sin_ku, cos_ku) = super::sin_cos(k * u);
        let slope = self.amplitude * k * cos_ku;
        Frame {
            p: Vec3::new(u, self.amplitude * sin_ku, -v),
            pu: Vec3::new(1.0, slope, 0.0),
            pv: Vec3::new(0.0, 0.0, -1.0),
            n: normalize_or(Vec3::new(-slope, 1.0, 0.0), Vec3::Y),
        }
    }

    /// Cells along u: `density` cells per half wavelength of phase (π radians), as for the spheres.
    pub(super) fn cells_along_u(&self, density: u32) -> u32 {
        let half_waves = (self.wavenumber() * self.size.x / PI).max(1.0);
        (half_waves * density as f32).ceil().clamp(1.0, 65536.0) as u32
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::assert_frame_matches_finite_differences;
    use super::*;

    #[test]
    fn frame_is_consistent() {
        let w = Wave {
            origin: DVec3::ZERO,
            size: Vec2::new(400.0, 300.0),
            amplitude: 12.0,
            wavelength: 100.0,
        };
        assert_frame_matches_finite_differences(|u, v| w.frame(u, v), w.domain(), 0.02);
        assert!(w.frame(0.0, 0.0).n.y > 0.0);
    }
}
