//! Shading from the tessellation instead of the exact surface: position and normal interpolated
//! across each triangle from its vertices (Phong shading), the classic rasterizer's frame.
//!
//! A fragment carries its perspective-correct (u,v). Each triangle maps its (u,v) triangle
//! affinely onto its 3D triangle, so the barycentric coordinates of the fragment's (u,v) in the
//! (u,v) triangle are exactly its perspective-correct barycentrics on the screen triangle: locating
//! (u,v) in the mesh's parameter plane and interpolating there is the same as interpolating vertex
//! normals as extra attribute planes, without widening the rasterizer's fragments.
//!
//! Precision: f32 throughout. (u,v) spans at most a few thousand units and cells are ≥ 0.1 unit,
//! so barycentrics keep ~1e-4 absolute accuracy, far below what a shaded normal shows.

use crate::surface::{Mesh, Surface, normalize_or};
use glam::{Vec2, Vec3};

/// One object's vertex normals and a uniform grid over its (u,v) domain for point location.
pub struct VertexNormals {
    positions: Vec<Vec3>,
    normals: Vec<Vec3>,
    uvs: Vec<Vec2>,
    indices: Vec<[u32; 3]>,
    grid: UvGrid,
}

/// Triangles bucketed by the cells of (u,v) their bounding boxes overlap.
struct UvGrid {
    min: Vec2,
    cell: Vec2,
    cols: u32,
    rows: u32,
    /// `triangles[starts[c]..starts[c + 1]]` overlap cell c.
    starts: Vec<u32>,
    triangles: Vec<u32>,
}

/// The interpolated point and unit normal at a fragment, relative to the surface's anchor.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interpolated {
    pub p: Vec3,
    pub n: Vec3,
}

impl VertexNormals {
    /// Vertex normals are the surface's exact unit normals at the vertices' (u,v).
    pub fn new(surface: &Surface, mesh: &Mesh) -> VertexNormals {
        let normals = mesh
            .uvs
            .iter()
            .map(|uv| surface.frame(uv.x, uv.y).n)
            .collect();
        VertexNormals {
            positions: mesh.positions.clone(),
            normals,
            uvs: mesh.uvs.clone(),
            grid: UvGrid::new(&mesh.uvs, &mesh.indices),
            indices: mesh.indices.clone(),
        }
    }

    /// Position and normal interpolated at `uv` in the triangle containing it (or, for a (u,v)
    /// just outside every triangle, the nearest one's closest point); `None` for an empty mesh.
    pub fn at(&self, uv: Vec2) -> Option<Interpolated> {
        let (triangle, weights) = self
            .grid
            .candidates(uv)
            .iter()
            .map(|&t| {
                (
                    t,
                    barycentric(self.indices[t as usize].map(|i| self.uvs[i as usize]), uv),
                )
            })
            .max_by(|a, b| min_weight(a.1).total_cmp(&min_weight(b.1)))?;
        let weights = clamp_weights(weights);
        let corners = self.indices[triangle as usize];
        let mix = |values: &[Vec3]| {
            corners
                .iter()
                .zip(weights)
                .map(|(&i, w)| values[i as usize] * w)
                .sum::<Vec3>()
        };
        let n = mix(&self.normals);
        let fallback = self.normals[corners[0] as usize];
        Some(Interpolated {
            p: mix(&self.positions),
            n: normalize_or(n, fallback),
        })
    }
}

impl UvGrid {
    fn new(uvs: &[Vec2], indices: &[[u32; 3]]) -> UvGrid {
        let (min, max) = uvs.iter().fold(
            (Vec2::splat(f32::INFINITY), Vec2::splat(f32::NEG_INFINITY)),
            |(lo, hi), &uv| (lo.min(uv), hi.max(uv)),
        );
        let extent = if indices.is_empty() {
            Vec2::ONE
        } else {
            (max - min).max(Vec2::splat(1e-6))
        };
        // About two triangles per cell, cells roughly square in (u,v).
        let target = (indices.len() as f32 / 2.0).max(1.0);
        let aspect = extent.x / extent.y;
        let cols = (target * aspect).sqrt().ceil().clamp(1.0, 4096.0) as u32;
        let rows = (target / cols as f32).ceil().clamp(1.0, 4096.0) as u32;
        let mut grid = UvGrid {
            min: if indices.is_empty() { Vec2::ZERO } else { min },
            cell: extent / Vec2::new(cols as f32, rows as f32),
            cols,
            rows,
            starts: Vec::new(),
            triangles: Vec::new(),
        };
        grid.bucket(uvs, indices);
        grid
    }

    /// Counting sort of triangles into the cells their (u,v) bounding boxes overlap.
    fn bucket(&mut self, uvs: &[Vec2], indices: &[[u32; 3]]) {
        let cells = (self.cols * self.rows) as usize;
        let ranges: Vec<_> = indices
            .iter()
            .map(|tri| self.cell_range(tri.map(|i| uvs[i as usize])))
            .collect();
        let mut counts = vec![0u32; cells + 1];
        for_each_cell(&ranges, self.cols, |cell, _| counts[cell + 1] += 1);
        for c in 0..cells {
            counts[c + 1] += counts[c];
        }
        let mut next = counts.clone();
        self.triangles = vec![0; counts[cells] as usize];
        for_each_cell(&ranges, self.cols, |cell, triangle| {
            self.triangles[next[cell] as usize] = triangle;
            next[cell] += 1;
        });
        self.starts = counts;
    }

    fn cell_of(&self, uv: Vec2) -> (u32, u32) {
        let c = ((uv - self.min) / self.cell).floor();
        let clamp = |x: f32, n: u32| (x.max(0.0) as u32).min(n - 1); // NaN → 0
        (clamp(c.x, self.cols), clamp(c.y, self.rows))
    }

    fn cell_range(&self, corners: [Vec2; 3]) -> [(u32, u32); 2] {
        let lo = corners[0].min(corners[1]).min(corners[2]);
        let hi = corners[0].max(corners[1]).max(corners[2]);
        [self.cell_of(lo), self.cell_of(hi)]
    }

    fn candidates(&self, uv: Vec2) -> &[u32] {
        let (x, y) = self.cell_of(uv);
        let cell = (y * self.cols + x) as usize;
        &self.triangles[self.starts[cell] as usize..self.starts[cell + 1] as usize]
    }
}

fn for_each_cell(ranges: &[[(u32, u32); 2]], cols: u32, mut visit: impl FnMut(usize, u32)) {
    for (triangle, [(x0, y0), (x1, y1)]) in ranges.iter().enumerate() {
        for y in *y0..=*y1 {
            for x in *x0..=*x1 {
                visit((y * cols + x) as usize, triangle as u32);
            }
        }
    }
}

/// Barycentric coordinates of `p` in the triangle `corners` (any winding); a degenerate
/// triangle gives weights far outside, so it never wins against a real one.
fn barycentric(corners: [Vec2; 3], p: Vec2) -> [f32; 3] {
    let [a, b, c] = corners;
    let area = (b - a).perp_dot(c - a);
    if area.abs() < 1e-12 {
        return [-1e30; 3];
    }
    let wa = (b - p).perp_dot(c - p) / area;
    let wb = (c - p).perp_dot(a - p) / area;
    [wa, wb, 1.0 - wa - wb]
}

fn min_weight(w: [f32; 3]) -> f32 {
    w[0].min(w[1]).min(w[2])
}

/// Negative weights (a (u,v) a rounding error outside) clamped and renormalised.
fn clamp_weights(w: [f32; 3]) -> [f32; 3] {
    let w = w.map(|x| x.max(0.0));
    let sum = w[0] + w[1] + w[2];
    if sum > 0.0 {
        w.map(|x| x / sum)
    } else {
        [1.0 / 3.0; 3]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::{Sphere, Tessellation};
    use glam::DVec3;

    fn sphere() -> Surface {
        Surface::Sphere(Sphere {
            center: DVec3::ZERO,
            radius: 100.0,
        })
    }

    #[test]
    fn at_a_vertex_the_normal_is_the_exact_one() {
        let surface = sphere();
        let mesh = surface.tessellate(Tessellation { density: 8 });
        let normals = VertexNormals::new(&surface, &mesh);
        for (i, uv) in mesh.uvs.iter().enumerate().step_by(7) {
            let at = normals.at(*uv).unwrap();
            let exact = surface.frame(uv.x, uv.y).n;
            assert!(
                (at.n - exact).length() < 1e-4,
                "vertex {i}: {at:?} vs {exact:?}"
            );
            assert!((at.p - mesh.positions[i]).length() < 1e-3);
        }
    }

    #[test]
    fn inside_a_triangle_the_point_lies_on_its_plane() {
        let surface = sphere();
        let mesh = surface.tessellate(Tessellation { density: 6 });
        let normals = VertexNormals::new(&surface, &mesh);
        for tri in mesh.indices.iter().step_by(5) {
            let uv = tri.iter().map(|&i| mesh.uvs[i as usize]).sum::<Vec2>() / 3.0;
            let centroid = tri
                .iter()
                .map(|&i| mesh.positions[i as usize])
                .sum::<Vec3>()
                / 3.0;
            let at = normals.at(uv).unwrap();
            assert!((at.p - centroid).length() < 1e-3, "{tri:?}");
        }
    }

    #[test]
    fn an_empty_mesh_has_no_normals() {
        let normals = VertexNormals::new(&sphere(), &Mesh::default());
        assert_eq!(normals.at(Vec2::ONE), None);
    }
}
