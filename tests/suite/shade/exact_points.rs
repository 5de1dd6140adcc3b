//! Shading at the true surface point: every fragment of a sphere, cone or paraboloid is moved
//! to where its own ray meets the analytic surface (within 1e-5 of a pattern period of the
//! reference's f64 intersection), the wave's Newton steps settle or give up (counted), and
//! nothing is NaN at poles, apexes, seams or silhouettes; exact coverage shows, pixel by pixel,
//! the object (or background) the reference's exact rays meet first.

use crate::common::render_with;
use bumpwork::quality::{Coverage, Quality};
use bumpwork::raster::{Fragment, FragmentShader, RenderTarget, SampleRays, ViewRays, Viewport};
use bumpwork::reference::{cast_pixel, render_reference};
use bumpwork::scene::PreparedScene;
use bumpwork::scene::{Camera, Material, Object, Scene, preset};
use bumpwork::shade::{ExactScratch, Neighbours, SurfacePointSource, exact_fragments};
use bumpwork::shade::{FrameObject, PerFragment, frame_objects};
use bumpwork::surface::{AxisBasis, Cone, Paraboloid, Sphere, Surface, Tessellation, Torus, Wave};
use glam::{DVec3, Vec2, Vec3};
use std::sync::Mutex;

const VIEW: Viewport = Viewport {
    width: 200,
    height: 150,
};

/// The seed's dimple period, in (u,v) units: the scale patterns repeat on.
const PERIOD: f32 = 30.0;

/// Records each fragment as rasterized and as moved to its true surface.
#[derive(Default)]
struct Recorder {
    seen: Mutex<Vec<(Fragment, Fragment)>>,
}

impl FragmentShader for Recorder {
    type Object<'o> = FrameObject<'o>;
    type Scratch = ExactScratch;

    fn scratch(&self) -> ExactScratch {
        ExactScratch::default()
    }

    fn shade(
        &self,
        objects: &[FrameObject],
        rays: &SampleRays,
        fragments: &mut [Fragment],
        scratch: &mut ExactScratch,
        out: &mut [Vec3],
    ) -> usize {
        let before = fragments.to_vec();
        exact_fragments(objects, None, rays, fragments, scratch);
        let pairs = before.into_iter().zip(fragments.iter().copied());
        self.seen.lock().unwrap().extend(pairs);
        out.fill(Vec3::ONE);
        0
    }
}

fn scene_of(surface: Surface, eye: [f64; 3], target: [f64; 3]) -> Scene {
    let mut scene = preset("sphere-on-plane-dimples").unwrap();
    scene.objects = vec![Object {
        surface,
        material: Material::default(),
        displace: false,
    }];
    scene.camera = Camera {
        eye: DVec3::from(eye),
        target: DVec3::from(target),
        up: Vec3::Y,
        vfov_degrees: 40.0,
        near: 1.0,
        far: 1e5,
    };
    scene
}

fn sphere_seen_from_above() -> Scene {
    let sphere = Surface::Sphere(Sphere {
        center: DVec3::new(10.0, 5.0, -20.0),
        radius: 280.0,
    });
    scene_of(sphere, [200.0, 700.0, 900.0], [10.0, 5.0, -20.0])
}

fn cone_towards_its_apex() -> Scene {
    let cone = Surface::Cone(Cone {
        apex: DVec3::new(0.0, 150.0, 0.0),
        basis: AxisBasis::from_axis(Vec3::new(0.2, -1.0, 0.3)),
        half_angle: 0.45,
        height: 300.0,
    });
    scene_of(cone, [100.0, 450.0, 500.0], [0.0, 0.0, 0.0])
}

fn bowl_inside_and_out() -> Scene {
    let bowl = Surface::Paraboloid(Paraboloid {
        apex: DVec3::new(0.0, -100.0, 0.0),
        basis: AxisBasis::from_axis(Vec3::new(0.0, 1.0, 0.25)),
        curvature: 0.004,
        radius: 200.0,
    });
    scene_of(bowl, [0.0, 350.0, 800.0], [0.0, -20.0, 0.0])
}

/// Seen from above and to the side: the hole, the saddle inside the ring and both seams.
fn torus_through_its_hole() -> Scene {
    let torus = Surface::Torus(Torus {
        center: DVec3::new(5.0, -10.0, 0.0),
        basis: AxisBasis::from_axis(Vec3::new(0.1, 1.0, 0.4)),
        major_radius: 200.0,
        minor_radius: 70.0,
    });
    scene_of(torus, [150.0, 500.0, 650.0], [5.0, -10.0, 0.0])
}

/// How far apart two (u,v) of one surface are, as the distance between their points over the
/// length of a period along v there.
fn apart_in_periods(surface: &Surface, a: Vec2, b: Vec2) -> f32 {
    let (fa, fb) = (surface.frame(a.x, a.y), surface.frame(b.x, b.y));
    (fa.p - fb.p).length() / (PERIOD * fa.pv.length())
}

struct Agreement {
    compared: usize,
    kept: usize,
    worst_periods: f32,
    worst_depth: f32,
}

/// Every fragment of the scene's one object against the reference's exact hit through the same
/// sample point.
fn agreement(scene: &Scene) -> Agreement {
    let prepared = PreparedScene::new(scene.clone(), Tessellation { density: 64 });
    let camera = &scene.camera;
    let recorder = Recorder::default();
    render_with(&prepared, &RenderTarget::new(camera, VIEW), &recorder);
    let objects = frame_objects(&prepared, camera);
    let rays = ViewRays::new(camera, VIEW);
    let surface = &prepared.objects[0].surface;
    let mut result = Agreement {
        compared: 0,
        kept: 0,
        worst_periods: 0.0,
        worst_depth: 0.0,
    };
    for (before, after) in recorder.seen.into_inner().unwrap() {
        assert!(after.uv.is_finite() && after.depth.is_finite(), "{after:?}");
        if after == before {
            result.kept += 1;
            continue;
        }
        let Some(exact) = cast_pixel(&objects, camera, &rays, before.x, before.y) else {
            continue;
        };
        result.compared += 1;
        let periods = apart_in_periods(surface, after.uv, exact.uv);
        result.worst_periods = result.worst_periods.max(periods);
        let depth =
            (after.depth - exact.depth).abs() / (PERIOD * surface.frame(0.0, 1.0).pv.length());
        result.worst_depth = result.worst_depth.max(depth);
    }
    result
}

fn assert_exact(scene: &Scene, what: &str, kept_allowed: usize) {
    assert_within(scene, what, kept_allowed, 1e-5);
}

fn assert_within(scene: &Scene, what: &str, kept_allowed: usize, periods: f32) {
    let a = agreement(scene);
    eprintln!(
        "{what}: {} fragments compared, {} kept, worst {:.2e} periods apart, depth {:.2e}",
        a.compared, a.kept, a.worst_periods, a.worst_depth
    );
    assert!(a.compared > 5000, "{what}: only {} fragments", a.compared);
    assert!(
        a.kept <= kept_allowed,
        "{what}: {} kept their mesh (u,v)",
        a.kept
    );
    assert!(
        a.worst_periods < periods,
        "{what}: {:e} periods",
        a.worst_periods
    );
    assert!(
        a.worst_depth < 1e-4,
        "{what}: depth {:e} periods",
        a.worst_depth
    );
}

#[test]
fn a_spheres_fragments_are_at_its_analytic_hits_poles_seam_and_silhouette_included() {
    assert_exact(&sphere_seen_from_above(), "sphere", 0);
}

#[test]
fn a_toruss_fragments_are_at_its_analytic_hits_saddle_and_seams_included() {
    // A ray through the pushed-out mesh just past the outline may miss the tube: such a
    // fragment keeps its mesh (u,v) (exact coverage drops it). A few pixels.
    assert_exact(&torus_through_its_hole(), "torus", VIEW.width as usize / 4);
}

#[test]
fn a_cones_fragments_are_at_its_analytic_hits_up_to_its_apex() {
    // Past the base a ray through a chord may meet the cone's quadric only beyond its height:
    // such a fragment keeps its mesh (u,v). They are a thin line, a few pixels.
    assert_exact(&cone_towards_its_apex(), "cone", VIEW.width as usize / 4);
}

#[test]
fn a_paraboloids_fragments_are_at_its_analytic_hits_inside_and_out() {
    // Past the rim a ray through a chord may meet the paraboloid only beyond its radius: such a
    // fragment keeps its mesh (u,v). They are a thin line, a few pixels.
    assert_exact(
        &bowl_inside_and_out(),
        "paraboloid",
        VIEW.width as usize / 4,
    );
}

#[test]
fn a_waves_fragments_are_at_its_analytic_hits_to_f32_rounding() {
    // The Newton steps run to the root along the same f64 ray the reference casts, so the
    // (u,v) agree to the rounding of f32 coordinates of a few hundred units (3e-5, 1e-6 of a
    // period), not just within the steps' tolerance: a bump whose slope is unbounded at its
    // rim (the spheres pattern) then falls on the same side of the rim in both.
    let wave = Surface::Wave(Wave {
        origin: DVec3::new(-200.0, 0.0, 150.0),
        size: Vec2::new(400.0, 300.0),
        amplitude: 12.0,
        wavelength: 100.0,
    });
    let scene = scene_of(wave, [0.0, 300.0, 500.0], [0.0, 0.0, 0.0]);
    assert_within(&scene, "wave", VIEW.width as usize / 4, 4e-6);
}

/// Rays at `degrees` above the mean plane of a wave, through points on its density-64 chords.
fn wave_at_grazing(degrees: f32) -> (usize, usize) {
    let wave = Wave {
        origin: DVec3::ZERO,
        size: Vec2::new(400.0, 300.0),
        amplitude: 12.0,
        wavelength: 100.0,
    };
    let surface = Surface::Wave(wave.clone());
    let mesh = surface.tessellate(Tessellation { density: 64 });
    let (sin, cos) = degrees.to_radians().sin_cos();
    let (mut settled, mut fell_back) = (0, 0);
    for (i, triangle) in mesh.indices.iter().enumerate().step_by(7) {
        let corners = triangle.map(|k| mesh.positions[k as usize]);
        let chord = (corners[0] + corners[1] + corners[2]) / 3.0;
        // Looking down at the angle, across the crests and at a slant to them.
        let azimuth = (i % 5) as f32 * 0.3;
        let direction = Vec3::new(azimuth.cos() * cos, -sin, -azimuth.sin() * cos);
        let direction = direction / direction.length();
        let eye = chord - direction * 500.0;
        match surface.true_hit(eye.as_dvec3(), direction.as_dvec3(), 500.0) {
            Some(hit) => {
                let p = eye + direction * hit.depth;
                let on_surface = p.y - wave.amplitude * (std::f32::consts::TAU * p.x / 100.0).sin();
                assert!(
                    on_surface.abs() < 1e-3,
                    "{degrees}°: {on_surface} off the surface"
                );
                assert!((hit.uv - Vec2::new(p.x, -p.z)).length() < 1e-3);
                // No leap to another sheet: within a quarter wave of the chord point.
                assert!(
                    (p - chord).length() < 25.0,
                    "{degrees}°: {} away",
                    (p - chord).length()
                );
                settled += 1;
            }
            None => fell_back += 1,
        }
    }
    (settled, fell_back)
}

#[test]
fn the_waves_newton_steps_settle_at_grazing_angles_or_give_up() {
    for degrees in [1.0, 3.0, 10.0, 45.0, 89.0] {
        let (settled, fell_back) = wave_at_grazing(degrees);
        eprintln!("wave at {degrees}°: {settled} settled, {fell_back} fell back");
        let fraction = fell_back as f64 / (settled + fell_back) as f64;
        assert!(
            fraction < 0.02,
            "{degrees}°: {fell_back} of {} fell back",
            settled + fell_back
        );
    }
}

#[test]
fn exact_surface_points_leave_no_nan_at_poles_apexes_seams_or_silhouettes() {
    let quality = Quality {
        surface_point: SurfacePointSource::Exact,
        ..Quality::interactive()
    };
    let mut wave_scene = preset("wave-spheres").unwrap();
    wave_scene.camera.eye.y *= 0.2;
    for scene in [
        sphere_seen_from_above(),
        cone_towards_its_apex(),
        bowl_inside_and_out(),
        torus_through_its_hole(),
        wave_scene,
    ] {
        let prepared = quality
            .prepare(scene.clone(), &scene.camera, VIEW, 0)
            .unwrap();
        let shader = quality.shader(&prepared, &scene.camera, VIEW);
        let target = RenderTarget::new(&scene.camera, VIEW);
        let (frame, stats) = render_with(&prepared, &target, &shader);
        assert!(stats.fragments > 1000, "{}", scene.name);
        let bad = frame.color().iter().filter(|c| !c.is_finite()).count();
        assert_eq!(bad, 0, "{}: {bad} pixels not finite", scene.name);
    }
    // At the poles and apex themselves.
    let sphere = &sphere_seen_from_above().objects[0].surface;
    for pole in [1.0, -1.0] {
        let (eye, down) = (
            DVec3::new(0.0, 600.0 * pole, 0.0),
            DVec3::new(0.0, -pole, 0.0),
        );
        let hit = sphere.true_hit(eye, down, 320.1);
        assert!(
            hit.is_some_and(|h| h.uv.is_finite() && (h.depth - 320.0).abs() < 1e-3),
            "{hit:?}"
        );
    }
    let cone = &cone_towards_its_apex().objects[0].surface;
    let towards_apex = DVec3::new(0.3, 0.5, -1.0);
    // Exactly through the apex, rounding may put the hit a hair behind it, off the surface: the
    // fragment then keeps its mesh (u,v). Either way nothing is NaN.
    let hit = cone.true_hit(-towards_apex * 400.0, towards_apex, 400.0);
    assert!(
        hit.is_none_or(|h| h.uv.is_finite() && (h.depth - 400.0).abs() < 1e-2),
        "{hit:?}"
    );
}

/// Writes each fragment's object (plus one) as its colour, after settling it on the true
/// surfaces as exact coverage does; background stays 0.
struct ObjectIds {
    neighbours: Neighbours,
}

impl FragmentShader for ObjectIds {
    type Object<'o> = FrameObject<'o>;
    type Scratch = ExactScratch;

    fn scratch(&self) -> ExactScratch {
        ExactScratch::default()
    }

    fn shade(
        &self,
        objects: &[FrameObject],
        rays: &SampleRays,
        fragments: &mut [Fragment],
        scratch: &mut ExactScratch,
        out: &mut [Vec3],
    ) -> usize {
        let coverage = Some(&self.neighbours);
        exact_fragments(objects, coverage, rays, fragments, scratch);
        for (fragment, out) in fragments.iter().zip(out) {
            *out = Vec3::splat((fragment.object + 1) as f32 % (objects.len() + 1) as f32);
        }
        0
    }
}

/// Pixels whose object (or background) differs between exact coverage and the reference.
fn coverage_mismatches(scene: &Scene, coverage: Coverage) -> (usize, usize) {
    // A coarse mesh, whose chords cut well inside the outline: the hull and the true surfaces
    // must make up all of it.
    let quality = Quality {
        coverage,
        tessellation: 12,
        ..Quality::interactive()
    };
    let mut scene = scene.clone();
    scene.background = Vec3::ZERO;
    let prepared = quality
        .prepare(scene.clone(), &scene.camera, VIEW, 0)
        .unwrap();
    // The neighbours exact coverage finds for this scene (with the mesh's, it finds none).
    let exact = Quality {
        coverage: Coverage::Exact,
        ..quality
    };
    let shader = exact.shader(&prepared, &scene.camera, VIEW);
    let neighbours = shader.exact_coverage.as_deref().unwrap().clone();
    let ours = ObjectIds { neighbours };
    let target = RenderTarget::new(&scene.camera, VIEW);
    let (frame, _) = render_with(&prepared, &target, &ours);
    let ids = PerFragment(|_: &FrameObject, f: &Fragment| Vec3::splat((f.object + 1) as f32));
    let (exact, _) = render_reference(&prepared, &scene.camera, VIEW, &ids);
    let covered = exact.color().iter().filter(|c| c.x > 0.0).count();
    let differ = frame.color().iter().zip(exact.color());
    let mismatches = differ.filter(|(a, b)| a.x != b.x).count();
    (mismatches, covered)
}

fn two_spheres_cutting_each_other_on_a_floor() -> Scene {
    let mut scene = preset("sphere-on-plane-dimples").unwrap();
    let sphere = |x: f64, radius: f32| Object {
        surface: Surface::Sphere(Sphere {
            center: DVec3::new(x, radius as f64, 0.0),
            radius,
        }),
        material: Material::default(),
        displace: false,
    };
    scene.objects.truncate(1);
    scene
        .objects
        .extend([sphere(-80.0, 150.0), sphere(90.0, 120.0)]);
    scene
}

/// A sphere whose lower third lies below the floor, seen from above or below it: where the
/// floor cuts it, which of the two a pixel shows is settled by the floor's plane alone.
fn sphere_sunk_through_a_floor(from_below: bool) -> Scene {
    let mut scene = preset("sphere-on-plane-dimples").unwrap();
    scene.objects.truncate(1);
    scene.objects.push(Object {
        surface: Surface::Sphere(Sphere {
            center: DVec3::new(20.0, 30.0, 0.0),
            radius: 100.0,
        }),
        material: Material::default(),
        displace: false,
    });
    if from_below {
        scene.camera.eye = DVec3::new(150.0, -260.0, 420.0);
        scene.camera.target = DVec3::new(0.0, 0.0, 0.0);
    }
    scene
}

/// A sphere on a floor with the eye so close that the near plane cuts its cap away: the hull is
/// clipped a little before the true surface, and the floor shows through the hole.
fn sphere_at_the_near_plane() -> Scene {
    let mut scene = two_spheres_cutting_each_other_on_a_floor();
    scene.objects.truncate(2);
    scene.camera.near = 45.0;
    scene.camera.eye = DVec3::new(-80.0, 150.0, 185.0);
    scene.camera.target = DVec3::new(-80.0, 60.0, 0.0);
    scene
}

#[test]
fn exact_coverage_is_the_references_outline_and_order_of_surfaces() {
    let mut mesh_total = 0;
    for (what, scene) in [
        ("sphere", sphere_seen_from_above()),
        ("cone", cone_towards_its_apex()),
        ("bowl", bowl_inside_and_out()),
        (
            "two spheres cutting each other on a floor",
            two_spheres_cutting_each_other_on_a_floor(),
        ),
        ("wave and spheres", preset("wave-spheres").unwrap()),
        (
            "a sphere sunk through a floor",
            sphere_sunk_through_a_floor(false),
        ),
        (
            "a sphere sunk through a floor, from below",
            sphere_sunk_through_a_floor(true),
        ),
        (
            "a sphere grazing the near plane",
            sphere_at_the_near_plane(),
        ),
    ] {
        let (mismatches, covered) = coverage_mismatches(&scene, Coverage::Exact);
        let (mesh_mismatches, _) = coverage_mismatches(&scene, Coverage::Mesh);
        eprintln!(
            "{what}: {mismatches} of {covered} covered pixels differ ({mesh_mismatches} with the \
             mesh's coverage)"
        );
        assert!(covered > 2000, "{what}: only {covered} pixels covered");
        assert!(
            mismatches <= 2,
            "{what}: {mismatches} pixels differ from the reference"
        );
        mesh_total += mesh_mismatches;
    }
    // The coarse meshes' own outlines are well off: the test sees what exact coverage mends.
    assert!(
        mesh_total > 200,
        "the meshes alone are off by only {mesh_total} pixels"
    );
}
