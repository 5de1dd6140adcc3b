//! The reference's intersections and (u,v) inversions, surface by surface: every hit lies on the
//! surface (frame(u,v) of the inverted (u,v) reproduces the hit point to 1e-4 of the surface's
//! size), no hit is missed in front of a known surface point, and inversion undoes `frame`.

use crate::reference::support::XorShift;
use bumpwork::surface::{
    AxisBasis, Cone, Paraboloid, Plane, Sphere, Surface, Torus, Triangle, Wave,
};
use bumpwork::surface::{Ray, intersect, surface_uv};
use glam::{DVec3, Vec2, Vec3};

fn surfaces() -> Vec<(&'static str, Surface, f64)> {
    vec![
        (
            "plane",
            Surface::Plane(Plane::new(
                DVec3::new(-200.0, 0.0, 100.0),
                Vec3::new(0.1, 1.0, 0.3),
                Vec3::X,
                Vec2::new(400.0, 300.0),
            )),
            400.0,
        ),
        (
            "sphere",
            Surface::Sphere(Sphere {
                center: DVec3::new(1e6, -1e6, 1e6),
                radius: 150.0,
            }),
            150.0,
        ),
        (
            "paraboloid",
            Surface::Paraboloid(Paraboloid {
                apex: DVec3::ZERO,
                basis: AxisBasis::from_axis(Vec3::new(0.2, 1.0, 0.4)),
                curvature: 0.01,
                radius: 100.0,
            }),
            100.0,
        ),
        (
            "cone",
            Surface::Cone(Cone {
                apex: DVec3::new(0.0, 100.0, 0.0),
                basis: AxisBasis::from_axis(-Vec3::Y),
                half_angle: 0.4,
                height: 200.0,
            }),
            200.0,
        ),
        (
            "wave",
            Surface::Wave(Wave {
                origin: DVec3::new(-200.0, 0.0, 150.0),
                size: Vec2::new(400.0, 300.0),
                amplitude: 12.0,
                wavelength: 100.0,
            }),
            400.0,
        ),
        (
            "triangle",
            Surface::Triangle(Triangle::new(
                DVec3::new(-50.0, 0.0, 0.0),
                DVec3::new(60.0, 10.0, -20.0),
                DVec3::new(0.0, 90.0, 30.0),
            )),
            120.0,
        ),
        (
            "torus",
            Surface::Torus(Torus {
                center: DVec3::new(-1e5, 2e5, 3e5),
                basis: AxisBasis::from_axis(Vec3::new(0.3, 1.0, -0.2)),
                major_radius: 200.0,
                minor_radius: 80.0,
            }),
            280.0,
        ),
    ]
}

/// A (u,v) strictly inside the surface's domain (inside the triangle for a triangle).
fn random_uv(rng: &mut XorShift, surface: &Surface) -> Vec2 {
    if let Surface::Triangle(t) = surface {
        let (a, b) = (rng.next_f64() as f32, rng.next_f64() as f32);
        let (a, b) = if a + b > 1.0 {
            (1.0 - a, 1.0 - b)
        } else {
            (a, b)
        };
        let [p, q, r] = t.corners_uv;
        return p + (q - p) * a + (r - p) * b;
    }
    let d = surface.domain();
    let s = Vec2::new(rng.range(0.01, 0.99) as f32, rng.range(0.01, 0.99) as f32);
    d.min + (d.max - d.min) * s
}

#[test]
fn rays_aimed_at_surface_points_hit_the_surface_no_later() {
    let mut rng = XorShift(0x5eed_1234_5678_9abc);
    for (name, surface, size) in surfaces() {
        let mut hits = 0;
        for _ in 0..400 {
            let uv = random_uv(&mut rng, &surface);
            let frame = surface.frame(uv.x, uv.y);
            let target = frame.p.as_dvec3();
            let eye = target + rng.unit_vector() * rng.range(0.5, 4.0) * size;
            let direction = target - eye;
            // The f32 target may sit a hair off the surface: a ray grazing it there may rightly
            // miss. Grazing rays have their own tests.
            if frame.n.as_dvec3().dot(direction.normalize()).abs() < 0.05 {
                hits += 1;
                continue;
            }
            let ray = Ray {
                origin: eye,
                direction,
            };
            let hit = intersect(&surface, &ray, 1e-9..=1.0 + 1e-4)
                .unwrap_or_else(|| panic!("{name}: missed {uv} from {eye}"));
            hits += 1;
            let p = ray.at(hit.t);
            let back = surface.frame(hit.uv.x, hit.uv.y).p.as_dvec3();
            assert!(
                (back - p).length() <= 1e-4 * size,
                "{name}: frame({}) = {back} but the hit is {p}",
                hit.uv
            );
        }
        assert_eq!(hits, 400);
    }
}

#[test]
fn inversion_undoes_the_frame_away_from_seams_and_poles() {
    let mut rng = XorShift(0x0dd_ba11);
    for (name, surface, size) in surfaces() {
        for _ in 0..400 {
            let uv = random_uv(&mut rng, &surface);
            let back = surface_uv(&surface, surface.frame(uv.x, uv.y).p.as_dvec3());
            let d = surface.domain();
            // f32 frames: about 1e-6 of the surface's size, magnified near the axis for the azimuth.
            let tolerance = (d.max - d.min) * 1e-3;
            assert!(
                (back - uv).abs().cmple(tolerance).all(),
                "{name}: {uv} came back as {back} (size {size})"
            );
        }
    }
}

#[test]
fn sphere_inversion_follows_the_seed_convention() {
    let sphere = Surface::Sphere(Sphere {
        center: DVec3::ZERO,
        radius: 2.0,
    });
    let uv = |p: [f64; 3]| surface_uv(&sphere, DVec3::from(p));
    // Facing +Z at the equator is u = 180, v = 180; u grows towards +X; the +Y pole is v = 0.
    assert!((uv([0.0, 0.0, 2.0]) - Vec2::new(180.0, 180.0)).length() < 1e-3);
    assert!((uv([2.0, 0.0, 0.0]).x - 360.0).abs() < 1e-3);
    assert!(uv([0.0, 2.0, 0.0]).y.abs() < 1e-3);
    assert!((uv([0.0, -2.0, 0.0]).y - 360.0).abs() < 1e-3);
    // The seam (−Z side) wraps into [0, 720).
    for x in [1e-9, -1e-9, 0.0] {
        let u = uv([x, 0.0, -2.0]).x;
        assert!((0.0..720.0).contains(&u), "u = {u}");
    }
}

#[test]
fn misses_and_ranges_are_respected() {
    for (name, surface, size) in surfaces() {
        let far_away = Ray {
            origin: DVec3::splat(50.0 * size),
            direction: DVec3::splat(1.0),
        };
        assert!(
            intersect(&surface, &far_away, 0.0..=1e9).is_none(),
            "{name}"
        );
        // A ray at a surface point, with the range ending before it, finds nothing there.
        let target = surface.frame(0.0, 0.0).p.as_dvec3();
        let ray = Ray {
            origin: target + DVec3::new(0.3, 3.0, 0.2) * size,
            direction: DVec3::new(-0.3, -3.0, -0.2) * size,
        };
        if let Some(hit) = intersect(&surface, &ray, 0.0..=0.5) {
            assert!(hit.t <= 0.5, "{name}");
        }
    }
}

#[test]
fn wave_finds_the_first_of_many_crossings_at_grazing_angles() {
    let wave = Wave {
        origin: DVec3::ZERO,
        size: Vec2::new(1000.0, 10.0),
        amplitude: 5.0,
        wavelength: 20.0,
    };
    let surface = Surface::Wave(wave.clone());
    // Almost along the crests: the ray dips into the first trough-side flank it meets.
    let ray = Ray {
        origin: DVec3::new(-1.0, 4.9, -5.0),
        direction: DVec3::new(1.0, -1e-4, 0.0),
    };
    let hit = intersect(&surface, &ray, 0.0..=1e6).expect("grazing ray hits the first crest");
    let p = ray.at(hit.t);
    let height = 5.0 * (std::f64::consts::TAU / 20.0 * p.x).sin();
    assert!((p.y - height).abs() < 1e-9, "{p} vs height {height}");
    // The first crest is at x = 5: the ray at y ≈ 4.9 meets its rising flank before it.
    assert!(p.x > 0.0 && p.x < 5.0, "{p}");
}

/// The torus's quartic against its implicit form sampled along the ray: its hit is where the
/// sign first changes (to within the sampling step), and a ray on which the sign never changes
/// misses. Rays from all around, many through the hole, many grazing.
#[test]
fn torus_hits_are_the_first_sign_change_of_its_implicit_form() {
    let (big, small) = (200.0, 80.0);
    let torus = Surface::Torus(Torus {
        center: DVec3::ZERO,
        basis: AxisBasis::from_axis(Vec3::Y),
        major_radius: big as f32,
        minor_radius: small as f32,
    });
    let inside = |p: DVec3| (p.x.hypot(p.z) - big).hypot(p.y) < small;
    let mut rng = XorShift(0x7042_5eed);
    let (mut hits, mut misses) = (0, 0);
    for _ in 0..2000 {
        let eye = rng.unit_vector() * rng.range(300.0, 1500.0);
        let aim = DVec3::new(
            rng.range(-300.0, 300.0),
            rng.range(-90.0, 90.0),
            rng.range(-300.0, 300.0),
        );
        let ray = Ray {
            origin: eye,
            direction: aim - eye,
        };
        let steps = 20_000;
        let span = 3.0;
        let first_change = (1..=steps)
            .map(|i| span * i as f64 / steps as f64)
            .find(|&t| inside(ray.at(t)) != inside(eye));
        let step = span / steps as f64;
        match (intersect(&torus, &ray, 0.0..=span), first_change) {
            (Some(hit), Some(t)) => {
                hits += 1;
                assert!(
                    hit.t <= t && hit.t >= t - step,
                    "hit at {} vs sign change at {t}",
                    hit.t
                );
            }
            (None, None) => misses += 1,
            // A ray that only grazes the tube between two samples: it leaves again within a step.
            (Some(hit), None) => {
                let out = intersect(&torus, &ray, hit.t * (1.0 + 1e-12)..=span);
                assert!(
                    out.is_some_and(|out| out.t - hit.t <= step),
                    "{hit:?} on {ray:?}"
                );
            }
            (None, Some(t)) => panic!("missed a crossing at {t} on {ray:?}"),
        }
    }
    assert!(hits > 500 && misses > 200, "{hits} hits, {misses} misses");
}
