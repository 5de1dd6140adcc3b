//! Live edits of one object's material: which bump pattern and colour pattern it wears, the bump's
//! strength and sign, and the values of the bump pattern's parameters.

use crate::pattern::{BUILTINS, OutputKind, Pattern};
use crate::scene::{Bump, BumpSource, Material, PatternBinding, Placement, Texturing};
use crate::texture::Mapping;

/// The built-in patterns of one kind (bump or colour), in the order they are shipped.
fn builtins_of(colour: bool) -> Vec<(&'static str, Pattern)> {
    BUILTINS
        .iter()
        .filter_map(|&(name, source)| Some((name, Pattern::compile(source, name).ok()?)))
        .filter(|(_, p)| (p.output() == OutputKind::Color) == colour)
        .collect()
}

/// The next (`step` = 1) or previous built-in after `current` in `list`, wrapping.
fn cycle(list: &[(&'static str, Pattern)], current: Option<&str>, step: i32) -> (String, Pattern) {
    let position = current.and_then(|name| list.iter().position(|(n, _)| *n == name));
    let index = match position {
        Some(i) => (i as i32 + step).rem_euclid(list.len() as i32) as usize,
        None if step >= 0 => 0,
        None => list.len() - 1,
    };
    (list[index].0.to_string(), list[index].1.clone())
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
        BumpSource::Image(_) => None,
    }
}

fn bump_pattern_mut(material: &mut Material) -> Option<&mut PatternBinding> {
    match &mut material.bump.as_mut()?.source {
        BumpSource::Pattern(binding) => Some(binding),
        BumpSource::Image(_) => None,
    }
}

/// Puts the next or previous built-in bump pattern on the material, keeping its placement,
/// strength and sign. Returns the new pattern's name.
pub fn cycle_bump_pattern(material: &mut Material, step: i32) -> String {
    let list = builtins_of(false);
    let current = bump_pattern(material).map(|b| b.name.clone());
    let (name, pattern) = cycle(&list, current.as_deref(), step);
    let placement = bump_pattern(material).map_or_else(Placement::default, |b| b.placement);
    let source = BumpSource::Pattern(binding(name.clone(), pattern, placement));
    match &mut material.bump {
        Some(bump) => bump.source = source,
        None => {
            material.bump = Some(Bump {
                source,
                strength: 1.0,
                invert: false,
            })
        }
    }
    name
}

/// Puts the next or previous built-in colour pattern on the material as its texture.
pub fn cycle_texture_pattern(material: &mut Material, step: i32) -> String {
    let list = builtins_of(true);
    let current = match &material.texture {
        Some(Texturing::Pattern(binding)) => Some(binding.name.clone()),
        _ => None,
    };
    let (name, pattern) = cycle(&list, current.as_deref(), step);
    let placement = match &material.texture {
        Some(Texturing::Pattern(binding)) => binding.placement,
        _ => Placement::default(),
    };
    material.texture = Some(Texturing::Pattern(binding(
        name.clone(),
        pattern,
        placement,
    )));
    name
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

/// Moves bump parameter `index` by `steps`, clamped to its range; false if there is none.
pub fn adjust_param(material: &mut Material, index: usize, steps: f32) -> bool {
    let Some(binding) = bump_pattern_mut(material) else {
        return false;
    };
    let Some(param) = binding.pattern.params().get(index) else {
        return false;
    };
    let (min, max) = (param.min, param.max);
    let Some(value) = binding.params.get_mut(index) else {
        return false;
    };
    *value = (*value + steps * (max - min) / PARAM_STEPS).clamp(min, max);
    true
}

/// Whether the material changes with time: an animated pattern or a scrolling image.
pub fn animates(material: &Material) -> bool {
    let texture = match &material.texture {
        Some(Texturing::Pattern(b)) => b.pattern.uses_time(),
        Some(Texturing::Image(image)) => matches!(image.mapping, Mapping::Scroll(_)),
        None => false,
    };
    texture || bump_pattern(material).is_some_and(|b| b.pattern.uses_time())
}

#[cfg(test)]
mod tests {
    use super::*;

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
}
