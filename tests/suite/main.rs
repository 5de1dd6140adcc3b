//! The integration tests, as modules of one test crate: the library and its dev-dependencies are
//! linked once, not once a file. `tests/term_signals.rs` stays a crate of its own because it
//! raises signals at its own process.

mod animations;
mod bake_maps;
mod bench_command;
mod cli;
mod cli_support;
mod common;
mod export;
#[path = "../../fuzz/src/lib.rs"]
#[allow(dead_code)]
mod fuzz_entry;
mod fuzz_regressions;
mod graphics_support;
mod hostile_files;
mod hostile_tui;
mod memory_budget;
mod messages;
mod models;
mod never_stuck;
mod nothing_lost;
mod output_paths;
mod pattern;
mod pov_support;
mod pty_support;
mod quality;
mod raster;
mod real_terminals;
mod reference;
mod render_watch;
mod scene;
mod settings;
mod shade;
mod shadow;
mod shaped_link;
mod shards;
mod slow_link;
mod source_layout;
mod ssh_session;
mod still;
mod surface;
mod sweeps;
mod term;
mod test_dir;
mod texture;
mod tmux_support;
mod tui;
mod variant_names;
mod watch;
