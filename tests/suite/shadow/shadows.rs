//! Shadows: no acne, no detached contact shadows, lights that cannot reach, and shadow
//! boundaries within a pixel of the reference's exact shadow rays.

use crate::common::render_with;
use bumpwork::quality::{Quality, ShadowEdges};
use bumpwork::raster::{Framebuffer, Viewport};
use bumpwork::scene::{Scene, parse_scene};
use bumpwork::shade::Showing;
use bumpwork::shadow::{ShadowMaps, ShadowSettings};
use glam::Vec3;
use std::sync::Arc;

const VIEW: Viewport = Viewport {
    width: 160,
    height: 120,
};

/// Ambient light of every test scene: a shadowed pixel is its colour times this.
const AMBIENT: f32 = 0.1;

/// A scene of a 20 × 20 floor (y = 0), the given objects and lights, seen from `eye`.
fn scene(eye: [f64; 3], target: [f64; 3], lights: &str, objects: &str) -> Scene {
    let text = format!(
        "ambient = [{AMBIENT}, {AMBIENT}, {AMBIENT}]\n\
         [camera]\neye = {eye:?}\ntarget = {target:?}\nfov = 40\n\
         {lights}\n\
         [[object]]\n\
         surface = {{ plane = {{ origin = [-10, 0, 10], normal = [0, 1, 0], u-axis = [1, 0, 0], size = [20, 20] }} }}\n\
         material = {{ color = [0.6, 0.6, 0.6], specular = 0 }}\n\
         {objects}"
    );
    parse_scene(&text, "test scene").unwrap()
}

fn point_light(at: [f64; 3]) -> String {
    format!("[[light]]\npoint = {{ position = {at:?}, color = [1, 1, 1] }}")
}

fn directional_light(towards: [f64; 3]) -> String {
    format!("[[light]]\ndirectional = {{ towards = {towards:?}, color = [1, 1, 1] }}")
}

fn sphere(center: [f64; 3], radius: f64) -> String {
    format!(
        "[[object]]\nsurface = {{ sphere = {{ center = {center:?}, radius = {radius} }} }}\n\
         material = {{ color = [0.8, 0.5, 0.3], specular = 0 }}"
    )
}

/// The resting sphere of most tests: radius 1, touching the floor at the origin.
fn resting_sphere() -> String {
    sphere([0.0, 1.0, 0.0], 1.0)
}

fn without_shadows(scene: &Scene) -> Scene {
    Scene {
        shadows: false,
        ..scene.clone()
    }
}

/// How the rasterizer's shadows are found.
#[derive(Clone, Copy, Debug)]
enum By {
    /// As the quality chooses: by exact rays alone where those cost less than maps (scenes of
    /// spheres, planes and triangles with exact edges).
    Choice,
    /// Through maps, as in a scene holding a surface that exact rays cost more for.
    Maps,
}

const BOTH_WAYS: [By; 2] = [By::Choice, By::Maps];

fn without_lights(scene: &Scene) -> Scene {
    Scene {
        lights: Vec::new(),
        ..scene.clone()
    }
}

/// The rasterizer's frame at `quality` (one sample a pixel).
fn raster(scene: &Scene, quality: &Quality) -> Framebuffer {
    raster_by(scene, quality, By::Choice)
}

/// The rasterizer's frame at `quality`, its shadows found `by`.
fn raster_by(scene: &Scene, quality: &Quality, by: By) -> Framebuffer {
    let camera = &scene.camera;
    let prepared = quality.prepare(scene.clone(), camera, VIEW, 0).unwrap();
    let settings = ShadowSettings {
        rays_where_cheaper: matches!(by, By::Choice),
        ..quality.shadow_settings()
    };
    let maps = ShadowMaps::build(&prepared, camera, VIEW, settings).map(Arc::new);
    let shader = quality.shader_with_maps(&prepared, camera, maps, Showing::default());
    render_with(&prepared, &quality.target(camera, VIEW), &shader).0
}

/// The reference's frame: exact surfaces and exact shadow rays.
fn reference(scene: &Scene) -> Framebuffer {
    crate::reference::support::exact_frame(scene, VIEW)
}

/// Per pixel: of the light that would reach it without shadows, the fraction that does, from
/// `render`'s frames of the scene with shadows, without, and without lights; and the depth seen
/// there. `None` where the lights add almost nothing or nothing is drawn.
fn light_fractions(
    scene: &Scene,
    render: impl Fn(&Scene) -> Framebuffer,
) -> Vec<Option<(f32, f32)>> {
    let dark = without_lights(scene);
    let (on, off, ambient) = (
        render(scene),
        render(&without_shadows(scene)),
        render(&dark),
    );
    on.color()
        .iter()
        .zip(off.color())
        .zip(ambient.color())
        .zip(off.depth())
        .map(|(((on, off), ambient), &depth)| {
            let light = (*off - *ambient).max_element();
            let reached = (*on - *ambient).max_element();
            let fraction = (reached / light).clamp(0.0, 1.0);
            (depth.is_finite() && light > 0.02).then_some((fraction, depth))
        })
        .collect()
}

/// Which pixels are in shadow (less than half the light reaches them), and their depth.
fn shadowed(fractions: &[Option<(f32, f32)>]) -> Vec<Option<(bool, f32)>> {
    fractions
        .iter()
        .map(|f| f.map(|(fraction, depth)| (fraction < 0.5, depth)))
        .collect()
}

/// Pixels where `ours` says otherwise than `exact` with no pixel of `exact` within one pixel
/// (8-neighbourhood) saying as `ours` does: boundary misplacements of more than a pixel. Only
/// pixels where both see the same surface (depths within 1 %) are compared: where the mesh's
/// outline and the true one part, they see different things, which is the tessellation's error.
fn misplaced(ours: &[Option<(bool, f32)>], exact: &[Option<(bool, f32)>]) -> Vec<(u32, u32)> {
    let (w, h) = (VIEW.width as i64, VIEW.height as i64);
    let at = |x: i64, y: i64| exact[(y * w + x) as usize].map(|(s, _)| s);
    let mut out = Vec::new();
    for y in 1..h - 1 {
        for x in 1..w - 1 {
            let i = (y * w + x) as usize;
            let (Some((mine, near_depth)), Some((theirs, depth))) = (ours[i], exact[i]) else {
                continue;
            };
            if (near_depth - depth).abs() > 0.01 * depth {
                continue;
            }
            let around = (-1..=1).flat_map(|dy| (-1..=1).map(move |dx| (dx, dy)));
            let agreed = around
                .into_iter()
                .any(|(dx, dy)| at(x + dx, y + dy) == Some(mine));
            if mine != theirs && !agreed {
                out.push((x as u32, y as u32));
            }
        }
    }
    out
}

/// The raster's (at `quality`, its shadows found `by`) and the reference's shadows of `scene`,
/// compared pixel by pixel: returns how many pixels the reference says are in shadow, after
/// asserting every difference lies on its boundary.
fn assert_boundary_within_a_pixel(scene: &Scene, quality: &Quality, by: By, what: &str) -> usize {
    let ours = light_fractions(scene, |s| raster_by(s, quality, by));
    let exact = light_fractions(scene, reference);
    let wrong = misplaced(&shadowed(&ours), &shadowed(&exact));
    let in_shadow = shadowed(&exact)
        .iter()
        .flatten()
        .filter(|(s, _)| *s)
        .count();
    let shown: Vec<String> = wrong
        .iter()
        .take(6)
        .map(|&(x, y)| {
            let i = (y * VIEW.width + x) as usize;
            format!("({x},{y}) {:?} vs exact {:?}", ours[i], exact[i])
        })
        .collect();
    assert!(
        wrong.is_empty(),
        "{what} by {by:?}: {} pixels more than a pixel from the exact shadow boundary (of {in_shadow} in \
         shadow): (fraction, depth) {shown:?}",
        wrong.len(),
    );
    in_shadow
}

#[test]
fn a_plane_lit_at_a_grazing_angle_is_nowhere_darker_than_without_shadows() {
    // The sphere is below the floor: it can shadow nothing the camera sees, so every pixel of
    // the floor must keep all its light, however low the light.
    for elevation in [1.0f64, 3.0, 10.0, 30.0] {
        let (s, c) = elevation.to_radians().sin_cos();
        for lights in [
            directional_light([c, s, 0.3]),
            point_light([-30.0 * c, 30.0 * s, -4.0]),
        ] {
            let scene = scene(
                [0.0, 4.0, 9.0],
                [0.0, 0.0, 0.0],
                &lights,
                &sphere([0.0, -3.0, 0.0], 1.0),
            );
            for quality in [Quality::draft(), Quality::interactive(), Quality::high()] {
                let without = raster(&without_shadows(&scene), &quality);
                for by in BOTH_WAYS {
                    let with = raster_by(&scene, &quality, by);
                    let darker = with
                        .color()
                        .iter()
                        .zip(without.color())
                        .filter(|(a, b)| a.x < b.x - 1e-6)
                        .count();
                    assert_eq!(
                        darker, 0,
                        "{darker} pixels acne at {elevation}° ({lights}) by {by:?}"
                    );
                }
            }
        }
    }
}

#[test]
fn a_resting_spheres_shadow_reaches_its_contact_with_the_floor() {
    // Lit from behind and above, the sphere throws its shadow towards the camera. Down each
    // column through the sphere, wherever the exact shadow touches the sphere's outline (the
    // first floor pixel below it is in shadow), the rasterizer's does too: no lit gap between
    // a shadow and its caster. (Not at `draft`: its 16-cell sphere is a cone near the floor,
    // whose shadow stops short of the true sphere's.)
    for lights in [
        directional_light([0.0, 1.0, -1.5]),
        point_light([0.0, 6.0, -8.0]),
    ] {
        let scene = scene([0.0, 2.5, 7.0], [0.0, 0.5, 0.0], &lights, &resting_sphere());
        let exact_frame = reference(&scene);
        let exact = shadowed(&light_fractions(&scene, reference));
        let sphere_pixel = |x: u32, y: u32| {
            let i = (y * VIEW.width + x) as usize;
            let c = exact_frame.color()[i];
            exact_frame.depth()[i].is_finite() && (c.x - c.y).abs() > 1e-3
        };
        let touching: Vec<usize> = (0..VIEW.width)
            .filter_map(|x| {
                let bottom = (0..VIEW.height - 1).rev().find(|&y| sphere_pixel(x, y))?;
                let below = ((bottom + 1) * VIEW.width + x) as usize;
                exact[below].is_some_and(|(dark, _)| dark).then_some(below)
            })
            .collect();
        assert!(
            touching.len() > 20,
            "{lights}: the shadow touches the sphere in {} columns",
            touching.len()
        );
        for quality in [Quality::interactive(), Quality::high()] {
            for by in BOTH_WAYS {
                let in_shadow = assert_boundary_within_a_pixel(&scene, &quality, by, &lights);
                assert!(in_shadow > 200, "the shadow is seen: {in_shadow} pixels");
                let ours = shadowed(&light_fractions(&scene, |s| raster_by(s, &quality, by)));
                for &i in &touching {
                    let (x, y) = (i as u32 % VIEW.width, i as u32 / VIEW.width);
                    let gap = ours[i].is_some_and(|(dark, _)| !dark);
                    assert!(
                        !gap,
                        "{lights}: a lit gap under the sphere at {x},{y} at {} by {by:?}",
                        quality.describe()
                    );
                }
            }
        }
    }
}

#[test]
fn the_shadow_boundary_is_within_a_pixel_of_the_exact_one_at_high() {
    let cases = [
        (
            directional_light([0.6, 1.0, 0.3]),
            "directional from the side",
        ),
        (point_light([-4.0, 6.0, 5.0]), "point light in front"),
        (point_light([3.0, 3.0, -1.0]), "low point light"),
    ];
    for (lights, what) in cases {
        let objects = format!("{}\n{}", resting_sphere(), sphere([2.2, 0.6, 0.8], 0.6));
        let scene = scene([0.0, 3.0, 8.0], [0.5, 0.6, 0.0], &lights, &objects);
        for by in BOTH_WAYS {
            let in_shadow = assert_boundary_within_a_pixel(&scene, &Quality::high(), by, what);
            assert!(in_shadow > 300, "{what}: {in_shadow} pixels in shadow");
        }
    }
}

#[test]
fn a_hovering_square_and_triangle_cast_shadows_within_a_pixel_of_the_exact_ones() {
    let objects = "[[object]]\nsurface = { plane = { origin = [-2.5, 1.5, 1.5], normal = [0, 1, 0], \
                   u-axis = [1, 0, 0], size = [1.2, 1.2] } }\n\
                   [[object]]\nsurface = { triangle = { a = [1, 1.2, 1], b = [2.5, 1.4, 1.2], \
                   c = [1.8, 1.0, -0.5] } }";
    for (lights, what) in [
        (directional_light([0.6, 1.0, 0.3]), "directional"),
        (point_light([-1.0, 5.0, 3.0]), "point light"),
    ] {
        let scene = scene([0.0, 3.0, 8.0], [0.0, 0.6, 0.0], &lights, objects);
        for by in BOTH_WAYS {
            let in_shadow = assert_boundary_within_a_pixel(&scene, &Quality::high(), by, what);
            assert!(in_shadow > 200, "{what}: {in_shadow} pixels in shadow");
        }
    }
}

#[test]
fn exact_shadow_edges_shadow_the_very_pixels_the_exact_shadow_rays_do_at_interactive() {
    let objects = format!("{}\n{}", resting_sphere(), sphere([2.2, 0.6, 0.8], 0.6));
    for (lights, what) in [
        (directional_light([0.6, 1.0, 0.3]), "directional"),
        (point_light([3.0, 3.0, -1.0]), "low point light"),
    ] {
        let scene = scene([0.0, 3.0, 8.0], [0.5, 0.6, 0.0], &lights, &objects);
        // Pixels where a tenth of the light or more reaches one frame and not the other.
        let exact = light_fractions(&scene, reference);
        let differ = |quality: &Quality, by: By| {
            let ours = light_fractions(&scene, |s| raster_by(s, quality, by));
            let apart = |a: &Option<(f32, f32)>, b: &Option<(f32, f32)>| match (a, b) {
                (Some(a), Some(b)) => (a.0 - b.0).abs() > 0.1,
                (a, b) => a.is_some() != b.is_some(),
            };
            ours.iter().zip(&exact).filter(|(a, b)| apart(a, b)).count()
        };
        // A coarse map, whose filtered edges are texels wide: the rays must settle all of them.
        let rays = Quality {
            shadow_map: 128,
            ..Quality::interactive()
        };
        let filtered = Quality {
            shadow_edges: ShadowEdges::Filtered,
            ..rays
        };
        let (with_rays, with_filter) = (differ(&rays, By::Maps), differ(&filtered, By::Maps));
        let rays_alone = differ(&rays, By::Choice);
        eprintln!(
            "{what}: {with_rays} pixels differ ({with_filter} with filtered edges, {rays_alone} \
             with rays alone)"
        );
        assert!(
            with_rays <= 2,
            "{what}: {with_rays} pixels shadowed otherwise than exactly"
        );
        // Rays alone are the reference's shadow rays, so whatever pixels differ differ for
        // another reason (the maps' run found it too).
        assert!(
            rays_alone <= with_rays,
            "{what}: rays alone differ in {rays_alone}, more than maps with exact edges"
        );
        assert!(
            with_filter > 10,
            "{what}: the filter alone differs in only {with_filter}"
        );
    }
}

#[test]
fn a_light_below_the_floor_lights_nothing_above_it() {
    for lights in [
        point_light([0.5, -2.0, 1.0]),
        directional_light([0.2, -1.0, 0.1]),
    ] {
        let scene = scene([0.0, 3.0, 8.0], [0.0, 0.7, 0.0], &lights, &resting_sphere());
        let dark = without_lights(&scene);
        let ambient = raster(&dark, &Quality::interactive());
        for by in BOTH_WAYS {
            let lit = raster_by(&scene, &Quality::interactive(), by);
            // Brighter by no 8-bit step: the filter's taps at the sphere's terminator, where the
            // light grazes it, may let through a few thousandths of it.
            let srgb = |c: &Vec3| c.to_array().map(bumpwork::raster::linear_to_srgb8);
            let brighter = lit
                .color()
                .iter()
                .zip(ambient.color())
                .filter(|(a, b)| srgb(a) != srgb(b))
                .count();
            assert_eq!(
                brighter, 0,
                "{lights} by {by:?}: {brighter} pixels see the light through the floor"
            );
        }
        // Without shadows the sphere's underside would be lit (it faces the light).
        let through = raster(&without_shadows(&scene), &Quality::interactive());
        assert!(
            through.color() != ambient.color(),
            "{lights}: the test sees the sphere's underside"
        );
    }
}

#[test]
fn inside_a_dome_a_light_within_casts_the_exact_shadows_and_one_without_lights_nothing() {
    // The camera, the floor and a resting sphere inside a sphere of radius 15: seen from
    // within, the dome can stand between its own inside and the light.
    let objects = format!("{}\n{}", resting_sphere(), sphere([0.0, 0.0, 0.0], 15.0));
    let within = scene(
        [0.0, 3.0, 8.0],
        [0.0, 1.0, 0.0],
        &point_light([-3.0, 6.0, 2.0]),
        &objects,
    );
    for by in BOTH_WAYS {
        let in_shadow =
            assert_boundary_within_a_pixel(&within, &Quality::interactive(), by, "light within");
        assert!(in_shadow > 100, "{in_shadow} pixels in shadow");
    }
    let without = scene(
        [0.0, 3.0, 8.0],
        [0.0, 1.0, 0.0],
        &point_light([2.0, 40.0, 1.0]),
        &objects,
    );
    let dark = without_lights(&within);
    let ambient = raster(&dark, &Quality::interactive());
    for by in BOTH_WAYS {
        let lit = raster_by(&without, &Quality::interactive(), by);
        let brighter = (lit.color().iter().zip(ambient.color()))
            .filter(|(a, b)| a.max_element() > b.max_element() + 1e-4)
            .count();
        assert_eq!(
            brighter, 0,
            "{brighter} pixels lit through the dome by {by:?}"
        );
    }
}

#[test]
fn a_light_behind_the_camera_casts_the_exact_shadows() {
    let scene = scene(
        [0.0, 3.0, 8.0],
        [0.0, 0.7, 0.0],
        &point_light([-5.0, 4.0, 13.0]),
        &resting_sphere(),
    );
    for by in BOTH_WAYS {
        let in_shadow =
            assert_boundary_within_a_pixel(&scene, &Quality::high(), by, "behind the camera");
        assert!(in_shadow > 100, "{in_shadow} pixels in shadow");
    }
}

#[test]
fn a_point_light_inside_a_bowl_lights_all_of_its_inside_and_none_of_its_outside() {
    // A paraboloid alone: a point light inside it sees its whole inside (the inside of a
    // paraboloid is convex), while its outside faces away.
    let text = format!(
        "ambient = [{AMBIENT}, {AMBIENT}, {AMBIENT}]\n\
         [camera]\neye = [0, 5, 9]\ntarget = [0, 1, 0]\nfov = 40\n\
         {}\n\
         [[object]]\n\
         surface = {{ paraboloid = {{ apex = [0, 0, 0], curvature = 0.5, radius = 2 }} }}\n\
         material = {{ color = [0.6, 0.6, 0.6], specular = 0 }}",
        point_light([0.3, 1.0, 0.2])
    );
    let scene = parse_scene(&text, "bowl").unwrap();
    for quality in [Quality::draft(), Quality::interactive(), Quality::high()] {
        let fractions = light_fractions(&scene, |s| raster(s, &quality));
        let lit: Vec<f32> = fractions.iter().flatten().map(|(f, _)| *f).collect();
        assert!(lit.len() > 1000, "{} pixels the light reaches", lit.len());
        let worst = lit.iter().copied().fold(1.0, f32::min);
        assert!(
            worst > 0.999,
            "a pixel of the inside gets {worst} of the light"
        );
    }
    assert_boundary_within_a_pixel(&scene, &Quality::interactive(), By::Choice, "inside a bowl");
}

#[test]
fn a_sphere_lit_from_behind_darkens_the_floor_before_it_to_ambient_and_changes_nothing_else() {
    let scene = scene(
        [0.0, 2.0, 8.0],
        [0.0, 0.8, 0.0],
        &directional_light([0.0, 0.8, -1.0]),
        &resting_sphere(),
    );
    let quality = Quality::interactive();
    let without = raster(&without_shadows(&scene), &quality);
    let exact = shadowed(&light_fractions(&scene, reference));
    let (w, h) = (VIEW.width as i64, VIEW.height as i64);
    let near_exact_shadow = |x: i64, y: i64| {
        (-1..=1).any(|dy: i64| {
            (-1..=1).any(|dx: i64| {
                let (x, y) = ((x + dx).clamp(0, w - 1), (y + dy).clamp(0, h - 1));
                exact[(y * w + x) as usize].is_some_and(|(s, _)| s)
            })
        })
    };
    let floor_ambient = Vec3::splat(0.6 * AMBIENT);
    for by in BOTH_WAYS {
        let with = raster_by(&scene, &quality, by);
        let (mut changed, mut at_ambient) = (0, 0);
        for y in 0..h {
            for x in 0..w {
                let i = (y * w + x) as usize;
                let (a, b) = (with.color()[i], without.color()[i]);
                if a == b {
                    continue;
                }
                changed += 1;
                assert!(
                    near_exact_shadow(x, y),
                    "pixel {x},{y} changed outside the shadow by {by:?}: {a} vs {b}"
                );
                assert!(a.x < b.x, "pixel {x},{y} brighter with shadows by {by:?}");
                if (a - floor_ambient).abs().max_element() < 1e-5 {
                    at_ambient += 1;
                }
            }
        }
        assert!(changed > 300, "{changed} pixels in shadow by {by:?}");
        // Inside the shadow, all but its edge is at the ambient level exactly.
        assert!(
            at_ambient as f64 > 0.7 * changed as f64,
            "{at_ambient} of {changed} at ambient by {by:?}"
        );
    }
}

#[test]
fn spheres_and_planes_with_exact_edges_draw_no_map_and_a_cone_brings_the_maps_back() {
    let objects = format!("{}\n{}", resting_sphere(), sphere([2.2, 0.6, 0.8], 0.6));
    let cone = "[[object]]\nsurface = { cone = { apex = [-3, 1, -2], axis = [0, -1, 0], \
                half-angle = 25, height = 1 } }";
    let maps_drawn = |objects: &str, quality: &Quality| {
        let scene = scene(
            [0.0, 3.0, 8.0],
            [0.5, 0.6, 0.0],
            &point_light([3.0, 3.0, -1.0]),
            objects,
        );
        let camera = &scene.camera;
        let prepared = quality.prepare(scene.clone(), camera, VIEW, 0).unwrap();
        let maps = ShadowMaps::build(&prepared, camera, VIEW, quality.shadow_settings());
        maps.expect("the spheres shadow the floor").maps_drawn()
    };
    for quality in [Quality::interactive(), Quality::high()] {
        assert_eq!(maps_drawn(&objects, &quality), 0, "{}", quality.describe());
        let with_cone = format!("{objects}\n{cone}");
        assert!(
            maps_drawn(&with_cone, &quality) > 0,
            "{}",
            quality.describe()
        );
    }
    // Filtered edges keep the maps' soft edges.
    assert!(maps_drawn(&objects, &Quality::draft()) > 0);
}

#[test]
fn one_convex_object_alone_makes_no_shadow_maps() {
    let text = "[camera]\neye = [0, 0, 6]\ntarget = [0, 0, 0]\n\
                [[light]]\npoint = { position = [2, 3, 4] }\n\
                [[object]]\nsurface = { sphere = { center = [0, 0, 0], radius = 1 } }";
    let scene = parse_scene(text, "sphere").unwrap();
    let quality = Quality::interactive();
    let prepared = quality
        .prepare(scene.clone(), &scene.camera, VIEW, 0)
        .unwrap();
    assert!(
        quality
            .shader(&prepared, &scene.camera, VIEW)
            .shadows
            .is_none()
    );
    let two = parse_scene(&format!("{text}\n{}", sphere([3.0, 0.0, 0.0], 1.0)), "two").unwrap();
    let prepared = quality.prepare(two.clone(), &two.camera, VIEW, 0).unwrap();
    assert!(
        quality
            .shader(&prepared, &two.camera, VIEW)
            .shadows
            .is_some()
    );
    let off = without_shadows(&two);
    let prepared = quality.prepare(off.clone(), &off.camera, VIEW, 0).unwrap();
    assert!(
        quality
            .shader(&prepared, &off.camera, VIEW)
            .shadows
            .is_none()
    );
}

#[test]
fn a_lone_sphere_seen_from_within_is_dark_inside_where_the_light_is_outside() {
    let text = "ambient = [0.1, 0.1, 0.1]\n[camera]\neye = [0, 0, 2]\ntarget = [0, 0, -5]\n\
                [[light]]\npoint = { position = [0, 20, -10] }\n\
                [[object]]\nsurface = { sphere = { center = [0, 0, 0], radius = 10 } }";
    let scene = parse_scene(text, "dome").unwrap();
    let dark = without_lights(&scene);
    let ambient = raster(&dark, &Quality::interactive());
    let lit_pixels = |frame: &Framebuffer| {
        (frame.color().iter().zip(ambient.color()))
            .filter(|(a, b)| a.max_element() > b.max_element() + 1e-4)
            .count()
    };
    let unshadowed = lit_pixels(&raster(&without_shadows(&scene), &Quality::interactive()));
    assert!(
        unshadowed > 1000,
        "the light faces the inside it cannot reach"
    );
    assert_eq!(lit_pixels(&reference(&scene)), 0, "the reference");
    for by in BOTH_WAYS {
        let lit = lit_pixels(&raster_by(&scene, &Quality::interactive(), by));
        assert_eq!(lit, 0, "{lit} pixels lit by {by:?}");
    }
    // Filtered edges (a map alone) may leak along the band where the light grazes the dome.
    let lit = lit_pixels(&raster(&scene, &Quality::draft()));
    assert!(
        lit * 100 < unshadowed,
        "{lit} of {unshadowed} pixels lit at draft"
    );
}

#[test]
fn a_scene_file_a_setting_and_a_recipe_each_turn_shadows_off() {
    use crate::cli_support::{bumpwork, decode_png, stderr, temp_dir};
    let dir = temp_dir("shadows-off");
    let render = |name: &str, args: &[&str]| {
        let path = dir.join(name);
        let size = ["--size", "96x72", "-o", path.to_str().unwrap()];
        let out = bumpwork(&[&["render"][..], args, &size].concat());
        assert!(out.status.success(), "{}", stderr(&out));
        decode_png(&path).2
    };
    let still = |name: &str, extra: &[&str]| {
        render(name, &[&["sphere-on-plane-squares"][..], extra].concat())
    };
    let shadowed = still("on.png", &[]);
    let flat = still("off.png", &["--set", "shadows=false"]);
    assert_ne!(shadowed, flat, "the shadow shows");
    // A shadow only darkens.
    assert!(shadowed.iter().zip(&flat).all(|(on, off)| on <= off));
    // The recipe keeps the setting.
    let from = dir.join("off.png");
    assert_eq!(
        render("again.png", &["--from", from.to_str().unwrap()]),
        flat
    );
    // So does a scene file's own `shadows = false`.
    let text = bumpwork::scene::preset_file("sphere-on-plane-squares")
        .unwrap()
        .to_toml();
    assert!(parse_scene(&text, "on").unwrap().shadows, "on unless said");
    let file = dir.join("off.toml");
    std::fs::write(&file, format!("shadows = false\n{text}")).unwrap();
    assert_eq!(render("file.png", &[file.to_str().unwrap()]), flat);
}

#[test]
fn the_workbenchs_shadows_follow_the_light_keys_and_s_turns_them_off() {
    use bumpwork::term::{ColorChoice, ColorMode};
    use bumpwork::tui::{Action, App, WorkbenchOptions, render_frame};
    let options = WorkbenchOptions {
        scenes: vec!["sphere-on-plane-squares".into()],
        colors: ColorChoice::Fixed(ColorMode::TrueColor),
        ..WorkbenchOptions::default()
    };
    let mut app = App::new(&options, ColorMode::TrueColor).unwrap();
    let frame = |app: &App| {
        let mut framebuffer = Framebuffer::new(0, 0, Vec3::ZERO);
        render_frame(&app.view(), 120, 90, &mut framebuffer);
        framebuffer.color().to_vec()
    };
    let first = frame(&app);
    assert_eq!(frame(&app), first, "the kept maps draw the same picture");
    app.apply(Action::MoveLight(30.0, 0.0));
    let moved = frame(&app);
    assert_ne!(moved, first, "the light and its shadow moved");
    app.apply(Action::ToggleShadows);
    assert!(!app.scene().shadows);
    let flat = frame(&app);
    let darker = |a: &[Vec3], b: &[Vec3]| a.iter().zip(b).filter(|(p, q)| p.x < q.x - 1e-4).count();
    assert!(
        darker(&moved, &flat) > 50,
        "the shadow is gone without shadows"
    );
    assert_eq!(darker(&flat, &moved), 0, "and nothing else darkened");
    app.apply(Action::ToggleShadows);
    assert_eq!(frame(&app), moved, "back on, the same shadows");
}
