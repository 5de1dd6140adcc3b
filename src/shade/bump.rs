//! Blinn's perturbation of the normal by the gradient (Bu, Bv) of a bump height B(u,v).
//!
//! The bumped surface is P' = P + B·n (n the unit outward normal, so higher B is raised). Then
//! P'u = Pu + Bu·n + B·nu and P'v = Pv + Bv·n + B·nv, and N' = P'u × P'v. Dropping the B·nu and
//! B·nv terms (small when B is small) leaves Blinn's N' = N + Bu·(n × Pv) − Bv·(n × Pu) with
//! N = Pu × Pv: the lecture's D = Bu·A − Bv·B. Some parametrisations (the seed's sphere) have
//! Pu × Pv pointing inwards; every form here is oriented by the outward n instead.

use crate::surface::{Frame, Surface, normalize_or};
use glam::{Vec2, Vec3};

/// Which normal the bump produces: the trade between speed and exactness.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum NormalForm {
    /// Blinn's first-order normal N + Bu·(n × Pv) − Bv·(n × Pu).
    #[default]
    Blinn,
    /// The seed code's shortcut: unit n, Pu and Pv (its `Norm(Du)`, `Norm(Dv)`), so bumps have
    /// the same strength per parameter unit on any surface.
    Seed,
    /// The exact normal of P + B·n, keeping the B·nu and B·nv terms.
    Full,
}

/// The unit normal of the bumped surface at `uv`, oriented like `frame.n` (falling back to it
/// where the result has no direction). `b` is the height, (`bu`, `bv`) its gradient.
#[inline]
pub fn bumped_normal(
    surface: &Surface,
    uv: Vec2,
    frame: &Frame,
    b: f32,
    bu: f32,
    bv: f32,
    form: NormalForm,
) -> Vec3 {
    let n = frame.n;
    if b == 0.0 && bu == 0.0 && bv == 0.0 {
        return n; // exactly: a bump of strength 0 must not change a single bit
    }
    let orientation = if frame.pu.cross(frame.pv).dot(n) < 0.0 {
        -1.0
    } else {
        1.0
    };
    let bumped = match form {
        NormalForm::Blinn => {
            let area = frame.pu.cross(frame.pv).length();
            n * area + (n.cross(frame.pv) * bu - n.cross(frame.pu) * bv) * orientation
        }
        NormalForm::Seed => {
            let pu = normalize_or(frame.pu, Vec3::ZERO);
            let pv = normalize_or(frame.pv, Vec3::ZERO);
            n + (n.cross(pv) * bu - n.cross(pu) * bv) * orientation
        }
        NormalForm::Full => {
            let (nu, nv) = normal_derivatives(surface, uv);
            let pu = frame.pu + n * bu + nu * b;
            let pv = frame.pv + n * bv + nv * b;
            pu.cross(pv) * orientation
        }
    };
    normalize_or(bumped, n)
}

/// ∂n/∂u and ∂n/∂v by central differences (steps of 1e-5 of the domain: f32 keeps ~1e-2
/// relative accuracy there, plenty for a term that is itself a correction).
fn normal_derivatives(surface: &Surface, uv: Vec2) -> (Vec3, Vec3) {
    let domain = surface.domain();
    let h = ((domain.max - domain.min) * 1e-5).max(Vec2::splat(1e-6));
    let normal_at = |du: f32, dv: f32| surface.frame(uv.x + du, uv.y + dv).n;
    let nu = (normal_at(h.x, 0.0) - normal_at(-h.x, 0.0)) / (2.0 * h.x);
    let nv = (normal_at(0.0, h.y) - normal_at(0.0, -h.y)) / (2.0 * h.y);
    (nu, nv)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::{Plane, Sphere};
    use glam::DVec3;

    fn plane() -> Surface {
        Surface::Plane(Plane::new(
            DVec3::ZERO,
            Vec3::Z,
            Vec3::X,
            Vec2::splat(400.0),
        ))
    }

    fn perturb(surface: &Surface, uv: Vec2, bu: f32, bv: f32, form: NormalForm) -> Vec3 {
        bumped_normal(surface, uv, &surface.frame(uv.x, uv.y), 0.0, bu, bv, form)
    }

    #[test]
    fn zero_gradient_leaves_the_normal() {
        let p = plane();
        for form in [NormalForm::Blinn, NormalForm::Seed, NormalForm::Full] {
            assert_eq!(perturb(&p, Vec2::new(10.0, 20.0), 0.0, 0.0, form), Vec3::Z);
        }
    }

    #[test]
    fn a_ramp_rising_along_u_tilts_the_normal_back_along_u() {
        // B = u: the surface P + u·n rises along +u, so its normal leans towards −u.
        let expected = Vec3::new(-1.0, 0.0, 1.0).normalize();
        for form in [NormalForm::Blinn, NormalForm::Seed, NormalForm::Full] {
            let n = perturb(&plane(), Vec2::new(10.0, 20.0), 1.0, 0.0, form);
            assert!((n - expected).length() < 1e-6, "{form:?}: {n:?}");
        }
    }

    #[test]
    fn blinn_matches_the_exact_normal_of_a_bumped_sphere_for_small_bumps() {
        // B = ε·v on a sphere: compare with the normal of P + B·n by finite differences. On a
        // sphere nu ∥ Pu and nv ∥ Pv, so the dropped terms only rescale the tangents by 1 + B/r:
        // Blinn's tilt is off by that factor, which the exact form keeps.
        let s = Sphere {
            center: DVec3::ZERO,
            radius: 100.0,
        };
        let surface = Surface::Sphere(s.clone());
        let eps = 0.2;
        let bumped = |u: f32, v: f32| {
            let f = s.frame(u, v);
            f.p + f.n * (eps * v)
        };
        for (u, v) in [(100.0, 90.0), (300.0, 200.0), (600.0, 300.0)] {
            let f = s.frame(u, v);
            let h = 0.01;
            let du = (bumped(u + h, v) - bumped(u - h, v)) / (2.0 * h);
            let dv = (bumped(u, v + h) - bumped(u, v - h)) / (2.0 * h);
            let exact = (du.cross(dv)
                * if f.pu.cross(f.pv).dot(f.n) < 0.0 {
                    -1.0
                } else {
                    1.0
                })
            .normalize();
            let uv = Vec2::new(u, v);
            let full = bumped_normal(&surface, uv, &f, eps * v, 0.0, eps, NormalForm::Full);
            let blinn = bumped_normal(&surface, uv, &f, eps * v, 0.0, eps, NormalForm::Blinn);
            let (full_error, blinn_error) = ((full - exact).length(), (blinn - exact).length());
            assert!(full_error < 1e-3, "full {full:?} vs {exact:?}");
            // B = 18 to 60 on r = 100: Blinn's first-order normal is visibly off, still bounded.
            assert!(blinn_error < 0.2, "blinn {blinn:?} vs {exact:?}");
            assert!(
                blinn_error > 10.0 * full_error,
                "blinn {blinn_error} vs full {full_error}"
            );
        }
    }

    #[test]
    fn collapsed_frames_give_finite_normals() {
        let s = Surface::Sphere(Sphere {
            center: DVec3::ZERO,
            radius: 1.0,
        });
        for form in [NormalForm::Blinn, NormalForm::Seed, NormalForm::Full] {
            let n = perturb(&s, Vec2::new(10.0, 0.0), 1e6, -1e6, form);
            assert!(
                n.is_finite() && (n.length() - 1.0).abs() < 1e-4,
                "{form:?}: {n:?}"
            );
        }
    }
}
