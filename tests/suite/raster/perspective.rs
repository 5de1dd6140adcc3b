//! Perspective-correct (u,v): on a plane seen at a grazing angle, the (u,v) of each pixel centre
//! equals the analytic ray–plane intersection to within 1e-3 of a texture period. Affine
//! interpolation fails the same check, so the check can fail.

use crate::common::*;
use bumpwork::raster::{Interpolation, Viewport};
use bumpwork::scene::{Material, Object, Scene};
use bumpwork::surface::{Plane, Surface};
use glam::{DVec3, Vec2, Vec3};

const PERIOD: f64 = 30.0;
const TOLERANCE: f64 = 1e-3 * PERIOD;

fn grazing_plane_scene() -> (Scene, Plane) {
    // A 4000-unit ground, the eye 40 units above it looking 2000 units ahead: the far rows meet
    // the plane at 89° from its normal.
    let plane = Plane::new(
        DVec3::new(-2000.0, 0.0, 1000.0),
        Vec3::Y,
        Vec3::X,
        Vec2::new(4000.0, 4000.0),
    );
    let scene = Scene {
        name: "grazing".into(),
        camera: camera([13.0, 40.0, 200.0], [0.0, 0.0, -1800.0], 50.0),
        background: Vec3::ZERO,
        ambient: Vec3::ZERO,
        lights: vec![],
        time: 0.0,
        quality: Vec::new(),
        shadows: true,
        objects: vec![Object {
            surface: Surface::Plane(plane.clone()),
            material: Material {
                color: Vec3::ONE,
                specular: 0.0,
                shininess: 1.0,
                ..Material::default()
            },
            displace: false,
        }],
    };
    (scene, plane)
}

/// The largest (u,v) error over covered pixels, and how many pixels were compared.
fn max_uv_error(interpolation: Interpolation) -> (f64, usize) {
    let viewport = Viewport {
        width: 320,
        height: 200,
    };
    let (scene, plane) = grazing_plane_scene();
    let cam = scene.camera.clone();
    let fb = render_uv(scene, viewport, interpolation, 1);
    let (mut worst, mut compared) = (0.0f64, 0);
    for y in 0..viewport.height {
        for x in 0..viewport.width {
            let i = (y * viewport.width + x) as usize;
            if fb.depth()[i].is_infinite() {
                continue;
            }
            let ray = cam.ray_direction(
                viewport.width,
                viewport.height,
                x as f64 + 0.5,
                y as f64 + 0.5,
            );
            let t = -cam.eye.y / ray.y;
            let hit = cam.eye + ray * t - plane.origin;
            let exact = (
                hit.dot(plane.u_axis.as_dvec3()),
                hit.dot(plane.v_axis.as_dvec3()),
            );
            let got = fb.color()[i];
            let error = (got.x as f64 - exact.0)
                .abs()
                .max((got.y as f64 - exact.1).abs());
            worst = worst.max(error);
            compared += 1;
        }
    }
    (worst, compared)
}

#[test]
fn perspective_correct_uv_matches_the_ray_plane_intersection() {
    let (error, compared) = max_uv_error(Interpolation::PerspectiveCorrect);
    eprintln!("perspective-correct: max (u,v) error {error:.2e} over {compared} pixels");
    assert!(
        compared > 20_000,
        "the plane covers most of the image: {compared}"
    );
    assert!(error <= TOLERANCE, "max (u,v) error {error} > {TOLERANCE}");
}

#[test]
fn affine_uv_fails_the_same_check() {
    let (error, _) = max_uv_error(Interpolation::Affine);
    eprintln!("affine: max (u,v) error {error:.1}");
    assert!(error > 100.0 * TOLERANCE, "affine error only {error}");
}

#[test]
fn screen_derivatives_of_uv_match_neighbouring_pixels() {
    use crate::common::render_with;
    use bumpwork::raster::{Fragment, RenderTarget};
    use bumpwork::scene::PreparedScene;
    use bumpwork::shade::{FrameObject, PerFragment};
    use bumpwork::surface::Tessellation;
    let viewport = Viewport {
        width: 320,
        height: 200,
    };
    let (scene, _) = grazing_plane_scene();
    let cam = scene.camera.clone();
    let prepared = PreparedScene::new(scene, Tessellation { density: 1 });
    let target = RenderTarget::new(&cam, viewport);
    let shader =
        PerFragment(|_: &FrameObject, f: &Fragment| Vec3::new(f.uv.x, f.duv_dx.x, f.duv_dy.y));
    let fb = render_with(&prepared, &target, &shader).0;
    let shader_v = PerFragment(|_: &FrameObject, f: &Fragment| Vec3::new(f.uv.y, 0.0, 0.0));
    let fb_v = render_with(&prepared, &target, &shader_v).0;
    let at = |x: u32, y: u32| (y * viewport.width + x) as usize;
    let mut checked = 0;
    for y in 1..viewport.height - 1 {
        for x in 1..viewport.width - 1 {
            let neighbours = [
                at(x - 1, y),
                at(x + 1, y),
                at(x, y - 1),
                at(x, y + 1),
                at(x, y),
            ];
            if neighbours.iter().any(|&i| fb.depth()[i].is_infinite()) {
                continue;
            }
            let du_dx = (fb.color()[at(x + 1, y)].x - fb.color()[at(x - 1, y)].x) / 2.0;
            let v = |x, y| fb_v.color()[at(x, y)].x;
            let (forward, backward) = (v(x, y + 1) - v(x, y), v(x, y) - v(x, y - 1));
            let dv_dy = (forward + backward) / 2.0;
            // Near the horizon v curves too fast between rows for a difference to be a reference.
            if (forward - backward).abs() > 0.05 * dv_dy.abs() {
                continue;
            }
            let c = fb.color()[at(x, y)];
            // u is linear along rows of a ground plane seen upright.
            assert!(
                (c.y - du_dx).abs() <= 1e-3 * du_dx.abs().max(1.0),
                "du/dx {} vs {du_dx} at ({x}, {y})",
                c.y
            );
            assert!(
                (c.z - dv_dy).abs() <= 0.02 * dv_dy.abs().max(1e-2),
                "dv/dy {} vs {dv_dy} at ({x}, {y})",
                c.z
            );
            checked += 1;
        }
    }
    assert!(checked > 20_000, "{checked}");
}
