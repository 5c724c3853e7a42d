#version 460
#extension GL_GOOGLE_include_directive : require
#include "field_common.glsl"
#include "lod_select.h"
#include "sunlit_select.h"

// LOD2 billboards (docs/IMPOSTORS.md): the quads of appendBillboardMesh
// expanded around each visible plant, each drawn as the outline of the frame
// it shows (the polygon around what the frame covers, not the whole
// frame), and textured with its atlas frames
// (engine/field/impostor_atlas.h: frame f views from azimuth 2π·f/frames along
// d = (sin a, 0, cos a), right axis (cos a, 0, -sin a)). One quad turns to
// the view about the vertical axis and shows the frame nearest the view
// azimuth; two or three crossed quads stay fixed in plant space, each
// showing the frame baked along its normal (or its opposite, mirrored, when
// seen from behind). The shadow passes draw impostors with
// impostor_shadow.vert and the shadow frames instead.
layout(location = 0) out vec3 outWorldPos;
layout(location = 1) out vec2 outUv;
layout(location = 2) flat out uint outLayer; // the atlas frame shown
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
    // Where the view comes from, in plant space (the instance's yaw undone).
    vec3 toView = frame.cameraPosition.xyz - inst.positionScale.xyz;
    vec3 local = transpose(yawMatrix(inst.orientation.x)) * toView;
    float viewAzimuth = dot(local.xz, local.xz) > 1e-12 ? atan(local.x, local.z) : 0.0;

    float quadAzimuth;
    bool back = false;
    if (quads == 1u) {
        float t = mod(viewAzimuth / kTau * float(frames), float(frames));
        // The nearest frame, not a blend: frames are 30° apart and far
        // plants small, so the switch is not seen, and one texture fetch
        // per pixel is what a CPU rasteriser can afford.
        outLayer = m.impostor.x + uint(round(t)) % frames;
        quadAzimuth = viewAzimuth;
    } else {
        quadAzimuth = v.position.z * 0.5 * kTau / float(quads);
        back = dot(local.xz, vec2(sin(quadAzimuth), cos(quadAzimuth))) < 0.0;
        float shown = quadAzimuth + (back ? 0.5 * kTau : 0.0);
        uint f = uint(round(shown / kTau * float(frames))) % frames;
        outLayer = m.impostor.x + f;
    }
    // This vertex is corner v.position.x of the shown frame's outline; the
    // frame spans the quad, u across [-halfWidth, halfWidth], v from top to
    // bottom. The opposite frame's right axis is this quad's left.
    vec2 uv = outlineCorner(outLayer, uint(v.position.x));
    float across = back ? 1.0 - uv.x : uv.x;
    float height = 1.0 - uv.y; // 0 at the bottom, 1 at the top
    vec3 right = vec3(cos(quadAzimuth), 0.0, -sin(quadAzimuth));
    vec3 plantPos = right * ((2.0 * across - 1.0) * m.impostorQuad.x) +
                    vec3(0.0, mix(m.impostorQuad.y, m.impostorQuad.z, height), 0.0);

    outWorldPos = plantToWorld(inst, plantPos);
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
    // The shown frame was baked looking along -d (impostor_atlas.h), its
    // depth running half its box's depth either side of the quad along d.
    float frameAzimuth = float(outLayer - m.impostor.x) / float(frames) * kTau;
    outDepthAxis = yawMatrix(inst.orientation.x) * vec3(sin(frameAzimuth), 0.0, cos(frameAzimuth)) *
                   (m.impostorQuad.w * inst.positionScale.w);
    outFog = vertexFog(outWorldPos);
    gl_Position = frame.viewProj * vec4(outWorldPos, 1.0);
    // A colour draw of one part keeps only that part's impostors: the others
    // collapse onto a point beyond the far plane, and the rasteriser drops
    // their triangles before any fragment.
    if (impostorPartOf(instanceSphere(inst, m), field.sunViewProj, field.viewport.z, field.viewport.w > 0.5) !=
        fieldPush.impostorPart)
        gl_Position = vec4(0.0, 0.0, 2.0, 1.0);
}
