#version 460
#extension GL_GOOGLE_include_directive : require
#define DEPTH_REDUCE_MULTISAMPLED
#include "depth_reduce.glsl"
