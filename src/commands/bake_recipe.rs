//! What a bake was made from, as the TOML each baked map carries: enough for `bake --from` to
//! make the same maps again.

use bumpwork::Error;
use bumpwork::texture::NormalConvention;
use glam::Vec2;
use serde::{Deserialize, Serialize};
use std::path::Path;

/// A bake's source and options.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub struct BakeRecipe {
    /// The pattern, shipped name or scene (with `:OBJECT`), as given.
    pub source: String,
    pub size: (u32, u32),
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tile: Option<TileRect>,
    #[serde(default)]
    pub convention: NormalConvention,
    /// `--set` settings as given.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub set: Vec<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub time: Option<f64>,
}

impl BakeRecipe {
    pub fn to_text(&self) -> String {
        toml::to_string(self).expect("a bake recipe is a TOML table")
    }

    /// The recipe a map made by `bumpwork bake` carries.
    pub fn read_from(map: &Path) -> Result<BakeRecipe, Error> {
        let texts = bumpwork::export::read_png_text(map)?;
        let shown = bumpwork::diagnostic::sanitize(&map.display().to_string()).into_owned();
        let text = texts
            .iter()
            .find(|(keyword, _)| keyword == bumpwork::export::BAKE_RECIPE)
            .map(|(_, text)| text)
            .ok_or_else(|| {
                Error::InvalidArgument(format!(
                    "{shown} holds no bake recipe; --from takes a map `bumpwork bake` wrote"
                ))
            })?;
        toml::from_str(text).map_err(|e| {
            Error::Diagnostic(format!(
                "{shown}: its bake recipe: {}",
                bumpwork::diagnostic::shorten_quotes(e.message())
            ))
        })
    }
}

/// A (u,v) rectangle: `min` at its lower left, `max` at its upper right.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct TileRect {
    pub min: Vec2,
    pub max: Vec2,
}

/// The largest |u| or |v| a tile may reach: f32 (u,v) hold steps finer than a pixel of a
/// 16384-wide map out to here.
const MAX_TILE_COORDINATE: f32 = 1e6;

impl TileRect {
    /// `U0..U1,V0..V1` or `W,H` (for 0..W,0..H).
    pub fn parse(text: &str) -> Result<TileRect, String> {
        let shown = bumpwork::diagnostic::shown_input(text);
        let expected = || format!("expected U0..U1,V0..V1 or W,H; got '{shown}'");
        let (u, v) = text.split_once(',').ok_or_else(expected)?;
        let number = |s: &str| {
            s.trim()
                .parse::<f32>()
                .ok()
                .filter(|x| x.is_finite() && x.abs() <= MAX_TILE_COORDINATE)
        };
        let span = |s: &str| match s.split_once("..") {
            Some((a, b)) => number(a).zip(number(b)),
            None => number(s).map(|w| (0.0, w)),
        };
        let ((u0, u1), (v0, v1)) = span(u).zip(span(v)).ok_or_else(|| {
            format!("expected U0..U1,V0..V1 or W,H with each within ±1e6; got '{shown}'")
        })?;
        if !(u0 < u1 && v0 < v1) {
            return Err(format!("a tile needs U0 < U1 and V0 < V1; got '{shown}'"));
        }
        Ok(TileRect {
            min: Vec2::new(u0, v0),
            max: Vec2::new(u1, v1),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tiles_parse_as_spans_or_sizes_and_bad_ones_are_told() {
        let tile = TileRect::parse("10..40,-5..25").unwrap();
        assert_eq!(
            (tile.min, tile.max),
            (Vec2::new(10.0, -5.0), Vec2::new(40.0, 25.0))
        );
        let size = TileRect::parse("30,30").unwrap();
        assert_eq!((size.min, size.max), (Vec2::ZERO, Vec2::splat(30.0)));
        for bad in ["30", "0..0,0..1", "a,b", "1e30,1", "5..1,0..1", "NaN,1"] {
            assert!(TileRect::parse(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn a_recipe_reads_back_as_written_and_escapes_its_strings() {
        let recipe = BakeRecipe {
            source: "my \"odd\"\nname.pat".into(),
            size: (64, 32),
            tile: Some(TileRect::parse("30,30").unwrap()),
            convention: NormalConvention::Directx,
            set: vec!["bump.period=20".into()],
            time: Some(1.5),
        };
        let back: BakeRecipe = toml::from_str(&recipe.to_text()).unwrap();
        assert_eq!(back, recipe);
    }
}
