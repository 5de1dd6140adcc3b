//! Bump mapping and textures as the renderer applies them: properties of whole frames.

use bumpwork::raster::{Framebuffer, RenderTarget, Viewport};
use bumpwork::render::render_lit;
use bumpwork::scene::PreparedScene;
use bumpwork::scene::{Light, Scene, parse_scene, preset};
use bumpwork::surface::Tessellation;
use glam::{DVec3, Vec3};

use crate::test_dir::TestDir;

fn frame(scene: Scene, width: u32, height: u32) -> (Framebuffer, bumpwork::raster::FrameStats) {
    let camera = scene.camera.clone();
    let prepared = PreparedScene::new(scene, Tessellation { density: 32 });
    let target = RenderTarget::new(&camera, Viewport { width, height });
    render_lit(&prepared, &target)
}

fn temp_dir(name: &str) -> TestDir {
    TestDir::new(&format!("bump-{name}"))
}

#[test]
fn strength_zero_renders_exactly_the_unbumped_image() {
    for name in [
        "sphere-on-plane-dimples",
        "cone-ripple",
        "plane-image-bump",
        "big-sphere-mesh",
    ] {
        let mut zero = preset(name).unwrap();
        let mut none = preset(name).unwrap();
        for (z, n) in zero.objects.iter_mut().zip(&mut none.objects) {
            if let Some(bump) = &mut z.material.bump {
                bump.strength = 0.0;
            }
            n.material.bump = None;
        }
        let (a, b) = (frame(zero, 96, 72).0, frame(none, 96, 72).0);
        let differing: Vec<_> = a
            .color()
            .iter()
            .zip(b.color())
            .enumerate()
            .filter(|(_, (x, y))| x != y)
            .take(3)
            .collect();
        assert!(
            differing.is_empty(),
            "{name}: strength 0 differs from no bump: {differing:?}"
        );
    }
}

/// The waffle plane lit by a directional light at 45° elevation and the given azimuth about the
/// plane's normal, without specular (which depends on the view too).
fn waffle_lit_from(azimuth_degrees: f64, bumped: bool) -> Framebuffer {
    let mut scene = preset("plane-waffle").unwrap();
    let a = azimuth_degrees.to_radians();
    scene.lights = vec![Light::Directional {
        towards: DVec3::new(a.cos(), a.sin(), 1.0).as_vec3(),
        color: Vec3::ONE,
    }];
    for object in &mut scene.objects {
        object.material.specular = 0.0;
        if !bumped {
            object.material.bump = None;
        }
    }
    frame(scene, 96, 96).0
}

fn mean_difference(a: &Framebuffer, b: &Framebuffer) -> f32 {
    let total: f32 = a
        .color()
        .iter()
        .zip(b.color())
        .map(|(x, y)| (*x - *y).abs().element_sum())
        .sum();
    total / a.color().len() as f32
}

#[test]
fn moving_the_light_around_the_normal_changes_a_bumped_plane_and_not_a_flat_one() {
    let flat = mean_difference(&waffle_lit_from(0.0, false), &waffle_lit_from(90.0, false));
    let bumped = mean_difference(&waffle_lit_from(0.0, true), &waffle_lit_from(90.0, true));
    assert!(flat < 1e-5, "the flat plane changed by {flat}");
    assert!(bumped > 0.01, "the bumped plane changed by only {bumped}");
}

fn scene_with_bump(
    dir: &std::path::Path,
    pattern_source: &str,
    bump_extra: &str,
) -> Result<Scene, String> {
    std::fs::write(dir.join("p.pat"), pattern_source).unwrap();
    let text = format!(
        "[camera]\neye = [200, 200, 700]\ntarget = [200, 200, 0]\nfov = 40\n\
         [[light]]\npoint = {{ position = [0, 400, 500] }}\n\
         [[object]]\nsurface = {{ plane = {{ origin = [0, 0, 0], normal = [0, 0, 1], u-axis = [1, 0, 0], size = [400, 400] }} }}\n\
         bump = {{ pattern = \"p.pat\"{bump_extra} }}\n"
    );
    let path = dir.join("scene.toml");
    std::fs::write(&path, &text).unwrap();
    bumpwork::scene::load_scene_file(&path).map_err(|e| e.to_string())
}

#[test]
fn a_pattern_that_divides_by_zero_is_drawn_flat_and_counted() {
    let dir = temp_dir("nan");
    let scene = scene_with_bump(&dir, "height = sqrt(u - 200) + 1 / (v - v)", "").unwrap();
    let (fb, stats) = frame(scene, 64, 64);
    assert!(fb.color().iter().all(|c| c.is_finite()));
    assert_eq!(
        stats.flattened, stats.fragments,
        "every fragment divides by zero"
    );
    let scene = scene_with_bump(&dir, "height = sqrt(u - 200)", "").unwrap();
    let (fb, stats) = frame(scene, 64, 64);
    assert!(fb.color().iter().all(|c| c.is_finite()));
    // The plane fills the view; the left half (u < 200) takes sqrt of a negative.
    let ratio = stats.flattened as f64 / stats.fragments as f64;
    assert!(
        (0.4..0.6).contains(&ratio),
        "flattened {} of {}",
        stats.flattened,
        stats.fragments
    );
}

#[test]
fn pattern_parameters_in_a_scene_are_checked_by_name_and_range() {
    let dir = temp_dir("params");
    let source = "param period = 30 in 5..100\nheight = sin(u / period)";
    assert!(scene_with_bump(&dir, source, ", params = { period = 50 }").is_ok());
    let unknown = scene_with_bump(&dir, source, ", params = { perod = 50 }").unwrap_err();
    assert!(
        unknown.contains("no parameter 'perod'") && unknown.contains("period"),
        "{unknown}"
    );
    let outside = scene_with_bump(&dir, source, ", params = { period = 500 }").unwrap_err();
    assert!(outside.contains("outside its range"), "{outside}");
    let broken = scene_with_bump(&dir, "height = sin(u", "").unwrap_err();
    assert!(
        broken.contains("p.pat:1:") && broken.contains('^'),
        "{broken}"
    );
}

#[test]
fn an_image_texture_shows_its_texels_where_the_mapping_puts_them() {
    let dir = temp_dir("texels");
    // 2×2 image: red, green / blue, white (top row first).
    let pixels: [u8; 12] = [255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255];
    let file = std::fs::File::create(dir.join("four.png")).unwrap();
    let mut encoder = png::Encoder::new(std::io::BufWriter::new(file), 2, 2);
    encoder.set_color(png::ColorType::Rgb);
    encoder
        .write_header()
        .unwrap()
        .write_image_data(&pixels)
        .unwrap();
    let text = "ambient = [1, 1, 1]\n[camera]\neye = [200, 200, 700]\ntarget = [200, 200, 0]\nfov = 40\n\
        [[object]]\nsurface = { plane = { origin = [0, 0, 0], normal = [0, 0, 1], u-axis = [1, 0, 0], size = [400, 400] } }\n\
        material = { specular = 0 }\ntexture = { image = \"four.png\", filter = \"nearest\" }\n";
    let path = dir.join("scene.toml");
    std::fs::write(&path, text).unwrap();
    let scene = bumpwork::scene::load_scene_file(&path).unwrap();
    let (fb, _) = frame(scene, 100, 100);
    let at = |x: usize, y: usize| fb.color()[y * 100 + x];
    // The plane is upright (v up), so the image's top row is at the top of the picture.
    let expect = [
        (30, 30, Vec3::X),
        (70, 30, Vec3::Y),
        (30, 70, Vec3::Z),
        (70, 70, Vec3::ONE),
    ];
    for (x, y, colour) in expect {
        assert!(
            (at(x, y) - colour).abs().max_element() < 1e-3,
            "({x}, {y}): {:?} vs {colour:?}",
            at(x, y)
        );
    }
}

#[test]
fn a_scene_with_a_missing_image_names_it() {
    let text = "[camera]\neye = [0, 0, 5]\ntarget = [0, 0, 0]\n[[object]]\n\
        surface = { sphere = { center = [0, 0, 0], radius = 1 } }\ntexture = { image = \"nowhere.png\", mapping = \"spherical\" }\n";
    let error = parse_scene(text, "s.toml").unwrap_err().to_string();
    assert!(
        error.contains("nowhere.png") && error.contains("object 1"),
        "{error}"
    );
}
