//! Parameter sweeps: the axes `--vary KEY=A..B:N` or `--vary KEY=a,b,c` name, every combination
//! of their values in a fixed order, and what each still of a sweep records of its values (so
//! the contact sheet and the index can be made from the stills alone, after shards).

use crate::overrides::Override;

/// The most stills one sweep may have.
pub const MAX_STILLS: u64 = 10_000;
/// The most values one axis may have.
pub const MAX_VALUES: usize = 1_000;

/// One `--vary`: a setting's key and the values it takes, as `--set` would be given them.
#[derive(Clone, Debug, PartialEq)]
pub struct Axis {
    pub key: String,
    pub values: Vec<String>,
}

impl Axis {
    /// `KEY=A..B:N` (N values evenly from A to B, both ends included) or `KEY=a,b,c` (a
    /// command-line value parser). Every value must make a valid `--set`.
    pub fn parse(text: &str) -> Result<Axis, String> {
        let shown = crate::diagnostic::shown_input(text);
        let (key, spec) = text.split_once('=').ok_or_else(|| {
            format!("expected KEY=START..END:COUNT or KEY=A,B,C, found '{shown}'")
        })?;
        let key = key.trim().to_string();
        let values = match spec.split_once("..") {
            Some((start, rest)) => range_values(start, rest, &shown)?,
            None => list_values(spec, &shown)?,
        };
        for value in &values {
            Override::parse(&format!("{key}={value}"))?;
        }
        Ok(Axis { key, values })
    }
}

/// A key as a label shows it: its last part (`period` of `bump.period`).
fn short_key(key: &str) -> &str {
    key.rsplit('.').next().unwrap_or(key)
}

/// `START..END:COUNT`, the part after `START..` being `rest`.
fn range_values(start: &str, rest: &str, shown: &str) -> Result<Vec<String>, String> {
    let expected = || format!("expected START..END:COUNT, like 10..60:6, found '{shown}'");
    let (end, count) = rest.split_once(':').ok_or_else(expected)?;
    let number = |s: &str| s.trim().parse::<f64>().ok().filter(|x| x.is_finite());
    let (Some(start), Some(end)) = (number(start), number(end)) else {
        return Err(expected());
    };
    let count = count
        .trim()
        .parse::<usize>()
        .ok()
        .filter(|n| (2..=MAX_VALUES).contains(n))
        .ok_or_else(|| format!("'{shown}': COUNT is the number of values, 2..={MAX_VALUES}"))?;
    Ok((0..count)
        .map(|i| {
            let at = start + (end - start) * i as f64 / (count - 1) as f64;
            shortest(if i == count - 1 { end } else { at })
        })
        .collect())
}

/// `a,b,c`: each value as given, trimmed.
fn list_values(spec: &str, shown: &str) -> Result<Vec<String>, String> {
    let values: Vec<String> = spec.split(',').map(|v| v.trim().to_string()).collect();
    if values.iter().any(String::is_empty) {
        return Err(format!(
            "expected a list of values A,B,C or a range START..END:COUNT, found '{shown}'"
        ));
    }
    if values.len() > MAX_VALUES {
        return Err(format!("'{shown}': more than {MAX_VALUES} values"));
    }
    Ok(values)
}

/// `x` to 12 significant digits, written as briefly as that allows (`0.3`, not
/// `0.30000000000000004`), so labels and file recipes read as the user would write them.
fn shortest(x: f64) -> String {
    let rounded: f64 = format!("{x:.11e}").parse().unwrap_or(x);
    format!("{rounded}")
}

/// The number of combinations of `axes`, or why there are too many.
pub fn count(axes: &[Axis]) -> Result<u64, String> {
    axes.iter()
        .try_fold(1u64, |n, axis| n.checked_mul(axis.values.len() as u64))
        .filter(|&n| n <= MAX_STILLS)
        .ok_or_else(|| {
            let sizes: Vec<String> = axes.iter().map(|a| a.values.len().to_string()).collect();
            format!(
                "the sweep has {} combinations; at most {MAX_STILLS} are rendered",
                sizes.join(" × ")
            )
        })
}

/// Combination `index` (from 0): one `(key, value)` per axis. The last axis varies fastest, so
/// a sheet with as many columns as the last axis has values is a table of the first two.
pub fn combination(axes: &[Axis], index: u64) -> Vec<(String, String)> {
    let mut rest = index;
    let mut values: Vec<(String, String)> = axes
        .iter()
        .rev()
        .map(|axis| {
            let n = axis.values.len() as u64;
            let value = axis.values[(rest % n) as usize].clone();
            rest /= n;
            (axis.key.clone(), value)
        })
        .collect();
    values.reverse();
    values
}

/// The text a sweep's still carries of its values: one `KEY=VALUE` a line.
pub fn values_text(values: &[(String, String)]) -> String {
    values
        .iter()
        .map(|(key, value)| format!("{key}={value}\n"))
        .collect()
}

/// The values a still's `values_text` records, or `None` if it does not read as one.
pub fn parse_values_text(text: &str) -> Option<Vec<(String, String)>> {
    text.lines()
        .map(|line| {
            let (key, value) = line.split_once('=')?;
            Some((key.to_string(), value.to_string()))
        })
        .collect()
}

/// A still's label on the contact sheet: `period=10 strength=0.5`, each key by its last part
/// unless two axes share that.
pub fn label(values: &[(String, String)]) -> String {
    let short: Vec<&str> = values.iter().map(|(key, _)| short_key(key)).collect();
    let unique = (1..short.len()).all(|i| !short[..i].contains(&short[i]));
    values
        .iter()
        .zip(&short)
        .map(|((key, value), short)| match unique {
            true => format!("{short}={value}"),
            false => format!("{key}={value}"),
        })
        .collect::<Vec<_>>()
        .join(" ")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn axis(text: &str) -> Axis {
        Axis::parse(text).unwrap()
    }

    #[test]
    fn ranges_include_both_ends_and_read_as_written() {
        assert_eq!(
            axis("bump.period=10..60:6").values,
            ["10", "20", "30", "40", "50", "60"]
        );
        assert_eq!(
            axis("bump.strength=0..0.3:4").values,
            ["0", "0.1", "0.2", "0.3"]
        );
        assert_eq!(axis("bump.strength=1..-1:3").values, ["1", "0", "-1"]);
        assert_eq!(axis("shadows=true,false").values, ["true", "false"]);
        assert_eq!(axis("bump.strength= 0.5, 1 ,2").values, ["0.5", "1", "2"]);
    }

    #[test]
    fn bad_axes_say_what_was_expected() {
        for (bad, said) in [
            ("bump.period", "expected KEY=START..END:COUNT"),
            ("bump.period=10..60", "expected START..END:COUNT"),
            ("bump.period=10..x:3", "expected START..END:COUNT"),
            ("bump.period=10..60:1", "COUNT is the number of values"),
            ("bump.period=10..60:1001", "COUNT is the number of values"),
            ("bump.period=1,,2", "expected a list of values"),
            ("nothing.here=1,2", "unknown setting"),
        ] {
            let error = Axis::parse(bad).unwrap_err();
            assert!(error.contains(said), "{bad}: {error}");
        }
    }

    #[test]
    fn combinations_count_up_with_the_last_axis_fastest() {
        let axes = [axis("bump.period=10,20,30"), axis("bump.strength=0.5,1")];
        assert_eq!(count(&axes), Ok(6));
        let pairs = |i| {
            combination(&axes, i)
                .into_iter()
                .map(|(_, v)| v)
                .collect::<Vec<_>>()
        };
        assert_eq!(pairs(0), ["10", "0.5"]);
        assert_eq!(pairs(1), ["10", "1"]);
        assert_eq!(pairs(5), ["30", "1"]);
        let big = [axis("bump.period=1..2:1000"), axis("bump.strength=1..2:11")];
        assert!(count(&big).unwrap_err().contains("1000 × 11"));
        assert_eq!(count(&[]), Ok(1));
    }

    #[test]
    fn values_round_trip_through_the_still_text_and_label_briefly() {
        let values = combination(&[axis("bump.period=10,20"), axis("1.bump.strength=2,3")], 3);
        let text = values_text(&values);
        assert_eq!(parse_values_text(&text), Some(values.clone()));
        assert_eq!(label(&values), "period=20 strength=3");
        let shared = vec![
            ("1.bump.period".to_string(), "5".to_string()),
            ("2.bump.period".to_string(), "6".to_string()),
        ];
        assert_eq!(label(&shared), "1.bump.period=5 2.bump.period=6");
        assert_eq!(parse_values_text("no equals sign"), None);
    }
}
