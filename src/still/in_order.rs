//! Finished strips written to a sink top first by the threads that render them: whichever
//! thread finishes the strip the sink waits for writes it, and every strip after it that is
//! ready. A writer thread of its own made a third busy thread on two cores: the scheduler let
//! it fall a few milliseconds behind, which it then caught up alone while the cores idled.

use super::row_sink::RowSink;
use std::collections::BTreeMap;
use std::sync::{Mutex, MutexGuard, PoisonError, TryLockError};

/// Strips of 8-bit rows handed in from any thread in any order, written to the sink in order.
pub struct InOrderWriter<'s> {
    /// Finished strips the sink is not ready for, by index.
    waiting: Mutex<BTreeMap<usize, Vec<u8>>>,
    /// Held by the one thread writing.
    writing: Mutex<Writing<'s>>,
    spare: &'s SpareRows,
}

/// Buffers of 8-bit rows already written, for the next strips to fill (a fresh one would be
/// zeroed, and its pages first touched, for every strip); kept from band to band.
#[derive(Default)]
pub struct SpareRows(Mutex<Vec<Vec<u8>>>);

struct Writing<'s> {
    sink: &'s mut dyn RowSink,
    /// The strip the sink takes next.
    next: usize,
    /// The first failed write: nothing is written after it.
    failure: Option<String>,
}

fn lock<T>(mutex: &Mutex<T>) -> MutexGuard<'_, T> {
    mutex.lock().unwrap_or_else(PoisonError::into_inner)
}

impl<'s> InOrderWriter<'s> {
    pub fn new(sink: &'s mut dyn RowSink, spare: &'s SpareRows) -> InOrderWriter<'s> {
        InOrderWriter {
            waiting: Mutex::default(),
            writing: Mutex::new(Writing {
                sink,
                next: 0,
                failure: None,
            }),
            spare,
        }
    }

    /// A buffer for a strip's bytes: one already written if any.
    pub fn buffer(&self) -> Vec<u8> {
        lock(&self.spare.0).pop().unwrap_or_default()
    }

    /// Hands in strip `index` (from the top), writing it and the ready strips after it if the
    /// sink waits for it and no other thread is writing; that thread writes them otherwise.
    pub fn finished(&self, index: usize, bytes: Vec<u8>) {
        lock(&self.waiting).insert(index, bytes);
        loop {
            let mut writing = match self.writing.try_lock() {
                Ok(writing) => writing,
                Err(TryLockError::Poisoned(poisoned)) => poisoned.into_inner(),
                Err(TryLockError::WouldBlock) => return,
            };
            self.write_ready(&mut writing);
            let next = writing.next;
            drop(writing);
            // A strip handed in between the last look and the release found the sink busy and
            // left it here: write it, unless another thread has taken the sink meanwhile.
            if !lock(&self.waiting).contains_key(&next) {
                return;
            }
        }
    }

    fn write_ready(&self, writing: &mut Writing) {
        loop {
            let Some(bytes) = lock(&self.waiting).remove(&writing.next) else {
                return;
            };
            if writing.failure.is_none()
                && let Err(reason) = writing.sink.write_rows(&bytes)
            {
                writing.failure = Some(reason);
            }
            writing.next += 1;
            lock(&self.spare.0).push(bytes);
        }
    }

    /// Whether all of `strip_count` strips were written: the first failed write, or how many
    /// came before a missing strip.
    pub fn finish(self, strip_count: usize) -> Result<(), String> {
        let writing = self
            .writing
            .into_inner()
            .unwrap_or_else(PoisonError::into_inner);
        if let Some(failure) = writing.failure {
            return Err(failure);
        }
        if writing.next == strip_count {
            Ok(())
        } else {
            Err(format!(
                "{} of {strip_count} strips of rows were rendered",
                writing.next
            ))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rows as the sink received them, a write at a time; fails on write number `fail_at`.
    struct Writes {
        writes: Vec<Vec<u8>>,
        fail_at: Option<usize>,
    }

    impl RowSink for Writes {
        fn write_rows(&mut self, rgb: &[u8]) -> Result<(), String> {
            if self.fail_at == Some(self.writes.len()) {
                return Err("disk full".into());
            }
            self.writes.push(rgb.to_vec());
            Ok(())
        }
    }

    fn sink(fail_at: Option<usize>) -> Writes {
        Writes {
            writes: Vec::new(),
            fail_at,
        }
    }

    /// Strip k holds the byte k, k + 1 times.
    fn strip(k: usize) -> Vec<u8> {
        vec![k as u8; k + 1]
    }

    fn hand_in(order: &[usize], strip_count: usize, rows: &mut Writes) -> Result<(), String> {
        let spare = SpareRows::default();
        let writer = InOrderWriter::new(rows, &spare);
        for &k in order {
            writer.finished(k, strip(k));
        }
        writer.finish(strip_count)
    }

    #[test]
    fn strips_arriving_in_any_order_are_written_top_first() {
        let mut rows = sink(None);
        assert_eq!(hand_in(&[2, 0, 4, 1, 3], 5, &mut rows), Ok(()));
        assert_eq!(rows.writes, (0..5).map(strip).collect::<Vec<_>>());
    }

    #[test]
    fn written_buffers_come_back_for_the_next_strips() {
        let mut rows = sink(None);
        let spare = SpareRows::default();
        let writer = InOrderWriter::new(&mut rows, &spare);
        writer.finished(1, strip(1));
        assert!(writer.buffer().is_empty(), "strip 1 waits for strip 0");
        writer.finished(0, strip(0));
        let reused: Vec<Vec<u8>> = (0..3).map(|_| writer.buffer()).collect();
        assert!(reused[0].capacity() > 0 && reused[1].capacity() > 0);
        assert!(reused[2].is_empty(), "two written, two back");
    }

    #[test]
    fn a_failing_sink_stops_the_rows_with_its_reason() {
        let mut rows = sink(Some(1));
        assert_eq!(hand_in(&[0, 1, 2], 3, &mut rows), Err("disk full".into()));
        assert_eq!(rows.writes.len(), 1, "nothing written after the failure");
    }

    #[test]
    fn a_missing_strip_is_an_error_not_a_shorter_image() {
        let mut rows = sink(None);
        let result = hand_in(&[0, 2], 3, &mut rows);
        assert_eq!(result, Err("1 of 3 strips of rows were rendered".into()));
        assert_eq!(rows.writes.len(), 1, "only the rows before the gap");
    }

    /// Threads handing in interleaved strips at once: each written once, in order, whichever
    /// thread writes it.
    #[test]
    fn strips_from_many_threads_are_written_once_in_order() {
        for round in 0..20 {
            let (threads, count) = (4, 300);
            let mut rows = sink(None);
            let spare = SpareRows::default();
            let writer = InOrderWriter::new(&mut rows, &spare);
            std::thread::scope(|scope| {
                for t in 0..threads {
                    let writer = &writer;
                    scope.spawn(move || {
                        // Each thread's strips, in an order that differs by thread and round.
                        let mut mine: Vec<usize> = (t..count).step_by(threads).collect();
                        if (t + round) % 2 == 1 {
                            mine.reverse();
                        }
                        for k in mine {
                            writer.finished(k, strip(k));
                        }
                    });
                }
            });
            assert_eq!(writer.finish(count), Ok(()));
            assert_eq!(rows.writes, (0..count).map(strip).collect::<Vec<_>>());
        }
    }
}
