#version 450
#extension GL_EXT_control_flow_attributes : require
// Horizon-based AO (Jimenez et al. 2016, GTAO): visibility only (sfx_ao_horizon_pass.h).
#include "sfx_ao_horizon_pass.h"
