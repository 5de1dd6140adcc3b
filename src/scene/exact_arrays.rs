//! Fixed-length lists in scene files, read strictly. serde reads an array of N from the first N
//! values of a longer TOML list and drops the rest without a word, so `size = [1, 2, 3]` would
//! load as `[1, 2]`; these read the whole list and refuse any other length.

use serde::de::{Deserialize, Deserializer, Error};

/// Exactly `N` values (`#[serde(deserialize_with = "exact")]`).
pub fn exact<'de, D, T, const N: usize>(deserializer: D) -> Result<[T; N], D::Error>
where
    D: Deserializer<'de>,
    T: Deserialize<'de>,
{
    let values = Vec::<T>::deserialize(deserializer)?;
    of_length(values)
}

/// An optional field of exactly `N` values (with `#[serde(default)]`).
pub fn exact_optional<'de, D, T, const N: usize>(
    deserializer: D,
) -> Result<Option<[T; N]>, D::Error>
where
    D: Deserializer<'de>,
    T: Deserialize<'de>,
{
    exact(deserializer).map(Some)
}

/// An optional list of exactly `N` lists of exactly `M` values.
pub fn exact_nested_optional<'de, D, T, const N: usize, const M: usize>(
    deserializer: D,
) -> Result<Option<[[T; M]; N]>, D::Error>
where
    D: Deserializer<'de>,
    T: Deserialize<'de>,
{
    let lists = Vec::<Vec<T>>::deserialize(deserializer)?;
    let inner = lists
        .into_iter()
        .map(of_length)
        .collect::<Result<Vec<[T; M]>, D::Error>>()?;
    of_length(inner).map(Some)
}

fn of_length<T, E: Error, const N: usize>(values: Vec<T>) -> Result<[T; N], E> {
    let found = values.len();
    values
        .try_into()
        .map_err(|_| E::invalid_length(found, &format!("a list of {N} values").as_str()))
}
