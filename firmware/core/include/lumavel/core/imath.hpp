// Integer elementary functions for table generation (start-up, not per frame).
// Error budgets were measured against double precision in tests/core/test_imath.cpp.
#pragma once
#include <cstdint>

#include "lumavel/core/fixed.hpp"

namespace lumavel::fx {

// atan(x) for x in Q15.16 -> Q3.28 rad. |error| <= 4e-9 rad (CORDIC, 30 steps).
AngleQ28 atan_q16(int32_t x_q16);
// atan2(y, x) for any int32 pair -> Q3.28 rad in (-pi, pi]. |error| <= 4e-9 rad.
AngleQ28 atan2_i32(int32_t y, int32_t x);
// cos and sin of a Q3.28 angle -> Q1.30. |error| <= 3e-9.
void cos_sin_q30(AngleQ28 a, int32_t* c, int32_t* s);
// exp(-x) for x >= 0 in Q4.27 (x < 16) -> Q1.30; 0 beyond. |relative error| <= 2e-9.
int32_t exp_neg_q27(int64_t x_q27);
// floor(sqrt(v)).
uint32_t isqrt64(uint64_t v);
// Wraps an angle difference into [-pi, pi).
AngleQ28 wrap_pi(int64_t a_q28);

}  // namespace lumavel::fx
