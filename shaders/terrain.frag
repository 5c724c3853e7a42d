#version 460
#extension GL_GOOGLE_include_directive : require
#include "terrain_ground.glsl"

// The ground within reach of the sun's shadow map: the plants' shadows on it.
void main() {
    outColor = groundColor(true);
}
