// The window blit's descriptor set (engine/window/window_blit.h), shared by
// GLSL and C++ like layouts.h.
#ifndef PLANTFIELD_SHADERS_WINDOW_BLIT_LAYOUTS_H
#define PLANTFIELD_SHADERS_WINDOW_BLIT_LAYOUTS_H

// The pass's one binding (set 0): the finished frame, sampled bilinearly
// through a view whose format matches the swapchain's encoding.
#define WINDOW_BLIT_BINDING_SOURCE 0

#endif
