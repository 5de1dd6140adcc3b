//! The seed's parametric surfaces and the torus: P(u,v), its partials Pu and Pv, and the unit normal, each
//! with a documented (u,v) domain, plus their tessellation into indexed grids. What a surface
//! defines is the `Parametric` trait; each surface implements it in its own file, and `Surface`
//! is the one enum of them the rest of the program holds.
//!
//! Numerics: every surface is stored as an f64 anchor point (its `origin`, so a scene translated by
//! 1e6 keeps its precision) plus f32 local geometry. Frames are evaluated in f32 relative to the
//! anchor: local coordinates stay within a few thousand units, where f32 keeps ~1e-4 absolute
//! precision, far below a pixel or a pattern period.

/// `$body` with `$s` bound to the surface inside whichever kind `$surface` is: the one place
/// that lists every kind.
macro_rules! each_kind {
    ($surface:expr, $s:ident => $body:expr) => {
        match $surface {
            Surface::Plane($s) => $body,
            Surface::Sphere($s) => $body,
            Surface::Paraboloid($s) => $body,
            Surface::Cone($s) => $body,
            Surface::Wave($s) => $body,
            Surface::Triangle($s) => $body,
            Surface::Torus($s) => $body,
            Surface::Model($s) => $body,
            Surface::Displaced($s) => $body,
        }
    };
}

mod angles;
mod basis;
mod cone;
mod corner;
mod displaced;
mod frames;
mod grid_shape;
mod hull;
mod model;
mod model_bvh;
mod paraboloid;
mod parametric;
mod plane;
mod ray_differentials;
mod ray_hits;
mod seed_angles;
mod sphere;
mod tessellate;
mod torus;
mod triangle;
mod true_hit;
mod wave;

pub use angles::{atan2, sin_cos};
pub use basis::AxisBasis;
pub use cone::Cone;
pub use corner::Corner;
pub use displaced::{Displaced, DisplacedBase, HeightField};
pub use frames::{FrameSlices, Frames, Vectors};
pub use grid_shape::GridShape;
pub use hull::push_out_to_hull;
pub use model::{ModelData, ModelSurface, TexturePoint};
pub use model_bvh::ModelHit;
pub use paraboloid::Paraboloid;
pub use parametric::Parametric;
pub use plane::Plane;
pub use ray_differentials::uv_derivatives;
pub use ray_hits::{Hit, Ray, Rays, TrueHit, intersect, surface_uv};
pub use sphere::Sphere;
pub use tessellate::{Mesh, Tessellation};
pub use torus::Torus;
pub use triangle::Triangle;
pub use wave::{WAVE_NEWTON_STEPS, Wave};

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
    Torus(Torus),
    /// A user's triangle mesh, in the (u,v) of its chart (see `model.rs`).
    Model(ModelSurface),
    /// A plane or sphere moved along its normal by a height field (see `displaced.rs`).
    Displaced(Displaced),
}

/// The rectangle of (u,v) a surface is defined on. The triangle's domain is the triangle inside it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Domain {
    pub min: Vec2,
    pub max: Vec2,
}

impl Surface {
    /// What a person calls it: its kind, or a model's file name.
    pub fn kind_name(&self) -> String {
        if let Surface::Model(model) = self {
            let path = std::path::Path::new(&*model.file);
            let name = path.file_name().map(|n| n.to_string_lossy());
            return name.map_or_else(|| "model".into(), |n| n.into_owned());
        }
        each_kind!(self, s => s.kind()).into()
    }

    /// The world-space anchor that frames are relative to.
    pub fn origin(&self) -> DVec3 {
        each_kind!(self, s => s.origin())
    }

    /// Moves the surface, keeping its shape.
    pub fn move_by(&mut self, offset: DVec3) {
        each_kind!(self, s => *s.origin_mut() += offset)
    }

    /// The exact frame at (u,v).
    #[inline]
    pub fn frame(&self, u: f32, v: f32) -> Frame {
        each_kind!(self, s => s.frame(u, v))
    }

    /// The exact frames at `uv(0) … uv(count − 1)`, appended to `out`: one dispatch per batch,
    /// so each surface's frame is inlined into its own loop (and the sphere's is vectorised).
    pub fn frames(&self, count: usize, uv: impl Fn(usize) -> Vec2, out: &mut Frames) {
        each_kind!(self, s => s.frames(count, uv, out))
    }

    /// Whether Pu, Pv and n are the same at every (u,v) (only the point varies).
    pub fn is_flat(&self) -> bool {
        each_kind!(self, s => s.is_flat())
    }

    /// Whether the rasterizer's triangles are the surface itself, so its fragments lie on it
    /// already: the flat surfaces and models.
    pub fn is_its_own_mesh(&self) -> bool {
        each_kind!(self, s => s.is_its_own_mesh())
    }

    pub fn domain(&self) -> Domain {
        each_kind!(self, s => s.domain())
    }

    /// The largest normal curvature anywhere on the surface, 1/length (how far it can bend from
    /// a tangent plane: by about κ·d²/2 at distance d).
    pub fn max_curvature(&self) -> f32 {
        each_kind!(self, s => s.max_curvature())
    }

    /// Whether the surface encloses a volume the camera can be outside of (so back faces may be culled).
    pub fn encloses(&self, eye: DVec3) -> Option<bool> {
        self.encloses_eye_at(eye - self.origin())
    }

    /// `encloses`, for an eye given relative to the surface's anchor.
    pub fn encloses_eye_at(&self, eye_from_anchor: DVec3) -> Option<bool> {
        each_kind!(self, s => s.encloses_eye_at(eye_from_anchor))
    }

    pub fn tessellate(&self, tessellation: Tessellation) -> Mesh {
        each_kind!(self, s => s.own_mesh().unwrap_or_else(|| tessellate::grid(s, tessellation)))
    }

    /// The triangles `tessellate` makes, counted without making them.
    pub fn triangle_count(&self, tessellation: Tessellation) -> u64 {
        each_kind!(self, s => s.triangle_count(tessellation))
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

/// The frame of a flat surface P = u·U + v·V with unit normal N, given as [U, V, N].
#[inline(always)]
fn flat_frame([u_axis, v_axis, normal]: [Vec3; 3], u: f32, v: f32) -> Frame {
    Frame {
        p: u_axis * u + v_axis * v,
        pu: u_axis,
        pv: v_axis,
        n: normal,
    }
}

/// `Parametric::frames` for a flat surface (`is_flat`), whose point is P = u·Pu + v·Pv and whose
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
            AxisBasis, Cone, Paraboloid, Plane, Sphere, Surface, Tessellation, Torus, Triangle,
            Wave,
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
            Surface::Torus(Torus {
                center: DVec3::ZERO,
                basis,
                major_radius: 2.0,
                minor_radius: 1.0,
            }),
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
