// Raw bytes of a 16-bit float texture (as readTexture or a host readback gives them) as doubles,
// for tests that compare such textures value by value.
#pragma once

#include <cstdint>
#include <cstring>
#include <vector>

#include "sfx/half.hpp"

namespace sfx::test {

inline std::vector<double> halfBytesToDoubles(const std::vector<uint8_t>& bytes) {
    std::vector<double> out(bytes.size() / 2);
    for (size_t i = 0; i < out.size(); ++i) {
        uint16_t h;
        std::memcpy(&h, bytes.data() + 2 * i, 2);
        out[i] = halfToFloat(h);
    }
    return out;
}

}  // namespace sfx::test
