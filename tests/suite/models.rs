//! Models (OBJ meshes) in scenes: the rasterizer's fragments on a model are the exact
//! reference's, bumps shade it as the reference shades them, and bad model files are one line.

use crate::cli_support::{assert_user_error, bumpwork, run_ok, stderr, temp_dir};
use crate::common::render_with;
use crate::reference::support::{SMALL, raster_error, render_both};
use bumpwork::raster::{Fragment, RenderTarget};
use bumpwork::reference::render_reference;
use bumpwork::scene::PreparedScene;
use bumpwork::scene::preset;
use bumpwork::shade::{FrameObject, PerFragment};
use bumpwork::surface::Tessellation;
use glam::Vec3;

/// The point each fragment names on its object (in the colour channels), and the object in
/// the depth's place: a pixel on an edge two triangles share may name either, and the same point.
fn point_shader() -> PerFragment<impl Fn(&FrameObject, &Fragment) -> Vec3 + Sync> {
    PerFragment(|o: &FrameObject, f: &Fragment| {
        let surface = &o.prepared.surface;
        let p = surface.frame(f.uv.x, f.uv.y).p;
        if f.object == 1 { p } else { Vec3::splat(-1e6) }
    })
}

#[test]
fn a_models_fragments_are_where_the_exact_rays_meet_its_triangles() {
    let scene = preset("rounded-cube-dimples").unwrap();
    let prepared = PreparedScene::new(scene.clone(), Tessellation::default());
    let target = RenderTarget::new(&scene.camera, SMALL);
    let raster = render_with(&prepared, &target, &point_shader()).0;
    let reference = render_reference(&prepared, &scene.camera, SMALL, &point_shader()).0;
    let (mut compared, mut mismatched) = (0, 0);
    let on_model = |p: Vec3| p.x > -1e5;
    for i in 0..raster.color().len() {
        let (a, b) = (raster.color()[i], reference.color()[i]);
        match (on_model(a), on_model(b)) {
            (true, true) => {
                // Model units of a cube 160 across: a thousandth of a unit.
                compared += 1;
                assert!(
                    (a - b).abs().max_element() <= 1e-3,
                    "pixel {i}: raster {a} against reference {b}"
                );
            }
            (false, false) => {}
            _ => mismatched += 1,
        }
    }
    assert!(compared > 500, "only {compared} pixels of the model");
    assert!(
        mismatched <= 4,
        "{mismatched} pixels differ in coverage or object"
    );
}

/// The model is its own surface, so only pixels whose centre lies on an edge where the
/// texture's (u,v) jumps (one face's island to the next) or a shadow's edge may differ: two
/// of 3072 here, which set the PSNR (measured 39.1 dB, 0.04° mean normal error).
#[test]
fn a_bumped_model_shades_as_the_exact_reference_shades_it() {
    let scene = preset("rounded-cube-dimples").unwrap();
    let density = Tessellation::default().density;
    let error = raster_error(&scene, SMALL, density);
    eprintln!("rounded-cube-dimples: {error:?}");
    assert!(error.psnr_db >= 37.0, "{error:?}");
    assert!(error.mean_normal_angle_degrees <= 0.1, "{error:?}");
    assert!(error.silhouette_mismatch <= 4, "{error:?}");
    let pair = render_both(&scene, SMALL, density, |_| {});
    let (raster, reference) = (pair.raster.color(), pair.reference.color());
    let apart = (raster.iter().zip(reference))
        .filter(|(a, b)| (**a - **b).abs().max_element() > 0.05)
        .count();
    assert!(apart <= 4, "{apart} pixels differ by over 5 %");
}

/// A scene around the model file `name` in `dir`.
fn model_scene(dir: &std::path::Path, name: &str) -> std::path::PathBuf {
    let scene = dir.join("scene.toml");
    let text = format!(
        "[camera]\neye = [0, 0, 5]\ntarget = [0, 0, 0]\nfov = 40\n\
         [[light]]\npoint = {{ position = [3, 4, 5] }}\n\
         [[object]]\nsurface = {{ mesh = {{ file = \"{name}\" }} }}\n\
         bump = {{ pattern = \"dimples\" }}\n"
    );
    std::fs::write(&scene, text).unwrap();
    scene
}

const QUAD: &str = "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n\
                    vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n";

fn render(dir: &std::path::Path, model: &str, text: &[u8]) -> std::process::Output {
    std::fs::write(dir.join(model), text).unwrap();
    let scene = model_scene(dir, model);
    let still = dir.join("still.png");
    bumpwork(&[
        "render",
        scene.to_str().unwrap(),
        "-o",
        still.to_str().unwrap(),
        "--size",
        "64x48",
    ])
}

#[test]
fn bad_model_files_are_one_line_and_degenerate_triangles_are_left_out() {
    let dir = temp_dir("models-bad");
    let good = render(&dir, "quad.obj", QUAD.as_bytes());
    assert!(good.status.success(), "{}", stderr(&good));
    let no_uvs = "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nf 1 2 3\n";
    assert_user_error(
        &render(&dir, "bare.obj", no_uvs.as_bytes()),
        "no texture coordinates",
    );
    let nan = QUAD.replace("v 1 1 0", "v 1 nan 0");
    assert_user_error(
        &render(&dir, "nan.obj", nan.as_bytes()),
        "nan.obj:3:5: expected a finite number, found 'nan'",
    );
    let outside = QUAD.replace("f 1/1 2/2 3/3 4/4", "f 1/1 2/2 9/3");
    assert_user_error(
        &render(&dir, "outside.obj", outside.as_bytes()),
        "not a readable OBJ",
    );
    assert_user_error(
        &render(&dir, "binary.obj", b"v 0 0 0\n\xff\xfe\n"),
        "binary.obj:2:1: expected UTF-8 text",
    );
    assert_user_error(
        &render(&dir, "empty.obj", b"# nothing\n"),
        "it has no triangles",
    );
    let scene = model_scene(&dir, "missing.obj");
    let missing = bumpwork(&["check", scene.to_str().unwrap()]);
    assert_user_error(&missing, "missing.obj");
    // A face repeated onto a line: no area, left out; the model is the quad's other triangle.
    let degenerate = format!("{QUAD}v 2 2 0\nvt 0.5 0.5\nf 1/1 3/3 5/5\n");
    let said = bumpwork(&["check", &*render_and_path(&dir, "line.obj", &degenerate)]);
    assert!(said.status.success(), "{}", stderr(&said));
    let out = String::from_utf8_lossy(&said.stdout);
    assert!(out.contains("1 degenerate triangle left out"), "{out}");
}

/// Writes `text` as the model `name` and returns its scene's path.
fn render_and_path(dir: &std::path::Path, name: &str, text: &str) -> String {
    std::fs::write(dir.join(name), text).unwrap();
    model_scene(dir, name).to_str().unwrap().to_string()
}

#[test]
fn a_model_past_the_memory_budget_is_refused_before_it_is_read() {
    let dir = temp_dir("models-budget");
    // 200 000 triangles of text (3 MB): past a 16 MiB budget at the worst expansion.
    let mut text = String::from(QUAD);
    for _ in 0..200_000 {
        text.push_str("f 1/1 2/2 3/3\n");
    }
    std::fs::write(dir.join("big.obj"), text).unwrap();
    let scene = model_scene(&dir, "big.obj");
    let still = dir.join("still.png");
    let run = std::process::Command::new(env!("CARGO_BIN_EXE_bumpwork"))
        .args([
            "render",
            scene.to_str().unwrap(),
            "-o",
            still.to_str().unwrap(),
        ])
        .env("BUMPWORK_MEMORY_MIB", "16")
        .output()
        .unwrap();
    assert_user_error(&run, "over the 16 MiB memory budget");
    assert!(!still.exists());
}

/// `render --watch model.obj+my.pat`: saving the model or the pattern renders again; Ctrl-C ends
/// the watch.
#[test]
fn a_watched_model_and_its_pattern_render_again_when_either_is_saved() {
    use std::time::Duration;
    let dir = temp_dir("models-watch");
    let (model, pattern, still) = (dir.join("m.obj"), dir.join("p.pat"), dir.join("m.png"));
    std::fs::write(&model, QUAD).unwrap();
    std::fs::write(&pattern, "height = sin(u / 10)\n").unwrap();
    let source = format!("{}+{}", model.display(), pattern.display());
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_bumpwork"))
        .args(["render", &source, "--size", "48x32", "--watch", "-o"])
        .arg(&still)
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let read = || std::fs::read(&still).ok();
    let wait = |what: &str, condition: &dyn Fn() -> bool| {
        crate::cli_support::wait_until(what, Duration::from_secs(60), condition)
    };
    wait("the first still", &|| read().is_some());
    let first = read().unwrap();
    std::fs::write(&pattern, "height = 4 * sin(u / 3)\n").unwrap();
    wait("a still after the pattern's save", &|| {
        read().is_some_and(|b| b != first)
    });
    let second = read().unwrap();
    std::fs::write(&model, QUAD.replace("v 1 1 0", "v 1 1 0.8")).unwrap();
    wait("a still after the model's save", &|| {
        read().is_some_and(|b| b != second)
    });
    // SAFETY: kill only sends a signal to the process we started.
    assert_eq!(unsafe { libc::kill(child.id() as i32, libc::SIGINT) }, 0);
    let deadline = std::time::Instant::now() + Duration::from_secs(30);
    while child.try_wait().unwrap().is_none() {
        assert!(
            std::time::Instant::now() < deadline,
            "still watching after Ctrl-C"
        );
        std::thread::sleep(Duration::from_millis(20));
    }
    assert_eq!(child.wait().unwrap().code(), Some(0));
}

/// The quad as a glTF buffer: four positions, four (u,v) (glTF's v runs down), six indices.
fn quad_buffer() -> Vec<u8> {
    let positions: [f32; 12] = [-1., -1., 0., 1., -1., 0., 1., 1., 0., -1., 1., 0.];
    let uvs: [f32; 8] = [0., 1., 1., 1., 1., 0., 0., 0.];
    let indices: [u16; 6] = [0, 1, 2, 0, 2, 3];
    let mut bytes: Vec<u8> = positions.iter().flat_map(|f| f.to_le_bytes()).collect();
    bytes.extend(uvs.iter().flat_map(|f| f.to_le_bytes()));
    bytes.extend(indices.iter().flat_map(|i| i.to_le_bytes()));
    bytes
}

/// glTF JSON for the quad, its buffer at `uri` (`None`: the GLB's own).
fn quad_gltf(uri: Option<&str>) -> String {
    let buffer = match uri {
        Some(uri) => format!("{{\"byteLength\": 92, \"uri\": \"{uri}\"}}"),
        None => "{\"byteLength\": 92}".into(),
    };
    format!(
        r#"{{"asset": {{"version": "2.0"}}, "scene": 0, "scenes": [{{"nodes": [0]}}],
        "nodes": [{{"mesh": 0, "translation": [0, 0, 0.5]}}],
        "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0, "TEXCOORD_0": 1}}, "indices": 2}}]}}],
        "buffers": [{buffer}],
        "bufferViews": [{{"buffer": 0, "byteOffset": 0, "byteLength": 48}},
                        {{"buffer": 0, "byteOffset": 48, "byteLength": 32}},
                        {{"buffer": 0, "byteOffset": 80, "byteLength": 12}}],
        "accessors": [
          {{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
            "min": [-1, -1, 0], "max": [1, 1, 0]}},
          {{"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"}},
          {{"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}}]}}"#
    )
}

/// A GLB: the JSON chunk and the buffer as its BIN chunk.
fn quad_glb() -> Vec<u8> {
    let mut json = quad_gltf(None).into_bytes();
    while !json.len().is_multiple_of(4) {
        json.push(b' ');
    }
    let mut bin = quad_buffer();
    while !bin.len().is_multiple_of(4) {
        bin.push(0);
    }
    let total = 12 + 8 + json.len() + 8 + bin.len();
    let mut glb = b"glTF".to_vec();
    glb.extend(2u32.to_le_bytes());
    glb.extend((total as u32).to_le_bytes());
    glb.extend((json.len() as u32).to_le_bytes());
    glb.extend(b"JSON");
    glb.extend(json);
    glb.extend((bin.len() as u32).to_le_bytes());
    glb.extend(b"BIN\0");
    glb.extend(bin);
    glb
}

#[test]
fn gltf_models_read_their_buffers_only_from_beside_them() {
    let dir = temp_dir("models-gltf");
    std::fs::write(dir.join("quad.bin"), quad_buffer()).unwrap();
    let check = |name: &str| bumpwork(&["check", dir.join(name).to_str().unwrap()]);
    std::fs::write(dir.join("quad.gltf"), quad_gltf(Some("quad.bin"))).unwrap();
    let beside = check("quad.gltf");
    assert!(beside.status.success(), "{}", stderr(&beside));
    assert!(String::from_utf8_lossy(&beside.stdout).contains("a model of 2 triangles"));
    std::fs::write(dir.join("quad.glb"), quad_glb()).unwrap();
    let glb = render(&dir, "quad.glb", &quad_glb());
    assert!(glb.status.success(), "{}", stderr(&glb));
    // A buffer named outside the model's directory is refused, by name or through a link.
    let outside = dir.join("outside");
    std::fs::create_dir_all(&outside).unwrap();
    std::fs::write(outside.join("up.gltf"), quad_gltf(Some("../quad.bin"))).unwrap();
    assert_user_error(
        &check("outside/up.gltf"),
        "is not a plain name in the model's directory",
    );
    std::fs::write(outside.join("abs.gltf"), quad_gltf(Some("/etc/passwd"))).unwrap();
    assert_user_error(&check("outside/abs.gltf"), "is not a plain name");
    std::os::unix::fs::symlink(dir.join("quad.bin"), outside.join("link.bin")).unwrap();
    std::fs::write(outside.join("link.gltf"), quad_gltf(Some("link.bin"))).unwrap();
    assert_user_error(
        &check("outside/link.gltf"),
        "leads outside the model's directory",
    );
    std::fs::write(dir.join("short.bin"), &quad_buffer()[..40]).unwrap();
    std::fs::write(dir.join("short.gltf"), quad_gltf(Some("short.bin"))).unwrap();
    assert_user_error(&check("short.gltf"), "holds 40 bytes of the 92 it declares");
    std::fs::write(dir.join("junk.glb"), b"glTF\x02\0\0\0junk").unwrap();
    assert_user_error(&check("junk.glb"), "not a readable glTF model");
}

/// The rounded cube close up, its texture cross 640 units wide so a unit of (u,v) is a unit of
/// its side (a normal map's tilt does not stretch with the surface, a height's slope does),
/// with `bump`.
fn cube_scene(bump: &str) -> String {
    format!(
        "[camera]\neye = [-120, 200, 260]\ntarget = [0, 40, 0]\nfov = 40\n\
         [[light]]\npoint = {{ position = [-400, 600, 500] }}\n\
         [[object]]\nsurface = {{ mesh = {{ file = \"rounded-cube\", position = [0, 80, 0], \
         scale = 80, uv-scale = 640 }} }}\nbump = {bump}\n"
    )
}

/// A tangent-space normal map baked from a pattern shades a model as the pattern does: the
/// map is read in the model's MikkTSpace frame, the pattern's gradient in its (u,v) partials
/// turned to the same frame (measured 40.6 dB; 22.2 dB without bumps).
#[test]
fn a_baked_normal_map_shades_a_model_as_its_pattern_does() {
    let dir = temp_dir("models-normal-map");
    let maps = dir.join("maps");
    let maps_arg = maps.to_str().unwrap();
    run_ok(&[
        "bake", "dimples", "-o", maps_arg, "--size", "2048", "--tile", "640,640",
    ]);
    let render = |name: &str, bump: &str| {
        let scene = dir.join(format!("{name}.toml"));
        std::fs::write(&scene, cube_scene(bump)).unwrap();
        let still = dir.join(format!("{name}.png"));
        run_ok(&[
            "render",
            scene.to_str().unwrap(),
            "-o",
            still.to_str().unwrap(),
            "--size",
            "320x240",
            "--samples",
            "16",
        ]);
        crate::cli_support::decode_png(&still).2
    };
    let pattern = render("pattern", "{ pattern = \"dimples\" }");
    let map = render("map", "{ normal-map = \"maps/dimples-normal.png\" }");
    let flat = render("flat", "{ pattern = \"dimples\", strength = 0 }");
    let agreement = crate::graphics_support::psnr(&pattern, &map);
    let unbumped = crate::graphics_support::psnr(&pattern, &flat);
    eprintln!("normal map against pattern {agreement:.1} dB; unbumped {unbumped:.1} dB");
    assert!(
        agreement >= 38.0 && agreement > unbumped + 10.0,
        "the normal map is {agreement:.1} dB from the pattern, an unbumped cube {unbumped:.1} dB"
    );
}

/// Interpolated vertex normals are what a model is shaded with anyway: the knob leaves it as
/// it is (and does not look its texture (u,v) up as a chart).
#[test]
fn the_interpolated_normals_knob_leaves_a_model_as_it_is() {
    let dir = temp_dir("models-knobs");
    let still = |name: &str, extra: &[&str]| {
        let out = dir.join(name);
        let mut args = vec!["render", "rounded-cube-dimples", "--size", "96x72", "-o"];
        args.push(out.to_str().unwrap());
        args.extend(extra);
        run_ok(&args);
        crate::cli_support::decode_png(&out).2
    };
    let plain = still("plain.png", &[]);
    let interpolated = still(
        "interpolated.png",
        &["--set", "quality.normals=interpolated-vertex"],
    );
    assert_eq!(plain, interpolated);
}
