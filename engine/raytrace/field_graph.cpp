#include "engine/raytrace/field_graph.h"

#include "lsystem/instancing/instance_graph.h"

#include <glm/gtc/packing.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <bit>

namespace pf {
namespace {

// A corner's texture coordinates in the w the traversal leaves free.
float packedUv(const gpu::FieldVertex& v) {
    return std::bit_cast<float>(glm::packHalf2x16(glm::vec2(v.position.w, v.normal.w)));
}

struct ModelObject {
    lsys::Bvh bvh;                   // over the model's primitives, in itemWords order
    std::vector<uint32_t> itemWords; // their global indices
    lsys::Bounds bounds;
};

// The model's full-detail bark and foliage as polygon primitives of up to
// kFieldTrianglesPerPrimitive consecutive triangles of one kind, and its BVH.
ModelObject appendModelTriangles(GpuGraph& packed, const PlantModelPool& pool, const PlantModelInfo& model) {
    ModelObject object;
    std::vector<lsys::Bounds> boxes;
    std::vector<uint32_t>& itemWords = object.itemWords;
    for (const MeshRange& mesh : model.meshes[LOD_FULL]) {
        uint32_t open = RAYTRACE_NO_HIT; // the primitive still taking triangles
        for (uint32_t i = 0; i + 2 < mesh.indexCount; i += 3) {
            const uint32_t* corner = &pool.indices[mesh.firstIndex + i];
            const gpu::FieldVertex& a = pool.vertices[mesh.vertexOffset + corner[0]];
            const gpu::FieldVertex& b = pool.vertices[mesh.vertexOffset + corner[1]];
            const gpu::FieldVertex& c = pool.vertices[mesh.vertexOffset + corner[2]];
            const auto kind = uint32_t(a.albedo.a + 0.5f);
            if (open == RAYTRACE_NO_HIT || packed.primitives[open].material != kind ||
                packed.primitives[open].triangleCount == kFieldTrianglesPerPrimitive) {
                open = uint32_t(packed.primitives.size());
                gpu::RtPrimitive primitive{};
                primitive.rotation = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
                primitive.kind = RAYTRACE_KIND_POLYGON;
                primitive.material = kind;
                primitive.firstTriangle = uint32_t(packed.triangles.size());
                packed.primitives.push_back(primitive);
                itemWords.push_back(open);
                boxes.emplace_back();
            }
            packed.triangles.push_back({glm::vec4(glm::vec3(a.position), packedUv(a)),
                                        glm::vec4(glm::vec3(b.position), packedUv(b)),
                                        glm::vec4(glm::vec3(c.position), packedUv(c))});
            ++packed.primitives[open].triangleCount;
            for (const gpu::FieldVertex* v : {&a, &b, &c}) boxes.back().extend(glm::vec3(v->position));
        }
    }
    object.bvh = lsys::buildBvh(boxes);
    for (const lsys::Bounds& box : boxes) object.bounds.extend(box);
    return object;
}

} // namespace

uint64_t fieldGraphBytes(const PlantModelPool& models, size_t plants) {
    uint64_t triangles = 0;
    for (const PlantModelInfo& model : models.models)
        for (const MeshRange& mesh : model.meshes[LOD_FULL]) triangles += mesh.indexCount / 3;
    // A triangle, at worst its own primitive, box, item and two BVH nodes;
    // a plant its instance, box, item and two nodes.
    const uint64_t perTriangle = sizeof(gpu::RtTriangle) + sizeof(gpu::RtPrimitive) + sizeof(lsys::Bounds) +
                                 2 * sizeof(uint32_t) + 2 * (sizeof(gpu::RtNode) + sizeof(lsys::BvhNode));
    const uint64_t perPlant = sizeof(gpu::RtInstance) + sizeof(lsys::Bounds) + 2 * sizeof(uint32_t) +
                              2 * (sizeof(gpu::RtNode) + sizeof(lsys::BvhNode));
    return triangles * perTriangle + plants * perPlant;
}

GpuGraph packFieldGraph(const PlantModelPool& models, std::span<const gpu::FieldInstance> plants) {
    GpuGraph packed;
    std::vector<ModelObject> objects;
    uint32_t modelStack = 1;
    for (const PlantModelInfo& model : models.models) {
        objects.push_back(appendModelTriangles(packed, models, model));
        modelStack = std::max(modelStack, bvhHeight(objects.back().bvh));
    }
    for (const ModelObject& object : objects)
        packed.objectRoots.push_back(appendObjectBvh(packed, object.bvh, object.itemWords));

    std::vector<lsys::Bounds> boxes;
    std::vector<uint32_t> itemWords;
    for (const gpu::FieldInstance& plant : plants) {
        const uint32_t model = plant.ids.x;
        const glm::quat yaw = glm::angleAxis(plant.orientation.x, glm::vec3(0.0f, 1.0f, 0.0f));
        const gpu::RtInstance instance{glm::vec4(yaw.x, yaw.y, yaw.z, yaw.w),
                                       glm::vec3(plant.positionScale),
                                       model,
                                       plant.positionScale.w,
                                       0,
                                       0,
                                       0};
        itemWords.push_back(RAYTRACE_ITEM_INSTANCE | uint32_t(packed.instances.size()));
        // The model's box scaled (an empty one stays empty), turned by the yaw and placed.
        const lsys::Bounds& local = objects.at(model).bounds;
        boxes.push_back(
            lsys::transformed({local.min * instance.scale, local.max * instance.scale}, {instance.position, yaw}));
        packed.instances.push_back(instance);
    }
    // A plant is a whole subtree: one a leaf, as the graph tracer's objects (kGraphObjectLeafSize).
    const lsys::Bvh root = lsys::buildBvh(boxes, 1);
    const uint32_t rootNode = appendObjectBvh(packed, root, itemWords);
    packed.objectRoots.push_back(rootNode);
    if (rootNode != RAYTRACE_NO_NODE) setRoot(packed, rootNode, 2, bvhHeight(root) + modelStack + 1);
    return packed;
}

} // namespace pf
