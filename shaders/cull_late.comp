#version 460
#extension GL_GOOGLE_include_directive : require
#define CULL_LATE
#include "cull.glsl"
