//! The seed's parametric surfaces: P(u,v), its partials Pu and Pv, and the unit normal, each
//! with a documented (u,v) domain, plus their tessellation into indexed grids.
//!
//! Numerics: every surface is stored as an f64 anchor point (its `origin`, so a scene translated by
//! 1e6 keeps its precision) plus f32 local geometry. Frames are evaluated in f32 relative to the
//! anchor: local coordinates stay within a few thousand units, where f32 keeps ~1e-4 absolute
//! precision, far below a pixel or a pattern period.

mod angles;
mod basis;
mod cone;
mod frames;
mod hull;
mod model;
mod model_bvh;
mod paraboloid;
mod plane;
mod ray_differentials;
mod ray_hits;
mod sphere;
mod tessellate;
mod triangle;
mod true_hit;
mod wave;

pub use angles::{atan2, sin_cos};
pub use basis::AxisBasis;
pub use cone::Cone;
pub use frames::{FrameSlices, Frames, Vectors};
pub use hull::push_out_to_hull;
pub use model::{Corner, ModelData, ModelSurface, TexturePoint};
pub use model_bvh::ModelHit;
pub use paraboloid::Paraboloid;
pub use plane::Plane;
pub use ray_differentials::uv_derivatives;
pub use ray_hits::{Hit, Ray, intersect, surface_uv};
pub use sphere::Sphere;
pub use tessellate::{Mesh, Tessellation};
pub use triangle::Triangle;
pub use true_hit::{TrueHit, WAVE_NEWTON_STEPS};
pub use wave::Wave;

use glam::{DVec3, Vec2, Vec3};

/// The local differential geometry of a surface at one (u,v), relative to the surface's anchor.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Frame {
    /// P(u,v) − origin.
    pub p: Vec3,
    /// ∂P/∂u; zero where the parametrisation collapses (poles, apexes).
    pub pu: Vec3,
    /// ∂P/∂v.
    pub pv: Vec3,
    /// Unit normal, always finite, continuous through poles and apexes (the analytic limit there).
    pub n: Vec3,
}

/// Any of the seed's surfaces.
#[derive(Clone, Debug, PartialEq)]
pub enum Surface {
    Plane(Plane),
    Sphere(Sphere),
    Paraboloid(Paraboloid),
    Cone(Cone),
    Wave(Wave),
    Triangle(Triangle),
    /// A user's triangle mesh, in the (u,v) of its chart (see `model.rs`).
    Model(ModelSurface),
}

impl Surface {
    /// What a person calls it: its kind, or a model's file name.
    pub fn kind_name(&self) -> String {
        let kind = match self {
            Surface::Plane(_) => "plane",
            Surface::Sphere(_) => "sphere",
            Surface::Paraboloid(_) => "paraboloid",
            Surface::Cone(_) => "cone",
            Surface::Wave(_) => "wave surface",
            Surface::Triangle(_) => "triangle",
            Surface::Model(model) => {
                let path = std::path::Path::new(&*model.file);
                let name = path.file_name().map(|n| n.to_string_lossy());
                return name.map_or_else(|| "model".into(), |n| n.into_owned());
            }
        };
        kind.into()
    }
}

/// The rectangle of (u,v) a surface is defined on. The triangle's domain is the triangle inside it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Domain {
    pub min: Vec2,
    pub max: Vec2,
}

impl Surface {
    /// The world-space anchor that frames are relative to.
    pub fn origin(&self) -> DVec3 {
        match self {
            Surface::Plane(s) => s.origin,
            Surface::Sphere(s) => s.center,
            Surface::Paraboloid(s) => s.apex,
            Surface::Cone(s) => s.apex,
            Surface::Wave(s) => s.origin,
            Surface::Triangle(s) => s.a,
            Surface::Model(s) => s.origin,
        }
    }

    /// The exact frame at (u,v).
    #[inline]
    pub fn frame(&self, u: f32, v: f32) -> Frame {
        match self {
            Surface::Plane(s) => s.frame(u, v),
            Surface::Sphere(s) => s.frame(u, v),
            Surface::Paraboloid(s) => s.frame(u, v),
            Surface::Cone(s) => s.frame(u, v),
            Surface::Wave(s) => s.frame(u, v),
            Surface::Triangle(s) => s.frame(u, v),
            Surface::Model(s) => s.frame(u, v),
        }
    }

    /// The exact frames at `uv(0) … uv(count − 1)`, appended to `out`: one dispatch per batch,
    /// so each surface's frame is inlined into its own loop (and the sphere's is vectorised).
    /// Indexed rather than an iterator: plain index loops inline the same way in every build.
    pub fn frames(&self, count: usize, uv: impl Fn(usize) -> Vec2, out: &mut Frames) {
        match self {
            Surface::Plane(s) => flat_frames(count, uv, s.frame(0.0, 0.0), out),
            Surface::Sphere(s) => s.frames(count, uv, out),
            Surface::Paraboloid(s) => frames_each(count, uv, |u, v| s.frame(u, v), out),
            Surface::Cone(s) => frames_each(count, uv, |u, v| s.frame(u, v), out),
            Surface::Wave(s) => frames_each(count, uv, |u, v| s.frame(u, v), out),
            Surface::Triangle(s) => flat_frames(count, uv, s.frame(0.0, 0.0), out),
            Surface::Model(s) => frames_each(count, uv, |u, v| s.frame(u, v), out),
        }
    }

    /// Whether Pu, Pv and n are the same at every (u,v) (only the point varies).
    pub fn is_flat(&self) -> bool {
        matches!(self, Surface::Plane(_) | Surface::Triangle(_))
    }

    /// Whether the rasterizer's triangles are the surface itself, so its fragments lie on it
    /// already: the flat surfaces and models.
    pub fn is_its_own_mesh(&self) -> bool {
        matches!(
            self,
            Surface::Plane(_) | Surface::Triangle(_) | Surface::Model(_)
        )
    }

    pub fn domain(&self) -> Domain {
        match self {
            Surface::Plane(s) => s.domain(),
            Surface::Sphere(_) => Sphere::DOMAIN,
            Surface::Paraboloid(s) => s.domain(),
            Surface::Cone(s) => s.domain(),
            Surface::Wave(s) => s.domain(),
            Surface::Triangle(s) => s.domain(),
            Surface::Model(s) => s.domain(),
        }
    }

    /// The largest normal curvature anywhere on the surface, 1/length (how far it can bend from
    /// a tangent plane: by about κ·d²/2 at distance d). A cone's grows without bound towards
    /// its apex; its value half way along the side is given.
    pub fn max_curvature(&self) -> f32 {
        match self {
            // A model's triangles are the surface: nothing to tessellate.
            Surface::Plane(_) | Surface::Triangle(_) | Surface::Model(_) => 0.0,
            Surface::Sphere(s) => 1.0 / s.radius,
            Surface::Paraboloid(s) => 2.0 * s.curvature,
            Surface::Cone(s) => {
                let radius_half_way = 0.5 * s.height * s.half_angle.tan();
                s.half_angle.cos() / radius_half_way.max(f32::MIN_POSITIVE)
            }
            Surface::Wave(s) => {
                let k = std::f32::consts::TAU / s.wavelength;
                s.amplitude.abs() * k * k
            }
        }
    }

    /// Whether the surface encloses a volume the camera can be outside of (so back faces may be culled).
    pub fn encloses(&self, eye: DVec3) -> Option<bool> {
        self.encloses_eye_at(eye - self.origin())
    }

    /// `encloses`, for an eye given relative to the surface's anchor.
    pub fn encloses_eye_at(&self, eye_from_anchor: DVec3) -> Option<bool> {
        match self {
            Surface::Sphere(s) => Some(eye_from_anchor.length() > s.radius as f64),
            Surface::Model(s) => s.encloses_eye_at(eye_from_anchor),
            _ => None,
        }
    }

    pub fn tessellate(&self, tessellation: Tessellation) -> Mesh {
        match self {
            Surface::Triangle(s) => s.mesh(),
            Surface::Model(s) => s.mesh(),
            _ => tessellate::grid(self, tessellation),
        }
    }

    /// The triangles `tessellate` makes, counted without making them.
    pub fn triangle_count(&self, tessellation: Tessellation) -> u64 {
        match self {
            Surface::Triangle(_) => return 1,
            Surface::Model(s) => return s.triangle_count() as u64,
            _ => {}
        }
        let shape = self.grid_shape(tessellation);
        let fans = u64::from(shape.collapsed_v_min) + u64::from(shape.collapsed_v_max);
        let cells_u = u64::from(shape.cells_u);
        2 * cells_u * u64::from(shape.cells_v) - fans * cells_u
    }

    /// Grid resolution (cells along u, cells along v) and which v edges collapse to a point.
    fn grid_shape(&self, tessellation: Tessellation) -> tessellate::GridShape {
        let d = tessellation.density.max(1);
        match self {
            Surface::Plane(_) | Surface::Triangle(_) | Surface::Model(_) => {
                tessellate::GridShape::flat(1, 1)
            }
            // Both poles are fans: a single row would have to be a fan at both ends at once.
            Surface::Sphere(_) => tessellate::GridShape {
                cells_u: 2 * d,
                cells_v: d.max(2),
                collapsed_v_min: true,
                collapsed_v_max: true,
            },
            Surface::Paraboloid(_) => tessellate::GridShape {
                cells_u: 2 * d,
                cells_v: (d / 2).max(2),
                collapsed_v_min: true,
                collapsed_v_max: false,
            },
            // A cone is ruled, so a single cell along v would be exact in position; but the
            // apex fan's vertex sits at mid-cell u, and u interpolated from it is off by up to
            // half a cell across the whole fan row. Rows along v confine that to the first one.
            Surface::Cone(_) => tessellate::GridShape {
                cells_u: 2 * d,
                cells_v: (d / 2).max(2),
                collapsed_v_min: true,
                collapsed_v_max: false,
            },
            Surface::Wave(w) => tessellate::GridShape::flat(w.cells_along_u(d), 1),
        }
    }
}

/// Normalise, or return `fallback` when the vector is too short (or non-finite) to have a direction.
#[inline]
pub fn normalize_or(v: Vec3, fallback: Vec3) -> Vec3 {
    let len2 = v.length_squared();
    if len2 > 1e-30 && len2.is_finite() {
        v / len2.sqrt()
    } else {
        fallback
    }
}

/// `frame` at `uv(0) … uv(count − 1)`, appended to `out`.
fn frames_each(
    count: usize,
    uv: impl Fn(usize) -> Vec2,
    frame: impl Fn(f32, f32) -> Frame,
    out: &mut Frames,
) {
    out.extend((0..count).map(|k| {
        let uv = uv(k);
        frame(uv.x, uv.y)
    }));
}

/// `frames_each` for a flat surface (`is_flat`), whose point is P = u·Pu + v·Pv and whose
/// tangents and normal are those of `at_origin` everywhere: the frames are filled with
/// `at_origin`, then only their points are written.
fn flat_frames(count: usize, uv: impl Fn(usize) -> Vec2, at_origin: Frame, out: &mut Frames) {
    let (pu, pv) = (at_origin.pu, at_origin.pv);
    let start = out.len();
    out.resize(start + count, at_origin);
    let [x, y, z] = out.p.coordinates_mut();
    let points = x[start..]
        .iter_mut()
        .zip(&mut y[start..])
        .zip(&mut z[start..]);
    for (k, ((x, y), z)) in points.enumerate() {
        let uv = uv(k);
        (*x, *y, *z) = (pu * uv.x + pv * uv.y).into();
    }
}

#[cfg(test)]
pub(crate) mod tests {
    #[test]
    fn triangle_counts_match_the_tessellated_meshes() {
        use super::{
            AxisBasis, Cone, Paraboloid, Plane, Sphere, Surface, Tessellation, Triangle, Wave,
        };
        use glam::{DVec3, Vec2, Vec3};
        let basis = AxisBasis::from_axis(Vec3::Y);
        let surfaces = [
            Surface::Plane(Plane::new(DVec3::ZERO, Vec3::Y, Vec3::X, Vec2::ONE)),
            Surface::Sphere(Sphere {
                center: DVec3::ZERO,
                radius: 1.0,
            }),
            Surface::Paraboloid(Paraboloid {
                apex: DVec3::ZERO,
                basis,
                curvature: 1.0,
                radius: 1.0,
            }),
            Surface::Cone(Cone {
                apex: DVec3::ZERO,
                basis,
                half_angle: 0.5,
                height: 1.0,
            }),
            Surface::Wave(Wave {
                origin: DVec3::ZERO,
                size: Vec2::new(4.0, 2.0),
                amplitude: 0.1,
                wavelength: 1.0,
            }),
            Surface::Triangle(Triangle::new(DVec3::ZERO, DVec3::X, DVec3::Y)),
        ];
        for surface in &surfaces {
            for density in [1, 2, 3, 17, 64] {
                let tessellation = Tessellation { density };
                let made = surface.tessellate(tessellation).indices.len() as u64;
                assert_eq!(
                    surface.triangle_count(tessellation),
                    made,
                    "{surface:?} at {density}"
                );
            }
        }
    }

    /// The flat surfaces' batch gives `frame`'s bits, appended after what `out` held.
    #[test]
    fn flat_batch_frames_are_single_frames() {
        use super::{Plane, Surface, Triangle};
        use glam::{DVec3, Vec2, Vec3};
        let surfaces = [
            Surface::Plane(Plane::new(
                DVec3::new(-600.0, 0.0, 600.0),
                Vec3::Y,
                Vec3::X,
                Vec2::splat(1200.0),
            )),
            Surface::Triangle(Triangle::new(
                DVec3::new(0.0, 0.0, 0.0),
                DVec3::new(30.0, 5.0, -2.0),
                DVec3::new(-4.0, 20.0, 9.0),
            )),
        ];
        let uvs: Vec<Vec2> = (0..150)
            .map(|i| Vec2::new(i as f32 * 8.3 - 30.0, 1200.0 - i as f32 * 7.9))
            .collect();
        for surface in surfaces {
            assert!(surface.is_flat());
            let earlier = surface.frame(1.0, 2.0);
            let mut batch: super::Frames = [earlier].into_iter().collect();
            surface.frames(uvs.len(), |k| uvs[k], &mut batch);
            assert_eq!(batch.len(), uvs.len() + 1);
            assert_eq!(batch.at(0), earlier);
            let bits =
                |f: &super::Frame| [f.p, f.pu, f.pv, f.n].map(|v| v.to_array().map(f32::to_bits));
            for (uv, got) in uvs.iter().zip(batch.iter().skip(1)) {
                assert_eq!(bits(&got), bits(&surface.frame(uv.x, uv.y)), "at {uv}");
            }
        }
    }

    use super::{Domain, Frame};

    /// Checks Pu and Pv against central differences of P, and that n is a unit normal, on a grid
    /// over the domain's interior. `tolerance` is relative to the partials' size.
    pub fn assert_frame_matches_finite_differences(
        frame: impl Fn(f32, f32) -> Frame,
        domain: Domain,
        tolerance: f32,
    ) {
        let size = domain.max - domain.min;
        let h = size * 1e-3;
        for i in 1..8 {
            for j in 1..8 {
                let uv = domain.min + size * glam::Vec2::new(i as f32, j as f32) / 8.0;
                let f = frame(uv.x, uv.y);
                let du = (frame(uv.x + h.x, uv.y).p - frame(uv.x - h.x, uv.y).p) / (2.0 * h.x);
                let dv = (frame(uv.x, uv.y + h.y).p - frame(uv.x, uv.y - h.y).p) / (2.0 * h.y);
                let scale = f.pu.length().max(f.pv.length()).max(1e-6);
                assert!(
                    (f.pu - du).length() <= tolerance * scale,
                    "Pu at {uv}: {:?} vs {du:?}",
                    f.pu
                );
                assert!(
                    (f.pv - dv).length() <= tolerance * scale,
                    "Pv at {uv}: {:?} vs {dv:?}",
                    f.pv
                );
                assert!((f.n.length() - 1.0).abs() < 1e-5, "|n| at {uv}");
                assert!(
                    f.n.dot(f.pu).abs() <= 1e-4 * f.pu.length().max(1.0),
                    "n·Pu at {uv}"
                );
                assert!(
                    f.n.dot(f.pv).abs() <= 1e-4 * f.pv.length().max(1.0),
                    "n·Pv at {uv}"
                );
            }
        }
    }
}
