#version 450
#extension GL_EXT_control_flow_attributes : require
// Horizon-based AO with bent normals in a second attachment (AoSettings.bentNormals):
// sfx_ao_horizon_pass.h.
#define SFX_AO_BENT_NORMALS 1
#include "sfx_ao_horizon_pass.h"
