//! Supersampled stills in bands: edges get intermediate values (and keep their area), a still
//! streamed in bands matches the same still rendered whole, and no value is lost or made up.

use crate::common::render_with;
use bumpwork::raster::{
    Fragment, FrameStats, Framebuffer, ImageWindow, Interpolation, RenderTarget, Viewport,
};
use bumpwork::scene::Camera;
use bumpwork::scene::PreparedScene;
use bumpwork::scene::{Material, Object, Scene};
use bumpwork::shade::{FrameObject, PerFragment};
use bumpwork::still::{
    BandBuffers, BandJob, ResolveFilter, RowSink, Supersampling, render_supersampled, stream_still,
};
use bumpwork::surface::{Surface, Tessellation, Triangle};
use glam::{DVec3, Vec3};

/// A white triangle on black, seen head on: a black/white edge at several angles.
fn triangle_scene() -> (PreparedScene, Camera) {
    let scene = Scene {
        name: "edge".into(),
        camera: crate::common::camera([0.0, 0.0, 10.0], [0.0, 0.0, 0.0], 40.0),
        background: Vec3::ZERO,
        ambient: Vec3::ZERO,
        lights: vec![],
        time: 0.0,
        quality: Vec::new(),
        shadows: true,
        objects: vec![Object {
            surface: Surface::Triangle(Triangle::new(
                DVec3::new(-2.5, -1.7, 0.0),
                DVec3::new(2.9, -0.9, 0.0),
                DVec3::new(-0.4, 2.6, 0.0),
            )),
            material: Material::default(),
            displace: false,
        }],
    };
    let camera = scene.camera.clone();
    (PreparedScene::new(scene, Tessellation::default()), camera)
}

type Shader = fn(&FrameObject, &Fragment) -> Vec3;

fn white() -> PerFragment<Shader> {
    PerFragment(|_, _| Vec3::ONE)
}

/// Runs `work` on a band job over the white triangle.
fn with_job<R>(
    full: Viewport,
    supersampling: Supersampling,
    adaptive: Option<f32>,
    work: impl FnOnce(&BandJob<PerFragment<Shader>>) -> R,
) -> R {
    let (prepared, camera) = triangle_scene();
    let shader = white();
    let job = BandJob {
        prepared: &prepared,
        camera: &camera,
        full,
        shader: &shader,
        supersampling,
        interpolation: Interpolation::PerspectiveCorrect,
        adaptive,
    };
    work(&job)
}

/// The white triangle supersampled in memory, adaptively at `adaptive` if given.
fn supersampled(
    full: Viewport,
    supersampling: Supersampling,
    adaptive: Option<f32>,
) -> (Framebuffer, FrameStats) {
    with_job(full, supersampling, adaptive, |job| {
        render_supersampled(job, &mut BandBuffers::default())
    })
}

fn render(samples: u32, filter: ResolveFilter, full: Viewport) -> Framebuffer {
    let supersampling = Supersampling { samples, filter };
    with_job(full, supersampling, None, |job| {
        render_supersampled(job, &mut BandBuffers::default()).0
    })
}

const VIEW: Viewport = Viewport {
    width: 160,
    height: 120,
};

fn is_between(c: Vec3) -> bool {
    c.x > 0.02 && c.x < 0.98
}

#[test]
fn one_sample_is_all_or_nothing_and_sixteen_soften_the_edges() {
    let one = render(1, ResolveFilter::Box, VIEW);
    assert!(one.color().iter().all(|c| c.x == 0.0 || c.x == 1.0));
    let covered = one.color().iter().filter(|c| c.x == 1.0).count() as f32;
    for filter in [ResolveFilter::Box, ResolveFilter::Tent] {
        let sixteen = render(16, filter, VIEW);
        let between = sixteen.color().iter().filter(|&&c| is_between(c)).count();
        assert!(
            between > 100,
            "{filter:?}: only {between} edge pixels are in between"
        );
        assert!(
            sixteen
                .color()
                .iter()
                .all(|c| c.is_finite() && c.x >= 0.0 && c.x <= 1.0 + 1e-5)
        );
        // Antialiasing moves coverage across the edge, it does not make or lose any.
        let area: f32 = sixteen.color().iter().map(|c| c.x).sum();
        assert!(
            (area - covered).abs() < 0.01 * covered,
            "{filter:?}: {area} vs {covered}"
        );
    }
}

/// Rows collected from a streamed still.
struct Rows(Vec<u8>);

impl RowSink for Rows {
    fn write_rows(&mut self, rgb: &[u8]) -> Result<(), String> {
        self.0.extend_from_slice(rgb);
        Ok(())
    }
}

#[test]
fn a_still_streamed_in_narrow_bands_matches_the_whole_render() {
    let full = Viewport {
        width: 150,
        height: 200,
    };
    let supersampling = Supersampling {
        samples: 4,
        filter: ResolveFilter::Tent,
    };
    with_job(full, supersampling, None, |job| {
        let whole = render_supersampled(job, &mut BandBuffers::default()).0;
        let expected: Vec<u8> = whole.to_srgb8().into_iter().flatten().collect();
        // One band of four 64-row strips, written as they finish, in any order: the same bytes.
        let mut rows = Rows(Vec::new());
        let stats = stream_still(job, 1 << 30, &mut rows, &mut |_| {}, &|| true);
        assert!(stats.is_ok());
        assert_eq!(rows.0, expected, "one band");
        let mut rows = Rows(Vec::new());
        let mut fractions = Vec::new();
        // A budget for a single 64-row band: 200 rows take 4 bands (the last one short).
        let budget = 150 * 64 * 28;
        let stats = stream_still(job, budget, &mut rows, &mut |f| fractions.push(f), &|| true);
        assert!(stats.is_ok());
        assert_eq!(fractions.len(), 4 * 4, "one report per pass");
        assert_eq!(fractions.last(), Some(&1.0));
        assert_eq!(rows.0.len(), expected.len());
        let differing = rows
            .0
            .iter()
            .zip(&expected)
            .filter(|(a, b)| a.abs_diff(**b) > 1)
            .count();
        // Bands see the same projection; only float rounding of the window transform can move an
        // edge sample, and then by one level of one sample.
        assert!(
            differing <= expected.len() / 1000,
            "{differing} bytes differ"
        );
    });
}

#[test]
fn a_cancelled_still_stops_before_writing() {
    with_job(VIEW, Supersampling::default(), None, |job| {
        let mut rows = Rows(Vec::new());
        let result = stream_still(job, 1 << 20, &mut rows, &mut |_| {}, &|| false);
        assert!(result.is_err());
        assert!(rows.0.is_empty());
    });
}

#[test]
fn a_still_cancelled_between_its_passes_writes_nothing() {
    let supersampling = Supersampling {
        samples: 16,
        filter: ResolveFilter::Box,
    };
    with_job(VIEW, supersampling, Some(0.05), |job| {
        // Yes for the centre pass, no before the supersampling passes.
        let asked = std::sync::atomic::AtomicUsize::new(0);
        let keep_going = || asked.fetch_add(1, std::sync::atomic::Ordering::Relaxed) == 0;
        let mut rows = Rows(Vec::new());
        let mut fractions = Vec::new();
        let result = stream_still(
            job,
            1 << 30,
            &mut rows,
            &mut |f| fractions.push(f),
            &keep_going,
        );
        assert!(result.is_err());
        assert!(rows.0.is_empty());
        assert_eq!(fractions.len(), 1, "only the centre pass was reported");
    });
}

#[test]
fn adaptive_supersampling_samples_every_edge_pixel_fully_and_shades_far_fewer() {
    let supersampling = Supersampling {
        samples: 16,
        filter: ResolveFilter::Tent,
    };
    let (full, full_stats) = supersampled(VIEW, supersampling, None);
    let (adaptive, adaptive_stats) = supersampled(VIEW, supersampling, Some(0.02));
    // Flat inside and outside: an edge line crossing a pixel's filter square (at most a pixel
    // from its centre) separates the pixel's centre from a neighbour's, so the pixel is marked
    // and gets the very samples of full supersampling. Only a corner of the triangle can poke
    // into a footprint between centres: at most a few pixels at each of the three.
    let differing: Vec<usize> = (0..full.color().len())
        .filter(|&i| (adaptive.color()[i] - full.color()[i]).abs().max_element() > 1e-5)
        .collect();
    assert!(differing.len() <= 6, "differing pixels {differing:?}");
    assert!(adaptive.color().iter().filter(|&&c| is_between(c)).count() > 100);
    assert!(
        adaptive_stats.fragments * 5 < full_stats.fragments,
        "{} vs {} fragments",
        adaptive_stats.fragments,
        full_stats.fragments
    );
}

#[test]
fn refining_box_supersampling_misses_at_most_one_sample_where_an_edge_crosses() {
    let supersampling = Supersampling {
        samples: 16,
        filter: ResolveFilter::Box,
    };
    // Large, for many edge pixels at each of the three angles.
    let view = Viewport {
        width: 960,
        height: 720,
    };
    let (full, full_stats) = supersampled(view, supersampling, None);
    let (adaptive, adaptive_stats) = supersampled(view, supersampling, Some(0.1));
    // A marked pixel whose four corner samples agree with its centre stops there. A straight
    // edge that misses all five can cut off only a sample outside the corners' hull (one near
    // the middle of a side), so such a pixel is off by at most one sample's weight, 1/16 of
    // the white-on-black step. Only a corner of the triangle can poke further in.
    let errors: Vec<f32> = (0..full.color().len())
        .map(|i| (adaptive.color()[i] - full.color()[i]).abs().max_element())
        .collect();
    let beyond_one_sample = errors.iter().filter(|&&e| e > 1.0 / 16.0 + 1e-5).count();
    let stopped_early = errors.iter().filter(|&&e| e > 1e-5).count();
    let edge_pixels = full.color().iter().filter(|&&c| is_between(c)).count();
    eprintln!(
        "{stopped_early} of {edge_pixels} edge pixels differ, {beyond_one_sample} by more than \
         a sample; fragments {} against {}",
        adaptive_stats.fragments, full_stats.fragments
    );
    assert!(
        beyond_one_sample <= 3,
        "{beyond_one_sample} pixels off by more than a sample"
    );
    assert!(
        stopped_early * 5 < edge_pixels,
        "{stopped_early} of {edge_pixels}"
    );
    assert!(adaptive.color().iter().filter(|&&c| is_between(c)).count() > 100);
    assert!(adaptive_stats.fragments * 5 < full_stats.fragments);
}

#[test]
fn a_supersampled_band_keeps_the_last_passs_depth() {
    let supersampling = Supersampling {
        samples: 16,
        filter: ResolveFilter::Box,
    };
    with_job(VIEW, supersampling, None, |job| {
        let still = render_supersampled(job, &mut BandBuffers::default()).0;
        let last = *supersampling.offsets().last().expect("16 offsets");
        let target = RenderTarget {
            window: ImageWindow {
                offset: last,
                ..ImageWindow::whole(VIEW)
            },
            footprint: supersampling.footprint(),
            ..RenderTarget::new(job.camera, VIEW)
        };
        let pass = render_with(job.prepared, &target, job.shader).0;
        let bits = |fb: &Framebuffer| fb.depth().iter().map(|d| d.to_bits()).collect::<Vec<_>>();
        assert!(bits(&still) == bits(&pass), "depths differ");
        assert!(still.depth().iter().any(|d| d.is_finite()));
        assert!(still.depth().iter().any(|d| d.is_infinite()));
    });
}
