//! Where a view ray meets the true surface near the point where it meets the tessellation.
//!
//! A fragment's ray crosses its triangle at the chord point; the true surface lies a chord
//! error away along the same ray. The quadrics (sphere, cone, paraboloid) are solved in closed
//! form around the chord point, the wave by safeguarded Newton steps from it.
//!
//! Numerics: the rays are f64 and the quadratics are formed and solved in f64 around the chord
//! point, so their constant term (how far the chord point is from the surface) keeps its digits
//! when the surface is large; the angles of the (u,v) are f32 (`atan2`, within 3e-7 rad).

use super::angles::atan2;
use super::ray_hits::{Ray, intersect, ordered_roots};
use super::sphere::SEED_UNITS_PER_RADIAN;
use super::{AxisBasis, Cone, Paraboloid, Sphere, Surface, Wave};
use glam::{DVec3, Vec2, Vec3};
use std::f32::consts::{FRAC_PI_2, TAU};

/// The true surface's point along a fragment's ray.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TrueHit {
    /// The surface's (u,v) there.
    pub uv: Vec2,
    /// The ray parameter there: the hit is `eye + depth·direction`.
    pub depth: f32,
}

/// Newton steps the wave is given before its fragment keeps the tessellation's (u,v).
pub const WAVE_NEWTON_STEPS: u32 = 8;

/// Fragments whose hits are computed together, in plain arrays the compiler turns into SIMD.
const CHUNK: usize = 64;

impl Surface {
    /// Where the ray `eye + t·direction` (relative to the surface's anchor), which meets the
    /// surface's tessellation at t = `depth`, meets the true surface: the first hit in front of
    /// the eye for the quadrics and flat surfaces (as the reference sees it), the hit the Newton
    /// steps reach from the tessellation's point for the wave. `None` where the ray misses the
    /// true surface, and where the wave's steps do not settle.
    pub fn true_hit(&self, eye: DVec3, direction: DVec3, depth: f32) -> Option<TrueHit> {
        let (mut hit, mut found) = ([TrueHit::default()], [false]);
        self.true_hits(eye, &[direction], &[depth], &mut hit, &mut found);
        found[0].then_some(hit[0])
    }

    /// `true_hit` of each (direction, depth) pair from one eye, into `hits` where `found` is set.
    pub fn true_hits(
        &self,
        eye: DVec3,
        directions: &[DVec3],
        depths: &[f32],
        hits: &mut [TrueHit],
        found: &mut [bool],
    ) {
        let n = directions.len();
        assert!(depths.len() == n && hits.len() == n && found.len() == n);
        let rays = Rays {
            eye,
            directions,
            depths,
        };
        match self {
            Surface::Plane(_) | Surface::Triangle(_) | Surface::Model(_) => {
                for k in 0..n {
                    let ray = Ray {
                        origin: eye,
                        direction: directions[k],
                    };
                    let hit = intersect(self, &ray, f64::MIN_POSITIVE..=f64::INFINITY);
                    found[k] = hit.is_some();
                    hits[k] = hit.map_or(TrueHit::default(), |hit| TrueHit {
                        uv: hit.uv,
                        depth: hit.t as f32,
                    });
                }
            }
            Surface::Sphere(s) => quadric_hits(&SphereQuadric(s), rays, hits, found),
            Surface::Paraboloid(p) => quadric_hits(&ParaboloidQuadric(p), rays, hits, found),
            Surface::Cone(c) => quadric_hits(&ConeQuadric::new(c), rays, hits, found),
            Surface::Wave(w) => {
                for k in 0..n {
                    let hit = wave_hit(w, rays.chord(k), directions[k]);
                    let hit = hit.map(|(uv, s)| TrueHit {
                        uv,
                        depth: (depths[k] as f64 + s) as f32,
                    });
                    found[k] = hit.is_some_and(|h| h.depth > 0.0);
                    hits[k] = hit.unwrap_or_default();
                }
            }
        }
    }
}

/// Rays from one eye, each with the parameter where it meets the tessellation.
#[derive(Clone, Copy)]
struct Rays<'a> {
    eye: DVec3,
    directions: &'a [DVec3],
    depths: &'a [f32],
}

impl Rays<'_> {
    /// Where ray `k` meets the tessellation.
    #[inline(always)]
    fn chord(&self, k: usize) -> DVec3 {
        self.eye + self.directions[k] * self.depths[k] as f64
    }
}

/// A surface that is a quadratic along any ray: its coordinates, the quadratic's coefficients,
/// which points of the quadric are the surface, and the (u,v) of a point on it.
trait Quadric {
    fn local(&self, v: DVec3) -> DVec3;
    fn coefficients(&self, q: DVec3, d: DVec3) -> [f64; 3];
    fn contains(&self, _p: DVec3) -> bool {
        true
    }
    fn uv(&self, p: Vec3) -> Vec2;
}

struct SphereQuadric<'a>(&'a Sphere);

impl Quadric for SphereQuadric<'_> {
    #[inline(always)]
    fn local(&self, v: DVec3) -> DVec3 {
        v
    }

    /// |q + s·d|² = r². Formed in f64 around the chord point, |q|² − r² keeps the chord point's
    /// small distance from the surface.
    #[inline(always)]
    fn coefficients(&self, q: DVec3, d: DVec3) -> [f64; 3] {
        let r = self.0.radius as f64;
        [d.dot(d), 2.0 * q.dot(d), q.dot(q) - r * r]
    }

    #[inline(always)]
    fn uv(&self, p: Vec3) -> Vec2 {
        let v = atan2((p.x * p.x + p.z * p.z).sqrt(), p.y) * SEED_UNITS_PER_RADIAN;
        Vec2::new(azimuth_u(p.x, p.z), v)
    }
}

/// h = k·ρ² (h along the axis, ρ from it).
struct ParaboloidQuadric<'a>(&'a Paraboloid);

impl Quadric for ParaboloidQuadric<'_> {
    #[inline(always)]
    fn local(&self, v: DVec3) -> DVec3 {
        local(&self.0.basis, v)
    }

    #[inline(always)]
    fn coefficients(&self, q: DVec3, d: DVec3) -> [f64; 3] {
        let k = self.0.curvature as f64;
        [
            k * (d.x * d.x + d.z * d.z),
            2.0 * k * (q.x * d.x + q.z * d.z) - d.y,
            k * (q.x * q.x + q.z * q.z) - q.y,
        ]
    }

    /// Past the rim the quadric is not the surface.
    #[inline(always)]
    fn contains(&self, p: DVec3) -> bool {
        let radius = self.0.radius as f64;
        p.x * p.x + p.z * p.z <= radius * radius
    }

    #[inline(always)]
    fn uv(&self, p: Vec3) -> Vec2 {
        Vec2::new(azimuth_u(p.x, p.z), (p.x * p.x + p.z * p.z).sqrt())
    }
}

/// ρ² = tan²α·h²; the nappe behind the apex (h < 0) is not the surface.
struct ConeQuadric<'a> {
    cone: &'a Cone,
    spread2: f64,
}

impl ConeQuadric<'_> {
    fn new(cone: &Cone) -> ConeQuadric<'_> {
        let spread2 = (cone.half_angle as f64).tan().powi(2);
        ConeQuadric { cone, spread2 }
    }
}

impl Quadric for ConeQuadric<'_> {
    #[inline(always)]
    fn local(&self, v: DVec3) -> DVec3 {
        local(&self.cone.basis, v)
    }

    #[inline(always)]
    fn coefficients(&self, q: DVec3, d: DVec3) -> [f64; 3] {
        let t2 = self.spread2;
        [
            d.x * d.x + d.z * d.z - t2 * d.y * d.y,
            2.0 * (q.x * d.x + q.z * d.z - t2 * q.y * d.y),
            q.x * q.x + q.z * q.z - t2 * q.y * q.y,
        ]
    }

    /// The nappe behind the apex, and the quadric past the base, are not the surface.
    #[inline(always)]
    fn contains(&self, p: DVec3) -> bool {
        p.y >= 0.0 && p.y <= self.cone.height as f64
    }

    #[inline(always)]
    fn uv(&self, p: Vec3) -> Vec2 {
        Vec2::new(azimuth_u(p.x, p.z), p.y)
    }
}

fn quadric_hits<Q: Quadric>(quadric: &Q, rays: Rays, hits: &mut [TrueHit], found: &mut [bool]) {
    let eye = quadric.local(rays.eye);
    let chunks = rays.directions.chunks(CHUNK).zip(rays.depths.chunks(CHUNK));
    let outputs = hits.chunks_mut(CHUNK).zip(found.chunks_mut(CHUNK));
    for ((directions, depths), (hits, found)) in chunks.zip(outputs) {
        crate::simd::widest(
            #[inline(always)]
            || quadric_chunk(quadric, eye, directions, depths, hits, found),
        );
    }
}

/// One chunk, branch-free so that it vectorises. The quadratic is in s from the chord point
/// q (t = depth + s), so its constant term is the chord point's small distance from the surface.
#[inline(always)]
fn quadric_chunk<Q: Quadric>(
    quadric: &Q,
    eye: DVec3,
    directions: &[DVec3],
    depths: &[f32],
    hits: &mut [TrueHit],
    found: &mut [bool],
) {
    let n = directions
        .len()
        .min(depths.len())
        .min(hits.len())
        .min(found.len());
    for k in 0..n {
        let d = quadric.local(directions[k]);
        let depth = depths[k] as f64;
        let q = eye + d * depth;
        let [a, b, c] = quadric.coefficients(q, d);
        let (first, second, real) = ordered_roots(a, b, c);
        let usable =
            |s: f64| real & s.is_finite() & (depth + s > 0.0) & quadric.contains(q + d * s);
        let (first_usable, second_usable) = (usable(first), usable(second));
        let s = if first_usable { first } else { second };
        let s = if first_usable | second_usable { s } else { 0.0 };
        hits[k] = TrueHit {
            uv: quadric.uv((q + d * s).as_vec3()),
            depth: (depth + s) as f32,
        };
        found[k] = first_usable | second_usable;
    }
}

/// The chord point or direction along (e1, axis, e2).
#[inline(always)]
fn local(basis: &AxisBasis, v: DVec3) -> DVec3 {
    DVec3::new(
        v.dot(basis.e1.as_dvec3()),
        v.dot(basis.axis.as_dvec3()),
        v.dot(basis.e2.as_dvec3()),
    )
}

/// The seed's u of an azimuth whose sine and cosine axes carry (x, z), in [0, 720): the inverse
/// of `sphere::azimuth`.
#[inline(always)]
fn azimuth_u(x: f32, z: f32) -> f32 {
    let u = (atan2(x, z) + FRAC_PI_2) * SEED_UNITS_PER_RADIAN;
    let u = if u < 0.0 { u + 720.0 } else { u };
    u.min(720.0f32.next_down())
}

/// y = A·sin(k·x) along the ray, by Newton steps from the chord point. Each step is held to an
/// eighth of a wavelength in x (and in s where the ray runs along the crests), so it cannot leap
/// over a crest to a farther sheet of the surface; steps that have not settled by
/// `WAVE_NEWTON_STEPS` give `None`, and the fragment keeps its tessellated (u,v); so does a hit
/// past the sheet's edges.
fn wave_hit(wave: &Wave, q: DVec3, d: DVec3) -> Option<(Vec2, f64)> {
    let amplitude = wave.amplitude as f64;
    let k = (TAU / wave.wavelength) as f64;
    let f = |s: f64| q.y + s * d.y - amplitude * (k * (q.x + s * d.x)).sin();
    let df = |s: f64| d.y - amplitude * k * d.x * (k * (q.x + s * d.x)).cos();
    let eighth = wave.wavelength as f64 / 8.0;
    let max_step = eighth / d.x.abs().max(d.length() * 1e-3);
    let tolerance = 1e-6 * (amplitude.abs() + q.length());
    let mut s = 0.0;
    for _ in 0..WAVE_NEWTON_STEPS {
        let value = f(s);
        if value.abs() <= tolerance {
            // One more step: within the tolerance Newton converges quadratically, so this puts
            // the hit at the root to f64 rounding rather than anywhere within the tolerance,
            // and the (u,v) no longer depends on where along the ray the steps began.
            let polish = -value / df(s);
            if polish.is_finite() {
                s += polish;
            }
            let p = q + d * s;
            let uv = Vec2::new(p.x as f32, -p.z as f32);
            let inside = uv.cmpge(Vec2::ZERO).all() && uv.cmple(wave.size).all();
            return inside.then_some((uv, s));
        }
        let step = (-value / df(s)).clamp(-max_step, max_step);
        if !step.is_finite() {
            return None;
        }
        s += step;
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn azimuth_u_inverts_the_frames_azimuth() {
        for u in [0.0f32, 0.3, 179.0, 360.0, 541.5, 719.9] {
            let (sin_phi, cos_phi) = super::super::sin_cos(super::super::sphere::azimuth(u));
            let back = azimuth_u(sin_phi, cos_phi);
            assert!((back - u).abs() < 1e-3, "{u} → {back}");
        }
    }
}
