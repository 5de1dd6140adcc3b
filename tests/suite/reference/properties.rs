//! Properties over random cameras and scenes (proptest): neither renderer writes a NaN or an
//! infinity, and the rasterizer's error against the reference shrinks as the tessellation grows.

use crate::reference::support::*;
use bumpwork::raster::Viewport;
use bumpwork::reference::metrics::{normal_angle_error, silhouette_mismatch};
use bumpwork::scene::{Scene, parse_scene};
use bumpwork::shade::ShaderMode;
use proptest::prelude::*;

const VIEWPORT: Viewport = Viewport {
    width: 48,
    height: 36,
};

const SURFACES: &[&str] = &[
    "sphere = { center = [0, 0, 0], radius = 100 }",
    "cone = { apex = [0, 100, 0], axis = [0, -1, 0], half-angle = 30, height = 200 }",
    "paraboloid = { apex = [0, -50, 0], axis = [0, 1, 0], curvature = 0.01, radius = 120 }",
    "wave = { origin = [-200, 0, 200], size = [400, 400], amplitude = 15, wavelength = 90 }",
    "triangle = { a = [-150, -50, 50], b = [150, -40, 0], c = [0, 150, -50] }",
    "plane = { origin = [-300, -100, 300], normal = [0, 1, 0], u-axis = [1, 0, 0], size = [600, 600] }",
];

fn random_scene(surface: usize, eye: [f64; 3], fov: f32, bump: bool) -> Scene {
    let bump = if bump {
        "bump = { pattern = \"dimples\", strength = 1 }\n"
    } else {
        ""
    };
    let text = format!(
        "ambient = [0.1, 0.1, 0.1]\n[camera]\neye = [{}, {}, {}]\ntarget = [0, 0, 0]\nfov = {fov}\n\
         [[light]]\npoint = {{ position = [-400, 600, 500], color = [0.9, 0.9, 0.9] }}\n\
         [[object]]\nsurface = {{ {} }}\ntexture = {{ pattern = \"checks\" }}\n{bump}",
        eye[0], eye[1], eye[2], SURFACES[surface]
    );
    parse_scene(&text, "random.toml").unwrap()
}

fn eye() -> impl Strategy<Value = [f64; 3]> {
    // Anywhere from inside the surfaces to far away, from every side.
    (-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0, 1.0f64..800.0).prop_map(|(x, y, z, r)| {
        let len = (x * x + y * y + z * z).sqrt().max(1e-3);
        [x / len * r, y / len * r + 0.5, z / len * r]
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    #[test]
    fn no_nan_or_infinity_from_any_camera(
        surface in 0..SURFACES.len(),
        eye in eye(),
        fov in 5.0f32..150.0,
        bump in any::<bool>(),
    ) {
        let scene = random_scene(surface, eye, fov, bump);
        for mode in [ShaderMode::Shaded, ShaderMode::Normals] {
            let pair = render_both(&scene, VIEWPORT, 16, |s| s.mode = mode);
            assert_all_finite(&pair.raster, "raster");
            assert_all_finite(&pair.reference, "reference");
        }
    }

    #[test]
    fn error_shrinks_as_tessellation_grows(
        surface in 0..4usize,
        eye in eye().prop_filter("outside the curved surfaces", |e| {
            (e[0] * e[0] + e[1] * e[1] + e[2] * e[2]).sqrt() > 350.0
        }),
        fov in 20.0f32..60.0,
    ) {
        let scene = random_scene(surface, eye, fov, true);
        let error = |density: u32| {
            let shaded = render_both(&scene, VIEWPORT, density, |_| {});
            let normals = render_both(&scene, VIEWPORT, density, |s| s.mode = ShaderMode::Normals);
            let angles = normal_angle_error(&normals.raster, &normals.reference);
            (silhouette_mismatch(&shaded.raster, &shaded.reference), angles.mean_degrees)
        };
        let (coarse, fine) = (error(4), error(64));
        // 16 times the density: the chord sag falls 256-fold. Allow a pixel and 0.05° of noise
        // (pixel centres that sit on an edge, f32 rounding) on top of "no worse".
        prop_assert!(fine.0 <= coarse.0 + 1, "silhouette {} -> {}", coarse.0, fine.0);
        prop_assert!(fine.1 <= coarse.1 + 0.05, "mean angle {} -> {}", coarse.1, fine.1);
    }
}
