#version 450
// The bilateral blur of the obscurance and, with its weights, of the bent normals
// (AoSettings.bentNormals): sfx_ao_blur_pass.h.
#define SFX_AO_BENT_NORMALS 1
#include "sfx_ao_blur_pass.h"
