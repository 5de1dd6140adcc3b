//! What the fuzz targets run, one function a target. `tests/fuzz_regressions.rs` includes this
//! file too, so the saved crash inputs and corpora go through exactly the same code under
//! `cargo test`.
//!
//! Each function asserts the properties every input must keep, so the fuzzer counts a broken one
//! as a crash just like a panic: an error is one message with nothing in it that could steer a
//! terminal; what compiles evaluates to finite numbers; a decoded image has the size it claims.

use bumpwork::export::metadata::{RECIPE, SCENE, png_text, text_of};
use bumpwork::pattern::{BumpSample, Inputs, OutputKind, Pattern, Precision};
use bumpwork::still::Recipe;
use bumpwork::texture::{Encoding, Limits, decode_image};
use std::io::Cursor;
use std::path::Path;

/// Where fuzzed scenes and recipes live: nowhere, so the relative file names they hold name
/// nothing (absolute ones are still tried).
const NOWHERE: &str = "/nonexistent-bumpwork-fuzz";

/// Fuzzing limits: the same checks as the defaults, scaled down so one input stays cheap.
pub const IMAGE_LIMITS: Limits = Limits {
    max_width: 4096,
    max_height: 4096,
    max_bytes: 64 << 20,
};

/// An error as the user sees it: something said, and no control character but line breaks.
pub fn assert_printable(message: &str) {
    assert!(!message.trim().is_empty(), "an empty error message");
    if let Some(c) = message.chars().find(|&c| c.is_control() && c != '\n') {
        panic!("raw control character {c:?} in the message: {message:?}");
    }
}

/// Lex, parse, check and compile; then evaluate what compiles (values, gradients, colours) at
/// ordinary, negative and huge points (past 2^63, up to f32::MAX), with default and hostile
/// parameter values.
pub fn pattern(data: &[u8]) {
    let Ok(source) = std::str::from_utf8(data) else {
        return;
    };
    match Pattern::compile(source, "fuzz.pat") {
        Ok(pattern) => evaluate(&pattern),
        Err(error) => {
            assert!(error.line >= 1 && error.column >= 1, "{error}");
            assert_printable(&error.to_string());
        }
    }
}

const COORDS: [f32; 10] = [
    0.0,
    1.5,
    -37.25,
    400.0,
    1.0e7,
    -3.0e9,
    9.3e18,
    -1.0e19,
    3.0e38,
    -f32::MAX,
];

fn evaluate(pattern: &Pattern) {
    let a: Vec<f32> = COORDS.to_vec();
    let b: Vec<f32> = COORDS.iter().rev().copied().collect();
    let inputs = |t, precision| Inputs {
        u: &a,
        v: &b,
        x: &b,
        y: &a,
        z: &a,
        x_u: &a,
        x_v: &b,
        y_u: &b,
        y_v: &a,
        z_u: &a,
        z_v: &b,
        t,
        precision,
    };
    let hostile: Vec<f32> = [f32::MAX, f32::NEG_INFINITY, f32::NAN, -1.0e30, 0.0]
        .iter()
        .copied()
        .cycle()
        .take(pattern.params().len())
        .collect();
    let mut scratch = pattern.scratch();
    let runs = [(0.0, &[][..]), (1.0e7, &hostile[..]), (-1.0e300, &[][..])];
    let precisions = [Precision::Fastest, Precision::Double];
    for ((t, params), precision) in runs.into_iter().flat_map(|r| precisions.map(|p| (r, p))) {
        let inputs = inputs(t, precision);
        match pattern.output() {
            OutputKind::Color => {
                let mut out = vec![[0.0; 3]; a.len()];
                pattern.eval_color(&inputs, params, &mut scratch, &mut out);
                assert!(out.iter().flatten().all(|c| (0.0..=1.0).contains(c)));
            }
            kind => {
                let mut out = vec![BumpSample::default(); a.len()];
                pattern.eval_bump(&inputs, params, &mut scratch, &mut out);
                let finite =
                    |s: &BumpSample| s.height.is_finite() && s.du.is_finite() && s.dv.is_finite();
                assert!(out.iter().all(finite), "{out:?}");
                if kind == OutputKind::Height {
                    let mut heights = vec![0.0; a.len()];
                    pattern.eval_height(&inputs, params, &mut scratch, &mut heights);
                    assert!(heights.iter().all(|h| h.is_finite()), "{heights:?}");
                }
            }
        }
    }
}

/// Scene text, parsed and checked as `bumpwork check` and `render` read it.
pub fn scene(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let origin = format!("{NOWHERE}/fuzz.toml");
    if let Err(error) = bumpwork::scene::parse_scene(text, &origin) {
        assert_printable(&error.to_string());
    }
}

/// An OBJ model read as a scene reads one: refused with a printable message, or made into
/// finite triangles whose chart names each one back and that a ray through one meets.
pub fn obj(data: &[u8]) {
    match bumpwork::model::parse_obj(data, "fuzz.obj") {
        Ok(raw) => assert_model(raw),
        Err(error) => assert_printable(&error.to_string()),
    }
}

/// A glTF or GLB model read with no directory beside it (a buffer file is refused, as one
/// outside the model's directory is), with `obj`'s properties.
pub fn gltf(data: &[u8]) {
    match bumpwork::model::parse_gltf(data, Path::new("fuzz.glb"), None) {
        Ok(raw) => assert_model(raw),
        Err(error) => assert_printable(&error.to_string()),
    }
}

/// Triangles made into a model are finite, their chart names each one back, and a ray through
/// one meets it.
fn assert_model(raw: bumpwork::model::RawTriangles) {
    let model = bumpwork::model::model_data(raw, bumpwork::model::AS_IT_IS);
    for corner in &model.corners {
        assert!(corner.p.is_finite() && corner.n.is_finite() && corner.uv.is_finite());
        assert!(
            (corner.n.length() - 1.0).abs() < 1e-3,
            "normal {:?}",
            corner.n
        );
    }
    for t in (0..model.corners.len() / 3).take(64) {
        let chart = model.chart_uv(t, 0.25, 0.25);
        assert_eq!(model.locate(chart).0, t, "the chart names triangle {t}");
        let [a, b, c] = [0, 1, 2].map(|k| model.triangle(t)[k].p.as_dvec3());
        let centre = (a + b + c) / 3.0;
        let normal = (b - a).cross(c - a).normalize();
        let hit = model.bvh.intersect(
            &model.corners,
            centre + normal,
            -normal,
            &(0.0..=f64::INFINITY),
        );
        assert!(hit.is_some(), "no hit through triangle {t}'s centre");
    }
}

/// An image decoded through our header checks and limits; the first byte picks the file name's
/// extension, which decides for TGA (no signature) and names the format in messages.
pub fn image(data: &[u8]) {
    let Some((&pick, bytes)) = data.split_first() else {
        return;
    };
    let names = ["f.png", "f.jpg", "f.ppm", "f.pgm", "f.bmp", "f.tga", "f"];
    let name = Path::new(names[usize::from(pick) % names.len()]);
    match decode_image(bytes, name, &IMAGE_LIMITS, Encoding::Srgb) {
        Ok(image) => {
            let (width, height) = (image.info.width, image.info.height);
            assert!((1..=IMAGE_LIMITS.max_width).contains(&width));
            assert!((1..=IMAGE_LIMITS.max_height).contains(&height));
            assert_eq!(
                (image.texels.width(), image.texels.height()),
                (width, height)
            );
        }
        Err(error) => assert_printable(&error.to_string()),
    }
}

/// A PNG's text chunks, and the recipe and scene a still carries, as `render --from` reads
/// them. Data that is not a PNG is taken as recipe text itself, so the recipe parser is fuzzed
/// directly too.
pub fn png_metadata(data: &[u8]) {
    let origin = format!("{NOWHERE}/still.png");
    if data.starts_with(b"\x89PNG") {
        match png_text(Cursor::new(data), Path::new(&origin)) {
            Ok(texts) => {
                let path = Path::new(&origin);
                if let (Ok(recipe), Ok(scene)) =
                    (text_of(&texts, RECIPE, path), text_of(&texts, SCENE, path))
                {
                    recipe_and_scene(recipe, scene);
                }
            }
            Err(error) => assert_printable(&error.to_string()),
        }
    } else if let Ok(text) = std::str::from_utf8(data) {
        let scene = bumpwork::scene::source_text("plane-dimples").expect("a built-in scene");
        recipe_and_scene(text, &scene);
    }
}

fn recipe_and_scene(recipe: &str, scene: &str) {
    match Recipe::parse(recipe, "still.png (bumpwork-recipe)") {
        Ok(recipe) => {
            if let Err(error) = recipe.scene(scene, &recipe.source_directory()) {
                assert_printable(&error.to_string());
            }
        }
        Err(error) => assert_printable(&error.to_string()),
    }
}
