//! The scene's fragment program: per batch of fragments, grouped by object, the exact surface
//! frame, the texture or material colour, the bumped normal, then lighting (or a view mode).
//! Work the scene does not need is skipped: no texture, no sampling; no bump, no perturbation.

use super::bump::NormalForm;
use super::bump_stage::BumpStage;
use super::colour_stage::base_colors;
use super::exact_coverage::Neighbours;
use super::exact_point::{SurfacePointSource, exact_fragments, true_hit_derivatives};
use super::frame_object::FrameObject;
use super::gradient::GradientMethod;
use super::light_stage::LightStage;
use super::lighting::{FrameLights, Reach, facing_sign};
use super::shade_scratch::ShadeScratch;
use super::shader_mode::ShaderMode;
use super::shadowing::Shadowing;
use super::vertex_normals::VertexNormals;
use crate::pattern::Precision;
use crate::raster::{Fragment, FragmentShader, SampleRays};
use crate::scene::Camera;
use crate::scene::{BumpSource, Scene, Texturing};
use crate::surface::{Frames, ModelSurface, Surface, Vectors};
use glam::Vec3;
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

impl FragmentShader for LitShader {
    type Object<'o> = FrameObject<'o>;
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
        self.surface_frames(batch, rays, fragments, scratch);
        let fragments = &*fragments;
        let mut flattened = base_colors(self.time, object, fragments, group, scratch);
        flattened += self
            .bump_stage()
            .gradients(object, fragments, group, scratch);
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
        let light = self.light_stage();
        let terminator_in_lighting = unbumped && self.terminators && !light.any_light_casts();
        if self.mode == ShaderMode::Shaded && !terminator_in_lighting {
            light.reach(object_index, constant_normal, scratch);
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
            light.group(material, group, &scratch.colors, reach).light(
                surface,
                &mut scratch.lit,
                out,
            );
            return flattened;
        }
        light.normals(object, fragments, group, constant_normal, scratch);
        if self.mode == ShaderMode::Shaded {
            let (points, normals) = (&scratch.points, &scratch.normals);
            let surface = |range: Range<usize>| {
                let points = points[range.clone()].iter().copied();
                points.zip(normals[range].iter().copied())
            };
            let reach = Reach::Rows(&scratch.reach);
            light.group(material, group, &scratch.colors, reach).light(
                surface,
                &mut scratch.lit,
                out,
            );
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

    /// The group's surface frames, into `scratch.frames`: exact, or with the tessellation's
    /// interpolated position and normal; a model's in its texture's (u,v), its fragments moved
    /// there too.
    fn surface_frames(
        &self,
        batch: ObjectBatch,
        rays: &SampleRays,
        fragments: &mut [Fragment],
        scratch: &mut ShadeScratch,
    ) {
        let (object, group) = (batch.object, batch.group);
        let surface = &object.prepared.surface;
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
        // A model's frames are interpolated from its vertices already (and its fragments'
        // (u,v) are the texture's by now, which name no triangle).
        let from_vertices = self.vertex_normals.as_ref();
        if let Some(normals) = from_vertices.filter(|_| !matches!(surface, Surface::Model(_))) {
            let normals = &normals[batch.index];
            interpolate_frames(normals, fragments, group, &mut scratch.frames);
        }
    }

    fn bump_stage(&self) -> BumpStage {
        BumpStage {
            time: self.time,
            gradient: self.gradient,
        }
    }

    fn light_stage(&self) -> LightStage<'_> {
        LightStage {
            lights: &self.lights,
            shadows: self.shadows.as_deref(),
            terminators: self.terminators,
            normal_form: self.normal_form,
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

/// `origin + p` for every point `p`, appended to `points`.
fn origin_plus(origin: Vec3, p: &Vectors, points: &mut Vec<Vec3>) {
    let [x, y, z] = p.coordinates();
    let each = x.iter().zip(y).zip(z);
    points.extend(each.map(|((&x, &y), &z)| origin + Vec3::new(x, y, z)));
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::raster::{RenderTarget, Viewport};
    use crate::render::render_with;
    use crate::scene::PreparedScene;
    use crate::shade::colour_stage::over_material;
    use crate::shade::frame_objects;
    use crate::texture::{Mapping, SurfaceUv, Texel, Wrap};
    use glam::{Vec2, Vec4};

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
        type Object<'o> = FrameObject<'o>;
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
