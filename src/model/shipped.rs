//! The shipped models, embedded so the binary works without the `models/` directory.

/// (name, OBJ text) of every shipped model; the name is the file stem in `models/`.
pub const BUILTIN_MODELS: &[(&str, &[u8])] = &[(
    "rounded-cube",
    include_bytes!("../../models/rounded-cube.obj"),
)];

/// The OBJ text of the shipped model `name`.
pub fn builtin_model(name: &str) -> Option<&'static [u8]> {
    BUILTIN_MODELS
        .iter()
        .find(|(n, _)| *n == name)
        .map(|&(_, bytes)| bytes)
}
