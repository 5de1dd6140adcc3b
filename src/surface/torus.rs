//! The torus, the one surface with both curvatures (convex outside, a saddle inside the ring):
//! P(u,v), its partial derivatives and normal, its exact ray hits (a quartic along the ray) and
//! the inverse of its parametrisation.

use super::grid_shape::GridShape;
use super::parametric::Parametric;
use super::ray_hits::{Hit, Ray, polynomial_roots_in};
use super::seed_angles::{SEED_UNITS_PER_RADIAN, SEED_UNITS_PER_RADIAN_F64, azimuth, azimuth_u};
use super::{AxisBasis, Domain, Frame};
use glam::{DVec3, Vec2, Vec3};
use std::ops::RangeInclusive;

/// A ring torus around `basis.axis`: the circle of radius `minor_radius` swept around the axis
/// at `major_radius` from it (major > minor > 0). Domain, both in the sphere's seed units (720
/// a turn): u ∈ [0, 720) azimuth around the axis, as the sphere's; v ∈ [0, 720) angle around the
/// tube from its top (v = 0 on the side the axis points to, 180 on the outer equator, 540 on the
/// inner). The normal points out of the tube.
#[derive(Clone, Debug, PartialEq)]
pub struct Torus {
    pub center: DVec3,
    pub basis: AxisBasis,
    pub major_radius: f32,
    pub minor_radius: f32,
}

impl Torus {
    /// The squared distance from the tube's centre circle, less r², of a point along (e1, axis,
    /// e2): negative inside the tube.
    fn inside_tube(&self, q: DVec3) -> f64 {
        let (big, small) = (self.major_radius as f64, self.minor_radius as f64);
        let rho = q.x.hypot(q.z);
        (rho - big).powi(2) + q.y * q.y - small * small
    }
}

impl Parametric for Torus {
    fn kind(&self) -> &'static str {
        "torus"
    }

    fn origin(&self) -> DVec3 {
        self.center
    }

    fn origin_mut(&mut self) -> &mut DVec3 {
        &mut self.center
    }

    fn domain(&self) -> Domain {
        Domain {
            min: Vec2::ZERO,
            max: Vec2::splat(720.0),
        }
    }

    #[inline]
    fn frame(&self, u: f32, v: f32) -> Frame {
        let b = &self.basis;
        let (sin_phi, cos_phi) = super::sin_cos(azimuth(u));
        let (sin_theta, cos_theta) = super::sin_cos(v / SEED_UNITS_PER_RADIAN);
        let radial = b.to_world(sin_phi, 0.0, cos_phi);
        let tangent = b.to_world(cos_phi, 0.0, -sin_phi);
        let n = radial * sin_theta + b.axis * cos_theta;
        let (big, small) = (self.major_radius, self.minor_radius);
        Frame {
            p: radial * big + n * small,
            pu: tangent * ((big + small * sin_theta) / SEED_UNITS_PER_RADIAN),
            pv: (radial * cos_theta - b.axis * sin_theta) * (small / SEED_UNITS_PER_RADIAN),
            n,
        }
    }

    /// Around the tube, 1/r; along the inner equator, 1/(R − r), larger when the hole is small.
    fn max_curvature(&self) -> f32 {
        let (big, small) = (self.major_radius, self.minor_radius);
        (1.0 / small).max(1.0 / (big - small).max(f32::MIN_POSITIVE))
    }

    fn encloses_eye_at(&self, eye_from_anchor: DVec3) -> Option<bool> {
        Some(self.inside_tube(self.basis.local(eye_from_anchor)) > 0.0)
    }

    /// A full turn each way, closed in both: no collapsed rows.
    fn grid_shape(&self, density: u32) -> GridShape {
        GridShape::flat(2 * density, 2 * density)
    }

    /// Out of the tube everywhere: on the outer half both curvatures bend away from the normal;
    /// on the inner (saddle) half the chords around the tube still sag inwards, and the push
    /// covers them, while those along the ring already lie outside.
    fn hull_outwards(&self, _uv: Vec2, frame: &Frame) -> Vec3 {
        frame.n
    }

    /// (|p|² + R² − r²)² = 4R²·ρ² along the ray is a quartic in t. It is formed about the ray's
    /// point nearest the centre, with a unit direction, so its coefficients stay the size of
    /// the torus however far the eye is; every hit lies within R + r of the centre, which
    /// bounds the interval its roots are isolated in.
    fn intersect(&self, ray: &Ray, range: &RangeInclusive<f64>) -> Option<Hit> {
        let (big, small) = (self.major_radius as f64, self.minor_radius as f64);
        let length = ray.direction.length();
        let d = self.basis.local(ray.direction) / length;
        let o = self.basis.local(ray.origin);
        let nearest = -o.dot(d);
        let q = o + d * nearest;
        let reach2 = (big + small).powi(2) - q.length_squared();
        if reach2.is_nan() || reach2 < 0.0 {
            return None;
        }
        let reach = reach2.sqrt() * (1.0 + 1e-9);
        let c = q.length_squared() + big * big - small * small;
        let four_r2 = 4.0 * big * big;
        let coefficients = [
            c * c - four_r2 * (q.x * q.x + q.z * q.z),
            -2.0 * four_r2 * (q.x * d.x + q.z * d.z),
            2.0 * c - four_r2 * (d.x * d.x + d.z * d.z),
            0.0,
            1.0,
        ];
        let mut roots = [0.0; 4];
        let count = polynomial_roots_in(&coefficients, -reach, reach, &mut roots);
        roots[..count]
            .iter()
            .map(|s| (nearest + s) / length)
            .find(|t| range.contains(t))
            .map(|t| Hit {
                t,
                uv: self.uv_at(ray.at(t)),
            })
    }

    /// u from the azimuth about the axis, v from the angle around the tube.
    fn uv_at(&self, p: DVec3) -> Vec2 {
        let q = self.basis.local(p);
        let from_tube_circle = q.x.hypot(q.z) - self.major_radius as f64;
        let theta = from_tube_circle.atan2(q.y);
        let v = (theta * SEED_UNITS_PER_RADIAN_F64).rem_euclid(720.0) as f32;
        Vec2::new(azimuth_u(q.x, q.z), v.min(720.0f32.next_down()))
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::assert_frame_matches_finite_differences;
    use super::*;

    fn ring() -> Torus {
        Torus {
            center: DVec3::new(3.0, -2.0, 1.0),
            basis: AxisBasis::from_axis(Vec3::new(0.2, 1.0, 0.4)),
            major_radius: 200.0,
            minor_radius: 80.0,
        }
    }

    #[test]
    fn frame_is_consistent_and_the_normal_leaves_the_tube() {
        let t = ring();
        assert_frame_matches_finite_differences(|u, v| t.frame(u, v), t.domain(), 0.02);
        for (u, v) in [(0.0, 0.0), (100.0, 180.0), (300.0, 540.0), (719.0, 719.0)] {
            let f = t.frame(u, v);
            let radial = (f.p - t.basis.axis * f.p.dot(t.basis.axis)).normalize();
            let tube_centre = radial * t.major_radius;
            let out = (f.p - tube_centre).normalize();
            assert!(f.n.dot(out) > 0.9999, "at ({u}, {v})");
            assert!(((f.p - tube_centre).length() - t.minor_radius).abs() < 1e-3);
        }
    }

    #[test]
    fn v_runs_from_the_top_over_the_outer_equator() {
        let t = Torus {
            center: DVec3::ZERO,
            basis: AxisBasis::from_axis(Vec3::Y),
            major_radius: 2.0,
            minor_radius: 1.0,
        };
        assert!((t.frame(180.0, 0.0).p - Vec3::new(0.0, 1.0, 2.0)).length() < 1e-5);
        assert!((t.frame(180.0, 180.0).p - Vec3::new(0.0, 0.0, 3.0)).length() < 1e-5);
        assert!((t.frame(180.0, 540.0).p - Vec3::new(0.0, 0.0, 1.0)).length() < 1e-5);
    }

    #[test]
    fn the_eye_is_outside_unless_within_the_tube() {
        let t = ring();
        assert_eq!(t.encloses_eye_at(DVec3::ZERO), Some(true));
        let in_tube = t.frame(100.0, 200.0).p - t.frame(100.0, 200.0).n * 10.0;
        assert_eq!(t.encloses_eye_at(in_tube.as_dvec3()), Some(false));
        assert_eq!(t.encloses_eye_at(DVec3::splat(1000.0)), Some(true));
    }

    /// A ray along the axis passes through the hole; one across the ring through the centre
    /// meets it four times, the first at the outer equator.
    #[test]
    fn rays_through_the_hole_and_across_the_ring() {
        let t = Torus {
            center: DVec3::ZERO,
            basis: AxisBasis::from_axis(Vec3::Y),
            major_radius: 2.0,
            minor_radius: 0.5,
        };
        let along_axis = Ray {
            origin: DVec3::new(0.0, 100.0, 0.0),
            direction: DVec3::new(0.0, -3.0, 0.0),
        };
        assert_eq!(t.intersect(&along_axis, &(0.0..=1e9)), None);
        let across = Ray {
            origin: DVec3::new(0.0, 0.0, 1e5),
            direction: DVec3::new(0.0, 0.0, -2.0),
        };
        let hit = t.intersect(&across, &(0.0..=1e9)).expect("meets the ring");
        assert!((across.at(hit.t).z - 2.5).abs() < 1e-9, "{hit:?}");
        assert!((hit.uv - Vec2::new(180.0, 180.0)).abs().max_element() < 1e-3);
        // From inside the hole: the inner equator is next.
        let from_hole = t.intersect(&across, &(hit.t + 1e-6..=1e9)).unwrap();
        assert!((across.at(from_hole.t).z - 1.5).abs() < 1e-9);
    }
}
