//! The lecture's new surface, drawn: P'(u,v) = P(u,v) + B(u,v)·n(u,v), a base surface moved
//! along its unit normal n by a height field B (true displacement, where Blinn's bump only
//! tilts the normal of the unmoved surface). Its frame keeps every term of the lecture's
//! derivation: P'u = Pu + Bu·n + B·nu, P'v = Pv + Bv·n + B·nv, N' = P'u × P'v.
//!
//! A ray meets P' where the point's height above the base, h(X), equals B at the point's (u,v):
//! the search marches the ray through the shell the heights fill and bisects the first sign
//! change. Bases are those whose point-to-(u,v, height) projection is exact: planes (the height
//! is the distance along the normal) and spheres (the distance from the centre less the radius).
//!
//! Numerics: frames in f32 like every surface's; the ray search in f64 on the geometry, the
//! height field's f32 values compared at f32 rounding.

use super::grid_shape::GridShape;
use super::parametric::Parametric;
use super::ray_hits::{Hit, Ray};
use super::{Domain, Frame, Frames, Mesh, Plane, Sphere, Surface, normalize_or, tessellate};
use glam::{DVec3, Vec2, Vec3};
use std::ops::RangeInclusive;
use std::sync::Arc;

/// A height B(u,v) over a surface, in the surface's length units, and its (u,v) gradient.
pub trait HeightField: Send + Sync + std::fmt::Debug {
    /// B and (Bu, Bv) at each of `uvs`, where the base surface's frames are `frames`; the
    /// outputs are resized to `uvs.len()`.
    fn sample(
        &self,
        uvs: &[Vec2],
        frames: &Frames,
        heights: &mut Vec<f32>,
        gradients: &mut Vec<Vec2>,
    );
}

/// A base surface that can be displaced: one whose points project exactly onto it.
#[derive(Clone, Debug, PartialEq)]
pub enum DisplacedBase {
    Plane(Plane),
    Sphere(Sphere),
}

/// P + B·n over `base`, cut into `shape`'s grid, with heights within `heights`.
#[derive(Clone, Debug)]
pub struct Displaced {
    pub base: DisplacedBase,
    pub field: Arc<dyn HeightField>,
    /// The grid the mesh is cut into (chosen for the view: see `quality::displaced_grid`).
    pub shape: GridShape,
    /// Bounds of B over the surface (sampled on a fine grid, with a margin), which bound the
    /// shell a ray searches.
    pub heights: (f32, f32),
    /// The ray search's step along the ray, in length units: under the finest detail the
    /// mesh resolves.
    pub march_step: f32,
    /// The largest normal curvature, measured between the grid's neighbouring vertices.
    pub curvature: f32,
}

impl PartialEq for Displaced {
    fn eq(&self, other: &Displaced) -> bool {
        self.base == other.base
            && Arc::ptr_eq(&self.field, &other.field)
            && self.shape == other.shape
            && self.heights == other.heights
            && self.march_step == other.march_step
            && self.curvature == other.curvature
    }
}

impl DisplacedBase {
    /// `surface` as a base, or what it is when it cannot be one.
    /// `surface` as a base, or `None` where its points do not project exactly onto it.
    pub fn of(surface: &Surface) -> Option<DisplacedBase> {
        match surface {
            Surface::Plane(plane) => Some(DisplacedBase::Plane(plane.clone())),
            Surface::Sphere(sphere) => Some(DisplacedBase::Sphere(sphere.clone())),
            _ => None,
        }
    }

    fn parametric(&self) -> &dyn BaseSurface {
        match self {
            DisplacedBase::Plane(plane) => plane,
            DisplacedBase::Sphere(sphere) => sphere,
        }
    }
}

/// What displacement needs of its base beyond `Parametric`.
trait BaseSurface {
    fn frames_at(&self, uvs: &[Vec2], out: &mut Frames);
    /// ∂n/∂u and ∂n/∂v at `frame`.
    fn normal_derivatives(&self, frame: &Frame) -> (Vec3, Vec3);
    /// The (u,v) a point (relative to the anchor) projects to along the normal, and its height
    /// above the base there; `None` outside the domain.
    fn project(&self, point: DVec3) -> Option<(Vec2, f64)>;
    /// The part of the ray's `range` that may lie within `heights` of the base.
    fn shell(
        &self,
        ray: &Ray,
        heights: (f64, f64),
        range: &RangeInclusive<f64>,
    ) -> Option<(f64, f64)>;
}

impl BaseSurface for Plane {
    fn frames_at(&self, uvs: &[Vec2], out: &mut Frames) {
        self.frames(uvs.len(), |k| uvs[k], out);
    }

    fn normal_derivatives(&self, _frame: &Frame) -> (Vec3, Vec3) {
        (Vec3::ZERO, Vec3::ZERO)
    }

    fn project(&self, point: DVec3) -> Option<(Vec2, f64)> {
        let uv = self.uv_at(point);
        let inside = uv.cmpge(Vec2::ZERO).all() && uv.cmple(self.size).all();
        inside.then(|| (uv, point.dot(self.normal.as_dvec3())))
    }

    fn shell(
        &self,
        ray: &Ray,
        (low, high): (f64, f64),
        range: &RangeInclusive<f64>,
    ) -> Option<(f64, f64)> {
        let n = self.normal.as_dvec3();
        let (height, rate) = (ray.origin.dot(n), ray.direction.dot(n));
        if rate == 0.0 {
            return (low..=high)
                .contains(&height)
                .then_some((*range.start(), *range.end()));
        }
        let (a, b) = ((low - height) / rate, (high - height) / rate);
        clip((a.min(b), a.max(b)), range)
    }
}

impl BaseSurface for Sphere {
    fn frames_at(&self, uvs: &[Vec2], out: &mut Frames) {
        self.frames(uvs.len(), |k| uvs[k], out);
    }

    /// The normal is P/r, so nu = Pu/r and nv = Pv/r.
    fn normal_derivatives(&self, frame: &Frame) -> (Vec3, Vec3) {
        (frame.pu / self.radius, frame.pv / self.radius)
    }

    fn project(&self, point: DVec3) -> Option<(Vec2, f64)> {
        let distance = point.length();
        (distance > 0.0).then(|| (self.uv_at(point), distance - f64::from(self.radius)))
    }

    fn shell(
        &self,
        ray: &Ray,
        (_, high): (f64, f64),
        range: &RangeInclusive<f64>,
    ) -> Option<(f64, f64)> {
        // Inside the outer sphere; the inner one is crossed by the march like any height.
        let outer = f64::from(self.radius) + high.max(0.0);
        let (o, d) = (ray.origin, ray.direction);
        let (a, b, c) = (
            d.length_squared(),
            o.dot(d),
            o.length_squared() - outer * outer,
        );
        let discriminant = b * b - a * c;
        if discriminant < 0.0 || a == 0.0 {
            return None;
        }
        let root = discriminant.sqrt();
        clip(((-b - root) / a, (-b + root) / a), range)
    }
}

fn clip((start, end): (f64, f64), range: &RangeInclusive<f64>) -> Option<(f64, f64)> {
    let (start, end) = (start.max(*range.start()), end.min(*range.end()));
    (start <= end).then_some((start, end))
}

/// Steps of the ray search evaluated together.
const MARCH_BATCH: u64 = 32;
/// Rounds narrowing a bracketed crossing: each to a 32nd, 32⁻⁶ ≈ 2⁻³⁰ of a march step in all.
const REFINEMENTS: u32 = 6;

impl Displaced {
    fn base(&self) -> &dyn BaseSurface {
        self.base.parametric()
    }

    /// The frames of P' at `uvs`, appended to `out`: the base's frames and the field's heights
    /// and gradients, combined with every term.
    pub fn displaced_frames(&self, uvs: &[Vec2], out: &mut Frames) {
        let mut base = Frames::default();
        self.base().frames_at(uvs, &mut base);
        let (mut heights, mut gradients) = (Vec::new(), Vec::new());
        self.field.sample(uvs, &base, &mut heights, &mut gradients);
        out.reserve(uvs.len());
        for k in 0..uvs.len() {
            out.push(self.moved(&base.at(k), heights[k], gradients[k]));
        }
    }

    /// The frame of P' over the base's `frame` for height `b` and gradient (Bu, Bv).
    fn moved(&self, frame: &Frame, b: f32, gradient: Vec2) -> Frame {
        let (nu, nv) = self.base().normal_derivatives(frame);
        let n = frame.n;
        let pu = frame.pu + n * gradient.x + nu * b;
        let pv = frame.pv + n * gradient.y + nv * b;
        // Oriented by the base's outward normal, whatever the handedness of its (u,v).
        let orientation = if frame.pu.cross(frame.pv).dot(n) < 0.0 {
            -1.0
        } else {
            1.0
        };
        Frame {
            p: frame.p + n * b,
            pu,
            pv,
            n: normalize_or(pu.cross(pv) * orientation, n),
        }
    }

    /// The signed gap between the ray's point at each `t` and P' along the normal there:
    /// positive above the displaced surface, negative below; `None` off the domain. One batch of
    /// heights for them all: the field's evaluation has a cost per call.
    fn gaps(&self, ray: &Ray, ts: &[f64]) -> Vec<Option<(Vec2, f64)>> {
        let projected: Vec<Option<(Vec2, f64)>> = (ts.iter())
            .map(|&t| self.base().project(ray.origin + ray.direction * t))
            .collect();
        let uvs: Vec<Vec2> = projected.iter().flatten().map(|&(uv, _)| uv).collect();
        let mut frames = Frames::default();
        self.base().frames_at(&uvs, &mut frames);
        let (mut heights, mut gradients) = (Vec::new(), Vec::new());
        self.field
            .sample(&uvs, &frames, &mut heights, &mut gradients);
        let mut heights = heights.into_iter();
        (projected.into_iter())
            .map(|point| {
                let (uv, above_base) = point?;
                Some((uv, above_base - f64::from(heights.next()?)))
            })
            .collect()
    }

    /// The first crossing from above P' to below it along the ray within `range`, marched
    /// `MARCH_BATCH` steps at a time.
    fn march(&self, ray: &Ray, range: &RangeInclusive<f64>) -> Option<Hit> {
        let heights = (f64::from(self.heights.0), f64::from(self.heights.1));
        let (start, end) = self.base().shell(ray, heights, range)?;
        let speed = ray.direction.length();
        let step = f64::from(self.march_step.max(1e-6)) / speed.max(1e-300);
        let steps = ((end - start) / step).ceil().clamp(1.0, 1e6) as u64;
        let mut first = 0;
        while first < steps {
            let last = (first + MARCH_BATCH).min(steps);
            let ts: Vec<f64> = (first..=last)
                .map(|k| (start + step * k as f64).min(end))
                .collect();
            if let Some(k) = first_crossing(&self.gaps(ray, &ts)) {
                return Some(self.refine(ray, ts[k - 1], ts[k]));
            }
            first = last;
        }
        None
    }

    /// The crossing between `above` and `below` (t along the ray), narrowed by
    /// `REFINEMENTS` rounds of `MARCH_BATCH` even steps each.
    fn refine(&self, ray: &Ray, mut above: f64, mut below: f64) -> Hit {
        for _ in 0..REFINEMENTS {
            let width = (below - above) / MARCH_BATCH as f64;
            let ts: Vec<f64> = (0..=MARCH_BATCH)
                .map(|k| above + width * k as f64)
                .collect();
            let Some(k) = first_crossing(&self.gaps(ray, &ts)) else {
                break;
            };
            (above, below) = (ts[k - 1], ts[k]);
        }
        let uv = self.gaps(ray, &[below])[0].map_or(Vec2::NAN, |(uv, _)| uv);
        Hit { t: below, uv }
    }
}

/// The first index whose gap is at or below P' while the one before it is above.
fn first_crossing(gaps: &[Option<(Vec2, f64)>]) -> Option<usize> {
    (1..gaps.len()).find(|&k| {
        let (before, now) = (gaps[k - 1], gaps[k]);
        matches!((before, now), (Some((_, a)), Some((_, b))) if a > 0.0 && b <= 0.0)
    })
}

impl Parametric for Displaced {
    fn kind(&self) -> &'static str {
        match self.base {
            DisplacedBase::Plane(_) => "displaced plane",
            DisplacedBase::Sphere(_) => "displaced sphere",
        }
    }

    fn origin(&self) -> DVec3 {
        match &self.base {
            DisplacedBase::Plane(plane) => plane.origin(),
            DisplacedBase::Sphere(sphere) => sphere.origin(),
        }
    }

    fn origin_mut(&mut self) -> &mut DVec3 {
        match &mut self.base {
            DisplacedBase::Plane(plane) => plane.origin_mut(),
            DisplacedBase::Sphere(sphere) => sphere.origin_mut(),
        }
    }

    fn domain(&self) -> Domain {
        match &self.base {
            DisplacedBase::Plane(plane) => plane.domain(),
            DisplacedBase::Sphere(sphere) => sphere.domain(),
        }
    }

    fn frame(&self, u: f32, v: f32) -> Frame {
        let mut out = Frames::default();
        self.displaced_frames(&[Vec2::new(u, v)], &mut out);
        out.at(0)
    }

    fn frames(&self, count: usize, uv: impl Fn(usize) -> Vec2, out: &mut Frames) {
        let uvs: Vec<Vec2> = (0..count).map(uv).collect();
        self.displaced_frames(&uvs, out);
    }

    fn max_curvature(&self) -> f32 {
        self.curvature
    }

    /// Its mesh stays within the view's tolerance of it (see `quality::displaced_grid`), so its
    /// fragments are shaded where they are, at the exact frame of their (u,v).
    fn is_its_own_mesh(&self) -> bool {
        true
    }

    fn encloses_eye_at(&self, _eye_from_anchor: DVec3) -> Option<bool> {
        // Displaced faces may turn away from the eye and still be seen past a bump: none culled.
        None
    }

    fn grid_shape(&self, _density: u32) -> GridShape {
        self.shape
    }

    /// The base's grid moved to P', its rows' seam and pole vertices welded to one height so the
    /// moved mesh has no crack where the base's did not.
    fn own_mesh(&self) -> Option<Mesh> {
        let (_, mesh) = Displaced::cut(self.base.clone(), self.field.clone(), self.shape);
        Some(mesh)
    }

    fn intersect(&self, ray: &Ray, range: &RangeInclusive<f64>) -> Option<Hit> {
        self.march(ray, range)
    }

    fn uv_at(&self, p: DVec3) -> Vec2 {
        self.base().project(p).map_or(Vec2::NAN, |(uv, _)| uv)
    }
}

impl Displaced {
    /// P + B·n over `base`, cut into `shape`, and its mesh, from one evaluation of the field at
    /// the grid's vertices: its height bounds are those samples' (and a tenth of their span
    /// beyond), its ray search steps half a cell.
    pub fn cut(
        base: DisplacedBase,
        field: Arc<dyn HeightField>,
        shape: GridShape,
    ) -> (Displaced, Mesh) {
        let mut displaced = Displaced {
            base,
            field,
            shape,
            heights: (0.0, 0.0),
            march_step: 0.0,
            curvature: 0.0,
        };
        let mut mesh = match &displaced.base {
            DisplacedBase::Plane(plane) => tessellate::grid_with_shape(plane, shape),
            DisplacedBase::Sphere(sphere) => tessellate::grid_with_shape(sphere, shape),
        };
        let mut frames = Frames::default();
        displaced.base().frames_at(&mesh.uvs, &mut frames);
        let (mut heights, mut gradients) = (Vec::new(), Vec::new());
        (displaced.field).sample(&mesh.uvs, &frames, &mut heights, &mut gradients);
        let low = heights.iter().copied().fold(0.0, f32::min);
        let high = heights.iter().copied().fold(0.0, f32::max);
        let margin = 0.1 * (high - low);
        displaced.heights = (low - margin, high + margin);
        displaced.march_step = displaced.cell_size() / 2.0;
        let moved: Vec<Frame> = (0..mesh.uvs.len())
            .map(|k| displaced.moved(&frames.at(k), heights[k], gradients[k]))
            .collect();
        displaced.curvature = largest_turn(&mesh, &moved).max(displaced.base_curvature());
        mesh.positions = moved.iter().map(|f| f.p).collect();
        if let DisplacedBase::Sphere(_) = displaced.base {
            weld_seams_and_poles(shape, &mut mesh.positions);
        }
        mesh.chord_error = displaced.chord_error(&mesh);
        (displaced, mesh)
    }

    fn base_curvature(&self) -> f32 {
        match &self.base {
            DisplacedBase::Plane(_) => 0.0,
            DisplacedBase::Sphere(sphere) => sphere.max_curvature(),
        }
    }

    /// The length of a grid cell's shorter side on the base (at a sphere's equator).
    pub fn cell_size(&self) -> f32 {
        let (cells_u, cells_v) = (
            self.shape.cells_u.max(1) as f32,
            self.shape.cells_v.max(1) as f32,
        );
        match &self.base {
            DisplacedBase::Plane(plane) => (plane.size.x / cells_u).min(plane.size.y / cells_v),
            DisplacedBase::Sphere(sphere) => std::f32::consts::PI * sphere.radius / cells_v,
        }
    }

    /// The farthest a triangle's centroid lies from P' at its centroid's (u,v): how far a
    /// triangle's plane strays from the tangent planes of the exact normals shaded on it, which
    /// shadow lookups are lifted past.
    fn chord_error(&self, mesh: &Mesh) -> f32 {
        let piece_error = |indices: &[[u32; 3]]| {
            let centres: Vec<Vec2> = (indices.iter())
                .map(|t| t.iter().map(|&i| mesh.uvs[i as usize]).sum::<Vec2>() / 3.0)
                .collect();
            let mut frames = Frames::default();
            self.displaced_frames(&centres, &mut frames);
            let gaps = indices.iter().zip(frames.iter()).map(|(t, frame)| {
                let centroid = t.iter().map(|&i| mesh.positions[i as usize]).sum::<Vec3>() / 3.0;
                frame.p.distance(centroid)
            });
            gaps.filter(|g| g.is_finite()).fold(0.0, f32::max)
        };
        // A piece at a time, so the centres' frames take little memory beside the mesh.
        (mesh.indices.chunks(1 << 14))
            .map(piece_error)
            .fold(0.0, f32::max)
    }
}

/// The largest turn of the normal per unit length along any edge of `mesh`, whose vertices'
/// frames are `frames`: the curvature the grid resolves.
fn largest_turn(mesh: &Mesh, frames: &[Frame]) -> f32 {
    let turn = |a: usize, b: usize| {
        let (fa, fb) = (&frames[a], &frames[b]);
        fa.n.distance(fb.n) / fa.p.distance(fb.p)
    };
    let edges = mesh.indices.iter().flat_map(|t| {
        let [a, b, c] = t.map(|i| i as usize);
        [turn(a, b), turn(b, c), turn(c, a)]
    });
    edges.filter(|k| k.is_finite()).fold(0.0, f32::max)
}

/// Each row of a sphere's grid (`shape`, laid out as `tessellate::grid_with_shape` lays it)
/// with its seam's two vertices, and each pole row's vertices, moved to their mean: where the
/// base's vertices coincide the displaced ones do too, so the mesh stays closed.
fn weld_seams_and_poles(shape: GridShape, positions: &mut [Vec3]) {
    let mut start = 0;
    for row in 0..=shape.cells_v {
        let count = if shape.is_collapsed(row) {
            shape.cells_u
        } else {
            shape.cells_u + 1
        } as usize;
        let vertices = &mut positions[start..start + count];
        let mean = if shape.is_collapsed(row) {
            vertices.iter().sum::<Vec3>() / count as f32
        } else {
            (vertices[0] + vertices[count - 1]) / 2.0
        };
        if shape.is_collapsed(row) {
            vertices.fill(mean);
        } else {
            (vertices[0], vertices[count - 1]) = (mean, mean);
        }
        start += count;
    }
}
