#version 450
// Opacity-based AO through the layers, brute force: every tap walks the list at its pixel
// (sfx_shared_oit_ao.h).
#include "sfx_shared_oit_ao.h"
