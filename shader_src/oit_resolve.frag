#version 450
// A-buffer resolve (high tier): sort and composite each pixel's list over the opaque colour
// (the pass itself is sfx_shared_oit_resolve.h, shared with oit_resolve_compress.frag).
#include "sfx_shared_oit_resolve.h"
