//! The sphere in the seed's angle units: P(u,v), its partial derivatives and normal, its exact
//! ray hits and the inverse of its parametrisation.

use super::grid_shape::GridShape;
use super::parametric::Parametric;
use super::ray_hits::{Hit, Ray, Rays, TrueHit, nearest_hit, quadratic_roots};
use super::seed_angles::{
    SEED_UNITS_PER_RADIAN, SEED_UNITS_PER_RADIAN_F64, azimuth, azimuth_u, azimuth_u_f32,
};
use super::true_hit::{Quadric, quadric_hits};
use super::{Domain, Frame, Frames, atan2};
use glam::{DVec3, Vec2, Vec3};
use std::ops::RangeInclusive;

/// A sphere. Domain: u ∈ [0, 720) azimuth, v ∈ [0, 360] polar angle from the +Y pole, both in
/// seed units. As in the seed, u = 180 faces +Z (the default camera), the front hemisphere is
/// u ∈ [0, 360] and u grows towards +X;
/// v grows downwards. Pu vanishes at the poles; the normal there is the pole's direction.
#[derive(Clone, Debug, PartialEq)]
pub struct Sphere {
    pub center: DVec3,
    pub radius: f32,
}

impl Sphere {
    pub const DOMAIN: Domain = Domain {
        min: Vec2::ZERO,
        max: Vec2::new(720.0, 360.0),
    };

    /// A chunk's frames from its angles, as p, Pu, Pv and n, each as x, y and z lanes.
    fn chunk_frames(&self, angles: &[[f32; CHUNK]; 4], out: &mut [[f32; CHUNK]; 12]) {
        crate::simd::widest(
            #[inline(always)]
            || {
                let [sin_phi, cos_phi, sin_theta, cos_theta] = angles;
                for k in 0..CHUNK {
                    let frame =
                        self.frame_from_angles(sin_phi[k], cos_phi[k], sin_theta[k], cos_theta[k]);
                    let [px, py, pz, pux, puy, puz, pvx, pvy, pvz, nx, ny, nz] = out;
                    (px[k], py[k], pz[k]) = frame.p.into();
                    (pux[k], puy[k], puz[k]) = frame.pu.into();
                    (pvx[k], pvy[k], pvz[k]) = frame.pv.into();
                    (nx[k], ny[k], nz[k]) = frame.n.into();
                }
            },
        );
    }

    #[inline(always)]
    fn frame_from_angles(
        &self,
        sin_phi: f32,
        cos_phi: f32,
        sin_theta: f32,
        cos_theta: f32,
    ) -> Frame {
        let n = Vec3::new(sin_theta * sin_phi, cos_theta, sin_theta * cos_phi);
        let k = self.radius / SEED_UNITS_PER_RADIAN;
        Frame {
            p: n * self.radius,
            pu: Vec3::new(cos_phi, 0.0, -sin_phi) * (k * sin_theta),
            pv: Vec3::new(cos_theta * sin_phi, -sin_theta, cos_theta * cos_phi) * k,
            n,
        }
    }
}

impl Parametric for Sphere {
    fn kind(&self) -> &'static str {
        "sphere"
    }

    fn origin(&self) -> DVec3 {
        self.center
    }

    fn origin_mut(&mut self) -> &mut DVec3 {
        &mut self.center
    }

    fn domain(&self) -> Domain {
        Sphere::DOMAIN
    }

    #[inline]
    fn frame(&self, u: f32, v: f32) -> Frame {
        let (sin_phi, cos_phi) = super::sin_cos(azimuth(u));
        let (sin_theta, cos_theta) = super::sin_cos(v / SEED_UNITS_PER_RADIAN);
        self.frame_from_angles(sin_phi, cos_phi, sin_theta, cos_theta)
    }

    /// A chunk's sines, cosines and frames are computed in loops of plain arrays, which the
    /// compiler turns into SIMD: the same polynomials and products, so the same frames to the bit.
    fn frames(&self, count: usize, uv: impl Fn(usize) -> Vec2, out: &mut Frames) {
        out.reserve(count);
        // Made once, not per chunk: zeroed per chunk, they cost more than the frames.
        let (mut u, mut v) = ([0.0f32; CHUNK], [0.0f32; CHUNK]);
        let mut angles = [[0.0f32; CHUNK]; 4];
        let mut coordinates = [[0.0f32; CHUNK]; 12];
        for first in (0..count).step_by(CHUNK) {
            let len = CHUNK.min(count - first);
            for k in 0..len {
                (u[k], v[k]) = uv(first + k).into();
            }
            chunk_angles(&u, &v, &mut angles);
            self.chunk_frames(&angles, &mut coordinates);
            out.extend_from_lanes(&coordinates, len);
        }
    }

    fn max_curvature(&self) -> f32 {
        1.0 / self.radius
    }

    fn encloses_eye_at(&self, eye_from_anchor: DVec3) -> Option<bool> {
        Some(eye_from_anchor.length() > self.radius as f64)
    }

    /// Both poles are fans: a single row would have to be a fan at both ends at once.
    fn grid_shape(&self, density: u32) -> GridShape {
        GridShape {
            cells_u: 2 * density,
            cells_v: density.max(2),
            collapsed_v_min: true,
            collapsed_v_max: true,
        }
    }

    fn hull_outwards(&self, _uv: Vec2, frame: &Frame) -> Vec3 {
        frame.n
    }

    fn intersect(&self, ray: &Ray, range: &RangeInclusive<f64>) -> Option<Hit> {
        let r = self.radius as f64;
        let (o, d) = (ray.origin, ray.direction);
        let roots = quadratic_roots(d.dot(d), 2.0 * o.dot(d), o.dot(o) - r * r);
        nearest_hit(roots, range, |t| Some(self.uv_at(ray.at(t))))
    }

    /// u from the azimuth (φ = atan2(x, z), u = (φ + π/2)·360/π in [0, 720)), v from the polar
    /// angle (acos(y/r)·360/π), as the seed computes them.
    fn uv_at(&self, p: DVec3) -> Vec2 {
        let n = p.normalize_or(DVec3::Y);
        let v = n.y.clamp(-1.0, 1.0).acos() * SEED_UNITS_PER_RADIAN_F64;
        Vec2::new(azimuth_u(n.x, n.z), v as f32)
    }

    fn true_hits(&self, rays: &Rays, hits: &mut [TrueHit], found: &mut [bool]) {
        quadric_hits(&SphereQuadric(self), rays, hits, found);
    }
}

/// |q + s·d|² = r².
struct SphereQuadric<'a>(&'a Sphere);

impl Quadric for SphereQuadric<'_> {
    #[inline(always)]
    fn local(&self, v: DVec3) -> DVec3 {
        v
    }

    /// Formed in f64 around the chord point, |q|² − r² keeps the chord point's small distance
    /// from the surface.
    #[inline(always)]
    fn coefficients(&self, q: DVec3, d: DVec3) -> [f64; 3] {
        let r = self.0.radius as f64;
        [d.dot(d), 2.0 * q.dot(d), q.dot(q) - r * r]
    }

    #[inline(always)]
    fn uv(&self, p: Vec3) -> Vec2 {
        let v = atan2((p.x * p.x + p.z * p.z).sqrt(), p.y) * SEED_UNITS_PER_RADIAN;
        Vec2::new(azimuth_u_f32(p.x, p.z), v)
    }
}

/// Fragments whose angles are computed together.
const CHUNK: usize = 64;

/// sin φ, cos φ, sin θ, cos θ of a chunk of (u, v), in that order.
fn chunk_angles(u: &[f32; CHUNK], v: &[f32; CHUNK], angles: &mut [[f32; CHUNK]; 4]) {
    crate::simd::widest(
        #[inline(always)]
        || chunk_angles_here(u, v, angles),
    );
}

/// The loop, inlined into `chunk_angles`'s call so it is compiled for the widest SIMD the CPU
/// has.
#[inline(always)]
fn chunk_angles_here(u: &[f32; CHUNK], v: &[f32; CHUNK], angles: &mut [[f32; CHUNK]; 4]) {
    let [sin_phi, cos_phi, sin_theta, cos_theta] = angles;
    for k in 0..CHUNK {
        (sin_phi[k], cos_phi[k]) = super::sin_cos(azimuth(u[k]));
        (sin_theta[k], cos_theta[k]) = super::sin_cos(v[k] / SEED_UNITS_PER_RADIAN);
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::assert_frame_matches_finite_differences;
    use super::*;

    /// The batch (its angles SIMD-computed, AVX2 where the CPU has it) gives `frame`'s bits,
    /// over more than one chunk, the whole domain, its edges and beyond.
    #[test]
    fn batch_frames_are_single_frames() {
        let s = Sphere {
            center: DVec3::new(1.0, -2.0, 3.0),
            radius: 280.0,
        };
        let mut uvs: Vec<Vec2> = (0..150)
            .map(|i| Vec2::new(i as f32 * 4.9 - 10.0, i as f32 * 2.5 - 5.0))
            .collect();
        uvs.extend([0.0, 180.0, 360.0, 720.0, -720.0, 1e4].map(|u| Vec2::new(u, u / 2.0)));
        let mut batch = Frames::default();
        s.frames(uvs.len(), |k| uvs[k], &mut batch);
        assert_eq!(batch.len(), uvs.len());
        let bits = |f: &Frame| [f.p, f.pu, f.pv, f.n].map(|v| v.to_array().map(f32::to_bits));
        for (uv, got) in uvs.iter().zip(batch.iter()) {
            assert_eq!(bits(&got), bits(&s.frame(uv.x, uv.y)), "at {uv}");
        }
    }

    #[test]
    fn matches_the_seed_angles() {
        let s = Sphere {
            center: DVec3::ZERO,
            radius: 280.0,
        };
        // Facing the camera (+Z) at the equator: the seed's uu = (π/2 + atan(0))·360/π = 180.
        let f = s.frame(180.0, 180.0);
        assert!(
            (f.p - Vec3::new(0.0, 0.0, 280.0)).length() < 1e-3,
            "{:?}",
            f.p
        );
        // The +Y pole is v = 0 (seed: vv = acos(y/r)·360/π).
        assert!((s.frame(123.0, 0.0).p - Vec3::new(0.0, 280.0, 0.0)).length() < 1e-3);
        // u grows towards +X.
        assert!(s.frame(200.0, 180.0).p.x > 0.0);
    }

    #[test]
    fn frame_is_consistent() {
        let s = Sphere {
            center: DVec3::ZERO,
            radius: 3.0,
        };
        assert_frame_matches_finite_differences(|u, v| s.frame(u, v), Sphere::DOMAIN, 0.05);
    }

    #[test]
    fn poles_have_finite_unit_normals() {
        let s = Sphere {
            center: DVec3::ZERO,
            radius: 1.0,
        };
        for u in [0.0, 100.0, 719.9] {
            for v in [0.0, 360.0] {
                let f = s.frame(u, v);
                assert!((f.n.length() - 1.0).abs() < 1e-6);
                assert!(f.n.y.abs() > 0.999);
            }
        }
    }
}
