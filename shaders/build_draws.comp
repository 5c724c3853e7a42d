#version 460
#extension GL_GOOGLE_include_directive : require
#include "field_layouts.h"

// One invocation per DrawTemplate: its (model, LOD) list becomes an indexed
// indirect command. Every template gets one in allCommands (the fallback
// path without vkCmdDrawIndexedIndirectCount draws them all, empty ones
// included); non-empty ones are also compacted into their class's region
// of commands, counted in drawCounts.
layout(local_size_x = CULL_GROUP_SIZE) in;

layout(set = 0, binding = CULL_BINDING_UNIFORMS, std140) uniform CullBlock {
    CullUniforms cull;
};
layout(set = 0, binding = CULL_BINDING_COUNTS, std430) readonly buffer Counts {
    uint counts[];
};
layout(set = 0, binding = CULL_BINDING_TEMPLATES, std430) readonly buffer Templates {
    DrawTemplate templates[];
};
layout(set = 0, binding = CULL_BINDING_COMMANDS, std430) writeonly buffer Commands {
    DrawCommand commands[];
};
layout(set = 0, binding = CULL_BINDING_DRAW_COUNTS, std430) buffer DrawCounts {
    uint drawCounts[];
};
layout(set = 0, binding = CULL_BINDING_ALL_COMMANDS, std430) writeonly buffer AllCommands {
    DrawCommand allCommands[];
};

void main() {
    uint t = gl_GlobalInvocationID.x;
    uint templateCount = cull.counts.y;
    if (t >= templateCount) return;

    DrawTemplate tmpl = templates[t];
    uint n = counts[tmpl.list.x];
    DrawCommand command = DrawCommand(tmpl.mesh.x, n, tmpl.mesh.y, tmpl.mesh.z, tmpl.list.y);
    allCommands[t] = command;
    if (n == 0u) return;
    uint drawClass = tmpl.mesh.w;
    uint i = atomicAdd(drawCounts[drawClass], 1u);
    commands[drawClass * templateCount + i] = command;
}
