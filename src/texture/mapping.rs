//! From a surface point to texture coordinates, with the Jacobian ∂(s,t)/∂(u,v) so the
//! renderer can chain it with the screen-space derivatives of (u,v) for the mip level.
//!
//! Jacobians are analytic, not differences of `st`: across a wrap-around seam `s`
//! jumps from 1 to 0 but its derivative does not, so the mip level stays sane there.

use std::f32::consts::{PI, TAU};

use glam::{Mat2, Mat3, Vec2, Vec3};

use super::sampler::Footprint;

/// What a mapping may look at: the object-space point, its partials along the
/// surface parameters, the parameters themselves and the time (seconds).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SurfacePoint {
    pub p: Vec3,
    pub pu: Vec3,
    pub pv: Vec3,
    pub uv: Vec2,
    pub time: f32,
}

/// Texture coordinates and `jacobian` = ∂(s,t)/∂(u,v): column 0 is ∂/∂u, column 1 ∂/∂v.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mapped {
    pub st: Vec2,
    pub jacobian: Mat2,
}

impl Mapped {
    /// The sampler's footprint, given the screen-space derivatives of (u,v) per pixel.
    pub fn footprint(&self, duv_dx: Vec2, duv_dy: Vec2) -> Footprint {
        Footprint {
            dx: self.jacobian * duv_dx,
            dy: self.jacobian * duv_dy,
        }
    }

    /// Coordinates and Jacobian from ∂(s,t)/∂p (rows as vectors) and the surface partials.
    fn from_gradients(st: Vec2, ds_dp: Vec3, dt_dp: Vec3, at: &SurfacePoint) -> Self {
        let column = |dp: Vec3| Vec2::new(ds_dp.dot(dp), dt_dp.dot(dp));
        Self {
            st,
            jacobian: Mat2::from_cols(column(at.pu), column(at.pv)),
        }
    }
}

/// Anything that places an image on a surface.
pub trait TextureMapping {
    fn map(&self, at: &SurfacePoint) -> Mapped;
}

/// Every mapping of the seed lecture, as one type the renderer can store.
#[derive(Debug, Clone, PartialEq)]
pub enum Mapping {
    Planar(Planar),
    Triangle(TriangleMap),
    Spherical(Spherical),
    Cylindrical(Cylindrical),
    SurfaceUv(SurfaceUv),
    Scroll(Scroll),
}

impl Mapping {
    /// Maps a batch of `count` points, `point(k)` the k-th, calling `each(k, mapped)` for it:
    /// one dispatch per batch, so each mapping is inlined into its own loop. Indexed rather
    /// than an iterator: plain index loops inline the same way in every build.
    #[inline]
    pub fn map_each(
        &self,
        count: usize,
        point: impl Fn(usize) -> SurfacePoint,
        mut each: impl FnMut(usize, Mapped),
    ) {
        fn with<M: TextureMapping>(
            m: &M,
            count: usize,
            point: impl Fn(usize) -> SurfacePoint,
            each: &mut impl FnMut(usize, Mapped),
        ) {
            for k in 0..count {
                each(k, m.map(&point(k)));
            }
        }
        match self {
            Mapping::Planar(m) => with(m, count, point, &mut each),
            Mapping::Triangle(m) => with(m, count, point, &mut each),
            Mapping::Spherical(m) => with(m, count, point, &mut each),
            Mapping::Cylindrical(m) => with(m, count, point, &mut each),
            Mapping::SurfaceUv(m) => with(m, count, point, &mut each),
            Mapping::Scroll(m) => with(m, count, point, &mut each),
        }
    }
}

impl Mapping {
    /// Whether it shifts with time: a scroll at a velocity other than zero.
    pub fn moves_with_time(&self) -> bool {
        match self {
            Mapping::Scroll(scroll) => {
                scroll.velocity != Vec2::ZERO || scroll.inner.moves_with_time()
            }
            _ => false,
        }
    }
}

impl TextureMapping for Mapping {
    fn map(&self, at: &SurfacePoint) -> Mapped {
        match self {
            Mapping::Planar(m) => m.map(at),
            Mapping::Triangle(m) => m.map(at),
            Mapping::Spherical(m) => m.map(at),
            Mapping::Cylindrical(m) => m.map(at),
            Mapping::SurfaceUv(m) => m.map(at),
            Mapping::Scroll(m) => m.map(at),
        }
    }
}

/// How plane coordinates (a, b) become (s, t). The image is upright when the plane's
/// U axis points right and V points up (t grows down the image, so along −V).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PlanarLayout {
    /// One copy per `size` (plane units), repeated by floored modulo in both directions
    /// (the seed's `x % width` breaks below 0; this does not). Sample with `Wrap::Repeat`.
    Tile { size: Vec2 },
    /// One copy stretched over the rectangle `min..max` (plane units), the seed's
    /// "small image onto a large planar area"; outside it the sampler's wrap decides.
    Stretch { min: Vec2, max: Vec2 },
}

/// The seed's plane mapping: `P = P0 + a·U + b·V`, for a plane of any orientation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Planar {
    origin: Vec3,
    // Dual basis: a = (P − P0)·dual_u, b = (P − P0)·dual_v, even for skew axes.
    dual_u: Vec3,
    dual_v: Vec3,
    layout: PlanarLayout,
}

impl Planar {
    /// `a` and `b` count multiples of `axis_u` and `axis_v`; `None` if they are parallel.
    pub fn new(origin: Vec3, axis_u: Vec3, axis_v: Vec3, layout: PlanarLayout) -> Option<Self> {
        let (dual_u, dual_v) = dual_basis(axis_u, axis_v)?;
        Some(Self {
            origin,
            dual_u,
            dual_v,
            layout,
        })
    }

    /// The seed's recipe: U from `origin` toward `toward`, `V = N × U`, both unit length
    /// so a and b are distances. `None` if the points coincide or lie along the normal.
    pub fn from_normal(
        origin: Vec3,
        toward: Vec3,
        normal: Vec3,
        layout: PlanarLayout,
    ) -> Option<Self> {
        let n = normal.try_normalize()?;
        let along = toward - origin;
        let u = (along - n * n.dot(along)).try_normalize()?;
        Self::new(origin, u, n.cross(u), layout)
    }
}

impl TextureMapping for Planar {
    fn map(&self, at: &SurfacePoint) -> Mapped {
        let d = at.p - self.origin;
        let ab = Vec2::new(d.dot(self.dual_u), d.dot(self.dual_v));
        let (st, scale) = match self.layout {
            PlanarLayout::Tile { size } => {
                let scale = Vec2::new(safe_recip(size.x), -safe_recip(size.y));
                let st = ab * scale;
                (st - st.floor(), scale)
            }
            PlanarLayout::Stretch { min, max } => {
                let scale = Vec2::new(safe_recip(max.x - min.x), -safe_recip(max.y - min.y));
                ((ab - Vec2::new(min.x, max.y)) * scale, scale)
            }
        };
        Mapped::from_gradients(st, self.dual_u * scale.x, self.dual_v * scale.y, at)
    }
}

/// The seed's "Image to Triangle": three image points (in s,t) pinned to the triangle's
/// corners, everything between by barycentric coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TriangleMap {
    corner: Vec3,
    dual_1: Vec3,
    dual_2: Vec3,
    st_corner: Vec2,
    st_edge_1: Vec2,
    st_edge_2: Vec2,
}

impl TriangleMap {
    /// `None` for a degenerate (zero-area) triangle.
    pub fn new(corners: [Vec3; 3], image_points: [Vec2; 3]) -> Option<Self> {
        let (dual_1, dual_2) = dual_basis(corners[1] - corners[0], corners[2] - corners[0])?;
        Some(Self {
            corner: corners[0],
            dual_1,
            dual_2,
            st_corner: image_points[0],
            st_edge_1: image_points[1] - image_points[0],
            st_edge_2: image_points[2] - image_points[0],
        })
    }
}

impl TextureMapping for TriangleMap {
    fn map(&self, at: &SurfacePoint) -> Mapped {
        let d = at.p - self.corner;
        let (b1, b2) = (d.dot(self.dual_1), d.dot(self.dual_2));
        let st = self.st_corner + self.st_edge_1 * b1 + self.st_edge_2 * b2;
        let ds_dp = self.dual_1 * self.st_edge_1.x + self.dual_2 * self.st_edge_2.x;
        let dt_dp = self.dual_1 * self.st_edge_1.y + self.dual_2 * self.st_edge_2.y;
        Mapped::from_gradients(st, ds_dp, dt_dp, at)
    }
}

/// An orthonormal frame: the axis (local y) and the direction of the image's centre
/// (local z); longitude is measured from z toward x.
#[derive(Debug, Clone, Copy, PartialEq)]
struct AxisFrame {
    centre: Vec3,
    to_local: Mat3,
}

impl AxisFrame {
    fn new(centre: Vec3, axis: Vec3, front: Vec3) -> Option<Self> {
        let y = axis.try_normalize()?;
        let z = (front - y * y.dot(front)).try_normalize()?;
        let x = y.cross(z);
        Some(Self {
            centre,
            to_local: Mat3::from_cols(x, y, z).transpose(),
        })
    }

    /// The point in local coordinates.
    fn local(&self, p: Vec3) -> Vec3 {
        self.to_local * (p - self.centre)
    }

    /// A gradient with respect to local coordinates, as one with respect to object space.
    fn gradient_to_object(&self, local_gradient: Vec3) -> Vec3 {
        self.to_local.transpose() * local_gradient
    }
}

/// How close to the axis the longitude's derivative is still taken at face value; nearer,
/// it is held at this radius so the Jacobian (and the mip level) stays finite at poles
/// and apexes, where the image really does shrink to a point.
const MIN_AXIS_DISTANCE: f32 = 1e-4;

/// Longitude `s = 0.5 + atan2(x, z) / 2π` (the seed's `atan(x/z)` is undefined at z = 0)
/// and its gradient, with `rho` the distance from the axis, already clamped.
fn longitude(local: Vec3, rho: f32) -> (f32, Vec3) {
    let s = 0.5 + local.x.atan2(local.z) / TAU;
    let gradient = Vec3::new(local.z, 0.0, -local.x) / (TAU * rho * rho);
    (s, gradient)
}

/// Longitude/latitude about a centre: s = 0.5 faces `front`, t = 0 at the north pole
/// (along `axis`), t = 1 at the south. The back seam (s = 0 ≡ 1) is continuous with
/// `Wrap::Repeat` on s; use `Wrap::Clamp` on t.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spherical {
    frame: AxisFrame,
}

impl Spherical {
    /// Pole along +y, image centre facing +z (toward a default camera).
    pub fn new(centre: Vec3) -> Self {
        Self {
            frame: AxisFrame {
                centre,
                to_local: Mat3::IDENTITY,
            },
        }
    }

    /// `None` if `axis` is zero or parallel to `front`.
    pub fn oriented(centre: Vec3, axis: Vec3, front: Vec3) -> Option<Self> {
        AxisFrame::new(centre, axis, front).map(|frame| Self { frame })
    }

    /// Whether this is `Spherical::new(Vec3::ZERO)`: centred on the surface's anchor, pole
    /// along +y, front +z. On a sphere that is the sphere's own longitude and latitude, an
    /// affine map of its (u,v) (see `shade`'s use of it).
    pub fn is_upright_about_anchor(&self) -> bool {
        self.frame.centre == Vec3::ZERO && self.frame.to_local == Mat3::IDENTITY
    }
}

impl TextureMapping for Spherical {
    fn map(&self, at: &SurfacePoint) -> Mapped {
        let local = self.frame.local(at.p);
        let r = local.length();
        if !(r.is_finite() && r > 1e-30) {
            return Mapped {
                st: Vec2::splat(0.5),
                jacobian: Mat2::ZERO,
            };
        }
        let n = local / r;
        let rho = n.x.hypot(n.z).max(MIN_AXIS_DISTANCE);
        let (s, ds_dn) = longitude(n, rho);
        let t = n.y.clamp(-1.0, 1.0).acos() / PI;
        // d acos(y/r) = −(ŷ − n_y n) / (r ρ); longitude's gradient also scales by 1/r.
        let dt_dp = -(Vec3::Y - n * n.y) / (PI * r * rho);
        let ds_dp = ds_dn / r;
        Mapped::from_gradients(
            Vec2::new(s, t),
            self.frame.gradient_to_object(ds_dp),
            self.frame.gradient_to_object(dt_dp),
            at,
        )
    }
}

/// Around an axis from the base centre: s = longitude as for `Spherical`, t = 0 at
/// `height` up the axis and 1 at the base. A cone uses it unchanged (its apex is on the
/// axis, where the Jacobian is held finite).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cylindrical {
    frame: AxisFrame,
    height: f32,
}

impl Cylindrical {
    /// Axis +y from `base`, image centre facing +z.
    pub fn new(base: Vec3, height: f32) -> Self {
        Self {
            frame: AxisFrame {
                centre: base,
                to_local: Mat3::IDENTITY,
            },
            height,
        }
    }

    /// `None` if `axis` is zero or parallel to `front`.
    pub fn oriented(base: Vec3, axis: Vec3, front: Vec3, height: f32) -> Option<Self> {
        AxisFrame::new(base, axis, front).map(|frame| Self { frame, height })
    }
}

impl TextureMapping for Cylindrical {
    fn map(&self, at: &SurfacePoint) -> Mapped {
        let local = self.frame.local(at.p);
        let scale = self.height.abs().max(1e-30);
        let rho = local.x.hypot(local.z).max(MIN_AXIS_DISTANCE * scale);
        let (s, ds_dp) = longitude(local, rho);
        let inverse_height = safe_recip(self.height);
        let t = 1.0 - local.y * inverse_height;
        let dt_dp = Vec3::new(0.0, -inverse_height, 0.0);
        Mapped::from_gradients(
            Vec2::new(s, t),
            self.frame.gradient_to_object(ds_dp),
            self.frame.gradient_to_object(dt_dp),
            at,
        )
    }
}

/// The surface's own parameters: `st = uv · scale + offset`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SurfaceUv {
    pub scale: Vec2,
    pub offset: Vec2,
}

impl Default for SurfaceUv {
    fn default() -> Self {
        Self {
            scale: Vec2::ONE,
            offset: Vec2::ZERO,
        }
    }
}

impl TextureMapping for SurfaceUv {
    fn map(&self, at: &SurfacePoint) -> Mapped {
        Mapped {
            st: at.uv * self.scale + self.offset,
            jacobian: Mat2::from_diagonal(self.scale),
        }
    }
}

/// The seed's "Mona Scroll": any mapping, shifted by `velocity · time` (images per
/// second). The shift is taken modulo 1, the period of a repeating texture, so long
/// animations keep full precision; sample with `Wrap::Repeat`.
#[derive(Debug, Clone, PartialEq)]
pub struct Scroll {
    pub inner: Box<Mapping>,
    pub velocity: Vec2,
}

impl TextureMapping for Scroll {
    fn map(&self, at: &SurfacePoint) -> Mapped {
        let mapped = self.inner.map(at);
        let shift = self.velocity * at.time;
        let shift = if shift.is_finite() {
            shift - shift.floor()
        } else {
            Vec2::ZERO
        };
        Mapped {
            st: mapped.st + shift,
            ..mapped
        }
    }
}

/// Vectors `(a*, b*)` in the plane of `a` and `b` with `a*·a = b*·b = 1`,
/// `a*·b = b*·a = 0`; `None` if `a` and `b` are (nearly) parallel or zero.
fn dual_basis(a: Vec3, b: Vec3) -> Option<(Vec3, Vec3)> {
    let (aa, bb, ab) = (a.dot(a), b.dot(b), a.dot(b));
    let det = aa * bb - ab * ab;
    if !(det > 1e-12 * aa * bb && det.is_finite()) {
        return None;
    }
    Some(((a * bb - b * ab) / det, (b * aa - a * ab) / det))
}

/// `1/x`, or 0 for a zero or non-finite result, so a degenerate size never yields NaN.
fn safe_recip(x: f32) -> f32 {
    let r = x.recip();
    if r.is_finite() { r } else { 0.0 }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dual_basis_recovers_skew_coordinates() {
        let (a, b) = (Vec3::new(2.0, 0.0, 0.0), Vec3::new(1.0, 1.0, 0.0));
        let (da, db) = dual_basis(a, b).unwrap();
        let p = a * 0.3 + b * -1.7;
        assert!((p.dot(da) - 0.3).abs() < 1e-6 && (p.dot(db) + 1.7).abs() < 1e-6);
        assert!(dual_basis(a, a * 3.0).is_none());
        assert!(dual_basis(Vec3::ZERO, b).is_none());
    }
}
