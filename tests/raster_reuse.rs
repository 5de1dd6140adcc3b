//! A framebuffer reused from frame to frame (the workbench's, a still's band passes) skips
//! rewriting tiles it knows are still background: whatever happened in between, each frame
//! must hold exactly what a fresh framebuffer would.

use bumpwork::raster::{Framebuffer, PreparedScene, RenderTarget, Viewport, render, render_into};
use bumpwork::scene::{Scene, preset};
use bumpwork::shade::LitShader;
use bumpwork::surface::Tessellation;
use glam::{DVec3, Vec3};

const SMALL: Viewport = Viewport {
    width: 200,
    height: 150,
};

/// The sphere preset seen from `eye`: a small disc that leaves most tiles background.
fn sphere_from(eye: DVec3, background: Vec3) -> PreparedScene {
    let mut scene: Scene = preset("big-sphere-dimples").expect("preset");
    scene.camera.eye = eye;
    scene.background = background;
    PreparedScene::new(scene, Tessellation { density: 16 })
}

fn fresh(prepared: &PreparedScene, viewport: Viewport) -> Framebuffer {
    render(
        prepared,
        &RenderTarget::new(&prepared.scene.camera, viewport),
    )
    .0
}

fn render_reusing(prepared: &PreparedScene, viewport: Viewport, framebuffer: &mut Framebuffer) {
    let camera = &prepared.scene.camera;
    let shader = LitShader::new(&prepared.scene, camera);
    render_into(
        prepared,
        &RenderTarget::new(camera, viewport),
        &shader,
        framebuffer,
    );
}

fn assert_same(got: &Framebuffer, want: &Framebuffer, what: &str) {
    assert_eq!((got.width, got.height), (want.width, want.height), "{what}");
    let bits = |v: &[f32]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    let colours = |fb: &Framebuffer| bits(bytemuck::cast_slice(fb.color()));
    assert!(colours(got) == colours(want), "{what}: colours differ");
    assert!(
        bits(got.depth()) == bits(want.depth()),
        "{what}: depths differ"
    );
}

#[test]
fn a_reused_framebuffer_matches_a_fresh_one_whatever_came_before() {
    let base_eye = preset("big-sphere-dimples").unwrap().camera.eye;
    let grey = Vec3::splat(0.1);
    let frames = [
        (sphere_from(base_eye, grey), SMALL, "first frame"),
        (sphere_from(base_eye, grey), SMALL, "the same frame again"),
        // The sphere moves off the tiles it covered and onto others.
        (sphere_from(base_eye * 3.0, grey), SMALL, "farther away"),
        (sphere_from(base_eye * 0.6, grey), SMALL, "close up"),
        (
            sphere_from(base_eye * 3.0, Vec3::new(0.2, 0.0, 0.5)),
            SMALL,
            "a new background",
        ),
        (
            sphere_from(base_eye * 3.0, grey),
            Viewport {
                width: 131,
                height: 70,
            },
            "a new size",
        ),
        (sphere_from(base_eye, grey), SMALL, "back to the first"),
    ];
    let mut reused = Framebuffer::new(0, 0, Vec3::ZERO);
    for (prepared, viewport, what) in &frames {
        render_reusing(prepared, *viewport, &mut reused);
        assert_same(&reused, &fresh(prepared, *viewport), what);
    }
}

#[test]
fn pixels_written_between_frames_are_not_trusted_as_background() {
    let far = sphere_from(
        preset("big-sphere-dimples").unwrap().camera.eye * 3.0,
        Vec3::ZERO,
    );
    let mut reused = Framebuffer::new(0, 0, Vec3::ZERO);
    render_reusing(&far, SMALL, &mut reused);
    // An overlay (the wireframe view draws lines this way) scribbles over background tiles.
    reused.color_mut().fill(Vec3::ONE);
    render_reusing(&far, SMALL, &mut reused);
    assert_same(&reused, &fresh(&far, SMALL), "after colour_mut");
    reused.parts_mut().1.fill(0.5);
    render_reusing(&far, SMALL, &mut reused);
    assert_same(&reused, &fresh(&far, SMALL), "after parts_mut");
    let _ = reused.take_depth();
    render_reusing(&far, SMALL, &mut reused);
    assert_same(&reused, &fresh(&far, SMALL), "after take_depth");
}
