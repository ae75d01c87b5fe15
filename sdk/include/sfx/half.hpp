// IEEE 754 binary16 ("half") conversions for 16F texture uploads and readbacks.
#pragma once

#include <cstdint>

namespace sfx {

// Round to nearest even; overflow gives infinity, NaN stays NaN, subnormals are kept.
uint16_t floatToHalf(float value);
// Exact: every half is representable as a float.
float halfToFloat(uint16_t bits);

}  // namespace sfx
