//! Tessellation: a surface's (u,v) grid cut into an indexed triangle mesh.

use super::grid_shape::GridShape;
use super::parametric::Parametric;
use glam::{Vec2, Vec3};

/// How finely curved surfaces are cut into triangles: `density` cells per π radians of turning
/// (a sphere gets 2·density × density cells). Planar surfaces always use the fewest triangles,
/// since perspective-correct interpolation is exact on them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Tessellation {
    pub density: u32,
}

impl Default for Tessellation {
    fn default() -> Self {
        Tessellation { density: 64 }
    }
}

/// An indexed triangle mesh in a surface's local coordinates, with each vertex's (u,v).
/// Triangles wind counter-clockwise around the surface normal (seen from the side it points to).
#[derive(Clone, Debug, Default)]
pub struct Mesh {
    pub positions: Vec<Vec3>,
    pub uvs: Vec<Vec2>,
    pub indices: Vec<[u32; 3]>,
    /// The farthest a triangle's centroid lies from the surface at its centroid's (u,v): how far
    /// the chords stray from the true surface (0 for planar surfaces).
    pub chord_error: f32,
}

/// Tessellates a surface into a (u,v) grid. Seam vertices (u = min and u = max) are separate, so u
/// wraps without a crack in the interpolated parameters. A collapsed row gets one vertex per cell at
/// the cell's mid-u, so the pole is a fan of proper triangles rather than a row of zero-area slivers.
pub(super) fn grid(surface: &impl Parametric, tessellation: Tessellation) -> Mesh {
    grid_with_shape(surface, surface.grid_shape(tessellation.density.max(1)))
}

/// `grid` with the cells `shape` gives.
pub(super) fn grid_with_shape(surface: &impl Parametric, shape: GridShape) -> Mesh {
    let domain = surface.domain();
    let step = (domain.max - domain.min) / Vec2::new(shape.cells_u as f32, shape.cells_v as f32);
    let mut mesh = Mesh::default();
    let mut row_starts = Vec::with_capacity(shape.cells_v as usize + 1);
    for j in 0..=shape.cells_v {
        row_starts.push(mesh.positions.len() as u32);
        let v = domain.min.y + step.y * j as f32;
        let collapsed = shape.is_collapsed(j);
        let (count, offset) = if collapsed {
            (shape.cells_u, 0.5)
        } else {
            (shape.cells_u + 1, 0.0)
        };
        for i in 0..count {
            let u = domain.min.x + step.x * (i as f32 + offset);
            mesh.positions.push(surface.frame(u, v).p);
            mesh.uvs.push(Vec2::new(u, v));
        }
    }
    for j in 0..shape.cells_v {
        let (top, bottom) = (row_starts[j as usize], row_starts[j as usize + 1]);
        for i in 0..shape.cells_u {
            let corner = |row: u32, di: u32| row + i + di;
            if shape.is_collapsed(j) {
                mesh.indices
                    .push([corner(top, 0), corner(bottom, 0), corner(bottom, 1)]);
            } else if shape.is_collapsed(j + 1) {
                mesh.indices
                    .push([corner(top, 0), corner(bottom, 0), corner(top, 1)]);
            } else {
                mesh.indices
                    .push([corner(top, 0), corner(bottom, 0), corner(top, 1)]);
                mesh.indices
                    .push([corner(top, 1), corner(bottom, 0), corner(bottom, 1)]);
            }
        }
    }
    orient_along_normals(surface, &mut mesh);
    mesh
}

/// Makes every triangle wind counter-clockwise around the surface normal at its centre, whatever
/// the handedness of the surface's (u,v), so back faces can be told by winding alone; and
/// measures the mesh's chord error at the same centres.
fn orient_along_normals(surface: &impl Parametric, mesh: &mut Mesh) {
    let mut chord_error: f32 = 0.0;
    for tri in &mut mesh.indices {
        let [a, b, c] = tri.map(|i| mesh.positions[i as usize]);
        let centre_uv = tri.iter().map(|&i| mesh.uvs[i as usize]).sum::<Vec2>() / 3.0;
        let frame = surface.frame(centre_uv.x, centre_uv.y);
        if (b - a).cross(c - a).dot(frame.n) < 0.0 {
            tri.swap(1, 2);
        }
        let gap = frame.p.distance((a + b + c) / 3.0);
        if gap.is_finite() {
            chord_error = chord_error.max(gap);
        }
    }
    mesh.chord_error = chord_error;
}

#[cfg(test)]
mod tests {
    use super::super::{AxisBasis, Cone, Sphere, Surface};
    use super::*;
    use glam::DVec3;

    fn sphere() -> Surface {
        Surface::Sphere(Sphere {
            center: DVec3::ZERO,
            radius: 2.0,
        })
    }

    #[test]
    fn sphere_grid_has_fans_at_the_poles_and_no_slivers() {
        let mesh = sphere().tessellate(Tessellation { density: 8 });
        // 16 × 8 cells: two fan rows of 16 triangles, six rows of 32.
        assert_eq!(mesh.indices.len(), 16 * 2 + 16 * 6 * 2);
        for tri in &mesh.indices {
            let [a, b, c] = tri.map(|i| mesh.positions[i as usize]);
            assert!(
                (b - a).cross(c - a).length() > 1e-4,
                "zero-area triangle {tri:?}"
            );
        }
    }

    #[test]
    fn the_coarsest_densities_give_whole_meshes() {
        for density in [1, 2, 3] {
            let mesh = sphere().tessellate(Tessellation { density });
            assert!(!mesh.indices.is_empty());
            for tri in &mesh.indices {
                assert!(tri.iter().all(|&i| (i as usize) < mesh.positions.len()));
            }
        }
    }

    #[test]
    fn triangles_face_outwards() {
        let cone = Surface::Cone(Cone {
            apex: DVec3::ZERO,
            basis: AxisBasis::from_axis(-Vec3::Y),
            half_angle: 0.5,
            height: 3.0,
        });
        for surface in [sphere(), cone] {
            let mesh = surface.tessellate(Tessellation { density: 6 });
            for tri in &mesh.indices {
                let [a, b, c] = tri.map(|i| mesh.positions[i as usize]);
                let centroid = (a + b + c) / 3.0;
                let radial = centroid - Vec3::Y * centroid.y;
                assert!(
                    (b - a).cross(c - a).dot(radial) > 0.0,
                    "{tri:?} faces inwards"
                );
            }
        }
    }

    #[test]
    fn the_chord_error_follows_the_circle_sag_and_shrinks_as_the_square_of_density() {
        // A cell of a radius-2 sphere spans π/density each way. A chord across it sags
        // r(1 − cos(π/2d)); a triangle's centroid, curved away from in both directions, sits
        // deeper, but by less than three such sags.
        for density in [8, 16, 32] {
            let error = sphere().tessellate(Tessellation { density }).chord_error;
            let half_cell = std::f32::consts::PI / (2 * density) as f32;
            let sag = 2.0 * (1.0 - half_cell.cos());
            assert!(
                error > sag && error < 3.0 * sag,
                "density {density}: {error} vs {sag}"
            );
        }
        let coarse = sphere().tessellate(Tessellation { density: 8 }).chord_error;
        let fine = sphere()
            .tessellate(Tessellation { density: 32 })
            .chord_error;
        assert!((coarse / fine - 16.0).abs() < 3.0, "{coarse} / {fine}");
    }

    #[test]
    fn seam_vertices_share_positions_but_not_u() {
        let mesh = sphere().tessellate(Tessellation { density: 4 });
        let seam: Vec<_> = (0..mesh.uvs.len())
            .filter(|&i| mesh.uvs[i].x == 0.0 || mesh.uvs[i].x == 720.0)
            .collect();
        for &i in &seam {
            let twin = seam
                .iter()
                .find(|&&j| j != i && mesh.uvs[j].y == mesh.uvs[i].y)
                .expect("every seam vertex has a twin");
            assert!((mesh.positions[i] - mesh.positions[*twin]).length() < 1e-5);
        }
    }
}
