#version 460
#extension GL_GOOGLE_include_directive : require
#include "impostor_color.glsl"

// LOD2 billboards the frame's shadow map may reach (IMPOSTOR_PART_SHADOWED).
void main() {
    shadeImpostor(true);
}
