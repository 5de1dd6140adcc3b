//! Every message of the run, kept for the message log.

use super::status_message::Message;
use std::collections::VecDeque;

/// Messages kept; older ones go first.
const KEPT: usize = 1000;

/// Every message shown, with the seconds since start it was shown at.
#[derive(Debug, Default)]
pub struct Log {
    entries: VecDeque<(f64, Message)>,
}

impl Log {
    /// Keeps `message`, unless it is none or the same as the last kept.
    pub fn keep(&mut self, seconds: f64, message: &Message) {
        let same = self.entries.back().is_some_and(|(_, last)| last == message);
        if *message == Message::None || same {
            return;
        }
        if self.entries.len() == KEPT {
            self.entries.pop_front();
        }
        self.entries.push_back((seconds, message.clone()));
    }

    /// Oldest first.
    pub fn entries(&self) -> &VecDeque<(f64, Message)> {
        &self.entries
    }

    pub fn len(&self) -> usize {
        self.entries.len()
    }

    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }
}
