//! A real SSH session: `sshd` on a free loopback port with a host key and a user key made here,
//! the real `ssh -tt` inside tmux, the workbench on the far side. Keys are driven, the window is
//! resized, then the ssh client is killed (SIGKILL: nothing of it runs again). The remote
//! workbench must take the hang-up (SIGHUP when its pseudo-terminal goes) and leave no process
//! behind; where a parent catches the hang-up instead, it must notice its terminal is gone and
//! end with the hang-up's status, 129.
//!
//! Needs `sshd`, `ssh`, `ssh-keygen` and `tmux`: `.ci/run` installs them; without them the test
//! prints why it skips. (Nothing restores the local pane after the client is killed: SIGKILL gives
//! ssh no chance to put its terminal back, and that pane's program is gone. The remote workbench's
//! terminal is the one it restores, and that terminal is gone with the connection.)

#![cfg(unix)]

use crate::shaped_link::write_sshd_files;
use crate::test_dir::TestDir;
use crate::tmux_support::{DEADLINE, Tmux, eventually, require};
use std::net::{Ipv4Addr, TcpListener, TcpStream};
use std::path::Path;
use std::process::{Child, Command, Stdio};

const SSHD: &str = "/usr/sbin/sshd";

/// `sshd` killed (and its host keys removed) when the test ends, however it ends.
struct Server {
    child: Child,
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn user() -> String {
    let output = Command::new("id").arg("-un").output().unwrap();
    String::from_utf8(output.stdout).unwrap().trim().to_string()
}

fn free_port() -> u16 {
    TcpListener::bind((Ipv4Addr::LOCALHOST, 0))
        .unwrap()
        .local_addr()
        .unwrap()
        .port()
}

fn start_sshd(dir: &Path, port: u16) -> Server {
    write_sshd_files(dir, port);
    // As root, sshd wants its privilege-separation directory.
    let _ = std::fs::create_dir_all("/run/sshd");
    let child = Command::new(SSHD)
        .args(["-D", "-e", "-f"])
        .arg(dir.join("sshd_config"))
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(std::fs::File::create(dir.join("sshd.log")).unwrap())
        .spawn()
        .expect("sshd starts");
    let mut server = Server { child };
    let listening = eventually(DEADLINE, || {
        TcpStream::connect((Ipv4Addr::LOCALHOST, port)).is_ok()
    });
    let log = std::fs::read_to_string(dir.join("sshd.log")).unwrap_or_default();
    assert!(
        listening && server.child.try_wait().unwrap().is_none(),
        "sshd did not start: {log}"
    );
    server
}

/// Processes running the program named `marker` (their argv[0] ends with it; the ssh client's
/// and tmux's command lines merely mention it).
fn processes_with(marker: &str) -> Vec<u32> {
    std::fs::read_dir("/proc")
        .unwrap()
        .filter_map(|e| e.ok()?.file_name().to_str()?.parse::<u32>().ok())
        .filter(|pid| {
            std::fs::read(format!("/proc/{pid}/cmdline")).is_ok_and(|c| {
                let program = c.split(|&b| b == 0).next().unwrap_or_default();
                program.ends_with(marker.as_bytes())
            })
        })
        .collect()
}

/// One session: the workbench on the far side (`remote`, a shell command line that runs
/// `binary`), driven, resized, then the client killed; returns once no remote workbench is left.
fn session(name: &str, remote: impl Fn(&Path) -> String) {
    let dir = TestDir::new(&format!("ssh-{name}"));
    let port = free_port();
    let _server = start_sshd(&dir, port);

    // A name of its own for the remote binary, to find its process and no other test's.
    let marker = format!("bumpwork-over-ssh-{name}-{}", std::process::id());
    let binary = dir.join(&marker);
    std::os::unix::fs::symlink(env!("CARGO_BIN_EXE_bumpwork"), &binary).unwrap();
    let ssh = format!(
        "exec ssh -tt -i {dir}/user_key -o StrictHostKeyChecking=no -o UserKnownHostsFile=/dev/null \
         -o BatchMode=yes -o LogLevel=ERROR -p {port} {user}@127.0.0.1 '{remote}'",
        dir = dir.display(),
        user = user(),
        remote = remote(&binary),
    );
    let tmux = Tmux::start(&format!("ssh-{name}"), 100, 30, &ssh);
    let client = tmux.pane("#{pane_pid}");

    tmux.wait_for("the first frame over ssh", |s| {
        s.contains("1/2 plane-dimples")
    });
    assert_eq!(processes_with(&marker).len(), 1, "one remote workbench");
    tmux.send_keys(&["v"]);
    tmux.wait_for("the height view", |s| s.contains("│ height │"));
    tmux.send_keys(&["Tab"]);
    tmux.wait_for("the next scene", |s| {
        s.contains("2/2 sphere-on-plane-dimples")
    });

    // The window change travels through ssh; the workbench lays out for 80×20.
    tmux.resize(80, 20);
    tmux.wait_for("the status line on the new last row", |s| {
        let lines: Vec<&str> = s.lines().collect();
        lines.len() == 20 && lines[19].contains("2/2 sphere-on-plane-dimples")
    });

    let killed = Command::new("kill")
        .args(["-KILL", &client])
        .status()
        .unwrap();
    assert!(killed.success(), "kill the ssh client {client}");
    let gone = eventually(DEADLINE, || processes_with(&marker).is_empty());
    if !gone {
        // Leave no stray workbench behind the failure.
        for pid in processes_with(&marker) {
            let _ = Command::new("kill")
                .args(["-KILL", &pid.to_string()])
                .status();
        }
        panic!("the remote workbench outlived its session");
    }
}

/// `ssh host bumpwork`: the workbench leads the remote session, so the hang-up is its own.
#[test]
#[ignore = "needs sshd, ssh and tmux; bash .ci/run installs them and runs the ignored tests"]
fn killing_the_ssh_client_hangs_up_the_remote_workbench() {
    require(&[SSHD, "ssh", "ssh-keygen", "tmux"]);
    session("exec", |binary| {
        format!(
            "exec {} view plane-dimples sphere-on-plane-dimples --no-watch",
            binary.display()
        )
    });
}

/// A parent that catches the hang-up itself (here a shell with a trap, waiting to record the exit
/// status): no SIGHUP reaches the workbench, only a terminal that is gone. It must notice that,
/// and end as a hang-up would, with status 129.
#[test]
#[ignore = "needs sshd, ssh and tmux; bash .ci/run installs them and runs the ignored tests"]
fn a_vanished_terminal_ends_the_workbench_without_a_hang_up_signal() {
    require(&[SSHD, "ssh", "ssh-keygen", "tmux"]);
    let dir = tempfile::tempdir().expect("a temporary directory");
    let status_file = dir.path().join("status");
    session("trap", |binary| {
        format!(
            "trap : HUP; {} view plane-dimples sphere-on-plane-dimples --no-watch; echo $? > {}",
            binary.display(),
            status_file.display()
        )
    });
    assert!(
        eventually(DEADLINE, || std::fs::read_to_string(&status_file)
            .is_ok_and(|s| s.ends_with('\n'))),
        "the remote shell recorded no exit status"
    );
    let status = std::fs::read_to_string(&status_file).unwrap();
    assert_eq!(
        status.trim(),
        "129",
        "exit status once the terminal is gone"
    );
    let _ = std::fs::remove_file(&status_file);
}
