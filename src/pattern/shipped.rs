//! The shipped patterns, embedded so the binary works without the `patterns/` directory.

/// (name, source) of every shipped pattern; the name is the file stem in `patterns/`.
pub const BUILTINS: &[(&str, &str)] = &[
    ("spheres", include_str!("../../patterns/spheres.pat")),
    (
        "horizontal-wave",
        include_str!("../../patterns/horizontal-wave.pat"),
    ),
    (
        "vertical-wave",
        include_str!("../../patterns/vertical-wave.pat"),
    ),
    ("ripple", include_str!("../../patterns/ripple.pat")),
    ("ripples", include_str!("../../patterns/ripples.pat")),
    ("mesh", include_str!("../../patterns/mesh.pat")),
    ("waffle", include_str!("../../patterns/waffle.pat")),
    (
        "dimples-seed",
        include_str!("../../patterns/dimples-seed.pat"),
    ),
    ("dimples", include_str!("../../patterns/dimples.pat")),
    ("squares", include_str!("../../patterns/squares.pat")),
    (
        "dots-and-dimples",
        include_str!("../../patterns/dots-and-dimples.pat"),
    ),
    ("stripes", include_str!("../../patterns/stripes.pat")),
    ("checks", include_str!("../../patterns/checks.pat")),
    ("bricks", include_str!("../../patterns/bricks.pat")),
    ("hexagons", include_str!("../../patterns/hexagons.pat")),
    ("bumps", include_str!("../../patterns/bumps.pat")),
    ("stucco", include_str!("../../patterns/stucco.pat")),
    ("cobbles", include_str!("../../patterns/cobbles.pat")),
    ("bark", include_str!("../../patterns/bark.pat")),
];

/// Source of the shipped pattern `name` (e.g. `"dimples"`).
pub fn builtin(name: &str) -> Option<&'static str> {
    BUILTINS
        .iter()
        .find(|(n, _)| *n == name)
        .map(|&(_, source)| source)
}
