//! Mappings from surfaces to texture space: coordinates, and Jacobians that agree with
//! the surfaces' own parameterisations, stay finite at poles and apexes, and do not
//! jump at the sphere's seam.

use std::f32::consts::{PI, TAU};

use bumpwork::texture::{
    Cylindrical, Mapped, Mapping, Planar, PlanarLayout, Scroll, Spherical, SurfacePoint, SurfaceUv,
    Texel, TexelGrid, Texture, TextureMapping, TriangleMap,
};
use glam::{Mat2, Vec2, Vec3};

/// Deterministic xorshift numbers in [0, 1).
struct Numbers(u32);

impl Numbers {
    fn next(&mut self) -> f32 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 17;
        self.0 ^= self.0 << 5;
        (self.0 >> 8) as f32 / (1 << 24) as f32
    }
}

fn close(a: f32, b: f32, tolerance: f32) -> bool {
    (a - b).abs() <= tolerance
}

fn assert_mat_close(a: Mat2, b: Mat2, tolerance: f32) {
    let diff = (a - b).to_cols_array();
    assert!(diff.iter().all(|d| d.abs() <= tolerance), "{a:?} vs {b:?}");
}

fn is_finite(m: &Mapped) -> bool {
    m.st.is_finite() && m.jacobian.is_finite()
}

/// Sphere of radius `r` at `c`: u longitude from +z toward +x, v colatitude from +y.
fn sphere_point(c: Vec3, r: f32, u: f32, v: f32) -> SurfacePoint {
    let (su, cu, sv, cv) = (u.sin(), u.cos(), v.sin(), v.cos());
    SurfacePoint {
        p: c + r * Vec3::new(sv * su, cv, sv * cu),
        pu: r * Vec3::new(sv * cu, 0.0, -sv * su),
        pv: r * Vec3::new(cv * su, -sv, cv * cu),
        uv: Vec2::new(u, v),
        time: 0.0,
    }
}

fn plane_point(p: Vec3) -> SurfacePoint {
    SurfacePoint {
        p,
        pu: Vec3::X,
        pv: Vec3::Y,
        uv: p.truncate(),
        time: 0.0,
    }
}

#[test]
fn planar_tiles_repeat_by_floored_modulo_across_zero() {
    let layout = PlanarLayout::Tile {
        size: Vec2::new(2.0, 4.0),
    };
    let plane = Planar::from_normal(Vec3::ZERO, Vec3::new(5.0, 0.0, 0.0), Vec3::Z, layout)
        .expect("valid plane");
    let st = |x: f32, y: f32| plane.map(&plane_point(Vec3::new(x, y, 0.0))).st;
    assert!(close(st(-0.5, 0.0).x, 0.75, 1e-6));
    assert!(close(st(0.5, 0.0).x, 0.25, 1e-6));
    // V points up the image, so one unit up is a quarter tile toward t = 0.
    assert!(close(st(0.0, 1.0).y, 0.75, 1e-6));
    let mut numbers = Numbers(7);
    for _ in 0..200 {
        let (x, y) = (numbers.next() * 40.0 - 20.0, numbers.next() * 40.0 - 20.0);
        let here = st(x, y);
        assert!(
            (0.0..1.0).contains(&here.x) && (0.0..1.0).contains(&here.y),
            "{here}"
        );
        for shifted in [st(x + 2.0, y), st(x - 6.0, y + 8.0)] {
            let wrapped = (here - shifted)
                .abs()
                .min(Vec2::ONE - (here - shifted).abs());
            assert!(wrapped.max_element() < 1e-4, "{here} vs {shifted}");
        }
    }
    let jacobian = plane.map(&plane_point(Vec3::new(-3.0, 1.0, 0.0))).jacobian;
    assert_mat_close(jacobian, Mat2::from_diagonal(Vec2::new(0.5, -0.25)), 1e-6);
}

#[test]
fn planar_stretch_fits_the_image_to_the_rectangle_on_a_tilted_plane() {
    let (u_axis, v_axis) = (Vec3::new(1.0, 0.0, 1.0), Vec3::new(0.0, 1.0, 0.0));
    let origin = Vec3::new(1.0, 2.0, 3.0);
    let layout = PlanarLayout::Stretch {
        min: Vec2::new(-10.0, -5.0),
        max: Vec2::new(10.0, 5.0),
    };
    let plane = Planar::new(origin, u_axis, v_axis, layout).unwrap();
    let at = |a: f32, b: f32| plane.map(&plane_point(origin + u_axis * a + v_axis * b)).st;
    assert!((at(-10.0, 5.0) - Vec2::ZERO).length() < 1e-5, "top-left");
    assert!((at(10.0, -5.0) - Vec2::ONE).length() < 1e-5, "bottom-right");
    assert!((at(0.0, 0.0) - Vec2::splat(0.5)).length() < 1e-5, "centre");
    assert!(Planar::new(origin, u_axis, u_axis * 2.0, layout).is_none());
}

#[test]
fn triangle_pins_image_points_to_corners_and_interpolates_between() {
    let corners = [
        Vec3::new(0.0, 0.0, 1.0),
        Vec3::new(3.0, 1.0, 0.0),
        Vec3::new(-1.0, 2.0, 2.0),
    ];
    let image = [
        Vec2::new(0.1, 0.9),
        Vec2::new(0.8, 0.7),
        Vec2::new(0.4, 0.05),
    ];
    let triangle = TriangleMap::new(corners, image).expect("not degenerate");
    let (e1, e2) = (corners[1] - corners[0], corners[2] - corners[0]);
    let point = |u: f32, v: f32| SurfacePoint {
        p: corners[0] + e1 * u + e2 * v,
        pu: e1,
        pv: e2,
        uv: Vec2::new(u, v),
        time: 0.0,
    };
    for (corner, expected) in [(point(0.0, 0.0), image[0]), (point(1.0, 0.0), image[1])] {
        assert!((triangle.map(&corner).st - expected).length() < 1e-5);
    }
    assert!((triangle.map(&point(0.0, 1.0)).st - image[2]).length() < 1e-5);
    let middle = triangle.map(&point(0.5, 0.5)).st;
    assert!((middle - (image[1] + image[2]) * 0.5).length() < 1e-5);
    // In barycentric parameters the Jacobian is just the image-space edges.
    let expected = Mat2::from_cols(image[1] - image[0], image[2] - image[0]);
    assert_mat_close(triangle.map(&point(0.2, 0.3)).jacobian, expected, 1e-5);
    assert!(TriangleMap::new([Vec3::ZERO, Vec3::X, Vec3::X * 2.0], image).is_none());
}

#[test]
fn sphere_jacobian_matches_the_parameterisation_everywhere_including_the_seam() {
    let sphere = Spherical::new(Vec3::new(1.0, -2.0, 0.5));
    let expected = Mat2::from_diagonal(Vec2::new(1.0 / TAU, 1.0 / PI));
    let mut numbers = Numbers(99);
    for _ in 0..500 {
        let u = numbers.next() * TAU;
        let v = 0.02 + numbers.next() * (PI - 0.04);
        let mapped = sphere.map(&sphere_point(Vec3::new(1.0, -2.0, 0.5), 3.0, u, v));
        assert_mat_close(mapped.jacobian, expected, 2e-3);
        assert!(close(mapped.st.y, v / PI, 1e-4));
        let s = (0.5 + u / TAU).fract();
        let wrapped = (mapped.st.x - s).abs().min(1.0 - (mapped.st.x - s).abs());
        assert!(wrapped < 1e-4, "u {u}: s {} vs {s}", mapped.st.x);
    }
}

#[test]
fn sphere_is_continuous_across_the_seam() {
    let sphere = Spherical::new(Vec3::ZERO);
    let seam = PI; // straight behind: atan2 switches from +π to −π here
    for v in [0.3, 1.0, PI / 2.0, 2.5] {
        let before = sphere.map(&sphere_point(Vec3::ZERO, 1.0, seam - 1e-3, v));
        let after = sphere.map(&sphere_point(Vec3::ZERO, 1.0, seam + 1e-3, v));
        let jump = (before.st.x - after.st.x).abs();
        assert!(jump.min(1.0 - jump) < 1e-3, "s jumps by {jump}");
        assert!(close(before.st.y, after.st.y, 1e-5));
        assert_mat_close(before.jacobian, after.jacobian, 1e-4);
    }
}

#[test]
fn sphere_poles_and_centre_are_finite() {
    let sphere = Spherical::new(Vec3::ZERO);
    for v in [0.0, 1e-7, PI - 1e-7, PI] {
        for u in [0.0, 1.0, PI] {
            let mut at = sphere_point(Vec3::ZERO, 2.0, u, v);
            assert!(is_finite(&sphere.map(&at)), "u {u} v {v}");
            // Even a surface whose u-partial does not vanish at the pole.
            at.pu = Vec3::new(1.0, 0.0, 1.0);
            assert!(is_finite(&sphere.map(&at)), "u {u} v {v}");
        }
    }
    let north = sphere.map(&sphere_point(Vec3::ZERO, 2.0, 0.0, 0.0));
    assert!(close(north.st.y, 0.0, 1e-6), "t = 0 at the north pole");
    assert!(is_finite(&sphere.map(&plane_point(Vec3::ZERO))));
}

#[test]
fn mip_level_is_finite_for_random_points_and_extreme_derivatives() {
    let texture = Texture::from_raster(TexelGrid::from_fn(64, 32, |x, _| Texel::splat(x as f32)));
    let coarsest = (texture.mip_chain().levels().len() - 1) as f32;
    let sphere = Spherical::new(Vec3::ZERO);
    let extremes = [
        0.0,
        1e-30,
        1e-3,
        1.0,
        1e30,
        f32::MAX,
        f32::INFINITY,
        f32::NAN,
    ];
    let mut numbers = Numbers(12345);
    for i in 0..2000 {
        let u = if i % 10 == 0 {
            PI
        } else {
            numbers.next() * TAU
        };
        let v = if i % 7 == 0 { 0.0 } else { numbers.next() * PI };
        let mapped = sphere.map(&sphere_point(Vec3::ZERO, 1.0, u, v));
        let pick = |n: &mut Numbers| extremes[(n.next() * extremes.len() as f32) as usize];
        let random = |n: &mut Numbers| (n.next() - 0.5) * 0.1;
        let duv_dx = if i % 2 == 0 {
            Vec2::new(pick(&mut numbers), -pick(&mut numbers))
        } else {
            Vec2::new(random(&mut numbers), random(&mut numbers))
        };
        let duv_dy = Vec2::new(random(&mut numbers), pick(&mut numbers));
        let lod = texture.level_of_detail(mapped.footprint(duv_dx, duv_dy));
        assert!(lod.is_finite() && (0.0..=coarsest).contains(&lod), "{lod}");
    }
}

#[test]
fn sphere_mip_level_does_not_change_at_the_seam() {
    let texture = Texture::from_raster(TexelGrid::from_fn(256, 128, |_, _| Texel::ONE));
    let sphere = Spherical::new(Vec3::ZERO);
    let duv = (Vec2::new(0.01, 0.0), Vec2::new(0.0, 0.01));
    let lod_at = |u: f32| {
        let mapped = sphere.map(&sphere_point(Vec3::ZERO, 1.0, u, 1.2));
        texture.level_of_detail(mapped.footprint(duv.0, duv.1))
    };
    let front = lod_at(0.0);
    for u in [PI - 1e-4, PI, PI + 1e-4] {
        assert!(close(lod_at(u), front, 1e-3), "{} vs {front}", lod_at(u));
    }
}

#[test]
fn cylinder_and_cone_follow_their_parameters_and_stay_finite_at_the_apex() {
    let (radius, height) = (2.0, 5.0);
    let cylinder = Cylindrical::new(Vec3::ZERO, height);
    let cone_point = |u: f32, v: f32, taper: bool| {
        let k = if taper { (height - v) / height } else { 1.0 };
        let dk = if taper { -1.0 / height } else { 0.0 };
        let ring = Vec3::new(u.sin(), 0.0, u.cos()) * radius;
        SurfacePoint {
            p: ring * k + Vec3::Y * v,
            pu: Vec3::new(u.cos(), 0.0, -u.sin()) * radius * k,
            pv: ring * dk + Vec3::Y,
            uv: Vec2::new(u, v),
            time: 0.0,
        }
    };
    let expected = Mat2::from_diagonal(Vec2::new(1.0 / TAU, -1.0 / height));
    for taper in [false, true] {
        for (u, v) in [(0.3, 1.0), (3.0, 4.0), (PI, 2.5)] {
            let mapped = cylinder.map(&cone_point(u, v, taper));
            assert_mat_close(mapped.jacobian, expected, 1e-4);
            assert!(close(mapped.st.y, 1.0 - v / height, 1e-5));
        }
        let apex = cylinder.map(&cone_point(1.0, height, taper));
        assert!(is_finite(&apex));
        assert!(close(apex.st.y, 0.0, 1e-6), "t = 0 at the top");
    }
}

#[test]
fn surface_uv_scales_and_offsets() {
    let mapping = SurfaceUv {
        scale: Vec2::new(2.0, -3.0),
        offset: Vec2::new(0.25, 1.0),
    };
    let mut at = plane_point(Vec3::ZERO);
    at.uv = Vec2::new(0.5, 0.25);
    let mapped = mapping.map(&at);
    assert!((mapped.st - Vec2::new(1.25, 0.25)).length() < 1e-6);
    assert_eq!(mapped.jacobian, Mat2::from_diagonal(Vec2::new(2.0, -3.0)));
}

#[test]
fn scroll_moves_with_time_modulo_one_and_keeps_the_jacobian() {
    let inner = Mapping::SurfaceUv(SurfaceUv::default());
    let scroll = Scroll {
        inner: Box::new(inner.clone()),
        velocity: Vec2::new(0.25, -0.1),
    };
    let mut at = plane_point(Vec3::ZERO);
    at.uv = Vec2::new(0.3, 0.6);
    let still = inner.map(&at);
    at.time = 3.0;
    let moved = scroll.map(&at);
    let shift = moved.st - still.st;
    assert!(
        close(shift.x, 0.75, 1e-5) && close(shift.y, 0.7, 1e-5),
        "{shift}"
    );
    assert_eq!(moved.jacobian, still.jacobian);
    at.time = 1e9;
    assert!(is_finite(&scroll.map(&at)));
    at.time = f32::INFINITY;
    assert!(is_finite(&scroll.map(&at)));
}

#[test]
fn oriented_sphere_puts_the_pole_on_its_axis() {
    let sphere = Spherical::oriented(Vec3::ZERO, Vec3::X, Vec3::Y).unwrap();
    let pole = sphere.map(&plane_point(Vec3::X * 4.0));
    assert!(close(pole.st.y, 0.0, 1e-6));
    let front = sphere.map(&plane_point(Vec3::Y * 4.0));
    assert!((front.st - Vec2::splat(0.5)).length() < 1e-6);
    assert!(Spherical::oriented(Vec3::ZERO, Vec3::X, Vec3::X).is_none());
}
