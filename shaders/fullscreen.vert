#version 460
// One triangle that covers the whole viewport (vertices 0, 1, 2 at clip
// (-1,-1), (3,-1), (-1,3)), for full-screen passes that work from
// gl_FragCoord and need no inputs.
void main() {
    vec2 corner = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
