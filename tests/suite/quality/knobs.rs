//! Each quality knob changes what it claims to, by a stated amount, against the exact reference
//! or the exact setting of the same knob.

use crate::common::render_with;
use bumpwork::quality::{Coverage, NormalSource, Quality};
use bumpwork::raster::{Framebuffer, Interpolation, Viewport};
use bumpwork::reference::metrics::normal_angle_error;
use bumpwork::reference::render_reference;
use bumpwork::scene::{Scene, Texturing, preset};
use bumpwork::shade::Showing;
use bumpwork::shade::{GradientMethod, NormalForm, ShaderMode, SurfacePointSource};
use bumpwork::texture::Filter;

const VIEW: Viewport = Viewport {
    width: 96,
    height: 72,
};

fn scene(name: &str) -> Scene {
    preset(name).expect("built-in scene")
}

/// The scene rendered at this quality in a view mode.
fn render(scene: &Scene, quality: &Quality, mode: ShaderMode) -> Framebuffer {
    let showing = Showing { mode, time: 0.0 };
    bumpwork::render::frame(scene, quality, VIEW, showing)
        .unwrap()
        .0
}

/// The exact reference in a view mode, shaded with this quality's shading knobs.
fn reference(scene: &Scene, quality: &Quality, mode: ShaderMode) -> Framebuffer {
    let prepared = quality
        .prepare(scene.clone(), &scene.camera, VIEW, 0)
        .unwrap();
    let showing = Showing { mode, time: 0.0 };
    let shader = quality.shader_showing(&prepared, &scene.camera, VIEW, showing);
    render_reference(&prepared, &scene.camera, VIEW, &shader).0
}

/// Mean absolute difference of the covered pixels' (u,v) (the Uv view shows fract(uv / 30)).
fn mean_uv_difference(a: &Framebuffer, b: &Framebuffer) -> f32 {
    let covered: Vec<usize> = (0..a.color().len())
        .filter(|&i| a.depth()[i].is_finite() && b.depth()[i].is_finite())
        .collect();
    let sum: f32 = covered
        .iter()
        .map(|&i| {
            let d = (a.color()[i] - b.color()[i]).truncate().abs();
            // fract wraps: a difference of 0.98 is one of 0.02.
            d.x.min(1.0 - d.x) + d.y.min(1.0 - d.y)
        })
        .sum();
    sum / covered.len().max(1) as f32
}

#[test]
fn affine_uvs_drift_from_the_exact_ones_on_a_tilted_plane_and_perspective_ones_do_not() {
    let floor = scene("plane-checks");
    let exact = reference(&floor, &Quality::interactive(), ShaderMode::Uv);
    let perspective = render(&floor, &Quality::interactive(), ShaderMode::Uv);
    let affine_quality = Quality {
        interpolation: Interpolation::Affine,
        ..Quality::interactive()
    };
    let affine = render(&floor, &affine_quality, ShaderMode::Uv);
    let (good, bad) = (
        mean_uv_difference(&perspective, &exact),
        mean_uv_difference(&affine, &exact),
    );
    // In units of the 30-unit period the view shows: perspective-correct (u,v) is exact on a
    // plane to rounding; affine is off by a visible fraction of a period on average.
    assert!(good < 1e-3, "perspective-correct off by {good} periods");
    assert!(bad > 0.05, "affine only off by {bad} periods");
}

/// A bare sphere: no bump, no texture, so normals are the frame's (or the mesh's) alone.
fn bare_sphere() -> Scene {
    let mut scene = scene("textured-sphere");
    for object in &mut scene.objects {
        object.material.bump = None;
        object.material.texture = None;
    }
    scene
}

fn mean_normal_error(scene: &Scene, quality: &Quality, exact: &Framebuffer) -> f64 {
    normal_angle_error(&render(scene, quality, ShaderMode::Normals), exact).mean_degrees
}

#[test]
fn interpolated_vertex_normals_differ_from_the_exact_frame_and_converge_with_density() {
    let sphere = bare_sphere();
    let exact = reference(&sphere, &Quality::interactive(), ShaderMode::Normals);
    // Shaded on the chords, whose normals the vertex normals interpolate.
    let at = |density: u32, normals: NormalSource| Quality {
        tessellation: density,
        normals,
        surface_point: SurfacePointSource::Interpolated,
        coverage: Coverage::Mesh,
        ..Quality::interactive()
    };
    let densities = [6, 12, 24, 48];
    let errors: Vec<f64> = densities
        .iter()
        .map(|&d| mean_normal_error(&sphere, &at(d, NormalSource::InterpolatedVertex), &exact))
        .collect();
    // On a 12 × 6 sphere, Phong-interpolated normals are off by degrees; the error is second
    // order in the cell size (about fourfold per doubling; at least twofold asserted).
    assert!(
        errors[0] > 1.0,
        "coarse interpolated normals off by only {errors:?}°"
    );
    for pair in errors.windows(2) {
        assert!(pair[1] < pair[0] / 2.0, "no convergence: {errors:?}");
    }
    // And they are not the exact frame's normals on the same mesh.
    let frame = render(
        &sphere,
        &at(6, NormalSource::ExactFrame),
        ShaderMode::Normals,
    );
    let interpolated = render(
        &sphere,
        &at(6, NormalSource::InterpolatedVertex),
        ShaderMode::Normals,
    );
    let apart = normal_angle_error(&interpolated, &frame).mean_degrees;
    assert!(
        apart > 0.5,
        "interpolated and exact-frame normals only {apart}° apart"
    );
}

#[test]
fn central_differences_agree_with_exact_derivatives_within_the_truncation_bound() {
    // B = A·sin(2πv/λ) with A = 3, λ = 40 (the shipped pattern's defaults) and strength s: the
    // central difference's error in Bv is s·h²/6·A·(2π/λ)³, and the normal's angle changes by
    // at most the slope's change (d atan(x)/dx ≤ 1).
    let wave = scene("plane-horizontal-wave");
    let strength = wave.objects[0]
        .material
        .bump
        .as_ref()
        .unwrap()
        .scale()
        .abs() as f64;
    let exact = render(&wave, &Quality::interactive(), ShaderMode::Normals);
    let error_at = |step: f32| {
        let quality = Quality {
            gradient: GradientMethod::CentralDifference { step },
            ..Quality::interactive()
        };
        normal_angle_error(&render(&wave, &quality, ShaderMode::Normals), &exact)
    };
    let k = 2.0 * std::f64::consts::PI / 40.0;
    for step in [1.0f32, 2.0] {
        let h = step as f64;
        let bound_degrees = (strength * h * h / 6.0 * 3.0 * k.powi(3)).to_degrees();
        let error = error_at(step);
        // 1e-4° of slack for f32 rounding of heights of ~3 differenced over h.
        assert!(
            error.max_degrees <= bound_degrees * 1.01 + 1e-4,
            "h = {h}: {}° > bound {bound_degrees}°",
            error.max_degrees
        );
        assert!(
            error.max_degrees > bound_degrees * 0.5,
            "h = {h}: the method did not run"
        );
    }
    let ratio = error_at(2.0).mean_degrees / error_at(1.0).mean_degrees;
    assert!(
        (3.0..5.0).contains(&ratio),
        "not second order: ratio {ratio}"
    );
}

#[test]
fn the_seed_lattice_makes_a_smooth_pattern_steppy() {
    let wave = scene("plane-horizontal-wave");
    let exact = render(&wave, &Quality::interactive(), ShaderMode::Normals);
    let lattice = Quality {
        gradient: GradientMethod::SeedLattice,
        ..Quality::interactive()
    };
    let error = normal_angle_error(&render(&wave, &lattice, ShaderMode::Normals), &exact);
    // Truncating v by up to one unit moves the phase by up to 2π/40: the slope changes by up to
    // A·k·(1 − cos k) + A·k·sin k, several tenths of a degree, and by nothing at whole v.
    assert!(error.max_degrees > 0.2, "{error:?}");
    assert!(error.max_degrees < 10.0, "{error:?}");
}

#[test]
fn the_seed_normal_form_differs_from_blinns_on_a_sphere_and_full_keeps_it_close() {
    let sphere = scene("big-sphere-squares");
    let with_form = |normal_form| Quality {
        normal_form,
        ..Quality::interactive()
    };
    let blinn = render(&sphere, &with_form(NormalForm::Blinn), ShaderMode::Normals);
    let seed = render(&sphere, &with_form(NormalForm::Seed), ShaderMode::Normals);
    let full = render(&sphere, &with_form(NormalForm::Full), ShaderMode::Normals);
    let seed_error = normal_angle_error(&seed, &blinn).mean_degrees;
    let full_error = normal_angle_error(&full, &blinn).mean_degrees;
    // Unit tangents on a sphere of radius 280 whose Pu, Pv are ~80 and ~140 long: the seed form
    // tilts bumps by far more than the full form's small (1 + B/r) correction.
    assert!(
        seed_error > 5.0 * full_error,
        "seed {seed_error}°, full {full_error}°"
    );
    assert!(seed_error > 0.5, "seed {seed_error}°");
}

#[test]
fn the_filter_override_reaches_every_image_texture_and_changes_the_picture() {
    let textured = scene("textured-sphere");
    let nearest = Quality {
        filter: Some(Filter::Nearest),
        ..Quality::interactive()
    };
    let prepared = nearest
        .prepare(textured.clone(), &textured.camera, VIEW, 0)
        .unwrap();
    let filters: Vec<Filter> = prepared
        .objects
        .iter()
        .filter_map(|o| match &o.material.texture {
            Some(Texturing::Image(image)) => Some(image.sampler.filter),
            _ => None,
        })
        .collect();
    assert!(!filters.is_empty() && filters.iter().all(|&f| f == Filter::Nearest));
    let trilinear = Quality {
        filter: Some(Filter::Trilinear),
        ..Quality::interactive()
    };
    let a = render(&textured, &nearest, ShaderMode::Shaded);
    let b = render(&textured, &trilinear, ShaderMode::Shaded);
    let changed = a
        .color()
        .iter()
        .zip(b.color())
        .filter(|(x, y)| (**x - **y).abs().max_element() > 1e-3);
    assert!(changed.count() > 100, "the filter changed too few pixels");
}

#[test]
fn adaptive_tessellation_brings_a_coarse_silhouette_within_its_tolerance() {
    let sphere = bare_sphere();
    let exact = reference(&sphere, &Quality::interactive(), ShaderMode::Shaded);
    // The mesh's own outline: exact coverage would hide what adaptive density does to it.
    let coarse = Quality {
        tessellation: 4,
        coverage: Coverage::Mesh,
        ..Quality::interactive()
    };
    let adaptive = Quality {
        adaptive_tolerance_px: Some(0.25),
        adaptive_samples: None,
        ..coarse
    };
    let mismatch = |q: &Quality| {
        let frame = render(&sphere, q, ShaderMode::Shaded);
        bumpwork::reference::metrics::silhouette_mismatch(&frame, &exact)
    };
    let (before, after) = (mismatch(&coarse), mismatch(&adaptive));
    // The silhouette is ~140 pixels around; chords within 0.25 px flip at most the pixels whose
    // centres lie within that band, a small fraction of the coarse mesh's mismatch.
    assert!(before > 50, "density 4 mismatched only {before} pixels");
    assert!(after * 5 < before, "adaptive {after} vs coarse {before}");
}

/// One pass of each renderer at the same sub-pixel offset: the rasterizer through the image
/// window, the reference through shifted rays.
fn passes_at(scene: &Scene, offset: glam::Vec2) -> (Framebuffer, Framebuffer) {
    use bumpwork::raster::ViewRays;
    use bumpwork::raster::{ImageWindow, RenderTarget};
    use bumpwork::reference::render_rays_into;
    let quality = Quality::interactive();
    let prepared = quality
        .prepare(scene.clone(), &scene.camera, VIEW, 0)
        .unwrap();
    let shader = quality.shader(&prepared, &scene.camera, VIEW);
    let target = RenderTarget {
        window: ImageWindow {
            offset,
            ..ImageWindow::whole(VIEW)
        },
        ..RenderTarget::new(&scene.camera, VIEW)
    };
    let raster = render_with(&prepared, &target, &shader).0;
    let rays = ViewRays::new(&scene.camera, VIEW).at_sample(offset.as_dvec2(), 1.0);
    let mut reference = Framebuffer::new(0, 0, glam::Vec3::ZERO);
    render_rays_into(
        &prepared,
        &scene.camera,
        VIEW,
        rays,
        &shader,
        &mut reference,
    );
    (raster, reference)
}

#[test]
fn shifted_reference_rays_sample_where_the_shifted_raster_pass_does() {
    use bumpwork::reference::metrics::silhouette_mismatch;
    let sphere = bare_sphere();
    let (centred, centred_reference) = passes_at(&sphere, glam::Vec2::ZERO);
    let offset = glam::Vec2::new(0.45, -0.4);
    let (shifted, shifted_reference) = passes_at(&sphere, offset);
    let agree = silhouette_mismatch(&shifted, &shifted_reference);
    let crossed = silhouette_mismatch(&shifted, &centred_reference);
    // At the same sample positions only pixels whose sample lies within ~0.01 px of the
    // silhouette may flip (chord sag at density 64 plus 1/256-px vertex snapping): a handful
    // along ~200 px of silhouette. Against centred rays the whole silhouette disagrees.
    assert!(silhouette_mismatch(&centred, &centred_reference) <= 12);
    assert!(agree <= 12, "{agree} pixels disagree at the same offset");
    assert!(
        crossed > 4 * agree.max(5),
        "crossed {crossed}, agree {agree}"
    );
}
