// The sun's shadow casters (engine/field/shadow_casters.h, shaders/shared/shadow_select.h):
// the GPU pass against its CPU reference, and on the CPU what the split
// between the cache and the frame guarantees.
#include "cull_fixture.h"
#include "engine/field/shadow_casters.h"
#include "shaders/shared/shadow_select.h"

#include <algorithm>
#include <map>
#include <set>

namespace pf::test {
namespace {

constexpr float kRadius = 60.0f;
constexpr uint32_t kTexels = 1024;
constexpr float kDepthRadius = 250.0f;

// The sun at 38° elevation from the south-east, as in the default scene.
const glm::vec3 kSun = glm::normalize(glm::vec3(0.505f, 0.616f, 0.602f));

ShadowView shadowViewOf(const View& v, const glm::vec3& sun, uint32_t forcedLod) {
    const glm::vec3 forward = glm::normalize(glm::vec3(v.target.x - v.position.x, 0, v.target.z - v.position.z));
    ShadowView s;
    s.square = sunSquareAround(sun, v.position + forward * (0.6f * kRadius), kRadius, kTexels);
    s.sunDirection = sun;
    s.camera = v.position;
    s.pixelsPerMetre = pixelsPerMetre(kFovY, kViewportHeight);
    s.forcedLod = forcedLod;
    return s;
}

// Both passes of a frame seen from `frame` whose cache was drawn from `cacheView`.
struct ShadowPasses {
    gpu::ShadowCullUniforms cache, frame;
};

ShadowPasses shadowPasses(const View& cacheView, const View& frameView, const glm::vec3& sun = kSun,
                          uint32_t forcedLod = LOD_NOT_FORCED) {
    const ShadowCacheSettings settings;
    const ShadowView cache =
        shadowCacheFor(shadowViewOf(cacheView, sun, forcedLod), shadowCacheMargin(settings, 2 * kRadius / kTexels));
    const ShadowView frame = shadowViewOf(frameView, sun, forcedLod);
    EXPECT_TRUE(shadowCacheServes(cache, frame, settings));
    SunSquare square = frame.square;
    square.depth = cache.square.depth;
    return {makeShadowCullUniforms(sunViewProjection(cache.square, kDepthRadius), viewProj(frameView), frame, cache,
                                   settings, SHADOW_CULL_CACHE),
            makeShadowCullUniforms(sunViewProjection(square, kDepthRadius), viewProj(frameView), frame, cache, settings,
                                   SHADOW_CULL_FRAME)};
}

// True when float rounding could flip a decision of either pass: the sphere
// grazing a plane of the box or the view, or its projected height (from the
// camera, or the bounds the cache takes) within a hair of a threshold.
bool ambiguous(const gpu::FieldInstance& inst, const gpu::PlantModel& model, const gpu::ShadowCullUniforms& u) {
    const ExactSphere s = exactSphere(inst, model);
    for (const glm::vec4* planes : {u.box, u.view})
        for (int i = 0; i < 6; ++i)
            if (grazesPlane(s, planes[i])) return true;
    const double toCache = glm::distance(glm::dvec3(u.cacheCamera), s.centre), reach = u.cacheCamera.w;
    std::vector<double> pixels = {2.0 * s.radius * u.camera.w / glm::distance(glm::dvec3(u.camera), s.centre)};
    for (double scale : {u.cachePixels.x, u.cachePixels.y})
        for (double d : {toCache - reach, toCache + reach})
            pixels.push_back(2.0 * s.radius * scale / std::max(d, 0.001));
    for (double p : pixels)
        for (double threshold : {model.lod.x, model.lod.y, model.boxMax.w})
            if (nearBoundary(p, threshold)) return true;
    return false;
}

const View kAhead{{2.0f, 2.2f, 5.5f}, {2.0f, 2.0f, 6.5f}}; // 5.9 m on: one the cache still serves

// Random instances unambiguous in both passes of every case, the last
// model hidden below 8 pixels.
Field shadowField(uint32_t n, uint32_t seed, const std::vector<ShadowPasses>& cases) {
    std::vector<gpu::PlantModel> models = makeModels();
    models.back().boxMax.w = 8.0f;
    std::vector<gpu::FieldInstance> instances = randomInstances(n, seed, [&](const gpu::FieldInstance& inst) {
        return std::none_of(cases.begin(), cases.end(), [&](const ShadowPasses& c) {
            return ambiguous(inst, models[inst.ids.x], c.cache) || ambiguous(inst, models[inst.ids.x], c.frame);
        });
    });
    return layOut(std::move(instances), std::move(models));
}

size_t entriesOfLod(const std::vector<std::vector<uint32_t>>& lists, uint32_t lod) {
    size_t n = 0;
    for (size_t l = lod; l < lists.size(); l += LOD_COUNT) n += lists[l].size();
    return n;
}

TEST_F(CullPassTest, ShadowCastersOnTheGpuEqualTheCpuReference) {
    const std::vector<ShadowPasses> cases = {shadowPasses(kStart, kStart), shadowPasses(kStart, kAhead),
                                             shadowPasses(kMoved, kMoved)};
    const Field f = shadowField(20000, 11, cases);
    create(f, CullKind::ShadowCasters);
    for (size_t c = 0; c < cases.size(); ++c)
        for (const gpu::ShadowCullUniforms& u : {cases[c].cache, cases[c].frame}) {
            const GpuFrame gpuFrame = run(u);
            const CpuCullResult cpu = shadowCastersOnCpu(f.instances, f.models, u);
            ASSERT_EQ(gpuFrame.lists.size(), cpu.lists.size());
            for (size_t l = 0; l < cpu.lists.size(); ++l)
                EXPECT_EQ(gpuFrame.lists[l], cpu.lists[l])
                    << "case " << c << " mode " << u.counts.w << " model " << l / LOD_COUNT << " LOD " << l % LOD_COUNT;
            // Meshes only for LOD0, impostors for everything else: no
            // reduced caster without a forced LOD.
            EXPECT_GT(entriesOfLod(cpu.lists, LOD_IMPOSTOR), u.counts.w == SHADOW_CULL_CACHE ? 100u : 10u);
            EXPECT_EQ(entriesOfLod(cpu.lists, LOD_FULL) > 10u, u.counts.w == SHADOW_CULL_FRAME);
            EXPECT_EQ(entriesOfLod(cpu.lists, LOD_REDUCED), 0u);
        }
}

// Every caster the frame draws casts its mesh exactly when the camera sees
// it at LOD0, and its impostor otherwise, among them more than ten plants
// the camera draws at LOD1 (so the test fails if reduced trees cast their
// reduced meshes). Those it draws at LOD2 the cache holds.
TEST(ShadowCasters, FrameCastersAreMeshesAtLod0AndImpostorsElsewhere) {
    const ShadowPasses passes = shadowPasses(kStart, kStart);
    const Field f = shadowField(20000, 13, {passes});
    const gpu::ShadowCullUniforms& u = passes.frame;
    std::array<size_t, LOD_COUNT> cameraLods{};
    const CpuCullResult frame = shadowCastersOnCpu(f.instances, f.models, u);
    for (size_t l = 0; l < frame.lists.size(); ++l)
        for (uint32_t entry : frame.lists[l]) {
            const gpu::FieldInstance& inst = f.instances[entry & VISIBLE_INDEX_MASK];
            const gpu::PlantModel& model = f.models[inst.ids.x];
            const float pixels = gpu::projectedPixels(gpu::instanceSphere(inst, model), u.camera);
            const uint32_t seen = gpu::lodForPixels(pixels, model.lod.x, model.lod.y);
            ++cameraLods[seen];
            EXPECT_EQ(l % LOD_COUNT, seen == LOD_FULL ? LOD_FULL : LOD_IMPOSTOR) << "camera LOD " << seen;
        }
    EXPECT_GT(cameraLods[LOD_FULL], 10u);
    EXPECT_GT(cameraLods[LOD_REDUCED], 10u);
}

// A forced LOD casts as forced: reduced meshes only when LOD1 is forced,
// and then the cache (which holds impostors) holds nothing.
TEST(ShadowCasters, AForcedLodCastsAsForced) {
    for (uint32_t forced : {uint32_t(LOD_FULL), uint32_t(LOD_REDUCED), uint32_t(LOD_IMPOSTOR)}) {
        const ShadowPasses passes = shadowPasses(kStart, kStart, kSun, forced);
        const Field f = shadowField(5000, 14, {passes});
        const CpuCullResult cache = shadowCastersOnCpu(f.instances, f.models, passes.cache);
        const CpuCullResult frame = shadowCastersOnCpu(f.instances, f.models, passes.frame);
        for (uint32_t lod = 0; lod < LOD_COUNT; ++lod) {
            EXPECT_EQ(entriesOfLod(frame.lists, lod) > 0u, lod == forced && forced != LOD_IMPOSTOR)
                << "forced " << forced << " LOD " << lod;
            EXPECT_EQ(entriesOfLod(cache.lists, lod) > 0u, lod == forced && forced == LOD_IMPOSTOR)
                << "forced " << forced << " LOD " << lod;
        }
    }
}

// The casters whose shadow may fall in the frame's view, each with the LOD
// it is drawn at: those the cache holds (inside the frame's box) and those
// the frame draws. Fails the test if a plant is drawn by both.
std::map<uint32_t, uint32_t> castersInView(const Field& f, const ShadowPasses& passes) {
    std::map<uint32_t, uint32_t> lodOf;
    const CpuCullResult cache = shadowCastersOnCpu(f.instances, f.models, passes.cache);
    const CpuCullResult frame = shadowCastersOnCpu(f.instances, f.models, passes.frame);
    const gpu::ShadowCullUniforms& u = passes.frame;
    for (const CpuCullResult* result : {&cache, &frame})
        for (size_t l = 0; l < result->lists.size(); ++l)
            for (uint32_t entry : result->lists[l]) {
                const uint32_t i = entry & VISIBLE_INDEX_MASK;
                const glm::vec4 sphere = gpu::instanceSphere(f.instances[i], f.models[f.instances[i].ids.x]);
                if (!gpu::sphereInFrustum(sphere, u.box[0], u.box[1], u.box[2], u.box[3], u.box[4], u.box[5]) ||
                    !gpu::shadowMayFallInView(sphere, u))
                    continue;
                EXPECT_TRUE(lodOf.emplace(i, uint32_t(l % LOD_COUNT)).second) << "plant " << i << " drawn twice";
            }
    return lodOf;
}

// A frame whose cache was drawn some metres back shows the same casters at
// the same LODs as one whose cache was drawn for itself.
TEST(ShadowCasters, TheCacheChangesNoCasterInView) {
    const std::vector<ShadowPasses> cases = {shadowPasses(kStart, kAhead), shadowPasses(kAhead, kAhead),
                                             shadowPasses(kAhead, kStart), shadowPasses(kStart, kStart)};
    const Field f = shadowField(20000, 12, cases);
    const std::map<uint32_t, uint32_t> aheadFromStart = castersInView(f, cases[0]);
    const std::map<uint32_t, uint32_t> aheadFromScratch = castersInView(f, cases[1]);
    EXPECT_EQ(aheadFromStart, aheadFromScratch);
    EXPECT_GT(aheadFromScratch.size(), 1000u);
    EXPECT_EQ(castersInView(f, cases[2]), castersInView(f, cases[3]));
}

// Camera at the origin looking along +z; the sun low in the west, so
// shadows fall toward +x. A plant left of the view casts into it; one right
// of it or behind the camera casts away from it.
TEST(ShadowCasters, PlantsOutOfViewCastWhenTheirShadowFallsInIt) {
    std::vector<gpu::PlantModel> models = makeModels();
    models.resize(1); // a unit sphere 1 m above its base
    const Field f = layOut({makeInstance({-9.0f, 0.0f, 5.0f}, 0, 1, 0), makeInstance({9.0f, 0.0f, 5.0f}, 0, 1, 0),
                            makeInstance({0.0f, 0.0f, -10.0f}, 0, 1, 0), makeInstance({0.0f, 0.0f, 10.0f}, 0, 1, 0)},
                           std::move(models));
    const glm::vec3 west = glm::normalize(glm::vec3(-1.0f, 0.8f, 0.0f));
    const ShadowPasses passes = shadowPasses(kStart, kStart, west);
    const std::array<glm::vec4, 6> view = frustumPlanes(viewProj(kStart));
    for (uint32_t i = 0; i < 3; ++i)
        ASSERT_FALSE(gpu::sphereInFrustum(gpu::instanceSphere(f.instances[i], f.models[0]), view[0], view[1], view[2],
                                          view[3], view[4], view[5]))
            << "plant " << i << " should be out of view";
    std::set<uint32_t> casters;
    for (const std::vector<uint32_t>& list : shadowCastersOnCpu(f.instances, f.models, passes.frame).lists)
        for (uint32_t entry : list) casters.insert(entry & VISIBLE_INDEX_MASK);
    EXPECT_EQ(casters, (std::set<uint32_t>{0, 3}));
}

} // namespace
} // namespace pf::test
