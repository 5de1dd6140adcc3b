//! Which pixel protocol a terminal speaks: the kitty graphics query, the primary device
//! attributes (DA1; attribute 4 is sixel), XTSMGRAPHICS for the sixel size limit, the cell size
//! in pixels (`CSI 16 t`), and for iTerm2 its environment. The replies are read here, before the
//! key handler reads anything, within a short time-out, so none reaches it or the screen.

use super::{GraphicsChoice, Protocol, kitty, tmux_passthrough};
use std::io::{self, Write};
use std::time::{Duration, Instant};

/// The longest wait for the replies. Every terminal answers DA1, which comes last, and the wait
/// ends there; this bounds it for one that does not, and is long enough that a terminal slowed by
/// a loaded machine is not taken for one without graphics for the rest of the session.
pub const REPLY_TIME_OUT: Duration = Duration::from_secs(2);

/// The longest wait over SSH, where the replies cross the link and back: a reply after the wait
/// would reach the key handler.
pub const REPLY_TIME_OUT_OVER_SSH: Duration = Duration::from_secs(3);

/// Bytes of replies read at most.
const MAX_REPLY_BYTES: usize = 4096;

/// What the terminal said.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Replies {
    pub kitty: bool,
    /// DA1 was answered (the terminal speaks at all).
    pub attributes: bool,
    pub sixel: bool,
    /// The largest sixel image, from XTSMGRAPHICS.
    pub sixel_limit: Option<(u32, u32)>,
    /// A cell's width and height in pixels.
    pub cell_pixels: Option<(u32, u32)>,
}

impl Replies {
    /// Reads the replies in `bytes`.
    pub fn parse(bytes: &[u8]) -> Replies {
        let text = String::from_utf8_lossy(bytes);
        let mut replies = Replies {
            kitty: kitty::answered(bytes),
            ..Replies::default()
        };
        for reply in text.split('\x1b').filter_map(|r| r.strip_prefix('[')) {
            let numbers = |body: &str| -> Vec<u32> {
                body.split(';').filter_map(|n| n.parse().ok()).collect()
            };
            if let Some(body) = reply.strip_prefix('?').and_then(|r| r.split('c').next())
                && reply.starts_with(&format!("?{body}c"))
            {
                replies.attributes = true;
                replies.sixel |= body.split(';').any(|a| a == "4");
            } else if let Some(body) = reply
                .strip_prefix("?2;0;")
                .and_then(|r| r.strip_suffix('S'))
                && let [w, h] = numbers(body)[..]
            {
                replies.sixel_limit = Some((w, h));
            } else if let Some(body) = reply.strip_prefix("6;").and_then(|r| r.split('t').next())
                && let [h, w] = numbers(body)[..]
                && w > 0
                && h > 0
            {
                replies.cell_pixels = Some((w, h));
            }
        }
        replies
    }
}

/// The queries, the kitty one through tmux when `through_tmux`; DA1 last, as every terminal
/// (and tmux itself) answers it.
pub fn queries(through_tmux: bool) -> Vec<u8> {
    let kitty = match through_tmux {
        true => tmux_passthrough(&kitty::query()),
        false => kitty::query(),
    };
    let mut out = kitty;
    out.extend_from_slice(b"\x1b[?2;1;0S\x1b[16t\x1b[c");
    out
}

/// How long input must stay quiet after the replies before the key handler may read: a reply
/// that comes late (through tmux, the outer terminal's answers follow tmux's own) is taken here,
/// not as keys.
const QUIET_AFTER_REPLIES: Duration = Duration::from_millis(40);

/// Sends the queries to standard output and reads the replies from standard input (raw mode
/// must be on): until DA1's reply (through tmux, which answers DA1 itself, until the outer
/// terminal's kitty reply too), then until input has been quiet a moment, within the time-out.
pub fn query_terminal(through_tmux: bool) -> io::Result<Replies> {
    let mut out = io::stdout().lock();
    out.write_all(&queries(through_tmux))?;
    out.flush()?;
    let over_ssh =
        std::env::var_os("SSH_TTY").is_some() || std::env::var_os("SSH_CONNECTION").is_some();
    let time_out = match over_ssh {
        true => REPLY_TIME_OUT_OVER_SSH,
        false => REPLY_TIME_OUT,
    };
    let deadline = Instant::now() + time_out;
    let mut bytes = Vec::new();
    let answered = |bytes: &[u8]| {
        let replies = Replies::parse(bytes);
        replies.attributes && (!through_tmux || replies.kitty)
    };
    while bytes.len() < MAX_REPLY_BYTES {
        let left = deadline.saturating_duration_since(Instant::now());
        let wait = match answered(&bytes) {
            true => left.min(QUIET_AFTER_REPLIES),
            false => left,
        };
        if wait.is_zero() || !readable(wait)? || !read_some(&mut bytes) {
            break;
        }
    }
    Ok(Replies::parse(&bytes))
}

/// Appends what standard input holds now to `bytes`; false at its end or on an error.
fn read_some(bytes: &mut Vec<u8>) -> bool {
    let mut buffer = [0u8; 512];
    // SAFETY: reading into a buffer of the length given, from our own standard input.
    let n = unsafe { libc::read(0, buffer.as_mut_ptr().cast(), buffer.len()) };
    if n <= 0 {
        return false;
    }
    bytes.extend_from_slice(&buffer[..n as usize]);
    true
}

/// Whether standard input has bytes within `wait`.
fn readable(wait: Duration) -> io::Result<bool> {
    let mut poll = libc::pollfd {
        fd: 0,
        events: libc::POLLIN,
        revents: 0,
    };
    let millis = wait.as_millis().min(i32::MAX as u128) as i32;
    // SAFETY: one pollfd, alive for the call.
    let ready = unsafe { libc::poll(&mut poll, 1, millis) };
    match ready {
        -1 => Err(io::Error::last_os_error()),
        n => Ok(n > 0),
    }
}

/// The protocols the terminal speaks, the one chosen and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct GraphicsFound {
    pub supported: Vec<Protocol>,
    pub chosen: Option<Protocol>,
    pub reason: String,
    /// Inside tmux with passthrough on: the kitty and iTerm2 sequences go through it.
    pub through_tmux: bool,
    pub cell_pixels: Option<(u32, u32)>,
    /// The largest sixel picture, if the terminal said.
    pub sixel_limit: Option<(u32, u32)>,
}

/// What to use, from `choice`, the replies, the environment (`var`) and whether tmux passes
/// sequences through (`None` outside tmux).
pub fn decide(
    choice: GraphicsChoice,
    replies: &Replies,
    var: impl Fn(&str) -> Option<String>,
    tmux_passthrough: Option<bool>,
) -> GraphicsFound {
    let iterm = ["TERM_PROGRAM", "LC_TERMINAL"]
        .iter()
        .filter_map(|name| var(name).map(|v| (*name, v)))
        .find(|(_, v)| v.starts_with("iTerm") || v == "WezTerm");
    let mut supported = Vec::new();
    let mut why = Vec::new();
    if replies.kitty {
        supported.push(Protocol::Kitty);
        why.push("the terminal answered the kitty query".to_string());
    }
    if let Some((name, value)) = &iterm {
        supported.push(Protocol::Iterm2);
        why.push(format!("{name}={}", crate::term::sanitize(value)));
    }
    if replies.sixel {
        supported.push(Protocol::Sixel);
        why.push("DA1 lists sixel".to_string());
    }
    let blocked_by_tmux = tmux_passthrough == Some(false);
    if blocked_by_tmux {
        supported.retain(|p| *p == Protocol::Sixel);
    }
    let (chosen, reason) = match choice {
        GraphicsChoice::Blocks => (None, "--graphics blocks".to_string()),
        GraphicsChoice::Only(p) if blocked_by_tmux && p != Protocol::Sixel => (
            None,
            format!(
                "{} asked, but tmux passes no graphics through (tmux set -g allow-passthrough on)",
                p.name()
            ),
        ),
        GraphicsChoice::Only(p) => {
            if !supported.contains(&p) {
                supported.push(p);
            }
            (Some(p), format!("--graphics {}", p.name()))
        }
        GraphicsChoice::Auto => match Protocol::ALL
            .iter()
            .copied()
            .find(|p| supported.contains(p))
        {
            Some(p) => (Some(p), why.join(", ")),
            None if blocked_by_tmux => (
                None,
                "inside tmux without allow-passthrough (tmux set -g allow-passthrough on)".into(),
            ),
            None if !replies.attributes => (None, "no reply to the graphics queries".into()),
            None => (None, "the terminal answered no graphics query".into()),
        },
    };
    GraphicsFound {
        supported,
        chosen,
        reason,
        through_tmux: tmux_passthrough == Some(true),
        cell_pixels: replies.cell_pixels,
        sixel_limit: replies.sixel_limit,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn replies_are_read_whatever_else_comes_with_them() {
        let bytes = b"\x1b_Gi=32;OK\x1b\\\x1b[?2;0;1920;1080S\x1b[6;20;10t\x1b[?62;4;22c";
        let replies = Replies::parse(bytes);
        assert!(replies.kitty && replies.sixel && replies.attributes);
        assert_eq!(replies.sixel_limit, Some((1920, 1080)));
        assert_eq!(replies.cell_pixels, Some((10, 20)));
        let plain = Replies::parse(b"\x1b[?1;2c");
        assert!(plain.attributes && !plain.sixel && !plain.kitty);
        assert!(!Replies::parse(b"\x1b_Gi=32;ENOENT\x1b\\").kitty);
        assert!(!Replies::parse(b"").attributes);
    }

    #[test]
    fn auto_prefers_exact_colours_and_tmux_without_passthrough_means_blocks() {
        let none = |_: &str| None;
        let all = Replies::parse(b"\x1b_Gi=32;OK\x1b\\\x1b[?62;4c");
        let found = decide(GraphicsChoice::Auto, &all, none, None);
        assert_eq!(found.chosen, Some(Protocol::Kitty));
        assert_eq!(found.supported, [Protocol::Kitty, Protocol::Sixel]);
        let sixel_only = Replies::parse(b"\x1b[?62;4c");
        let found = decide(GraphicsChoice::Auto, &sixel_only, none, None);
        assert_eq!(found.chosen, Some(Protocol::Sixel));
        let iterm = |n: &str| (n == "TERM_PROGRAM").then(|| "iTerm.app".to_string());
        let found = decide(GraphicsChoice::Auto, &Replies::default(), iterm, None);
        assert_eq!(found.chosen, Some(Protocol::Iterm2));
        let in_tmux = decide(GraphicsChoice::Auto, &all, none, Some(false));
        assert_eq!(
            in_tmux.chosen,
            Some(Protocol::Sixel),
            "tmux draws sixel itself"
        );
        let plain = Replies::parse(b"\x1b[?1;2c");
        let blocks = decide(GraphicsChoice::Auto, &plain, none, Some(false));
        assert_eq!(blocks.chosen, None);
        assert!(
            blocks.reason.contains("allow-passthrough"),
            "{}",
            blocks.reason
        );
        let asked = decide(
            GraphicsChoice::Only(Protocol::Kitty),
            &plain,
            none,
            Some(false),
        );
        assert_eq!(asked.chosen, None);
        let forced = decide(GraphicsChoice::Only(Protocol::Kitty), &plain, none, None);
        assert_eq!(forced.chosen, Some(Protocol::Kitty));
        let silent = decide(GraphicsChoice::Auto, &Replies::default(), none, None);
        assert!(silent.chosen.is_none() && silent.reason.contains("no reply"));
    }
}
