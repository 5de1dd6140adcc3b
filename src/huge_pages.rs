//! Large buffers on huge pages where the system allows. On virtual machines a first touch of a
//! 4 KiB page can cost microseconds and a scattered write misses the TLB: a 1080p framebuffer is
//! 8 000 such pages but 17 huge ones of 2 MiB.

/// A zeroed buffer of `n` values whose whole pages are marked for huge pages before anything
/// touches them (Linux transparent huge pages in `madvise` mode; elsewhere a plain zeroed buffer).
/// Zeroed by the rayon pool, a part a thread: once a process has freed a buffer this large,
/// glibc serves the next from its heap, where `calloc` zeroes it in one serial `memset` on one
/// core while the other waits.
pub fn zeroed_huge<T: bytemuck::Zeroable + Clone + Send + Sync>(n: usize) -> Vec<T> {
    use rayon::prelude::*;
    let mut values: Vec<T> = Vec::with_capacity(n);
    advise_huge_pages(values.spare_capacity_mut());
    values.par_extend(rayon::iter::repeat_n(T::zeroed(), n));
    values
}

/// Makes `values` `n` long, for its caller to overwrite every value. Growing past its capacity
/// takes a fresh buffer from `zeroed_huge`, zeroed by the pool (the pages' first-touch faults
/// split across the threads, on huge pages where the system allows) instead of by one thread.
pub fn resize_for_overwrite<T: bytemuck::Zeroable + Clone + Send + Sync>(
    values: &mut Vec<T>,
    n: usize,
) {
    if n > values.capacity() {
        *values = zeroed_huge(n);
    } else {
        values.resize(n, T::zeroed());
    }
}

/// Asks the kernel to back the whole pages inside `buffer` with huge pages; to take effect, call
/// it before the pages are first touched. Advice only: the contents do not change, and a system
/// that cannot follow it ignores it.
pub fn advise_huge_pages<T>(buffer: &mut [T]) {
    #[cfg(target_os = "linux")]
    {
        let Some(page) = page_size() else {
            return;
        };
        let start = buffer.as_mut_ptr() as usize;
        let end = start + std::mem::size_of_val(buffer);
        let (first, last) = (start.next_multiple_of(page), end / page * page);
        if last > first {
            // SAFETY: [first, last) lies inside `buffer`, which we hold mutably, and
            // MADV_HUGEPAGE changes how its pages are backed, never what they hold. The
            // result is ignored on purpose: the advice is an optimisation.
            unsafe {
                libc::madvise(
                    first as *mut libc::c_void,
                    last - first,
                    libc::MADV_HUGEPAGE,
                )
            };
        }
    }
    #[cfg(not(target_os = "linux"))]
    let _ = buffer;
}

/// The system's page size, where it says (Linux).
pub fn page_size() -> Option<usize> {
    #[cfg(target_os = "linux")]
    {
        // SAFETY: sysconf only reads a system constant.
        match unsafe { libc::sysconf(libc::_SC_PAGESIZE) } {
            size if size > 0 => Some(size as usize),
            _ => None,
        }
    }
    #[cfg(not(target_os = "linux"))]
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn huge_page_buffers_are_zeroed_and_keep_what_is_written() {
        for n in [0, 1, 1000, 3 << 20] {
            let mut values: Vec<f32> = zeroed_huge(n);
            assert_eq!(values.len(), n);
            assert!(values.iter().all(|&v| v == 0.0));
            values
                .iter_mut()
                .enumerate()
                .for_each(|(i, v)| *v = i as f32);
            // Advising again, on a part that starts and ends inside pages, changes nothing.
            let middle = n / 3..n - n / 5;
            advise_huge_pages(&mut values[middle]);
            assert!(values.iter().enumerate().all(|(i, &v)| v == i as f32));
        }
    }
}
