//! Clipping: the camera inside a sphere, just above and exactly on a plane that runs behind it,
//! triangles crossing the near plane. No panic, no NaN, and coverage and depth agree with a
//! per-pixel ray cast of the exact surfaces.

use crate::common::*;
use bumpwork::raster::{Framebuffer, Interpolation, Viewport};
use bumpwork::scene::Camera;
use bumpwork::scene::{Material, Object, Scene};
use bumpwork::surface::{Plane, Sphere, Surface};
use glam::{DVec3, Vec2, Vec3};

const VIEWPORT: Viewport = Viewport {
    width: 200,
    height: 150,
};

fn scene_of(camera: Camera, surface: Surface) -> Scene {
    Scene {
        name: "clip".into(),
        camera,
        background: Vec3::ZERO,
        ambient: Vec3::ZERO,
        lights: vec![],
        time: 0.0,
        quality: Vec::new(),
        shadows: true,
        objects: vec![Object {
            surface,
            material: Material {
                color: Vec3::ONE,
                specular: 0.0,
                shininess: 1.0,
                ..Material::default()
            },
            displace: false,
        }],
    }
}

fn assert_all_finite(fb: &Framebuffer) {
    for (i, c) in fb.color().iter().enumerate() {
        assert!(c.is_finite(), "NaN or infinity at pixel {i}: {c:?}");
    }
    for (i, d) in fb.depth().iter().enumerate() {
        assert!(d.is_finite() || *d == f32::INFINITY, "bad depth at {i}");
    }
}

/// For each pixel, the view depth of the nearest ray hit past the near plane, from `hits`
/// (distances along the unit ray, any order).
fn ray_cast(camera: &Camera, hits: impl Fn(DVec3) -> Vec<f64>) -> Vec<Option<f64>> {
    let forward = camera.forward().as_dvec3();
    let mut depths = Vec::new();
    for y in 0..VIEWPORT.height {
        for x in 0..VIEWPORT.width {
            let ray = camera.ray_direction(
                VIEWPORT.width,
                VIEWPORT.height,
                x as f64 + 0.5,
                y as f64 + 0.5,
            );
            let nearest = hits(ray)
                .into_iter()
                .map(|t| t * ray.dot(forward))
                .filter(|&depth| depth >= camera.near as f64 && depth <= camera.far as f64)
                .fold(None, |best: Option<f64>, d| {
                    Some(best.map_or(d, |b| b.min(d)))
                });
            depths.push(nearest);
        }
    }
    depths
}

#[test]
fn camera_inside_a_sphere_sees_it_everywhere_at_the_right_depth() {
    let radius = 100.0;
    let cam = camera([30.0, -20.0, 10.0], [100.0, 50.0, -30.0], 70.0);
    let sphere = Sphere {
        center: DVec3::ZERO,
        radius,
    };
    let fb = render_uv(
        scene_of(cam.clone(), Surface::Sphere(sphere)),
        VIEWPORT,
        Interpolation::PerspectiveCorrect,
        64,
    );
    assert_all_finite(&fb);
    let reference = ray_cast(&cam, |ray| {
        // |eye + t·ray|² = r², eye inside: the positive root.
        let b = cam.eye.dot(ray);
        let c = cam.eye.length_squared() - (radius as f64).powi(2);
        vec![-b + (b * b - c).sqrt()]
    });
    // Chords of a 128×64 tessellation of r = 100 sit at most r·(1 − cos(π/64)) ≈ 0.12 inside.
    for (i, (got, want)) in fb.depth().iter().zip(&reference).enumerate() {
        let want = want.expect("every ray from inside hits the sphere");
        assert!(got.is_finite(), "hole at pixel {i}");
        assert!(
            (*got as f64 - want).abs() <= 0.13 + 1e-4 * want,
            "depth {got} vs {want} at pixel {i}"
        );
    }
}

fn ground() -> Surface {
    Surface::Plane(Plane::new(
        DVec3::new(-500.0, 0.0, 500.0),
        Vec3::Y,
        Vec3::X,
        Vec2::new(1000.0, 1000.0),
    ))
}

fn plane_hits(cam: &Camera) -> impl Fn(DVec3) -> Vec<f64> + '_ {
    move |ray: DVec3| {
        let t = -cam.eye.y / ray.y;
        let hit = cam.eye + ray * t;
        let on_plane = hit.x.abs() <= 500.0 && hit.z.abs() <= 500.0;
        if t > 0.0 && on_plane { vec![t] } else { vec![] }
    }
}

#[test]
fn plane_crossing_the_near_plane_matches_the_ray_cast() {
    // The eye hovers just above a plane that extends behind it: its triangles cross the near plane.
    let mut cam = camera([0.0, 0.5, 0.0], [0.0, -40.0, -400.0], 80.0);
    cam.near = 0.05;
    let fb = render_uv(
        scene_of(cam.clone(), ground()),
        VIEWPORT,
        Interpolation::PerspectiveCorrect,
        1,
    );
    assert_all_finite(&fb);
    let reference = ray_cast(&cam, plane_hits(&cam));
    let mut mismatches = 0;
    for (i, (got, want)) in fb.depth().iter().zip(&reference).enumerate() {
        match want {
            Some(want) if got.is_finite() => {
                assert!(
                    (*got as f64 - want).abs() <= 1e-3 * want.max(1.0),
                    "depth {got} vs {want} at {i}"
                )
            }
            None if got.is_infinite() => {}
            _ => mismatches += 1,
        }
    }
    // Only pixels whose centre is within a pixel of the far edge or the frame edge may disagree.
    assert!(
        mismatches <= VIEWPORT.width as usize,
        "{mismatches} coverage mismatches"
    );
    assert!(reference.iter().filter(|d| d.is_some()).count() > 10_000);
}

#[test]
fn camera_exactly_on_a_plane_sees_it_edge_on() {
    let cam = camera([0.0, 0.0, 0.0], [0.0, 0.0, -100.0], 60.0);
    let fb = render_uv(
        scene_of(cam.clone(), ground()),
        VIEWPORT,
        Interpolation::PerspectiveCorrect,
        1,
    );
    assert_all_finite(&fb);
    let covered = fb.depth().iter().filter(|d| d.is_finite()).count();
    assert!(
        covered <= VIEWPORT.width as usize,
        "an edge-on plane covers at most a row: {covered}"
    );
}

#[test]
fn sphere_behind_the_camera_is_not_drawn() {
    let cam = camera([0.0, 0.0, 0.0], [0.0, 0.0, -100.0], 60.0);
    let sphere = Sphere {
        center: DVec3::new(0.0, 0.0, 50.0),
        radius: 20.0,
    };
    let fb = render_uv(
        scene_of(cam, Surface::Sphere(sphere)),
        VIEWPORT,
        Interpolation::PerspectiveCorrect,
        32,
    );
    assert!(fb.depth().iter().all(|d| d.is_infinite()));
}
