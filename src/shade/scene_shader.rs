//! The scene's fragment program: per batch of fragments, grouped by object, the exact surface
//! frame, the texture or material colour, the bumped normal, then lighting (or a view mode).
//! Work the scene does not need is skipped: no texture, no sampling; no bump, no perturbation.

use super::bump::{NormalForm, bumped_normal};
use super::lighting::{FrameLights, blinn_phong, facing_sign};
use super::pattern_batch::PatternBatch;
use super::view_mode::ViewMode;
use crate::raster::{Camera, Fragment, FragmentShader, FrameObject};
use crate::scene::{BumpSource, Scene, Texturing};
use crate::surface::Frame;
use crate::texture::{SurfacePoint, TextureMapping};
use glam::{Vec2, Vec3};

/// The default program for a scene: Blinn-Phong with textures and bump maps.
pub struct LitShader {
    pub lights: FrameLights,
    /// Seconds, for animated patterns and scrolling images.
    pub time: f64,
    pub mode: ViewMode,
    pub normal_form: NormalForm,
    /// Depth that the depth view shows as mid-grey.
    pub depth_scale: f32,
}

impl LitShader {
    pub fn new(scene: &Scene, camera: &Camera) -> LitShader {
        LitShader {
            lights: FrameLights::new(scene.ambient, &scene.lights, camera.eye),
            time: 0.0,
            mode: ViewMode::Shaded,
            normal_form: NormalForm::Blinn,
            depth_scale: (camera.target - camera.eye).length() as f32,
        }
    }
}

/// Per-thread working memory, reused for every batch.
#[derive(Default)]
pub struct ShadeScratch {
    /// Fragment indices grouped by object.
    order: Vec<u32>,
    group_starts: Vec<usize>,
    frames: Vec<Frame>,
    colors: Vec<Vec3>,
    heights: Vec<f32>,
    gradients: Vec<Vec2>,
    patterns: PatternBatch,
}

impl FragmentShader for LitShader {
    type Scratch = ShadeScratch;

    fn scratch(&self) -> ShadeScratch {
        ShadeScratch::default()
    }

    fn shade(
        &self,
        objects: &[FrameObject],
        fragments: &[Fragment],
        scratch: &mut ShadeScratch,
        out: &mut [Vec3],
    ) -> usize {
        let mut order = std::mem::take(&mut scratch.order);
        group_by_object(
            fragments,
            objects.len(),
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
                flattened += self.shade_object(object, fragments, &order[start..end], scratch, out);
            }
        }
        scratch.order = order;
        flattened
    }
}

impl LitShader {
    fn shade_object(
        &self,
        object: &FrameObject,
        fragments: &[Fragment],
        group: &[u32],
        scratch: &mut ShadeScratch,
        out: &mut [Vec3],
    ) -> usize {
        let surface = &object.prepared.surface;
        let material = &object.prepared.material;
        scratch.frames.clear();
        scratch.frames.extend(group.iter().map(|&i| {
            let uv = fragments[i as usize].uv;
            surface.frame(uv.x, uv.y)
        }));
        let mut flattened = self.base_colors(object, fragments, group, scratch);
        flattened += self.bump_gradients(object, fragments, group, scratch);
        for (k, &i) in group.iter().enumerate() {
            let fragment = &fragments[i as usize];
            let frame = &scratch.frames[k];
            let p = object.origin + frame.p;
            let (b, gradient) = (scratch.heights[k], scratch.gradients[k]);
            let n = if material.bump.is_some() {
                bumped_normal(
                    surface,
                    fragment.uv,
                    frame,
                    b,
                    gradient.x,
                    gradient.y,
                    self.normal_form,
                )
            } else {
                frame.n
            };
            let n = n * facing_sign(p, frame.n);
            out[i as usize] = match self.mode {
                ViewMode::Shaded => blinn_phong(&self.lights, material, scratch.colors[k], p, n),
                ViewMode::Height => Vec3::splat(0.5 + 0.5 * (b * 0.2).tanh()),
                ViewMode::Normals => n * 0.5 + Vec3::splat(0.5),
                ViewMode::Uv => (fragment.uv / 30.0).fract_gl().extend(0.0),
                ViewMode::Depth => Vec3::splat((-fragment.depth / self.depth_scale).exp2()),
            };
        }
        flattened
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
        scratch.colors.resize(group.len(), material.color);
        match &material.texture {
            None => 0,
            Some(Texturing::Pattern(binding)) => {
                let patterns = &mut scratch.patterns;
                patterns.load(binding, fragments, group, &scratch.frames);
                patterns.colors(binding, self.time, &mut scratch.colors)
            }
            Some(Texturing::Image(image)) => {
                for (k, &i) in group.iter().enumerate() {
                    let fragment = &fragments[i as usize];
                    let mapped = image
                        .mapping
                        .map(&self.surface_point(&scratch.frames[k], fragment));
                    let footprint = mapped.footprint(fragment.duv_dx, fragment.duv_dy);
                    let texel = image.texture.sample(&image.sampler, mapped.st, footprint);
                    // Premultiplied: where the image is transparent the material shows through.
                    scratch.colors[k] = texel.truncate() + material.color * (1.0 - texel.w);
                }
                0
            }
        }
    }

    /// The bump height and its (u,v) gradient per fragment, into `scratch.heights` and
    /// `scratch.gradients` (zero without a bump).
    fn bump_gradients(
        &self,
        object: &FrameObject,
        fragments: &[Fragment],
        group: &[u32],
        scratch: &mut ShadeScratch,
    ) -> usize {
        scratch.heights.clear();
        scratch.heights.resize(group.len(), 0.0);
        scratch.gradients.clear();
        scratch.gradients.resize(group.len(), Vec2::ZERO);
        let Some(bump) = &object.prepared.material.bump else {
            return 0;
        };
        let scale = bump.scale();
        let flattened = match &bump.source {
            BumpSource::Pattern(binding) => {
                let patterns = &mut scratch.patterns;
                patterns.load(binding, fragments, group, &scratch.frames);
                patterns.bump(
                    binding,
                    self.time,
                    &mut scratch.heights,
                    &mut scratch.gradients,
                )
            }
            BumpSource::Image(image) => {
                for (k, &i) in group.iter().enumerate() {
                    let fragment = &fragments[i as usize];
                    let mapped = image
                        .mapping
                        .map(&self.surface_point(&scratch.frames[k], fragment));
                    let footprint = mapped.footprint(fragment.duv_dx, fragment.duv_dy);
                    let sample =
                        image
                            .map
                            .sample_gradient(mapped.st, image.wrap_s, image.wrap_t, footprint);
                    scratch.heights[k] = sample.height;
                    scratch.gradients[k] = sample.surface_gradient(mapped.jacobian);
                }
                0
            }
        };
        for (h, g) in scratch.heights.iter_mut().zip(&mut scratch.gradients) {
            *h *= scale;
            *g *= scale;
        }
        flattened
    }

    fn surface_point(&self, frame: &Frame, fragment: &Fragment) -> SurfacePoint {
        SurfacePoint {
            p: frame.p,
            pu: frame.pu,
            pv: frame.pv,
            uv: fragment.uv,
            time: self.time as f32,
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
    starts.resize(objects + 1, 0);
    for f in fragments {
        starts[f.object as usize + 1] += 1;
    }
    for o in 0..objects {
        starts[o + 1] += starts[o];
    }
    let mut next = starts.clone();
    order.clear();
    order.resize(fragments.len(), 0);
    for (i, f) in fragments.iter().enumerate() {
        let slot = &mut next[f.object as usize];
        order[*slot] = i as u32;
        *slot += 1;
    }
}
