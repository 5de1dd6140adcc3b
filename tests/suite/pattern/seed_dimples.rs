//! `dimples-seed.pat` reproduces the seed lecture's dimples code, and `dimples.pat` is its
//! continuous height form.

use crate::pattern::support::{bump, sample_points, shipped};
use bumpwork::pattern::native::dimples_seed;

#[test]
fn slope_file_matches_the_seed_code() {
    let pattern = shipped("dimples-seed");
    let mut points = sample_points(2000, -400.0, 800.0, 5);
    points.extend((-60..60).flat_map(|u| (-2..2).map(move |v| (u as f32, v as f32 * 7.5))));
    let (samples, bad) = bump(&pattern, &points);
    assert_eq!(bad, 0);
    let mut inside = 0;
    for (&(u, v), s) in points.iter().zip(&samples) {
        let (bu, bv) = dimples_seed(f64::from(u), f64::from(v));
        inside += usize::from(bu != 0.0 || bv != 0.0);
        assert!((f64::from(s.du) - bu).abs() < 1e-6, "Bu at ({u}, {v})");
        assert!((f64::from(s.dv) - bv).abs() < 1e-6, "Bv at ({u}, {v})");
        assert_eq!(s.height, 0.0);
    }
    assert!(inside > points.len() / 4, "too few points inside dimples");
}

#[test]
fn height_form_has_the_seed_gradient_at_integer_points() {
    let pattern = shipped("dimples");
    let points: Vec<(f32, f32)> = (-45..45)
        .flat_map(|u| (-45..45).step_by(7).map(move |v| (u as f32, v as f32)))
        .collect();
    let (samples, _) = bump(&pattern, &points);
    for (&(u, v), s) in points.iter().zip(&samples) {
        let (bu, bv) = dimples_seed(f64::from(u), f64::from(v));
        assert!((f64::from(s.du) - bu).abs() < 1e-5, "Bu at ({u}, {v})");
        assert!((f64::from(s.dv) - bv).abs() < 1e-5, "Bv at ({u}, {v})");
    }
}

#[test]
fn dimples_are_lowered_and_flat_between() {
    let pattern = shipped("dimples");
    let (samples, _) = bump(&pattern, &[(15.0, 15.0), (0.5, 0.5), (-15.0, 45.0)]);
    assert_eq!(samples[0].height, -5.0);
    assert_eq!(samples[1].height, 0.0);
    assert_eq!(samples[2].height, -5.0);
}
