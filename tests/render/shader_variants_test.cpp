// lavapipe compiles a new variant of a shader, with the values inlined, each
// time a uniform block or push constant it branches on changes (Mesa's
// lvp_inline_uniforms), and its on-disk shader cache keeps every variant
// compiled. A frame from a camera a centimetre away then costs LLVM
// compilations, not rendering: a window, whose camera moves every frame,
// would compile shaders every frame. Frames from new cameras and times must
// therefore add nothing to an otherwise warm cache (docs/BENCHMARKS.md).
#include "field_render.h"
#include "gpu_test.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace pf::test {
namespace {

namespace fs = std::filesystem;

struct Shot {
    Camera camera;
    float time = 0.0f;
};

// Around the test field: among its plants (the per-plant cull, reduced and
// full LODs, casters drawn every frame), then above it (far canopies),
// far enough apart that the shadow cache is drawn again; every camera looks
// at `target`. `shift` moves every camera by that many metres and every
// time by that many seconds.
std::vector<Shot> tour(float metres, float seconds, const glm::vec3& target) {
    std::vector<Shot> shots;
    const float heights[] = {2.0f, 6.0f, 45.0f};
    for (int i = 0; i < 3; ++i) {
        const float angle = 0.9f * float(i) + metres / 50.0f;
        Shot shot;
        shot.camera.position = {50.0f * std::cos(angle), heights[i] + metres, 50.0f * std::sin(angle)};
        shot.camera.target = target;
        shot.camera.fovYDegrees = 50.0f;
        shot.time = 1.0f + 0.5f * float(i) + seconds;
        shots.push_back(shot);
    }
    return shots;
}

// Files in Mesa's multi-file shader cache under `dir` (its index aside).
size_t cachedShaders(const fs::path& dir) {
    size_t files = 0;
    if (!fs::exists(dir)) return 0;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(dir))
        if (entry.is_regular_file() && entry.path().filename() != "index") ++files;
    return files;
}

// Renders the shots, one after another as a window does, in a context of
// its own whose cache is `cacheDir`: destroying the device finishes the
// cache's writes. Returns the device's name.
std::string renderTour(const fs::path& cacheDir, const std::string& scene, const std::vector<Shot>& shots) {
    setenv("MESA_SHADER_CACHE_DIR", cacheDir.c_str(), 1);
    unsetenv("MESA_SHADER_CACHE_DISABLE");
    GpuContext ctx;
    createValidatedContext(ctx);
    if (ctx.device == VK_NULL_HANDLE) return {};
    const std::string device = ctx.properties.deviceName;
    {
        FieldSequence sequence(ctx, scene, {320, 180});
        for (size_t i = 0; i < shots.size(); ++i) {
            FieldView view;
            view.camera = shots[i].camera;
            view.time = shots[i].time;
            view.firstFrame = i == 0;
            view.deltaTime = i == 0 ? 0.0f : shots[i].time - shots[i - 1].time;
            sequence.frame(view);
        }
    }
    destroyValidatedContext(ctx);
    return device;
}

struct Tour {
    const char* scene;
    glm::vec3 target;
};

void PrintTo(const Tour& tour, std::ostream* out) { *out << tour.scene; }

class ShaderVariantsTest : public testing::TestWithParam<Tour> {};

TEST_P(ShaderVariantsTest, FramesFromNewCamerasAndTimesCompileNoShader) {
    const Tour& scene = GetParam();
    const fs::path cache = fs::path(PLANTFIELD_TEST_OUTPUT_DIR) / ("shader_variants_cache_" + std::string(scene.scene));
    fs::remove_all(cache);
    // Mesa makes only the cache's last folder: a fresh build has no output folder yet.
    fs::create_directories(cache.parent_path());
    if (renderTour(cache, scene.scene, tour(0.0f, 0.0f, scene.target)).find("llvmpipe") == std::string::npos)
        GTEST_SKIP() << "the shader variants checked are lavapipe's";
    const size_t warm = cachedShaders(cache);
    ASSERT_GT(warm, 0u) << "lavapipe wrote no shader to " << cache << ": its disk cache is off";
    // A whole second later, physics takes the same sub-steps in the same
    // dispatches: the pipelines of each sub-step count (physics_pass.h) are
    // the ones already compiled.
    renderTour(cache, scene.scene, tour(0.01f, 1.0f, scene.target));
    EXPECT_EQ(cachedShaders(cache), warm) << "the same tour a centimetre away and a second later compiled new shader "
                                             "variants";
}

// The plant field, and the cloud of test_clouds.json (the cloud pass) seen from below.
INSTANTIATE_TEST_SUITE_P(Scenes, ShaderVariantsTest,
                         testing::Values(Tour{"test_clusters.json", {0.0f, 3.0f, 0.0f}},
                                         Tour{"test_clouds.json", {0.0f, 70.0f, -150.0f}}),
                         [](const testing::TestParamInfo<Tour>& info) {
                             const std::string scene = info.param.scene;
                             return scene.substr(0, scene.find('.'));
                         });

} // namespace
} // namespace pf::test
