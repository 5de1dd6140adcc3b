//! The colour stage of the scene's fragment program: each fragment's diffuse colour, from the
//! material, a colour pattern or an image (over the material where it is transparent).

use super::frame_object::FrameObject;
use super::pattern_batch::Sites;
use super::shade_scratch::ShadeScratch;
use crate::raster::Fragment;
use crate::scene::Texturing;
use crate::surface::{Frames, Surface};
use crate::texture::{Footprint, Mapping, SurfacePoint, SurfaceUv, Texel, Wrap};
use glam::{Vec2, Vec3, Vec4};
use std::borrow::Cow;

/// The diffuse colour of each fragment of the group, into `scratch.colors`.
pub(super) fn base_colors(
    time: f64,
    object: &FrameObject,
    fragments: &[Fragment],
    group: &[u32],
    scratch: &mut ShadeScratch,
) -> usize {
    let material = &object.prepared.material;
    scratch.colors.clear();
    match &material.texture {
        None => {
            scratch.colors.resize(group.len(), material.color);
            0
        }
        Some(Texturing::Pattern(binding)) => {
            scratch.colors.resize(group.len(), material.color);
            let at = Sites {
                fragments,
                group,
                frames: &scratch.frames,
            };
            let patterns = &mut scratch.patterns;
            patterns.colors(binding, at, time, &mut scratch.colors)
        }
        Some(Texturing::Image(image)) => {
            let surface = &object.prepared.surface;
            let mapping = mapping_on(&image.mapping, surface, image.sampler.wrap_s);
            let point = surface_points(time, fragments, group, &scratch.frames);
            let texture = &mut scratch.texture;
            // Every coordinate (and footprint, if wanted) is written below: resized, not
            // cleared, and written in place (a push per fragment stalled on the list's length).
            let wants_footprint = image.sampler.filter.uses_footprint();
            texture.st.resize(group.len(), Vec2::ZERO);
            let footprints = if wants_footprint { group.len() } else { 0 };
            texture.footprints.resize(footprints, Footprint::POINT);
            mapping.map_each(group.len(), point, |k, mapped| {
                texture.st[k] = mapped.st;
                if wants_footprint {
                    let fragment = &fragments[group[k] as usize];
                    texture.footprints[k] = mapped.footprint(fragment.duv_dx, fragment.duv_dy);
                }
            });
            // Every texel is written by the sampler: resized, not cleared.
            texture.texels.resize(group.len(), Texel::ZERO);
            let (st, footprints) = (&texture.st, &texture.footprints);
            image
                .texture
                .sample_many(&image.sampler, st, footprints, &mut texture.texels);
            // The material's colour held by value, not read through the material at each
            // texel.
            let base = material.color.extend(0.0);
            let over = texture
                .texels
                .iter()
                .map(|texel| over_material(*texel, base));
            scratch.colors.extend(over);
            0
        }
    }
}

/// What a mapping sees of the k-th fragment of the group (`frames` in the group's order).
pub(super) fn surface_points<'a>(
    time: f64,
    fragments: &'a [Fragment],
    group: &'a [u32],
    frames: &'a Frames,
) -> impl Fn(usize) -> SurfacePoint + 'a {
    let time = time as f32;
    let frames = frames.slices();
    let group = &group[..frames.len];
    #[inline(always)]
    move |k| {
        let frame = frames.at(k);
        SurfacePoint {
            p: frame.p,
            pu: frame.pu,
            pv: frame.pv,
            uv: fragments[group[k] as usize].uv,
            time,
        }
    }
}

/// An image's mapping in its cheapest exact form on `surface`. A spherical mapping about a
/// sphere's centre (pole +y, front +z: what scene files bind) reads back the sphere's own
/// parameters: φ = u·π/360 − π/2 and θ = v·π/360, so s = ½ + φ/2π = u/720 + ¼ and
/// t = θ/π = v/360, and the per-fragment atan2, acos, hypot and Jacobian (a third of a textured
/// sphere's instructions) become one multiply-add with a constant Jacobian (the analytic one;
/// the general form holds ∂s/∂u finite within 10⁻⁴ of the poles). s then spans [¼, 5/4): the
/// same texels under the repeat wrap spherical mappings use on s; other wraps keep the general form.
pub(super) fn mapping_on<'a>(
    mapping: &'a Mapping,
    surface: &Surface,
    wrap_s: Wrap,
) -> Cow<'a, Mapping> {
    match (mapping, surface) {
        (Mapping::Spherical(m), Surface::Sphere(_))
            if wrap_s == Wrap::Repeat && m.is_upright_about_anchor() =>
        {
            Cow::Owned(Mapping::SurfaceUv(SurfaceUv {
                scale: Vec2::new(1.0 / 720.0, 1.0 / 360.0),
                offset: Vec2::new(0.25, 0.0),
            }))
        }
        _ => Cow::Borrowed(mapping),
    }
}

/// A premultiplied texel over the material's colour `base` (its fourth lane unused): where the
/// image is transparent the material shows through. In four lanes, the same arithmetic per
/// channel as `texel.xyz + colour * (1 - alpha)` in three.
#[inline(always)]
pub(super) fn over_material(texel: Texel, base: Vec4) -> Vec3 {
    (texel + base * Vec4::splat(1.0 - texel.w)).truncate()
}
