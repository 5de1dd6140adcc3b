//! The scene file's value types, each checked as it is read: serde reports a refused value at
//! its own line and column with the type's "expected …" text.

use glam::{DVec3, Vec3};
use serde::{Deserialize, Serialize};

/// Defines a value type that is checked as it is read, with the "expected …" text given here.
macro_rules! checked {
    ($(#[$doc:meta])* $name:ident($inner:ty) from $raw:literal $raw_ty:ty, $expected:literal,
     check |$v:ident| $check:expr, make $make:expr, back |$b:ident| $back:expr) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
        #[serde(try_from = $raw, into = $raw)]
        pub struct $name(pub $inner);

        impl TryFrom<$raw_ty> for $name {
            type Error = String;
            fn try_from($v: $raw_ty) -> Result<Self, String> {
                if $check {
                    Ok($name($make))
                } else {
                    Err(format!(concat!("expected ", $expected, ", found {}"), found(&$v)))
                }
            }
        }

        impl From<$name> for $raw_ty {
            fn from($b: $name) -> $raw_ty {
                $back
            }
        }
    };
}

/// Coordinates past this are refused: beyond it even f64 positions lose sub-unit precision.
const MAX_COORDINATE: f64 = 1e12;

/// The largest scene time, in seconds either way: past it f32 pattern time loses whole seconds.
pub const MAX_TIME_SECONDS: f64 = 1e9;

checked!(
    /// Seconds, within `MAX_TIME_SECONDS` of zero.
    SceneTime(f64) from "f64" f64, "a time in seconds (|t| ≤ 1e9)",
    check |v| v.is_finite() && v.abs() <= MAX_TIME_SECONDS, make v, back |x| x.0);
checked!(Finite(f32) from "f64" f64, "a finite number",
    check |v| v.is_finite() && v.abs() < 1e30, make v as f32, back |x| shortest(x.0));
checked!(Positive(f32) from "f64" f64, "a positive number",
    check |v| v.is_finite() && v < 1e30 && (v as f32) > 0.0, make v as f32, back |x| shortest(x.0));
checked!(NonNegative(f32) from "f64" f64, "a number ≥ 0",
    check |v| (0.0..1e30).contains(&v), make v as f32, back |x| shortest(x.0));
checked!(
    /// Degrees, strictly between 0 and 180.
    FieldOfView(f32) from "f64" f64, "an angle in degrees between 0 and 180",
    check |v| v > 0.0 && v < 180.0, make v as f32, back |x| shortest(x.0));
checked!(
    /// Degrees, strictly between 0 and 90.
    HalfAngle(f32) from "f64" f64, "an angle in degrees between 0 and 90",
    check |v| v > 0.0 && v < 90.0, make v as f32, back |x| shortest(x.0));
// Lists are read whole (`Vec`), not as `[f64; 3]`, which would drop a fourth value unseen.
checked!(Point(DVec3) from "Vec<f64>" Vec<f64>, "a point: three finite numbers",
    check |v| v.len() == 3 && v.iter().all(|c| c.abs() < MAX_COORDINATE),
    make DVec3::from_slice(&v), back |x| x.0.to_array().to_vec());
checked!(Direction(Vec3) from "Vec<f64>" Vec<f64>, "a direction: three finite numbers, not all zero",
    check |v| v.len() == 3 && v.iter().all(|c| c.abs() < 1e30) && v.iter().any(|&c| c as f32 != 0.0),
    make DVec3::from_slice(&v).as_vec3(), back |x| x.0.to_array().map(shortest).to_vec());
checked!(Rgb(Vec3) from "Vec<f64>" Vec<f64>, "a linear RGB colour: three numbers ≥ 0",
    check |v| v.len() == 3 && v.iter().all(|&c| (0.0..1e30).contains(&c)),
    make DVec3::from_slice(&v).as_vec3(), back |x| x.0.to_array().map(shortest).to_vec());

/// What a refused value was, as a message quotes it: at most `FOUND_CHARS` characters.
fn found(value: &impl std::fmt::Debug) -> String {
    const FOUND_CHARS: usize = 60;
    let text = format!("{value:?}");
    match text.char_indices().nth(FOUND_CHARS) {
        Some((cut, _)) => format!("{}…", &text[..cut]),
        None => text,
    }
}

/// The f64 that prints like the f32 (0.02, not 0.019999999552965164): files written from scenes
/// stay readable, and read back to the same f32.
pub fn shortest(x: f32) -> f64 {
    x.to_string().parse().unwrap_or(x as f64)
}

/// The default axis of a paraboloid or torus: +Y.
pub fn up() -> Direction {
    Direction(Vec3::Y)
}

/// The default axis of a cone, apex to base: −Y.
pub fn down() -> Direction {
    Direction(-Vec3::Y)
}
