#version 460
#extension GL_GOOGLE_include_directive : require
#include "terrain_ground.glsl"

// The ground the sun's shadow map does not reach (or with shadows off): in
// full sun.
void main() {
    outColor = groundColor(false);
}
