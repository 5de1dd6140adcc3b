//! bumpwork against euc (crates.io), a Rust software rasterizer, on the same frame: a lit,
//! textured 128×64 sphere 540 pixels high at 1920×1080, the chelsea photograph sampled bilinearly
//! (both through bumpwork's sampler, so the rasterizers and pipelines are what differ) and
//! per-pixel Blinn-Phong with one point light. euc is single-threaded; bumpwork is measured on one
//! thread and on all. The three take turns, round by round; each ratio is the median of the
//! rounds' ratios, with the least and greatest.
//!
//! Run: `cargo bench --bench peer_euc`.

mod bench_support;

use bench_support::{bilinear, textured_sphere_scene};
use bumpwork::measure::{Timing, ratio_by_round};
use bumpwork::raster::{Framebuffer, RenderTarget, Viewport, linear_to_srgb8};
use bumpwork::render::render_scene_pass;
use bumpwork::scene::Light;
use bumpwork::scene::PreparedScene;
use bumpwork::shade::LitShader;
use bumpwork::surface::{Mesh, Tessellation};
use bumpwork::texture::{Footprint, Texture};
use euc::buffer::Buffer2d;
use euc::rasterizer::{BackfaceCullingDisabled, Triangles};
use euc::{DepthStrategy, Pipeline};
use glam::{Mat4, Vec2, Vec3};

const WIDTH: usize = 1920;
const HEIGHT: usize = 1080;

fn runs() -> usize {
    bench_support::runs_or(15)
}

/// The textured sphere as euc sees it: indexed vertices, per-pixel lighting.
struct EucSphere<'a> {
    view_projection: Mat4,
    mesh: &'a Mesh,
    /// The eye relative to the sphere's centre.
    eye: Vec3,
    light: Vec3,
    texture: &'a Texture,
    ambient: Vec3,
    specular: f32,
    shininess: f32,
}

impl Pipeline for EucSphere<'_> {
    type Vertex = u32;
    /// Normal, position, (s,t).
    type VsOut = (vek::Vec3<f32>, vek::Vec3<f32>, vek::Vec2<f32>);
    type Pixel = u32;

    fn vert(&self, index: &u32) -> ([f32; 4], Self::VsOut) {
        let p = self.mesh.positions[*index as usize];
        let uv = self.mesh.uvs[*index as usize];
        let clip = self.view_projection * (p - self.eye).extend(1.0);
        let st = vek::Vec2::new(uv.x / 720.0, uv.y / 360.0);
        (
            clip.to_array(),
            (
                vek::Vec3::from(p.to_array()),
                vek::Vec3::from(p.to_array()),
                st,
            ),
        )
    }

    fn get_depth_strategy(&self) -> DepthStrategy {
        DepthStrategy::IfLessWrite
    }

    fn frag(&self, (normal, position, st): &Self::VsOut) -> u32 {
        let n = Vec3::from_array(normal.into_array()).normalize_or_zero();
        let p = Vec3::from_array(position.into_array());
        let texel = self
            .texture
            .sample(&bilinear(), Vec2::new(st.x, st.y), Footprint::POINT);
        let albedo = texel.truncate();
        let to_light = (self.light - p).normalize_or_zero();
        let to_eye = (self.eye - p).normalize_or_zero();
        let half = (to_light + to_eye).normalize_or_zero();
        let diffuse = n.dot(to_light).max(0.0);
        let specular = n.dot(half).max(0.0).powf(self.shininess) * self.specular;
        let c = albedo * (self.ambient + Vec3::splat(diffuse)) + Vec3::splat(specular);
        let [r, g, b] = c.to_array().map(linear_to_srgb8);
        u32::from_be_bytes([255, r, g, b])
    }
}

fn main() {
    let (scene, texture) = textured_sphere_scene();
    let camera = scene.camera.clone();
    let Light::Point { position, .. } = scene.lights[0] else {
        unreachable!("the bench sphere has a point light")
    };
    let material = scene.objects[0].material.clone();
    let ambient = scene.ambient;
    let prepared = PreparedScene::new(scene, Tessellation { density: 64 });
    let viewport = Viewport {
        width: WIDTH as u32,
        height: HEIGHT as u32,
    };
    let target = RenderTarget::new(&camera, viewport);
    let shader = LitShader::new(&prepared.scene, &camera);

    let mesh = &prepared.objects[0].mesh;
    let indices: Vec<u32> = mesh.indices.iter().flatten().copied().collect();
    let euc_sphere = EucSphere {
        view_projection: camera.view_projection(viewport.aspect()),
        mesh,
        eye: camera.eye.as_vec3(),
        light: position.as_vec3(),
        texture: &texture,
        ambient,
        specular: material.specular,
        shininess: material.shininess,
    };
    let mut color = Buffer2d::new([WIDTH, HEIGHT], 0u32);
    let mut depth = Buffer2d::new([WIDTH, HEIGHT], 1.0f32);
    let mut euc_frame = || {
        euc::Target::clear(&mut color, 0);
        euc::Target::clear(&mut depth, 1.0);
        euc_sphere.draw::<Triangles<'_, Buffer2d<f32>, BackfaceCullingDisabled>, _>(
            &indices,
            &mut color,
            Some(&mut depth),
        );
    };
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let pool = |threads: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("thread pool")
    };
    let (one_thread, all_threads) = (pool(1), pool(cores));
    let fragments = std::cell::Cell::new(0);
    let ours_on = |pool: &rayon::ThreadPool, framebuffer: &mut Framebuffer| {
        let stats = pool.install(|| render_scene_pass(&prepared, &target, &shader, framebuffer));
        fragments.set(stats.fragments);
    };
    // A framebuffer each, for the two turns to borrow apart.
    let empty = || Framebuffer::new(0, 0, Vec3::ZERO);
    let (mut framebuffer_one, mut framebuffer_all) = (empty(), empty());
    let (mut ours_one, mut ours_all) = (
        || ours_on(&one_thread, &mut framebuffer_one),
        || ours_on(&all_threads, &mut framebuffer_all),
    );
    // Round by round, so the machine's drift slows all three alike. Each measured frame follows
    // unmeasured ones of its own: a frame of a few milliseconds right after euc's runs slowly
    // (caches, the idle second core), and four settle it where one does not.
    let times = Timing::interleaved(
        2,
        runs(),
        &mut [(1, &mut euc_frame), (4, &mut ours_one), (4, &mut ours_all)],
    );
    let euc_pixels = color.as_ref().iter().filter(|&&c| c != 0).count();
    println!(
        "textured lit 128x64 sphere at {WIDTH}x{HEIGHT}, bilinear, {} rounds",
        runs()
    );
    println!(
        "  euc 0.5 (1 thread):      {}  ({euc_pixels} pixels drawn)",
        Timing::from_samples(times[0].clone()).summary_ms()
    );
    for (threads, ours) in [(1, &times[1]), (cores, &times[2])] {
        let (ratio, least, most) = ratio_by_round(&times[0], ours);
        println!(
            "  bumpwork ({threads} thread{}):  {}  ({} pixels shaded) — {ratio:.2}x euc's speed (rounds {least:.2}–{most:.2}x)",
            if threads == 1 { "" } else { "s" },
            Timing::from_samples(ours.clone()).summary_ms(),
            fragments.get()
        );
    }
}
