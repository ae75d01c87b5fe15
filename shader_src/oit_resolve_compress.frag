#version 450
// A-buffer resolve that also compresses each pixel's list to M (depth, opacity) nodes for the
// AO passes (high tier, when TransparencyDesc::compressedNodes is set): sfx_shared_oit_resolve.h.
#define SFX_OIT_COMPRESS 1
#include "sfx_shared_oit_resolve.h"
