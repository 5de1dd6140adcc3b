//! The names enums give their variants are the ones the command line, recipes and scene files
//! use: lowercase, unchanged by deriving them.

use bumpwork::pattern::Precision;
use bumpwork::shade::ShaderMode;
use bumpwork::still::ResolveFilter;
use bumpwork::term::graphics::Protocol;
use bumpwork::texture::NormalConvention;

#[test]
fn names_are_the_lowercase_variants_the_command_line_and_recipes_use() {
    let names: Vec<&str> = ShaderMode::ALL.iter().map(|m| m.name()).collect();
    assert_eq!(names, ["shaded", "height", "normals", "uv", "depth"]);
    let filters = [ResolveFilter::Box, ResolveFilter::Tent].map(ResolveFilter::name);
    assert_eq!(filters, ["box", "tent"]);
    assert_eq!(ResolveFilter::parse("tent"), Some(ResolveFilter::Tent));
    assert_eq!(ResolveFilter::parse("Tent"), None);
    let conventions = [NormalConvention::Opengl, NormalConvention::Directx];
    assert_eq!(
        conventions.map(NormalConvention::name),
        ["opengl", "directx"]
    );
    let protocols: Vec<&str> = Protocol::ALL.iter().map(|p| p.name()).collect();
    assert_eq!(protocols, ["kitty", "iterm2", "sixel"]);
    let precisions = [Precision::Fastest, Precision::Double].map(Precision::name);
    assert_eq!(precisions, ["fastest", "double"]);
}
