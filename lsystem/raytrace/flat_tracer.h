#pragma once
// Tracing a flat PlantAsset: one BVH over all its primitives in plant space
// (docs/RAYTRACING.md). The reference the hierarchical tracer is compared to,
// and the flat side of the Calgary b-grammar thesis' hierarchical-versus-flat
// comparison (ch. 7).

#include <optional>
#include <vector>

#include "lsystem/raytrace/bvh.h"
#include "lsystem/raytrace/ray.h"
#include "lsystem/raytrace/traced_primitive.h"
#include "lsystem/turtle/plant_asset.h"

namespace lsys {

struct FlatTracer {
    const PlantAsset* plant = nullptr; // must outlive the tracer
    TracedShapes shapes;
    std::vector<Bounds> primitiveBounds; // by PlantAsset::primitives index
    Bvh bvh;                             // over primitiveBounds
};

FlatTracer buildFlatTracer(const PlantAsset& plant);

// The nearest hit in [ray.tMin, ray.tMax] (Closest), or any hit (Any); the
// hit's primitive indexes PlantAsset::primitives, its normal is in plant space.
std::optional<Hit> trace(const FlatTracer& tracer, Ray ray, HitQuery query);

} // namespace lsys
