// The field as a graph for the GPU traversal (gpu_graph.h): a root object
// whose BVH holds every plant as an instance of its model, placed by the
// plant's position, yaw and scale, and per model an object holding the
// triangles of its full-detail mesh. The plants' own hierarchy is flattened
// into each model, as the colour pass draws it; the field's instancing is
// kept, so a model is stored once however many plants share it (Hart and
// DeFanti 1991, "Efficient antialiased rendering of 3-D linear fractals",
// trace an instancing hierarchy so). The sun's rays of plantfield's ray-
// traced shadows (docs/RAYTRACING.md, "Ray-traced sun shadows") are traced
// through it. Pure CPU.
#pragma once

#include "engine/raytrace/gpu_graph.h"
#include "engine/scene/plant_models.h"
#include "shaders/shared/field_layouts.h"

#include <span>

namespace pf {

// Consecutive triangles of one kind a primitive holds at most: a leaf card's
// two, a few of a tube's ring. Fewer primitives make a shallower BVH; more
// triangles a leaf cost more tests per ray.
inline constexpr uint32_t kFieldTrianglesPerPrimitive = 4;

// Host bytes packFieldGraph needs at most for these models and this many
// plants: checked against a memory budget before packing.
uint64_t fieldGraphBytes(const PlantModelPool& models, size_t plants);

// A primitive's material is its triangles' SURFACE_* kind; the cut-out test
// of leaf cards (shaders/raytraced_sun.comp) reads the texture coordinates each
// triangle corner keeps in its w, two halves packed (glm::packHalf2x16).
// Throws GpuGraphError when the traversal's arrays cannot hold the field.
GpuGraph packFieldGraph(const PlantModelPool& models, std::span<const gpu::FieldInstance> plants);

} // namespace pf
