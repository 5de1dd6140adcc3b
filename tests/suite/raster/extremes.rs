//! Extremes: zero-area triangles, 1×1 and 1×N outputs, scenes translated by 1e6.

use crate::common::*;
use bumpwork::raster::{Framebuffer, RenderTarget, Viewport};
use bumpwork::render::render_lit;
use bumpwork::scene::PreparedScene;
use bumpwork::scene::{Light, PRESET_NAMES, Scene, preset};
use bumpwork::surface::Tessellation;
use glam::DVec3;

fn render_scene(scene: Scene, viewport: Viewport) -> Framebuffer {
    let camera = scene.camera.clone();
    let prepared = PreparedScene::new(scene, Tessellation { density: 16 });
    let target = RenderTarget::new(&camera, viewport);
    render_lit(&prepared, &target).0
}

#[test]
fn zero_area_triangles_produce_nothing() {
    let viewport = Viewport {
        width: 16,
        height: 16,
    };
    assert!(
        screen_triangle(viewport, [(1.0, 1.0), (5.0, 5.0), (9.0, 9.0)]).is_none(),
        "collinear"
    );
    assert!(
        screen_triangle(viewport, [(3.5, 3.5), (3.5, 3.5), (3.5, 3.5)]).is_none(),
        "a point"
    );
    // Distinct in floating point, identical after snapping to 1/256 pixel.
    assert!(
        screen_triangle(viewport, [(3.0, 3.0), (3.0001, 3.0), (3.0, 3.0001)]).is_none(),
        "sub-snap"
    );
}

#[test]
fn every_preset_renders_finite_pixels_at_tiny_and_thin_sizes() {
    for name in PRESET_NAMES {
        for (width, height) in [(1, 1), (1, 37), (53, 1), (3, 2)] {
            let fb = render_scene(preset(name).unwrap(), Viewport { width, height });
            assert_eq!(fb.color().len(), (width * height) as usize);
            assert!(
                fb.color().iter().all(|c| c.is_finite()),
                "{name} at {width}x{height}"
            );
        }
    }
}

#[test]
fn every_preset_covers_something_and_has_no_nan() {
    for name in PRESET_NAMES {
        let fb = render_scene(
            preset(name).unwrap(),
            Viewport {
                width: 96,
                height: 64,
            },
        );
        assert!(
            fb.color().iter().all(|c| c.is_finite()),
            "{name} has a non-finite pixel"
        );
        let covered = fb.depth().iter().filter(|d| d.is_finite()).count();
        assert!(
            covered > 96 * 64 / 10,
            "{name} covers only {covered} pixels"
        );
    }
}

fn translated(mut scene: Scene, offset: DVec3) -> Scene {
    scene.camera.eye += offset;
    scene.camera.target += offset;
    for light in &mut scene.lights {
        if let Light::Point { position, .. } = light {
            *position += offset;
        }
    }
    for object in &mut scene.objects {
        object.surface.move_by(offset);
    }
    scene
}

#[test]
fn a_scene_translated_by_a_million_renders_the_same() {
    let viewport = Viewport {
        width: 160,
        height: 120,
    };
    for name in [
        "sphere-on-plane-dimples",
        "cone-ripple",
        "image-to-triangle",
        "wave-spheres",
        "rounded-cube-dimples",
        "torus-dimples",
    ] {
        let near = render_scene(preset(name).unwrap(), viewport);
        let far = render_scene(
            translated(preset(name).unwrap(), DVec3::new(1e6, -1e6, 1e6)),
            viewport,
        );
        let max_difference = near
            .color()
            .iter()
            .zip(far.color())
            .map(|(a, b)| (*a - *b).abs().max_element())
            .fold(0.0f32, f32::max);
        assert!(
            max_difference < 1e-3,
            "{name}: colours differ by {max_difference}"
        );
        let coverage_changes = near
            .depth()
            .iter()
            .zip(far.depth())
            .filter(|(a, b)| a.is_finite() != b.is_finite())
            .count();
        assert!(
            coverage_changes <= 2,
            "{name}: {coverage_changes} pixels changed coverage"
        );
    }
}
