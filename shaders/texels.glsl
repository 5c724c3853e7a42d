// Reading float data from uint texel views (R32G32B32A32_UINT uniform texel
// buffers): uintBitsToFloat keeps every bit, where a float view could
// canonicalise NaN patterns such as JOINT_NO_PARENT. The passes read through
// texel views because lavapipe gathers a texel for all SIMD lanes at once,
// where it reads a storage buffer at a per-invocation index one float and
// one lane at a time.
#ifndef TEXELS_GLSL
#define TEXELS_GLSL

vec4 floatTexel(usamplerBuffer b, int t) {
    return uintBitsToFloat(texelFetch(b, t));
}

#endif
