#version 460
#extension GL_GOOGLE_include_directive : require
#include "impostor_color.glsl"

// LOD2 billboards beyond the frame's shadow map (IMPOSTOR_PART_SUNLIT): in
// full sun, no shadow lookup.
void main() {
    shadeImpostor(false);
}
