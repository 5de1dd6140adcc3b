//! The limit kernel: the POV-Ray peer's frame shaded by one hand-written function, everything
//! known in advance. Visibility is a ray per pixel against the scene's one plane and one sphere
//! (no triangles, no set-up), the checks and dimples are their formulas written out, the
//! photograph is sampled trilinearly and the gravel's height by Catmull-Rom at two mip levels,
//! one point light with Blinn-Phong, a shadow ray against the sphere for the floor and the
//! terminator for the sphere, and the 65 536-entry sRGB table: 64 pixels of a row at a time,
//! in arrays the compiler turns into SIMD (AVX2 where the CPU has it). Nothing is written to a
//! file. What it costs is the floor the renderer's design aims at.
//!
//! Numbers are `f32` throughout, as the renderer's fast path; angles come from a polynomial
//! `atan2` good to 1e-5 radians (a thousandth of a texel of the photograph).

// Lane loops index several arrays by the lane: the form the vectoriser takes.
#![allow(clippy::needless_range_loop)]

use bumpwork::scene::{Light, Scene, Texturing};
use bumpwork::surface::Surface;
use bumpwork::texture::{Encoding, Limits, MipChain, Texel, TexelGrid, load_image};
use glam::{Vec2, Vec3};
use rayon::prelude::*;
use std::f32::consts::{FRAC_PI_2, PI, TAU};
use std::path::Path;

/// Pixels shaded together: loops over 64 compile to 8-wide SIMD (AVX2); loops over 8 were
/// unrolled before the vectoriser saw them and stayed scalar (measured).
const LANES: usize = 64;

type Lane = [f32; LANES];

/// Rows a pool thread takes at a time.
const ROWS_PER_TASK: usize = 8;

/// Vectors of a lane of pixels, one array per coordinate.
#[derive(Clone, Copy)]
struct Vectors {
    x: Lane,
    y: Lane,
    z: Lane,
}

impl Default for Vectors {
    #[inline(always)]
    fn default() -> Vectors {
        Vectors {
            x: [0.0; LANES],
            y: [0.0; LANES],
            z: [0.0; LANES],
        }
    }
}

impl Vectors {
    #[inline(always)]
    fn at(&self, k: usize) -> Vec3 {
        Vec3::new(self.x[k], self.y[k], self.z[k])
    }

    #[inline(always)]
    fn set(&mut self, k: usize, v: Vec3) {
        (self.x[k], self.y[k], self.z[k]) = (v.x, v.y, v.z);
    }
}

/// Which of the scene's parts the kernel draws: the same as the scene it was made from has.
#[derive(Clone, Copy, Debug)]
struct Parts {
    checks: bool,
    dimples: bool,
    photograph: bool,
    gravel: bool,
    shadows: bool,
}

#[derive(Clone, Copy)]
struct Finish {
    color: Vec3,
    specular: f32,
}

/// The POV-Ray peer's scene, camera-relative (eye at the origin), ready to shade.
pub struct PeerKernel {
    width: usize,
    height: usize,
    /// The ray through pixel (x, y)'s centre is `corner + (x + ½)·right − (y + ½)·down`.
    corner: Vec3,
    right: Vec3,
    down: Vec3,
    plane_origin: Vec3,
    u_axis: Vec3,
    v_axis: Vec3,
    plane_normal: Vec3,
    plane_size: Vec2,
    centre: Vec3,
    radius: f32,
    light: Vec3,
    light_color: Vec3,
    ambient: Vec3,
    background: Vec3,
    floor: Finish,
    ball: Finish,
    parts: Parts,
    check_period: f32,
    dimple_period: f32,
    dimple_depth: f32,
    photograph: MipChain<Texel>,
    gravel: MipChain<f32>,
    srgb: Box<[u8; 1 << 16]>,
}

impl PeerKernel {
    /// The kernel for `scene`, the peer's plane and sphere with or without each of its parts.
    /// Panics on any other scene: the kernel knows only this one.
    pub fn new(scene: &Scene, (width, height): (u32, u32)) -> PeerKernel {
        let [Surface::Plane(plane), Surface::Sphere(sphere)] =
            [&scene.objects[0].surface, &scene.objects[1].surface]
        else {
            panic!("the limit kernel draws the peer's plane and sphere");
        };
        let Light::Point { position, color } = scene.lights[0] else {
            panic!("the peer's light is a point light");
        };
        let eye = scene.camera.eye;
        let relative = |p: glam::DVec3| (p - eye).as_vec3();
        let (floor, ball) = (&scene.objects[0].material, &scene.objects[1].material);
        let finish = |m: &bumpwork::scene::Material| {
            assert_eq!(m.shininess, 40.0, "the kernel's highlight is x⁴⁰");
            Finish {
                color: m.color,
                specular: m.specular,
            }
        };
        let param = |texture: Option<&bumpwork::scene::PatternBinding>, k: usize, default| {
            texture.map_or(default, |b| b.params[k])
        };
        let checks = match &floor.texture {
            Some(Texturing::Pattern(binding)) => Some(binding),
            _ => None,
        };
        let dimples = floor.bump.as_ref().and_then(|bump| match &bump.source {
            bumpwork::scene::BumpSource::Pattern(binding) => Some(binding),
            _ => None,
        });
        let (corner, right, down) = camera_rays(scene, width, height);
        PeerKernel {
            width: width as usize,
            height: height as usize,
            corner,
            right,
            down,
            plane_origin: relative(plane.origin),
            u_axis: plane.u_axis,
            v_axis: plane.v_axis,
            plane_normal: plane.normal,
            plane_size: plane.size,
            centre: relative(sphere.center),
            radius: sphere.radius,
            light: relative(position),
            light_color: color,
            ambient: scene.ambient,
            background: scene.background,
            floor: finish(floor),
            ball: finish(ball),
            parts: Parts {
                checks: checks.is_some(),
                dimples: dimples.is_some(),
                photograph: ball.texture.is_some(),
                gravel: ball.bump.is_some(),
                shadows: scene.shadows,
            },
            check_period: param(checks, 0, 50.0),
            dimple_period: param(dimples, 0, 30.0),
            dimple_depth: param(dimples, 1, 1.0),
            photograph: MipChain::build(shipped("chelsea.png", Encoding::Srgb)),
            gravel: MipChain::build(shipped("gravel.png", Encoding::Linear).map(|t| t.x)),
            srgb: srgb_table(),
        }
    }

    /// The frame as 8-bit sRGB, row-major, on the rayon pool.
    pub fn render(&self, out: &mut [[u8; 3]]) {
        assert_eq!(out.len(), self.width * self.height);
        out.par_chunks_mut(self.width * ROWS_PER_TASK)
            .enumerate()
            .for_each(|(band, rows)| {
                bumpwork::simd::widest(
                    #[inline(always)]
                    || {
                        for (r, row) in rows.chunks_mut(self.width).enumerate() {
                            self.row(band * ROWS_PER_TASK + r, row);
                        }
                    },
                )
            });
    }

    #[inline(always)]
    fn row(&self, y: usize, out: &mut [[u8; 3]]) {
        for (lane, out) in out.chunks_mut(LANES).enumerate() {
            let mut rgb = [[0u8; 3]; LANES];
            self.lane(lane * LANES, y, &mut rgb);
            out.copy_from_slice(&rgb[..out.len()]);
        }
    }

    /// `LANES` pixels of row `y` from column `x0`.
    #[inline(always)]
    fn lane(&self, x0: usize, y: usize, out: &mut [[u8; 3]; LANES]) {
        let mut ray = Vectors::default();
        for k in 0..LANES {
            let (px, py) = ((x0 + k) as f32 + 0.5, y as f32 + 0.5);
            ray.set(k, self.corner + self.right * px - self.down * py);
        }
        let (plane_t, ball_t) = (self.plane_hits(&ray), self.sphere_hits(&ray));
        let mut color = Vectors::default();
        for k in 0..LANES {
            color.set(k, self.background);
        }
        let on_ball: [bool; LANES] = std::array::from_fn(|k| ball_t[k] < plane_t[k]);
        let on_plane: [bool; LANES] = std::array::from_fn(|k| plane_t[k] < ball_t[k]);
        if on_plane.contains(&true) {
            let shaded = self.shade_plane(&ray, &plane_t);
            blend(&mut color, &shaded, &on_plane);
        }
        if on_ball.contains(&true) {
            let shaded = self.shade_sphere(&ray, &ball_t);
            blend(&mut color, &shaded, &on_ball);
        }
        // The table's indices in one loop (vector code), then the look-ups.
        let mut indices = [[0u16; LANES]; 3];
        for (indices, channel) in indices.iter_mut().zip([&color.x, &color.y, &color.z]) {
            for (index, &c) in indices.iter_mut().zip(channel) {
                let scaled = if c > 0.0 { c.min(1.0) } else { 0.0 } * 65535.0 + 0.5;
                // SAFETY: NaN fails the comparison, so `scaled` lies in [0.5, 65535.5].
                *index = unsafe { scaled.to_int_unchecked::<i32>() } as u16;
            }
        }
        for (k, out) in out.iter_mut().enumerate() {
            let code = |channel: usize| self.srgb[usize::from(indices[channel][k])];
            *out = [code(0), code(1), code(2)];
        }
    }

    /// Ray parameter of the plane's hit within its rectangle, or infinity.
    #[inline(always)]
    fn plane_hits(&self, ray: &Vectors) -> Lane {
        let mut t = [f32::INFINITY; LANES];
        let height = self.plane_origin.dot(self.plane_normal);
        for k in 0..LANES {
            let d = ray.at(k);
            let hit = height / d.dot(self.plane_normal);
            let along = d * hit - self.plane_origin;
            let (u, v) = (along.dot(self.u_axis), along.dot(self.v_axis));
            // `&`, not `&&`: no branches, so the loop stays vector code.
            let inside = (u >= 0.0)
                & (u <= self.plane_size.x)
                & (v >= 0.0)
                & (v <= self.plane_size.y)
                & (hit > 0.0);
            if inside {
                t[k] = hit;
            }
        }
        t
    }

    /// Ray parameter of the sphere's near hit, or infinity.
    #[inline(always)]
    fn sphere_hits(&self, ray: &Vectors) -> Lane {
        let mut t = [f32::INFINITY; LANES];
        let c2 = self.centre.length_squared() - self.radius * self.radius;
        for k in 0..LANES {
            let d = ray.at(k);
            let (a, b) = (d.length_squared(), d.dot(self.centre));
            let disc = b * b - a * c2;
            let hit = (b - disc.max(0.0).sqrt()) / a;
            if disc >= 0.0 && hit > 0.0 {
                t[k] = hit;
            }
        }
        t
    }

    /// The checked, dimpled floor at the lane's hits, lit and shadowed.
    #[inline(always)]
    fn shade_plane(&self, ray: &Vectors, t: &Lane) -> Vectors {
        // One short loop per step: each compiles to vector code.
        let mut points = Vectors::default();
        let (mut u, mut v) = ([0.0f32; LANES], [0.0f32; LANES]);
        for k in 0..LANES {
            let p = ray.at(k) * t[k].min(1e30);
            let along = p - self.plane_origin;
            (u[k], v[k]) = (along.dot(self.u_axis), along.dot(self.v_axis));
            points.set(k, p);
        }
        let mut normals = Vectors::default();
        for k in 0..LANES {
            let mut n = self.plane_normal;
            if self.parts.dimples {
                let (bu, bv) = self.dimple_slope(u[k], v[k]);
                n = (n - self.u_axis * bu - self.v_axis * bv).normalize();
            }
            normals.set(k, n);
        }
        let mut albedo = Vectors::default();
        for k in 0..LANES {
            let color = if self.parts.checks {
                self.check(self.u_axis * u[k] + self.v_axis * v[k])
            } else {
                self.floor.color
            };
            albedo.set(k, color);
        }
        let mut reach = [1.0f32; LANES];
        if self.parts.shadows {
            for k in 0..LANES {
                if self.sphere_blocks(points.at(k)) {
                    reach[k] = 0.0;
                }
            }
        }
        self.light_lanes(&points, &normals, &albedo, &reach, self.floor)
    }

    /// The photographed, gravel-bumped sphere at the lane's hits, lit up to its terminator.
    #[inline(always)]
    fn shade_sphere(&self, ray: &Vectors, t: &Lane) -> Vectors {
        let (mut points, mut normals, mut albedo) =
            (Vectors::default(), Vectors::default(), Vectors::default());
        let mut reach = [1.0f32; LANES];
        for k in 0..LANES {
            let d = ray.at(k);
            let p = d * t[k].min(1e30);
            let n = (p - self.centre) / self.radius;
            let rho = (n.x * n.x + n.z * n.z).sqrt().max(1e-6);
            let st = Vec2::new(0.5 + atan2(n.x, n.z) / TAU, atan2(rho, n.y) / PI);
            // ∂(s,t)/∂P on the sphere, and the pixel's step on the surface (a ray differential).
            let ds_dp = Vec3::new(n.z, 0.0, -n.x) / (TAU * rho * rho * self.radius);
            let dt_dp = -(Vec3::Y - n * n.y) / (PI * self.radius * rho);
            let step = |screen: Vec3| (screen - d * (screen.dot(n) / d.dot(n))) * t[k];
            let (across, down) = (step(self.right), step(self.down));
            let footprint = [
                Vec2::new(ds_dp.dot(across), dt_dp.dot(across)),
                Vec2::new(ds_dp.dot(down), dt_dp.dot(down)),
            ];
            let color = if self.parts.photograph {
                trilinear(&self.photograph, st, footprint)
            } else {
                self.ball.color
            };
            let mut bumped = n;
            if self.parts.gravel {
                let (h, dh) = catmull_rom_height(&self.gravel, st, footprint);
                // The exact normal of P + h·n on a sphere: n − ∇h·R/(R+h).
                let slope = (ds_dp * dh.x + dt_dp * dh.y) * (self.radius / (self.radius + h));
                bumped = (n - slope).normalize();
            }
            if n.dot(self.light - p) <= 0.0 {
                reach[k] = 0.0;
            }
            Vectors::set(&mut points, k, p);
            Vectors::set(&mut normals, k, bumped);
            Vectors::set(&mut albedo, k, color);
        }
        self.light_lanes(&points, &normals, &albedo, &reach, self.ball)
    }

    /// Blinn-Phong of the one point light, times how much of it reaches each point.
    #[inline(always)]
    fn light_lanes(
        &self,
        points: &Vectors,
        normals: &Vectors,
        albedo: &Vectors,
        reach: &Lane,
        finish: Finish,
    ) -> Vectors {
        let mut out = Vectors::default();
        for k in 0..LANES {
            let (p, n) = (points.at(k), normals.at(k));
            let to_eye = (-p).normalize();
            let to_light = (self.light - p).normalize();
            let lambert = n.dot(to_light);
            let half = (to_light + to_eye).normalize();
            let lit = if lambert > 0.0 { reach[k] } else { 0.0 };
            let highlight = power_40(n.dot(half).max(0.0));
            let diffuse = self.ambient + self.light_color * (lambert * lit);
            let specular = self.light_color * (highlight * lit);
            out.set(k, albedo.at(k) * diffuse + specular * finish.specular);
        }
        out
    }

    /// Whether the sphere stands between floor point `p` and the light.
    #[inline(always)]
    fn sphere_blocks(&self, p: Vec3) -> bool {
        let (way, from_centre) = (self.light - p, p - self.centre);
        let (a, b) = (way.length_squared(), from_centre.dot(way));
        let c = from_centre.length_squared() - self.radius * self.radius;
        let disc = b * b - a * c;
        let s = (-b - disc.max(0.0).sqrt()) / a;
        disc > 0.0 && s > 0.0 && s < 1.0
    }

    /// The checks pattern: cyan where "x low = y low" equals "z low", else magenta.
    #[inline(always)]
    fn check(&self, along: Vec3) -> Vec3 {
        let half = self.check_period / 2.0;
        let low = |c: f32| modulo(c, self.check_period) < half;
        if (low(along.x) == low(along.y)) == low(along.z) {
            Vec3::new(0.0, 1.0, 1.0)
        } else {
            Vec3::new(1.0, 0.0, 1.0)
        }
    }

    /// The dimples' slope (∂h/∂u, ∂h/∂v): spherical hollows, flat beyond their rims.
    #[inline(always)]
    fn dimple_slope(&self, u: f32, v: f32) -> (f32, f32) {
        let half = self.dimple_period / 2.0;
        let rim = self.dimple_period / 3.0;
        let cu = modulo(u, self.dimple_period) - half;
        let cv = modulo(v, self.dimple_period) - half;
        let cap = half * half - cu * cu - cv * cv;
        let scale = self.dimple_depth / cap.max(rim * rim).sqrt();
        let scale = if cap > rim * rim { scale } else { 0.0 };
        (cu * scale, cv * scale)
    }
}

/// Ray corner and per-pixel steps of the scene's camera at `width`×`height`.
fn camera_rays(scene: &Scene, width: u32, height: u32) -> (Vec3, Vec3, Vec3) {
    let camera = &scene.camera;
    let forward = (camera.target - camera.eye).as_vec3().normalize();
    let right = forward.cross(camera.up).normalize();
    let up = right.cross(forward);
    let half_height = (camera.vfov_degrees.to_radians() / 2.0).tan();
    let half_width = half_height * width as f32 / height as f32;
    let corner = forward - right * half_width + up * half_height;
    let right_step = right * (2.0 * half_width / width as f32);
    let down_step = up * (2.0 * half_height / height as f32);
    (corner, right_step, down_step)
}

/// A texture of the repository's `textures/`, as texels decoded by `encoding`.
fn shipped(name: &str, encoding: Encoding) -> TexelGrid<Texel> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("textures")
        .join(name);
    load_image(&path, &Limits::default(), encoding)
        .expect("shipped texture")
        .texels
}

fn srgb_table() -> Box<[u8; 1 << 16]> {
    let mut table = Box::new([0u8; 1 << 16]);
    for (i, code) in table.iter_mut().enumerate() {
        let linear = i as f64 / 65535.0;
        let encoded = if linear <= 0.003_130_8 {
            12.92 * linear
        } else {
            1.055 * linear.powf(1.0 / 2.4) - 0.055
        };
        *code = (encoded * 255.0).round() as u8;
    }
    table
}

fn blend(color: &mut Vectors, shaded: &Vectors, mask: &[bool; LANES]) {
    for k in 0..LANES {
        if mask[k] {
            color.set(k, shaded.at(k));
        }
    }
}

/// The floored remainder (`%` in the pattern language) without `fmod`'s library call.
#[inline(always)]
fn modulo(x: f32, period: f32) -> f32 {
    x - period * (x / period).floor()
}

/// atan2 to 1e-5 radians, without a library call.
#[inline(always)]
fn atan2(y: f32, x: f32) -> f32 {
    let (ax, ay) = (x.abs(), y.abs());
    let a = ax.min(ay) / ax.max(ay).max(f32::MIN_POSITIVE);
    let s = a * a;
    let mut r = ((-0.046_496_474 * s + 0.159_314_22) * s - 0.327_622_76) * s * a + a;
    if ay > ax {
        r = FRAC_PI_2 - r;
    }
    if x < 0.0 {
        r = PI - r;
    }
    if y < 0.0 { -r } else { r }
}

/// x⁴⁰, the peer's shininess, in six multiplies; 0 below 0.1127, about where x⁴⁰ becomes a
/// subnormal float (slow on x86) far under any colour's last bit.
#[inline(always)]
fn power_40(x: f32) -> f32 {
    let x = if x < 0.1127 { 0.0 } else { x };
    let x2 = x * x;
    let x4 = x2 * x2;
    let x8 = x4 * x4;
    let x32 = x8 * x8 * x8 * x8;
    x32 * x8
}

/// The finer of the two mip levels for a footprint of ∂(s,t)/∂x and ∂(s,t)/∂y, and how far
/// towards the coarser one it lies.
#[inline(always)]
fn levels<T: bumpwork::texture::Averageable>(
    chain: &MipChain<T>,
    footprint: [Vec2; 2],
) -> (usize, f32) {
    let lod = level_of_detail(chain, footprint);
    let fine = lod.floor();
    (fine as usize, lod - fine)
}

/// The mip level (fractional) for a footprint of ∂(s,t)/∂x and ∂(s,t)/∂y.
#[inline(always)]
fn level_of_detail<T: bumpwork::texture::Averageable>(
    chain: &MipChain<T>,
    footprint: [Vec2; 2],
) -> f32 {
    let (base, coarsest) = (chain.base(), chain.coarsest_level());
    let texels = Vec2::new(base.width() as f32, base.height() as f32);
    let longest = (footprint[0] * texels)
        .length_squared()
        .max((footprint[1] * texels).length_squared());
    if longest <= 1.0 {
        return 0.0;
    }
    (0.5 * longest.log2()).min(coarsest as f32)
}

/// Taps along one axis: first texel index and fraction, `s` repeating or clamped.
#[inline(always)]
fn axis(s: f32, n: u32, repeat: bool) -> (i32, f32) {
    let reduced = if repeat { s - s.floor() } else { s };
    let x = reduced * n as f32 - 0.5;
    let x0 = x.floor();
    (x0 as i32, x - x0)
}

#[inline(always)]
fn wrap(i: i32, n: u32, repeat: bool) -> usize {
    if repeat {
        i.rem_euclid(n as i32) as usize
    } else {
        i.clamp(0, n as i32 - 1) as usize
    }
}

/// Trilinear sample of `chain` at `st` (s repeating, t clamped).
#[inline(always)]
fn trilinear(chain: &MipChain<Texel>, st: Vec2, footprint: [Vec2; 2]) -> Vec3 {
    let (fine, blend) = levels(chain, footprint);
    let near = bilinear(chain.level(fine), st);
    if blend == 0.0 {
        return near;
    }
    near + (bilinear(chain.level(fine + 1), st) - near) * blend
}

#[inline(always)]
fn bilinear(level: &TexelGrid<Texel>, st: Vec2) -> Vec3 {
    let (w, h) = (level.width(), level.height());
    let ((x0, fx), (y0, fy)) = (axis(st.x, w, true), axis(st.y, h, false));
    let texels = level.texels();
    let at = |x: i32, y: i32| texels[wrap(y, h, false) * w as usize + wrap(x, w, true)].truncate();
    let top = at(x0, y0).lerp(at(x0 + 1, y0), fx);
    let bottom = at(x0, y0 + 1).lerp(at(x0 + 1, y0 + 1), fx);
    top.lerp(bottom, fy)
}

/// Height and its (s, t) gradient by Catmull-Rom at the footprint's two mip levels.
#[inline(always)]
fn catmull_rom_height(chain: &MipChain<f32>, st: Vec2, footprint: [Vec2; 2]) -> (f32, Vec2) {
    let (fine, blend) = levels(chain, footprint);
    let (h, g) = bicubic(chain.level(fine), st);
    if blend == 0.0 {
        return (h, g);
    }
    let (h2, g2) = bicubic(chain.level(fine + 1), st);
    (h + (h2 - h) * blend, g + (g2 - g) * blend)
}

#[inline(always)]
fn bicubic(level: &TexelGrid<f32>, st: Vec2) -> (f32, Vec2) {
    let (w, h) = (level.width(), level.height());
    let ((x0, fx), (y0, fy)) = (axis(st.x, w, true), axis(st.y, h, false));
    let (wx, dx, wy, dy) = (weights(fx), slopes(fx), weights(fy), slopes(fy));
    let texels = level.texels();
    let (mut height, mut ds, mut dt) = (0.0, 0.0, 0.0);
    for j in 0..4 {
        let row = wrap(y0 - 1 + j as i32, h, false) * w as usize;
        let (mut across, mut across_slope) = (0.0, 0.0);
        for i in 0..4 {
            let texel = texels[row + wrap(x0 - 1 + i as i32, w, true)];
            across += texel * wx[i];
            across_slope += texel * dx[i];
        }
        height += across * wy[j];
        ds += across_slope * wy[j];
        dt += across * dy[j];
    }
    (height, Vec2::new(ds * w as f32, dt * h as f32))
}

#[inline(always)]
fn weights(f: f32) -> [f32; 4] {
    let (f2, f3) = (f * f, f * f * f);
    [
        0.5 * (-f3 + 2.0 * f2 - f),
        0.5 * (3.0 * f3 - 5.0 * f2 + 2.0),
        0.5 * (-3.0 * f3 + 4.0 * f2 + f),
        0.5 * (f3 - f2),
    ]
}

#[inline(always)]
fn slopes(f: f32) -> [f32; 4] {
    let f2 = f * f;
    [
        0.5 * (-3.0 * f2 + 4.0 * f - 1.0),
        0.5 * (9.0 * f2 - 10.0 * f),
        0.5 * (-9.0 * f2 + 8.0 * f + 1.0),
        0.5 * (3.0 * f2 - 2.0 * f),
    ]
}
