//! The rasterizer against the exact reference on the same frames: identical where interpolation
//! is exact (planes, triangles), within stated bounds on the curved presets at the default
//! tessellation, and converging as the tessellation grows.

mod reference_support;

use bumpwork::raster::{
    Fragment, FrameObject, Interpolation, PerFragment, PreparedScene, RenderTarget, render_with,
};
use bumpwork::reference::render_reference;
use bumpwork::scene::preset;
use bumpwork::surface::Tessellation;
use glam::Vec3;
use reference_support::*;

/// (u, v, object) in the colour channels: the fragments themselves, before any shading.
fn uv_shader() -> PerFragment<impl Fn(&FrameObject, &Fragment) -> Vec3 + Sync> {
    PerFragment(|_: &FrameObject, f: &Fragment| Vec3::new(f.uv.x, f.uv.y, f.object as f32))
}

#[test]
fn planar_scenes_give_the_same_fragments_both_ways() {
    // Perspective-correct interpolation is exact on a plane: only sub-pixel snapping of the
    // silhouette (1/256 px) and f32 rounding separate the two.
    for name in ["plane-dimples", "two-planes-textured", "image-to-triangle"] {
        let scene = preset(name).unwrap();
        let prepared = PreparedScene::new(scene.clone(), Tessellation::default());
        let target = RenderTarget {
            camera: &scene.camera,
            viewport: SMALL,
            interpolation: Interpolation::PerspectiveCorrect,
        };
        let raster = render_with(&prepared, &target, &uv_shader()).0;
        let reference = render_reference(&prepared, &scene.camera, SMALL, &uv_shader()).0;
        let mut mismatched = 0;
        for i in 0..raster.color.len() {
            let (a, b) = (raster.color[i], reference.color[i]);
            match (raster.depth[i].is_finite(), reference.depth[i].is_finite()) {
                (true, true) if a.z == b.z => {
                    // 1e-3 of the uv period of 30 units, relative to depth for far pixels.
                    let tolerance = 2e-3 + 2e-6 * raster.depth[i];
                    assert!(
                        (a - b).abs().max_element() <= tolerance,
                        "{name}: pixel {i}: raster {a} vs reference {b}"
                    );
                    let dd = (raster.depth[i] - reference.depth[i]).abs();
                    assert!(dd <= 1e-4 * reference.depth[i], "{name}: depth at {i}");
                }
                (false, false) => {}
                _ => mismatched += 1,
            }
        }
        // Pixel centres within 1/256 px of an edge may fall either way: a handful at most.
        assert!(mismatched <= 4, "{name}: {mismatched} pixels differ in coverage or object");
    }
}
