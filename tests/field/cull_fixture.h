// What the cull-pass tests share: synthetic models and fields, and a fixture
// that runs a cull pass (the camera's or the shadow casters') on the GPU and
// reads back its lists, commands and state.
#pragma once

#include "engine/field/cluster_pass.h"
#include "engine/field/cull_pass.h"
#include "engine/field/cull_reference.h"
#include "engine/field/visible_lists.h"
#include "engine/vk/render_target.h"
#include "gpu_test.h"

#include <glm/glm.hpp>

#include <functional>
#include <vector>

namespace pf::test {

inline constexpr uint32_t kModels = 4;
inline constexpr float kFovY = 1.0471976f; // 60°
inline constexpr uint32_t kViewportHeight = 1080;
inline constexpr float kFadeSeconds = 0.25f;

struct View {
    glm::vec3 position;
    glm::vec3 target;
};

// Where the camera paths of the cull tests start, and a view 6.7 m on, turned 45°.
inline const View kStart{{0.0f, 1.7f, 0.0f}, {0.0f, 1.7f, 1.0f}};
inline const View kMoved{{3.0f, 1.9f, 6.0f}, {4.0f, 1.8f, 7.0f}};

// A 16:9 perspective over kFovY, near 0.1 m, far 1000 m, and the view and
// projection it is made of.
glm::mat4 viewProj(const View& v);
glm::mat4 viewMatrix(const View& v);
glm::mat4 projection();

// Synthetic species: spheres of different sizes and offsets, LOD0 above
// 200 px, LOD1 above 40 px, 10 % hysteresis, a quarter-second fade.
std::vector<gpu::PlantModel> makeModels();
// Per model: LOD 0 and 1 have bark and foliage meshes, LOD 2 an impostor;
// sorted by draw class.
std::vector<gpu::DrawTemplate> makeTemplates(const std::vector<gpu::PlantModel>& models);
gpu::FieldInstance makeInstance(glm::vec3 position, float yaw, float scale, uint32_t model);

// An instance's bounding sphere in double precision, to tell when float
// rounding (sin/cos, dot products on the GPU) could flip a decision.
struct ExactSphere {
    glm::dvec3 centre;
    double radius;
};
ExactSphere exactSphere(const gpu::FieldInstance& inst, const gpu::PlantModel& model);
// The sphere within a hair of touching the plane from outside.
bool grazesPlane(const ExactSphere& s, const glm::vec4& plane);
// A value within a hair of a boundary.
bool nearBoundary(double value, double boundary);

// n instances in a disc of 300 m around the origin, denser toward the
// centre (density ∝ 1/r, so every LOD gets plants), only those `keep` accepts.
std::vector<gpu::FieldInstance> randomInstances(uint32_t n, uint32_t seed,
                                                const std::function<bool(const gpu::FieldInstance&)>& keep);

struct Field {
    std::vector<gpu::FieldInstance> instances;
    std::vector<gpu::PlantModel> models;
    std::vector<gpu::DrawTemplate> templates;
};
// The models' visible lists assigned and the templates made.
Field layOut(std::vector<gpu::FieldInstance> instances, std::vector<gpu::PlantModel> models);

// What one GPU frame produced, read back.
struct GpuFrame {
    std::vector<std::vector<uint32_t>> lists; // [model · LOD_COUNT + lod], sorted
    CullCounts counts;
    std::vector<gpu::DrawCommand> commands;    // DRAW_CLASS_COUNT × templateCount
    std::vector<gpu::DrawCommand> allCommands; // templateCount
    std::vector<uint32_t> state;
    double gpuMilliseconds = -1; // of recordCullPass, when the queue has timestamps
};

class CullPassTest : public GpuTest {
protected:
    // `near`: the chunks of a cluster pass (CullPassInputs::near), recorded
    // before the cull when `clusters` is set.
    void create(const Field& f, CullKind kind = CullKind::Camera, const Buffer* near = nullptr);
    void TearDown() override;
    GpuFrame run(const gpu::CullUniforms& uniforms);
    GpuFrame run(const gpu::ShadowCullUniforms& uniforms);
    // The early then the late phase, the late against `target`'s depth
    // pyramid of a depth buffer cleared to the far plane (nothing hides).
    GpuFrame runTwoPhases(const gpu::CullUniforms& uniforms, const View& view, const RenderTarget& target);

    const Field* field = nullptr;
    Buffer instances, models, host;
    CullPass pass;
    const ClusterPass* clusters = nullptr;
    VkQueryPool queries = VK_NULL_HANDLE;

private:
    bool hasTimestamps();
    GpuFrame record(const std::function<void(VkCommandBuffer)>& recordCull);
};

} // namespace pf::test
