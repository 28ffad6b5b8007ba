// Forwarding header: the definitions live in the units floor
// (firmware/units/include/lumavel/units/status.hpp), which core, hal and protocol share.
#pragma once
#include "lumavel/units/status.hpp"
