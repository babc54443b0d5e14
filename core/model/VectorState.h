#pragma once

namespace learnid {

/// Clears the upper halves of the AVX registers (vzeroupper) on a CPU that has them, when this
/// code is compiled for the x86-64 baseline (SSE2, as Debian builds it).
///
/// Why: Qt 6.4.2's QHash hashes its keys with 256-bit VAES instructions on CPUs that have them
/// and returns without vzeroupper. On Intel CPUs every SSE instruction that follows then carries
/// a false dependency on those dirty upper halves: this project's numerical code ran two to five
/// times slower after any QHash use (a trial plan 0.25 ms, then 1.3 ms; the 6-trial session
/// twice as long; docs/benchmarks.md, "Speed"). Qt uses QHash everywhere (meta types, signals,
/// logging), so the numerical entry points (planning, the pre-trial check, the simulation, the
/// learning laws) call this first, and the simulation again after each progress report. It
/// costs one instruction; code compiled with AVX needs none.
inline void clearUpperVectorState()
{
#if defined(__x86_64__) && !defined(__AVX__) && (defined(__GNUC__) || defined(__clang__))
    static const bool hasAvx = __builtin_cpu_supports("avx");
    if (hasAvx)
        asm volatile("vzeroupper");
#endif
}

} // namespace learnid
