#version 460
// One triangle that covers the whole viewport (vertices 0, 1, 2 at clip
// (-1,-1), (3,-1), (-1,3)), for full-screen passes: those that work from
// gl_FragCoord need no input; outUv is the viewport's texture coordinate,
// (0, 0) at the top-left corner and (1, 1) at the bottom-right, for passes
// that sample an image of another size (the window blit).
layout(location = 0) out vec2 outUv;

void main() {
    vec2 corner = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    outUv = corner;
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
