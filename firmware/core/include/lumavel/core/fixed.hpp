// Forwarding header: the definitions live in the units floor
// (firmware/units/include/lumavel/units/fixed.hpp), which core, hal and protocol share.
#pragma once
#include "lumavel/units/fixed.hpp"
