//! `--set KEY=VALUE`: one setting of a scene or of the quality, from the command line.
//!
//! Keys: `quality.KNOB` for every knob of [`Quality`] (as a still's recipe names them:
//! `tessellation`, `samples`, `normal-form`, `gradient`, …), and `[OBJECT.]bump.PARAM`,
//! `[OBJECT.]texture.PARAM`, `[OBJECT.]bump.strength` (the bump's own factor) and
//! `[OBJECT.]bump.params.PARAM` (a pattern parameter, also one called `strength`) for the
//! objects' bindings (OBJECT counts from 1; without it, every object whose binding has PARAM);
//! `shadows` (true or false), whether the scene's lights cast shadows; and `[OBJECT.]displace`
//! (true or false), whether an object's bump height moves its surface (every object's without
//! OBJECT).

use crate::quality::Quality;
use crate::scene::{BumpSource, KnobPlace, KnobSetting, PatternBinding, Scene, Texturing};

/// One `--set`, parsed.
#[derive(Clone, Debug, PartialEq)]
pub struct Override {
    target: Target,
    value: String,
    /// As given, for messages.
    text: String,
}

#[derive(Clone, Debug, PartialEq)]
enum Target {
    Quality(String),
    Shadows,
    Displace(Option<usize>),
    Binding {
        object: Option<usize>,
        slot: Slot,
        name: Name,
    },
}

/// What of a binding is set.
#[derive(Clone, Debug, PartialEq)]
enum Name {
    /// The bump's own factor (a scene file's `strength`).
    Strength,
    /// A parameter of the binding's pattern (`params.NAME`; plain `NAME` where it is not
    /// `strength`).
    Param(String),
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Slot {
    Bump,
    Texture,
}

impl Override {
    /// `KEY=VALUE`, or a message saying what keys there are (a command-line value parser).
    pub fn parse(text: &str) -> Result<Override, String> {
        let shown = crate::diagnostic::shown_input(text);
        let (key, value) = text
            .split_once('=')
            .ok_or_else(|| format!("expected KEY=VALUE, found '{shown}'"))?;
        let mut parts: Vec<&str> = key.trim().split('.').collect();
        let object = match parts.first().map(|p| p.parse::<usize>()) {
            Some(Ok(0)) => return Err(format!("'{shown}': an object is counted from 1")),
            Some(Ok(n)) => {
                parts.remove(0);
                Some(n)
            }
            _ => None,
        };
        if let [
            slot @ ("bump" | "texture"),
            what @ ("pattern" | "image" | "normal-map"),
        ] = parts.as_slice()
        {
            return Err(source_is_not_a_setting(slot, what, &shown));
        }
        let target = match parts.as_slice() {
            ["quality", knob] if object.is_none() => Some(Target::Quality(knob.to_string())),
            ["shadows"] if object.is_none() => Some(Target::Shadows),
            ["displace"] => Some(Target::Displace(object)),
            [slot, "strength"] => binding(object, slot, Name::Strength),
            [slot, "params", name] | [slot, name] => {
                binding(object, slot, Name::Param(name.to_string()))
            }
            _ => None,
        }
        .ok_or_else(|| {
            format!(
                "unknown setting '{shown}'; the keys are quality.KNOB, shadows, \
                 [OBJECT.]displace, [OBJECT.]bump.PARAM, [OBJECT.]texture.PARAM, [OBJECT.]bump.strength and \
                 [OBJECT.]bump.params.PARAM"
            )
        })?;
        Ok(Override {
            target,
            value: value.trim().to_string(),
            text: text.to_string(),
        })
    }

    /// The setting as given.
    pub fn text(&self) -> &str {
        &self.text
    }

    /// The setting as given, safe to show.
    pub fn shown(&self) -> String {
        crate::diagnostic::shown_input(&self.text)
    }

    /// The value as a switch: true or false (on or off).
    fn switch(&self) -> Result<bool, String> {
        match self.value.as_str() {
            "true" | "on" => Ok(true),
            "false" | "off" => Ok(false),
            _ => Err(format!("--set {}: expected true or false", self.shown())),
        }
    }

    /// Whether it sets a binding of the scene (not the quality).
    pub fn is_binding(&self) -> bool {
        matches!(self.target, Target::Binding { .. })
    }
}

/// Why `--set bump.pattern=…` (or `image`, `normal-map`) is not taken, and what does it.
fn source_is_not_a_setting(slot: &str, what: &str, shown: &str) -> String {
    let value = shown.split_once('=').map_or("NAME", |(_, v)| v.trim());
    format!(
        "'{shown}': --set changes numbers; a {slot}'s {what} is chosen in a scene file \
         ({slot} = {{ {what} = \"{value}\" }}), by showing the file itself (bumpwork view \
         FILE.pat or PHOTO.png), or with {} in the workbench",
        if slot == "bump" { "p" } else { "t" }
    )
}

fn binding(object: Option<usize>, slot: &str, name: Name) -> Option<Target> {
    let slot = match (slot, &name) {
        ("bump", _) => Slot::Bump,
        ("texture", Name::Param(_)) => Slot::Texture,
        _ => return None,
    };
    let empty = matches!(&name, Name::Param(n) if n.is_empty());
    (!empty).then_some(Target::Binding { object, slot, name })
}

/// `quality` with every `quality.KNOB` override applied, checked as a recipe's quality is.
pub fn apply_to_quality(overrides: &[Override], quality: Quality) -> Result<Quality, String> {
    quality.with_settings(&knob_settings(overrides))
}

/// The `quality.KNOB` overrides as knob settings.
pub fn knob_settings(overrides: &[Override]) -> Vec<KnobSetting> {
    overrides
        .iter()
        .filter_map(|o| match &o.target {
            Target::Quality(knob) => Some(KnobSetting {
                knob: knob.clone(),
                value: toml_value(&o.value),
                place: KnobPlace::CommandLine(o.shown()),
            }),
            Target::Shadows | Target::Displace(_) | Target::Binding { .. } => None,
        })
        .collect()
}

/// The value as TOML reads it (a number, a boolean, an inline table), else as text: so
/// `normal-form=full` needs no quotes.
fn toml_value(value: &str) -> toml::Value {
    toml::from_str::<toml::Table>(&format!("v = {value}"))
        .ok()
        .and_then(|mut t| t.remove("v"))
        .unwrap_or_else(|| toml::Value::String(value.to_string()))
}

/// `scene` with every binding override applied. An override no object takes is an error naming
/// the parameters there are.
pub fn apply_to_scene(overrides: &[Override], scene: &mut Scene) -> Result<(), String> {
    for o in overrides {
        if let Applied::NoPlace(known) = apply_to(o, scene)? {
            return Err(no_such_parameter(o, &known));
        }
    }
    Ok(())
}

/// As `apply_to_scene` for one scene of many (the gallery): an override the scene has no place
/// for is left out; returns which overrides it took.
pub fn apply_where_known(overrides: &[Override], scene: &mut Scene) -> Result<Vec<bool>, String> {
    overrides
        .iter()
        .map(|o| Ok(apply_to(o, scene)? == Applied::Taken))
        .collect()
}

/// The error for an override that no scene took, `known` the parameters there were.
pub fn no_such_parameter(o: &Override, known: &[String]) -> String {
    let what = match known.is_empty() {
        true => "no object has a pattern there".to_string(),
        false => format!("the parameters there are {}", known.join(", ")),
    };
    format!("--set {}: no such parameter; {what}", o.shown())
}

/// What a binding override found in a scene.
#[derive(Debug, PartialEq)]
enum Applied {
    /// It is a quality override.
    NotABinding,
    Taken,
    /// No object took it; the parameters there were.
    NoPlace(Vec<String>),
}

/// Applies `o` if it is a setting of the scene (not of the quality).
fn apply_to(o: &Override, scene: &mut Scene) -> Result<Applied, String> {
    match o.target {
        Target::Quality(_) => Ok(Applied::NotABinding),
        Target::Shadows => {
            scene.shadows = o.switch()?;
            Ok(Applied::Taken)
        }
        Target::Displace(object) => {
            let on = o.switch()?;
            let count = scene.objects.len();
            if object.is_some_and(|n| n > count) {
                return Err(format!(
                    "--set {}: the scene has {count} objects",
                    o.shown()
                ));
            }
            for (index, each) in scene.objects.iter_mut().enumerate() {
                if object.is_none_or(|n| n == index + 1) {
                    each.displace = on;
                }
            }
            Ok(Applied::Taken)
        }
        Target::Binding { .. } => apply_binding(o, scene),
    }
}

/// Applies `o` if it is a binding override; an error for a value out of range or an object past
/// the scene's.
fn apply_binding(o: &Override, scene: &mut Scene) -> Result<Applied, String> {
    let Target::Binding { object, slot, name } = &o.target else {
        return Ok(Applied::NotABinding);
    };
    if object.is_some_and(|n| n > scene.objects.len()) {
        return Err(format!(
            "--set {}: the scene has {} objects",
            o.shown(),
            scene.objects.len()
        ));
    }
    // f64 first, so a number too large for the f32 a parameter holds is told as out of range.
    let value: f64 = o
        .value
        .parse()
        .ok()
        .filter(|v: &f64| v.is_finite())
        .ok_or_else(|| {
            format!(
                "--set {}: expected a number, found '{}'",
                o.shown(),
                crate::diagnostic::shown_input(&o.value)
            )
        })?;
    let mut taken = false;
    let mut known = Vec::new();
    for (index, material) in scene
        .objects
        .iter_mut()
        .map(|o| &mut o.material)
        .enumerate()
    {
        if object.is_some_and(|n| n != index + 1) {
            continue;
        }
        let name = match name {
            Name::Strength => {
                if let Some(bump) = &mut material.bump {
                    bump.strength =
                        strength(value).map_err(|e| format!("--set {}: {e}", o.shown()))?;
                    taken = true;
                }
                continue;
            }
            Name::Param(name) => name,
        };
        let binding = match slot {
            Slot::Bump => material.bump.as_mut().and_then(|b| match &mut b.source {
                BumpSource::Pattern(p) => Some(p),
                BumpSource::Image(_) | BumpSource::NormalMap(_) => None,
            }),
            Slot::Texture => material.texture.as_mut().and_then(|t| match t {
                Texturing::Pattern(p) => Some(p),
                Texturing::Image(_) => None,
            }),
        };
        if let Some(binding) = binding {
            taken |=
                set_param(binding, name, value).map_err(|e| format!("--set {}: {e}", o.shown()))?;
            known.extend(binding.pattern.params().iter().map(|p| p.name.clone()));
        }
    }
    known.sort();
    known.dedup();
    Ok(if taken {
        Applied::Taken
    } else {
        Applied::NoPlace(known)
    })
}

/// Sets parameter `name` of `binding` to `value` within its range; `Ok(false)` if it has none
/// of that name.
fn set_param(binding: &mut PatternBinding, name: &str, value: f64) -> Result<bool, String> {
    let Some(index) = binding.pattern.params().iter().position(|p| p.name == name) else {
        return Ok(false);
    };
    let param = &binding.pattern.params()[index];
    if !(f64::from(param.min)..=f64::from(param.max)).contains(&value) {
        return Err(format!(
            "{} is outside {}'s range {}..{}",
            shown_number(value),
            param.name,
            param.min,
            param.max
        ));
    }
    binding.params[index] = value as f32;
    Ok(true)
}

/// A bump's strength (an f32 with no range of its own) from `value`.
fn strength(value: f64) -> Result<f32, String> {
    let max = f64::from(f32::MAX);
    match value.abs() <= max {
        true => Ok(value as f32),
        false => Err(format!(
            "{} is beyond ±{max:.1e}, the most a strength can be",
            shown_number(value)
        )),
    }
}

/// `value` as a person writes it: plainly, or in exponent form where that would run long.
fn shown_number(value: f64) -> String {
    match value == 0.0 || (1e-4..1e7).contains(&value.abs()) {
        true => value.to_string(),
        false => format!("{value:e}"),
    }
}
