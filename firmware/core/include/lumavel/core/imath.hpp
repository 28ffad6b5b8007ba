// Integer elementary functions for table generation (start-up, not per frame).
// Error budgets were measured against double precision in tests/core/test_imath.cpp.
#pragma once
#include <cstdint>

#include "lumavel/core/fixed.hpp"

namespace lumavel::fx {

// atan2(y, x) for any int32 pair -> Q3.28 rad in (-pi, pi]. |error| <= 5e-9 rad
// (CORDIC, 32 steps, angle kept in Q3.32 inside).
AngleQ28 atan2_i32(int32_t y, int32_t x);
// exp(-x) for x >= 0 in Q4.27 (x < 16) -> Q1.30; 0 beyond. |relative error| <= 2e-9.
int32_t exp_neg_q27(int64_t x_q27);
// atan2 with 32-bit arithmetic only (per-frame use on small cores): |y|, |x|
// any int32; 24 CORDIC steps, |error| <= 2e-7 rad.
AngleQ28 atan2_fast(int32_t y, int32_t x);
// cos(a) for any Q3.28 angle -> Q1.30. |error| <= 3e-9 (rotation CORDIC, 32 steps).
int32_t cos_q30(AngleQ28 a);
// floor(sqrt(v)).
uint32_t isqrt64(uint64_t v);
uint32_t isqrt32(uint32_t v);
// Wraps an angle into [-pi, pi), exactly: whole turns of 2 pi (not 2 kPiQ28)
// are taken off, so a heading stays right after any number of turns.
AngleQ28 wrap_pi(int64_t a_q28);

}  // namespace lumavel::fx
