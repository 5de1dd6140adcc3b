//! True displacement: the new surface P + B·n drawn, beside Blinn's bump on the unmoved surface.

use crate::test_dir::TestDir;
use bumpwork::quality::Quality;
use bumpwork::raster::{Framebuffer, Viewport};
use bumpwork::reference::metrics::psnr;
use bumpwork::reference::render_reference;
use bumpwork::render::{frame, render_with};
use bumpwork::scene::{Scene, parse_scene_in};
use bumpwork::shade::Showing;

const VIEW: Viewport = Viewport {
    width: 96,
    height: 72,
};

/// A sphere of radius 100 (or a lone plane) bumped by `height` (a pattern's body) at
/// `strength`, displaced or not, lit by one point light and seen from 420 units.
fn scene(dir: &TestDir, height: &str, strength: f32, displace: bool) -> Scene {
    std::fs::write(dir.join("h.pat"), height).unwrap();
    let text = format!(
        r#"
        name = "displaced"
        background = [0, 0, 0]
        ambient = [0.05, 0.05, 0.05]
        [camera]
        eye = [0, 0, 420]
        target = [0, 0, 0]
        up = [0, 1, 0]
        fov = 36
        [[light]]
        point = {{ position = [-300, 400, 500], color = [1, 1, 1] }}
        [[object]]
        surface = {{ sphere = {{ center = [0, 0, 0], radius = 100 }} }}
        material = {{ color = [0.8, 0.5, 0.3] }}
        bump = {{ pattern = "h.pat", strength = {strength} }}
        displace = {displace}
        "#
    );
    parse_scene_in(&text, "test", dir).expect("a valid scene")
}

fn render(scene: &Scene, quality: &Quality) -> Framebuffer {
    frame(scene, quality, VIEW, Showing::default()).unwrap().0
}

fn covered(fb: &Framebuffer) -> usize {
    fb.depth().iter().filter(|d| d.is_finite()).count()
}

fn sphere_of_radius(dir: &TestDir, radius: f32) -> Scene {
    let mut scene = scene(dir, "height = 0", 1.0, false);
    if let bumpwork::surface::Surface::Sphere(sphere) = &mut scene.objects[0].surface {
        sphere.radius = radius;
    }
    scene
}

#[test]
fn a_constant_height_grows_the_outline_as_a_larger_sphere_and_blinns_bump_does_not() {
    let dir = TestDir::new("displaced-outline");
    let quality = Quality::interactive();
    let displaced = covered(&render(&scene(&dir, "height = 10", 1.0, true), &quality));
    let bumped = covered(&render(&scene(&dir, "height = 10", 1.0, false), &quality));
    let plain = covered(&render(&sphere_of_radius(&dir, 100.0), &quality));
    let larger = covered(&render(&sphere_of_radius(&dir, 110.0), &quality));
    assert_eq!(
        bumped, plain,
        "Blinn's bump leaves the outline where it was"
    );
    let perimeter = (4.0 * std::f64::consts::PI * larger as f64).sqrt();
    let off = displaced.abs_diff(larger) as f64;
    assert!(
        off <= 0.05 * perimeter,
        "displaced by 10: {displaced} pixels; a sphere of radius 110: {larger} ({off} apart)"
    );
}

#[test]
fn as_the_strength_falls_displacement_and_the_full_bumped_normal_converge() {
    let dir = TestDir::new("displaced-converge");
    let quality = Quality::interactive();
    let pattern = "height = sin(u * 0.25) * sin(v * 0.25)";
    let agreement: Vec<f64> = [8.0, 2.0, 0.5]
        .iter()
        .map(|&strength| {
            let displaced = render(&scene(&dir, pattern, strength, true), &quality);
            let bumped = render(&scene(&dir, pattern, strength, false), &quality);
            psnr(&displaced, &bumped)
        })
        .collect();
    assert!(
        agreement.windows(2).all(|w| w[1] > w[0] + 3.0),
        "PSNR against the bump as B falls: {agreement:?}"
    );
    assert!(agreement[2] > 35.0, "at strength 0.5: {agreement:?}");
}

#[test]
fn displaced_renders_agree_with_the_exact_judge() {
    let dir = TestDir::new("displaced-judge");
    let scene = scene(&dir, "height = 3 * sin(u * 0.2) * sin(v * 0.2)", 1.0, true);
    let quality = Quality::interactive();
    let camera = &scene.camera;
    let prepared = quality.prepare(scene.clone(), camera, VIEW, 0).unwrap();
    let shader = quality.shader(&prepared, camera, VIEW);
    let raster = render_with(&prepared, &quality.target(camera, VIEW), &shader).0;
    let reference = render_reference(&prepared, camera, VIEW, &shader).0;
    let agreement = psnr(&raster, &reference);
    assert!(
        agreement > 30.0,
        "{agreement:.1} dB against the ray search on P'"
    );
}

/// A lone plane seen from above with deep round pits, lit from low on one side.
fn pitted_floor(dir: &TestDir, displace: bool, shadows: bool) -> Scene {
    std::fs::write(
        dir.join("pits.pat"),
        "let cu = u % 40 - 20\nlet cv = v % 40 - 20\nlet r2 = cu^2 + cv^2\n\
         height = if r2 < 196 then -12 * (1 - r2 / 196) else 0\n",
    )
    .unwrap();
    let text = format!(
        r#"
        name = "pits"
        background = [0, 0, 0]
        ambient = [0.02, 0.02, 0.02]
        shadows = {shadows}
        [camera]
        eye = [0, 300, 120]
        target = [0, 0, 0]
        up = [0, 1, 0]
        fov = 40
        [[light]]
        directional = {{ towards = [-1, 0.35, 0], color = [1, 1, 1] }}
        [[object]]
        surface = {{ plane = {{ origin = [-200, 0, 200], normal = [0, 1, 0], u-axis = [1, 0, 0], size = [400, 400] }} }}
        material = {{ color = [0.7, 0.7, 0.7] }}
        bump = {{ pattern = "pits.pat", strength = 1 }}
        displace = {displace}
        "#
    );
    parse_scene_in(&text, "test", dir).expect("a valid scene")
}

#[test]
fn pits_shadow_their_own_floors_only_when_displaced() {
    let dir = TestDir::new("displaced-shadows");
    let quality = Quality::draft();
    let darker = |displace: bool| {
        let lit = render(&pitted_floor(&dir, displace, false), &quality);
        let shadowed = render(&pitted_floor(&dir, displace, true), &quality);
        let pairs = lit.color().iter().zip(shadowed.color());
        pairs.filter(|(a, b)| b.length() < 0.5 * a.length()).count()
    };
    assert_eq!(
        darker(false),
        0,
        "Blinn's bump casts no shadow on its own plane"
    );
    let shadowed = darker(true);
    assert!(
        shadowed > 100,
        "{shadowed} of {} pixels in the pits' own shadows",
        VIEW.width * VIEW.height
    );
}

#[test]
fn heights_past_the_radius_are_refused_in_one_line_and_drawn_as_blinns_bump() {
    let dir = TestDir::new("displaced-refused");
    let scene = scene(&dir, "height = sin(u * 0.25) * sin(v * 0.25)", 1e6, true);
    let quality = Quality::draft();
    let prepared = quality
        .prepare(scene.clone(), &scene.camera, VIEW, 0)
        .unwrap();
    assert_eq!(prepared.notices.len(), 1, "{:?}", prepared.notices);
    assert!(
        prepared.notices[0].contains("past the sphere's radius"),
        "{}",
        prepared.notices[0]
    );
    let surface = &prepared.objects[0].surface;
    assert!(matches!(surface, bumpwork::surface::Surface::Sphere(_)));
    assert!(
        prepared.objects[0].material.bump.is_some(),
        "the bump stays"
    );
}

#[test]
fn a_height_with_no_value_leaves_the_surface_where_it_was_and_nothing_is_nan() {
    let dir = TestDir::new("displaced-nan");
    let frame = render(
        &scene(&dir, "height = sqrt(u - 200)", 1.0, true),
        &Quality::interactive(),
    );
    assert!(frame.color().iter().all(|c| c.is_finite()));
    assert!(covered(&frame) > 1000, "the sphere is drawn");
}

#[test]
fn a_moving_height_is_cut_at_the_moment_each_still_shows() {
    use bumpwork::still::{ResolveFilter, StillSettings};
    let dir = TestDir::new("displaced-moving");
    let scene = scene(&dir, "height = 4 * sin(u * 0.25 + 3 * t)", 1.0, true);
    let at = |time: f64| StillSettings {
        size: (VIEW.width, VIEW.height),
        quality: Quality::draft(),
        resolve: ResolveFilter::default(),
        time,
        mode: bumpwork::shade::ShaderMode::Shaded,
    };
    let shape = |time: f64| {
        let prepared = at(time).prepare(scene.clone(), &scene.camera).unwrap();
        assert_eq!(prepared.scene.time, time, "the scene at the still's moment");
        prepared.objects[0].mesh.positions.clone()
    };
    let (now, later) = (shape(0.0), shape(0.5));
    let moved = now
        .iter()
        .zip(&later)
        .filter(|(a, b)| a.distance(**b) > 0.1)
        .count();
    assert!(
        moved > now.len() / 4,
        "{moved} of {} vertices moved",
        now.len()
    );
}
