//! Blinn–Phong lighting of a fragment by the scene's point and directional lights.

use super::lanes::{LANES, Lanes};
use crate::scene::{Light, Material};
use glam::{DVec3, Vec3};
use std::ops::Range;

/// The scene's lights for one frame, moved into camera-relative space (eye at the origin).
#[derive(Clone, Debug)]
pub struct FrameLights {
    pub ambient: Vec3,
    pub lights: Vec<RelativeLight>,
}

#[derive(Clone, Copy, Debug)]
pub enum RelativeLight {
    Point {
        position: Vec3,
        color: Vec3,
    },
    /// `towards` is the unit vector from the surface to the light.
    Directional {
        towards: Vec3,
        color: Vec3,
    },
}

impl RelativeLight {
    /// The way from camera-relative point `p` to the light: to a point light (not unit), or a
    /// directional light's unit direction. Its sign against a normal tells which side it lights.
    #[inline(always)]
    pub fn way_from(&self, p: Vec3) -> Vec3 {
        match *self {
            RelativeLight::Point { position, .. } => position - p,
            RelativeLight::Directional { towards, .. } => towards,
        }
    }
}

impl FrameLights {
    pub fn new(ambient: Vec3, lights: &[Light], eye: DVec3) -> FrameLights {
        let lights = lights
            .iter()
            .map(|light| match *light {
                Light::Point { position, color } => RelativeLight::Point {
                    position: (position - eye).as_vec3(),
                    color,
                },
                Light::Directional { towards, color } => RelativeLight::Directional {
                    towards: crate::surface::normalize_or(towards, Vec3::Y),
                    color,
                },
            })
            .collect();
        FrameLights { ambient, lights }
    }
}

/// Turns a normal to the side of the surface the viewer sees: open surfaces are lit on whichever
/// side is seen. Decide with the geometric normal and apply the same flip to a bumped one.
#[inline]
pub fn facing_sign(p: Vec3, geometric_normal: Vec3) -> f32 {
    if geometric_normal.dot(-p) < 0.0 {
        -1.0
    } else {
        1.0
    }
}

/// Blinn-Phong in linear light at camera-relative point `p` with unit normal `n` (already facing
/// the viewer) and diffuse colour `color`. The one-fragment definition; the renderer runs
/// `blinn_phong_many`, which is tested to give the same bits.
#[inline]
pub fn blinn_phong(
    lights: &FrameLights,
    material: &Material,
    color: Vec3,
    p: Vec3,
    n: Vec3,
) -> Vec3 {
    let to_eye = crate::surface::normalize_or(-p, n);
    let mut diffuse = lights.ambient;
    let mut specular = Vec3::ZERO;
    for light in &lights.lights {
        let (to_light, color) = match *light {
            RelativeLight::Point { position, color } => {
                (crate::surface::normalize_or(position - p, n), color)
            }
            RelativeLight::Directional { towards, color } => (towards, color),
        };
        let lambert = n.dot(to_light);
        if lambert <= 0.0 {
            continue;
        }
        diffuse += color * lambert;
        let half = crate::surface::normalize_or(to_light + to_eye, n);
        specular += color * power(n.dot(half).max(0.0), material.shininess);
    }
    color * diffuse + specular * material.specular
}

/// `blinn_phong` for a batch: `out[k]` lights `colors[k]` at fragment k's camera-relative
/// point and facing unit normal. The same arithmetic in the same order (so the same
/// colours to the bit), rearranged as structure-of-arrays loops over lanes of fragments, one
/// light at a time, which the compiler turns into SIMD: the normalisations and the highlight's
/// power run four fragments at once (eight where the CPU has AVX2). `surface(range)` gives
/// those of fragments `range` (a lane's worth at a time), read straight into the lanes: callers
/// need not store points and normals first. `reach` says how much of each light reaches each
/// fragment.
pub fn blinn_phong_many<Pairs: Iterator<Item = (Vec3, Vec3)>>(
    lights: &FrameLights,
    material: &Material,
    colors: &[Vec3],
    surface: impl Fn(Range<usize>) -> Pairs,
    reach: Reach,
    out: &mut [Vec3],
) {
    match reach {
        Reach::Rows(rows) => crate::simd::widest(
            #[inline(always)]
            || blinn_phong_lanes::<_, false>(lights, material, colors, surface, rows, out),
        ),
        Reach::Terminator => crate::simd::widest(
            #[inline(always)]
            || blinn_phong_lanes::<_, true>(lights, material, colors, surface, &[], out),
        ),
    }
}

/// How much of each light reaches each fragment of a batch.
#[derive(Clone, Copy, Debug)]
pub enum Reach<'a> {
    /// Light by light, a row of `colors.len()` fractions (shadows and terminators); empty,
    /// every light reaches every fragment whole.
    Rows(&'a [f32]),
    /// Every light whole, but none past the terminator: where a fragment's normal is its
    /// surface's geometric one (no bump) and nothing casts shadows, tested in the lighting loop
    /// as `stop_at_terminator` tests it, so the same bits as its rows.
    Terminator,
}

/// The batch loops, inlined into `blinn_phong_many`'s call so they are compiled for the widest
/// SIMD the CPU has; with `TERMINATOR`, `Reach::Terminator`'s (and `reach` is empty).
#[inline(always)]
fn blinn_phong_lanes<Pairs: Iterator<Item = (Vec3, Vec3)>, const TERMINATOR: bool>(
    lights: &FrameLights,
    material: &Material,
    colors: &[Vec3],
    surface: impl Fn(Range<usize>) -> Pairs,
    reach: &[f32],
    out: &mut [Vec3],
) {
    let fragments = colors.len();
    debug_assert!(reach.is_empty() || reach.len() == fragments * lights.lights.len());
    let chunks = colors.chunks(LANES).zip(out.chunks_mut(LANES));
    for (chunk, (colors, out)) in chunks.enumerate() {
        let first = chunk * LANES;
        let (mut p, mut n) = (Lanes::splat(Vec3::ZERO), Lanes::splat(Vec3::ZERO));
        Lanes::set_pairs(&mut p, &mut n, surface(first..first + colors.len()));
        let to_eye = Lanes::from_fn(|k| crate::surface::normalize_or(-p.at(k), n.at(k)));
        let mut diffuse = Lanes::splat(lights.ambient);
        let mut specular = Lanes::splat(Vec3::ZERO);
        for (index, light) in lights.lights.iter().enumerate() {
            // Copied into a lane array first: read through `get` in the loop below, the
            // compiler made masked loads of `reach`, and when it is empty (no shadows) every one
            // of them touched its dangling address and took a microcode assist, so a still
            // without shadows took longer than one with them.
            let mut reaching = [1.0f32; LANES];
            if !TERMINATOR && !reach.is_empty() {
                let row = index * fragments + first;
                reaching[..colors.len()].copy_from_slice(&reach[row..row + colors.len()]);
            }
            let (mut lambert, mut highlight) = ([0.0f32; LANES], [0.0f32; LANES]);
            let color = match *light {
                RelativeLight::Point { position, color } => {
                    for k in 0..LANES {
                        let way = position - p.at(k);
                        let to_light = crate::surface::normalize_or(way, n.at(k));
                        (lambert[k], highlight[k]) = light_terms(n.at(k), to_light, to_eye.at(k));
                        if TERMINATOR {
                            reaching[k] = facing_light(n.at(k), way);
                        }
                    }
                    color
                }
                RelativeLight::Directional { towards, color } => {
                    for k in 0..LANES {
                        (lambert[k], highlight[k]) = light_terms(n.at(k), towards, to_eye.at(k));
                        if TERMINATOR {
                            reaching[k] = facing_light(n.at(k), towards);
                        }
                    }
                    color
                }
            };
            power_lanes(&mut highlight, material.shininess);
            for k in 0..LANES {
                // As `blinn_phong`'s `continue`: a light behind the surface adds nothing
                // (and a NaN term is added, as there).
                if lambert[k] > 0.0 || lambert[k].is_nan() {
                    // Times 1 when the light is unblocked: exact, so the same bits as above.
                    let reaching = reaching[k];
                    diffuse.set(k, diffuse.at(k) + color * (lambert[k] * reaching));
                    specular.set(k, specular.at(k) + color * (highlight[k] * reaching));
                }
            }
        }
        for (k, (out, &color)) in out.iter_mut().zip(colors).enumerate() {
            *out = color * diffuse.at(k) + specular.at(k) * material.specular;
        }
    }
}

/// Whether normal `n` faces the light that lies `way` off (`RelativeLight::way_from`): the
/// terminator's test. False for a NaN normal.
#[inline(always)]
pub fn faces_light(n: Vec3, way: Vec3) -> bool {
    n.dot(way) > 0.0
}

/// 1 where `faces_light`, else 0.
#[inline(always)]
fn facing_light(n: Vec3, way: Vec3) -> f32 {
    if faces_light(n, way) { 1.0 } else { 0.0 }
}

/// n·l and the Blinn highlight's base max(n·h, 0).
#[inline(always)]
fn light_terms(n: Vec3, to_light: Vec3, to_eye: Vec3) -> (f32, f32) {
    let half = crate::surface::normalize_or(to_light + to_eye, n);
    (n.dot(to_light), n.dot(half).max(0.0))
}

/// `power` on every lane, squaring for all lanes at once.
#[inline(always)]
fn power_lanes(x: &mut [f32; LANES], exponent: f32) {
    if !is_whole_power(exponent) {
        x.iter_mut().for_each(|x| *x = x.powf(exponent));
        return;
    }
    let least = least_base(exponent);
    x.iter_mut()
        .for_each(|x| *x = if *x < least { 0.0 } else { *x });
    let (mut base, mut n, mut result) = (*x, exponent as u32, [1.0f32; LANES]);
    while n > 0 {
        if n & 1 == 1 {
            (0..LANES).for_each(|k| result[k] *= base[k]);
        }
        n >>= 1;
        if n > 0 {
            (0..LANES).for_each(|k| base[k] *= base[k]);
        }
    }
    *x = result;
}

/// The least base whose power `exponent` is a normal float. Below it the power is subnormal or
/// zero, far below anything a colour can show, and it is taken as zero: arithmetic on subnormal
/// floats takes a microcode assist on x86, many times a multiply's time.
#[inline(always)]
fn least_base(exponent: f32) -> f32 {
    f32::MIN_POSITIVE.powf(1.0 / exponent)
}

/// Whether `power` takes `exponent` by repeated squaring.
fn is_whole_power(exponent: f32) -> bool {
    (0.0..=1024.0).contains(&exponent) && exponent == (exponent as u32) as f32
}

/// x^exponent; whole exponents (the usual case) by repeated squaring inline, several times
/// faster than `powf` (and than the `powi` library call), equal to within rounding.
#[inline]
fn power(x: f32, exponent: f32) -> f32 {
    if !is_whole_power(exponent) {
        return x.powf(exponent);
    }
    let x = if x < least_base(exponent) { 0.0 } else { x };
    let (mut base, mut n, mut result) = (x, exponent as u32, 1.0f32);
    while n > 0 {
        if n & 1 == 1 {
            result *= base;
        }
        n >>= 1;
        if n > 0 {
            base *= base;
        }
    }
    result
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn power_agrees_with_powf() {
        for exponent in [0.0, 1.0, 2.0, 7.0, 32.0, 40.0, 1024.0, 2.5, 1500.0] {
            for x in [0.0f32, 0.3, 0.9, 0.999, 1.0] {
                let (got, want) = (power(x, exponent), x.powf(exponent));
                assert!(
                    (got - want).abs() <= 1e-5 * want.max(1e-30) + 1e-30,
                    "{x}^{exponent}: {got} vs {want}"
                );
            }
        }
    }

    #[test]
    fn powers_are_zero_or_normal_floats() {
        for exponent in [1.0, 2.0, 7.0, 32.0, 40.0, 1024.0] {
            let least = least_base(exponent);
            for i in 0..=2000 {
                let x = i as f32 / 2000.0;
                let (got, exact) = (power(x, exponent), f64::from(x).powf(f64::from(exponent)));
                assert!(
                    got == 0.0 || got >= f32::MIN_POSITIVE,
                    "{x}^{exponent} = {got:e}"
                );
                // Only powers below the least normal float are dropped.
                assert!(got != 0.0 || exact < 1.0001 * f64::from(f32::MIN_POSITIVE));
                assert_eq!(got == 0.0, x < least, "{x}^{exponent}");
            }
        }
    }

    fn material() -> Material {
        Material {
            color: Vec3::new(0.8, 0.4, 0.2),
            specular: 0.5,
            shininess: 20.0,
            ..Material::default()
        }
    }

    /// A point light, a directional one and a point light on the surface itself (the fallback
    /// direction).
    fn three_lights() -> Vec<Light> {
        vec![
            Light::Point {
                position: DVec3::new(-4.0, 4.0, 6.0),
                color: Vec3::new(1.0, 0.9, 0.8),
            },
            Light::Directional {
                towards: Vec3::new(0.3, -1.0, 0.2),
                color: Vec3::splat(0.4),
            },
            Light::Point {
                position: DVec3::new(0.0, 0.0, -5.0),
                color: Vec3::ONE,
            },
        ]
    }

    /// 150 fragments' points, normals and colours: two whole lanes and a partial one; facing,
    /// grazing and facing away.
    fn fragments() -> (Vec<Vec3>, Vec<Vec3>, Vec<Vec3>) {
        let n = 150;
        let angle = |k: usize| k as f32 * 0.37;
        let points = (0..n)
            .map(|k| Vec3::new(angle(k).sin(), angle(k).cos(), -5.0 + (k % 7) as f32 * 0.1))
            .collect();
        let normals = (0..n)
            .map(|k| Vec3::new(angle(k).cos(), 0.2, angle(k).sin()).normalize())
            .collect();
        let colors = (0..n).map(|k| Vec3::splat(k as f32 / n as f32)).collect();
        (points, normals, colors)
    }

    #[test]
    fn a_blocked_light_adds_nothing_to_the_fragments_it_misses() {
        let all = three_lights();
        let lights = FrameLights::new(Vec3::splat(0.05), &all, DVec3::ZERO);
        let (points, normals, colors) = fragments();
        let n = colors.len();
        // Light j reaches fragment k unless (k + j) is a multiple of 3: a row per light.
        let reaches = |j: usize, k: usize| !(k + j).is_multiple_of(3);
        let reach: Vec<f32> = (0..all.len())
            .flat_map(|j| (0..n).map(move |k| if reaches(j, k) { 1.0 } else { 0.0 }))
            .collect();
        let batch = lit(&lights, (&points, &normals, &colors), Reach::Rows(&reach));
        for k in 0..n {
            let reaching: Vec<Light> = (0..all.len())
                .filter(|&j| reaches(j, k))
                .map(|j| all[j])
                .collect();
            let only = FrameLights::new(Vec3::splat(0.05), &reaching, DVec3::ZERO);
            let one = blinn_phong(&only, &material(), colors[k], points[k], normals[k]);
            assert_eq!(
                batch[k].to_array().map(f32::to_bits),
                one.to_array().map(f32::to_bits),
                "fragment {k}"
            );
        }
    }

    /// `blinn_phong_many` of the fragments' points, normals and colours, in a new batch.
    fn lit(lights: &FrameLights, (points, normals, colors): Fragments, reach: Reach) -> Vec<Vec3> {
        let surface = |range: Range<usize>| {
            let points = points[range.clone()].iter().copied();
            points.zip(normals[range].iter().copied())
        };
        let mut batch = vec![Vec3::NAN; colors.len()];
        blinn_phong_many(lights, &material(), colors, surface, reach, &mut batch);
        batch
    }

    type Fragments<'a> = (&'a [Vec3], &'a [Vec3], &'a [Vec3]);

    /// The terminator tested in the lighting loop lights every fragment as rows of 1 where the
    /// normal faces the light and 0 where it does not: the same bits, a NaN normal included.
    #[test]
    fn the_terminator_in_the_loop_is_its_rows() {
        let all = three_lights();
        let lights = FrameLights::new(Vec3::splat(0.05), &all, DVec3::ZERO);
        let (mut points, mut normals, mut colors) = fragments();
        normals[17] = Vec3::NAN;
        // Where the terminator decides: grazing normals that face the first light by the unit
        // way to it (so it lights them) but not by the way itself (its rows stop it).
        let RelativeLight::Point { position, .. } = lights.lights[0] else {
            unreachable!("the first light is a point light")
        };
        let grazing = (0..200_000).filter_map(|k| {
            let t = k as f32 * 0.618;
            let p = Vec3::new(t.sin(), t.cos(), (t * 0.37).sin()) * 3.0;
            let way = position - p;
            let normal = way.cross(Vec3::new(t.cos(), 1.0, t)).normalize();
            let to_light = crate::surface::normalize_or(way, normal);
            (normal.dot(way) <= 0.0 && normal.dot(to_light) > 0.0).then_some((p, normal))
        });
        for (p, normal) in grazing.take(12) {
            points.push(p);
            normals.push(normal);
            colors.push(Vec3::ONE);
        }
        assert!(points.len() > 150, "no grazing fragment found");
        let n = colors.len();
        let rows: Vec<f32> = lights
            .lights
            .iter()
            .flat_map(|light| (0..n).map(|k| facing_light(normals[k], light.way_from(points[k]))))
            .collect();
        assert!(rows.contains(&0.0) && rows.contains(&1.0), "both sides lit");
        let batch: Fragments = (&points, &normals, &colors);
        let from_rows = lit(&lights, batch, Reach::Rows(&rows));
        let in_loop = lit(&lights, batch, Reach::Terminator);
        let bits = |c: Vec3| c.to_array().map(f32::to_bits);
        for k in 0..n {
            assert_eq!(bits(in_loop[k]), bits(from_rows[k]), "fragment {k}");
        }
        let unstopped = lit(&lights, batch, Reach::Rows(&[]));
        let stopped = (150..n)
            .filter(|&k| bits(unstopped[k]) != bits(in_loop[k]))
            .count();
        assert!(stopped > 0, "the grazing fragments test the terminator");
    }

    #[test]
    fn the_batch_lights_every_fragment_as_the_single_fragment_form_does() {
        let lights = FrameLights::new(Vec3::splat(0.05), &three_lights(), DVec3::ZERO);
        let (points, normals, colors) = fragments();
        let n = colors.len();
        for shininess in [0.0, 1.0, 32.0, 7.5, 2000.0] {
            let material = Material {
                shininess,
                ..material()
            };
            // The dispatching entry (the AVX2 build where the CPU has it) and the portable build.
            let mut batch = vec![Vec3::NAN; n];
            let surface = |range: Range<usize>| {
                points[range.clone()]
                    .iter()
                    .copied()
                    .zip(normals[range].iter().copied())
            };
            blinn_phong_many(
                &lights,
                &material,
                &colors,
                surface,
                Reach::Rows(&[]),
                &mut batch,
            );
            let mut portable = vec![Vec3::NAN; n];
            blinn_phong_lanes::<_, false>(&lights, &material, &colors, surface, &[], &mut portable);
            for k in 0..n {
                let one = blinn_phong(&lights, &material, colors[k], points[k], normals[k]);
                for (lit, build) in [(batch[k], "dispatched"), (portable[k], "portable")] {
                    assert_eq!(
                        lit.to_array().map(f32::to_bits),
                        one.to_array().map(f32::to_bits),
                        "fragment {k} at shininess {shininess}, {build} batch"
                    );
                }
            }
        }
    }

    #[test]
    fn a_head_on_light_gives_full_diffuse_plus_specular() {
        let lights = FrameLights::new(
            Vec3::ZERO,
            &[Light::Directional {
                towards: Vec3::Z,
                color: Vec3::ONE,
            }],
            DVec3::ZERO,
        );
        let c = blinn_phong(
            &lights,
            &material(),
            material().color,
            Vec3::new(0.0, 0.0, -10.0),
            Vec3::Z,
        );
        assert!(
            (c - (material().color + Vec3::splat(0.5))).length() < 1e-5,
            "{c:?}"
        );
    }

    #[test]
    fn lights_behind_the_surface_add_nothing_and_back_sides_are_lit() {
        let lights = FrameLights::new(
            Vec3::splat(0.1),
            &[Light::Point {
                position: DVec3::new(0.0, 0.0, -20.0),
                color: Vec3::ONE,
            }],
            DVec3::ZERO,
        );
        // The normal points away from the eye: it is flipped, and the light is then behind.
        let p = Vec3::new(0.0, 0.0, -10.0);
        let n = Vec3::Z * facing_sign(p, Vec3::Z);
        let c = blinn_phong(&lights, &material(), material().color, p, n);
        assert!((c - material().color * 0.1).length() < 1e-6, "{c:?}");
    }
}
