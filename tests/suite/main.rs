//! The integration tests, as modules of one test crate: the library and its dev-dependencies are
//! linked once, not once a file. `tests/term_signals.rs` stays a crate of its own because it
//! raises signals at its own process.

#[path = "../../fuzz/src/lib.rs"]
#[allow(dead_code)]
mod fuzz_entry;

mod bake_maps;
mod bench_command;
mod bump_shading;
mod cli;
mod cli_support;
mod common;
mod exact_points;
mod export_stills;
mod fuzz_regressions;
mod graphics_support;
mod hostile_files;
mod hostile_tui;
mod memory_budget;
mod messages;
mod never_stuck;
mod nothing_lost;
mod output_paths;
mod pattern_builtins;
mod pattern_errors;
mod pattern_fuzz;
mod pattern_gradients;
mod pattern_non_finite;
mod pattern_precision;
mod pattern_seed_dimples;
mod pattern_support;
mod pattern_textures;
mod pty_support;
mod quality_knobs;
mod raster_clipping;
mod raster_extremes;
mod raster_perspective;
mod raster_reuse;
mod raster_watertight;
mod real_terminals;
mod reference_accuracy;
mod reference_extremes;
mod reference_properties;
mod reference_round_trip;
mod reference_support;
mod render_watch;
mod scene_files;
mod scene_quality;
mod settings;
mod shadows;
mod source_layout;
mod ssh_session;
mod still_bands;
mod term_encode;
mod term_env;
mod term_writer;
mod terminators;
mod test_dir;
mod texture_limits;
mod texture_loading;
mod texture_mapping;
mod texture_mutations;
mod texture_pngsuite;
mod texture_sampling;
mod texture_shipped;
mod tmux_support;
mod tui_cells;
mod tui_error_view;
mod tui_graphics;
mod tui_pty;
mod tui_refinement;
mod tui_screen;
mod watch_churn;
mod watch_reload;
mod watch_soak;
mod watch_support;
