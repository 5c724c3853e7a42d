#version 460
// One triangle over the whole viewport, as fullscreen.vert, with the
// source's texture coordinates: (0, 0) at the top-left corner, (1, 1) at the
// bottom-right, whatever the two images' sizes.
layout(location = 0) out vec2 outUv;

void main() {
    vec2 corner = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    outUv = corner;
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
