#version 450
// Opacity-based AO through the layers from the compressed lists: every tap reads the M nodes the
// compressing resolve wrote at its pixel, one 12-byte record (sfx_shared_oit_ao.h).
#define SFX_OIT_AO_COMPRESSED 1
#include "sfx_shared_oit_ao.h"
