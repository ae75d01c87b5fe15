#version 450
// The depth-aware upsample of the half-size AO and, with its weights, of the bent normals
// (AoSettings.bentNormals): sfx_ao_upsample_pass.h.
#define SFX_AO_BENT_NORMALS 1
#include "sfx_ao_upsample_pass.h"
