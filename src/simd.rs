//! Running a hot loop compiled for the widest SIMD this CPU has. The default build targets
//! baseline x86-64 (SSE2: four f32 or two f64 lanes per instruction); where the CPU has AVX2,
//! `widest` runs the same code compiled for it (eight f32 or four f64 lanes). No FMA is enabled
//! and Rust never fuses a multiply and an add on its own, so both builds give the same bits.

/// Runs `f`, compiled for AVX2 when the CPU has it. Only code inlined into the AVX2 function is
/// compiled so: pass an `#[inline(always)]` closure that calls `#[inline(always)]` loops (a
/// plain closure was left out of line, and its loops stayed SSE2: measured).
#[inline(always)]
pub fn widest<R>(f: impl FnOnce() -> R) -> R {
    #[cfg(target_arch = "x86_64")]
    if std::is_x86_feature_detected!("avx2") {
        // SAFETY: the CPU has just been seen to support AVX2.
        return unsafe { avx2(f) };
    }
    f()
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn avx2<R>(f: impl FnOnce() -> R) -> R {
    f()
}

/// `widest`, with a middle tier for CPUs that have SSE4.1 but not AVX2: for loops that round
/// (`floor`, `ceil`), which SSE4.1 does in one instruction and baseline x86-64 only by a call to
/// the library per value.
#[inline(always)]
pub fn widest_rounding<R>(f: impl FnOnce() -> R) -> R {
    #[cfg(target_arch = "x86_64")]
    if !std::is_x86_feature_detected!("avx2") {
        return sse41_tier(f);
    }
    widest(f)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "sse4.1")]
#[inline]
fn sse41<R>(f: impl FnOnce() -> R) -> R {
    f()
}

/// Runs `f` compiled for SSE4.1 where the CPU has it, else as the baseline: `widest_rounding`'s
/// tiers below AVX2 (public to the crate so tests on an AVX2 machine cover them too).
#[cfg_attr(not(target_arch = "x86_64"), allow(dead_code))]
#[inline(always)]
pub(crate) fn sse41_tier<R>(f: impl FnOnce() -> R) -> R {
    #[cfg(target_arch = "x86_64")]
    if std::is_x86_feature_detected!("sse4.1") {
        // SAFETY: the CPU has just been seen to support SSE4.1.
        return unsafe { sse41(f) };
    }
    f()
}
