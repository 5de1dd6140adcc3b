//! Starting and dropping a reloader 100 times leaves no thread and no watcher behind. Run in a
//! process of its own, so the thread count is this test's own.

use crate::watch::support::*;
use bumpwork::watch::{Reloader, SceneFileSource};
use std::fs;

#[test]
fn a_hundred_starts_and_drops_leave_no_thread_or_watcher_behind() {
    alone_in_a_process(
        "watch::churn::a_hundred_starts_and_drops_leave_no_thread_or_watcher_behind",
        || {
            let dir = TempDir::new("churn");
            fs::write(dir.join("ridges.pat"), pattern_source(1)).unwrap();
            fs::write(
                dir.join("scene.toml"),
                scene_toml("pattern = \"ridges.pat\""),
            )
            .unwrap();
            let start = || Reloader::start(SceneFileSource::new(dir.join("scene.toml"))).unwrap();
            let (threads, fds) = (thread_count(), open_fd_count());
            for round in 0..100 {
                let (reloader, first) = start();
                assert!(first.is_ok(), "round {round}");
                if round % 10 == 0 {
                    // Some rounds drop the reloader with a reload under way.
                    fs::write(dir.join("ridges.pat"), pattern_source(round)).unwrap();
                }
                drop(reloader);
            }
            wait_for_counts(threads, fds);
        },
    );
}
