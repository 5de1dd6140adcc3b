//! Live edits of one object's material: which bump pattern and colour pattern it wears, the bump's
//! strength and sign, and the values of its patterns' parameters.

use super::image_shelf::ImageShelf;
use crate::pattern::{BUILTINS, OutputKind, Pattern};
use crate::scene::{Bump, BumpSource, Material, PatternBinding, Placement, Texturing};
use crate::surface::Surface;

/// The built-in patterns of one kind (bump or colour), in the order they are shipped.
fn builtins_of(colour: bool) -> Vec<(&'static str, Pattern)> {
    BUILTINS
        .iter()
        .filter_map(|&(name, source)| Some((name, Pattern::compile(source, name).ok()?)))
        .filter(|(_, p)| (p.output() == OutputKind::Color) == colour)
        .collect()
}

/// Something the pattern or texture keys put on an object: a shipped pattern or an image.
enum Choice {
    Pattern(&'static str, Pattern),
    Image(String),
}

impl Choice {
    fn name(&self) -> &str {
        match self {
            Choice::Pattern(name, _) => name,
            Choice::Image(name) => name,
        }
    }
}

/// The shipped patterns of one kind, then the shelf's images.
fn choices(colour: bool, images: &ImageShelf) -> Vec<Choice> {
    let patterns = builtins_of(colour).into_iter();
    let images = images.names().iter().cloned().map(Choice::Image);
    patterns
        .map(|(name, pattern)| Choice::Pattern(name, pattern))
        .chain(images)
        .collect()
}

/// The next (`step` = 1) or previous choice after the one named `current`, wrapping.
fn cycle<'a>(list: &'a [Choice], current: Option<&str>, step: i32) -> &'a Choice {
    let position = current.and_then(|name| list.iter().position(|c| c.name() == name));
    let index = match position {
        Some(i) => (i as i32 + step).rem_euclid(list.len() as i32) as usize,
        None if step >= 0 => 0,
        None => list.len() - 1,
    };
    &list[index]
}

fn binding(name: String, pattern: Pattern, placement: Placement) -> PatternBinding {
    let params = pattern.params().iter().map(|p| p.default).collect();
    PatternBinding {
        name,
        pattern,
        params,
        placement,
    }
}

/// The material's bump pattern, if its bump is a pattern.
pub fn bump_pattern(material: &Material) -> Option<&PatternBinding> {
    match &material.bump.as_ref()?.source {
        BumpSource::Pattern(binding) => Some(binding),
        BumpSource::Image(_) | BumpSource::NormalMap(_) => None,
    }
}

fn bump_pattern_mut(material: &mut Material) -> Option<&mut PatternBinding> {
    match &mut material.bump.as_mut()?.source {
        BumpSource::Pattern(binding) => Some(binding),
        BumpSource::Image(_) | BumpSource::NormalMap(_) => None,
    }
}

/// Puts the next or previous shipped bump pattern or image on the material (on `surface`),
/// keeping a pattern's placement and the sign; the strength is kept unless the kind changes.
/// Returns the new bump's name.
pub fn cycle_bump(
    material: &mut Material,
    surface: &Surface,
    step: i32,
    images: &mut ImageShelf,
) -> Result<String, String> {
    let list = choices(false, images);
    let current = material.bump.as_ref().map(|b| match &b.source {
        BumpSource::Pattern(binding) => binding.name.clone(),
        BumpSource::Image(image) => image.name.clone(),
        BumpSource::NormalMap(map) => map.name.clone(),
    });
    let choice = cycle(&list, current.as_deref(), step);
    let placement = bump_pattern(material).map_or_else(Placement::default, |b| b.placement);
    let source = match choice {
        Choice::Pattern(name, pattern) => {
            BumpSource::Pattern(binding(name.to_string(), pattern.clone(), placement))
        }
        Choice::Image(name) => BumpSource::Image(images.height(name, surface)?),
    };
    let was_image = matches!(
        material.bump.as_ref().map(|b| &b.source),
        Some(BumpSource::Image(_))
    );
    let is_image = matches!(source, BumpSource::Image(_));
    let strength = match (&material.bump, was_image == is_image) {
        (Some(bump), true) => bump.strength,
        _ if is_image => crate::scene::IMAGE_BUMP_STRENGTH,
        _ => 1.0,
    };
    let invert = material.bump.as_ref().is_some_and(|b| b.invert);
    material.bump = Some(Bump {
        source,
        strength,
        invert,
    });
    Ok(choice.name().to_string())
}

/// Puts the next or previous shipped colour pattern or image on the material (on `surface`) as
/// its texture, keeping a pattern's placement. Returns the new texture's name.
pub fn cycle_texture(
    material: &mut Material,
    surface: &Surface,
    step: i32,
    images: &mut ImageShelf,
) -> Result<String, String> {
    let list = choices(true, images);
    let current = material.texture.as_ref().map(|t| match t {
        Texturing::Pattern(binding) => binding.name.clone(),
        Texturing::Image(image) => image.name.clone(),
    });
    let choice = cycle(&list, current.as_deref(), step);
    let placement = texture_pattern(material).map_or_else(Placement::default, |b| b.placement);
    material.texture = Some(match choice {
        Choice::Pattern(name, pattern) => {
            Texturing::Pattern(binding(name.to_string(), pattern.clone(), placement))
        }
        Choice::Image(name) => Texturing::Image(images.texture(name, surface)?),
    });
    Ok(choice.name().to_string())
}

/// Multiplies the bump strength; false if the material has no bump.
pub fn scale_bump(material: &mut Material, factor: f32) -> bool {
    let Some(bump) = &mut material.bump else {
        return false;
    };
    bump.strength = (bump.strength * factor).clamp(1e-3, 1e3);
    true
}

pub fn invert_bump(material: &mut Material) -> bool {
    let Some(bump) = &mut material.bump else {
        return false;
    };
    bump.invert = !bump.invert;
    true
}

/// Steps of one fiftieth of the parameter's range.
const PARAM_STEPS: f32 = 50.0;
/// A range from above 0 spanning this factor or more is stepped by a factor.
const SCALE_SPAN: f32 = 20.0;
/// The factor of one step of such a parameter.
const SCALE_STEP: f32 = 1.05;

/// Which of a material's pattern bindings a parameter belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ParamSlot {
    Bump,
    Texture,
}

/// One editable pattern parameter of a material, as the panel lists it.
#[derive(Clone, Debug, PartialEq)]
pub struct ParamRow {
    pub slot: ParamSlot,
    /// The binding's pattern name.
    pub pattern: String,
    pub name: String,
    pub value: f32,
    pub min: f32,
    pub max: f32,
    pub default: f32,
}

fn texture_pattern(material: &Material) -> Option<&PatternBinding> {
    match material.texture.as_ref()? {
        Texturing::Pattern(binding) => Some(binding),
        Texturing::Image(_) => None,
    }
}

fn texture_pattern_mut(material: &mut Material) -> Option<&mut PatternBinding> {
    match material.texture.as_mut()? {
        Texturing::Pattern(binding) => Some(binding),
        Texturing::Image(_) => None,
    }
}

/// Every pattern parameter of the material: the bump's, then the texture's. A parameter is
/// addressed by its place in this list.
pub fn param_rows(material: &Material) -> Vec<ParamRow> {
    let mut rows = binding_rows(ParamSlot::Bump, bump_pattern(material));
    rows.extend(binding_rows(ParamSlot::Texture, texture_pattern(material)));
    rows
}

fn binding_rows(slot: ParamSlot, binding: Option<&PatternBinding>) -> Vec<ParamRow> {
    let Some(binding) = binding else {
        return Vec::new();
    };
    binding
        .pattern
        .params()
        .iter()
        .zip(&binding.params)
        .map(|(param, &value)| ParamRow {
            slot,
            pattern: binding.name.clone(),
            name: param.name.clone(),
            value,
            min: param.min,
            max: param.max,
            default: param.default,
        })
        .collect()
}

/// Moves parameter `row` of `param_rows` by `steps`, clamped to its range; false if there is
/// none. A step is a fiftieth of the range, or for a parameter whose range spans a factor of
/// `SCALE_SPAN` from above 0 (a period, a size) a factor of `SCALE_STEP`, so it moves as
/// finely at 5 as at 300.
pub fn adjust_param(material: &mut Material, row: usize, steps: f32) -> bool {
    with_param(material, row, |value, min, max| {
        let moved = match min > 0.0 && max / min >= SCALE_SPAN {
            true => *value * SCALE_STEP.powf(steps),
            false => *value + steps * (max - min) / PARAM_STEPS,
        };
        *value = moved.clamp(min, max);
    })
}

/// Sets parameter `row` of `param_rows` to `value`, clamped to its range; false if there is
/// none.
pub fn set_param(material: &mut Material, row: usize, value: f32) -> bool {
    with_param(material, row, |v, min, max| *v = value.clamp(min, max))
}

/// Applies `change(value, min, max)` to parameter `row` of `param_rows`; false if there is none.
fn with_param(material: &mut Material, row: usize, change: impl Fn(&mut f32, f32, f32)) -> bool {
    let bump_count = bump_pattern(material).map_or(0, |b| b.params.len());
    let (binding, index) = match row < bump_count {
        true => (bump_pattern_mut(material), row),
        false => (texture_pattern_mut(material), row - bump_count),
    };
    let Some(binding) = binding else {
        return false;
    };
    let Some(param) = binding.pattern.params().get(index) else {
        return false;
    };
    let (min, max) = (param.min, param.max);
    let Some(value) = binding.params.get_mut(index) else {
        return false;
    };
    change(value, min, max);
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A plane's surface and the shelf of a scene with no images of its own.
    fn stage() -> (Surface, ImageShelf) {
        let scene = crate::scene::preset("plane-dimples").unwrap();
        let surface = scene.objects[0].surface.clone();
        (surface, ImageShelf::of(&scene, ".".into()))
    }

    fn cycle_bump_pattern(material: &mut Material, step: i32) -> String {
        let (surface, mut shelf) = stage();
        loop {
            let name = cycle_bump(material, &surface, step, &mut shelf).unwrap();
            if bump_pattern(material).is_some() {
                return name;
            }
        }
    }

    fn cycle_texture_pattern(material: &mut Material, step: i32) -> String {
        let (surface, mut shelf) = stage();
        loop {
            let name = cycle_texture(material, &surface, step, &mut shelf).unwrap();
            if texture_pattern(material).is_some() {
                return name;
            }
        }
    }

    #[test]
    fn images_follow_the_patterns_and_the_bump_strength_follows_the_kind() {
        let (surface, mut shelf) = stage();
        let mut material = Material::default();
        let patterns = builtins_of(false).len();
        let mut names = Vec::new();
        for _ in 0..patterns + shelf.names().len() {
            names.push(cycle_bump(&mut material, &surface, 1, &mut shelf).unwrap());
            let bump = material.bump.as_ref().unwrap();
            match &bump.source {
                BumpSource::Image(image) => {
                    assert!(image.chosen_live);
                    assert_eq!(bump.strength, crate::scene::IMAGE_BUMP_STRENGTH);
                }
                BumpSource::Pattern(_) => assert_eq!(bump.strength, 1.0),
                BumpSource::NormalMap(_) => panic!("the shelf cycles patterns and images"),
            }
        }
        assert_eq!(&names[patterns..], shelf.names());
        assert_eq!(
            cycle_bump(&mut material, &surface, 1, &mut shelf).unwrap(),
            names[0]
        );
        assert_eq!(
            cycle_texture(&mut material, &surface, -1, &mut shelf).unwrap(),
            "gravel"
        );
        let Some(Texturing::Image(image)) = &material.texture else {
            panic!("the last choice is an image");
        };
        assert!(image.chosen_live && image.texture.width() > 0);
    }

    #[test]
    fn cycling_bump_patterns_visits_only_bump_patterns_and_keeps_strength() {
        let mut material = Material::default();
        let first = cycle_bump_pattern(&mut material, 1);
        assert!(scale_bump(&mut material, 2.0));
        let second = cycle_bump_pattern(&mut material, 1);
        assert_ne!(first, second);
        assert_eq!(material.bump.as_ref().unwrap().strength, 2.0);
        assert_ne!(
            bump_pattern(&material).unwrap().pattern.output(),
            OutputKind::Color
        );
        assert_eq!(cycle_bump_pattern(&mut material, -1), first);
    }

    #[test]
    fn parameters_stay_in_their_range() {
        let mut material = Material::default();
        while bump_pattern(&material).is_none_or(|b| b.params.is_empty()) {
            cycle_bump_pattern(&mut material, 1);
        }
        for _ in 0..200 {
            assert!(adjust_param(&mut material, 0, 10.0));
        }
        let binding = bump_pattern(&material).unwrap();
        assert_eq!(binding.params[0], binding.pattern.params()[0].max);
        assert!(!adjust_param(&mut material, 99, 1.0));
    }

    #[test]
    fn rows_list_the_bump_parameters_then_the_textures_and_each_edits_its_own() {
        let mut material = Material::default();
        while bump_pattern(&material).is_none_or(|b| b.params.is_empty()) {
            cycle_bump_pattern(&mut material, 1);
        }
        while texture_pattern(&material).is_none_or(|b| b.params.is_empty()) {
            cycle_texture_pattern(&mut material, 1);
        }
        let rows = param_rows(&material);
        let bump_count = bump_pattern(&material).unwrap().params.len();
        assert!(rows[..bump_count].iter().all(|r| r.slot == ParamSlot::Bump));
        assert!(
            rows[bump_count..]
                .iter()
                .all(|r| r.slot == ParamSlot::Texture)
        );
        assert!(rows.len() > bump_count);
        let bump_before = bump_pattern(&material).unwrap().params.clone();
        assert!(adjust_param(&mut material, bump_count, 1.0));
        assert_eq!(bump_pattern(&material).unwrap().params, bump_before);
        let moved = &param_rows(&material)[bump_count];
        assert!(moved.value != rows[bump_count].value || moved.value == moved.max);
        assert!(!adjust_param(&mut material, rows.len(), 1.0));
    }

    #[test]
    fn a_period_steps_by_a_factor_and_a_depth_by_a_part_of_its_range() {
        let scene = crate::scene::preset("plane-ripple").unwrap();
        let mut material = scene.objects[0].material.clone();
        let rows = param_rows(&material);
        let wavelength = rows.iter().position(|r| r.name == "wavelength").unwrap();
        let amplitude = rows.iter().position(|r| r.name == "amplitude").unwrap();
        let (w, a) = (rows[wavelength].value, rows[amplitude].value);
        adjust_param(&mut material, wavelength, 10.0);
        adjust_param(&mut material, amplitude, 1.0);
        let rows = param_rows(&material);
        let ratio = rows[wavelength].value / w;
        assert!((ratio - 1.05f32.powi(10)).abs() < 1e-4, "{ratio}");
        let range = rows[amplitude].max - rows[amplitude].min;
        assert!((rows[amplitude].value - a - range / 50.0).abs() < 1e-4);
        assert!(set_param(&mut material, wavelength, 199.2));
        assert_eq!(param_rows(&material)[wavelength].value, 199.2);
    }
}
