//! Every shipped pattern compiles, matches its file on disk, and has the output kind its name
//! promises.

use bumpwork::pattern::{BUILTINS, OutputKind, Pattern, builtin, check_file};

const TEXTURES: [&str; 2] = ["stripes", "checks"];

#[test]
fn every_builtin_compiles_with_the_expected_output_kind() {
    for (name, source) in BUILTINS {
        let pattern = Pattern::compile(source, name).unwrap_or_else(|e| panic!("{e}"));
        let expected = match *name {
            n if TEXTURES.contains(&n) => OutputKind::Color,
            "dimples-seed" => OutputKind::Slope,
            _ => OutputKind::Height,
        };
        assert_eq!(pattern.output(), expected, "{name}");
    }
}

#[test]
fn embedded_sources_match_the_patterns_directory() {
    for (name, source) in BUILTINS {
        let path = format!("{}/patterns/{name}.pat", env!("CARGO_MANIFEST_DIR"));
        assert_eq!(std::fs::read_to_string(&path).unwrap(), *source);
        assert!(check_file(path.as_ref()).is_ok());
    }
}

#[test]
fn params_defaults_lie_in_their_ranges() {
    for (name, source) in BUILTINS {
        let pattern = Pattern::compile(source, name).unwrap();
        for p in pattern.params() {
            assert!(
                p.min < p.max && (p.min..=p.max).contains(&p.default),
                "{name}: {p:?}"
            );
        }
    }
}

#[test]
fn the_seed_patterns_are_all_shipped() {
    let seed = [
        "spheres",
        "horizontal-wave",
        "vertical-wave",
        "ripple",
        "ripples",
        "mesh",
        "waffle",
        "dimples-seed",
        "dimples",
        "squares",
        "dots-and-dimples",
        "stripes",
        "checks",
    ];
    for name in seed.iter().chain(&["bricks", "hexagons", "bumps"]) {
        assert!(builtin(name).is_some(), "{name}");
    }
}

#[test]
fn point_and_time_use_is_reported() {
    let bumps = Pattern::compile(builtin("bumps").unwrap(), "bumps").unwrap();
    assert!(bumps.uses_point() && !bumps.uses_time());
    let ripple = Pattern::compile(builtin("ripple").unwrap(), "ripple").unwrap();
    assert!(!ripple.uses_point() && ripple.uses_time());
}
