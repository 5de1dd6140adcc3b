//! The seed's parametric surfaces: P(u,v), its partials Pu and Pv, and the unit normal, each
//! with a documented (u,v) domain, plus their tessellation into indexed grids.
//!
//! Numerics: every surface is stored as an f64 anchor point (its `origin`, so a scene translated by
//! 1e6 keeps its precision) plus f32 local geometry. Frames are evaluated in f32 relative to the
//! anchor: local coordinates stay within a few thousand units, where f32 keeps ~1e-4 absolute
//! precision, far below a pixel or a pattern period.

mod basis;
mod cone;
mod paraboloid;
mod plane;
mod sphere;
mod tessellate;
mod triangle;
mod wave;

pub use basis::AxisBasis;
pub use cone::Cone;
pub use paraboloid::Paraboloid;
pub use plane::Plane;
pub use sphere::Sphere;
pub use tessellate::{Mesh, Tessellation};
pub use triangle::Triangle;
pub use wave::Wave;

use glam::{DVec3, Vec2, Vec3};

/// The local differential geometry of a surface at one (u,v), relative to the surface's anchor.
#[derive(Clone, Copy, Debug, PartialEq)]
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
        }
    }

    pub fn domain(&self) -> Domain {
        match self {
            Surface::Plane(s) => s.domain(),
            Surface::Sphere(_) => Sphere::DOMAIN,
            Surface::Paraboloid(s) => s.domain(),
            Surface::Cone(s) => s.domain(),
            Surface::Wave(s) => s.domain(),
            Surface::Triangle(s) => s.domain(),
        }
    }

    /// Whether the surface encloses a volume the camera can be outside of (so back faces may be culled).
    pub fn encloses(&self, eye: DVec3) -> Option<bool> {
        match self {
            Surface::Sphere(s) => Some((eye - s.center).length() > s.radius as f64),
            _ => None,
        }
    }

    pub fn tessellate(&self, tessellation: Tessellation) -> Mesh {
        match self {
            Surface::Triangle(s) => s.mesh(),
            _ => tessellate::grid(self, tessellation),
        }
    }

    /// Grid resolution (cells along u, cells along v) and which v edges collapse to a point.
    fn grid_shape(&self, tessellation: Tessellation) -> tessellate::GridShape {
        let d = tessellation.density.max(1);
        match self {
            Surface::Plane(_) | Surface::Triangle(_) => tessellate::GridShape::flat(1, 1),
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

#[cfg(test)]
pub(crate) mod tests {
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
