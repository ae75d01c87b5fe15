// CPU reference of the bilateral filter on the AO through the layers (double precision, the
// weights of shader_src/include/sfx_shared_oit.h's oitFilterTapWeight, as oit_ao_filter.frag):
// separable, horizontal then vertical, `radius` taps each side; the blended visibility keyed by
// each pixel's front depth (its nearest fragment that passes the depth test, else its opaque
// surface), the opaque visibility by the opaque depth; centres whose key is sky keep their value.
#pragma once

#include <cstdint>

#include "sfx/reference/oit_reference.hpp"

namespace sfx::reference {

// `raw` as opacityAmbientOcclusion returned it for `image`; returns it with blended and opaque
// filtered (perFragment untouched). radius 0 returns raw.
OitAoResult filterLayerAo(const FragmentImage& image, const OitAoResult& raw, uint32_t radius);

}  // namespace sfx::reference
