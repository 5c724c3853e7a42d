// The cut through the field's quadtree (docs/CLUSTERS.md), shared by
// shaders/cluster.comp and pf::clusterCutOnCpu like lod_select.h: per node,
// independently, whether it is drawn as its canopy (far), its plants go
// through the per-plant cull (a near leaf), or neither.
//
// A node's error is the size in pixels of one canopy cell at the nearest
// point of its box. A child's cell is half its parent's and its box lies
// inside its parent's, so the error never grows from parent to child; a node
// is far when its error is below the threshold and its parent's is not, a
// leaf near when its own error is not below it. Every leaf thus has exactly
// one far ancestor (itself included) or is near: the cut has no holes and
// no overlaps.
#ifndef PLANTFIELD_SHADERS_CLUSTER_SELECT_H
#define PLANTFIELD_SHADERS_CLUSTER_SELECT_H

#include "cluster_layouts.h"
#include "lod_select.h"

#ifdef __cplusplus
namespace gpu {
using glm::clamp;
#define CLUSTER_SELECT_FN inline
#else
#define CLUSTER_SELECT_FN
#endif

// Pixels one canopy cell of the node covers, seen from the camera at the
// nearest point of the node's box.
CLUSTER_SELECT_FN float clusterCellPixels(ClusterNode node, vec4 camera) {
    vec3 nearest = clamp(vec3(camera), vec3(node.boxMin), vec3(node.boxMax));
    return pixelsAtDistance(0.5f * node.square.w, camera.w, distance(vec3(camera), nearest));
}

// False when the box lies entirely outside the plane: its corner farthest
// along the plane's normal is outside.
CLUSTER_SELECT_FN bool boxInsidePlane(vec3 lo, vec3 hi, vec4 plane) {
    vec3 corner = vec3(plane.x >= 0.0f ? hi.x : lo.x, plane.y >= 0.0f ? hi.y : lo.y, plane.z >= 0.0f ? hi.z : lo.z);
    return dot(vec3(plane), corner) + plane.w >= 0.0f;
}

CLUSTER_SELECT_FN bool clusterInFrustum(ClusterNode node, ClusterUniforms u) {
    vec3 lo = vec3(node.boxMin), hi = vec3(node.boxMax);
    return boxInsidePlane(lo, hi, u.frustum[0]) && boxInsidePlane(lo, hi, u.frustum[1]) &&
           boxInsidePlane(lo, hi, u.frustum[2]) && boxInsidePlane(lo, hi, u.frustum[3]) &&
           boxInsidePlane(lo, hi, u.frustum[4]) && boxInsidePlane(lo, hi, u.frustum[5]);
}

// CLUSTER_CULLED, _COVERED, _FAR or _NEAR for a node with this error and
// its parent's (CLUSTER_ROOT_PARENT_PIXELS at the root).
CLUSTER_SELECT_FN uint clusterDecision(ClusterNode node, float pixels, float parentPixels, bool inside,
                                       ClusterUniforms u) {
    if (!inside) return CLUSTER_CULLED;
    bool leaf = node.range.w == 0u;
    uint cut = u.counts.z;
    if (cut == CLUSTER_CUT_ALL_NEAR || cut == CLUSTER_CUT_BOX_ONLY) return leaf ? CLUSTER_NEAR : CLUSTER_COVERED;
    if (cut == CLUSTER_CUT_ALL_FAR) return leaf ? CLUSTER_FAR : CLUSTER_COVERED;
    float threshold = u.threshold.x;
    if (pixels < threshold) return parentPixels < threshold ? CLUSTER_COVERED : CLUSTER_FAR;
    return leaf ? CLUSTER_NEAR : CLUSTER_COVERED;
}

#ifdef __cplusplus
} // namespace gpu
#endif
#undef CLUSTER_SELECT_FN

#endif
