#include "sfx/half.hpp"

#include <cmath>
#include <cstring>

namespace sfx {

uint16_t floatToHalf(float value) {
    uint32_t x;
    std::memcpy(&x, &value, 4);
    const uint32_t sign = (x >> 16) & 0x8000u;
    const uint32_t absx = x & 0x7fffffffu;
    if (absx >= 0x7f800000u) return uint16_t(sign | 0x7c00u | (absx > 0x7f800000u ? 0x200u : 0u));  // inf / nan
    if (absx >= 0x477ff000u) return uint16_t(sign | 0x7c00u);                                       // rounds past the largest half
    if (absx < 0x38800000u) {                                                                       // half subnormal or zero
        if (absx < 0x33000000u) return uint16_t(sign);
        const uint32_t mant = (absx & 0x7fffffu) | 0x800000u;
        const uint32_t shift = 126u - (absx >> 23);  // 14..24
        uint32_t h = mant >> shift;
        const uint32_t rem = mant & ((1u << shift) - 1u), halfway = 1u << (shift - 1u);
        if (rem > halfway || (rem == halfway && (h & 1u))) ++h;
        return uint16_t(sign | h);
    }
    uint32_t h = (absx >> 13) - (112u << 10);
    const uint32_t rem = absx & 0x1fffu;
    if (rem > 0x1000u || (rem == 0x1000u && (h & 1u))) ++h;
    return uint16_t(sign | h);
}

float halfToFloat(uint16_t bits) {
    const uint32_t exponent = (bits >> 10) & 31u, mantissa = bits & 1023u;
    const float sign = (bits & 0x8000u) ? -1.0f : 1.0f;
    if (exponent == 0) return sign * std::ldexp(float(mantissa), -24);
    if (exponent == 31) return mantissa ? std::nanf("") : sign * INFINITY;
    return sign * std::ldexp(float(mantissa | 1024u), int(exponent) - 25);
}

}  // namespace sfx
