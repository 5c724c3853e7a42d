// The field's moving plants: which simulated skeleton each plant
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

// Sub-steps of one physics dispatch: a frame that has more to catch up (a
// jump in time) records several, each followed by the poses, so parents'
// poses are never older than this many steps.
inline constexpr uint32_t kFrameSubSteps = 8;
static_assert(kFrameSubSteps <= PHYSICS_MAX_DISPATCH_SUB_STEPS, "a dispatch takes at most that many sub-steps");
// A capture at time T starts from rest at T − this (plants settle in ~5 s),
// so it costs the same at any T and depends on T alone; so does a sequence
// whose next frame is further ahead than this.
inline constexpr double kSettleSeconds = 5.0;
// In real time, at most this many steps between two frames: a slow frame
// (a window on a CPU device) must not make the next one slower still. Time
// beyond it passes without being simulated. A gap longer than one dispatch
// is taken by one dispatch of kFrameSubSteps longer sub-steps (at most
// twice the scene's): backward Euler keeps springs and damping stable at any
// length and the explicit drag stays stable up to about 50 m/s of wind at
// twice 1/240 s (docs/PHYSICS.md), while a second dispatch and pose pass
// would cost a window on lavapipe ~15 ms (of the default forest's 105 473
// joints, ~1.2 ms a sub-step and ~7 ms a dispatch with its poses). So a
// window at the 15 frames a second the dynamic render scale holds
// (engine/window/render_scale.h) sees the wind in real time, a slower one
// sees it slowed instead of its frames slowed further.
inline constexpr uint32_t kMaxFrameGapSubSteps = 2 * kFrameSubSteps;

// What the next recordFieldMotion records, as advanceFieldMotion planned it.
struct FieldMotionFrame {
    bool restart = false;                          // states and poses back to rest first
    std::vector<VkBufferCopy> ownStates, ownPoses; // near plants' new skeletons start from their shared copy's
    std::vector<gpu::PhysicsDispatch> dispatches;  // the catch-up, then the frame's own steps
    double subStepSeconds = 0.0;                   // each sub-step's length: the scene's, or longer in real time
};

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
    uint64_t simulatedStep = 0; // sub-steps from time 0 the states will be at after the next recorded frame
    FieldMotionFrame next;
};

// What the motion creates is owned by `owner`.
FieldMotion createFieldMotion(GpuResources& owner, const FieldContent& content);

// Plans the frame that brings the simulation to `time` (FieldMotion::next):
// from rest at max(0, time − kSettleSeconds) when `restart`, when time went
// backwards, or (not in real time) when it jumped further ahead than that.
// Writes what the host owns (which skeleton each plant follows, near plants'
// placements) and the uniforms, so call it while no frame is in flight; it
// submits nothing. Near plants are those around `camera`. `realTime` caps the
// steps between frames (kMaxFrameGapSubSteps) and takes a gap of up to that
// many in one dispatch of longer sub-steps; captures and sequences simulate
// every step at the scene's sub-step.
void advanceFieldMotion(FieldMotion& motion, double time, bool restart, const glm::vec3& camera, bool realTime);
// Records the planned frame: the copies, then the physics and pose passes
// (timer scopes kPhysicsScope, with any catch-up, and kPoseScope).
void recordFieldMotion(VkCommandBuffer cmd, const FieldMotion& motion, GpuTimer* timer = nullptr);

// The shared skeleton copies of a model follow each other along the wind
// this far apart (m): the gust wavelength over the number of copies.
float sharedPhaseSpacing(const PhysicsSettings& settings);

} // namespace pf
