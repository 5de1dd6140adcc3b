//! A user's triangle mesh (an OBJ or glTF model) as a surface. A mesh has no (u,v) → point
//! function of its own: its texture coordinates may repeat (mirrored or overlapping islands),
//! so they cannot tell a fragment's triangle. The rasterizer is given instead a chart of the
//! mesh's own: triangle t is laid in a unit cell of a grid, its corners at (¼,¼), (¾,¼) and
//! (¼,¾) of the cell, so a fragment's interpolated chart (u,v) names its triangle (the cell;
//! the margin keeps a fragment at a triangle's edge inside it) and its barycentric weights (the
//! place in the cell), exactly and perspective-correct. Shading then moves each fragment to the
//! texture's (u,v) (`to_texture_space`), where patterns and images are read and bumps tilt.
//!
//! Numerics: positions, normals and tangents are f32 relative to the model's anchor, as every
//! surface's local geometry is; chart coordinates are f32 and stay under √(triangles) + 1, so a
//! million triangles keep barycentrics to 1e-4.

use super::corner::Corner;
use super::grid_shape::GridShape;
use super::parametric::Parametric;
use super::ray_hits::{Hit, Ray};
use super::{Domain, Frame, Mesh, Tessellation, normalize_or};
use glam::{DVec3, Vec2, Vec3};
use std::ops::RangeInclusive;
use std::sync::Arc;

/// A loaded model: three corners a triangle, its bounding volume hierarchy, and where it came
/// from.
pub struct ModelData {
    /// `corners[3t..3t + 3]` are triangle t's.
    pub corners: Vec<Corner>,
    /// Cells across the chart.
    pub columns: u32,
    /// The texture domain in pattern units (0..uv-scale on each side).
    pub domain: Domain,
    pub bvh: super::model_bvh::Bvh,
    /// Triangles left out because they had no area in space or in (u,v).
    pub degenerate: usize,
    /// Whether the triangles close a volume, wound counter-clockwise seen from outside: every
    /// edge met once each way, and a positive volume. Only then may back faces be culled.
    pub closed: bool,
}

/// A model placed in a scene.
#[derive(Clone)]
pub struct ModelSurface {
    /// The file it was read from, as the scene names it.
    pub file: Arc<str>,
    /// The anchor: corners are relative to it.
    pub origin: DVec3,
    pub data: Arc<ModelData>,
}

impl std::fmt::Debug for ModelSurface {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        write!(
            f,
            "ModelSurface {{ origin: {:?}, triangles: {} }}",
            self.origin,
            self.triangles()
        )
    }
}

impl PartialEq for ModelSurface {
    fn eq(&self, other: &ModelSurface) -> bool {
        let same_data = |a: &ModelData, b: &ModelData| {
            a.corners == b.corners && a.domain == b.domain && a.degenerate == b.degenerate
        };
        self.origin == other.origin
            && (Arc::ptr_eq(&self.data, &other.data) || same_data(&self.data, &other.data))
    }
}

/// A chart corner's place in its cell: (¼,¼), (¾,¼), (¼,¾).
const CHART_CORNERS: [Vec2; 3] = [
    Vec2::new(0.25, 0.25),
    Vec2::new(0.75, 0.25),
    Vec2::new(0.25, 0.75),
];

impl ModelData {
    /// The data for `corners` (three a triangle), with the chart laid out for them.
    pub fn new(corners: Vec<Corner>, domain: Domain, degenerate: usize) -> ModelData {
        let triangles = corners.len() / 3;
        let columns = (triangles as f64).sqrt().ceil().max(1.0) as u32;
        let bvh = super::model_bvh::Bvh::new(&corners);
        let closed = closes_a_volume(&corners);
        ModelData {
            corners,
            columns,
            domain,
            bvh,
            degenerate,
            closed,
        }
    }

    pub fn triangle(&self, t: usize) -> &[Corner] {
        &self.corners[3 * t..3 * t + 3]
    }

    /// Triangle `t`'s chart cell's lowest corner.
    pub fn cell(&self, t: usize) -> Vec2 {
        let columns = self.columns as usize;
        Vec2::new((t % columns) as f32, (t / columns) as f32)
    }

    /// The chart (u,v) of the point with barycentric weights (1 − a − b, a, b) on triangle t.
    pub fn chart_uv(&self, t: usize, a: f32, b: f32) -> Vec2 {
        self.cell(t) + CHART_CORNERS[0] + Vec2::new(a, b) * 0.5
    }

    /// The triangle a chart (u,v) lies in, and the weights (a, b) of its second and third
    /// corners there.
    #[inline]
    pub fn locate(&self, chart: Vec2) -> (usize, f32, f32) {
        let cell = chart.floor();
        let columns = self.columns as usize;
        let triangles = self.corners.len() / 3;
        let column = (cell.x.max(0.0) as usize).min(columns - 1);
        let t = (cell.y.max(0.0) as usize * columns + column).min(triangles.max(1) - 1);
        let inside = (chart - self.cell(t) - CHART_CORNERS[0]) * 2.0;
        (t, inside.x, inside.y)
    }
}

/// Whether `corners` close a volume wound counter-clockwise from outside (see `closed`).
fn closes_a_volume(corners: &[Corner]) -> bool {
    // Adding 0 makes −0 the +0 it equals, so a seam's two zeros are one point.
    let key = |p: Vec3| p.to_array().map(|c| (c + 0.0).to_bits());
    let mut edges = std::collections::HashMap::with_capacity(corners.len());
    for face in corners.chunks_exact(3) {
        for k in 0..3 {
            let edge = (key(face[k].p), key(face[(k + 1) % 3].p));
            if edges.insert(edge, ()).is_some() {
                return false;
            }
        }
    }
    let paired = edges.keys().all(|&(a, b)| edges.contains_key(&(b, a)));
    let volume: f64 = corners
        .chunks_exact(3)
        .map(|f| f64::from(f[0].p.dot(f[1].p.cross(f[2].p))))
        .sum();
    paired && volume > 0.0
}

impl Parametric for ModelSurface {
    /// A model's kind is its file's name (see `Surface::kind_name`).
    fn kind(&self) -> &'static str {
        "model"
    }

    fn origin(&self) -> DVec3 {
        self.origin
    }

    fn origin_mut(&mut self) -> &mut DVec3 {
        &mut self.origin
    }

    fn domain(&self) -> Domain {
        self.data.domain
    }

    /// The frame at a chart (u,v): the point on the triangle, the interpolated vertex normal,
    /// and the partials along the chart's u and v (`to_texture_space` turns them into the
    /// texture's).
    #[inline]
    fn frame(&self, u: f32, v: f32) -> Frame {
        let data = &*self.data;
        if data.corners.is_empty() {
            return Frame::default();
        }
        let (t, a, b) = data.locate(Vec2::new(u, v));
        let [c0, c1, c2] = [0, 1, 2].map(|k| data.triangle(t)[k]);
        let (e1, e2) = (c1.p - c0.p, c2.p - c0.p);
        let flat = normalize_or(e1.cross(e2), Vec3::Z);
        let n = c0.n * (1.0 - a - b) + c1.n * a + c2.n * b;
        Frame {
            p: c0.p + e1 * a + e2 * b,
            pu: e1 * 2.0,
            pv: e2 * 2.0,
            n: normalize_or(n, flat),
        }
    }

    fn is_its_own_mesh(&self) -> bool {
        true
    }

    /// A model's triangles are the surface: nothing to tessellate.
    fn max_curvature(&self) -> f32 {
        0.0
    }

    /// For a closed model: whether the eye (relative to the anchor) is outside it, by the
    /// parity of a ray's crossings; `None` for an open one, whose back faces may show.
    fn encloses_eye_at(&self, eye: DVec3) -> Option<bool> {
        let data = &*self.data;
        if !data.closed {
            return None;
        }
        // A direction no face of an axis-aligned model lies along.
        let direction = DVec3::new(0.5773, 0.5774, 0.5775);
        Some(
            data.bvh
                .crossings(&data.corners, eye, direction)
                .is_multiple_of(2),
        )
    }

    fn grid_shape(&self, _density: u32) -> GridShape {
        GridShape::flat(1, 1)
    }

    /// The rasterizer's mesh: each triangle with its own three vertices at its chart corners.
    fn own_mesh(&self) -> Option<Mesh> {
        let data = &*self.data;
        let triangles = self.triangles();
        let uvs = (0..triangles)
            .flat_map(|t| CHART_CORNERS.map(|corner| data.cell(t) + corner))
            .collect();
        Some(Mesh {
            positions: data.corners.iter().map(|c| c.p).collect(),
            uvs,
            indices: (0..triangles as u32)
                .map(|t| [3 * t, 3 * t + 1, 3 * t + 2])
                .collect(),
            chord_error: 0.0,
        })
    }

    fn triangle_count(&self, _tessellation: Tessellation) -> u64 {
        self.triangles() as u64
    }

    /// The nearest hit of the ray with the model's triangles, in its chart's (u,v).
    fn intersect(&self, ray: &Ray, range: &RangeInclusive<f64>) -> Option<Hit> {
        let data = &*self.data;
        let hit = data
            .bvh
            .intersect(&data.corners, ray.origin, ray.direction, range)?;
        Some(Hit {
            t: hit.t,
            uv: data.chart_uv(hit.triangle, hit.a as f32, hit.b as f32),
        })
    }

    /// The chart (u,v) of the model's point nearest `p`: a point alone does not name its
    /// triangle, so every triangle is tried (for tests and tools, not for rendering).
    fn uv_at(&self, p: DVec3) -> Vec2 {
        let data = &*self.data;
        let nearest = (0..self.triangles())
            .map(|t| {
                let [a, b, c] = [0, 1, 2].map(|k| data.triangle(t)[k].p.as_dvec3());
                let (weights, distance) = closest_on_triangle(p, a, b, c);
                (distance, t, weights)
            })
            .min_by(|x, y| x.0.total_cmp(&y.0));
        nearest.map_or(Vec2::NAN, |(_, t, (wb, wc))| {
            data.chart_uv(t, wb as f32, wc as f32)
        })
    }
}

/// The weights of b and c at the point of triangle abc nearest `p`, and its distance.
fn closest_on_triangle(p: DVec3, a: DVec3, b: DVec3, c: DVec3) -> ((f64, f64), f64) {
    let (e1, e2) = (b - a, c - a);
    let (d11, d12, d22) = (e1.dot(e1), e1.dot(e2), e2.dot(e2));
    let (r1, r2) = ((p - a).dot(e1), (p - a).dot(e2));
    let det = d11 * d22 - d12 * d12;
    let (mut wb, mut wc) = if det > 0.0 {
        ((d22 * r1 - d12 * r2) / det, (d11 * r2 - d12 * r1) / det)
    } else {
        (0.0, 0.0)
    };
    // Outside: the nearest point is on an edge; clamping the weights is close enough for a
    // point that lies on the model, which is what this is asked of.
    wb = wb.clamp(0.0, 1.0);
    wc = wc.clamp(0.0, 1.0 - wb);
    let q = a + e1 * wb + e2 * wc;
    ((wb, wc), q.distance(p))
}

impl ModelSurface {
    pub fn triangles(&self) -> usize {
        self.data.corners.len() / 3
    }

    /// The texture's (u,v) at a chart (u,v), and how chart steps map to texture steps (a chart
    /// derivative `d` is `along_u · d.x + along_v · d.y` in the texture); `frame`, whose partials
    /// were along the chart, is turned to the texture's: partials along its u and v, in the
    /// MikkTSpace frame (the tangent the model was baked with, and its bitangent) at each one's
    /// stretch.
    pub fn to_texture_space(&self, chart: Vec2, frame: &mut Frame) -> TexturePoint {
        let data = &*self.data;
        if data.corners.is_empty() {
            return TexturePoint::default();
        }
        let (t, a, b) = data.locate(chart);
        let [c0, c1, c2] = [0, 1, 2].map(|k| data.triangle(t)[k]);
        // d(texture uv)/d(chart uv): the chart's corners are half a cell apart.
        let (along_u, along_v) = ((c1.uv - c0.uv) * 2.0, (c2.uv - c0.uv) * 2.0);
        let det = along_u.x * along_v.y - along_v.x * along_u.y;
        // d(chart)/d(texture) is the inverse; each column a partial of P along texture u, v.
        let (du, dv) = (
            Vec2::new(along_v.y, -along_u.y) / det,
            Vec2::new(-along_v.x, along_u.x) / det,
        );
        let pu = frame.pu * du.x + frame.pv * du.y;
        let pv = frame.pu * dv.x + frame.pv * dv.y;
        let tangent = c0.tangent * (1.0 - a - b) + c1.tangent * a + c2.tangent * b;
        let n = frame.n;
        let along = normalize_or(tangent.truncate() - n * n.dot(tangent.truncate()), pu);
        let across = n.cross(along) * tangent.w.signum();
        frame.pu = along * pu.length();
        frame.pv = across * pv.length();
        TexturePoint {
            uv: c0.uv + (c1.uv - c0.uv) * a + (c2.uv - c0.uv) * b,
            along_u,
            along_v,
        }
    }
}

/// A chart point in the texture: its (u,v) and the texture steps of unit chart steps.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TexturePoint {
    pub uv: Vec2,
    pub along_u: Vec2,
    pub along_v: Vec2,
}

impl TexturePoint {
    /// A chart derivative of (u,v) as the texture's.
    pub fn derivative(&self, chart: Vec2) -> Vec2 {
        self.along_u * chart.x + self.along_v * chart.y
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec4;

    /// A tetrahedron's corners, each face counter-clockwise from outside (reversed: inside).
    fn tetrahedron(reversed: bool) -> Vec<Corner> {
        let p = [Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z];
        let faces = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
        faces
            .iter()
            .flat_map(|&[a, b, c]| if reversed { [a, c, b] } else { [a, b, c] })
            .map(|i| Corner {
                p: p[i],
                n: Vec3::Y,
                tangent: Vec4::X,
                uv: p[i].truncate(),
            })
            .collect()
    }

    fn surface(corners: Vec<Corner>) -> ModelSurface {
        let domain = Domain {
            min: Vec2::ZERO,
            max: Vec2::ONE,
        };
        ModelSurface {
            file: "test.obj".into(),
            origin: DVec3::ZERO,
            data: Arc::new(ModelData::new(corners, domain, 0)),
        }
    }

    #[test]
    fn only_a_closed_outward_model_says_whether_the_eye_is_inside() {
        let closed = surface(tetrahedron(false));
        assert_eq!(closed.encloses_eye_at(DVec3::splat(5.0)), Some(true));
        assert_eq!(closed.encloses_eye_at(DVec3::splat(0.1)), Some(false));
        assert_eq!(
            surface(tetrahedron(true)).encloses_eye_at(DVec3::splat(5.0)),
            None
        );
        let mut open = tetrahedron(false);
        open.truncate(9);
        assert_eq!(surface(open).encloses_eye_at(DVec3::splat(5.0)), None);
    }

    #[test]
    fn the_chart_names_every_triangle_and_its_weights() {
        let model = surface(tetrahedron(false));
        for t in 0..4 {
            for (a, b) in [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (0.2, 0.3)] {
                let (found, fa, fb) = model.data.locate(model.data.chart_uv(t, a, b));
                assert_eq!(found, t);
                assert!((fa - a).abs() < 1e-6 && (fb - b).abs() < 1e-6);
            }
        }
    }
}
