#version 450
// Depth-aware upsample of half-size AO to the host's full-size output: sfx_ao_upsample_pass.h.
#include "sfx_ao_upsample_pass.h"
