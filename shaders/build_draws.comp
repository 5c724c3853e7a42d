#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/field_layouts.h"

// One invocation per DrawTemplate: its (model, LOD) list becomes an indexed
// indirect command. Every template gets one in allCommands (the fallback
// path without vkCmdDrawIndexedIndirectCount draws them all, empty ones
// included); non-empty ones are also compacted into their class's region
// of commands, counted in drawCounts. Each cull phase has its own region
// of commands, allCommands and drawCounts (CULL_PHASE_REGIONS); the late
// phase's draws start after the early phase's entries of each list.
layout(local_size_x = CULL_GROUP_SIZE) in;

layout(set = 0, binding = CULL_BINDING_UNIFORMS, std430) readonly buffer CullBlock {
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
layout(push_constant) uniform Push {
    CullPush push;
};

void main() {
    uint t = gl_GlobalInvocationID.x;
    uint templateCount = cull.counts.y;
    if (t >= templateCount) return;

    DrawTemplate tmpl = templates[t];
    bool late = push.phase.x == CULL_PHASE_LATE;
    uint region = late ? 1u : 0u;
    uint n = counts[region * push.phase.y + tmpl.list.x];
    uint first = tmpl.list.y + (late ? counts[tmpl.list.x] : 0u);
    DrawCommand command = DrawCommand(tmpl.mesh.x, n, tmpl.mesh.y, tmpl.mesh.z, first);
    allCommands[region * templateCount + t] = command;
    if (n == 0u) return;
    uint drawClass = tmpl.mesh.w;
    uint i = atomicAdd(drawCounts[region * DRAW_CLASS_COUNT + drawClass], 1u);
    commands[(region * DRAW_CLASS_COUNT + drawClass) * templateCount + i] = command;
}
