// The field's moving plants (issue 6): which simulated skeleton each plant
// follows, and when the physics pass steps. Farther plants share a model's
// skeletons, simulated in a few copies placed a fraction of a gust
// wavelength apart along the wind, so neighbours sway out of phase; each
// plant follows the copy its wind phase picks. Plants near the camera get
// skeletons of their own within the joint budget (near_skeletons.h).
// Impostors sway in their vertex shader instead.
#pragma once

#include "engine/physics/near_skeletons.h"
#include "engine/physics/physics_pass.h"
#include "engine/scene/field_content.h"

namespace pf {

// Steps recorded in the frame itself; more (a jump in time) run before it.
inline constexpr uint32_t kFrameSubSteps = 8;
// A capture at time T starts from rest at T − this (plants settle in ~5 s),
// so it costs the same at any T and depends on T alone.
inline constexpr double kSettleSeconds = 5.0;
// In real time, at most this many steps between two frames: a slow frame
// (a window on a CPU device) must not make the next one slower still. Time
// beyond it passes without being simulated.
inline constexpr uint32_t kMaxFrameGapSubSteps = 4 * kFrameSubSteps;

struct FieldMotion {
    const FieldContent* content = nullptr; // outlives the motion (the renderer owns both)
    PhysicsPass pass;
    Buffer instanceSkeleton;        // host-visible uint per plant: the skeleton its vertices follow
    std::vector<uint32_t> sharedOf; // per plant: the shared copy it follows when it has no own skeleton
    PlantGrid grid;
    NearSkeletons near;
    Buffer restStates; // copied over the states to restart at rest
    Buffer restPoses;
    Wind wind;
    PhysicsSettings settings;
    uint64_t simulatedStep = 0; // sub-steps from time 0 the states will be at after the recorded ones
    uint32_t frameSubSteps = 0; // steps the next recordFieldMotion takes
};

// What the motion creates is owned by `owner`.
FieldMotion createFieldMotion(GpuResources& owner, const FieldContent& content);

// Brings the simulation to `time`: from rest at max(0, time − kSettleSeconds)
// when `restart` or when time went backwards; steps beyond the last
// kFrameSubSteps run now (the GPU must be idle); the rest are left for the
// frame. Call while no frame is in flight.
// Near plants are those around `camera`. `realTime` caps the steps between
// frames (kMaxFrameGapSubSteps); captures and sequences simulate every step.
void advanceFieldMotion(const GpuContext& ctx, FieldMotion& motion, double time, bool restart, const glm::vec3& camera,
                        bool realTime);
// The physics and pose passes of the frame (timer scopes "physics", "pose").
void recordFieldMotion(VkCommandBuffer cmd, const FieldMotion& motion, GpuTimer* timer = nullptr);

// The shared skeleton copies of a model follow each other along the wind
// this far apart (m): the gust wavelength over the number of copies.
float sharedPhaseSpacing(const PhysicsSettings& settings);

} // namespace pf
