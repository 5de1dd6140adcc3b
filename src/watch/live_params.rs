//! Keeping the parameter values the user changed live across a reload.

use crate::scene::{BumpSource, Material, PatternBinding, Scene, Texturing};

/// Gives `reloaded` the pattern parameter values the user changed live: those where `live` (the
/// scene on screen) differs from `as_loaded` (the same scene as it was read from disk).
///
/// A binding is the same when it sits on the same object (by index), in the same slot (texture
/// or bump) and names the same pattern; a parameter is the same when its name is. Values are
/// clamped to the new range. Parameters the user did not touch take the new file's value, so
/// editing a default in the pattern file shows up. Returns the live values kept where the file's
/// own value changed, which the user should hear of.
pub fn carry_live_params(as_loaded: &Scene, live: &Scene, reloaded: &mut Scene) -> Vec<KeptValue> {
    let mut kept = Vec::new();
    for (index, object) in reloaded.objects.iter_mut().enumerate() {
        let (Some(before), Some(shown)) = (as_loaded.objects.get(index), live.objects.get(index))
        else {
            continue;
        };
        let slots = pattern_bindings(&before.material)
            .into_iter()
            .zip(pattern_bindings(&shown.material))
            .zip(pattern_bindings_mut(&mut object.material));
        for ((before, shown), new) in slots {
            if let (Some(before), Some(shown), Some(new)) = (before, shown, new) {
                carry_binding(before, shown, new, &mut kept);
            }
        }
    }
    kept
}

/// A value changed with the keys and kept over a reload whose file gave the parameter another.
#[derive(Clone, Debug, PartialEq)]
pub struct KeptValue {
    pub param: String,
    pub live: f32,
    /// What the file now says.
    pub file: f32,
}

fn carry_binding(
    before: &PatternBinding,
    shown: &PatternBinding,
    new: &mut PatternBinding,
    kept: &mut Vec<KeptValue>,
) {
    if before.name != new.name || shown.name != new.name {
        return;
    }
    for (slot, param) in new.pattern.params().iter().enumerate() {
        let Some(old) = before
            .pattern
            .params()
            .iter()
            .position(|p| p.name == param.name)
        else {
            continue;
        };
        let (Some(&loaded), Some(&value)) = (before.params.get(old), shown.params.get(old)) else {
            continue;
        };
        if value != loaded && value.is_finite() {
            let file = new.params[slot];
            new.params[slot] = value.clamp(param.min, param.max);
            if file != loaded {
                kept.push(KeptValue {
                    param: param.name.clone(),
                    live: new.params[slot],
                    file,
                });
            }
        }
    }
}

/// The texture's and the bump's pattern bindings, in that order.
fn pattern_bindings(material: &Material) -> [Option<&PatternBinding>; 2] {
    let texture = match &material.texture {
        Some(Texturing::Pattern(binding)) => Some(binding),
        _ => None,
    };
    let bump = material.bump.as_ref().and_then(|b| match &b.source {
        BumpSource::Pattern(binding) => Some(binding),
        BumpSource::Image(_) | BumpSource::NormalMap(_) => None,
    });
    [texture, bump]
}

fn pattern_bindings_mut(material: &mut Material) -> [Option<&mut PatternBinding>; 2] {
    let texture = match &mut material.texture {
        Some(Texturing::Pattern(binding)) => Some(binding),
        _ => None,
    };
    let bump = material.bump.as_mut().and_then(|b| match &mut b.source {
        BumpSource::Pattern(binding) => Some(binding),
        BumpSource::Image(_) | BumpSource::NormalMap(_) => None,
    });
    [texture, bump]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pattern::Pattern;
    use crate::scene::{Bump, Object, Placement, preset};
    use crate::surface::{Sphere, Surface};

    fn scene_with(name: &str, source: &str, params: Vec<f32>) -> Scene {
        let mut scene = preset(crate::scene::PRESET_NAMES[0]).unwrap();
        let binding = PatternBinding {
            name: name.into(),
            pattern: Pattern::compile(source, name).unwrap(),
            params,
            placement: Placement::default(),
        };
        let material = Material {
            bump: Some(Bump {
                source: BumpSource::Pattern(binding),
                strength: 1.0,
                invert: false,
            }),
            ..Material::default()
        };
        let surface = Surface::Sphere(Sphere {
            center: glam::DVec3::ZERO,
            radius: 1.0,
        });
        scene.objects = vec![Object {
            surface,
            material,
            displace: false,
        }];
        scene
    }

    fn bump_params(scene: &Scene) -> Vec<f32> {
        pattern_bindings(&scene.objects[0].material)[1]
            .unwrap()
            .params
            .clone()
    }

    const OLD: &str = "param a = 1 in 0..10\nparam b = 2 in 0..10\nheight = a * u + b * v";

    #[test]
    fn changed_values_survive_by_name_and_untouched_take_the_new_file() {
        let as_loaded = scene_with("p.pat", OLD, vec![1.0, 2.0]);
        let live = scene_with("p.pat", OLD, vec![1.0, 7.0]);
        let new_source = "param c = 3 in 0..10\nparam b = 4 in 0..5\nparam a = 6 in 0..10\nheight = a * b * c * u";
        let mut reloaded = scene_with("p.pat", new_source, vec![3.0, 4.0, 6.0]);
        let kept = carry_live_params(&as_loaded, &live, &mut reloaded);
        assert_eq!(bump_params(&reloaded), vec![3.0, 5.0, 6.0]);
        // b's value in the file changed (2 to 4) under the live 7: the user hears of it.
        let told = KeptValue {
            param: "b".into(),
            live: 5.0,
            file: 4.0,
        };
        assert_eq!(kept, vec![told]);
    }

    #[test]
    fn a_kept_value_whose_file_value_did_not_change_is_not_reported() {
        let as_loaded = scene_with("p.pat", OLD, vec![1.0, 2.0]);
        let live = scene_with("p.pat", OLD, vec![5.0, 2.0]);
        let mut reloaded = scene_with("p.pat", OLD, vec![1.0, 2.0]);
        let kept = carry_live_params(&as_loaded, &live, &mut reloaded);
        assert_eq!(bump_params(&reloaded), vec![5.0, 2.0]);
        assert!(kept.is_empty(), "{kept:?}");
    }

    #[test]
    fn another_pattern_in_the_slot_keeps_its_own_values() {
        let as_loaded = scene_with("p.pat", OLD, vec![1.0, 2.0]);
        let live = scene_with("p.pat", OLD, vec![9.0, 9.0]);
        let mut reloaded = scene_with("q.pat", OLD, vec![1.0, 2.0]);
        carry_live_params(&as_loaded, &live, &mut reloaded);
        assert_eq!(bump_params(&reloaded), vec![1.0, 2.0]);
    }
}
