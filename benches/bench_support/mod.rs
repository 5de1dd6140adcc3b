//! Scenes shared by the benchmarks.
#![allow(dead_code)]

use bumpwork::raster::Camera;
use bumpwork::scene::{Light, Material, Object, Scene};
use bumpwork::surface::{Sphere, Surface};
use glam::{DVec3, Vec3};

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
        }],
    }
}
