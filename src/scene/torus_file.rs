//! The `torus = {…}` table of a scene file, checked as it is read, so a tube wider than its ring
//! is reported at the table's line and column.

use super::checked_values::{Direction, Point, Positive, up};
use crate::surface::{AxisBasis, Torus};
use serde::{Deserialize, Serialize};

/// A ring torus: a tube of `minor-radius` swept around `axis` at `major-radius` from it.
#[derive(Clone, Copy, Debug, Serialize, Deserialize)]
#[serde(
    deny_unknown_fields,
    rename_all = "kebab-case",
    try_from = "TorusFields"
)]
pub struct TorusFile {
    pub center: Point,
    pub axis: Direction,
    pub major_radius: Positive,
    pub minor_radius: Positive,
}

/// The fields as written, before the check.
#[derive(Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
struct TorusFields {
    center: Point,
    #[serde(default = "up")]
    axis: Direction,
    major_radius: Positive,
    minor_radius: Positive,
}

impl TryFrom<TorusFields> for TorusFile {
    type Error = String;

    fn try_from(fields: TorusFields) -> Result<TorusFile, String> {
        if fields.minor_radius.0 >= fields.major_radius.0 {
            return Err(format!(
                "minor-radius ({}) must be less than major-radius ({})",
                fields.minor_radius.0, fields.major_radius.0
            ));
        }
        Ok(TorusFile {
            center: fields.center,
            axis: fields.axis,
            major_radius: fields.major_radius,
            minor_radius: fields.minor_radius,
        })
    }
}

impl TorusFile {
    pub fn to_torus(self) -> Torus {
        Torus {
            center: self.center.0,
            basis: AxisBasis::from_axis(self.axis.0),
            major_radius: self.major_radius.0,
            minor_radius: self.minor_radius.0,
        }
    }
}
