//! Helpers for the hot-reload tests: scenes in fresh temporary directories, what the workbench
//! would show, and waiting (with a generous timeout, for loaded CI machines) until it is right.
#![allow(dead_code)]

use bumpwork::scene::{BumpSource, Scene};
use bumpwork::watch::{ReloadError, ReloadOutcome, Reloader};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

pub const TIMEOUT: Duration = Duration::from_secs(60);

/// A directory removed (with its files) on drop.
pub struct TempDir(tempfile::TempDir);

impl TempDir {
    pub fn new(tag: &str) -> TempDir {
        let dir = tempfile::Builder::new()
            .prefix(&format!("bumpwork-{tag}-"))
            .tempdir()
            .expect("a temporary directory");
        TempDir(dir)
    }

    pub fn join(&self, name: &str) -> PathBuf {
        self.0.path().join(name)
    }

    pub fn path(&self) -> &Path {
        self.0.path()
    }
}

/// A sphere whose bump is `binding` (the inside of a `bump = { … }` table).
pub fn scene_toml(binding: &str) -> String {
    format!(
        "[camera]\neye = [0, 260, 620]\ntarget = [0, 70, 0]\n\n\
         [[light]]\npoint = {{ position = [-400, 600, 500] }}\n\n\
         [[object]]\nsurface = {{ sphere = {{ center = [0, 100, 0], radius = 100 }} }}\n\
         bump = {{ {binding} }}\n"
    )
}

/// A height pattern whose parameter `k` defaults to `k`: the mark of which save was loaded.
pub fn pattern_source(k: u32) -> String {
    format!("# save {k}\nparam k = {k} in 0..100000\nheight = k * 0.001 * sin(u)\n")
}

/// Breaks at the end: line 4, column 1.
pub const BROKEN_PATTERN: &str = "# broken\nparam k = 1 in 0..10\nheight = k *\n";

/// The bump pattern's `k` as compiled (the default, i.e. the file's mark), if any.
pub fn loaded_k(scene: &Scene) -> Option<f32> {
    let bump = scene.objects.first()?.material.bump.as_ref()?;
    let BumpSource::Pattern(binding) = &bump.source else {
        return None;
    };
    let param = binding.pattern.params().iter().find(|p| p.name == "k")?;
    Some(param.default)
}

/// What the workbench shows: the last good scene, the error since then, and counts.
#[derive(Debug)]
pub struct Shown {
    pub scene: Option<Scene>,
    pub error: Option<ReloadError>,
    pub reloads: usize,
    pub unchanged: usize,
}

impl Shown {
    pub fn new(first: Result<Scene, ReloadError>) -> Shown {
        let (scene, error) = match first {
            Ok(scene) => (Some(scene), None),
            Err(error) => (None, Some(error)),
        };
        Shown {
            scene,
            error,
            reloads: 0,
            unchanged: 0,
        }
    }

    pub fn apply(&mut self, outcome: ReloadOutcome) {
        match outcome {
            ReloadOutcome::Reloaded(reload) => {
                self.scene = Some(match &self.scene {
                    Some(live) => reload.keep_live_params(live),
                    None => reload.scene,
                });
                self.error = None;
                self.reloads += 1;
            }
            ReloadOutcome::Failed(error) => self.error = Some(error),
            ReloadOutcome::Unchanged => self.unchanged += 1,
        }
    }

    pub fn k(&self) -> Option<f32> {
        self.scene.as_ref().and_then(loaded_k)
    }

    pub fn error_line(&self) -> &str {
        self.error.as_ref().map_or("", |e| e.first_line())
    }

    /// Applies outcomes until `done` holds; panics after `TIMEOUT` naming `what`.
    pub fn wait_until(&mut self, reloader: &Reloader, what: &str, done: impl Fn(&Shown) -> bool) {
        let deadline = Instant::now() + TIMEOUT;
        while !done(self) {
            let left = deadline.saturating_duration_since(Instant::now());
            match reloader.wait(left.min(Duration::from_millis(100))) {
                Some(outcome) => self.apply(outcome),
                None if left.is_zero() => panic!(
                    "timed out waiting for {what}; shown k = {:?}, error = {:?}",
                    self.k(),
                    self.error_line()
                ),
                None => {}
            }
        }
    }

    /// Waits until the pattern saved as `k` is shown with no error.
    pub fn wait_for_k(&mut self, reloader: &Reloader, k: u32) {
        self.wait_until(reloader, &format!("save {k} to be shown"), |s| {
            s.k() == Some(k as f32) && s.error.is_none()
        });
    }

    /// Waits until an error containing `needle` is shown, with save `k` still on screen.
    pub fn wait_for_error(&mut self, reloader: &Reloader, needle: &str, k: u32) {
        self.wait_until(reloader, &format!("an error with '{needle}'"), |s| {
            s.error_line().contains(needle)
        });
        assert_eq!(self.k(), Some(k as f32), "the last good scene stays");
    }
}

/// Threads of this process, from /proc.
pub fn thread_count() -> usize {
    let status = std::fs::read_to_string("/proc/self/status").unwrap();
    status
        .lines()
        .find_map(|l| l.strip_prefix("Threads:"))
        .and_then(|n| n.trim().parse().ok())
        .unwrap()
}

/// Open file descriptors of this process (each watcher holds an inotify one).
pub fn open_fd_count() -> usize {
    std::fs::read_dir("/proc/self/fd").unwrap().count()
}

/// Waits until the thread and descriptor counts are back to `threads` and `fds` (a dropped
/// watcher's own threads end shortly after it is dropped, not during the drop).
pub fn wait_for_counts(threads: usize, fds: usize) {
    let deadline = Instant::now() + TIMEOUT;
    while thread_count() > threads || open_fd_count() > fds {
        assert!(
            Instant::now() < deadline,
            "leaked: {} threads (was {threads}), {} descriptors (was {fds})",
            thread_count(),
            open_fd_count()
        );
        std::thread::sleep(Duration::from_millis(10));
    }
}

/// Runs `body` in a process of its own (this test binary again, running only the test `name`),
/// so that thread and descriptor counts are the test's own and not those of tests running
/// beside it. Panics with the child's output if it fails or outlives `TIMEOUT` twice over.
pub fn alone_in_a_process(name: &str, body: impl FnOnce()) {
    const ALONE: &str = "BUMPWORK_TEST_ALONE";
    if std::env::var(ALONE).is_ok_and(|n| n == name) {
        body();
        return;
    }
    let mut child = std::process::Command::new(std::env::current_exe().unwrap())
        .args([name, "--exact", "--test-threads", "1", "--nocapture"])
        .env(ALONE, name)
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let deadline = Instant::now() + 2 * TIMEOUT;
    while child.try_wait().unwrap().is_none() {
        if Instant::now() > deadline {
            let _ = child.kill();
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    let output = child.wait_with_output().unwrap();
    assert!(
        output.status.success(),
        "{name} alone: {}\n{}",
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    );
    // The child ran the body: a filter matching no test would also succeed.
    assert!(
        String::from_utf8_lossy(&output.stdout).contains("1 passed"),
        "{name} did not run alone: {}",
        String::from_utf8_lossy(&output.stdout)
    );
}
