#version 460
#extension GL_GOOGLE_include_directive : require
#include "field_common.glsl"
#include "shared/impostor_frame.h"
#include "shared/lod_select.h"
#include "shared/sunlit_select.h"

// LOD2 billboards (docs/IMPOSTORS.md): the quads of appendBillboardMesh
// expanded around each visible plant, each drawn as the outline of the frame
// it shows (the polygon around what the frame covers, not the whole
// frame), and textured with its atlas frames (shaders/shared/impostor_frame.h: the
// frames' axes and extents on their rings of elevation). Seen from near the
// horizon (ring 0), one quad turns to the view about the vertical axis and
// shows the frame nearest the view azimuth; two or three crossed quads stay
// fixed in plant space, each showing the frame baked along its normal (or
// its opposite, mirrored, when seen from behind). Seen from higher up, the
// plant is one quad turned to the view's azimuth and tilted back by the
// nearest ring's elevation, showing that ring's frame nearest the view
// azimuth: a vertical card seen from above would shorten the crown. The
// shadow passes draw impostors with impostor_shadow.vert and the shadow
// frames instead.
layout(location = 0) out vec3 outWorldPos;
layout(location = 1) out vec2 outUv;
layout(location = 2) flat out uint outLayer; // the atlas frame shown
layout(location = 3) out vec3 outRestPos;      // outWorldPos before the wind's lean (raytraced_origin_impostor.frag)
layout(location = 4) flat out uint outFade;
layout(location = 5) flat out float outYaw;
layout(location = 6) out vec4 outFog;
layout(location = 7) flat out vec3 outDepthAxis; // world: from the quad to the shown frame's front (toward its view)

const float kTau = 6.28318531;

void main() {
    VisiblePlant p = visiblePlant(gl_InstanceIndex);
    FieldInstance inst = fieldInstanceAt(p.index);
    PlantModel m = plantModelAt(inst.ids.x);
    FieldVertex v = fieldVertexAt(gl_VertexIndex);

    uint frames = m.impostor.y;
    uint quads = m.impostor.z;
    // Where the view comes from, in plant space (the instance's yaw undone),
    // and its elevation seen from the frames' centre.
    vec3 toView = frame.cameraPosition.xyz - inst.positionScale.xyz;
    vec3 local = transpose(yawMatrix(inst.orientation.x)) * toView;
    float viewAzimuth = dot(local.xz, local.xz) > 1e-12 ? atan(local.x, local.z) : 0.0;
    vec3 centre = impostorFrameCentre(m.impostorQuad);
    float viewElevation = atan(local.y - centre.y * inst.positionScale.w, length(local.xz));
    uint ring = impostorRingOf(viewElevation);
    float elevation = impostorRingElevation(ring);
    float sinE = sin(elevation), cosE = cos(elevation);

    float quadAzimuth;
    bool back = false;
    uint shownFrame;
    if (quads == 1u || ring > 0u) {
        // Far plants are small: the switch between frames is not seen.
        shownFrame = impostorNearestFrame(viewAzimuth, frames);
        quadAzimuth = viewAzimuth;
    } else {
        quadAzimuth = v.position.z * 0.5 * kTau / float(quads);
        back = dot(local.xz, vec2(sin(quadAzimuth), cos(quadAzimuth))) < 0.0;
        float shown = quadAzimuth + (back ? 0.5 * kTau : 0.0);
        shownFrame = uint(round(shown / kTau * float(frames))) % frames;
    }
    outLayer = m.impostor.x + ring * frames + shownFrame;
    // This vertex is corner v.position.x of the shown frame's outline; the
    // frame spans the quad, u across its right axis, v from top to bottom.
    // The opposite frame's right axis is this quad's left.
    vec2 uv = outlineCorner(outLayer, uint(v.position.x));
    float across = back ? 1.0 - uv.x : uv.x;
    float height = 1.0 - uv.y; // 0 at the bottom, 1 at the top
    vec3 halfExtent = impostorFrameHalfExtents(m.impostorQuad, sinE, cosE);
    vec3 plantPos = centre + impostorFrameRight(quadAzimuth) * ((2.0 * across - 1.0) * halfExtent.x) +
                    impostorFrameUp(quadAzimuth, sinE, cosE) * ((2.0 * height - 1.0) * halfExtent.y);

    outWorldPos = plantToWorld(inst, plantPos);
    outRestPos = outWorldPos;
    // Far plants have no skeleton: the quad's top leans with the gusts and
    // turbulence (the wind beyond its mean), growing with height squared.
    // Like the skeletons, which start at rest at time 0, the lean rises over
    // the first second.
    vec3 gust = fieldWindAt(inst.positionScale.xyz) - vec3(field.wind.x, 0.0, field.wind.z);
    float lean = height * height * min(field.wind.w, 1.0);
    outWorldPos += vec3(gust.x, 0.0, gust.z) * (field.windDetail.w * lean * inst.positionScale.w);
    outUv = uv;
    outFade = packFade(p);
    outYaw = inst.orientation.x;
    // The shown frame was baked looking along -d (impostor_frame.h), its
    // depth running half its extent either side of the quad along d.
    outDepthAxis = yawMatrix(inst.orientation.x) *
                   impostorFrameToView(impostorFrameAzimuth(shownFrame, frames), sinE, cosE) *
                   (halfExtent.z * inst.positionScale.w);
    outFog = vertexFog(outWorldPos);
    gl_Position = frame.viewProj * vec4(outWorldPos, 1.0);
    // A colour draw of one part keeps only that part's impostors, and a
    // plant seen from above one quad: the others collapse onto a point
    // beyond the far plane, and the rasteriser drops their triangles before
    // any fragment.
    if ((ring > 0u && v.position.z > 0.5) ||
        impostorPartOf(instanceSphere(inst, m), field.sunViewProj, field.viewport.z,
                       field.viewport.w != FIELD_SUN_UNSHADOWED) !=
            fieldPush.impostorPart)
        gl_Position = vec4(0.0, 0.0, 2.0, 1.0);
}
