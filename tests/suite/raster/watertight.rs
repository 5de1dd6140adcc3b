//! Meshes with shared edges cover every pixel centre inside their outline exactly once: the
//! top-left rule gives each shared edge and vertex to exactly one triangle. So do the sample
//! points of a supersampling pass, which the rasteriser moves off the centres.

use crate::common::render_with;
use crate::common::*;
use bumpwork::raster::{Fragment, ImageWindow};
use bumpwork::raster::{
    PixelRect, RenderTarget, SampleShift, ShiftSpan, Viewport, scan_shifted, screen_triangles,
};
use bumpwork::scene::PreparedScene;
use bumpwork::scene::{Light, Material, Object, Scene};
use bumpwork::shade::frame_objects;
use bumpwork::shade::{FrameObject, PerFragment};
use bumpwork::surface::{Sphere, Surface, Tessellation};
use glam::{DVec3, Vec2, Vec3};
use proptest::prelude::*;

const VIEWPORT: Viewport = Viewport {
    width: 64,
    height: 48,
};

fn assert_covered_once(counts: &[u32], what: &str) {
    for (i, &c) in counts.iter().enumerate() {
        let (x, y) = (i as u32 % VIEWPORT.width, i as u32 / VIEWPORT.width);
        assert_eq!(c, 1, "{what}: pixel ({x}, {y}) covered {c} times");
    }
}

/// A grid of quads over (and past) the viewport, each split in two, with the given vertex jitter.
fn grid_triangles(
    spacing: f64,
    offset: (f64, f64),
    jitter: f64,
    seed: u64,
    span: &ShiftSpan,
) -> Vec<bumpwork::raster::ScreenTriangle> {
    let mut rng = XorShift(seed);
    let (nx, ny) = (
        ((VIEWPORT.width as f64 + 20.0) / spacing) as usize + 2,
        ((VIEWPORT.height as f64 + 20.0) / spacing) as usize + 2,
    );
    let mut points = vec![vec![(0.0, 0.0); nx]; ny];
    for (j, row) in points.iter_mut().enumerate() {
        for (i, p) in row.iter_mut().enumerate() {
            let dx = (rng.next_f64() - 0.5) * jitter;
            let dy = (rng.next_f64() - 0.5) * jitter;
            *p = (
                offset.0 - 10.0 + i as f64 * spacing + dx,
                offset.1 - 10.0 + j as f64 * spacing + dy,
            );
        }
    }
    let mut triangles = Vec::new();
    for j in 0..ny - 1 {
        for i in 0..nx - 1 {
            let (a, b, c, d) = (
                points[j][i],
                points[j][i + 1],
                points[j + 1][i],
                points[j + 1][i + 1],
            );
            // Alternate the diagonal so both orientations of shared diagonals are exercised.
            let quads = if (i + j) % 2 == 0 {
                [[a, b, c], [b, d, c]]
            } else {
                [[a, b, d], [a, d, c]]
            };
            let set_up = |&t: &[(f64, f64); 3]| shifted_screen_triangle(VIEWPORT, t, span);
            triangles.extend(quads.iter().filter_map(set_up));
        }
    }
    triangles
}

#[test]
fn grid_with_vertices_on_pixel_centres_covers_once() {
    // Spacing 4 from offset (0.5, 0.5): every vertex and many edges pass through pixel centres.
    assert_covered_once(
        &coverage(
            VIEWPORT,
            &grid_triangles(4.0, (0.5, 0.5), 0.0, 1, &ShiftSpan::NONE),
        ),
        "centres",
    );
}

#[test]
fn grid_with_vertices_on_pixel_edges_covers_once() {
    assert_covered_once(
        &coverage(
            VIEWPORT,
            &grid_triangles(3.0, (0.0, 0.0), 0.0, 1, &ShiftSpan::NONE),
        ),
        "edges",
    );
}

#[test]
fn jittered_grids_cover_once() {
    for seed in 1..20 {
        // Jitter of ±1 on a 5-pixel grid keeps every quad convex, so neither diagonal folds over.
        let triangles = grid_triangles(5.0, (0.25, 0.75), 2.0, seed, &ShiftSpan::NONE);
        assert_covered_once(
            &coverage(VIEWPORT, &triangles),
            &format!("jittered grid, seed {seed}"),
        );
    }
}

/// Shifted sample points (a supersampling pass's), up to a pixel off the centres, on grids whose
/// vertices lie on pixel centres and on jittered ones: each covered once, with the triangles
/// set up for that shift alone or for shifts anywhere within a pixel. Tiny triangles that cover
/// no pixel centre still cover shifted points: their bounds are the shifted points'.
#[test]
fn shifted_sample_points_are_covered_once() {
    let shifts = [
        (0.3, -0.7),
        (-1.0, 1.0),
        (0.5, 0.5),
        (0.99, -0.01),
        (-0.371, 0.629),
    ];
    for (sx, sy) in shifts {
        let shift = SampleShift::new(glam::Vec2::new(sx, sy));
        let corners = [(-1.0, -1.0), (1.0, 1.0)].map(|(x, y)| SampleShift::new(Vec2::new(x, y)));
        for (seed, span) in
            (1..8).flat_map(|s| [(s, ShiftSpan::of([shift])), (s, ShiftSpan::of(corners))])
        {
            let grids = [
                grid_triangles(4.0, (0.5, 0.5), 0.0, seed, &span),
                grid_triangles(0.7, (0.25, 0.75), 0.3, seed, &span),
            ];
            for triangles in grids {
                assert_covered_once(
                    &shifted_coverage(VIEWPORT, &triangles, &shift),
                    &format!("shift ({sx}, {sy}), seed {seed}"),
                );
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// A pixel is covered under a shift exactly when its moved sample point lies in the
    /// triangle (checked in f64 away from the edges, where 1/256-pixel snapping decides).
    #[test]
    fn a_shifted_sample_is_covered_where_the_triangle_holds_it(
        corners in proptest::array::uniform3((-4.0f64..68.0, -4.0f64..52.0)),
        shift in (-1.0f32..1.0, -1.0f32..1.0),
    ) {
        let shift = SampleShift::new(glam::Vec2::new(shift.0, shift.1));
        let counts = match shifted_screen_triangle(VIEWPORT, corners, &ShiftSpan::of([shift])) {
            Some(t) => shifted_coverage(VIEWPORT, &[t], &shift),
            None => vec![0; (VIEWPORT.width * VIEWPORT.height) as usize],
        };
        let area = cross(corners[0], corners[1], corners[2]);
        prop_assume!(area.abs() > 1.0);
        for (i, &count) in counts.iter().enumerate() {
            let (x, y) = ((i as u32 % VIEWPORT.width) as f64, (i as u32 / VIEWPORT.width) as f64);
            let p = (x + 0.5 + f64::from(shift.pixels.x), y + 0.5 + f64::from(shift.pixels.y));
            // Distances to the three edge lines, positive inside.
            let distance = |a: (f64, f64), b: (f64, f64)| {
                cross(a, b, p) * area.signum() / ((b.0 - a.0).hypot(b.1 - a.1))
            };
            let d = [
                distance(corners[0], corners[1]),
                distance(corners[1], corners[2]),
                distance(corners[2], corners[0]),
            ];
            let nearest = d.iter().fold(f64::INFINITY, |m, &v| m.min(v));
            if nearest > 0.02 {
                prop_assert_eq!(count, 1, "sample ({}, {}) inside, not covered", p.0, p.1);
            } else if nearest < -0.02 {
                prop_assert_eq!(count, 0, "sample ({}, {}) outside, covered", p.0, p.1);
            }
        }
    }

    /// A fan around a centre whose rim lies well outside the viewport covers it exactly once.
    #[test]
    fn random_fans_cover_once(
        centre in (0u32..64, 0u32..48, 0u32..3, 0u32..3),
        rim in proptest::collection::vec((0.0f64..1.0, 2.0f64..3.0), 7..24),
    ) {
        // Centres on pixel centres, pixel corners or edge midpoints.
        let c = (centre.0 as f64 + centre.2 as f64 * 0.25, centre.1 as f64 + centre.3 as f64 * 0.25);
        let diagonal = 80.0;
        let n = rim.len();
        // Angles: evenly spaced with jitter of up to a third of a step, so gaps stay under 60°.
        let points: Vec<(f64, f64)> = rim
            .iter()
            .enumerate()
            .map(|(k, &(jitter, radius))| {
                let angle = (k as f64 + (jitter - 0.5) * 0.66) * std::f64::consts::TAU / n as f64;
                (c.0 + radius * diagonal * angle.cos(), c.1 + radius * diagonal * angle.sin())
            })
            .collect();
        prop_assume!(n >= 7);
        let triangles: Vec<_> = (0..n)
            .filter_map(|k| screen_triangle(VIEWPORT, [c, points[k], points[(k + 1) % n]]))
            .collect();
        let counts = coverage(VIEWPORT, &triangles);
        for (i, &count) in counts.iter().enumerate() {
            prop_assert_eq!(count, 1, "pixel {} covered {} times", i, count);
        }
    }
}

#[test]
fn tessellated_sphere_front_faces_cover_its_silhouette_once() {
    let viewport = Viewport {
        width: 160,
        height: 120,
    };
    let radius = 1.0;
    let scene = sphere_scene(radius);
    let density = 32;
    let cam = scene.camera.clone();
    let prepared = PreparedScene::new(scene, Tessellation { density });
    let target = RenderTarget::new(&cam, viewport);
    let triangles = screen_triangles(&frame_objects(&prepared, &cam), &target);
    let counts = coverage(viewport, &triangles);
    let distance = cam.eye.length();
    let outer = (radius as f64 / distance).asin();
    // The tessellation's silhouette lies between the sphere and its inscribed polyhedron.
    let inner = (radius as f64 * (std::f64::consts::PI / density as f64).cos() / distance).asin();
    let (mut inside, mut outside) = (0, 0);
    for y in 0..viewport.height {
        for x in 0..viewport.width {
            let ray = cam.ray_direction(
                viewport.width,
                viewport.height,
                x as f64 + 0.5,
                y as f64 + 0.5,
            );
            let angle = ray.angle_between(-cam.eye);
            let count = counts[(y * viewport.width + x) as usize];
            assert!(count <= 1, "pixel ({x}, {y}) covered {count} times");
            if angle < inner - 1e-3 {
                assert_eq!(count, 1, "hole at ({x}, {y})");
                inside += 1;
            } else if angle > outer + 1e-3 {
                assert_eq!(count, 0, "spill at ({x}, {y})");
                outside += 1;
            }
        }
    }
    assert!(
        inside > 1000 && outside > 1000,
        "the test saw both regions: {inside}, {outside}"
    );
}

/// Twice the signed area of (a, b, p).
fn cross(a: (f64, f64), b: (f64, f64), p: (f64, f64)) -> f64 {
    (b.0 - a.0) * (p.1 - a.1) - (b.1 - a.1) * (p.0 - a.0)
}

/// A lit unit-coloured sphere of `radius` at the origin, seen from 4 units away.
fn sphere_scene(radius: f32) -> Scene {
    Scene {
        name: "sphere".into(),
        camera: camera([0.3, 0.2, 4.0], [0.0, 0.0, 0.0], 40.0),
        background: Vec3::ZERO,
        ambient: Vec3::ZERO,
        lights: vec![Light::Directional {
            towards: Vec3::Z,
            color: Vec3::ONE,
        }],
        time: 0.0,
        quality: Vec::new(),
        shadows: true,
        objects: vec![Object {
            surface: Surface::Sphere(Sphere {
                center: DVec3::ZERO,
                radius,
            }),
            material: Material {
                color: Vec3::ONE,
                specular: 0.0,
                shininess: 1.0,
                ..Material::default()
            },
            displace: false,
        }],
    }
}

/// A shifted pass over a sphere of triangles far smaller than a pixel (most hold no pixel
/// centre) leaves no hole inside the silhouette: the passes' shared set-up keeps the
/// triangles that only shifted sample points fall in.
#[test]
fn a_shifted_pass_over_sub_pixel_triangles_has_no_holes() {
    let viewport = Viewport {
        width: 64,
        height: 48,
    };
    let scene = sphere_scene(1.0);
    let cam = scene.camera.clone();
    let prepared = PreparedScene::new(scene, Tessellation { density: 256 });
    let shader = PerFragment(|_: &FrameObject, _: &Fragment| Vec3::ONE);
    for offset in [Vec2::new(0.5, 0.5), Vec2::new(-0.3, 0.8)] {
        let target = RenderTarget {
            window: ImageWindow {
                offset,
                ..ImageWindow::whole(viewport)
            },
            ..RenderTarget::new(&cam, viewport)
        };
        let (frame, _) = render_with(&prepared, &target, &shader);
        let distance = cam.eye.length();
        // Well inside the silhouette (its angular radius less two pixels' worth).
        let pixel_angle = (20f64.to_radians()) / (viewport.height as f64 / 2.0);
        let inner = (1.0 / distance).asin() - 2.0 * pixel_angle;
        for y in 0..viewport.height {
            for x in 0..viewport.width {
                let (sx, sy) = (
                    x as f64 + 0.5 + offset.x as f64,
                    y as f64 + 0.5 + offset.y as f64,
                );
                let ray = cam.ray_direction(viewport.width, viewport.height, sx, sy);
                if ray.angle_between(-cam.eye) < inner {
                    let depth = frame.depth()[(y * viewport.width + x) as usize];
                    assert!(depth.is_finite(), "offset {offset}: hole at ({x}, {y})");
                }
            }
        }
    }
}

proptest! {
    /// Scanning within any clip rectangle finds exactly the pixels whose own sample point the
    /// triangle covers: the whole-rectangle rejection (an edge outside at all four corners) is
    /// exact, for big triangles whose bounds reach far past them as for small ones.
    #[test]
    fn a_clipped_scan_finds_exactly_the_covered_samples(
        corners in prop::array::uniform3((-60.0..124.0f64, -60.0..108.0f64)),
        shift in (-0.5..0.5f32, -0.5..0.5f32),
        clip in (0..64u32, 0..48u32, 0..64u32, 0..48u32),
    ) {
        let shift_offset = Vec2::new(shift.0, shift.1);
        let span = ShiftSpan::of([SampleShift::new(shift_offset)].into_iter());
        let Some(t) = shifted_screen_triangle(VIEWPORT, corners, &span) else {
            return Ok(());
        };
        let shift = SampleShift::new(shift_offset);
        let clip = PixelRect {
            x0: clip.0.min(clip.2),
            y0: clip.1.min(clip.3),
            x1: clip.0.max(clip.2),
            y1: clip.1.max(clip.3),
        };
        let mut scanned = Vec::new();
        scan_shifted(&t, &clip, &shift, |x, y| scanned.push((x, y)));
        let mut one_by_one = Vec::new();
        for y in clip.y0..=clip.y1 {
            for x in clip.x0..=clip.x1 {
                let pixel = PixelRect { x0: x, y0: y, x1: x, y1: y };
                scan_shifted(&t, &pixel, &shift, |x, y| one_by_one.push((x, y)));
            }
        }
        prop_assert_eq!(scanned, one_by_one);
    }
}
