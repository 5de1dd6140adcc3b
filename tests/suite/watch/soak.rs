//! 1000 rapid saves alternating good and broken content: nothing panics, no thread or watcher
//! is left behind, and what is shown in the end is the final file. Run in a process of its
//! own, so the thread count is this test's own.

use crate::watch::support::*;
use bumpwork::watch::{Reloader, SceneFileSource};
use std::fs;

const SAVES: u32 = 1000;

#[test]
fn a_thousand_rapid_saves_end_showing_the_final_file() {
    alone_in_a_process(
        "watch::soak::a_thousand_rapid_saves_end_showing_the_final_file",
        || {
            let dir = TempDir::new("soak");
            let pattern = dir.join("ridges.pat");
            fs::write(&pattern, pattern_source(0)).unwrap();
            fs::write(
                dir.join("scene.toml"),
                scene_toml("pattern = \"ridges.pat\""),
            )
            .unwrap();
            let (threads, fds) = (thread_count(), open_fd_count());

            let (reloader, first) =
                Reloader::start(SceneFileSource::new(dir.join("scene.toml"))).unwrap();
            let mut shown = Shown::new(first);
            let mut most_threads = 0;
            for save in 1..=SAVES {
                let content = match save % 2 {
                    0 => pattern_source(save),
                    _ => BROKEN_PATTERN.to_string(),
                };
                fs::write(&pattern, content).unwrap();
                while let Some(outcome) = reloader.poll() {
                    shown.apply(outcome);
                }
                most_threads = most_threads.max(thread_count());
            }
            shown.wait_for_k(&reloader, SAVES);
            // The reloader's thread, the debouncer's and the watcher's event loop.
            assert!(
                most_threads <= threads + 3,
                "{most_threads} threads, from {threads}"
            );
            assert!(shown.reloads < SAVES as usize, "saves were not debounced");

            drop(reloader);
            wait_for_counts(threads, fds);
        },
    );
}
