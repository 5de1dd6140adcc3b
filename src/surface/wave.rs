//! The wave surface (a corrugated sheet): P(u,v), its partial derivatives and normal, its exact
//! ray hits, the inverse of its parametrisation, and the Newton steps that move a fragment from
//! the tessellation to it.

use super::grid_shape::GridShape;
use super::hull::past_edge;
use super::parametric::Parametric;
use super::ray_hits::{Hit, Ray, Rays, SineSheet, TrueHit};
use super::{Domain, Frame, normalize_or};
use glam::{DVec3, Vec2, Vec3};
use std::f32::consts::{PI, TAU};
use std::ops::RangeInclusive;

/// Newton steps the wave is given before its fragment keeps the tessellation's (u,v).
pub const WAVE_NEWTON_STEPS: u32 = 8;

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
    fn wavenumber(&self) -> f32 {
        2.0 * PI / self.wavelength
    }

    /// Cells along u: `density` cells per half wavelength of phase (π radians), as for the spheres.
    fn cells_along_u(&self, density: u32) -> u32 {
        let half_waves = (self.wavenumber() * self.size.x / PI).max(1.0);
        (half_waves * density as f32).ceil().clamp(1.0, 65536.0) as u32
    }

    fn sheet(&self) -> SineSheet {
        SineSheet {
            amplitude: self.amplitude as f64,
            wavelength: self.wavelength as f64,
            width: self.size.x as f64,
            depth: self.size.y as f64,
        }
    }

    /// y = A·sin(k·x) along the ray, by Newton steps from the chord point. Each step is held to
    /// an eighth of a wavelength in x (and in s where the ray runs along the crests), so it
    /// cannot leap over a crest to a farther sheet of the surface; steps that have not settled
    /// by `WAVE_NEWTON_STEPS` give `None`, and the fragment keeps its tessellated (u,v); so does
    /// a hit past the sheet's edges.
    fn newton_hit(&self, q: DVec3, d: DVec3) -> Option<(Vec2, f64)> {
        let amplitude = self.amplitude as f64;
        let k = (TAU / self.wavelength) as f64;
        let f = |s: f64| q.y + s * d.y - amplitude * (k * (q.x + s * d.x)).sin();
        let df = |s: f64| d.y - amplitude * k * d.x * (k * (q.x + s * d.x)).cos();
        let eighth = self.wavelength as f64 / 8.0;
        let max_step = eighth / d.x.abs().max(d.length() * 1e-3);
        let tolerance = 1e-6 * (amplitude.abs() + q.length());
        let mut s = 0.0;
        for _ in 0..WAVE_NEWTON_STEPS {
            let value = f(s);
            if value.abs() <= tolerance {
                // One more step: within the tolerance Newton converges quadratically, so this
                // puts the hit at the root to f64 rounding rather than anywhere within the
                // tolerance, and the (u,v) no longer depends on where along the ray the steps
                // began.
                let polish = -value / df(s);
                if polish.is_finite() {
                    s += polish;
                }
                let p = q + d * s;
                let uv = Vec2::new(p.x as f32, -p.z as f32);
                let inside = uv.cmpge(Vec2::ZERO).all() && uv.cmple(self.size).all();
                return inside.then_some((uv, s));
            }
            let step = (-value / df(s)).clamp(-max_step, max_step);
            if !step.is_finite() {
                return None;
            }
            s += step;
        }
        None
    }
}

impl Parametric for Wave {
    fn kind(&self) -> &'static str {
        "wave surface"
    }

    fn origin(&self) -> DVec3 {
        self.origin
    }

    fn origin_mut(&mut self) -> &mut DVec3 {
        &mut self.origin
    }

    fn domain(&self) -> Domain {
        Domain {
            min: Vec2::ZERO,
            max: self.size,
        }
    }

    #[inline]
    fn frame(&self, u: f32, v: f32) -> Frame {
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

    fn max_curvature(&self) -> f32 {
        let k = std::f32::consts::TAU / self.wavelength;
        self.amplitude.abs() * k * k
    }

    fn grid_shape(&self, density: u32) -> GridShape {
        GridShape::flat(self.cells_along_u(density), 1)
    }

    /// Crests bulge up, troughs down: out along the curvature's sign; and past the sheet's
    /// edges, whose profile curves as the crests do.
    fn hull_outwards(&self, uv: Vec2, frame: &Frame) -> Vec3 {
        let phase = std::f32::consts::TAU * uv.x / self.wavelength;
        let bulge = frame.n * (phase.sin() * self.amplitude.signum());
        bulge
            + past_edge(frame.pu, uv.x == 0.0, uv.x == self.size.x)
            + past_edge(frame.pv, uv.y == 0.0, uv.y == self.size.y)
    }

    fn intersect(&self, ray: &Ray, range: &RangeInclusive<f64>) -> Option<Hit> {
        let t = self.sheet().first_hit(ray, range)?;
        Some(Hit {
            t,
            uv: self.uv_at(ray.at(t)),
        })
    }

    /// u = x, v = −z.
    fn uv_at(&self, p: DVec3) -> Vec2 {
        Vec2::new(p.x as f32, -p.z as f32)
    }

    /// The hit the Newton steps reach from the tessellation's point.
    fn true_hits(&self, rays: &Rays, hits: &mut [TrueHit], found: &mut [bool]) {
        for k in 0..rays.directions.len() {
            let hit = self.newton_hit(rays.chord(k), rays.directions[k]);
            let hit = hit.map(|(uv, s)| TrueHit {
                uv,
                depth: (rays.depths[k] as f64 + s) as f32,
            });
            found[k] = hit.is_some_and(|h| h.depth > 0.0);
            hits[k] = hit.unwrap_or_default();
        }
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
