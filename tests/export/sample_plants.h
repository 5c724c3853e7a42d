#pragma once
// Plants built by hand for the exporter's tests (the turtle is tested on its
// own): every primitive kind, a bent stem, a branch, a shared surface.

#include "lsystem/instancing/instance_graph.h"
#include "lsystem/turtle/plant_asset.h"

namespace plantfield::test {

// Joints 0 → 1 → 2 are a stem that bends 30° twice (radii 0.1, 0.08, 0.064,
// 0.0512: the same 0.8 ratio each time), joint 3 a cylindrical branch from
// the tip of joint 0, joint 4 a zero-width segment on joint 3 (nothing to
// draw). Organs: a sphere on the stem's tip, the same leaf surface on joints
// 1 and 3, and a non-convex L-shaped polygon (6 corners, area 3) on joint 2.
// Materials: 0 "bark", 1 "leaf green" (two-sided).
lsys::PlantAsset samplePlant();

// One chain of `segments` segments (joint i on joint i−1), each turning 25°
// about a tilted axis from the last, so the stem winds up as a helix; the
// radius falls linearly from 0.1 to exactly 0 at the tip (a cone).
lsys::PlantAsset helixPlant(int segments);

// Where segment `index` of samplePlant() ends.
glm::vec3 segmentTip(const lsys::PlantAsset& asset, size_t index);

// The InstanceGraph of a small grammar drawing every primitive kind: objects
// with segments, a leaf and a petal, a sphere, a polygon, and instances of
// each other three levels deep (exact, from the built-in surfaces).
lsys::InstanceGraph sampleGraph();

} // namespace plantfield::test
