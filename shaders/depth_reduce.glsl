// One level of the depth pyramid (engine/vk/depth_pyramid.h): each texel is
// the largest (farthest) depth of the 2×2 texels under it, clamped at the
// source's last row and column, so a source of odd size keeps every texel
// and the level covers exactly the pixels below it. Included by
// depth_reduce.comp and, with DEPTH_REDUCE_MULTISAMPLED, depth_reduce_ms.comp,
// which reads every sample of a multisampled depth buffer.
#include "shared/depth_pyramid_layouts.h"

layout(local_size_x = DEPTH_REDUCE_GROUP_SIZE, local_size_y = DEPTH_REDUCE_GROUP_SIZE) in;

#ifdef DEPTH_REDUCE_MULTISAMPLED
layout(set = 0, binding = DEPTH_REDUCE_BINDING_SOURCE) uniform sampler2DMS source;
#else
layout(set = 0, binding = DEPTH_REDUCE_BINDING_SOURCE) uniform sampler2D source;
#endif
layout(set = 0, binding = DEPTH_REDUCE_BINDING_TARGET, r32f) uniform writeonly image2D target;
layout(push_constant) uniform Push {
    DepthReducePush push;
};

float farthest(ivec2 p) {
#ifdef DEPTH_REDUCE_MULTISAMPLED
    float depth = 0.0;
    for (int s = 0; s < int(push.samples.x); ++s) depth = max(depth, texelFetch(source, p, s).r);
    return depth;
#else
    return texelFetch(source, p, 0).r;
#endif
}

void main() {
    uvec2 p = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(p, push.size.zw))) return;
    ivec2 lo = ivec2(p * 2u);
    ivec2 hi = min(lo + 1, ivec2(push.size.xy) - 1);
    float depth = max(max(farthest(lo), farthest(ivec2(hi.x, lo.y))), max(farthest(ivec2(lo.x, hi.y)), farthest(hi)));
    imageStore(target, ivec2(p), vec4(depth));
}
