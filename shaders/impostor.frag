#version 460
#extension GL_GOOGLE_include_directive : require
#include "impostor_colour.glsl"

// LOD2 billboards the frame's shadow map may reach (IMPOSTOR_PART_SHADOWED,
// or every impostor with IMPOSTOR_PART_ALL).
void main() {
    shadeImpostor(true);
}
