// The FXAA pass's descriptor set (engine/vk/fxaa_pass.h), shared by GLSL and
// C++ like layouts.h.
#ifndef PLANTFIELD_SHADERS_FXAA_LAYOUTS_H
#define PLANTFIELD_SHADERS_FXAA_LAYOUTS_H

// The pass's one binding (set 0): the frame drawn with one sample a pixel,
// through a UNORM view of its sRGB bytes; the shader only fetches texels.
#define FXAA_BINDING_SOURCE 0

#endif
