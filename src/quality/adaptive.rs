//! Screen-space adaptive tessellation: per object, the density at which every chord of the mesh
//! lies within a pixel tolerance of the surface in this view.
//!
//! The chord error of an edge is the distance from the surface point at the edge's (u,v)
//! midpoint to the chord's midpoint (the sag, r·(1 − cos(π/2d)) on a circle of radius r cut d
//! times per half turn), projected to pixels at that point's depth. It falls as 1/d², so one
//! measurement predicts the density needed; the prediction is then checked by measuring again.
//!
//! Precision: f32 as the meshes are. Sags of a tenth of a pixel are ~1e-4 of an object's size,
//! well above f32's 6e-8 relative step at these magnitudes.

use crate::raster::Viewport;
use crate::scene::Camera;
use crate::surface::{Surface, Tessellation};
use glam::{DVec3, Vec2, Vec3};

/// Densest adaptive tessellation: a sphere at 512 has 512 K triangles.
pub const MAX_ADAPTIVE_DENSITY: u32 = 512;
/// Margin on the 1/d² prediction, so one refinement usually suffices.
const PREDICTION_MARGIN: f32 = 1.1;

/// The density, refined from `start` (never below it) by the 1/d² law up to
/// `MAX_ADAPTIVE_DENSITY`, at which the projected chord error is at most `tolerance_px`.
pub fn adaptive_density(
    surface: &Surface,
    camera: &Camera,
    viewport: Viewport,
    tolerance_px: f32,
    start: u32,
) -> u32 {
    let tolerance = tolerance_px.max(1e-3);
    let mut density = start.clamp(1, MAX_ADAPTIVE_DENSITY);
    for _ in 0..8 {
        let error = projected_chord_error(surface, density, camera, viewport);
        if error <= tolerance || density >= MAX_ADAPTIVE_DENSITY {
            break;
        }
        let predicted = density as f32 * (error / tolerance).sqrt() * PREDICTION_MARGIN;
        density = (predicted.ceil() as u32).clamp(density + 1, MAX_ADAPTIVE_DENSITY);
    }
    density
}

/// The largest distance, in pixels of this view, between a mesh edge's midpoint and the surface
/// at the edge's (u,v) midpoint, over the edges in front of the near plane.
pub fn projected_chord_error(
    surface: &Surface,
    density: u32,
    camera: &Camera,
    viewport: Viewport,
) -> f32 {
    let mesh = surface.tessellate(Tessellation { density });
    let midpoints = edge_midpoint_uvs(&mesh.uvs, &mesh.indices);
    let on_surface: Vec<Vec3> = midpoints
        .iter()
        .map(|uv| surface.frame(uv.x, uv.y).p)
        .collect();
    let triangles = (&mesh.positions[..], &mesh.indices[..]);
    worst_projected_sag(triangles, &on_surface, surface.origin(), camera, viewport)
}

/// The (u,v) midpoint of every edge of every triangle (`indices` into vertices at `uvs`),
/// three a triangle in order.
pub fn edge_midpoint_uvs(uvs: &[Vec2], indices: &[[u32; 3]]) -> Vec<Vec2> {
    let midpoint = |tri: &[u32; 3], (a, b): (usize, usize)| {
        (uvs[tri[a] as usize] + uvs[tri[b] as usize]) / 2.0
    };
    (indices.iter())
        .flat_map(|tri| EDGES.map(|edge| midpoint(tri, edge)))
        .collect()
}

const EDGES: [(usize, usize); 3] = [(0, 1), (1, 2), (2, 0)];

/// The largest distance in pixels between an edge's midpoint and `on_surface`, the surface at
/// its (u,v) midpoint (in `edge_midpoint_uvs`'s order, relative to `anchor`), over the edges in
/// front of the near plane of the triangles (`indices` into vertices at `positions`).
pub fn worst_projected_sag(
    (positions, indices): (&[Vec3], &[[u32; 3]]),
    on_surface: &[Vec3],
    anchor: DVec3,
    camera: &Camera,
    viewport: Viewport,
) -> f32 {
    let origin = (anchor - camera.eye).as_vec3();
    let forward = camera.forward();
    let half_fov = (camera.vfov_degrees.clamp(1e-3, 179.0).to_radians() / 2.0).tan();
    let pixels_per_unit_at_depth_1 = viewport.height as f32 / (2.0 * half_fov);
    let mut worst: f32 = 0.0;
    let edges = (indices.iter()).flat_map(|tri| EDGES.map(|(a, b)| (tri[a], tri[b])));
    for ((ia, ib), &on_surface) in edges.zip(on_surface) {
        let chord = (positions[ia as usize] + positions[ib as usize]) / 2.0;
        let depth = (origin + on_surface).dot(forward);
        if depth > camera.near {
            let sag = on_surface.distance(chord);
            worst = worst.max(sag * pixels_per_unit_at_depth_1 / depth);
        }
    }
    if worst.is_finite() { worst } else { 0.0 }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::Sphere;
    use glam::{DVec3, Vec3};

    fn camera_at(distance: f64) -> Camera {
        Camera {
            eye: DVec3::new(0.0, 0.0, distance),
            target: DVec3::ZERO,
            up: Vec3::Y,
            vfov_degrees: 40.0,
            near: 1.0,
            far: 1e5,
        }
    }

    fn sphere() -> Surface {
        Surface::Sphere(Sphere {
            center: DVec3::ZERO,
            radius: 100.0,
        })
    }

    const VIEW: Viewport = Viewport {
        width: 320,
        height: 240,
    };

    #[test]
    fn the_chosen_density_meets_the_tolerance_and_half_of_it_does_not() {
        for tolerance in [1.0, 0.5, 0.1] {
            let camera = camera_at(400.0);
            let d = adaptive_density(&sphere(), &camera, VIEW, tolerance, 4);
            let error = projected_chord_error(&sphere(), d, &camera, VIEW);
            let coarser = projected_chord_error(&sphere(), d / 2, &camera, VIEW);
            assert!(error <= tolerance, "d {d}: {error} px > {tolerance}");
            assert!(
                coarser > tolerance,
                "d {d} is not near minimal: d/2 gives {coarser} px"
            );
        }
    }

    #[test]
    fn the_error_follows_the_circle_sag_formula() {
        // The equator's chords along u sag by r(1 − cos(π/2d)), nearest at depth 400 − r; the
        // cells' diagonals are √2 longer, so sag up to twice as much.
        let (camera, d) = (camera_at(400.0), 16);
        let pixels_per_unit = 240.0 / (2.0 * 20f32.to_radians().tan());
        let sag = 100.0 * (1.0 - (std::f32::consts::PI / (2.0 * d as f32)).cos());
        let predicted = sag * pixels_per_unit / 300.0;
        let measured = projected_chord_error(&sphere(), d, &camera, VIEW);
        let ratio = measured / predicted;
        assert!((0.99..2.2).contains(&ratio), "{measured} vs {predicted}");
    }

    #[test]
    fn far_objects_and_small_viewports_get_coarser_meshes() {
        let near = adaptive_density(&sphere(), &camera_at(300.0), VIEW, 0.5, 4);
        let far = adaptive_density(&sphere(), &camera_at(3000.0), VIEW, 0.5, 4);
        let small = Viewport {
            width: 80,
            height: 60,
        };
        let tiny = adaptive_density(&sphere(), &camera_at(300.0), small, 0.5, 4);
        assert!(
            far < near && tiny < near,
            "near {near}, far {far}, tiny {tiny}"
        );
    }

    #[test]
    fn refinement_never_goes_below_the_start() {
        let far = camera_at(30000.0);
        assert_eq!(adaptive_density(&sphere(), &far, VIEW, 1.0, 64), 64);
        assert!(adaptive_density(&sphere(), &camera_at(300.0), VIEW, 0.01, 64) > 64);
    }
}
