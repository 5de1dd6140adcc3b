//! serde's and the TOML parser's messages in a user's words: "expected a number, found the text
//! "wide"" where serde says "invalid type: string "wide", expected f64".

/// `message` with serde's type names and word order replaced; anything else unchanged.
pub fn in_user_words(message: &str) -> String {
    let (found, expected) = if let Some(rest) = message
        .strip_prefix("invalid type: ")
        .or_else(|| message.strip_prefix("invalid value: "))
    {
        match rest.rsplit_once(", expected ") {
            Some((found, expected)) => (found_words(found), expected),
            None => return message.to_string(),
        }
    } else if let Some(rest) = message.strip_prefix("invalid length ") {
        match rest.split_once(", expected ") {
            Some(("1", expected)) => ("1 value".to_string(), expected),
            Some((count, expected)) => (format!("{count} values"), expected),
            None => return message.to_string(),
        }
    } else {
        return match message {
            "floating-point number overflowed" => "the number is too large".to_string(),
            "integer number overflowed" => "the number is too large".to_string(),
            _ => message.to_string(),
        };
    };
    format!("expected {}, found {found}", expected_words(expected))
}

fn expected_words(expected: &str) -> String {
    match expected {
        "f64" | "f32" => "a number".into(),
        "u8" | "u16" | "u32" | "u64" | "usize" | "i32" | "i64" => "a whole number".into(),
        "a boolean" => "true or false".into(),
        "a string" => "text in quotes".into(),
        "a sequence" => "a list in brackets".into(),
        _ => {
            if let Some(n) = expected
                .strip_prefix("an array of length ")
                .or_else(|| expected.strip_prefix("a list of "))
                .and_then(|rest| rest.split(' ').next())
            {
                format!("a list of {n} values in brackets")
            } else if expected.starts_with("struct ") || expected == "a map" {
                "a table".into()
            } else if expected.starts_with("enum ") {
                "a table naming its kind".into()
            } else {
                expected.into()
            }
        }
    }
}

fn found_words(found: &str) -> String {
    let quoted = |prefix: &str| {
        found
            .strip_prefix(prefix)
            .map(|rest| rest.trim_matches('`'))
    };
    if let Some(text) = found.strip_prefix("string ") {
        format!("the text {text}")
    } else if let Some(value) = quoted("boolean ")
        .or_else(|| quoted("integer "))
        .or_else(|| quoted("floating point "))
    {
        value.to_string()
    } else {
        match found {
            "sequence" => "a list".into(),
            "map" => "a table".into(),
            _ => found.into(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn serde_type_names_become_words() {
        for (serde, user) in [
            (
                "invalid type: boolean `true`, expected f64",
                "expected a number, found true",
            ),
            (
                "invalid type: string \"wide\", expected f64",
                "expected a number, found the text \"wide\"",
            ),
            (
                "invalid type: integer `5`, expected a sequence",
                "expected a list in brackets, found 5",
            ),
            (
                "invalid type: map, expected an array of length 3",
                "expected a list of 3 values in brackets, found a table",
            ),
            (
                "invalid length 3, expected a list of 2 values",
                "expected a list of 2 values in brackets, found 3 values",
            ),
            (
                "invalid type: floating point `1.5`, expected u32",
                "expected a whole number, found 1.5",
            ),
            (
                "invalid type: integer `5`, expected struct CameraFile",
                "expected a table, found 5",
            ),
            ("integer number overflowed", "the number is too large"),
            ("missing field `eye`", "missing field `eye`"),
        ] {
            assert_eq!(in_user_words(serde), user);
        }
    }
}
