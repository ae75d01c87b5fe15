#version 450
// Separable depth-aware bilateral blur of the obscurance: sfx_ao_blur_pass.h.
#include "sfx_ao_blur_pass.h"
