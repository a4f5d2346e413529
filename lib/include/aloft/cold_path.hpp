// ALOFT_COLD marks a function that runs at decision points, not once per sample: set-up,
// a release confirmed and dated, a landing dated, a flight ended and reported. GCC and
// clang then optimise it for size and keep it out of line, so that a firmware built for
// speed (-O3) spends its flash on the per-sample path only. The attribute moves code; it
// does not change the arithmetic (no fast-math, no contraction it would not do anyway).
#pragma once

//
// ALOFT_OUT_OF_LINE marks a larger function that both the per-sample path and the
// decision points call: one copy in flash, for the cost of a call.
#if defined(__GNUC__) || defined(__clang__)
#define ALOFT_COLD __attribute__((cold, noinline))
#define ALOFT_OUT_OF_LINE __attribute__((noinline))
#else
#define ALOFT_COLD
#define ALOFT_OUT_OF_LINE
#endif
