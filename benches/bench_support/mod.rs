//! Scenes shared by the benchmarks.
#![allow(dead_code)]

use bumpwork::export::{PreparedStill, StillFormat, StillPlace};
use bumpwork::measure::Timing;
use bumpwork::quality::Quality;
use bumpwork::scene::Camera;
use bumpwork::scene::{
    BindingFile, ImageTexture, Light, MappingKind, Material, Object, Scene, Texturing,
    load_scene_file, preset_file,
};
use bumpwork::shade::ShaderMode;
use bumpwork::still::{ResolveFilter, StillSettings};
use bumpwork::surface::{Sphere, Surface};
use bumpwork::texture::{Filter, ImageCache, Mapping, Sampler, Spherical, Texture, Wrap};
use glam::{DVec3, Vec3};
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// The rounds a benchmark runs: `BUMPWORK_BENCH_RUNS` if set, else `default`.
pub fn runs_or(default: usize) -> usize {
    std::env::var("BUMPWORK_BENCH_RUNS")
        .ok()
        .and_then(|r| r.parse().ok())
        .unwrap_or(default)
}

/// A lit unit sphere filling 540 of 1080 pixels, in the middle of the frame.
pub fn sphere_scene() -> Scene {
    // r / d = sin(atan(0.5·tan 20°)) puts the 1-unit sphere 540 of 1080 pixels high at fov 40°.
    let half_angle = (0.5 * 20f64.to_radians().tan()).atan();
    let distance = 1.0 / half_angle.sin();
    Scene {
        name: "bench-sphere".into(),
        camera: Camera {
            eye: DVec3::new(0.0, 0.0, distance),
            target: DVec3::ZERO,
            up: Vec3::Y,
            vfov_degrees: 40.0,
            near: 0.1,
            far: 100.0,
        },
        background: Vec3::ZERO,
        ambient: Vec3::splat(0.05),
        lights: vec![Light::Point {
            position: DVec3::new(-4.0, 4.0, 6.0),
            color: Vec3::ONE,
        }],
        time: 0.0,
        quality: Vec::new(),
        shadows: true,
        objects: vec![Object {
            surface: Surface::Sphere(Sphere {
                center: DVec3::ZERO,
                radius: 1.0,
            }),
            material: Material {
                color: Vec3::new(0.8, 0.5, 0.3),
                specular: 0.4,
                shininess: 32.0,
                ..Material::default()
            },
            displace: false,
        }],
    }
}

/// Bilinear filtering, repeating around the sphere and clamped at the poles.
pub fn bilinear() -> Sampler {
    Sampler {
        filter: Filter::Bilinear,
        wrap_s: Wrap::Repeat,
        wrap_t: Wrap::Clamp,
    }
}

/// The euc peer's frame: the bench sphere wearing the chelsea photograph (spherical mapping,
/// bilinear). Returns the scene and the texture it samples.
pub fn textured_sphere_scene() -> (Scene, Arc<Texture>) {
    let texture = ImageCache::new(u64::MAX)
        .texture("chelsea", Path::new("."))
        .expect("chelsea");
    let mut scene = sphere_scene();
    scene.objects[0].material.texture = Some(Texturing::Image(ImageTexture {
        name: "chelsea".into(),
        texture: Arc::clone(&texture),
        mapping: Mapping::Spherical(Spherical::new(Vec3::ZERO)),
        sampler: bilinear(),
        chosen_live: false,
    }));
    (scene, texture)
}

fn pattern(name: &str) -> Option<BindingFile> {
    Some(BindingFile {
        pattern: Some(name.into()),
        ..BindingFile::default()
    })
}

fn image(name: &str) -> Option<BindingFile> {
    Some(BindingFile {
        image: Some(name.into()),
        mapping: Some(MappingKind::Spherical),
        ..BindingFile::default()
    })
}

/// The POV-Ray peer's scene as a file in `dir`: sphere-on-plane-dimples with checks and
/// (height) dimples on the plane, chelsea and the gravel height map on the sphere.
pub fn write_pov_peer_scene(dir: &Path) -> PathBuf {
    let mut file = preset_file("sphere-on-plane-dimples").expect("preset");
    file.objects[0].texture = pattern("checks");
    file.objects[0].bump = pattern("dimples");
    file.objects[1].texture = image("chelsea");
    file.objects[1].bump = image("gravel");
    let path = dir.join("peer.toml");
    std::fs::write(&path, file.to_toml()).expect("scene file");
    path
}

/// The POV-Ray peer's scene written into `dir`, read back: its file, its text and the scene.
pub fn pov_peer_files(dir: &Path) -> (PathBuf, String, Scene) {
    let path = write_pov_peer_scene(dir);
    let text = std::fs::read_to_string(&path).expect("scene text");
    let scene = load_scene_file(&path).expect("peer scene");
    (path, text, scene)
}

/// The POV-Ray peer's 1920×1080 still at the interactive quality with `samples` per pixel,
/// adaptive at `adaptive_samples` if given, box-resolved.
pub fn pov_peer_settings(samples: u32, adaptive_samples: Option<f32>) -> StillSettings {
    StillSettings {
        size: (1920, 1080),
        quality: Quality {
            samples,
            adaptive_samples,
            ..Quality::interactive()
        },
        resolve: ResolveFilter::Box,
        time: 0.0,
        mode: ShaderMode::Shaded,
    }
}

/// The POV-Ray peer's scene (or a variant of it) prepared for a 1920×1080 still.
pub struct PeerStill {
    pub still: PreparedStill,
    pub settings: StillSettings,
}

impl PeerStill {
    /// `scene` (written as `text`) at `settings`.
    pub fn new(scene: Scene, text: String, settings: StillSettings) -> PeerStill {
        let camera = scene.camera.clone();
        let still = PreparedStill::new(("peer", &text), scene, &camera, &settings)
            .expect("prepared peer scene");
        PeerStill { still, settings }
    }

    /// Writes the still to `out` as `format`.
    pub fn write(&self, out: &Path, format: StillFormat) {
        let place = StillPlace::default();
        (self.still)
            .write(self.settings, place, (out, format), &mut |_| {}, &|| None)
            .expect("still");
    }
}

/// Writes `still` with `settings` as a PNG to `out` `runs` times after one unmeasured run; their
/// times.
pub fn time_png_stills(
    still: &PreparedStill,
    settings: StillSettings,
    out: &Path,
    runs: usize,
) -> Timing {
    let destination = (out, StillFormat::Png);
    Timing::measure(1, runs, || {
        let place = StillPlace::default();
        (still)
            .write(settings, place, destination, &mut |_| {}, &|| None)
            .expect("still");
    })
}

/// The POV-Ray peer's scene as a POV-Ray user would write it, into `dir/native.pov` beside copies
/// of its images: the same camera and lights, an analytic box for the floor with POV-Ray's own
/// checker and dents, an analytic sphere with the chelsea image and the gravel bump map
/// wrapped around it (`map_type 1`). The same look, drawn POV-Ray's way.
pub fn write_native_pov_scene(dir: &Path, scene: &Scene, size: (u32, u32)) -> PathBuf {
    use bumpwork::export::{pov, rgb, write_pov_header};
    use std::io::Write;
    for image in ["chelsea.png", "gravel.png"] {
        let shipped = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("textures")
            .join(image);
        std::fs::copy(shipped, dir.join(image)).expect("shipped image");
    }
    let mut sdl = Vec::new();
    write_pov_header(&mut sdl, scene, &scene.camera, size).expect("header");
    let finish = |material: &Material| {
        format!(
            "finish {{ ambient {} diffuse 1 specular {} roughness {} }}",
            rgb(scene.ambient),
            material.specular,
            1.0 / material.shininess.max(1e-3)
        )
    };
    for object in &scene.objects {
        match &object.surface {
            Surface::Plane(plane) => {
                let far = plane.origin
                    + (plane.u_axis * plane.size.x + plane.v_axis * plane.size.y).as_dvec3();
                let below = -plane.normal.as_dvec3();
                writeln!(
                    sdl,
                    "box {{ {} {}\n  texture {{ pigment {{ checker rgb <0, 1, 1> rgb <1, 0, 1> scale 25 }}\n    normal {{ dents 0.6 scale 12 }} {} }} }}",
                    pov(plane.origin),
                    pov(far + below),
                    finish(&object.material)
                )
            }
            Surface::Sphere(sphere) => writeln!(
                sdl,
                "sphere {{ <0, 0, 0>, {}\n  texture {{ pigment {{ image_map {{ png \"chelsea.png\" map_type 1 interpolate 2 }} }}\n    normal {{ bump_map {{ png \"gravel.png\" map_type 1 interpolate 2 bump_size 1.5 }} }} {} }}\n  translate {} }}",
                sphere.radius,
                finish(&object.material),
                pov(sphere.center)
            ),
            other => panic!("the peer scene has no {other:?}"),
        }
        .expect("in memory");
    }
    let path = dir.join("native.pov");
    std::fs::write(&path, sdl).expect("native scene");
    path
}
