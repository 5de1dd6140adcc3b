//! Work items shared out to the rayon pool in their order: each thread takes the first item not
//! yet taken. A still's writer takes finished strips top first; rayon's own split of an indexed
//! iterator (one thread from the top, the next from the middle) left it holding half a frame of
//! finished strips until the top half was done, then compressing them alone while the other
//! cores idled.

use rayon::prelude::*;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Mutex, PoisonError};

/// `work(state, index, item)` of every item, run top first across the current pool (each
/// thread's `state` made by `init` once), its results in the items' order.
pub fn map_top_first<T, S, R>(
    items: Vec<T>,
    init: impl Fn() -> S + Sync,
    work: impl Fn(&mut S, usize, T) -> R + Sync,
) -> Vec<R>
where
    T: Send,
    R: Send,
{
    let count = items.len();
    let slots: Vec<Mutex<Option<T>>> = items.into_iter().map(|t| Mutex::new(Some(t))).collect();
    let next = AtomicUsize::new(0);
    let threads = rayon::current_num_threads().clamp(1, count.max(1));
    let mut results: Vec<(usize, R)> = (0..threads)
        .into_par_iter()
        .with_max_len(1)
        .flat_map_iter(|_| {
            let mut state = init();
            let mut done = Vec::new();
            loop {
                let index = next.fetch_add(1, Ordering::Relaxed);
                let Some(slot) = slots.get(index) else {
                    break done;
                };
                let mut slot = slot.lock().unwrap_or_else(PoisonError::into_inner);
                let item = slot.take().expect("each index is handed out once");
                drop(slot);
                done.push((index, work(&mut state, index, item)));
            }
        })
        .collect();
    results.sort_unstable_by_key(|&(index, _)| index);
    debug_assert_eq!(results.len(), count);
    results.into_iter().map(|(_, result)| result).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeSet;

    fn pool(threads: usize) -> rayon::ThreadPool {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
    }

    #[test]
    fn every_item_is_worked_once_with_its_index() {
        for threads in [1, 2, 3, 8] {
            let items: Vec<u64> = (0..97).map(|i| i * 10).collect();
            let seen = Mutex::new(Vec::new());
            let results = pool(threads).install(|| {
                map_top_first(
                    items,
                    || (),
                    |_, index, item| {
                        assert_eq!(item, index as u64 * 10);
                        seen.lock().unwrap().push(index);
                        item + 1
                    },
                )
            });
            let expected: Vec<u64> = (0..97).map(|i| i * 10 + 1).collect();
            assert_eq!(results, expected, "results in the items' order");
            let mut seen = seen.into_inner().unwrap();
            seen.sort_unstable();
            assert_eq!(seen, (0..97).collect::<Vec<_>>(), "{threads} threads");
        }
    }

    /// When an item starts, every item before it has started but for those the other threads
    /// took and have not yet reported (at most one a thread). Rayon's halving split starts the
    /// middle item at once, with only the first reported.
    #[test]
    fn items_start_in_order_from_the_first() {
        let threads = 4;
        let started = Mutex::new(BTreeSet::new());
        pool(threads).install(|| {
            map_top_first(
                vec![(); 400],
                || (),
                |_, index, ()| {
                    let mut started = started.lock().unwrap();
                    let before = started.range(..index).count();
                    assert!(
                        before + (threads - 1) >= index,
                        "item {index} started when only {before} before it had"
                    );
                    started.insert(index);
                    drop(started);
                    std::hint::black_box((0..2000).sum::<u64>())
                },
            )
        });
    }

    #[test]
    fn per_thread_state_is_made_once_a_thread_at_most() {
        let made = AtomicUsize::new(0);
        let results = pool(2).install(|| {
            map_top_first(
                vec![1usize; 50],
                || made.fetch_add(1, Ordering::Relaxed),
                |_, _, one| one,
            )
        });
        assert_eq!(results.len(), 50);
        assert!((1..=2).contains(&made.load(Ordering::Relaxed)));
    }

    #[test]
    fn no_items_give_no_results() {
        let results = map_top_first(Vec::<u32>::new(), || (), |_, _, x| x);
        assert!(results.is_empty());
    }
}
