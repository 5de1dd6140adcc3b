//! `bumpwork bake`: one material's bump and colour over a (u,v) rectangle as PNG maps other
//! programs take: `NAME-height.png` (16-bit grey, its range in the file's text and printed),
//! `NAME-normal.png` (tangent space, 8-bit, from the bump's exact gradient) and, for colour
//! patterns and image textures, `NAME-color.png` (8-bit sRGB). Each map carries the bake's recipe,
//! which `--from` bakes again.

use super::bake_recipe::{BakeRecipe, TileRect};
use bumpwork::Error;
use bumpwork::export::{MapPng, write_map_png};
use bumpwork::overrides::{Override, apply_to_scene};
use bumpwork::pattern::{OutputKind, Pattern};
use bumpwork::scene::{Object, Scene, load_pattern, put_pattern_on};
use bumpwork::shade::{BakeGrid, bake_bump_on, bake_color_on};
use bumpwork::texture::NormalConvention;
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct BakeArgs {
    /// A pattern file (.pat), a shipped pattern's name (on the lecture's 400 × 400 plane), or a
    /// scene (a built-in name or a .toml file) with `:OBJECT` to pick an object (from 1).
    #[arg(required_unless_present = "from")]
    source: Option<String>,
    /// The directory the maps are written to (made if missing).
    #[arg(short, long)]
    output: PathBuf,
    /// The maps' size in pixels: N (square) or WIDTHxHEIGHT [default: 1024].
    #[arg(long, value_parser = parse_map_size)]
    size: Option<(u32, u32)>,
    /// The (u,v) rectangle to bake: U0..U1,V0..V1, or W,H for 0..W,0..H (one period of a
    /// pattern bakes a seamless tile) [default: the surface's whole domain].
    #[arg(long, value_parser = TileRect::parse)]
    tile: Option<TileRect>,
    /// Which way the normal map's green points: opengl (+Y: Blender, Godot) or directx (−Y)
    /// [default: opengl].
    #[arg(long, value_enum)]
    normal_convention: Option<NormalConvention>,
    /// A setting, KEY=VALUE (repeatable), as `render --set` takes it.
    #[arg(long, value_parser = Override::parse)]
    set: Vec<Override>,
    /// Scene time in seconds, for animated patterns [default: the scene's].
    #[arg(long, allow_negative_numbers = true, value_parser = super::render::parse_time)]
    time: Option<f64>,
    /// Bake again what a map made by `bumpwork bake` was baked from (options given here win).
    #[arg(long, conflicts_with = "source")]
    from: Option<PathBuf>,
}

/// The default map side.
const DEFAULT_SIDE: u32 = 1024;
/// The longest map side.
const MAX_MAP_SIDE: u32 = 16384;
/// What one texel of a bake holds at its peak: height, normal, colour and their encodings.
const BYTES_PER_TEXEL: u64 = 4 + 12 + 12 + 6;

pub fn run(args: BakeArgs) -> Result<(), Error> {
    let recipe = recipe_of(&args)?;
    let (name, object, scene_time) = baked_object(&recipe)?;
    let grid = grid_of(&recipe, &object)?;
    std::fs::create_dir_all(&args.output).map_err(|e| Error::write(&args.output, e))?;
    let text = recipe.to_text();
    let maps = Maps {
        dir: &args.output,
        name: &name,
        recipe: &text,
        grid: &grid,
    };
    let time = recipe.time.unwrap_or(scene_time);
    let material = &object.material;
    let mut wrote = 0;
    if let Some(bump) = &material.bump {
        let baked = bake_bump_on(&object.surface, bump, time, &grid);
        if let Some(heights) = &baked.heights {
            maps.height(heights)?;
        } else {
            eprintln!(
                "bumpwork: {}: a slope pattern or normal map has no height; baked its normals only",
                super::sanitized(&name)
            );
        }
        maps.normal(&baked.normals, recipe.convention)?;
        wrote += 1;
    }
    if material.texture.is_some() {
        maps.color(&bake_color_on(&object.surface, material, time, &grid))?;
        wrote += 1;
    }
    if wrote == 0 {
        return Err(Error::InvalidArgument(format!(
            "{} has neither a bump nor a texture to bake",
            super::sanitized(&name)
        )));
    }
    Ok(())
}

/// The bake asked for: the command line, over the recipe of `--from`'s map where given.
fn recipe_of(args: &BakeArgs) -> Result<BakeRecipe, Error> {
    let base = match &args.from {
        Some(map) => BakeRecipe::read_from(map)?,
        None => BakeRecipe::of_source(args.source.clone().expect("clap requires a source")),
    };
    Ok(BakeRecipe {
        size: args.size.unwrap_or(base.size),
        tile: args.tile.or(base.tile),
        convention: args.normal_convention.unwrap_or(base.convention),
        set: match args.set.is_empty() {
            true => base.set,
            false => args.set.iter().map(|o| o.text().to_string()).collect(),
        },
        time: args.time.or(base.time),
        ..base
    })
}

/// The name the maps take, the object to bake and its scene's time.
fn baked_object(recipe: &BakeRecipe) -> Result<(String, Object, f64), Error> {
    let (mut scene, index, name) = source_scene(&recipe.source)?;
    let overrides = recipe
        .set
        .iter()
        .map(|text| Override::parse(text).map_err(Error::InvalidArgument))
        .collect::<Result<Vec<_>, _>>()?;
    apply_to_scene(&overrides, &mut scene).map_err(Error::InvalidArgument)?;
    let (count, time) = (scene.objects.len(), scene.time);
    let object = scene.objects.into_iter().nth(index).ok_or_else(|| {
        Error::InvalidArgument(format!(
            "{}: the scene has {count} objects, counted from 1",
            super::sanitized(&recipe.source)
        ))
    })?;
    Ok((name, object, time))
}

/// The scene `source` names, the index of the object to bake and the maps' name.
fn source_scene(source: &str) -> Result<(Scene, usize, String), Error> {
    let stem = |path: &str| {
        Path::new(path)
            .file_stem()
            .map_or_else(|| "bake".to_string(), |s| s.to_string_lossy().into_owned())
    };
    if source.ends_with(".pat") || bumpwork::pattern::builtin(source).is_some() {
        let pattern = load_pattern(source, Path::new("")).map_err(Error::Diagnostic)?;
        return Ok((on_plane(source, &pattern)?, 0, stem(source)));
    }
    let (scene_name, object) = match source.rsplit_once(':') {
        Some((scene, n)) if !scene.is_empty() && n.parse::<usize>().is_ok() => {
            let n: usize = n.parse().expect("checked");
            if n == 0 {
                return Err(Error::InvalidArgument(format!(
                    "'{}': an object is counted from 1",
                    super::sanitized(source)
                )));
            }
            (scene, n)
        }
        _ => (source, 1),
    };
    let scene = bumpwork::scene::load_source(scene_name)?;
    let name = match scene.objects.len() {
        1 => stem(scene_name),
        _ => format!("{}-{object}", stem(scene_name)),
    };
    Ok((scene, object - 1, name))
}

/// The lecture's plane (400 × 400 units of (u,v)) with `pattern` as its bump, or as its texture
/// and no bump.
fn on_plane(name: &str, pattern: &Pattern) -> Result<Scene, Error> {
    let mut scene = bumpwork::scene::resolve("plane-dimples")?;
    put_pattern_on(&mut scene, name, pattern);
    if pattern.output() == OutputKind::Color {
        scene.objects[0].material.bump = None;
    }
    Ok(scene)
}

/// The bake's grid: the tile (or the whole domain) at the size asked, within the memory budget.
fn grid_of(recipe: &BakeRecipe, object: &Object) -> Result<BakeGrid, Error> {
    if let bumpwork::surface::Surface::Model(_) = object.surface {
        return Err(Error::InvalidArgument(
            "a model's bump is baked from its pattern alone (`bumpwork bake PATTERN`): a model has \
             no point for each (u,v) of a map, and the map follows its (u,v) as it is"
                .into(),
        ));
    }
    let (width, height) = recipe.size;
    let bytes = u64::from(width) * u64::from(height) * BYTES_PER_TEXEL;
    let budget = bumpwork::memory_budget::budget_bytes();
    if bytes > budget {
        return Err(Error::InvalidArgument(format!(
            "a {width}×{height} bake needs about {}, more than the memory budget of {} \
             ({} sets it)",
            bumpwork::memory_budget::size_words(bytes),
            bumpwork::memory_budget::size_words(budget),
            bumpwork::memory_budget::MEMORY_BUDGET_VAR
        )));
    }
    let domain = object.surface.domain();
    let (min, max) = match recipe.tile {
        Some(tile) => (tile.min, tile.max),
        None => (domain.min, domain.max),
    };
    Ok(BakeGrid {
        min,
        max,
        width,
        height,
    })
}

/// Where the maps go and what they carry.
struct Maps<'a> {
    dir: &'a Path,
    name: &'a str,
    recipe: &'a str,
    grid: &'a BakeGrid,
}

impl Maps<'_> {
    fn path(&self, kind: &str) -> PathBuf {
        self.dir.join(format!("{}-{kind}.png", self.name))
    }

    fn write(&self, kind: &str, map: MapPng, extra: Vec<(&str, String)>) -> Result<(), Error> {
        let path = self.path(kind);
        let mut texts = vec![(bumpwork::export::BAKE_RECIPE, self.recipe.to_string())];
        texts.extend(extra);
        write_map_png(&path, (self.grid.width, self.grid.height), map, &texts)?;
        super::write_line(format_args!(
            "{}",
            super::sanitized(&path.display().to_string())
        ))
    }

    /// Heights as 16-bit grey over their range, which is printed and kept in the file.
    fn height(&self, heights: &[f32]) -> Result<(), Error> {
        let (levels, (lo, hi)) = bumpwork::export::height_levels(heights);
        let range = hi - lo;
        let range_text = format!("{lo}..{hi}");
        self.write(
            "height",
            MapPng::Grey16(&levels),
            vec![(bumpwork::export::HEIGHT_RANGE, range_text.clone())],
        )?;
        eprintln!(
            "bumpwork: heights {range_text} (black to white): as a bump image, strength = {range}"
        );
        Ok(())
    }

    /// Tangent-space normals, each channel from −1..1 to 0..255.
    fn normal(&self, normals: &[glam::Vec3], convention: NormalConvention) -> Result<(), Error> {
        let channel = |c: f32| ((c.clamp(-1.0, 1.0) * 0.5 + 0.5) * 255.0).round() as u8;
        let rgb: Vec<u8> = normals
            .iter()
            .flat_map(|n| [channel(n.x), channel(convention.green(n.y)), channel(n.z)])
            .collect();
        let note = (
            bumpwork::export::NORMAL_CONVENTION,
            convention.name().to_string(),
        );
        self.write("normal", MapPng::LinearRgb8(&rgb), vec![note])
    }

    /// Colours as 8-bit sRGB.
    fn color(&self, colors: &[glam::Vec3]) -> Result<(), Error> {
        let rgb: Vec<u8> = colors
            .iter()
            .flat_map(|c| c.to_array().map(bumpwork::raster::linear_to_srgb8))
            .collect();
        self.write("color", MapPng::SrgbRgb8(&rgb), Vec::new())
    }
}

/// `N` or `WIDTHxHEIGHT`, each side 1..=16384.
fn parse_map_size(text: &str) -> Result<(u32, u32), String> {
    let expected = || {
        format!(
            "expected N or WIDTHxHEIGHT with each side 1..={MAX_MAP_SIDE}, like 2048; got '{}'",
            bumpwork::diagnostic::shown_input(text)
        )
    };
    let side = |s: &str| {
        s.trim()
            .parse::<u32>()
            .ok()
            .filter(|n| (1..=MAX_MAP_SIDE).contains(n))
    };
    let size = match text.split_once(['x', 'X']) {
        Some((w, h)) => side(w).zip(side(h)),
        None => side(text).map(|n| (n, n)),
    };
    size.ok_or_else(expected)
}

impl BakeRecipe {
    /// A bake of `source` with every option at its default.
    pub fn of_source(source: String) -> BakeRecipe {
        BakeRecipe {
            source,
            size: (DEFAULT_SIDE, DEFAULT_SIDE),
            tile: None,
            convention: NormalConvention::default(),
            set: Vec::new(),
            time: None,
        }
    }
}
