//! Progressive refinement of the terminal picture: the error against the area-averaged picture
//! falls as passes accrue and ends within the bound; the screen keeps refining while idle and
//! starts again on any change.

use bumpwork::term::{ColorChoice, ColorMode, GlyphSet};
use bumpwork::tui::{
    Accumulation, Action, App, CellShape, DEFAULT_CELL_ASPECT, MAX_PASSES, Sampling, Screen,
    WorkbenchOptions, render_frame, render_picture_pass,
};
use glam::Vec3;

const CELLS: (usize, usize) = (80, 24);
const HALF_BLOCKS: CellShape = CellShape {
    glyphs: GlyphSet::HalfBlock,
    aspect: DEFAULT_CELL_ASPECT,
};

fn app(scene: &str) -> App {
    let options = WorkbenchOptions {
        scenes: vec![scene.into()],
        colors: ColorChoice::Fixed(ColorMode::TrueColor),
        ..WorkbenchOptions::default()
    };
    App::new(&options, ColorMode::TrueColor).unwrap()
}

/// The half-block picture's sub-pixels averaged over their area from 8 × 8 samples each.
fn area_averaged(app: &App, size: (usize, usize)) -> Vec<Vec3> {
    const GRID: usize = 8;
    let mut framebuffer = bumpwork::raster::Framebuffer::new(0, 0, Vec3::ZERO);
    let (w, h) = (size.0 * GRID, size.1 * GRID);
    render_frame(&app.view(), w as u32, h as u32, &mut framebuffer);
    let colour = framebuffer.color();
    (0..size.0 * size.1)
        .map(|i| {
            let (x, y) = (i % size.0, i / size.0);
            let block =
                (0..GRID * GRID).map(|k| colour[(y * GRID + k / GRID) * w + x * GRID + k % GRID]);
            block.sum::<Vec3>() / (GRID * GRID) as f32
        })
        .collect()
}

/// PSNR in dB between two pictures as the terminal shows them (8-bit sRGB).
fn psnr(a: &[Vec3], b: &[Vec3]) -> f64 {
    let srgb = |c: f32| f64::from(bumpwork::raster::linear_to_srgb8(c));
    let squared: f64 = a
        .iter()
        .zip(b)
        .flat_map(|(p, q)| (0..3).map(move |i| (srgb(p[i]) - srgb(q[i])).powi(2)))
        .sum();
    let mse = squared / (a.len() * 3) as f64;
    10.0 * (255.0f64.powi(2) / mse.max(1e-12)).log10()
}

#[test]
fn the_error_falls_as_passes_accrue_and_the_settled_picture_is_within_the_bound() {
    for scene in ["sphere-on-plane-dimples", "textured-sphere"] {
        let app = app(scene);
        let mut framebuffer = bumpwork::raster::Framebuffer::new(0, 0, Vec3::ZERO);
        let view = app.view();
        let pass = |sampling: Sampling, framebuffer: &mut _| {
            render_picture_pass(&view, CELLS, HALF_BLOCKS, 1, sampling, framebuffer)
        };
        let first = pass(Sampling::CENTRE, &mut framebuffer);
        let reference = area_averaged(&app, first.size);
        let mut accumulation = Accumulation::default();
        accumulation.restart(first.linear, first.size);
        let mut errors = vec![(1, psnr(&accumulation.mean(), &reference))];
        while accumulation.wants_more() {
            let sampling = Sampling {
                offset: accumulation.next_offset(),
                footprint: accumulation.next_footprint(),
            };
            let next = pass(sampling, &mut framebuffer);
            accumulation.add(&next.linear);
            if accumulation.passes().is_power_of_two() {
                errors.push((
                    accumulation.passes(),
                    psnr(&accumulation.mean(), &reference),
                ));
            }
        }
        eprintln!("{scene}: passes and PSNR {errors:.1?}");
        assert_eq!(accumulation.passes(), MAX_PASSES);
        for pair in errors.windows(2) {
            // Each doubling of the samples gains, up to the noise of a few differing pixels.
            assert!(pair[1].1 > pair[0].1 - 0.5, "{scene}: {errors:.1?}");
        }
        let (first, settled) = (errors[0].1, errors.last().unwrap().1);
        assert!(settled > first + 6.0, "{scene}: {errors:.1?}");
        assert!(settled >= 40.0, "{scene}: settled at {settled:.1} dB");
    }
}

#[test]
fn an_idle_screen_refines_to_the_last_pass_and_a_key_starts_again() {
    let mut app = app("sphere-on-plane-dimples");
    let mut screen = Screen::new(40, 12);
    let mut out = Vec::new();
    screen.draw(&mut app, &mut out).unwrap();
    assert_eq!(app.frame_report().passes, 1);
    let mut redraws = 0;
    while screen.refining(&app) {
        if screen.refine(&mut app, &mut out).unwrap() > 0 {
            redraws += 1;
        }
    }
    assert_eq!(app.frame_report().passes, MAX_PASSES);
    assert!(
        (1..=6).contains(&redraws),
        "{redraws} redraws while refining"
    );
    app.apply(Action::Orbit(5.0, 0.0));
    assert!(
        !screen.refining(&app),
        "a change is drawn before any pass is added"
    );
    screen.draw(&mut app, &mut out).unwrap();
    assert_eq!(app.frame_report().passes, 1);
    assert!(screen.refining(&app));
}
