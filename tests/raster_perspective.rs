//! Perspective-correct (u,v): on a plane seen at a grazing angle, the (u,v) of each pixel centre
//! equals the analytic ray–plane intersection to within 1e-3 of a texture period. Affine
//! interpolation fails the same check, so the check can fail.

mod common;

use bumpwork::raster::{Interpolation, Viewport};
use bumpwork::scene::{Material, Object, Scene};
use bumpwork::surface::{Plane, Surface};
use common::*;
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
        objects: vec![Object {
            surface: Surface::Plane(plane.clone()),
            material: Material {
                color: Vec3::ONE,
                specular: 0.0,
                shininess: 1.0,
            },
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
            if fb.depth[i].is_infinite() {
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
            let got = fb.color[i];
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
