//! Filters and wrap modes on synthetic textures, and images as height fields.

use crate::test_dir::TestDir;
use bumpwork::texture::{
    Filter, Footprint, HeightMap, Limits, Sampler, Texel, TexelGrid, Texture, Wrap,
};
use glam::Vec2;

const WRAPS: [Wrap; 3] = [Wrap::Repeat, Wrap::Clamp, Wrap::Mirror];
const FILTERS: [Filter; 3] = [Filter::Nearest, Filter::Bilinear, Filter::Trilinear];

/// A texture whose texels all differ: red = column, green = row, blue = a hash.
fn distinct(width: u32, height: u32) -> Texture {
    Texture::from_raster(TexelGrid::from_fn(width, height, |x, y| {
        Texel::new(x as f32, y as f32, ((x * 7 + y * 13) % 5) as f32, 1.0)
    }))
}

fn texel_centre(x: u32, y: u32, texture: &Texture) -> Vec2 {
    Vec2::new(
        (x as f32 + 0.5) / texture.width() as f32,
        (y as f32 + 0.5) / texture.height() as f32,
    )
}

fn close(a: Texel, b: Texel, tolerance: f32) -> bool {
    (a - b).abs().max_element() <= tolerance
}

#[test]
fn bilinear_and_nearest_return_the_texel_at_its_centre() {
    for (w, h) in [(7, 5), (1, 1), (1, 6), (4, 4)] {
        let texture = distinct(w, h);
        for filter in FILTERS {
            for wrap in WRAPS {
                let sampler = Sampler::new(filter, wrap);
                for (x, y) in [(0, 0), (w - 1, 0), (w / 2, h - 1)] {
                    let expected = texture.mip_chain().base().at(x, y);
                    let got =
                        texture.sample(&sampler, texel_centre(x, y, &texture), Footprint::POINT);
                    assert!(
                        close(got, expected, 1e-5),
                        "{w}x{h} {filter:?} {wrap:?} ({x},{y}): {got}"
                    );
                }
            }
        }
    }
}

#[test]
fn t_zero_is_the_top_row() {
    let texture = distinct(3, 4);
    let sampler = Sampler::new(Filter::Nearest, Wrap::Clamp);
    assert_eq!(
        texture
            .sample(&sampler, Vec2::new(0.0, 0.01), Footprint::POINT)
            .y,
        0.0
    );
    assert_eq!(
        texture
            .sample(&sampler, Vec2::new(0.0, 0.99), Footprint::POINT)
            .y,
        3.0
    );
}

#[test]
fn repeat_has_period_one_across_negative_coordinates() {
    let texture = distinct(5, 3);
    for filter in [Filter::Nearest, Filter::Bilinear] {
        let sampler = Sampler::new(filter, Wrap::Repeat);
        for st in [
            Vec2::new(0.13, 0.71),
            Vec2::new(0.02, 0.98),
            Vec2::new(0.5, 0.5),
        ] {
            let base = texture.sample(&sampler, st, Footprint::POINT);
            for shift in [
                Vec2::new(-1.0, 0.0),
                Vec2::new(-3.0, -2.0),
                Vec2::new(2.0, -7.0),
            ] {
                let shifted = texture.sample(&sampler, st + shift, Footprint::POINT);
                assert!(
                    close(base, shifted, 1e-4),
                    "{filter:?} {st} {shift}: {base} vs {shifted}"
                );
            }
        }
    }
}

#[test]
fn bilinear_repeat_blends_across_the_edge() {
    let texture = distinct(4, 1);
    let sampler = Sampler::new(Filter::Bilinear, Wrap::Repeat);
    // s = 0 is halfway between the last column (3) and the first (0).
    let edge = texture.sample(&sampler, Vec2::new(0.0, 0.5), Footprint::POINT);
    assert!((edge.x - 1.5).abs() < 1e-5, "{edge}");
    let clamped = texture.sample(
        &Sampler::new(Filter::Bilinear, Wrap::Clamp),
        Vec2::new(0.0, 0.5),
        Footprint::POINT,
    );
    assert!(clamped.x.abs() < 1e-5, "{clamped}");
}

#[test]
fn mirror_has_period_two_and_reflects_at_zero() {
    let texture = distinct(5, 3);
    for filter in [Filter::Nearest, Filter::Bilinear] {
        let sampler = Sampler::new(filter, Wrap::Mirror);
        for st in [Vec2::new(0.13, 0.71), Vec2::new(0.3, 0.1)] {
            let base = texture.sample(&sampler, st, Footprint::POINT);
            for other in [st + Vec2::new(-2.0, 4.0), -st, Vec2::new(2.0, 2.0) - st] {
                let got = texture.sample(&sampler, other, Footprint::POINT);
                assert!(
                    close(base, got, 1e-4),
                    "{filter:?} {st} vs {other}: {base} vs {got}"
                );
            }
        }
    }
}

#[test]
fn clamp_extends_the_edge_texels() {
    let texture = distinct(5, 3);
    let sampler = Sampler::new(Filter::Bilinear, Wrap::Clamp);
    let far = texture.sample(&sampler, Vec2::new(-40.0, 1e9), Footprint::POINT);
    assert!(
        close(far, texture.mip_chain().base().at(0, 2), 1e-6),
        "{far}"
    );
}

#[test]
fn per_axis_wrap_modes_compose() {
    let texture = distinct(4, 4);
    let sampler = Sampler {
        filter: Filter::Nearest,
        wrap_s: Wrap::Repeat,
        wrap_t: Wrap::Clamp,
    };
    let got = texture.sample(&sampler, Vec2::new(-0.1, -5.0), Footprint::POINT);
    assert_eq!((got.x, got.y), (3.0, 0.0));
}

fn checkerboard(side: u32) -> Texture {
    Texture::from_raster(TexelGrid::from_fn(side, side, |x, y| {
        Texel::splat(((x + y) % 2) as f32)
    }))
}

#[test]
fn trilinear_on_a_far_minified_checkerboard_is_the_average() {
    let texture = checkerboard(64);
    let trilinear = Sampler::new(Filter::Trilinear, Wrap::Repeat);
    let nearest = Sampler::new(Filter::Nearest, Wrap::Repeat);
    let mut aliased = 0;
    for i in 0..50 {
        let st = Vec2::new(i as f32 * 0.173 + 0.5 / 64.0, i as f32 * 0.291 + 0.5 / 64.0);
        for size in [0.1, 1.0, 1e6] {
            let footprint = Footprint::new(size, 0.0, 0.0, size);
            let got = texture.sample(&trilinear, st, footprint);
            assert!((got.x - 0.5).abs() < 1e-4, "{st} {size}: {got}");
        }
        // Without mips, far-minified samples are whatever texel they hit.
        let naive = texture.sample(&nearest, st, Footprint::new(1.0, 0.0, 0.0, 1.0));
        aliased += usize::from((naive.x - 0.5).abs() > 0.25);
    }
    assert!(
        aliased > 10,
        "test texture does not alias, so proves nothing"
    );
}

#[test]
fn trilinear_without_minification_is_bilinear() {
    let texture = distinct(9, 6);
    let st = Vec2::new(0.37, 0.61);
    let bilinear = texture.sample(
        &Sampler::new(Filter::Bilinear, Wrap::Repeat),
        st,
        Footprint::POINT,
    );
    let trilinear = texture.sample(
        &Sampler::new(Filter::Trilinear, Wrap::Repeat),
        st,
        Footprint::POINT,
    );
    assert_eq!(bilinear, trilinear);
}

#[test]
fn trilinear_stays_finite_for_any_footprint() {
    let texture = distinct(16, 8);
    let sampler = Sampler::new(Filter::Trilinear, Wrap::Mirror);
    for d in [
        f32::NAN,
        f32::INFINITY,
        -f32::INFINITY,
        f32::MAX,
        0.0,
        -1e-30,
    ] {
        let got = texture.sample(&sampler, Vec2::new(0.3, 0.3), Footprint::new(d, d, d, -d));
        assert!(got.is_finite(), "{d}: {got}");
    }
    for st in [Vec2::NAN, Vec2::INFINITY, Vec2::splat(-1e30)] {
        assert!(texture.sample(&sampler, st, Footprint::POINT).is_finite());
    }
}

#[test]
fn batch_sampling_equals_one_at_a_time() {
    let texture = distinct(13, 7);
    // More than one chunk of taps, points on every side of the image and exactly on its
    // edges, and the non-finite coordinates each wrap must survive.
    let mut points: Vec<Vec2> = (0..150)
        .map(|i| Vec2::new(i as f32 * 0.37 - 30.0, i as f32 * 0.11 - 8.0))
        .collect();
    for s in [
        0.0,
        -0.0,
        1.0,
        -1.0,
        2.0,
        -1e-9,
        1e-9,
        0.999_999_9,
        1e30,
        -1e30,
    ] {
        points.push(Vec2::new(s, -s));
    }
    points.extend([Vec2::NAN, Vec2::INFINITY, Vec2::NEG_INFINITY]);
    // Growing footprints, and footprints magnified everywhere but at one point of the third
    // chunk of 64 (trilinear takes the bilinear batch where a whole chunk is magnified).
    let growing: Vec<Footprint> = (0..points.len())
        .map(|i| Footprint::new(i as f32 * 0.01, 0.0, 0.0, 0.02))
        .collect();
    let mostly_magnified: Vec<Footprint> = (0..points.len())
        .map(|i| Footprint::new(if i == 140 { 0.5 } else { 0.01 }, 0.0, 0.0, 0.02))
        .collect();
    for (filter, footprints) in [
        (Filter::Nearest, &growing),
        (Filter::Bilinear, &growing),
        (Filter::Trilinear, &growing),
        (Filter::Trilinear, &mostly_magnified),
    ] {
        for (wrap_s, wrap_t) in [
            (Wrap::Repeat, Wrap::Repeat),
            (Wrap::Clamp, Wrap::Mirror),
            (Wrap::Mirror, Wrap::Clamp),
        ] {
            let sampler = Sampler {
                filter,
                wrap_s,
                wrap_t,
            };
            let mut batch = vec![Texel::ZERO; points.len()];
            let given: &[Footprint] = if filter.uses_footprint() {
                footprints
            } else {
                &[]
            };
            sampler.sample_many(texture.mip_chain(), &points, given, &mut batch);
            for ((p, f), b) in points.iter().zip(footprints).zip(&batch) {
                let one = texture.sample(&sampler, *p, *f);
                assert!(
                    one.to_array().map(f32::to_bits) == b.to_array().map(f32::to_bits),
                    "{filter:?} {wrap_s:?}/{wrap_t:?} at {p}: {one} one at a time, {b} in a batch"
                );
            }
        }
    }
}

fn ramp_heights(width: u32, height: u32) -> TexelGrid<f32> {
    TexelGrid::from_fn(width, height, |x, y| (3 * x + y) as f32 / 100.0)
}

#[test]
fn height_gradient_of_a_linear_ramp_is_constant_away_from_the_border() {
    let (w, h) = (16, 12);
    let map = HeightMap::from_heights(ramp_heights(w, h));
    let expected = Vec2::new(0.03 * w as f32, 0.01 * h as f32);
    for i in 0..200 {
        let s = (2.5 + (i as f32 * 0.618).fract() * (w as f32 - 5.0)) / w as f32;
        let t = (2.5 + (i as f32 * 0.377).fract() * (h as f32 - 5.0)) / h as f32;
        for wrap in WRAPS {
            let g = map.sample_gradient(Vec2::new(s, t), wrap, wrap, Footprint::POINT);
            assert!((g.dh_ds - expected.x).abs() < 1e-4, "{s} {t}: {g:?}");
            assert!((g.dh_dt - expected.y).abs() < 1e-4, "{s} {t}: {g:?}");
        }
    }
}

#[test]
fn height_from_a_ramp_file_is_not_srgb_decoded() {
    let dir = TestDir::new("texture-ramp");
    let path = dir.join("ramp.pgm");
    let mut bytes = b"P5 32 4 255\n".to_vec();
    for _ in 0..4 {
        bytes.extend((0..32).map(|x| x as u8 * 8));
    }
    std::fs::write(&path, bytes).unwrap();
    let map = HeightMap::load(&path, &Limits::default()).unwrap();
    let slopes: Vec<f32> = [0.2, 0.5, 0.8]
        .iter()
        .map(|&s| {
            map.sample_gradient(
                Vec2::new(s, 0.5),
                Wrap::Clamp,
                Wrap::Clamp,
                Footprint::POINT,
            )
            .dh_ds
        })
        .collect();
    let expected = 8.0 / 255.0 * 32.0;
    assert!(
        slopes.iter().all(|s| (s - expected).abs() < 1e-3),
        "{slopes:?}"
    );
}

#[test]
fn magnified_height_gradient_has_no_steps_between_texels() {
    let noise = TexelGrid::from_fn(8, 8, |x, y| ((x * 37 + y * 91) % 17) as f32 / 16.0);
    let map = HeightMap::from_heights(noise);
    let step = 1e-4;
    let mut previous = map.sample_gradient(
        Vec2::new(0.0, 0.43),
        Wrap::Repeat,
        Wrap::Repeat,
        Footprint::POINT,
    );
    let mut largest_jump: f32 = 0.0;
    for i in 1..=(1.0 / step) as usize {
        let g = map.sample_gradient(
            Vec2::new(i as f32 * step, 0.43),
            Wrap::Repeat,
            Wrap::Repeat,
            Footprint::POINT,
        );
        largest_jump = largest_jump.max((g.dh_ds - previous.dh_ds).abs());
        previous = g;
    }
    // Slopes here are O(10) per unit s; a texel step would jump by that much.
    assert!(largest_jump < 0.1, "gradient jumps by {largest_jump}");
}

#[test]
fn colour_images_give_height_by_luma() {
    let green = TexelGrid::from_fn(2, 2, |_, _| Texel::new(0.0, 1.0, 0.0, 1.0));
    let map = HeightMap::from_texels(&green);
    let g = map.sample_gradient(Vec2::splat(0.5), Wrap::Clamp, Wrap::Clamp, Footprint::POINT);
    assert!(
        (g.height - 0.7152).abs() < 1e-5 && g.dh_ds.abs() < 1e-5,
        "{g:?}"
    );
}

#[test]
fn mip_levels_average_in_linear_light() {
    let dir = TestDir::new("texture-linear");
    let path = dir.join("checker.pgm");
    let mut bytes = b"P5 8 8 255\n".to_vec();
    bytes.extend((0..64).map(|i| if (i % 8 + i / 8) % 2 == 0 { 0u8 } else { 255 }));
    std::fs::write(&path, bytes).unwrap();
    let texture = Texture::load(&path, &Limits::default()).unwrap();
    let coarsest = texture.mip_chain().levels().last().unwrap().at(0, 0);
    // Half the light of white, which sRGB would store as ~0.735, not as code 128.
    assert!(
        close(coarsest, Texel::new(0.5, 0.5, 0.5, 1.0), 1e-6),
        "{coarsest}"
    );
}

#[test]
fn height_is_interpolated_through_the_texel_centres() {
    let heights = TexelGrid::from_fn(6, 5, |x, y| ((x * 5 + y * 3) % 7) as f32 / 6.0);
    let map = HeightMap::from_heights(heights.clone());
    for (x, y) in [(0, 0), (2, 3), (5, 4)] {
        let st = Vec2::new((x as f32 + 0.5) / 6.0, (y as f32 + 0.5) / 5.0);
        let g = map.sample_gradient(st, Wrap::Repeat, Wrap::Repeat, Footprint::POINT);
        assert!(
            (g.height - heights.at(x, y)).abs() < 1e-5,
            "({x},{y}): {g:?}"
        );
    }
}

#[test]
fn minified_bumps_flatten_instead_of_aliasing() {
    let checker = TexelGrid::from_fn(64, 64, |x, y| ((x + y) % 2) as f32);
    let map = HeightMap::from_heights(checker);
    let st = Vec2::new(0.3, 0.7);
    let sharp = map.sample_gradient(st, Wrap::Repeat, Wrap::Repeat, Footprint::POINT);
    let far = map.sample_gradient(
        st,
        Wrap::Repeat,
        Wrap::Repeat,
        Footprint::new(0.5, 0.0, 0.0, 0.5),
    );
    assert!(
        sharp.dh_ds.abs() > 10.0,
        "magnified checker must be steep: {sharp:?}"
    );
    assert!(far.dh_ds.abs() < 1e-3 && far.dh_dt.abs() < 1e-3, "{far:?}");
    assert!((far.height - 0.5).abs() < 1e-4, "{far:?}");
}
