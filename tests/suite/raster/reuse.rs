//! A framebuffer reused from frame to frame (the workbench's, a still's band passes) skips
//! rewriting tiles it knows are still background: whatever happened in between, each frame
//! must hold exactly what a fresh framebuffer would. Renders restricted to a mask, or adding
//! weighted colours into what is there (supersampling's passes), touch only their pixels.

use bumpwork::raster::{
    Blend, FrameOutput, Framebuffer, ImageWindow, Refinement, RenderTarget, STRIP_ROWS,
    Srgb8Strips, Viewport,
};
use bumpwork::render::{render_lit, render_scene, render_scene_pass};
use bumpwork::scene::PreparedScene;
use bumpwork::scene::{Scene, preset};
use bumpwork::shade::LitShader;
use bumpwork::still::RefineRule;
use bumpwork::surface::Tessellation;
use glam::{DVec3, Vec2, Vec3};
use std::sync::Mutex;

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

/// The sphere from three times as far: most tiles hold only background.
fn far_sphere(background: Vec3) -> PreparedScene {
    sphere_from(
        preset("big-sphere-dimples").unwrap().camera.eye * 3.0,
        background,
    )
}

fn fresh(prepared: &PreparedScene, viewport: Viewport) -> Framebuffer {
    render_lit(
        prepared,
        &RenderTarget::new(&prepared.scene.camera, viewport),
    )
    .0
}

fn render_reusing(prepared: &PreparedScene, viewport: Viewport, framebuffer: &mut Framebuffer) {
    let camera = &prepared.scene.camera;
    let shader = LitShader::new(&prepared.scene, camera);
    render_scene_pass(
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
    let far = far_sphere(Vec3::ZERO);
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

/// A framebuffer of made-up colours and depths, none of them what a render writes.
fn scribbled(viewport: Viewport) -> Framebuffer {
    let n = (viewport.width * viewport.height) as usize;
    let colours = (0..n)
        .map(|i| Vec3::new(i as f32 * 1e-4, 0.3, -0.2))
        .collect();
    Framebuffer::from_parts(viewport.width, viewport.height, colours, vec![-1.0; n])
}

/// A mask wanting about a third of the pixels, scattered, plus whole rows (background tiles
/// included) and nothing in the bottom-right corner's tile.
fn scattered_mask(viewport: Viewport) -> Vec<bool> {
    let mut state = 11u64;
    (0..viewport.width * viewport.height)
        .map(|i| {
            state = state.wrapping_mul(6364136223846793005).wrapping_add(1);
            let (x, y) = (i % viewport.width, i / viewport.width);
            let corner = x >= viewport.width - 40 && y >= viewport.height - 40;
            !corner && (y.is_multiple_of(17) || (state >> 33).is_multiple_of(3))
        })
        .collect()
}

fn render_as(
    prepared: &PreparedScene,
    mask: Option<&[bool]>,
    blend: Blend,
    framebuffer: &mut Framebuffer,
) {
    render_writing(prepared, mask, blend, true, framebuffer);
}

fn render_writing(
    prepared: &PreparedScene,
    mask: Option<&[bool]>,
    blend: Blend,
    writes_depth: bool,
    framebuffer: &mut Framebuffer,
) {
    let camera = &prepared.scene.camera;
    let target = RenderTarget {
        mask,
        blend,
        writes_depth,
        ..RenderTarget::new(camera, SMALL)
    };
    render_scene_pass(
        prepared,
        &target,
        &LitShader::new(&prepared.scene, camera),
        framebuffer,
    );
}

#[test]
fn a_masked_render_writes_its_pixels_and_leaves_the_rest() {
    let far = far_sphere(Vec3::splat(0.1));
    let want = fresh(&far, SMALL);
    let mask = scattered_mask(SMALL);
    let weight = 0.25;
    let kept = 0.75;
    let rescale = Blend::Rescale { kept, weight };
    for blend in [
        Blend::Replace,
        Blend::Scale(weight),
        Blend::Add(weight),
        rescale,
    ] {
        let before = scribbled(SMALL);
        let mut got = before.clone();
        render_as(&far, Some(&mask), blend, &mut got);
        for (i, &wanted) in mask.iter().enumerate() {
            let colour = match blend {
                _ if !wanted => before.color()[i],
                Blend::Replace => want.color()[i],
                Blend::Scale(_) => want.color()[i] * weight,
                Blend::Add(_) => before.color()[i] + want.color()[i] * weight,
                Blend::Rescale { .. } => before.color()[i] * kept + want.color()[i] * weight,
            };
            let depth = if wanted {
                want.depth()[i]
            } else {
                before.depth()[i]
            };
            let what = format!("{blend:?} at pixel {i}, wanted {wanted}");
            assert_eq!(
                got.color()[i].to_array().map(f32::to_bits),
                colour.to_array().map(f32::to_bits),
                "{what}"
            );
            assert_eq!(got.depth()[i].to_bits(), depth.to_bits(), "{what}");
        }
    }
}

#[test]
fn an_adding_render_neither_trusts_nor_leaves_known_background() {
    let far = far_sphere(Vec3::splat(0.1));
    let want = fresh(&far, SMALL);
    let mut reused = Framebuffer::new(0, 0, Vec3::ZERO);
    // The first render records its background tiles; the adding one must still add to them.
    render_as(&far, None, Blend::Replace, &mut reused);
    render_as(&far, None, Blend::Add(0.5), &mut reused);
    let doubled: Vec<Vec3> = want.color().iter().map(|&c| c + c * 0.5).collect();
    let expected =
        Framebuffer::from_parts(SMALL.width, SMALL.height, doubled, want.depth().to_vec());
    assert_same(&reused, &expected, "replace then add");
    // Nor may the sums be taken for background by the next replacing render.
    render_as(&far, None, Blend::Replace, &mut reused);
    assert_same(&reused, &want, "add then replace");
}

fn render_without_depth(
    prepared: &PreparedScene,
    mask: Option<&[bool]>,
    blend: Blend,
    framebuffer: &mut Framebuffer,
) {
    render_writing(prepared, mask, blend, false, framebuffer);
}

#[test]
fn a_render_without_depth_writes_the_same_colours_and_leaves_every_depth() {
    let far = far_sphere(Vec3::splat(0.1));
    let mask = scattered_mask(SMALL);
    for mask in [None, Some(&mask[..])] {
        for blend in [Blend::Replace, Blend::Scale(0.25), Blend::Add(0.25)] {
            let before = scribbled(SMALL);
            let mut want = before.clone();
            render_as(&far, mask, blend, &mut want);
            let mut got = before.clone();
            render_without_depth(&far, mask, blend, &mut got);
            let expected = Framebuffer::from_parts(
                SMALL.width,
                SMALL.height,
                want.color().to_vec(),
                before.depth().to_vec(),
            );
            let what = format!("{blend:?}, masked {}", mask.is_some());
            assert_same(&got, &expected, &what);
        }
    }
}

#[test]
fn a_render_without_depth_records_no_background_for_the_next_render_to_trust() {
    let base_eye = preset("big-sphere-dimples").unwrap().camera.eye;
    let grey = Vec3::splat(0.1);
    let (close, far) = (sphere_from(base_eye * 0.6, grey), far_sphere(grey));
    let mut reused = Framebuffer::new(0, 0, Vec3::ZERO);
    // The close sphere's depths stay where the far one leaves background but writes no depth.
    render_reusing(&close, SMALL, &mut reused);
    render_without_depth(&far, None, Blend::Replace, &mut reused);
    render_reusing(&far, SMALL, &mut reused);
    assert_same(&reused, &fresh(&far, SMALL), "depthless, then whole");
}

/// Supersampling-like passes over `SMALL`: each shifted within the pixel, adding or replacing,
/// with or without depth, over `mask`.
fn shifted_passes<'a>(
    prepared: &'a PreparedScene,
    mask: Option<&'a [bool]>,
) -> Vec<RenderTarget<'a>> {
    let pass = |(x, y), blend, writes_depth| RenderTarget {
        window: ImageWindow {
            offset: Vec2::new(x, y),
            ..ImageWindow::whole(SMALL)
        },
        footprint: 0.5,
        mask,
        blend,
        writes_depth,
        ..RenderTarget::new(&prepared.scene.camera, SMALL)
    };
    vec![
        pass((0.0, 0.0), Blend::Replace, true),
        pass((0.3, -0.2), Blend::Scale(0.25), false),
        pass((-0.4, 0.1), Blend::Add(0.25), true),
        pass((0.1, 0.45), Blend::Add(0.25), false),
    ]
}

/// A framebuffer holding a whole render, so its background tiles are known.
fn rendered_once(prepared: &PreparedScene) -> Framebuffer {
    let mut framebuffer = Framebuffer::new(0, 0, Vec3::ZERO);
    render_reusing(prepared, SMALL, &mut framebuffer);
    framebuffer
}

#[test]
fn passes_rendered_tile_by_tile_equal_the_passes_one_after_another() {
    let far = far_sphere(Vec3::splat(0.1));
    let shader = LitShader::new(&far.scene, &far.scene.camera);
    let mask = scattered_mask(SMALL);
    for mask in [None, Some(&mask[..])] {
        let passes = shifted_passes(&far, mask);
        let mut want = rendered_once(&far);
        for pass in &passes {
            render_scene_pass(&far, pass, &shader, &mut want);
        }
        let mut got = rendered_once(&far);
        let stats = render_scene(
            &far,
            &passes,
            &shader,
            FrameOutput::Framebuffer(&mut got),
            None,
        );
        let what = format!("masked {}", mask.is_some());
        assert_same(&got, &want, &what);
        assert!(stats.fragments > 0, "{what}: nothing shaded");
        // The background recorded for the next render is only what still is background.
        render_reusing(&far, SMALL, &mut got);
        assert_same(&got, &fresh(&far, SMALL), &format!("{what}, then whole"));
    }
}

/// The indices of `SMALL`'s strips, top first.
fn every_strip() -> Vec<usize> {
    (0..SMALL.height.div_ceil(STRIP_ROWS) as usize).collect()
}

/// Runs `render` with strips whose buffers come holding stale bytes (as reused ones do, so
/// every byte must be written), and collects what it hands on: its result, the strip indices in
/// order, and their bytes joined.
fn hearing_strips<R>(render: impl FnOnce(&Srgb8Strips) -> R) -> (R, Vec<usize>, Vec<u8>) {
    let heard = Mutex::new(Vec::new());
    let buffer = || vec![0xAB; 5];
    let finished = |strip: usize, bytes: Vec<u8>| heard.lock().unwrap().push((strip, bytes));
    let result = render(&Srgb8Strips {
        buffer: &buffer,
        finished: &finished,
    });
    let mut heard = heard.into_inner().unwrap();
    heard.sort_by_key(|&(strip, _)| strip);
    let indices = heard.iter().map(|&(strip, _)| strip).collect();
    let bytes = heard.into_iter().flat_map(|(_, bytes)| bytes).collect();
    (result, indices, bytes)
}

#[test]
fn a_lone_pass_into_strips_alone_hands_on_each_strip_as_the_renders_pixels() {
    // A background that is not grey, so background runs are encoded channel by channel.
    let far = far_sphere(Vec3::new(0.05, 0.2, 0.6));
    let camera = &far.scene.camera;
    let (stats, indices, bytes) = hearing_strips(|strips| {
        let target = RenderTarget {
            writes_depth: false,
            ..RenderTarget::new(camera, SMALL)
        };
        let shader = LitShader::new(&far.scene, camera);
        render_scene(&far, &[target], &shader, FrameOutput::Strips(strips), None)
    });
    assert_eq!(indices, every_strip(), "each strip once");
    let want = fresh(&far, SMALL);
    let expected: Vec<u8> = want.to_srgb8().into_iter().flatten().collect();
    assert!(bytes == expected, "the strips are the render's pixels");
    let covered = want.depth().iter().filter(|d| d.is_finite()).count();
    assert_eq!(stats.fragments, covered);
}

#[test]
fn passes_rendered_tile_by_tile_hand_on_each_strip_once_finished_as_srgb() {
    let far = far_sphere(Vec3::splat(0.1));
    let shader = LitShader::new(&far.scene, &far.scene.camera);
    let mask = scattered_mask(SMALL);
    for mask in [None, Some(&mask[..])] {
        let mut framebuffer = scribbled(SMALL);
        let ((), indices, bytes) = hearing_strips(|strips| {
            let passes = shifted_passes(&far, mask);
            let output = FrameOutput::FramebufferAndStrips(&mut framebuffer, strips);
            render_scene(&far, &passes, &shader, output, None);
        });
        assert_eq!(indices, every_strip(), "each strip once");
        let expected: Vec<u8> = framebuffer.to_srgb8().into_iter().flatten().collect();
        assert!(
            bytes == expected,
            "masked {}: not the finished pixels",
            mask.is_some()
        );
    }
}

/// The refinement's definition: a wanted pixel is refined when a channel of √colour moved by
/// more than `threshold` from before the group to after its first `from` passes.
fn refined_by_definition(
    before: &Framebuffer,
    after: &Framebuffer,
    wanted: Option<&[bool]>,
    threshold: f32,
) -> Vec<bool> {
    let key = |c: Vec3| c.max(Vec3::ZERO).to_array().map(f32::sqrt);
    (before.color().iter().zip(after.color()).enumerate())
        .map(|(i, (&b, &a))| {
            let moved = (0..3).any(|c| (key(a)[c] - key(b)[c]).abs() > threshold);
            wanted.is_none_or(|w| w[i]) && moved
        })
        .collect()
}

/// Settles the wanted pixels that are not refined by definition: `centre_weight` of their
/// colour `before` the group, the rest of what its first passes made of them (`after`).
fn settle_by_definition(
    before: &Framebuffer,
    after: &mut Framebuffer,
    settled: impl Fn(usize) -> bool,
    centre_weight: f32,
) {
    for (i, (after, &before)) in after.color_mut().iter_mut().zip(before.color()).enumerate() {
        if settled(i) {
            *after = *after * (1.0 - centre_weight) + before * centre_weight;
        }
    }
}

/// What the refinement tests keep of a settled pixel's colour before the group.
const CENTRE_WEIGHT: f32 = 0.3;

#[test]
fn refining_passes_render_only_the_moved_pixels_as_separate_passes_would() {
    let far = far_sphere(Vec3::splat(0.1));
    let shader = LitShader::new(&far.scene, &far.scene.camera);
    let mask = scattered_mask(SMALL);
    for mask in [None, Some(&mask[..])] {
        // The first two passes leave a quarter of a sample: the background (0.1) moves by 0.16 in
        // √colour, the lit sphere by more.
        for threshold in [-1.0, 0.16, f32::INFINITY] {
            let what = format!("masked {} at {threshold}", mask.is_some());
            let passes = shifted_passes(&far, mask);
            let before = rendered_once(&far);
            let mut want = before.clone();
            for pass in &passes[..2] {
                render_scene_pass(&far, pass, &shader, &mut want);
            }
            let expected = refined_by_definition(&before, &want, mask, threshold);
            let settled = |i: usize| mask.is_none_or(|m| m[i]) && !expected[i];
            settle_by_definition(&before, &mut want, settled, CENTRE_WEIGHT);
            for pass in &passes[2..] {
                let pass = RenderTarget {
                    mask: Some(&expected),
                    ..*pass
                };
                render_scene_pass(&far, &pass, &shader, &mut want);
            }
            let mut got = before.clone();
            let mut refined = vec![true; 3];
            let refinement = Refinement {
                rule: &RefineRule {
                    from_pass: 2,
                    threshold,
                    centre_weight: CENTRE_WEIGHT,
                },
                refined: &mut refined,
            };
            let output = FrameOutput::Framebuffer(&mut got);
            render_scene(&far, &passes, &shader, output, Some(refinement));
            assert!(refined == expected, "{what}: not the moved pixels");
            assert_same(&got, &want, &what);
            let count = expected.iter().filter(|&&r| r).count();
            let wanted = mask.map_or(expected.len(), |m| m.iter().filter(|&&w| w).count());
            match threshold {
                -1.0 => assert_eq!(count, wanted, "{what}"),
                0.16 => assert!(0 < count && count < wanted, "{what}: {count} of {wanted}"),
                _ => assert_eq!(count, 0, "{what}"),
            }
        }
    }
}
