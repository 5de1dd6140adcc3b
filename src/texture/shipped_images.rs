//! The shipped images (CC0, see textures/README.md), embedded so built-in scenes work from any
//! directory. A scene names them without a path or extension: `image = "brick"`.

pub const BUILTIN_IMAGES: &[(&str, &[u8])] = &[
    ("brick", include_bytes!("../../textures/brick.png")),
    ("chelsea", include_bytes!("../../textures/chelsea.png")),
    ("coffee", include_bytes!("../../textures/coffee.png")),
    ("gravel", include_bytes!("../../textures/gravel.png")),
];

/// The file contents of the built-in image `name`, if there is one.
pub fn builtin_bytes(name: &str) -> Option<&'static [u8]> {
    BUILTIN_IMAGES
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, bytes)| *bytes)
}
