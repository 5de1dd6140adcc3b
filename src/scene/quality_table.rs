//! A scene file's `[quality]` table: knob settings kept as written, each with where it was
//! written. The quality module applies them; the scene knows no knobs, only the table.

use crate::diagnostic::Spot;
use std::collections::BTreeMap;

/// One `KNOB = VALUE` of a `[quality]` table, or of a `--set quality.KNOB=VALUE`.
#[derive(Clone, Debug, PartialEq)]
pub struct KnobSetting {
    /// The knob's name as a still's recipe writes it (`samples`, `normal-form`, …).
    pub knob: String,
    pub value: toml::Value,
    pub place: KnobPlace,
}

/// Where a knob setting was written, for its error message.
#[derive(Clone, Debug, PartialEq)]
pub enum KnobPlace {
    /// `file`'s `[quality]` table, the value at `spot`.
    File { file: String, spot: Spot },
    /// The command line, as given (already safe to show).
    CommandLine(String),
}

impl KnobSetting {
    /// `message` about this setting, where it was written: `file:line:column: …` with the line
    /// and a caret, or `--set KEY=VALUE: …`.
    pub fn error(&self, message: &str) -> String {
        match &self.place {
            KnobPlace::File { file, spot } => {
                let message = format!("quality.{}: {message}", self.knob);
                crate::diagnostic::render_at(file, spot, &message)
            }
            KnobPlace::CommandLine(shown) => format!("--set {shown}: {message}"),
        }
    }
}

/// The table as a scene file holds it, each value with its byte span in the file.
pub type QualityTable = BTreeMap<String, toml::Spanned<toml::Value>>;

/// The settings of `table`, read from `source` (the text of `file`), in the table's key order.
pub fn knob_settings(table: &QualityTable, file: &str, source: &str) -> Vec<KnobSetting> {
    table
        .iter()
        .map(|(knob, value)| KnobSetting {
            knob: knob.clone(),
            value: value.get_ref().clone(),
            place: KnobPlace::File {
                file: file.to_string(),
                spot: Spot::at(source, value.span().start),
            },
        })
        .collect()
}

/// The table a scene file writes for `quality` (a quality as a TOML table, every knob set).
pub fn written_table(quality: toml::Table) -> QualityTable {
    quality
        .into_iter()
        .map(|(knob, value)| (knob, toml::Spanned::new(0..0, value)))
        .collect()
}
