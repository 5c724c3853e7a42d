// The GPU timer scopes of the field's frame (engine/vk/gpu_timer.h), each
// declared once: its name as the tools print it (--stats JSON keys,
// plantbench's tables and columns, the window's overlay) and whether it is
// nested inside "colour", in the order a frame records them. "colour" is the
// whole colour pass, its anti-aliasing included, and the scopes after it are
// nested inside it: four groups of draws of the early phase (or of the one
// phase without occlusion culling), the depth pyramid, the late cull with
// its occlusion test, the late phase's draws, the clouds' shadows and the
// clouds (cloud_shadow_pass.h, cloud_pass.h), then the anti-aliasing
// (target_pass.h). Without occlusion culling the three late scopes are
// empty, without clouds the clouds scope. The passes below the field record
// theirs by the names they declare (kPhysicsScope, kPoseScope,
// kAntialiasScope), which the table takes; the field's recorders name a
// FieldScope. field_scopes.cpp checks the table's order.
#pragma once

#include "engine/physics/physics_pass.h"
#include "engine/vk/gpu_timer.h"
#include "engine/vk/target_pass.h"

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

namespace pf {

enum class FieldScope {
    physics,
    pose,
    clusters,
    cull,
    shadow,
    color,
    plants,
    impostors,
    canopy,
    terrainSky,
    depthPyramid,
    occlusion,
    lateDraws,
    clouds,
    antialias,
};

struct FieldScopeDefinition {
    FieldScope scope;
    const char* name;
    bool insideColor; // recorded inside "colour": a frame's total adds only the others
};

inline constexpr std::array<FieldScopeDefinition, 15> kFieldScopes = {{
    {FieldScope::physics, kPhysicsScope, false},
    {FieldScope::pose, kPoseScope, false},
    {FieldScope::clusters, "clusters", false},
    {FieldScope::cull, "cull", false},
    {FieldScope::shadow, "shadow", false},
    {FieldScope::color, "colour", false},
    {FieldScope::plants, "plants", true},
    {FieldScope::impostors, "impostors", true},
    {FieldScope::canopy, "canopy", true},
    {FieldScope::terrainSky, "terrain_sky", true},
    {FieldScope::depthPyramid, "depth_pyramid", true},
    {FieldScope::occlusion, "occlusion", true},
    {FieldScope::lateDraws, "late_draws", true},
    {FieldScope::clouds, "clouds", true},
    {FieldScope::antialias, kAntialiasScope, true},
}};

constexpr const FieldScopeDefinition& fieldScope(FieldScope scope) { return kFieldScopes[size_t(scope)]; }

// The scope of that name; nullopt for a name the field does not record
// (plantbench's own "capture").
std::optional<FieldScope> fieldScopeNamed(std::string_view name);

// A scope of the field's frame open for the object's lifetime; nothing
// when `timer` is null.
class TimedFieldScope : public TimedScope {
public:
    TimedFieldScope(VkCommandBuffer cmd, GpuTimer* timer, FieldScope scope,
                    ScopeStart start = ScopeStart::outsideRendering);
};

} // namespace pf
