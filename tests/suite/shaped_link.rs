//! The workbench over a slow link, as a remote user has it: `sshd` in a network namespace of its
//! own whose loopback is shaped with `tc … tbf` (a poor uplink or a busy VPN), the real `ssh -tt`
//! inside tmux as the user's terminal, and the workbench on the far side. Shared by the test that
//! asserts the figures and the bench that reports them (`cargo bench --bench slow_link`).
//!
//! Needs root (for `ip netns`), `ip`, `tc`, `sshd`, `ssh`, `ssh-keygen` and `tmux`.
#![allow(dead_code)]

use crate::tmux_support::Tmux;
use std::path::Path;
use std::process::{Child, Command, Output, Stdio};
use std::sync::atomic::{AtomicU32, Ordering};
use std::time::{Duration, Instant};

pub const TOOLS: [&str; 6] = ["ip", "tc", "/usr/sbin/sshd", "ssh", "ssh-keygen", "tmux"];

/// The longest any one step may take before the harness gives up on it.
const STEP_LIMIT: Duration = Duration::from_secs(20);

const POLL: Duration = Duration::from_millis(10);

/// Longer than a key takes to reach the workbench over the link and its frame to start back.
const QUIET: Duration = Duration::from_millis(400);

/// A network namespace with a shaped loopback and `sshd` listening in it; all removed on drop.
pub struct ShapedLink {
    namespace: String,
    dir: tempfile::TempDir,
    sshd: Child,
    port: u16,
}

impl ShapedLink {
    /// A link carrying `kbit_per_second` each way.
    pub fn start(kbit_per_second: u32) -> ShapedLink {
        static COUNT: AtomicU32 = AtomicU32::new(0);
        let namespace = format!(
            "bumpwork-{}-{}",
            std::process::id(),
            COUNT.fetch_add(1, Ordering::Relaxed)
        );
        let dir = tempfile::Builder::new()
            .prefix("bumpwork-link-")
            .tempdir()
            .unwrap();
        run(&["ip", "netns", "add", &namespace]);
        let in_namespace = |args: &[&str]| {
            let mut all = vec!["ip", "netns", "exec", &namespace];
            all.extend(args);
            run(&all);
        };
        in_namespace(&["ip", "link", "set", "lo", "up"]);
        // Ethernet-sized packets: tbf drops any packet larger than its burst.
        in_namespace(&["ip", "link", "set", "lo", "mtu", "1500"]);
        let rate = format!("{kbit_per_second}kbit");
        in_namespace(&[
            "tc", "qdisc", "add", "dev", "lo", "root", "tbf", "rate", &rate, "burst", "16kb",
            "limit", "1mb",
        ]);
        let port = 2222;
        let sshd = start_sshd(dir.path(), &namespace, port);
        let link = ShapedLink {
            namespace,
            dir,
            sshd,
            port,
        };
        link.wait_until_listening();
        link
    }

    /// The ssh client's command line into the namespace's sshd; with `tty`, a remote terminal.
    fn ssh_command(&self, tty: bool) -> String {
        format!(
            "ip netns exec {namespace} ssh{tty} -i {dir}/user_key -o StrictHostKeyChecking=no \
             -o UserKnownHostsFile=/dev/null -o BatchMode=yes -o LogLevel=ERROR -p {port} \
             root@127.0.0.1",
            namespace = self.namespace,
            tty = if tty { " -tt" } else { "" },
            dir = self.dir.path().display(),
            port = self.port,
        )
    }

    fn wait_until_listening(&self) {
        let start = Instant::now();
        loop {
            let probe = format!("{} true", self.ssh_command(false));
            let ok = Command::new("sh")
                .args(["-c", &probe])
                .stdin(Stdio::null())
                .output()
                .is_ok_and(|o| o.status.success());
            if ok {
                return;
            }
            let log = std::fs::read_to_string(self.dir.path().join("sshd.log"));
            assert!(
                start.elapsed() < STEP_LIMIT,
                "sshd does not answer: {log:?}"
            );
            std::thread::sleep(Duration::from_millis(100));
        }
    }
}

impl Drop for ShapedLink {
    fn drop(&mut self) {
        let _ = self.sshd.kill();
        let _ = self.sshd.wait();
        let _ = Command::new("ip")
            .args(["netns", "del", &self.namespace])
            .output();
    }
}

fn run(args: &[&str]) -> Output {
    let output = Command::new(args[0])
        .args(&args[1..])
        .output()
        .unwrap_or_else(|e| panic!("{}: {e}", args[0]));
    assert!(
        output.status.success(),
        "{}: {}",
        args.join(" "),
        String::from_utf8_lossy(&output.stderr)
    );
    output
}

fn start_sshd(dir: &Path, namespace: &str, port: u16) -> Child {
    write_sshd_files(dir, port);
    let _ = std::fs::create_dir_all("/run/sshd");
    Command::new("ip")
        .args([
            "netns",
            "exec",
            namespace,
            "/usr/sbin/sshd",
            "-D",
            "-e",
            "-f",
        ])
        .arg(dir.join("sshd_config"))
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(std::fs::File::create(dir.join("sshd.log")).unwrap())
        .spawn()
        .expect("sshd starts")
}

/// A host key, a user key allowed in, and an `sshd_config` in `dir` for an `sshd` listening on
/// 127.0.0.1:`port`, logging in by that key alone.
pub fn write_sshd_files(dir: &Path, port: u16) {
    for key in ["host_key", "user_key"] {
        let path = dir.join(key);
        run(&[
            "ssh-keygen",
            "-q",
            "-t",
            "ed25519",
            "-N",
            "",
            "-f",
            path.to_str().unwrap(),
        ]);
    }
    std::fs::copy(dir.join("user_key.pub"), dir.join("authorized_keys")).unwrap();
    let config = format!(
        "Port {port}\nListenAddress 127.0.0.1\nHostKey {dir}/host_key\nPidFile {dir}/sshd.pid\n\
         AuthorizedKeysFile {dir}/authorized_keys\nStrictModes no\nUsePAM no\n\
         PasswordAuthentication no\nKbdInteractiveAuthentication no\nPubkeyAuthentication yes\n\
         PermitRootLogin prohibit-password\nAllowTcpForwarding no\nX11Forwarding no\n\
         PrintMotd no\nPrintLastLog no\nLogLevel ERROR\n",
        dir = dir.display()
    );
    std::fs::write(dir.join("sshd_config"), config).unwrap();
}

/// What the remote workbench's status line says of its picture.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Shown {
    /// No status line yet.
    Nothing,
    Refining,
    Settled,
    /// The workbench (and the ssh session) ended.
    Ended,
}

/// Whether the status line counts fewer samples than a settled picture's 64 (`… 16 spp`): how a
/// build that does not say `refining` shows it, where the line is wide enough.
fn fewer_samples_than_settled(status: &str) -> bool {
    status
        .split(" spp")
        .next()
        .filter(|before| before.len() < status.len())
        .and_then(|before| before.rsplit(' ').next()?.parse::<u32>().ok())
        .is_some_and(|samples| samples < 64)
}

/// The workbench run over `link` in a tmux pane of its own.
pub struct RemoteView {
    tmux: Tmux,
}

impl RemoteView {
    /// Starts `binary view SCENE` in truecolor over `link`, in a `cols`×`rows` pane.
    pub fn start(
        link: &ShapedLink,
        binary: &Path,
        scene: &str,
        (cols, rows): (u16, u16),
    ) -> RemoteView {
        let command = format!(
            "{} 'exec {} view {scene} --colors truecolor --no-watch'",
            link.ssh_command(true),
            binary.display()
        );
        let name = format!("link-{}", link.namespace);
        RemoteView {
            tmux: Tmux::start(&name, cols, rows, &command),
        }
    }

    /// The screen with its colours, a line a row.
    fn coloured_screen(&self) -> Vec<String> {
        let capture = self.tmux.run(&["capture-pane", "-e", "-p"]).stdout;
        String::from_utf8_lossy(&capture)
            .lines()
            .map(str::to_string)
            .collect()
    }

    fn shown(&self) -> Shown {
        if self.tmux.pane("#{pane_dead}") != "0" {
            return Shown::Ended;
        }
        let text = self.tmux.screen();
        let status = text
            .trim_end_matches('\n')
            .lines()
            .last()
            .unwrap_or_default();
        if status.contains("refining") || fewer_samples_than_settled(status) {
            Shown::Refining
        } else if status.contains('│') {
            Shown::Settled
        } else {
            Shown::Nothing
        }
    }

    fn send(&self, key: &str) {
        self.tmux.send_keys(&[key]);
    }

    /// The time from `start` until the status line is `what`, if within the step limit.
    fn until(&self, start: Instant, what: &[Shown]) -> Option<Duration> {
        while start.elapsed() < STEP_LIMIT {
            if what.contains(&self.shown()) {
                return Some(start.elapsed());
            }
            std::thread::sleep(POLL);
        }
        None
    }

    /// The time from `start`, when the last key was sent, until the picture has settled: the
    /// last change of a screen that then says it is settled and stays as it is for a while
    /// (frames still queued in the link would change it).
    fn settled(&self, start: Instant) -> Option<Duration> {
        let mut last = (self.tmux.screen(), start.elapsed());
        while start.elapsed() < STEP_LIMIT {
            let screen = self.tmux.screen();
            if screen != last.0 {
                last = (screen, start.elapsed());
            } else if start.elapsed() - last.1 >= QUIET && self.shown() != Shown::Refining {
                return Some(last.1);
            }
            std::thread::sleep(POLL);
        }
        None
    }

    /// `key` sent `count` times, `apart`; the time from the last until its new view shows: the
    /// status line says `refining` and most picture rows differ from those at the moment of the
    /// key. (A settled picture on the way at that moment may be cut short by the key, its status
    /// line never sent; what of it lands after the key is a few rows.)
    fn taps(&self, key: &str, count: u32, apart: Duration) -> Option<Duration> {
        let mut shown = None;
        for _ in 0..count {
            let tap = Instant::now();
            let before = self.coloured_screen();
            self.send(key);
            shown = None;
            while tap.elapsed() < apart.max(STEP_LIMIT / 4) {
                if self.shown() == Shown::Refining
                    && most_rows_differ(&before, &self.coloured_screen())
                {
                    shown = Some(tap.elapsed());
                    break;
                }
                std::thread::sleep(POLL);
            }
            std::thread::sleep(apart.saturating_sub(tap.elapsed()));
        }
        shown
    }

    /// `key` sent every 30 ms for `held`, as a terminal repeats a held key.
    fn hold(&self, key: &str, held: Duration) -> Instant {
        let start = Instant::now();
        while start.elapsed() < held {
            self.send(key);
            std::thread::sleep(Duration::from_millis(30));
        }
        Instant::now()
    }
}

/// Whether most picture rows (all but the status line) of two screens differ.
fn most_rows_differ(before: &[String], after: &[String]) -> bool {
    let rows = before.len().min(after.len()).saturating_sub(1);
    let differing = (0..rows).filter(|&row| before[row] != after[row]).count();
    differing * 2 > rows
}

/// How the workbench answers over a link, each from the key (or the start) that asked.
#[derive(Clone, Copy, Debug, Default)]
pub struct Figures {
    pub first_picture: Option<Duration>,
    pub start_settled: Option<Duration>,
    pub arrow_shown: Option<Duration>,
    pub arrow_settled: Option<Duration>,
    /// After an arrow held 0.6 s is let go.
    pub held_settled: Option<Duration>,
    /// After `q` right after an arrow held 0.6 s.
    pub quit_after_held: Option<Duration>,
    /// After `q` sent 0.1 s after an arrow, while its new view is on the way (at 160×50 and
    /// 2 Mbit/s; a smaller screen's may have landed).
    pub quit_mid_view: Option<Duration>,
    /// The fifth of five arrows a second apart, until its view shows.
    pub fifth_tap_shown: Option<Duration>,
}

/// Drives the workbench over `link` through start-up, one arrow, a held arrow, five arrows, and
/// `q` after another held arrow; then, started again, `q` while an arrow's view is on the way.
pub fn measure(link: &ShapedLink, binary: &Path, scene: &str, size: (u16, u16)) -> Figures {
    let start = Instant::now();
    let view = RemoteView::start(link, binary, scene, size);
    let mut figures = Figures {
        first_picture: view.until(start, &[Shown::Refining, Shown::Settled]),
        start_settled: view.settled(start),
        ..Figures::default()
    };
    let arrow = Instant::now();
    view.send("Right");
    figures.arrow_shown = view.until(arrow, &[Shown::Refining]);
    figures.arrow_settled = view.settled(arrow);
    let released = view.hold("Left", Duration::from_millis(600));
    figures.held_settled = view.settled(released);
    figures.fifth_tap_shown = view.taps("Up", 5, Duration::from_secs(1));
    view.hold("Right", Duration::from_millis(600));
    let quit = Instant::now();
    view.send("q");
    figures.quit_after_held = view.until(quit, &[Shown::Ended]);
    drop(view);
    let start = Instant::now();
    let view = RemoteView::start(link, binary, scene, size);
    view.until(start, &[Shown::Refining, Shown::Settled]);
    view.settled(start);
    view.send("Right");
    std::thread::sleep(Duration::from_millis(100));
    let quit = Instant::now();
    view.send("q");
    figures.quit_mid_view = view.until(quit, &[Shown::Ended]);
    figures
}
