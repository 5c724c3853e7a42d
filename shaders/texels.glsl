// Reading float data from uint texel views (R32G32B32A32_UINT uniform texel
// buffers): uintBitsToFloat keeps every bit, where a float view could
// canonicalise NaN patterns such as JOINT_NO_PARENT. The passes read through
// texel views because lavapipe gathers a texel for all SIMD lanes at once,
// where it reads a storage buffer at a per-invocation index one float and
// one lane at a time.
#ifndef TEXELS_GLSL
#define TEXELS_GLSL
#include "shared/physics_layouts.h"

vec4 floatTexel(usamplerBuffer b, int t) {
    return uintBitsToFloat(texelFetch(b, t));
}

// The physics arrays that both the physics passes and the draw shaders read.
Skeleton skeletonFromTexels(usamplerBuffer skeletons, uint i) {
    int t = int(i) * SKELETON_TEXELS;
    return Skeleton(texelFetch(skeletons, t), floatTexel(skeletons, t + 1), floatTexel(skeletons, t + 2));
}

JointPose poseFromTexels(usamplerBuffer poses, uint i) {
    int t = int(i) * JOINT_POSE_TEXELS;
    return JointPose(floatTexel(poses, t), floatTexel(poses, t + 1));
}

#endif
