#version 460
#extension GL_GOOGLE_include_directive : require
#include "field_common.glsl"
#include "shared/impostor_frame.h"

// LOD2 in the sun's shadow passes (docs/IMPOSTORS.md, "Shadow frames"): one
// quad per plant perpendicular to the sun direction, a true billboard in the
// sun's view (Tankard 2001's single billboard turned to the light), showing
// the shadow frame baked nearest the sun's azimuth in plant space (the
// instance's yaw undone, as impostor.vert does for the view). The quad's
// plane passes through the plant's centre; impostor_shadow.frag moves each
// texel's depth from it to the depth baked in the frame, the mesh's surface
// nearest the sun.
// The shadows stand at rest: most are drawn once into the cache of static
// casters and copied for many frames (a lean of a tenth of a metre is about
// one texel of the map).
layout(location = 1) out vec2 outUv;
layout(location = 2) flat out uint outLayer; // the shadow frame shown
layout(location = 4) flat out uint outFade;
layout(location = 5) flat out float outDepthSpan; // map depth from the quad to the frame's front

void main() {
    VisiblePlant p = visiblePlant(gl_InstanceIndex);
    FieldInstance inst = fieldInstanceAt(p.index);
    PlantModel m = plantModelAt(inst.ids.x);
    FieldVertex v = fieldVertexAt(gl_VertexIndex);
    outFade = packFade(p);
    // Crossed billboards' meshes (appendBillboardMesh) have two or three
    // quads; the sun sees one, so the others collapse to a point outside
    // the clip volume and rasterise nothing.
    if (v.position.z > 0.5) {
        outUv = vec2(0.0);
        outLayer = 0u;
        outDepthSpan = 0.0;
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
    // The sun in plant space; a yaw leaves its elevation as it is.
    vec3 toSun = transpose(yawMatrix(inst.orientation.x)) * frame.sunDirection.xyz;
    float cosE = length(toSun.xz);
    float sinE = toSun.y;
    float azimuth = cosE > 1e-6 ? atan(toSun.x, toSun.z) : 0.0;
    uint frames = m.impostor.y;
    // The nearest frame, as the colour pass's single billboards choose.
    outLayer = m.impostor.w + impostorNearestFrame(azimuth, frames);

    // Corner v.position.x of the whole frame, in impostor_outline.h's order:
    // (0, 0), (1, 0), (1, 1), (0, 1), v = 0 at the top.
    uint corner = uint(v.position.x);
    vec2 uv = vec2(corner == 1u || corner == 2u ? 1.0 : 0.0, corner >= 2u ? 1.0 : 0.0);
    vec3 halfExtent = impostorFrameHalfExtents(m.impostorQuad, sinE, cosE);
    vec3 plantPos = impostorFrameCentre(m.impostorQuad) +
                    impostorFrameRight(azimuth) * ((2.0 * uv.x - 1.0) * halfExtent.x) +
                    impostorFrameUp(azimuth, sinE, cosE) * ((1.0 - 2.0 * uv.y) * halfExtent.y);
    outUv = uv;
    mat4 sunViewProj = passViewProj();
    // The frame's half depth along the sun, in map depth (orthographic: a
    // direction moves depth the same everywhere).
    outDepthSpan = (sunViewProj * vec4(frame.sunDirection.xyz, 0.0)).z * halfExtent.z * inst.positionScale.w;
    gl_Position = sunViewProj * vec4(plantToWorld(inst, plantPos), 1.0);
}
