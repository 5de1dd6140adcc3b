//! Over a slow SSH link the workbench answers at once: at most one frame in flight, refinement
//! the link can carry, and `q` that quits now. The link is real (see `shaped_link`); the limits
//! are about twice what the workbench takes, and below what it took when it wrote every frame as
//! fast as it could (one arrow 2.5 s to settle, `q` after a held arrow 4.7 s, start-up 2.9 s).

use crate::shaped_link::{ShapedLink, TOOLS, measure};
use crate::tmux_support::require;
use std::path::Path;
use std::time::Duration;

#[test]
#[ignore = "needs root, ip, tc, sshd, ssh and tmux; bash .ci/run installs them and runs the ignored tests"]
fn over_a_2_mbit_link_the_workbench_answers_at_once() {
    require(&TOOLS);
    let link = ShapedLink::start(2_000);
    let binary = Path::new(env!("CARGO_BIN_EXE_bumpwork"));
    let figures = measure(&link, binary, "sphere-on-plane-dimples", (160, 50));
    eprintln!("{figures:?}");
    let within =
        |took: Option<Duration>, seconds: f64| took.is_some_and(|t| t.as_secs_f64() <= seconds);
    assert!(within(figures.arrow_shown, 1.2), "{figures:?}");
    assert!(within(figures.arrow_settled, 2.0), "{figures:?}");
    assert!(within(figures.held_settled, 3.0), "{figures:?}");
    assert!(within(figures.fifth_tap_shown, 1.2), "{figures:?}");
    assert!(within(figures.quit_after_held, 0.6), "{figures:?}");
    assert!(within(figures.quit_mid_view, 0.6), "{figures:?}");
    assert!(within(figures.start_settled, 2.5), "{figures:?}");
}
