//! Tessellations that cover their true surface: every vertex pushed out to the convex side, so
//! chords lie outside the surface and every ray that meets the surface meets the mesh first
//! (exact coverage then drops the fragments whose ray misses the true surface).

use super::parametric::Parametric;
use super::{Mesh, Surface};
use glam::Vec3;

/// How far past the mesh's chord error (measured at triangle centres) vertices are pushed: the
/// farthest point of a chord from the surface lies near, not at, its centre.
const MARGIN: f32 = 1.5;

/// Pushes the mesh's vertices out to the convex side of `surface` by a margin over its chord
/// error; the rim of a paraboloid, the base of a cone and the edges of a wave move outwards
/// along the surface too, so their chords of the curved boundary cover it. The chord error becomes the new bound on how far
/// the mesh lies from the surface. Flat surfaces are left as they are (their meshes are exact).
pub fn push_out_to_hull(surface: &Surface, mesh: &mut Mesh) {
    if surface.is_flat() || mesh.chord_error == 0.0 {
        return;
    }
    let push = MARGIN * mesh.chord_error;
    for (position, uv) in mesh.positions.iter_mut().zip(&mesh.uvs) {
        let outwards = each_kind!(surface, s => s.hull_outwards(*uv, &s.frame(uv.x, uv.y)));
        *position += outwards * push;
    }
    mesh.chord_error += push;
}

/// Outwards along the surface past its boundary, for a vertex at the least (`at_min`) or the
/// greatest (`at_max`) value of the parameter whose tangent is `along`.
pub(super) fn past_edge(along: Vec3, at_min: bool, at_max: bool) -> Vec3 {
    let along = along.normalize_or_zero();
    if at_max {
        along
    } else if at_min {
        -along
    } else {
        Vec3::ZERO
    }
}

#[cfg(test)]
mod tests {
    use super::super::{AxisBasis, Cone, Paraboloid, Sphere, Tessellation, Torus};
    use super::*;
    use glam::{DVec3, Vec2};

    /// Every triangle's centre and edge midpoints lie outside (on the convex side of) the
    /// surface, or on it.
    fn assert_chords_outside(surface: &Surface, outside: impl Fn(Vec3) -> f32) {
        let mut mesh = surface.tessellate(Tessellation { density: 12 });
        push_out_to_hull(surface, &mut mesh);
        for triangle in &mesh.indices {
            let [a, b, c] = triangle.map(|i| mesh.positions[i as usize]);
            for p in [
                (a + b + c) / 3.0,
                (a + b) / 2.0,
                (b + c) / 2.0,
                (c + a) / 2.0,
            ] {
                assert!(outside(p) >= -1e-4, "{p} is {} inside", -outside(p));
            }
        }
    }

    #[test]
    fn a_spheres_hull_lies_outside_it() {
        let sphere = Surface::Sphere(Sphere {
            center: DVec3::ZERO,
            radius: 100.0,
        });
        assert_chords_outside(&sphere, |p| p.length() - 100.0);
    }

    #[test]
    fn a_cones_hull_lies_outside_it_apex_included() {
        let cone = Cone {
            apex: DVec3::ZERO,
            basis: AxisBasis::from_axis(-Vec3::Y),
            half_angle: 0.5,
            height: 200.0,
        };
        let (sin, cos) = cone.half_angle.sin_cos();
        // Signed distance from the infinite cone's side, positive outside.
        let outside = |p: Vec3| {
            let h = -p.y;
            let rho = Vec2::new(p.x, p.z).length();
            rho * cos - h * sin
        };
        assert_chords_outside(&Surface::Cone(cone), outside);
    }

    #[test]
    fn a_paraboloids_hull_lies_below_its_bowl() {
        let bowl = Paraboloid {
            apex: DVec3::ZERO,
            basis: AxisBasis::from_axis(Vec3::Y),
            curvature: 0.01,
            radius: 100.0,
        };
        // Below the bowl's surface is its convex side.
        let outside = |p: Vec3| 0.01 * (p.x * p.x + p.z * p.z) - p.y;
        assert_chords_outside(&Surface::Paraboloid(bowl), outside);
    }

    /// Its inner half is a saddle: the chords around the tube sag into it, those along the
    /// ring bulge out of it. Pushed out of the tube, none is left inside.
    #[test]
    fn a_toruss_hull_lies_outside_its_tube_saddle_included() {
        let torus = Torus {
            center: DVec3::ZERO,
            basis: AxisBasis::from_axis(Vec3::Y),
            major_radius: 100.0,
            minor_radius: 60.0,
        };
        let outside =
            |p: Vec3| Vec2::new(Vec2::new(p.x, p.z).length() - 100.0, p.y).length() - 60.0;
        assert_chords_outside(&Surface::Torus(torus), outside);
    }
}
