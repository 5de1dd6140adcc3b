//! The images shipped in `textures/` load as the renderer loads them and are documented.

use std::path::Path;

use bumpwork::texture::{Footprint, HeightMap, Limits, Wrap, check_image};
use glam::Vec2;

const PHOTOS: [&str; 2] = ["chelsea.png", "coffee.png"];
const HEIGHT_MAPS: [&str; 2] = ["brick.png", "gravel.png"];

fn textures_dir() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/textures"))
}

#[test]
fn every_shipped_image_loads_and_is_listed_in_the_readme() {
    let readme = std::fs::read_to_string(textures_dir().join("README.md")).expect("README");
    for name in PHOTOS.iter().chain(&HEIGHT_MAPS) {
        let info = check_image(textures_dir().join(name)).unwrap_or_else(|e| panic!("{e}"));
        assert!(info.width >= 256 && info.height >= 256, "{name}: {info}");
        assert!(
            readme.contains(name),
            "{name} missing from textures/README.md"
        );
    }
    for name in PHOTOS {
        assert!(
            !check_image(textures_dir().join(name)).unwrap().is_grey(),
            "{name}"
        );
    }
}

#[test]
fn height_maps_have_relief() {
    for name in HEIGHT_MAPS {
        let map = HeightMap::load(textures_dir().join(name), &Limits::default()).unwrap();
        assert_eq!((map.width(), map.height()), (512, 512));
        let heights: Vec<f32> = (0..64)
            .map(|i| {
                let st = Vec2::new(i as f32 / 64.0, (i as f32 * 0.37).fract());
                map.sample_gradient(st, Wrap::Repeat, Wrap::Repeat, Footprint::POINT)
                    .height
            })
            .collect();
        let (low, high) = heights
            .iter()
            .fold((f32::MAX, f32::MIN), |(l, h), &v| (l.min(v), h.max(v)));
        assert!(high - low > 0.2, "{name}: heights only span {low}..{high}");
    }
}

#[test]
fn shipped_images_stay_small() {
    let total: u64 = std::fs::read_dir(textures_dir())
        .unwrap()
        .map(|entry| entry.unwrap().metadata().unwrap().len())
        .sum();
    assert!(total < 2 << 20, "textures/ holds {total} bytes");
}
