//! The reference renderer: one exact ray per pixel through the same shader as the rasterizer.

use crate::raster::{Fragment, Framebuffer, SampleRays, ViewRays, Viewport};
use crate::render::SceneShader;
use crate::scene::Camera;
use crate::scene::PreparedScene;
use crate::shade::{FrameObject, frame_objects, nearest_true_hit};
use crate::surface::{Hit, uv_derivatives};
use glam::{DVec2, DVec3, Vec3};
use rayon::prelude::*;

/// What a reference frame cost.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ReferenceStats {
    /// Pixels whose ray hit a surface (each shaded once).
    pub fragments: usize,
    /// Fragments drawn flat because a pattern gave no finite value there.
    pub flattened: usize,
}

/// Ray casts a frame of the prepared scene (its tessellation is not used) and shades it with
/// `shader`, into a new framebuffer.
pub fn render_reference(
    prepared: &PreparedScene,
    camera: &Camera,
    viewport: Viewport,
    shader: &impl SceneShader,
) -> (Framebuffer, ReferenceStats) {
    let mut framebuffer = Framebuffer::new(0, 0, Vec3::ZERO);
    let stats = render_reference_into(prepared, camera, viewport, shader, &mut framebuffer);
    (framebuffer, stats)
}

/// Ray casts a frame into `framebuffer`, one row per batch of fragments: every pixel is written,
/// shaded where a ray hits and background (at infinite depth) elsewhere, as the rasterizer does.
pub fn render_reference_into(
    prepared: &PreparedScene,
    camera: &Camera,
    viewport: Viewport,
    shader: &impl SceneShader,
    framebuffer: &mut Framebuffer,
) -> ReferenceStats {
    let rays = ViewRays::new(camera, viewport);
    render_rays_into(prepared, camera, viewport, rays, shader, framebuffer)
}

/// Ray casts a frame through `rays` (pixel centres, or one sample position of each pixel).
pub fn render_rays_into(
    prepared: &PreparedScene,
    camera: &Camera,
    viewport: Viewport,
    rays: ViewRays,
    shader: &impl SceneShader,
    framebuffer: &mut Framebuffer,
) -> ReferenceStats {
    framebuffer.resize(viewport.width, viewport.height);
    if viewport.width == 0 || viewport.height == 0 {
        return ReferenceStats::default();
    }
    let objects = frame_objects(prepared, camera);
    let footprint = rays.footprint as f32;
    let sample_rays = SampleRays::new(&rays, camera, (0, 0), DVec2::ZERO, footprint);
    let background = prepared.scene.background;
    let width = viewport.width as usize;
    let (color, depth) = framebuffer.parts_mut();
    let (fragments, flattened) = color
        .par_chunks_mut(width)
        .zip(depth.par_chunks_mut(width))
        .enumerate()
        .map_init(
            || (shader.scratch(), Vec::new(), Vec::new()),
            |(scratch, row_fragments, colors), (y, (color, depth))| {
                color.fill(background);
                depth.fill(f32::INFINITY);
                row_fragments.clear();
                row_fragments.extend(
                    (0..viewport.width)
                        .filter_map(|x| cast_pixel(&objects, camera, &rays, x, y as u32)),
                );
                colors.clear();
                colors.resize(row_fragments.len(), Vec3::ZERO);
                let flattened =
                    shader.shade(&objects, &sample_rays, row_fragments, scratch, colors);
                for (fragment, &c) in row_fragments.iter().zip(colors.iter()) {
                    color[fragment.x as usize] = c;
                    depth[fragment.x as usize] = fragment.depth;
                }
                (row_fragments.len(), flattened)
            },
        )
        .reduce(|| (0, 0), |a, b| (a.0 + b.0, a.1 + b.1));
    ReferenceStats {
        fragments,
        flattened,
    }
}

/// The fragment the exact scene shows at pixel (x, y): the nearest hit with view depth in
/// [near, far] over all objects (the first object wins an exact tie, as in the rasterizer), with
/// back faces of a sphere seen from outside culled, as the rasterizer culls them.
pub fn cast_pixel(
    objects: &[FrameObject],
    camera: &Camera,
    rays: &ViewRays,
    x: u32,
    y: u32,
) -> Option<Fragment> {
    let direction = rays.through_pixel(x, y);
    let range = camera.near as f64..=camera.far as f64;
    let eye = |object: &FrameObject| object.eye;
    let nearest = nearest_true_hit(objects, eye, direction, range);
    let (index, hit) = nearest?;
    Some(fragment_at(objects, rays, index, hit, direction, x, y))
}

fn fragment_at(
    objects: &[FrameObject],
    rays: &ViewRays,
    index: usize,
    hit: Hit,
    direction: DVec3,
    x: u32,
    y: u32,
) -> Fragment {
    let surface = &objects[index].prepared.surface;
    let frame = surface.frame(hit.uv.x, hit.uv.y);
    let domain = surface.domain();
    let step = |per_pixel: DVec3| (per_pixel * rays.footprint).as_vec3();
    let (t, direction) = (hit.t as f32, direction.as_vec3());
    Fragment {
        object: index as u32,
        uv: hit.uv,
        duv_dx: uv_derivatives(&frame, t, direction, step(rays.per_pixel_x), domain),
        duv_dy: uv_derivatives(&frame, t, direction, step(rays.per_pixel_y), domain),
        depth: hit.t as f32,
        x,
        y,
    }
}
