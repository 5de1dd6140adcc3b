//! The built-in scenes: one per figure of the seed lecture, named as in DESIGN.md.
//! Geometry uses the seed's units: a 400-wide plane, a "big sphere" of radius 280.

use super::Scene;
use super::binding_file::{BindingFile, MappingKind};
use super::file::*;
use super::torus_file::TorusFile;
use glam::{DVec3, Vec3};

/// Every built-in scene name, in the lecture's order.
pub const PRESET_NAMES: &[&str] = &[
    "plane-spheres",
    "plane-horizontal-wave",
    "plane-vertical-wave",
    "plane-ripple",
    "plane-ripples",
    "plane-mesh",
    "plane-waffle",
    "plane-dimples",
    "plane-squares",
    "plane-dots-and-dimples",
    "sphere-on-plane-spheres",
    "sphere-on-plane-horizontal-wave",
    "sphere-on-plane-vertical-wave",
    "sphere-on-plane-ripple",
    "sphere-on-plane-ripples",
    "sphere-on-plane-mesh",
    "sphere-on-plane-waffle",
    "sphere-on-plane-dimples",
    "sphere-on-plane-squares",
    "wave-spheres",
    "parabola-spheres",
    "parabola-dimples",
    "parabola-squares",
    "big-sphere-dimples",
    "big-sphere-squares",
    "big-sphere-vertical-wave",
    "big-sphere-mesh",
    "cone-vertical-wave",
    "cone-dimples",
    "cone-ripple",
    "cone-ripples",
    "plane-image-bump",
    "sphere-image-bump",
    "plane-stripes",
    "plane-checks",
    "plane-stripes-and-checks",
    "planes-stripes-checks-image",
    "image-scroll",
    "two-planes-textured",
    "image-to-triangle",
    "textured-sphere",
    "textured-spheres",
    "plane-stucco",
    "plane-cobbles",
    "cone-bark",
    "rounded-cube-dimples",
    "torus-dimples",
    "torus-bricks",
    "big-sphere-dimples-displaced",
    "plane-dimples-displaced",
];

/// The built-in scene of that name, as a scene file (so it can be printed and edited).
pub fn preset_file(name: &str) -> Option<SceneFile> {
    if !PRESET_NAMES.contains(&name) {
        return None;
    }
    let mut file = geometry(name);
    dress(name, &mut file.objects);
    file.name = Some(name.to_string());
    Some(file)
}

/// The scene's surfaces, camera and lights.
fn geometry(name: &str) -> SceneFile {
    match name {
        _ if name.starts_with("sphere-on-plane-") => sphere_on_plane(),
        _ if name.starts_with("wave-") => wave(),
        _ if name.starts_with("parabola-") => parabola(),
        _ if name.starts_with("big-sphere-") => big_sphere(),
        _ if name.starts_with("cone-") => cone(),
        _ if name.starts_with("rounded-cube-") => rounded_cube(),
        _ if name.starts_with("torus-") => torus(),
        "sphere-image-bump" | "textured-sphere" => single_sphere(),
        "textured-spheres" => spheres_on_floor(),
        "planes-stripes-checks-image" => room_corner(),
        "two-planes-textured" | "plane-stripes-and-checks" => two_planes(),
        "image-to-triangle" => triangle(),
        "plane-stripes" | "plane-checks" => floor_plane(),
        _ => facing_plane(),
    }
}

/// The bump patterns and textures of each figure.
fn dress(name: &str, objects: &mut [ObjectFile]) {
    if let Some(twin) = name.strip_suffix("-displaced") {
        return displace_dimples(twin, objects);
    }
    if name.starts_with("torus-") {
        return objects[0].bump = Some(torus_bump(name));
    }
    // "textured-spheres" names its objects, not a bump pattern.
    let bump_pattern = BUMP_PATTERNS
        .iter()
        .filter(|_| !name.starts_with("textured-"))
        .find(|p| name.ends_with(&format!("-{p}")));
    if let Some(pattern) = bump_pattern {
        // The seed's dimples are its own slope code; every surface of the figure gets the pattern.
        let file = if *pattern == "dimples" {
            "dimples-seed"
        } else {
            pattern
        };
        for object in objects.iter_mut() {
            object.bump = Some(pattern_binding(file));
        }
        return;
    }
    let textures: &[Option<BindingFile>] = match name {
        "plane-image-bump" => return objects[0].bump = Some(image_bump("brick", 40.0, None)),
        "sphere-image-bump" => {
            return objects[0].bump =
                Some(image_bump("gravel", 25.0, Some(MappingKind::Spherical)));
        }
        "plane-stripes" => &[Some(pattern_binding("stripes"))],
        "plane-checks" => &[Some(pattern_binding("checks"))],
        "plane-stripes-and-checks" => &[
            Some(pattern_binding("checks")),
            Some(pattern_binding("stripes")),
        ],
        "planes-stripes-checks-image" => &[
            Some(pattern_binding("stripes")),
            Some(pattern_binding("checks")),
            Some(image_texture("chelsea", None)),
        ],
        "image-scroll" => &[Some(BindingFile {
            scroll: Some([Finite(0.1), Finite(0.0)]),
            ..image_texture("coffee", None)
        })],
        "two-planes-textured" => &[
            Some(BindingFile {
                scale: Some([Positive(200.0), Positive(200.0)]),
                ..image_texture("chelsea", None)
            }),
            Some(image_texture("coffee", None)),
        ],
        "image-to-triangle" => &[Some(image_texture("chelsea", Some(MappingKind::Triangle)))],
        "textured-sphere" => &[Some(image_texture("chelsea", Some(MappingKind::Spherical)))],
        "textured-spheres" => &[
            None,
            Some(image_texture("chelsea", Some(MappingKind::Spherical))),
            Some(image_texture("coffee", Some(MappingKind::Spherical))),
            Some(image_texture("gravel", Some(MappingKind::Spherical))),
        ],
        _ => &[],
    };
    for (object, texture) in objects.iter_mut().zip(textures) {
        object.texture = texture.clone();
    }
}

/// The lecture's bump patterns, named as in the scene names.
const BUMP_PATTERNS: &[&str] = &[
    "spheres",
    "horizontal-wave",
    "vertical-wave",
    "ripples",
    "ripple",
    "mesh",
    "waffle",
    "dots-and-dimples",
    "dimples",
    "squares",
    "stucco",
    "cobbles",
    "bark",
];

/// `twin`'s dimples as the new surface: the height form (`dimples.pat`, whose slope is the
/// seed's), displaced.
fn displace_dimples(twin: &str, objects: &mut [ObjectFile]) {
    dress(twin, objects);
    for object in objects.iter_mut() {
        object.bump = Some(pattern_binding("dimples"));
        object.displace = true;
    }
}

/// The torus's u turns around the ring, 2.5 times the tube's length (its major radius over its
/// minor one): features a fifth of the size along u come out square half way round the tube,
/// and 60 dimples or 30 bricks go round it without a seam.
fn torus_bump(name: &str) -> BindingFile {
    let scale = Some([Positive(0.4), Positive(1.0)]);
    if name == "torus-bricks" {
        BindingFile {
            scale,
            params: [("course".to_string(), 24.0)].into(),
            ..pattern_binding("bricks")
        }
    } else {
        BindingFile {
            scale,
            ..pattern_binding("dimples-seed")
        }
    }
}

fn pattern_binding(pattern: &str) -> BindingFile {
    BindingFile {
        pattern: Some(pattern.to_string()),
        ..BindingFile::default()
    }
}

fn image_texture(image: &str, mapping: Option<MappingKind>) -> BindingFile {
    BindingFile {
        image: Some(image.to_string()),
        mapping,
        ..BindingFile::default()
    }
}

fn image_bump(image: &str, strength: f32, mapping: Option<MappingKind>) -> BindingFile {
    BindingFile {
        strength: Some(Finite(strength)),
        ..image_texture(image, mapping)
    }
}

/// The built-in scene of that name, ready to render.
pub fn preset(name: &str) -> Option<Scene> {
    let file = preset_file(name)?;
    Some(
        file.to_scene(name, std::path::Path::new("."))
            .expect("built-in scenes are valid"),
    )
}

/// The preset name nearest to a mistyped one, if any is close.
pub fn closest_name(name: &str) -> Option<String> {
    PRESET_NAMES
        .iter()
        .map(|candidate| (edit_distance(name, candidate), candidate))
        .filter(|&(d, candidate)| d <= 3.max(candidate.len() / 4))
        .min()
        .map(|(_, c)| c.to_string())
}

fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let next = (diagonal + usize::from(ca != cb))
                .min(row[j] + 1)
                .min(row[j + 1] + 1);
            diagonal = row[j + 1];
            row[j + 1] = next;
        }
    }
    row[b.len()]
}

fn point(x: f64, y: f64, z: f64) -> Point {
    Point(DVec3::new(x, y, z))
}

fn direction(x: f32, y: f32, z: f32) -> Direction {
    Direction(Vec3::new(x, y, z))
}

fn material(r: f32, g: f32, b: f32) -> MaterialFile {
    MaterialFile {
        color: Rgb(Vec3::new(r, g, b)),
        ..MaterialFile::default()
    }
}

fn camera(eye: Point, target: Point, fov: f32) -> CameraFile {
    CameraFile {
        eye,
        target,
        up: direction(0.0, 1.0, 0.0),
        fov: FieldOfView(fov),
        near: None,
        far: None,
    }
}

fn key_light(x: f64, y: f64, z: f64) -> LightFile {
    LightFile::Point {
        position: point(x, y, z),
        color: Rgb(Vec3::splat(0.9)),
    }
}

fn scene(camera: CameraFile, lights: Vec<LightFile>, objects: Vec<ObjectFile>) -> SceneFile {
    SceneFile {
        name: None,
        camera,
        background: Rgb(Vec3::splat(0.02)),
        ambient: Rgb(Vec3::splat(0.08)),
        lights,
        objects,
        time: None,
        shadows: None,
        quality: Default::default(),
    }
}

fn object(surface: SurfaceFile, material: MaterialFile) -> ObjectFile {
    ObjectFile {
        surface,
        material,
        texture: None,
        bump: None,
        displace: false,
    }
}

/// An axis-aligned rectangle: `normal` and `u_axis` are world axes.
fn rectangle(
    origin: Point,
    normal: Direction,
    u_axis: Direction,
    width: f32,
    height: f32,
) -> SurfaceFile {
    SurfaceFile::Plane {
        origin,
        normal,
        u_axis,
        size: [Positive(width), Positive(height)],
    }
}

fn sphere(x: f64, y: f64, z: f64, radius: f32) -> SurfaceFile {
    SurfaceFile::Sphere {
        center: point(x, y, z),
        radius: Positive(radius),
    }
}

/// The ground y = 0, `half` units each way from the origin; v runs towards −z.
fn ground(half: f32) -> SurfaceFile {
    let h = half as f64;
    rectangle(
        point(-h, 0.0, h),
        direction(0.0, 1.0, 0.0),
        direction(1.0, 0.0, 0.0),
        2.0 * half,
        2.0 * half,
    )
}

/// The seed's 400×400 plane facing the viewer: u = h, v = 400 − row, as in `x = h − 200`.
fn facing_plane() -> SceneFile {
    scene(
        camera(point(0.0, 0.0, 780.0), point(0.0, 0.0, 0.0), 30.0),
        vec![key_light(-350.0, 350.0, 500.0)],
        vec![object(
            rectangle(
                point(-200.0, -200.0, 0.0),
                direction(0.0, 0.0, 1.0),
                direction(1.0, 0.0, 0.0),
                400.0,
                400.0,
            ),
            material(0.72, 0.72, 0.78),
        )],
    )
}

fn sphere_on_plane() -> SceneFile {
    scene(
        camera(point(0.0, 260.0, 620.0), point(0.0, 70.0, 0.0), 40.0),
        vec![key_light(-400.0, 600.0, 500.0)],
        vec![
            object(ground(600.0), material(0.55, 0.6, 0.7)),
            object(sphere(0.0, 100.0, 0.0, 100.0), material(0.8, 0.45, 0.3)),
        ],
    )
}

/// The shipped rounded cube (side 160) resting on the floor, its texture cross 640 units wide so
/// a face's 160 units of (u,v) are its 160 units of side, as on the floor.
fn rounded_cube() -> SceneFile {
    scene(
        camera(point(-180.0, 300.0, 560.0), point(0.0, 70.0, 0.0), 40.0),
        vec![key_light(-400.0, 600.0, 500.0)],
        vec![
            object(ground(600.0), material(0.55, 0.6, 0.7)),
            object(
                SurfaceFile::Mesh {
                    file: "rounded-cube".into(),
                    position: point(0.0, 80.0, 0.0),
                    scale: Positive(80.0),
                    uv_scale: Positive(640.0),
                },
                material(0.8, 0.45, 0.3),
            ),
        ],
    )
}

fn wave() -> SceneFile {
    scene(
        camera(point(0.0, 330.0, 520.0), point(0.0, 0.0, -30.0), 40.0),
        vec![key_light(-300.0, 500.0, 300.0)],
        vec![object(
            SurfaceFile::Wave {
                origin: point(-200.0, 0.0, 200.0),
                size: [Positive(400.0), Positive(400.0)],
                amplitude: Finite(20.0),
                wavelength: Positive(100.0),
            },
            material(0.5, 0.7, 0.6),
        )],
    )
}

fn parabola() -> SceneFile {
    scene(
        camera(point(0.0, 330.0, 560.0), point(0.0, 20.0, 0.0), 40.0),
        vec![key_light(-300.0, 600.0, 400.0)],
        vec![object(
            SurfaceFile::Paraboloid {
                apex: point(0.0, -120.0, 0.0),
                axis: direction(0.0, 1.0, 0.0),
                curvature: Positive(0.012),
                radius: Positive(150.0),
            },
            material(0.75, 0.65, 0.4),
        )],
    )
}

fn big_sphere() -> SceneFile {
    scene(
        camera(point(0.0, 0.0, 1100.0), point(0.0, 0.0, 0.0), 32.0),
        vec![key_light(-500.0, 500.0, 800.0)],
        vec![object(
            sphere(0.0, 0.0, 0.0, 280.0),
            material(0.7, 0.55, 0.75),
        )],
    )
}

fn cone() -> SceneFile {
    scene(
        camera(point(0.0, 120.0, 900.0), point(0.0, 0.0, 0.0), 35.0),
        vec![key_light(-400.0, 400.0, 600.0)],
        vec![object(
            SurfaceFile::Cone {
                apex: point(0.0, 160.0, 0.0),
                axis: direction(0.0, -1.0, 0.0),
                half_angle: HalfAngle(30.0),
                height: Positive(320.0),
            },
            material(0.6, 0.7, 0.85),
        )],
    )
}

fn torus() -> SceneFile {
    scene(
        camera(point(0.0, 300.0, 850.0), point(0.0, -10.0, 0.0), 35.0),
        vec![key_light(-400.0, 500.0, 600.0)],
        vec![object(
            SurfaceFile::Torus(TorusFile {
                center: point(0.0, 0.0, 0.0),
                axis: direction(0.0, 1.0, 0.35),
                major_radius: Positive(200.0),
                minor_radius: Positive(80.0),
            }),
            material(0.8, 0.55, 0.4),
        )],
    )
}

fn single_sphere() -> SceneFile {
    scene(
        camera(point(0.0, 0.0, 620.0), point(0.0, 0.0, 0.0), 32.0),
        vec![key_light(-400.0, 400.0, 600.0)],
        vec![object(
            sphere(0.0, 0.0, 0.0, 150.0),
            material(0.8, 0.8, 0.8),
        )],
    )
}

fn spheres_on_floor() -> SceneFile {
    scene(
        camera(point(0.0, 220.0, 700.0), point(0.0, 60.0, 0.0), 40.0),
        vec![key_light(-400.0, 600.0, 500.0)],
        vec![
            object(ground(700.0), material(0.5, 0.5, 0.55)),
            object(sphere(-180.0, 80.0, 0.0, 80.0), material(0.8, 0.8, 0.8)),
            object(sphere(30.0, 110.0, -60.0, 110.0), material(0.8, 0.8, 0.8)),
            object(sphere(220.0, 60.0, 60.0, 60.0), material(0.8, 0.8, 0.8)),
        ],
    )
}

/// Three planes parallel to the coordinate planes, meeting at a corner.
fn room_corner() -> SceneFile {
    scene(
        camera(point(380.0, 300.0, 520.0), point(0.0, 100.0, 0.0), 45.0),
        vec![key_light(300.0, 500.0, 400.0)],
        vec![
            object(
                rectangle(
                    point(0.0, 0.0, 400.0),
                    direction(0.0, 1.0, 0.0),
                    direction(1.0, 0.0, 0.0),
                    400.0,
                    400.0,
                ),
                material(0.8, 0.3, 0.3),
            ),
            object(
                rectangle(
                    point(0.0, 0.0, 0.0),
                    direction(0.0, 0.0, 1.0),
                    direction(1.0, 0.0, 0.0),
                    400.0,
                    400.0,
                ),
                material(0.3, 0.8, 0.8),
            ),
            object(
                rectangle(
                    point(0.0, 0.0, 400.0),
                    direction(1.0, 0.0, 0.0),
                    direction(0.0, 0.0, -1.0),
                    400.0,
                    400.0,
                ),
                material(0.8, 0.8, 0.8),
            ),
        ],
    )
}

fn two_planes() -> SceneFile {
    scene(
        camera(point(0.0, 250.0, 650.0), point(0.0, 100.0, 0.0), 45.0),
        vec![key_light(-200.0, 500.0, 500.0)],
        vec![
            object(ground(300.0), material(0.8, 0.8, 0.8)),
            object(
                rectangle(
                    point(-300.0, 0.0, -300.0),
                    direction(0.0, 0.0, 1.0),
                    direction(1.0, 0.0, 0.0),
                    600.0,
                    400.0,
                ),
                material(0.8, 0.8, 0.8),
            ),
        ],
    )
}

fn triangle() -> SceneFile {
    scene(
        camera(point(0.0, 0.0, 700.0), point(0.0, 0.0, 0.0), 35.0),
        vec![key_light(0.0, 200.0, 600.0)],
        vec![object(
            SurfaceFile::Triangle {
                a: point(-180.0, -150.0, 0.0),
                b: point(200.0, -120.0, -60.0),
                c: point(-20.0, 190.0, 40.0),
            },
            material(0.85, 0.85, 0.85),
        )],
    )
}

/// A large floor seen at an angle, crossing x = 0 and z = 0 where the seed's `x % 50` breaks.
fn floor_plane() -> SceneFile {
    scene(
        camera(point(0.0, 300.0, 600.0), point(0.0, 0.0, 0.0), 45.0),
        vec![key_light(-200.0, 600.0, 400.0)],
        vec![object(ground(1000.0), material(0.8, 0.8, 0.8))],
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_preset_builds_and_round_trips_through_toml() {
        for name in PRESET_NAMES {
            let file = preset_file(name).unwrap();
            let text = file.to_toml();
            let scene = super::super::parse_scene(&text, "preset.toml")
                .unwrap_or_else(|e| panic!("{name}: {e}"));
            assert_eq!(scene.name, *name);
            assert_eq!(scene.objects.len(), file.objects.len());
        }
    }

    #[test]
    fn a_scene_named_for_its_textures_wears_them_and_no_bump() {
        let file = preset_file("textured-spheres").unwrap();
        let images: Vec<bool> = file.objects.iter().map(|o| o.texture.is_some()).collect();
        assert_eq!(images, [false, true, true, true]);
        assert!(file.objects.iter().all(|o| o.bump.is_none()));
    }

    #[test]
    fn suggests_a_close_name() {
        assert_eq!(
            closest_name("plane-dimple").as_deref(),
            Some("plane-dimples")
        );
        assert_eq!(closest_name("completely-different-thing"), None);
    }
}
