//! Meshes with shared edges cover every pixel centre inside their outline exactly once: the
//! top-left rule gives each shared edge and vertex to exactly one triangle.

mod common;

use bumpwork::raster::PreparedScene;
use bumpwork::raster::{RenderTarget, Viewport, frame_objects, screen_triangles};
use bumpwork::scene::{Light, Material, Object, Scene};
use bumpwork::surface::{Sphere, Surface, Tessellation};
use common::*;
use glam::{DVec3, Vec3};
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
            triangles.extend(quads.iter().filter_map(|&t| screen_triangle(VIEWPORT, t)));
        }
    }
    triangles
}

#[test]
fn grid_with_vertices_on_pixel_centres_covers_once() {
    // Spacing 4 from offset (0.5, 0.5): every vertex and many edges pass through pixel centres.
    assert_covered_once(
        &coverage(VIEWPORT, &grid_triangles(4.0, (0.5, 0.5), 0.0, 1)),
        "centres",
    );
}

#[test]
fn grid_with_vertices_on_pixel_edges_covers_once() {
    assert_covered_once(
        &coverage(VIEWPORT, &grid_triangles(3.0, (0.0, 0.0), 0.0, 1)),
        "edges",
    );
}

#[test]
fn jittered_grids_cover_once() {
    for seed in 1..20 {
        // Jitter of ±1 on a 5-pixel grid keeps every quad convex, so neither diagonal folds over.
        let triangles = grid_triangles(5.0, (0.25, 0.75), 2.0, seed);
        assert_covered_once(
            &coverage(VIEWPORT, &triangles),
            &format!("jittered grid, seed {seed}"),
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

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
    let scene = Scene {
        name: "sphere".into(),
        camera: camera([0.3, 0.2, 4.0], [0.0, 0.0, 0.0], 40.0),
        background: Vec3::ZERO,
        ambient: Vec3::ZERO,
        lights: vec![Light::Directional {
            towards: Vec3::Z,
            color: Vec3::ONE,
        }],
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
        }],
    };
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
