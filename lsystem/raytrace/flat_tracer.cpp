#include "lsystem/raytrace/flat_tracer.h"

namespace lsys {

FlatTracer buildFlatTracer(const PlantAsset& plant) {
    FlatTracer tracer{&plant, tracedShapesOf(plant), {}, {}};
    tracer.primitiveBounds.reserve(plant.primitives.size());
    for (const Primitive& primitive : plant.primitives)
        tracer.primitiveBounds.push_back(tracedBounds(primitive, tracer.shapes.surfaces, tracer.shapes.polygons));
    tracer.bvh = buildBvh(tracer.primitiveBounds);
    return tracer;
}

std::optional<Hit> trace(const FlatTracer& tracer, Ray ray, HitQuery query) {
    Hit hit;
    bool found = false;
    traverseBvh(tracer.bvh, ray, [&](uint32_t index) {
        found |= tracePrimitive(tracer.plant->primitives[index], index, tracer.shapes.surfaces, tracer.shapes.polygons,
                                ray, hit);
        return found && query == HitQuery::Any;
    });
    if (!found) return std::nullopt;
    return hit;
}

} // namespace lsys
