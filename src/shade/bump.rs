//! Blinn's perturbation of the normal by the gradient (Bu, Bv) of a bump height B(u,v).
//!
//! The bumped surface is P' = P + B·n (n the unit outward normal, so higher B is raised). Then
//! P'u = Pu + Bu·n + B·nu and P'v = Pv + Bv·n + B·nv, and N' = P'u × P'v. Dropping the B·nu and
//! B·nv terms (small when B is small) leaves Blinn's N' = N + Bu·(n × Pv) − Bv·(n × Pu) with
//! N = Pu × Pv: the lecture's D = Bu·A − Bv·B. Some parametrisations (the seed's sphere) have
//! Pu × Pv pointing inwards; every form here is oriented by the outward n instead.

use super::lanes::{LANES, Lanes};
use crate::surface::{Frame, Frames, Surface, normalize_or};
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
    let orientation = orientation(frame);
    let bumped = match form {
        NormalForm::Blinn => BlinnTilt::of(frame).unnormalised(bu, bv),
        NormalForm::Seed => {
            let pu = normalize_or(frame.pu, Vec3::ZERO);
            let pv = normalize_or(frame.pv, Vec3::ZERO);
            n + (n.cross(pv) * bu - n.cross(pu) * bv) * orientation
        }
        // On a flat surface n does not vary, so the full normal's B·nu and B·nv terms vanish
        // and what is left is Blinn's, exactly.
        NormalForm::Full if surface.is_flat() => BlinnTilt::of(frame).unnormalised(bu, bv),
        NormalForm::Full => {
            let (nu, nv) = normal_derivatives(surface, uv, frame);
            full_unnormalised(frame, b, bu, bv, nu, nv)
        }
    };
    normalize_or(bumped, n)
}

/// The full normal (unnormalised) of P + B·n from B, its gradient and the normal's derivatives.
#[inline(always)]
fn full_unnormalised(frame: &Frame, b: f32, bu: f32, bv: f32, nu: Vec3, nv: Vec3) -> Vec3 {
    let n = frame.n;
    let pu = frame.pu + n * bu + nu * b;
    let pv = frame.pv + n * bv + nv * b;
    pu.cross(pv) * orientation(frame)
}

/// `bumped_normal`'s full normal for a group, in SIMD lanes, where the normal's derivatives
/// have a closed form: flat surfaces (where it is Blinn's) and spheres (the same bits as one by
/// one). `false`, with nothing written, for other surfaces.
pub fn full_normals_in_closed_form(
    surface: &Surface,
    frames: &Frames,
    heights: &[f32],
    gradients: &[Vec2],
    out: &mut [Vec3],
) -> bool {
    if surface.is_flat() {
        blinn_normals(frames, heights, gradients, out);
        return true;
    }
    if !matches!(surface, Surface::Sphere(_)) {
        return false;
    }
    crate::simd::widest(
        #[inline(always)]
        || {
            let frames = frames.slices();
            let n = frames.len;
            let (heights, gradients, out) = (&heights[..n], &gradients[..n], &mut out[..n]);
            for k in 0..n {
                let (frame, b, (bu, bv)) = (frames.at(k), heights[k], gradients[k].into());
                let (nu, nv) = closed_form_normal_derivatives(surface, &frame);
                let bumped = normalize_or(full_unnormalised(&frame, b, bu, bv, nu, nv), frame.n);
                let unbumped = b == 0.0 && bu == 0.0 && bv == 0.0;
                out[k] = if unbumped { frame.n } else { bumped };
            }
        },
    );
    true
}

/// ∂n/∂u and ∂n/∂v where they have a closed form: zero on flat surfaces; a sphere's normal is
/// P/r, so Nu = Pu/r and Nv = Pv/r.
#[inline(always)]
fn closed_form_normal_derivatives(surface: &Surface, frame: &Frame) -> (Vec3, Vec3) {
    match surface {
        Surface::Sphere(sphere) => (frame.pu / sphere.radius, frame.pv / sphere.radius),
        _ => (Vec3::ZERO, Vec3::ZERO),
    }
}

/// +1 where Pu × Pv points along the outward normal, −1 where the parametrisation turns it in.
#[inline(always)]
fn orientation(frame: &Frame) -> f32 {
    if frame.pu.cross(frame.pv).dot(frame.n) < 0.0 {
        -1.0
    } else {
        1.0
    }
}

/// Blinn's normal n·|Pu × Pv| + (Bu·(n × Pv) − Bv·(n × Pu))·orientation, with the parts that
/// depend only on the frame worked out first: once for a whole group where the frame does not
/// vary (`blinn_normals_on_flat`). The orientation (±1, so exact) is folded into the two tilt
/// directions.
#[derive(Clone, Copy)]
struct BlinnTilt {
    n: Vec3,
    base: Vec3,
    along_u: Vec3,
    along_v: Vec3,
}

impl BlinnTilt {
    #[inline(always)]
    fn of(frame: &Frame) -> BlinnTilt {
        let (n, pu, pv) = (frame.n, frame.pu, frame.pv);
        let orientation = orientation(frame);
        BlinnTilt {
            n,
            base: n * pu.cross(pv).length(),
            along_u: n.cross(pv) * orientation,
            along_v: n.cross(pu) * orientation,
        }
    }

    #[inline(always)]
    fn unnormalised(&self, bu: f32, bv: f32) -> Vec3 {
        self.base + (self.along_u * bu - self.along_v * bv)
    }

    /// The normal for a gradient that is not all zero (the caller keeps the plain normal then).
    /// Straight-line code, no early return, so the lane loops below vectorise.
    #[inline(always)]
    fn normal(&self, bu: f32, bv: f32) -> Vec3 {
        normalize_or(self.unnormalised(bu, bv), self.n)
    }
}

/// `bumped_normal` in the Blinn form for a whole group: the same bits, computed a lane of
/// fragments at a time in the widest SIMD the CPU has (one fragment at a time, its square roots
/// and divisions were a third of the shader's own time).
pub fn blinn_normals(frames: &Frames, heights: &[f32], gradients: &[Vec2], out: &mut [Vec3]) {
    crate::simd::widest(
        #[inline(always)]
        || blinn_normal_lanes(frames, heights, gradients, out),
    );
}

/// `blinn_normals` where every fragment has the frame `frame` but for its point (a plane, a
/// triangle): the same bits, without reading a frame per fragment.
pub fn blinn_normals_on_flat(frame: &Frame, heights: &[f32], gradients: &[Vec2], out: &mut [Vec3]) {
    let tilt = BlinnTilt::of(frame);
    crate::simd::widest(
        #[inline(always)]
        || {
            let chunks = heights.chunks(LANES).zip(gradients.chunks(LANES));
            for ((heights, gradients), out) in chunks.zip(out.chunks_mut(LANES)) {
                let bump = BumpLanes::new(heights, gradients);
                let normals = Lanes::from_fn(|k| bump.normal(k, &tilt));
                normals.write(out);
            }
        },
    );
}

#[inline(always)]
fn blinn_normal_lanes(frames: &Frames, heights: &[f32], gradients: &[Vec2], out: &mut [Vec3]) {
    let n = out.len();
    let chunks = heights[..n]
        .chunks(LANES)
        .zip(gradients[..n].chunks(LANES))
        .zip(out.chunks_mut(LANES));
    for (chunk, ((heights, gradients), out)) in chunks.enumerate() {
        let range = chunk * LANES..chunk * LANES + out.len();
        let [mut normal, mut pu, mut pv] = [(); 3].map(|_| Lanes::splat(Vec3::ZERO));
        normal.load(&frames.n, range.clone());
        pu.load(&frames.pu, range.clone());
        pv.load(&frames.pv, range);
        let bump = BumpLanes::new(heights, gradients);
        let normals = Lanes::from_fn(|k| {
            let frame = Frame {
                p: Vec3::ZERO,
                pu: pu.at(k),
                pv: pv.at(k),
                n: normal.at(k),
            };
            bump.normal(k, &BlinnTilt::of(&frame))
        });
        normals.write(out);
    }
}

/// A lane of fragments' bump gradients, and whether each is flat (height and gradient 0).
/// Every lane of a short chunk is computed (on zeros); only the group's are written.
struct BumpLanes {
    bu: [f32; LANES],
    bv: [f32; LANES],
    flat: [bool; LANES],
}

impl BumpLanes {
    #[inline(always)]
    fn new(heights: &[f32], gradients: &[Vec2]) -> BumpLanes {
        let mut lanes = BumpLanes {
            bu: [0.0; LANES],
            bv: [0.0; LANES],
            flat: [false; LANES],
        };
        for (k, (&b, g)) in heights.iter().zip(gradients).enumerate() {
            lanes.bu[k] = g.x;
            lanes.bv[k] = g.y;
            lanes.flat[k] = b == 0.0 && g.x == 0.0 && g.y == 0.0;
        }
        lanes
    }

    /// Lane k's bumped normal; the plain normal, to the bit, where the bump is flat.
    #[inline(always)]
    fn normal(&self, k: usize, tilt: &BlinnTilt) -> Vec3 {
        let bumped = tilt.normal(self.bu[k], self.bv[k]);
        if self.flat[k] { tilt.n } else { bumped }
    }
}

/// ∂n/∂u and ∂n/∂v by central differences (steps of 1e-5 of the domain: f32 keeps ~1e-2
/// relative accuracy there, plenty for a term that is itself a correction).
fn normal_derivatives(surface: &Surface, uv: Vec2, frame: &Frame) -> (Vec3, Vec3) {
    if surface.is_flat() || matches!(surface, Surface::Sphere(_)) {
        return closed_form_normal_derivatives(surface, frame);
    }
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
    use crate::surface::{Parametric, Plane, Sphere};
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

    /// Frames of every kind the lanes meet: outward and inward parametrisations, collapsed
    /// tangents (a pole), flat and huge gradients, and a group that is not a whole number of
    /// lanes.
    #[test]
    fn lanes_give_the_bits_of_one_fragment_at_a_time() {
        let sphere = Surface::Sphere(Sphere {
            center: DVec3::ZERO,
            radius: 100.0,
        });
        let count = 3 * LANES + 5;
        let mut frames: Vec<Frame> = (0..count)
            .map(|k| {
                let t = k as f32;
                sphere.frame(37.0 * t % 720.0, 11.0 * t % 360.0)
            })
            .collect();
        frames[2].pu = Vec3::ZERO; // collapsed: no area
        frames[3] = Frame {
            pu: frames[3].pv,
            pv: frames[3].pu,
            ..frames[3]
        }; // turned inwards
        let heights: Vec<f32> = (0..count).map(|k| (k % 3) as f32 - 1.0).collect();
        let mut gradients: Vec<Vec2> = (0..count)
            .map(|k| Vec2::new((k as f32 * 0.7).sin() * 3.0, (k as f32 * 1.3).cos()))
            .collect();
        gradients[4] = Vec2::ZERO; // flat where the height is 0 too (k = 4: 4 % 3 − 1 = 0)
        gradients[5] = Vec2::new(1e30, -1e30);
        gradients[6] = Vec2::new(f32::NAN, 0.0);
        let mut lanes = vec![Vec3::NAN; count];
        blinn_normals(
            &frames.iter().copied().collect(),
            &heights,
            &gradients,
            &mut lanes,
        );
        for (k, frame) in frames.iter().enumerate() {
            let (g, b) = (gradients[k], heights[k]);
            let one = bumped_normal(&sphere, Vec2::ZERO, frame, b, g.x, g.y, NormalForm::Blinn);
            let bits = |v: Vec3| v.to_array().map(f32::to_bits);
            assert_eq!(bits(lanes[k]), bits(one), "fragment {k}: {frame:?} {b} {g}");
        }
        assert_eq!(lanes[4], frames[4].n);
    }

    /// A plane's frames, as built and turned inwards (Pu and Pv swapped), over more than a
    /// lane: the flat path, reading one frame, gives the bits of the one that reads them all.
    #[test]
    fn a_flat_surface_gives_the_bits_of_reading_every_frame() {
        let plane = plane();
        let count = LANES + 7;
        let heights: Vec<f32> = (0..count).map(|k| (k % 4) as f32 * 0.5).collect();
        let mut gradients: Vec<Vec2> = (0..count)
            .map(|k| Vec2::new((k as f32 * 0.9).cos() * 4.0, (k as f32 * 0.4).sin()))
            .collect();
        gradients[0] = Vec2::ZERO; // flat: height 0 too
        gradients[1] = Vec2::new(f32::INFINITY, 1.0);
        gradients[2] = Vec2::new(1.0, 0.0);
        for inward in [false, true] {
            let frames: Vec<Frame> = (0..count)
                .map(|k| {
                    let frame = plane.frame(k as f32 * 3.0, 50.0 - k as f32);
                    if inward {
                        Frame {
                            pu: frame.pv,
                            pv: frame.pu,
                            ..frame
                        }
                    } else {
                        frame
                    }
                })
                .collect();
            let (mut flat, mut each) = (vec![Vec3::NAN; count], vec![Vec3::NAN; count]);
            blinn_normals_on_flat(&frames[0], &heights, &gradients, &mut flat);
            blinn_normals(
                &frames.iter().copied().collect(),
                &heights,
                &gradients,
                &mut each,
            );
            let bits = |v: Vec3| v.to_array().map(f32::to_bits);
            for k in 0..count {
                assert_eq!(
                    bits(flat[k]),
                    bits(each[k]),
                    "fragment {k}, inward {inward}"
                );
            }
            assert_eq!(flat[0], Vec3::Z);
            assert!(flat.iter().all(|n| (n.length() - 1.0).abs() < 1e-6));
            // Either way round, a ramp rising along u tilts the normal back against Pu.
            let tilted = flat[2];
            assert!(
                tilted.dot(frames[2].pu) < 0.0 && tilted.z > 0.0,
                "inward {inward}: {tilted}"
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

    #[test]
    fn on_a_flat_surface_the_full_normal_is_the_bumped_surfaces_cross_product() {
        let surface = plane();
        let frame = surface.frame(40.0, 70.0);
        for (b, bu, bv) in [(0.5, 0.3, -0.2), (-3.0, 2.0, 5.0), (10.0, -40.0, 0.1)] {
            let full = bumped_normal(
                &surface,
                Vec2::new(40.0, 70.0),
                &frame,
                b,
                bu,
                bv,
                NormalForm::Full,
            );
            let exact = full_unnormalised(&frame, b, bu, bv, Vec3::ZERO, Vec3::ZERO).normalize();
            assert!((full - exact).length() < 1e-6, "{full} vs {exact}");
        }
    }

    #[test]
    fn batched_full_normals_are_the_one_by_one_bits_on_planes_and_spheres() {
        let sphere = Surface::Sphere(Sphere {
            center: DVec3::ZERO,
            radius: 280.0,
        });
        for surface in [plane(), sphere] {
            let uvs: Vec<Vec2> = (0..100)
                .map(|i| Vec2::new(i as f32 * 7.1, 5.0 + i as f32 * 3.3))
                .collect();
            let frames: Vec<Frame> = uvs.iter().map(|uv| surface.frame(uv.x, uv.y)).collect();
            let heights: Vec<f32> = (0..100).map(|i| (i % 7) as f32 * 0.6 - 1.0).collect();
            let gradients: Vec<Vec2> = (0..100)
                .map(|i| Vec2::new((i % 5) as f32 * 0.3 - 0.6, (i % 3) as f32 * -0.2))
                .collect();
            let mut batch = vec![Vec3::ZERO; 100];
            let batch_frames = frames.iter().copied().collect();
            assert!(full_normals_in_closed_form(
                &surface,
                &batch_frames,
                &heights,
                &gradients,
                &mut batch
            ));
            for k in 0..100 {
                let (b, g) = (heights[k], gradients[k]);
                let one =
                    bumped_normal(&surface, uvs[k], &frames[k], b, g.x, g.y, NormalForm::Full);
                assert_eq!(
                    batch[k].to_array().map(f32::to_bits),
                    one.to_array().map(f32::to_bits)
                );
            }
        }
    }
}
