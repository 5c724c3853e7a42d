// The vertex stage of plant meshes (LOD0 and LOD1, bark and foliage), for
// the camera view and the shadow map alike (field_common.glsl passViewProj).
// Included by plant.vert; the instance comes from the visible list the cull
// pass wrote, the vertex from the shared FieldVertex pool.
#include "field_common.glsl"

layout(location = 0) out vec3 outWorldPos;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec3 outAlbedo;
layout(location = 3) out vec2 outUv;
layout(location = 4) flat out uint outFade;
layout(location = 5) flat out float outKind;
layout(location = 6) out vec4 outFog;
layout(location = 7) out vec3 outRestPos; // before the pose: where raytraced_origin_plant.frag starts the sun's ray

void main() {
    VisiblePlant p = visiblePlant(gl_InstanceIndex);
    FieldInstance inst = fieldInstanceAt(p.index);
    FieldVertex v = fieldVertexAt(gl_VertexIndex);

    // Skinning: every vertex follows its joint's pose.
    JointPose pose = plantJointPose(p.index, v.joint.x);
    outWorldPos = plantToWorld(inst, posePoint(pose, v.position.xyz));
    outRestPos = plantToWorld(inst, v.position.xyz);
    outNormal = plantNormalToWorld(inst, quatRotate(pose.rotation, v.normal.xyz));
    outAlbedo = v.albedo.rgb;
    outUv = vec2(v.position.w, v.normal.w);
    outFade = packFade(p);
    outKind = v.albedo.a;
    outFog = fieldPush.shadowPass != FIELD_PASS_COLOR ? vec4(0.0) : vertexFog(outWorldPos);
    gl_Position = passViewProj() * vec4(outWorldPos, 1.0);
}
