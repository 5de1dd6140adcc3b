//! The scene's fragment program: per batch of fragments, grouped by object, the exact surface
//! frame, the texture or material colour, the bumped normal, then lighting (or a view mode).
//! Work the scene does not need is skipped: no texture, no sampling; no bump, no perturbation.

use super::bump::{
    NormalForm, blinn_normals, blinn_normals_on_flat, bumped_normal, full_normals_in_closed_form,
};
use super::exact_coverage::Neighbours;
use super::exact_point::{ExactScratch, SurfacePointSource, exact_fragments, true_hit_derivatives};
use super::gradient::{GradientMethod, central_difference, shifted_fragments};
use super::lighting::{
    FrameLights, Reach, RelativeLight, blinn_phong_many, faces_light, facing_sign,
};
use super::pattern_batch::{PatternBatch, Sites};
use super::shader_mode::ShaderMode;
use super::shadowing::Shadowing;
use super::vertex_normals::VertexNormals;
use crate::pattern::{OutputKind, Precision};
use crate::raster::{
    Fragment, FragmentShader, FrameObject, FrameStats, Framebuffer, PreparedScene, RenderTarget,
    SampleRays,
};
use crate::scene::Camera;
use crate::scene::{BumpSource, Material, Scene, Texturing};
use crate::surface::{Frame, Frames, ModelSurface, Surface, Vectors};
use crate::texture::{Footprint, HeightSample, Mapping, SurfacePoint, SurfaceUv, Texel, Wrap};
use glam::{Mat2, Vec2, Vec3, Vec4};
use std::borrow::Cow;
use std::ops::Range;
use std::sync::Arc;

/// The default program for a scene: Blinn-Phong with textures and bump maps.
pub struct LitShader {
    pub lights: FrameLights,
    /// Seconds, for animated patterns and scrolling images.
    pub time: f64,
    pub mode: ShaderMode,
    pub normal_form: NormalForm,
    pub gradient: GradientMethod,
    pub pattern_precision: Precision,
    /// Per object of the prepared scene: shade with the tessellation's interpolated position and
    /// normal instead of the exact surface frame (`None`: the exact frame).
    pub vertex_normals: Option<Arc<[VertexNormals]>>,
    /// Depth that the depth view shows as mid-grey.
    pub depth_scale: f32,
    /// Whether each light stops at every surface's geometric terminator: it reaches a point only
    /// where the point's unbumped seen side faces it, as shadows require (a bump facing the light
    /// past a sphere's terminator lies inside the sphere's own shadow). Off, as with shadows off,
    /// bumps are lit wherever their own normal faces a light, as in Blinn's pictures.
    pub terminators: bool,
    /// What else blocks the lights (`None`: nothing does).
    pub shadows: Option<Arc<dyn Shadowing>>,
    /// Which objects each one's true surface may pass in front of, for resolving coverage
    /// exactly at the true surfaces (`None`: the mesh's coverage stands).
    pub exact_coverage: Option<Arc<Neighbours>>,
    /// The colour of pixels whose ray meets no true surface.
    pub background: Vec3,
    /// Where fragments of curved surfaces are shaded: on their triangle or on the true surface.
    pub surface_point: SurfacePointSource,
}

impl LitShader {
    pub fn new(scene: &Scene, camera: &Camera) -> LitShader {
        LitShader {
            lights: FrameLights::new(scene.ambient, &scene.lights, camera.eye),
            time: 0.0,
            mode: ShaderMode::Shaded,
            normal_form: NormalForm::Blinn,
            gradient: GradientMethod::Exact,
            pattern_precision: Precision::Fastest,
            vertex_normals: None,
            depth_scale: (camera.target - camera.eye).length() as f32,
            terminators: scene.shadows,
            shadows: None,
            exact_coverage: None,
            background: scene.background,
            surface_point: SurfacePointSource::Interpolated,
        }
    }
}

/// Zeroes `reach` where the light is behind the seen side of the geometric surface (facing
/// unit `normals` at camera-relative `points`), or the side cannot be told (a NaN normal).
fn stop_at_terminator(light: &RelativeLight, points: &[Vec3], normals: &[Vec3], reach: &mut [f32]) {
    // One loop per kind of light, compiled for the widest SIMD: with the light's kind matched
    // inside it, the loop stayed scalar.
    #[inline(always)]
    fn stop(points: &[Vec3], normals: &[Vec3], reach: &mut [f32], way: impl Fn(Vec3) -> Vec3) {
        for ((reach, &p), &n) in reach.iter_mut().zip(points).zip(normals) {
            *reach = if faces_light(n, way(p)) { *reach } else { 0.0 };
        }
    }
    crate::simd::widest(
        #[inline(always)]
        || match *light {
            RelativeLight::Point { position, .. } => stop(points, normals, reach, |p| position - p),
            RelativeLight::Directional { towards, .. } => stop(points, normals, reach, |_| towards),
        },
    );
}

/// Per-thread working memory, reused for every batch.
#[derive(Default)]
pub struct ShadeScratch {
    /// The batch's fragments moved to their true surfaces (`SurfacePointSource::Exact`).
    exact: ExactScratch,
    /// Fragment indices grouped by object.
    order: Vec<u32>,
    group_starts: Vec<usize>,
    frames: Frames,
    colors: Vec<Vec3>,
    /// Camera-relative positions (for shadows and lighting), facing normals to light, and the
    /// lit colours.
    points: Vec<Vec3>,
    normals: Vec<Vec3>,
    lit: Vec<Vec3>,
    /// Per light, per fragment, the fraction of the light reaching it; empty without shadows.
    reach: Vec<f32>,
    /// The fragments' facing geometric normals, for shadows.
    shadow_normals: Vec<Vec3>,
    heights: Vec<f32>,
    gradients: Vec<Vec2>,
    patterns: PatternBatch,
    texture: TextureBatch,
    height_lookups: HeightLookups,
    /// Inputs and outputs of shifted height evaluations (central differences, the seed lattice).
    shifted: Shifted,
}

/// A batch's image lookups: texture coordinates, footprints (when the filter reads them) and
/// the texels.
#[derive(Default)]
struct TextureBatch {
    st: Vec<Vec2>,
    footprints: Vec<Footprint>,
    texels: Vec<Texel>,
}

/// A batch's bump-map lookups: texture coordinates, footprints, the mapping's Jacobians and
/// the samples.
#[derive(Default)]
struct HeightLookups {
    st: Vec<Vec2>,
    footprints: Vec<Footprint>,
    jacobians: Vec<Mat2>,
    samples: Vec<HeightSample>,
}

#[derive(Default)]
struct Shifted {
    fragments: Vec<Fragment>,
    identity: Vec<u32>,
    frames: Frames,
    heights: Vec<f32>,
    gradients: Vec<Vec2>,
    /// Heights at +u, −u, +v, −v.
    around: [Vec<f32>; 4],
}

impl FragmentShader for LitShader {
    type Scratch = ShadeScratch;

    fn scratch(&self) -> ShadeScratch {
        let mut scratch = ShadeScratch::default();
        scratch.patterns.precision = self.pattern_precision;
        scratch
    }

    /// Only image lookups read the derivatives: a colour image through a filter that picks a
    /// mip level, and image bump maps (whose gradient is filtered over the footprint).
    fn reads_derivatives(&self, object: &FrameObject) -> bool {
        let material = &object.prepared.material;
        let filtered_image = matches!(&material.texture,
            Some(Texturing::Image(image)) if image.sampler.filter.uses_footprint());
        let image_bump = matches!(&material.bump,
            Some(bump) if matches!(bump.source, BumpSource::Image(_)));
        filtered_image || image_bump
    }

    fn shade(
        &self,
        objects: &[FrameObject],
        rays: &SampleRays,
        fragments: &mut [Fragment],
        scratch: &mut ShadeScratch,
        out: &mut [Vec3],
    ) -> usize {
        if self.surface_point == SurfacePointSource::Exact {
            self.move_to_true_surfaces(objects, rays, fragments, scratch, out);
        }
        let mut order = std::mem::take(&mut scratch.order);
        // One group past the objects' holds the background fragments (already coloured).
        group_by_object(
            fragments,
            objects.len() + 1,
            &mut order,
            &mut scratch.group_starts,
        );
        let mut flattened = 0;
        for (object_index, object) in objects.iter().enumerate() {
            let (start, end) = (
                scratch.group_starts[object_index],
                scratch.group_starts[object_index + 1],
            );
            if start < end {
                let group = &order[start..end];
                for part in group.chunks(chunk_size(object)) {
                    let batch = ObjectBatch {
                        index: object_index,
                        object,
                        group: part,
                    };
                    flattened += self.shade_object(batch, rays, fragments, scratch, out);
                }
            }
        }
        scratch.order = order;
        flattened
    }
}

/// How many of an object's fragments are shaded together. Without patterns, a chunk's working
/// arrays (frames, texels, points, normals…) stay in L1 cache from stage to stage; 256 was the
/// fastest of the sizes tried on the euc peer's frame. The pattern interpreter instead spreads
/// its per-instruction dispatch over every lane it gets, so patterned objects are shaded whole
/// (chunks made the POV-Ray peer's frame slower).
fn chunk_size(object: &FrameObject) -> usize {
    const IN_CACHE: usize = 256;
    let material = &object.prepared.material;
    let pattern_texture = matches!(material.texture, Some(Texturing::Pattern(_)));
    let pattern_bump =
        matches!(&material.bump, Some(bump) if matches!(bump.source, BumpSource::Pattern(_)));
    if pattern_texture || pattern_bump {
        usize::MAX
    } else {
        IN_CACHE
    }
}

/// One shading batch: fragments of one object, by index into the tile's fragments.
#[derive(Clone, Copy)]
struct ObjectBatch<'a> {
    index: usize,
    object: &'a FrameObject<'a>,
    group: &'a [u32],
}

impl LitShader {
    /// Moves each fragment onto the true surface its ray meets (see `exact_fragments`); those
    /// that meet none are given the background colour here.
    fn move_to_true_surfaces(
        &self,
        objects: &[FrameObject],
        rays: &SampleRays,
        fragments: &mut [Fragment],
        scratch: &mut ShadeScratch,
        out: &mut [Vec3],
    ) {
        let coverage = self.exact_coverage.as_deref();
        let moved = exact_fragments(objects, coverage, rays, fragments, &mut scratch.exact);
        if moved.background > 0 {
            let background = objects.len() as u32;
            let fragments = fragments.iter().zip(out.iter_mut());
            for (_, out) in fragments.filter(|(f, _)| f.object == background) {
                *out = self.background;
            }
        }
    }

    fn shade_object(
        &self,
        batch: ObjectBatch,
        rays: &SampleRays,
        fragments: &mut [Fragment],
        scratch: &mut ShadeScratch,
        out: &mut [Vec3],
    ) -> usize {
        let ObjectBatch {
            index: object_index,
            object,
            group,
        } = batch;
        let surface = &object.prepared.surface;
        let material = &object.prepared.material;
        scratch.frames.clear();
        let uv = |k: usize| fragments[group[k] as usize].uv;
        surface.frames(group.len(), uv, &mut scratch.frames);
        if let Surface::Model(model) = surface {
            to_texture_space(model, fragments, group, &mut scratch.frames);
        }
        // Fragments moved to their true hits take their derivatives from these frames, the
        // true surface's (before any interpolated normals replace them).
        if self.surface_point == SurfacePointSource::Exact && self.reads_derivatives(object) {
            let (frames, exact) = (&scratch.frames, &mut scratch.exact);
            let moved = &exact.moved;
            let derivatives = &mut exact.derivatives;
            true_hit_derivatives(surface, rays, fragments, group, frames, moved, derivatives);
        }
        let fragments = &*fragments;
        // A model's frames are interpolated from its vertices already (and its fragments'
        // (u,v) are the texture's by now, which name no triangle).
        let from_vertices = self.vertex_normals.as_ref();
        if let Some(normals) = from_vertices.filter(|_| !matches!(surface, Surface::Model(_))) {
            interpolate_frames(
                &normals[object_index],
                fragments,
                group,
                &mut scratch.frames,
            );
        }
        let mut flattened = self.base_colors(object, fragments, group, scratch);
        flattened += self.bump_gradients(object, fragments, group, scratch);
        let (points, origin) = (&mut scratch.points, object.origin);
        points.clear();
        origin_plus(origin, &scratch.frames.p, points);
        // On a flat surface every frame has the same normal: read once, not from each frame.
        let constant_normal = match scratch.frames.first() {
            Some(frame) if self.frame_is_constant(surface) => Some(frame.n),
            _ => None,
        };
        let unbumped = material.bump.is_none();
        // Where the only thing that stops light is the terminator, and the lit normal is the
        // geometric one, the lighting loop tests it: no pass of its own.
        let terminator_in_lighting = unbumped && self.terminators && !self.any_light_casts();
        if self.mode == ShaderMode::Shaded && !terminator_in_lighting {
            self.light_reach(object_index, constant_normal, scratch);
        }
        if self.mode == ShaderMode::Shaded && unbumped {
            // The frames' own normals, read straight into the lighting's lanes.
            let (frames, points) = (&scratch.frames, &scratch.points);
            let surface = |range: Range<usize>| {
                let points = points[range.clone()].iter();
                points
                    .zip(frames.n.range(range))
                    .map(|(&p, n)| (p, n * facing_sign(p, n)))
            };
            let reach = match terminator_in_lighting {
                true => Reach::Terminator,
                false => Reach::Rows(&scratch.reach),
            };
            self.lighting(material, group, &scratch.colors, reach)
                .light(surface, &mut scratch.lit, out);
            return flattened;
        }
        self.lighting_inputs(object, fragments, group, constant_normal, scratch);
        if self.mode == ShaderMode::Shaded {
            let (points, normals) = (&scratch.points, &scratch.normals);
            let surface = |range: Range<usize>| {
                let points = points[range.clone()].iter().copied();
                points.zip(normals[range].iter().copied())
            };
            let reach = Reach::Rows(&scratch.reach);
            self.lighting(material, group, &scratch.colors, reach)
                .light(surface, &mut scratch.lit, out);
        } else {
            for (k, &i) in group.iter().enumerate() {
                // Without a bump there are no heights: the surface is at height 0.
                let height = scratch.heights.get(k).copied().unwrap_or(0.0);
                let normal = scratch.normals[k];
                out[i as usize] = self.view_colour(&fragments[i as usize], normal, height);
            }
        }
        flattened
    }

    /// Whether any light casts shadows in this frame.
    fn any_light_casts(&self) -> bool {
        let lights = self.lights.lights.len();
        let shadows = self.shadows.as_ref();
        shadows.is_some_and(|shadows| (0..lights).any(|light| shadows.casts(light)))
    }

    fn lighting<'a>(
        &'a self,
        material: &'a Material,
        group: &'a [u32],
        colors: &'a [Vec3],
        reach: Reach<'a>,
    ) -> GroupLighting<'a> {
        GroupLighting {
            lights: &self.lights,
            material,
            group,
            colors,
            reach,
        }
    }

    /// How much of each light reaches the group's fragments (at `scratch.points`), into
    /// `scratch.reach` (left empty when lights reach every fragment whole: no terminators).
    /// Shadows and terminators follow the geometric surface, not the bumps. `constant_normal` is
    /// every frame's normal, if they share one.
    fn light_reach(
        &self,
        object_index: usize,
        constant_normal: Option<Vec3>,
        scratch: &mut ShadeScratch,
    ) {
        scratch.reach.clear();
        if !self.terminators || self.lights.lights.is_empty() {
            return;
        }
        let (points, normals) = (&scratch.points, &mut scratch.shadow_normals);
        normals.clear();
        let facing = |p: Vec3, n: Vec3| n * facing_sign(p, n);
        match constant_normal {
            Some(n) => normals.extend(points.iter().map(|&p| facing(p, n))),
            None => {
                let frames = points.iter().zip(scratch.frames.n.range(0..points.len()));
                normals.extend(frames.map(|(&p, n)| facing(p, n)));
            }
        }
        let count = points.len();
        scratch.reach.resize(self.lights.lights.len() * count, 1.0);
        let per_light = scratch.reach.chunks_mut(count.max(1));
        for ((index, light), reach) in self.lights.lights.iter().enumerate().zip(per_light) {
            let shadows = self.shadows.as_ref().filter(|s| s.casts(index));
            if let Some(shadows) = shadows {
                shadows.reaching(index, object_index, points, normals, reach);
            }
            stop_at_terminator(light, points, normals, reach);
        }
    }

    /// Facing (bumped) normals of the group at `scratch.points`, into `scratch.normals`
    /// (shading without a bump reads them from the frames instead). `constant_normal` is every
    /// frame's normal, if they share one.
    fn lighting_inputs(
        &self,
        object: &FrameObject,
        fragments: &[Fragment],
        group: &[u32],
        constant_normal: Option<Vec3>,
        scratch: &mut ShadeScratch,
    ) {
        let surface = &object.prepared.surface;
        let bumped = object.prepared.material.bump.is_some();
        // Every normal is written below: resized, not cleared.
        let (points, normals) = (&scratch.points, &mut scratch.normals);
        normals.resize(group.len(), Vec3::ZERO);
        let (frames, heights, gradients) = (&scratch.frames, &scratch.heights, &scratch.gradients);
        let blinn_when_flat =
            bumped && matches!(self.normal_form, NormalForm::Blinn | NormalForm::Full);
        if let (true, Some(frame), Some(n)) = (blinn_when_flat, frames.first(), constant_normal) {
            // On a flat surface the full normal is Blinn's (see `bumped_normal`).
            blinn_normals_on_flat(&frame, heights, gradients, normals);
            let facing = normals.iter_mut().zip(points);
            facing.for_each(|(normal, &p)| *normal *= facing_sign(p, n));
            return;
        }
        // Normals worked out as a batch (or `false`: one by one below).
        let batched = match self.normal_form {
            _ if !bumped => false,
            NormalForm::Blinn => {
                blinn_normals(frames, heights, gradients, normals);
                true
            }
            NormalForm::Full => {
                full_normals_in_closed_form(surface, frames, heights, gradients, normals)
            }
            NormalForm::Seed => false,
        };
        if batched || !bumped {
            let geometric = scratch.frames.n.range(0..group.len());
            for ((&p, normal), n) in points.iter().zip(normals.iter_mut()).zip(geometric) {
                let shown = if batched { *normal } else { n };
                *normal = shown * facing_sign(p, n);
            }
            return;
        }
        let frames = group.iter().zip(scratch.frames.iter());
        let outputs = points.iter().zip(normals);
        for (k, ((&i, frame), (&p, normal))) in frames.zip(outputs).enumerate() {
            let (b, gradient) = (scratch.heights[k], scratch.gradients[k]);
            let uv = fragments[i as usize].uv;
            let (form, (bu, bv)) = (self.normal_form, gradient.into());
            let n = bumped_normal(surface, uv, &frame, b, bu, bv, form);
            *normal = n * facing_sign(p, frame.n);
        }
    }

    /// Whether every fragment of `surface` has the same frame but for its point: a flat
    /// surface without interpolated vertex normals.
    fn frame_is_constant(&self, surface: &Surface) -> bool {
        self.vertex_normals.is_none() && surface.is_flat()
    }

    /// What a view mode other than `Shaded` shows at a fragment.
    fn view_colour(&self, fragment: &Fragment, normal: Vec3, height: f32) -> Vec3 {
        match self.mode {
            ShaderMode::Shaded => unreachable!("shaded fragments are lit as a batch"),
            ShaderMode::Height => Vec3::splat(0.5 + 0.5 * (height * 0.2).tanh()),
            ShaderMode::Normals => normal * 0.5 + Vec3::splat(0.5),
            ShaderMode::Uv => (fragment.uv / 30.0).fract_gl().extend(0.0),
            ShaderMode::Depth => Vec3::splat((-fragment.depth / self.depth_scale).exp2()),
        }
    }

    /// The diffuse colour of each fragment of the group, into `scratch.colors`.
    fn base_colors(
        &self,
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
                patterns.colors(binding, at, self.time, &mut scratch.colors)
            }
            Some(Texturing::Image(image)) => {
                let surface = &object.prepared.surface;
                let mapping = mapping_on(&image.mapping, surface, image.sampler.wrap_s);
                let point = self.surface_point(fragments, group, &scratch.frames);
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

    /// The bump height and its (u,v) gradient per fragment, by the shader's gradient method,
    /// into `scratch.heights` and `scratch.gradients` (zero without a bump).
    fn bump_gradients(
        &self,
        object: &FrameObject,
        fragments: &[Fragment],
        group: &[u32],
        scratch: &mut ShadeScratch,
    ) -> usize {
        let Some(bump) = &object.prepared.material.bump else {
            scratch.heights.clear();
            scratch.gradients.clear();
            return 0;
        };
        let gives_slope = matches!(&bump.source,
            BumpSource::Pattern(b) if b.pattern.output() == OutputKind::Slope);
        let flattened = match self.gradient {
            GradientMethod::SeedLattice => {
                let shifted = &mut scratch.shifted;
                shifted_fragments(fragments, group, Vec2::floor, &mut shifted.fragments);
                let base = (&scratch.frames, fragments, group);
                let flattened = self.shifted_bump(
                    object,
                    shifted,
                    base,
                    (&mut scratch.patterns, &mut scratch.height_lookups),
                );
                std::mem::swap(&mut scratch.heights, &mut shifted.heights);
                std::mem::swap(&mut scratch.gradients, &mut shifted.gradients);
                flattened
            }
            GradientMethod::CentralDifference { step } if !gives_slope => {
                let flattened = self.bump_samples(object, fragments, group, scratch);
                self.central_gradients(object, fragments, group, step, scratch);
                flattened
            }
            _ => self.bump_samples(object, fragments, group, scratch),
        };
        let scale = bump.scale();
        for (h, g) in scratch.heights.iter_mut().zip(&mut scratch.gradients) {
            *h *= scale;
            *g *= scale;
        }
        flattened
    }

    /// Replaces `scratch.gradients` by central differences of heights a `step` away.
    fn central_gradients(
        &self,
        object: &FrameObject,
        fragments: &[Fragment],
        group: &[u32],
        step: f32,
        scratch: &mut ShadeScratch,
    ) {
        let shifts = [
            Vec2::new(step, 0.0),
            Vec2::new(-step, 0.0),
            Vec2::new(0.0, step),
            Vec2::new(0.0, -step),
        ];
        let shifted = &mut scratch.shifted;
        for (k, shift) in shifts.into_iter().enumerate() {
            shifted_fragments(fragments, group, |uv| uv + shift, &mut shifted.fragments);
            let work = (&mut scratch.patterns, &mut scratch.height_lookups);
            let base = (&scratch.frames, fragments, group);
            self.shifted_bump(object, shifted, base, work);
            std::mem::swap(&mut shifted.around[k], &mut shifted.heights);
        }
        let around = &shifted.around;
        for (k, g) in scratch.gradients.iter_mut().enumerate() {
            let heights = [around[0][k], around[1][k], around[2][k], around[3][k]];
            *g = central_difference(heights, step);
        }
    }

    /// Heights and exact gradients at `shifted.fragments` (each with its own surface frame),
    /// into `shifted.heights` and `shifted.gradients`.
    fn shifted_bump(
        &self,
        object: &FrameObject,
        shifted: &mut Shifted,
        base: (&Frames, &[Fragment], &[u32]),
        (patterns, height_lookups): (&mut PatternBatch, &mut HeightLookups),
    ) -> usize {
        let surface = &object.prepared.surface;
        let n = shifted.fragments.len();
        shifted.identity.clear();
        shifted.identity.extend(0..n as u32);
        shifted.frames.clear();
        let fragments = &shifted.fragments;
        match surface {
            // A model's (u,v) name no point: its shifted frames step along its unshifted ones.
            Surface::Model(_) => {
                let (frames, originals, group) = base;
                shifted.frames.extend((0..n).map(|k| {
                    let step = fragments[k].uv - originals[group[k] as usize].uv;
                    let frame = frames.at(k);
                    Frame {
                        p: frame.p + frame.pu * step.x + frame.pv * step.y,
                        ..frame
                    }
                }));
            }
            _ => surface.frames(n, |k| fragments[k].uv, &mut shifted.frames),
        }
        let mut output = BumpOutput {
            frames: &shifted.frames,
            patterns,
            height_lookups,
            heights: &mut shifted.heights,
            gradients: &mut shifted.gradients,
        };
        self.evaluate_bump(object, &shifted.fragments, &shifted.identity, &mut output)
    }

    /// Unscaled heights and exact gradients of the group at its own (u,v).
    fn bump_samples(
        &self,
        object: &FrameObject,
        fragments: &[Fragment],
        group: &[u32],
        scratch: &mut ShadeScratch,
    ) -> usize {
        let mut output = BumpOutput {
            frames: &scratch.frames,
            patterns: &mut scratch.patterns,
            height_lookups: &mut scratch.height_lookups,
            heights: &mut scratch.heights,
            gradients: &mut scratch.gradients,
        };
        self.evaluate_bump(object, fragments, group, &mut output)
    }

    /// The bump source's height and exact (u,v) gradient, before the bump's strength.
    fn evaluate_bump(
        &self,
        object: &FrameObject,
        fragments: &[Fragment],
        group: &[u32],
        output: &mut BumpOutput,
    ) -> usize {
        let Some(bump) = &object.prepared.material.bump else {
            reset(output.heights, group.len(), 0.0);
            reset(output.gradients, group.len(), Vec2::ZERO);
            return 0;
        };
        // Both sources write every height and gradient: resized, not cleared.
        output.heights.resize(group.len(), 0.0);
        output.gradients.resize(group.len(), Vec2::ZERO);
        match &bump.source {
            BumpSource::Pattern(binding) => {
                let at = Sites {
                    fragments,
                    group,
                    frames: output.frames,
                };
                let (heights, gradients) = (&mut *output.heights, &mut *output.gradients);
                output
                    .patterns
                    .bump(binding, at, self.time, heights, gradients)
            }
            BumpSource::Image(image) => {
                let surface = &object.prepared.surface;
                let mapping = mapping_on(&image.mapping, surface, image.wrap_s);
                let point = self.surface_point(fragments, group, output.frames);
                let lookups = &mut *output.height_lookups;
                // Every entry is written below: resized, not cleared.
                lookups.st.resize(group.len(), Vec2::ZERO);
                lookups.footprints.resize(group.len(), Footprint::POINT);
                lookups.jacobians.resize(group.len(), Mat2::ZERO);
                mapping.map_each(group.len(), point, |k, mapped| {
                    let fragment = &fragments[group[k] as usize];
                    lookups.st[k] = mapped.st;
                    lookups.footprints[k] = mapped.footprint(fragment.duv_dx, fragment.duv_dy);
                    lookups.jacobians[k] = mapped.jacobian;
                });
                lookups.samples.resize(group.len(), HeightSample::default());
                let wraps = (image.wrap_s, image.wrap_t);
                let (st, footprints) = (&lookups.st, &lookups.footprints);
                (image.map).sample_gradient_many(st, footprints, wraps, &mut lookups.samples);
                let samples = lookups.samples.iter().zip(&lookups.jacobians);
                for ((height, gradient), (sample, &jacobian)) in output
                    .heights
                    .iter_mut()
                    .zip(output.gradients.iter_mut())
                    .zip(samples)
                {
                    *height = sample.height;
                    *gradient = sample.surface_gradient(jacobian);
                }
                0
            }
            BumpSource::NormalMap(map) => {
                let point = self.surface_point(fragments, group, output.frames);
                let each = output.heights.iter_mut().zip(output.gradients.iter_mut());
                for (k, (height, gradient)) in each.enumerate() {
                    *height = 0.0;
                    *gradient = map.gradient(&point(k));
                }
                0
            }
        }
    }

    /// What a mapping sees of the k-th fragment of the group (`frames` in the group's order).
    fn surface_point<'a>(
        &self,
        fragments: &'a [Fragment],
        group: &'a [u32],
        frames: &'a Frames,
    ) -> impl Fn(usize) -> SurfacePoint + 'a {
        let time = self.time as f32;
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
}

/// Where one bump evaluation reads its frames and writes its results.
struct BumpOutput<'a> {
    frames: &'a Frames,
    patterns: &'a mut PatternBatch,
    height_lookups: &'a mut HeightLookups,
    heights: &'a mut Vec<f32>,
    gradients: &'a mut Vec<Vec2>,
}

/// Moves `group`'s fragments (chart (u,v) and derivatives) and their `frames` to the model's
/// texture (u,v), where patterns and images are read and bumps tilt.
fn to_texture_space(
    model: &ModelSurface,
    fragments: &mut [Fragment],
    group: &[u32],
    frames: &mut Frames,
) {
    for (k, &i) in group.iter().enumerate() {
        let fragment = &mut fragments[i as usize];
        let mut frame = frames.at(k);
        let texture = model.to_texture_space(fragment.uv, &mut frame);
        frames.set(k, frame);
        fragment.uv = texture.uv;
        fragment.duv_dx = texture.derivative(fragment.duv_dx);
        fragment.duv_dy = texture.derivative(fragment.duv_dy);
    }
}

/// An image's mapping in its cheapest exact form on `surface`. A spherical mapping about a
/// sphere's centre (pole +y, front +z: what scene files bind) reads back the sphere's own
/// parameters: φ = u·π/360 − π/2 and θ = v·π/360, so s = ½ + φ/2π = u/720 + ¼ and
/// t = θ/π = v/360, and the per-fragment atan2, acos, hypot and Jacobian (a third of a textured
/// sphere's instructions) become one multiply-add with a constant Jacobian (the analytic one;
/// the general form holds ∂s/∂u finite within 10⁻⁴ of the poles). s then spans [¼, 5/4): the
/// same texels under the repeat wrap spherical mappings use on s; other wraps keep the general form.
fn mapping_on<'a>(mapping: &'a Mapping, surface: &Surface, wrap_s: Wrap) -> Cow<'a, Mapping> {
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

/// What lighting one group takes: the lights, the material, the group's fragments and their
/// base colours.
struct GroupLighting<'a> {
    lights: &'a FrameLights,
    material: &'a Material,
    group: &'a [u32],
    colors: &'a [Vec3],
    reach: Reach<'a>,
}

impl GroupLighting<'_> {
    /// Lights the group in one batch into `out`, from the points and normals `surface` gives:
    /// straight into `out` when the group's fragments are consecutive (as a one-object batch's
    /// are), else through `lit` and a scatter.
    fn light<Pairs: Iterator<Item = (Vec3, Vec3)>>(
        &self,
        surface: impl Fn(Range<usize>) -> Pairs,
        lit: &mut Vec<Vec3>,
        out: &mut [Vec3],
    ) {
        let (lights, material, colors, reach) =
            (self.lights, self.material, self.colors, self.reach);
        if let Some(range) = consecutive(self.group) {
            blinn_phong_many(lights, material, colors, surface, reach, &mut out[range]);
            return;
        }
        lit.resize(self.group.len(), Vec3::ZERO);
        blinn_phong_many(lights, material, colors, surface, reach, lit);
        for (&i, &color) in self.group.iter().zip(lit.iter()) {
            out[i as usize] = color;
        }
    }
}

/// The range `group` lists, when its indices are consecutive. A group ascends without repeats
/// (`group_by_object` orders it so): then its ends alone tell.
fn consecutive(group: &[u32]) -> Option<Range<usize>> {
    debug_assert!(group.windows(2).all(|pair| pair[0] < pair[1]), "ascending");
    let (first, last) = (*group.first()? as usize, *group.last()? as usize);
    (last - first + 1 == group.len()).then_some(first..last + 1)
}

/// A premultiplied texel over the material's colour `base` (its fourth lane unused): where the
/// image is transparent the material shows through. In four lanes, the same arithmetic per
/// channel as `texel.xyz + colour * (1 - alpha)` in three.
#[inline(always)]
fn over_material(texel: Texel, base: Vec4) -> Vec3 {
    (texel + base * Vec4::splat(1.0 - texel.w)).truncate()
}

/// `origin + p` for every point `p`, appended to `points`.
fn origin_plus(origin: Vec3, p: &Vectors, points: &mut Vec<Vec3>) {
    let [x, y, z] = p.coordinates();
    let each = x.iter().zip(y).zip(z);
    points.extend(each.map(|((&x, &y), &z)| origin + Vec3::new(x, y, z)));
}

fn reset<T: Copy>(values: &mut Vec<T>, len: usize, value: T) {
    values.clear();
    values.resize(len, value);
}

/// Swaps the exact position and normal of each frame for the tessellation's interpolated ones
/// (the tangents stay exact: they orient the bump, which the mesh does not carry).
fn interpolate_frames(
    normals: &VertexNormals,
    fragments: &[Fragment],
    group: &[u32],
    frames: &mut Frames,
) {
    for (k, &i) in group.iter().enumerate() {
        if let Some(at) = normals.at(fragments[i as usize].uv) {
            frames.p.set(k, at.p);
            frames.n.set(k, at.n);
        }
    }
}

/// Counting sort of fragment indices by object: `order[starts[o]..starts[o + 1]]` are object o's.
fn group_by_object(
    fragments: &[Fragment],
    objects: usize,
    order: &mut Vec<u32>,
    starts: &mut Vec<usize>,
) {
    starts.clear();
    order.clear();
    if let Some(object) = single_object(fragments) {
        // Most batches (a tile's visible pixels) see one object: already in order. Counting
        // them one by one would be a chain of increments of one memory slot.
        let object = object as usize;
        starts.extend((0..=objects).map(|o| if o <= object { 0 } else { fragments.len() }));
        order.extend(0..fragments.len() as u32);
        return;
    }
    starts.resize(objects + 1, 0);
    for f in fragments {
        starts[f.object as usize + 1] += 1;
    }
    for o in 0..objects {
        starts[o + 1] += starts[o];
    }
    let mut next = starts.clone();
    order.resize(fragments.len(), 0);
    for (i, f) in fragments.iter().enumerate() {
        let slot = &mut next[f.object as usize];
        order[*slot] = i as u32;
        *slot += 1;
    }
}

/// The object of every fragment, when they all share one.
fn single_object(fragments: &[Fragment]) -> Option<u32> {
    let object = fragments.first()?.object;
    fragments
        .iter()
        .all(|f| f.object == object)
        .then_some(object)
}

/// Renders a lit frame, shaded as the scene asks, on the current rayon pool.
pub fn render_lit(prepared: &PreparedScene, target: &RenderTarget) -> (Framebuffer, FrameStats) {
    let shader = LitShader::new(&prepared.scene, target.camera);
    let mut framebuffer = Framebuffer::new(0, 0, Vec3::ZERO);
    let stats = crate::raster::render_pass(prepared, target, &shader, &mut framebuffer);
    (framebuffer, stats)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::raster::{PreparedScene, RenderTarget, Viewport, frame_objects, render_pass};

    /// A frame rendered into a new framebuffer.
    fn render_with(
        prepared: &PreparedScene,
        target: &RenderTarget,
        shader: &impl FragmentShader,
    ) -> (Framebuffer, FrameStats) {
        let mut framebuffer = Framebuffer::new(0, 0, Vec3::ZERO);
        let stats = render_pass(prepared, target, shader, &mut framebuffer);
        (framebuffer, stats)
    }
    use crate::scene::{ImageTexture, preset};
    use crate::surface::Tessellation;
    use crate::texture::{Filter, Sampler, TexelGrid, Texture};

    /// Over the material: opaque texels as they are, transparent ones the material, and every
    /// texel the same bits as the three-lane formula.
    #[test]
    fn texels_lie_over_the_material() {
        let colour = Vec3::new(0.2, 0.5, 0.9);
        let base = colour.extend(0.0);
        let texel = |k: u32| {
            let alpha = (k % 5) as f32 / 4.0;
            Vec4::new(
                0.31 * alpha,
                (k as f32 * 0.137).fract() * alpha,
                0.05,
                alpha,
            )
        };
        for k in 0..200 {
            let t = texel(k);
            let three = t.truncate() + colour * (1.0 - t.w);
            let four = over_material(t, base);
            assert_eq!(
                four.to_array().map(f32::to_bits),
                three.to_array().map(f32::to_bits)
            );
        }
        assert_eq!(over_material(Vec4::new(0.0, 0.0, 0.0, 0.0), base), colour);
        let opaque = Vec4::new(0.7, 0.1, 0.3, 1.0);
        assert_eq!(over_material(opaque, base), opaque.truncate());
    }

    /// `LitShader` with every fragment's derivatives computed (the trait's default).
    struct AllDerivatives<'a>(&'a LitShader);

    impl FragmentShader for AllDerivatives<'_> {
        type Scratch = ShadeScratch;

        fn scratch(&self) -> ShadeScratch {
            self.0.scratch()
        }

        fn shade(
            &self,
            objects: &[FrameObject],
            rays: &SampleRays,
            fragments: &mut [Fragment],
            scratch: &mut ShadeScratch,
            out: &mut [Vec3],
        ) -> usize {
            self.0.shade(objects, rays, fragments, scratch, out)
        }
    }

    /// A 64×64 checkerboard of 4-texel squares: its mip levels differ, so a footprint changes
    /// what a trilinear filter reads.
    fn checkerboard(filter: Filter) -> Texturing {
        let texels = TexelGrid::from_fn(64, 64, |x, y| {
            let bright = (x / 4 + y / 4) % 2 == 0;
            Texel::new(0.9, 0.2, 0.1, 1.0) * if bright { 1.0 } else { 0.2 }
        });
        Texturing::Image(ImageTexture {
            name: "checkerboard".into(),
            texture: Arc::new(Texture::from_raster(texels)),
            mapping: Mapping::SurfaceUv(SurfaceUv {
                scale: Vec2::splat(1.0 / 45.0),
                offset: Vec2::ZERO,
            }),
            sampler: Sampler {
                filter,
                wrap_s: Wrap::Repeat,
                wrap_t: Wrap::Repeat,
            },
            chosen_live: false,
        })
    }

    #[test]
    fn a_group_is_consecutive_when_its_ends_span_it() {
        assert_eq!(consecutive(&[3, 4, 5]), Some(3..6));
        assert_eq!(consecutive(&[7]), Some(7..8));
        assert_eq!(consecutive(&[3, 5, 6]), None);
        assert_eq!(consecutive(&[0, 1, 3]), None);
        assert_eq!(consecutive(&[]), None);
    }

    /// The shader skips derivatives only where nothing it reads needs them, object by object:
    /// frames rendered without them are the bits of frames rendered with them, and an object
    /// wearing a trilinear image (which would change without them) asks for them, alone in a
    /// scene of pattern-textured ones too.
    #[test]
    fn derivatives_are_skipped_only_where_unread() {
        // The preset, which object wears a checkerboard image through which filter, and
        // which objects read derivatives.
        type Case = (&'static str, Option<(usize, Filter)>, &'static [bool]);
        let cases: [Case; 5] = [
            ("sphere-on-plane-dimples", None, &[false, false]),
            (
                "sphere-on-plane-dimples",
                Some((1, Filter::Trilinear)),
                &[false, true],
            ),
            ("big-sphere-squares", Some((0, Filter::Bilinear)), &[false]),
            ("big-sphere-squares", Some((0, Filter::Nearest)), &[false]),
            ("big-sphere-squares", Some((0, Filter::Trilinear)), &[true]),
        ];
        for (name, image, reads) in cases {
            let mut scene = preset(name).expect("a built-in scene");
            let filter = image.map(|(object, filter)| {
                scene.objects[object].material.texture = Some(checkerboard(filter));
                filter
            });
            let camera = scene.camera.clone();
            let prepared = PreparedScene::new(scene, Tessellation { density: 24 });
            let target = RenderTarget::new(
                &camera,
                Viewport {
                    width: 96,
                    height: 64,
                },
            );
            let shader = LitShader::new(&prepared.scene, &camera);
            let objects = frame_objects(&prepared, &camera);
            let read: Vec<bool> = objects
                .iter()
                .map(|o| shader.reads_derivatives(o))
                .collect();
            assert_eq!(read, reads, "{name} {filter:?}");
            let (skipped, _) = render_with(&prepared, &target, &shader);
            let (computed, _) = render_with(&prepared, &target, &AllDerivatives(&shader));
            let bits = |f: &crate::raster::Framebuffer| -> Vec<[u32; 3]> {
                f.color()
                    .iter()
                    .map(|c| c.to_array().map(f32::to_bits))
                    .collect()
            };
            assert!(bits(&skipped) == bits(&computed), "{name} {filter:?}");
        }
    }

    fn fragments_of(objects: &[u32]) -> Vec<Fragment> {
        objects
            .iter()
            .map(|&object| Fragment {
                object,
                ..Fragment::default()
            })
            .collect()
    }

    /// `order` must list every fragment once, object by object as `starts` says, each object's
    /// fragments in their original order.
    fn assert_grouped(objects: &[u32], count: usize) {
        let fragments = fragments_of(objects);
        let (mut order, mut starts) = (vec![7; 3], vec![9]);
        group_by_object(&fragments, count, &mut order, &mut starts);
        assert_eq!(starts.len(), count + 1);
        assert_eq!((starts[0], starts[count]), (0, objects.len()));
        for o in 0..count {
            let group = &order[starts[o]..starts[o + 1]];
            let expected: Vec<u32> = (0..objects.len() as u32)
                .filter(|&i| objects[i as usize] == o as u32)
                .collect();
            assert_eq!(group, expected, "object {o} of {objects:?}");
        }
    }

    #[test]
    fn fragments_are_grouped_by_object_in_order() {
        assert_grouped(&[], 2);
        assert_grouped(&[0, 0, 0], 1);
        assert_grouped(&[1, 1, 1, 1], 3);
        assert_grouped(&[1, 0, 2, 0, 1, 1], 3);
        assert_grouped(&[2, 2, 0], 4);
    }
}
