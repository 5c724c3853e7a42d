// GPU layouts of the cloud pass (engine/field/cloud_pass.h, docs/CLOUDS.md),
// shared by GLSL and C++.
#ifndef PLANTFIELD_SHADERS_CLOUD_LAYOUTS_H
#define PLANTFIELD_SHADERS_CLOUD_LAYOUTS_H

#include "layouts.h"

#ifdef __cplusplus
namespace gpu {
#endif

// Descriptor bindings of the cloud pass's set (set 0).
#define CLOUD_BINDING_FRAME BINDING_FRAME_UNIFORMS // FrameUniforms (layouts.h): the field's frame block
#define CLOUD_BINDING_SPHERES 1                    // CloudBillboard[], farthest first, through a uint texel view

// Vertices of one sphere's billboard: two triangles.
#define CLOUD_BILLBOARD_VERTICES 6
#define CLOUD_BILLBOARD_TEXELS 2

// One sphere of a cloud as this frame draws it: 32 bytes.
struct CloudBillboard {
    vec4 sphere; // xyz world centre at this frame's time (wind drift included), w radius (m)
    vec4 shade; // x the sphere's height within its cloud (0 bottom, 1 top), yzw which side of the cloud it is on (unit)
};

// The clouds' shadows on the ground (engine/field/cloud_shadow_pass.h): the
// terrain drawn again over itself, multiplying the colour by the shade of
// engine/scene/cloud_shadow.h's map. Set 0:
#define CLOUD_SHADOW_BINDING_FRAME BINDING_FRAME_UNIFORMS // FrameUniforms
#define CLOUD_SHADOW_BINDING_TERRAIN 1                    // TerrainVertex[] (field_layouts.h), uint texels
#define CLOUD_SHADOW_BINDING_MAP 2                        // float transmittance per texel, R32_UINT texels

// Of the ground's light, the share the sun gives and a cloud's shadow takes away.
#define CLOUD_SHADOW_SUN_SHARE 0.7

struct CloudShadowPush {
    vec4 drift; // xz the wind's drift of the clouds since time 0 (m), y 0, w map height (texels)
    vec4 grid;  // xy the map's origin (texel 0's centre, x and z, m), z texels per metre, w map width (texels)
};

#ifdef __cplusplus
} // namespace gpu
static_assert(sizeof(gpu::CloudBillboard) == CLOUD_BILLBOARD_TEXELS * 16);
static_assert(sizeof(gpu::CloudShadowPush) == 32);
#endif

#endif
