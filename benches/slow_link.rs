//! The workbench over a slow SSH link (sshd in a network namespace shaped with `tc … tbf`, the
//! real `ssh -tt` in tmux): from start, one arrow, an arrow held 0.6 s, five arrows a second
//! apart, `q` after a held arrow and `q` while an arrow's view is on the way, the time until the
//! picture shows and settles, at 2 and 10 Mbit/s, at 160×50 and 80×24 cells. Medians of 3 runs,
//! with their range. `BUMPWORK_BINARY=PATH` measures another build beside this one (say the last
//! release), in the same run.
//!
//! Needs root, `ip`, `tc`, `sshd`, `ssh` and `tmux`. Run: `cargo bench --bench slow_link`.

#[path = "../tests/suite/shaped_link.rs"]
mod shaped_link;
#[path = "../tests/suite/tmux_support.rs"]
mod tmux_support;

use shaped_link::{Figures, ShapedLink, TOOLS, measure};
use std::path::PathBuf;
use std::process::Command;
use std::time::Duration;

const RUNS: usize = 3;
const SCENE: &str = "sphere-on-plane-dimples";

fn main() {
    if let Some(missing) = missing_tool() {
        println!(
            "slow_link not run: {missing} (root and iproute2, openssh-server, tmux are needed)"
        );
        return;
    }
    let mut binaries = vec![("this build", PathBuf::from(env!("CARGO_BIN_EXE_bumpwork")))];
    if let Some(other) = std::env::var_os("BUMPWORK_BINARY") {
        binaries.push(("BUMPWORK_BINARY", PathBuf::from(other)));
    }
    println!("{SCENE}, truecolor half blocks; seconds, median of {RUNS} runs (range)");
    for kbit in [2_000, 10_000] {
        for size in [(160, 50), (80, 24)] {
            for (name, binary) in &binaries {
                let runs: Vec<Figures> = (0..RUNS)
                    .map(|_| measure(&ShapedLink::start(kbit), binary, SCENE, size))
                    .collect();
                report(
                    &format!("{} Mbit/s, {}x{}, {name}", kbit / 1000, size.0, size.1),
                    &runs,
                );
            }
        }
    }
}

fn missing_tool() -> Option<String> {
    let root = Command::new("id").arg("-u").output().ok()?;
    if String::from_utf8_lossy(&root.stdout).trim() != "0" {
        return Some("not root".into());
    }
    TOOLS
        .iter()
        .find(|tool| {
            !std::path::Path::new(tool).exists()
                && !Command::new("sh")
                    .args(["-c", &format!("command -v {tool}")])
                    .output()
                    .is_ok_and(|o| o.status.success())
        })
        .map(|tool| format!("{tool} is missing"))
}

/// One of the figures of a run.
type Figure = fn(&Figures) -> Option<Duration>;

fn report(label: &str, runs: &[Figures]) {
    println!("\n{label}");
    let rows: [(&str, Figure); 8] = [
        ("start-up: first picture", |f| f.first_picture),
        ("start-up: settled", |f| f.start_settled),
        ("one arrow: new view shown", |f| f.arrow_shown),
        ("one arrow: settled", |f| f.arrow_settled),
        ("held arrow: settled after release", |f| f.held_settled),
        ("fifth of 5 arrows 1 s apart: shown", |f| f.fifth_tap_shown),
        ("q after a held arrow: ended", |f| f.quit_after_held),
        ("q as an arrow's view comes: ended", |f| f.quit_mid_view),
    ];
    for (what, figure) in rows {
        let mut seconds: Vec<f64> = runs
            .iter()
            .filter_map(|r| figure(r).map(|d| d.as_secs_f64()))
            .collect();
        seconds.sort_by(f64::total_cmp);
        match seconds.len() {
            0 => println!("  {what:<36} never"),
            n => println!(
                "  {what:<36} {:.2} ({:.2}–{:.2}){}",
                seconds[n / 2],
                seconds[0],
                seconds[n - 1],
                if n < runs.len() {
                    " (some runs never)"
                } else {
                    ""
                }
            ),
        }
    }
}
