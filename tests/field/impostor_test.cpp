// The impostor atlas bake (engine/field/impostor_atlas.h) on a hand-built model: a
// vertical bark cylinder, capped at the top, and a leaf card sticking out along +x, so frames
// differ with azimuth; read back and checked pixel by pixel.
#include "engine/field/impostor_atlas.h"
#include "engine/image/image.h"
#include "engine/vk/vk_check.h"
#include "gpu_test.h"
#include "shaders/shared/impostor_frame.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <vector>

namespace {

using namespace pf;

constexpr float kRadius = 0.1f; // cylinder around the y axis, y 0 … 2
constexpr float kHeight = 2.0f;
constexpr uint32_t kSides = 64;
constexpr float kLeafX0 = 0.1f, kLeafX1 = 0.6f; // leaf card in the plane z = 0, petiole at x0
constexpr float kLeafY0 = 1.2f, kLeafY1 = 1.6f;
constexpr uint32_t kSize = 128;
constexpr uint32_t kFrames = 12;
constexpr float kSunElevation = 0.7f; // radians: the shadow frames' view

gpu::FieldVertex vertex(glm::vec3 p, glm::vec3 n, glm::vec2 uv, glm::vec3 albedo, float kind) {
    return {glm::vec4(p, uv.x), glm::vec4(n, uv.y), glm::vec4(albedo, kind), glm::uvec4(0)};
}

// Two models of the same geometry: a Triple and a Single billboard. The
// card is a leaf (cut by leafCutOut) or an uncut blade (`cardKind`).
PlantModelPool testPool(float cardKind = SURFACE_LEAF) {
    PlantModelPool pool;
    const glm::vec3 bark(0.40f, 0.25f, 0.10f);
    for (uint32_t i = 0; i <= kSides; ++i) {
        float a = glm::two_pi<float>() * float(i) / float(kSides);
        glm::vec3 n(std::cos(a), 0.0f, std::sin(a));
        for (float y : {0.0f, kHeight})
            pool.vertices.push_back(
                vertex(n * kRadius + glm::vec3(0, y, 0), n, {float(i) / kSides, y / kHeight}, bark, SURFACE_BARK));
    }
    for (uint32_t i = 0; i < kSides; ++i) {
        uint32_t a = 2 * i, b = 2 * i + 1, c = 2 * i + 2, d = 2 * i + 3;
        // Counter-clockwise seen from outside, as every mesh of the pool.
        glm::vec3 pa = pool.vertices[a].position, pb = pool.vertices[c].position, pc = pool.vertices[b].position;
        bool ccw = glm::dot(glm::cross(pb - pa, pc - pa), glm::vec3(pool.vertices[a].normal)) > 0.0f;
        for (uint32_t index : ccw ? std::vector<uint32_t>{a, c, b, b, c, d} : std::vector<uint32_t>{a, b, c, b, d, c})
            pool.indices.push_back(index);
    }
    // The top's cap, a fan counter-clockwise seen from above: the upper
    // rings look down on it.
    const uint32_t capCentre = uint32_t(pool.vertices.size());
    pool.vertices.push_back(vertex({0, kHeight, 0}, {0, 1, 0}, {0.5f, 1.0f}, bark, SURFACE_BARK));
    for (uint32_t i = 0; i < kSides; ++i) {
        const uint32_t a = 2 * i + 1, b = 2 * i + 3; // the rim at the top
        const glm::vec3 pa = pool.vertices[a].position, pb = pool.vertices[b].position;
        const bool ccw = glm::cross(pa - glm::vec3(0, kHeight, 0), pb - glm::vec3(0, kHeight, 0)).y > 0.0f;
        for (uint32_t index : ccw ? std::vector<uint32_t>{capCentre, a, b} : std::vector<uint32_t>{capCentre, b, a})
            pool.indices.push_back(index);
    }
    MeshRange barkRange{0, uint32_t(pool.indices.size()), 0};

    const glm::vec3 leaf(0.15f, 0.50f, 0.10f);
    MeshRange leafRange{uint32_t(pool.indices.size()), 6, uint32_t(pool.vertices.size())};
    // uv: u across the card (y), v from the petiole (x0) to the tip (x1).
    for (glm::vec2 c : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1), glm::vec2(0, 1)})
        pool.vertices.push_back(vertex({kLeafX0 + c.y * (kLeafX1 - kLeafX0), kLeafY0 + c.x * (kLeafY1 - kLeafY0), 0.0f},
                                       {0, 0, 1}, c, leaf, cardKind));
    // Counter-clockwise seen from +z, the side its normal faces.
    for (uint32_t i : {0u, 2u, 1u, 0u, 3u, 2u}) pool.indices.push_back(i);

    for (BillboardKind kind : {BillboardKind::Triple, BillboardKind::Single}) {
        PlantModelInfo model;
        model.name = "test#" + std::to_string(pool.models.size());
        model.meshes[LOD_FULL] = {barkRange, leafRange};
        model.meshes[LOD_REDUCED] = {barkRange, leafRange};
        model.gpu.boxMin = {-kRadius, 0.0f, -kRadius, 0.0f};
        model.gpu.boxMax = {kLeafX1, kHeight, kRadius, 0.0f};
        model.billboard = kind;
        pool.models.push_back(model);
    }
    pool.firstModel = {0};
    return pool;
}

// Mip `level` of every layer, tightly packed, `texelBytes` a texel.
std::vector<uint8_t> readLayers(const GpuContext& ctx, const Image& image, uint32_t layers, uint32_t level,
                                uint32_t texelBytes = 4) {
    const uint32_t size = std::max(image.extent.width >> level, 1u);
    GpuResources scratch(ctx);
    Buffer readback =
        createHostBuffer(scratch, VkDeviceSize(size) * size * texelBytes * layers, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    submitAndWait(ctx, [&](VkCommandBuffer cmd) {
        auto barrier = [&](VkImageLayout from, VkImageLayout to, VkPipelineStageFlags2 src, VkAccessFlags2 srcAccess,
                           VkPipelineStageFlags2 dst, VkAccessFlags2 dstAccess) {
            const VkImageMemoryBarrier2 b =
                imageMemoryBarrier(image.image, {VK_IMAGE_ASPECT_COLOR_BIT, level, 1, 0, layers},
                                   {src, srcAccess, dst, dstAccess, from, to});
            VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
            dep.imageMemoryBarrierCount = 1;
            dep.pImageMemoryBarriers = &b;
            vkCmdPipelineBarrier2(cmd, &dep);
        };
        // The bake left the atlas for fragment shaders; copy, then give it back.
        barrier(VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COPY_BIT,
                VK_ACCESS_2_TRANSFER_READ_BIT);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, layers};
        region.imageExtent = {size, size, 1};
        vkCmdCopyImageToBuffer(cmd, image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.buffer, 1, &region);
        barrier(VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    });
    std::vector<uint8_t> out(readback.size);
    std::memcpy(out.data(), readback.mapped, out.size());
    return out;
}

struct Frame {
    const uint8_t* texels; // kSize² RGBA
    const uint8_t* at(uint32_t x, uint32_t y) const { return texels + (size_t(y) * kSize + x) * 4; }
    uint8_t alpha(uint32_t x, uint32_t y) const { return at(x, y)[3]; }
    bool covered(uint32_t x, uint32_t y) const { return alpha(x, y) >= 128; }
};

class ImpostorTest : public pf::test::GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        usePool(testPool());
    }
    void usePool(PlantModelPool p) {
        pool = std::move(p);
        vertices =
            createDeviceBufferWithData(resources, pool.vertices.data(), pool.vertices.size() * sizeof(gpu::FieldVertex),
                                       VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        indices = createDeviceBufferWithData(resources, pool.indices.data(), pool.indices.size() * sizeof(uint32_t),
                                             VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    }
    void bake() {
        auto start = std::chrono::steady_clock::now();
        atlas = bakeImpostorAtlas(resources, pool, vertices, indices, kSunElevation, {kSize, kFrames});
        bakeSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        color = readLayers(ctx, atlas.color, atlas.layers, 0);
        normal = readLayers(ctx, atlas.normalDepth, atlas.layers, 0);
    }
    Frame colorFrame(uint32_t layer) const { return {color.data() + size_t(layer) * kSize * kSize * 4}; }
    Frame normalFrame(uint32_t layer) const { return {normal.data() + size_t(layer) * kSize * kSize * 4}; }

    // Column of plant-space point p in frame f, row of height y.
    float column(glm::vec3 p, uint32_t f) const {
        float halfWidth = pool.models[0].gpu.impostorQuad.x;
        return (glm::dot(p, gpu::impostorFrameRight(gpu::impostorFrameAzimuth(f, kFrames))) / halfWidth * 0.5f + 0.5f) *
               kSize;
    }
    static float row(float y) { return (1.0f - y / kHeight) * kSize; }

    PlantModelPool pool;
    Buffer vertices, indices;
    ImpostorAtlas atlas;
    std::vector<uint8_t> color, normal;
    double bakeSeconds = 0.0;
};

TEST_F(ImpostorTest, WritesImpostorAndQuadFieldsOfEveryModel) {
    bake();
    EXPECT_EQ(atlas.layers, 2 * kFrames * IMPOSTOR_RINGS);
    EXPECT_EQ(atlas.shadowLayers, 2 * kFrames);
    EXPECT_EQ(atlas.mipLevels, 8u);
    EXPECT_EQ(pool.models[0].gpu.impostor, glm::uvec4(0, kFrames, 3, 0));
    EXPECT_EQ(pool.models[1].gpu.impostor, glm::uvec4(kFrames * IMPOSTOR_RINGS, kFrames, 1, kFrames));
    const float radius = std::sqrt(kLeafX1 * kLeafX1 + kRadius * kRadius);
    for (const PlantModelInfo& model : pool.models) {
        EXPECT_NEAR(model.gpu.impostorQuad.x, radius, 1e-6f);
        EXPECT_EQ(model.gpu.impostorQuad.y, 0.0f);
        EXPECT_EQ(model.gpu.impostorQuad.z, kHeight);
        EXPECT_NEAR(model.gpu.impostorQuad.w, radius, 1e-6f);
    }
    std::printf("bake of %u layers of %upx: %.3f s\n", atlas.layers, kSize, bakeSeconds);
}

TEST_F(ImpostorTest, CoverageIsNonEmptyAndInsideTheProjectedBox) {
    bake();
    for (uint32_t f = 0; f < kFrames; ++f) {
        Frame frame = colorFrame(f);
        // The box's extent along this frame's right axis, in columns.
        float lo = kSize, hi = 0.0f;
        for (float x : {-kRadius, kLeafX1})
            for (float z : {-kRadius, kRadius}) {
                lo = std::min(lo, column({x, 0, z}, f));
                hi = std::max(hi, column({x, 0, z}, f));
            }
        uint32_t covered = 0, top = kSize, bottom = 0;
        for (uint32_t y = 0; y < kSize; ++y)
            for (uint32_t x = 0; x < kSize; ++x) {
                if (frame.alpha(x, y) == 0) continue;
                EXPECT_GE(float(x) + 1.0f, lo - 1.0f) << "frame " << f << " texel " << x << "," << y;
                EXPECT_LE(float(x), hi + 1.0f) << "frame " << f << " texel " << x << "," << y;
                if (!frame.covered(x, y)) continue;
                ++covered;
                top = std::min(top, y);
                bottom = std::max(bottom, y);
            }
        EXPECT_GT(covered, 0u) << "frame " << f;
        // The cylinder spans the box's full height.
        EXPECT_LE(top, 1u) << "frame " << f;
        EXPECT_GE(bottom, kSize - 2) << "frame " << f;
    }
}

TEST_F(ImpostorTest, FrameFrom90DegreesDiffersFrom0) {
    bake();
    Frame front = colorFrame(0), side = colorFrame(kFrames / 4);
    uint32_t covered = 0, differing = 0;
    for (uint32_t y = 0; y < kSize; ++y)
        for (uint32_t x = 0; x < kSize; ++x) {
            covered += front.covered(x, y);
            differing += front.covered(x, y) != side.covered(x, y);
        }
    // The leaf card, seen face on at 0°, is edge-on at 90°.
    EXPECT_GT(differing, covered / 10) << covered << " covered at 0°";
}

TEST_F(ImpostorTest, LeafShowsLeafColorFromBothSidesWithNormalsFacingTheView) {
    bake();
    const glm::vec3 leafCentre(0.5f * (kLeafX0 + kLeafX1), 0.5f * (kLeafY0 + kLeafY1), 0.0f);
    for (uint32_t f : {0u, kFrames / 2}) {
        uint32_t x = uint32_t(column(leafCentre, f)), y = uint32_t(row(leafCentre.y));
        const uint8_t* c = colorFrame(f).at(x, y);
        EXPECT_EQ(c[3], 255) << "frame " << f;
        EXPECT_GT(c[1], c[0] + 40) << "frame " << f;
        EXPECT_GT(c[1], c[2] + 40) << "frame " << f;
        // Plant-space normal +z seen from the front, -z from behind.
        const uint8_t* n = normalFrame(f).at(x, y);
        EXPECT_NEAR(n[0], 128, 2) << "frame " << f;
        EXPECT_NEAR(n[1], 128, 2) << "frame " << f;
        EXPECT_NEAR(n[2], f == 0 ? 255 : 0, 2) << "frame " << f;
        // Depth: the card lies in the plane through the axis, mid-box.
        EXPECT_NEAR(n[3], 128, 2) << "frame " << f;
    }
    // Bark below the leaf: brown, red above blue.
    const uint8_t* bark = colorFrame(0).at(kSize / 2, uint32_t(row(0.5f)));
    EXPECT_EQ(bark[3], 255);
    EXPECT_GT(bark[0], bark[2] + 40);
}

TEST_F(ImpostorTest, CylinderSilhouetteHasTheExpectedWidth) {
    bake();
    const float expected = 2.0f * kRadius / (2.0f * pool.models[0].gpu.impostorQuad.x) * kSize;
    for (uint32_t f = 0; f < kFrames; ++f) {
        Frame frame = colorFrame(f);
        uint32_t y = uint32_t(row(0.5f)), width = 0;
        for (uint32_t x = 0; x < kSize; ++x) width += frame.covered(x, y);
        EXPECT_NEAR(float(width), expected, 2.0f) << "frame " << f;
    }
}

TEST_F(ImpostorTest, MipsKeepTheCoverage) {
    bake();
    const uint32_t level = 3, side = kSize >> level;
    std::vector<uint8_t> mip = readLayers(ctx, atlas.color, atlas.layers, level);
    for (uint32_t f = 0; f < kFrames; ++f) {
        double full = 0.0, small = 0.0;
        for (size_t i = 0; i < size_t(kSize) * kSize; ++i) full += colorFrame(f).texels[i * 4 + 3];
        for (size_t i = 0; i < size_t(side) * side; ++i) small += mip[(size_t(f) * side * side + i) * 4 + 3];
        EXPECT_NEAR(small * 64.0 / full, 1.0, 0.05) << "frame " << f;
    }
}

// Every texel with any coverage at full size, and every texel of the mip
// the outline was read from, lies inside its layer's outline; and the
// outlines are much smaller than the frames (a cylinder with one leaf).
TEST_F(ImpostorTest, OutlinesHoldAllCoverageAndCutTheEmptyFrame) {
    bake();
    ASSERT_EQ(atlas.outlines.size(), atlas.layers);
    double area = 0.0;
    for (uint32_t layer = 0; layer < atlas.layers; ++layer) {
        const ImpostorOutline& o = atlas.outlines[layer];
        auto inside = [&](glm::vec2 p) {
            bool positive = false, negative = false;
            for (size_t i = 0; i < o.size(); ++i) {
                const glm::vec2 a = o[i], b = o[(i + 1) % o.size()];
                const float s = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
                positive |= s > 1e-5f;
                negative |= s < -1e-5f;
            }
            return !(positive && negative);
        };
        const Frame frame = colorFrame(layer);
        for (uint32_t y = 0; y < kSize; ++y) {
            for (uint32_t x = 0; x < kSize; ++x) {
                if (frame.alpha(x, y) == 0) continue;
                ASSERT_TRUE(inside((glm::vec2(x, y) + 0.5f) / float(kSize)))
                    << "layer " << layer << " texel " << x << "," << y;
            }
        }
        area += outlineArea(o);
    }
    area /= atlas.layers;
    std::printf("mean outline area: %.2f of the frame\n", area);
    EXPECT_LT(area, 0.8);
    EXPECT_GT(area, 0.05);
}

// The mesh seen from a frame's azimuth and an elevation (the sun's or a
// ring's), per texel (row 0 at the top): the share covered, and where all
// of it is, the mean depth of the surface nearest the view (0 at the
// frame's front, 1 at its back), else -1.
struct MeshView {
    std::vector<float> coverage, nearest;
};

// The CPU reference: every triangle of the LOD0 meshes projected along the
// view onto the frame's plane and rasterised at `kSub`² points a texel, the
// frame's axes and extents derived here from the view direction alone.
MeshView meshViewOnCpu(const PlantModelPool& pool, uint32_t frame, float elevation, uint32_t size) {
    constexpr uint32_t kSub = 4;
    const gpu::PlantModel& model = pool.models[0].gpu;
    const float a = glm::two_pi<float>() * float(frame) / float(kFrames);
    const glm::vec3 toSun(std::sin(a) * std::cos(elevation), std::sin(elevation), std::cos(a) * std::cos(elevation));
    const glm::vec3 right = glm::normalize(glm::cross(glm::vec3(0, 1, 0), toSun));
    const glm::vec3 up = glm::cross(toSun, right);
    const glm::vec3 centre(0.0f, 0.5f * (model.boxMin.y + model.boxMax.y), 0.0f);
    // Half extents: the cylinder about the axis holding the box, projected.
    const float radius = model.impostorQuad.x;
    glm::vec3 half(radius, 0.0f, 0.0f);
    for (uint32_t i = 0; i < 360; ++i)
        for (float y : {model.boxMin.y, model.boxMax.y}) {
            const float b = glm::radians(float(i));
            const glm::vec3 p(radius * std::cos(b), y, radius * std::sin(b));
            half.y = std::max(half.y, std::abs(glm::dot(p - centre, up)));
            half.z = std::max(half.z, std::abs(glm::dot(p - centre, toSun)));
        }
    auto toGrid = [&](glm::vec3 p) {
        const glm::vec2 q(glm::dot(p - centre, right) / half.x, glm::dot(p - centre, up) / half.y);
        return glm::vec2(q.x * 0.5f + 0.5f, 0.5f - q.y * 0.5f) * float(size * kSub);
    };
    const uint32_t n = size * kSub;
    // Per point, the depth of the nearest surface (2 where none).
    std::vector<float> hit(size_t(n) * n, 2.0f);
    for (const MeshRange& mesh : pool.models[0].meshes[LOD_FULL]) {
        for (uint32_t t = 0; t < mesh.indexCount; t += 3) {
            glm::vec2 v[3];
            float depth[3];
            for (uint32_t k = 0; k < 3; ++k) {
                const glm::vec3 p = pool.vertices[mesh.vertexOffset + pool.indices[mesh.firstIndex + t + k]].position;
                v[k] = toGrid(p);
                depth[k] = 0.5f - 0.5f * glm::dot(p - centre, toSun) / half.z;
            }
            const float area = (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[1].y - v[0].y) * (v[2].x - v[0].x);
            if (std::abs(area) < 1e-9f) continue;
            const glm::vec2 lo = glm::max(glm::min(glm::min(v[0], v[1]), v[2]), glm::vec2(0.0f));
            const glm::vec2 hi = glm::min(glm::max(glm::max(v[0], v[1]), v[2]), glm::vec2(float(n)));
            for (uint32_t y = uint32_t(lo.y); y < uint32_t(std::ceil(hi.y)); ++y)
                for (uint32_t x = uint32_t(lo.x); x < uint32_t(std::ceil(hi.x)); ++x) {
                    const glm::vec2 p(float(x) + 0.5f, float(y) + 0.5f);
                    bool inside = true;
                    float z = 0.0f;
                    for (uint32_t k = 0; k < 3; ++k) {
                        const glm::vec2 e0 = v[k], e1 = v[(k + 1) % 3];
                        const float s = (e1.x - e0.x) * (p.y - e0.y) - (e1.y - e0.y) * (p.x - e0.x);
                        inside &= area > 0.0f ? s >= 0.0f : s <= 0.0f;
                        z += s / area * depth[(k + 2) % 3]; // the edge's share weighs the opposite vertex
                    }
                    float& nearest = hit[size_t(y) * n + x];
                    if (inside) nearest = std::min(nearest, z);
                }
        }
    }
    MeshView view{std::vector<float>(size_t(size) * size, 0.0f), std::vector<float>(size_t(size) * size, 0.0f)};
    for (uint32_t y = 0; y < n; ++y)
        for (uint32_t x = 0; x < n; ++x) {
            const float nearest = hit[size_t(y) * n + x];
            const size_t texel = size_t(y / kSub) * size + x / kSub;
            view.coverage[texel] += nearest <= 1.0f ? 1.0f / float(kSub * kSub) : 0.0f;
            view.nearest[texel] += nearest / float(kSub * kSub);
        }
    for (size_t t = 0; t < view.coverage.size(); ++t)
        if (view.coverage[t] < 1.0f) view.nearest[t] = -1.0f;
    return view;
}

// Each shadow frame's coverage matches the mesh's seen from the sun at its
// azimuth (the card uncut, so the CPU can rasterise it exactly): the texels'
// differences summed stay within 2% of the covered area (the 4× MSAA
// samples and the CPU's 16 points a texel disagree along the silhouette;
// measured 0.4%), while a frame seen from the horizon instead (the
// billboards' side view that the shadows used before) differs by over 40%.
TEST_F(ImpostorTest, ShadowFramesCoverWhatTheMeshCoversSeenFromTheSun) {
    usePool(testPool(SURFACE_BLADE));
    bake();
    const uint32_t size = atlas.shadow.extent.width;
    ASSERT_EQ(size, ImpostorSettings{}.shadowFrameSize);
    EXPECT_EQ(atlas.shadowMipLevels, 8u);
    const std::vector<uint8_t> shadow = readLayers(ctx, atlas.shadow, atlas.shadowLayers, 0, 2);
    double worst = 0.0, leastFromHorizon = 1e9;
    for (uint32_t f = 0; f < kFrames; ++f) {
        const std::vector<float> fromSun = meshViewOnCpu(pool, f, kSunElevation, size).coverage;
        const std::vector<float> fromHorizon = meshViewOnCpu(pool, f, 0.0f, size).coverage;
        double area = 0.0, baked = 0.0, error = 0.0, horizonError = 0.0;
        for (size_t t = 0; t < fromSun.size(); ++t) {
            const double g = shadow[(size_t(f) * size * size + t) * 2] / 255.0;
            area += fromSun[t];
            baked += g;
            error += std::abs(g - fromSun[t]);
            horizonError += std::abs(g - fromHorizon[t]);
        }
        ASSERT_GT(area, 100.0) << "frame " << f;
        EXPECT_NEAR(baked / area, 1.0, 0.02) << "frame " << f;
        EXPECT_LT(error / area, 0.02) << "frame " << f;
        EXPECT_GT(horizonError / area, 0.3) << "frame " << f;
        worst = std::max(worst, error / area);
        leastFromHorizon = std::min(leastFromHorizon, horizonError / area);
    }
    std::printf("shadow frames against the CPU: at most %.3f of the area differs (from the horizon: at least %.3f)\n",
                worst, leastFromHorizon);
}

// Each colour frame of every ring covers what the mesh covers seen from
// the ring's elevation at the frame's azimuth (the card uncut): within 2% of
// the covered area, as the shadow frames (measured 0.3%); the upper rings'
// frames differ from the horizon's view of the same azimuth by over 20%
// (measured 29% and more), since a plant seen from above is what their
// billboards must show.
TEST_F(ImpostorTest, RingFramesCoverWhatTheMeshCoversSeenFromTheirElevation) {
    usePool(testPool(SURFACE_BLADE));
    bake();
    double worst = 0.0;
    for (uint32_t ring = 0; ring < IMPOSTOR_RINGS; ++ring)
        for (uint32_t f = 0; f < kFrames; f += 3) {
            const float elevation = gpu::impostorRingElevation(ring);
            const std::vector<float> seen = meshViewOnCpu(pool, f, elevation, kSize).coverage;
            const std::vector<float> fromHorizon = meshViewOnCpu(pool, f, 0.0f, kSize).coverage;
            const Frame frame = colorFrame(ring * kFrames + f);
            double area = 0.0, error = 0.0, horizonError = 0.0;
            for (size_t t = 0; t < seen.size(); ++t) {
                const double baked = frame.texels[t * 4 + 3] / 255.0;
                area += seen[t];
                error += std::abs(baked - seen[t]);
                horizonError += std::abs(baked - fromHorizon[t]);
            }
            ASSERT_GT(area, 100.0) << "ring " << ring << " frame " << f;
            EXPECT_LT(error / area, 0.02) << "ring " << ring << " frame " << f;
            if (ring > 0) {
                EXPECT_GT(horizonError / area, 0.2) << "ring " << ring << " frame " << f;
            }
            worst = std::max(worst, error / area);
        }
    std::printf("ring frames against the CPU: at most %.3f of the area differs\n", worst);
}

// Where the mesh covers a whole texel, the shadow frame's depth is that of
// its surface nearest the sun: within 3/255 of the frame's depth (the
// bytes' step and the MSAA samples' positions against the CPU's 16 points)
// at 95% of those texels; the depth of the frame's centre there instead
// (the quad's own) is off by far more at most of them.
TEST_F(ImpostorTest, ShadowFramesHoldTheDepthNearestTheSun) {
    usePool(testPool(SURFACE_BLADE));
    bake();
    const uint32_t size = atlas.shadow.extent.width;
    const std::vector<uint8_t> shadow = readLayers(ctx, atlas.shadow, atlas.shadowLayers, 0, 2);
    std::vector<float> errors, centreErrors;
    for (uint32_t f = 0; f < kFrames; ++f) {
        const MeshView cpu = meshViewOnCpu(pool, f, kSunElevation, size);
        for (size_t t = 0; t < cpu.nearest.size(); ++t) {
            const uint8_t* texel = &shadow[(size_t(f) * size * size + t) * 2];
            if (cpu.nearest[t] < 0.0f || texel[0] != 255) continue;
            errors.push_back(std::abs(texel[1] / 255.0f - cpu.nearest[t]));
            centreErrors.push_back(std::abs(0.5f - cpu.nearest[t]));
        }
    }
    ASSERT_GT(errors.size(), 1000u);
    auto quantile = [](std::vector<float> v, double q) {
        std::sort(v.begin(), v.end());
        return v[size_t(q * double(v.size() - 1))];
    };
    const float p95 = quantile(errors, 0.95), centreMedian = quantile(centreErrors, 0.5);
    std::printf("shadow frames' depth: 95%% of %zu texels within %.4f (the centre's: median %.3f)\n", errors.size(),
                p95, centreMedian);
    EXPECT_LT(p95, 3.0f / 255.0f);
    EXPECT_GT(centreMedian, 0.05f);
}

TEST_F(ImpostorTest, TwoBakesAreIdentical) {
    bake();
    std::vector<uint8_t> firstColor = color, firstNormal = normal;
    bake();
    EXPECT_TRUE(firstColor == color);
    EXPECT_TRUE(firstNormal == normal);
}

// The frames of the test model side by side for a person to look at: albedo
// over grey, normals, depth.
TEST_F(ImpostorTest, WritesTheAtlasOfATestModelToPng) {
    bake();
    RgbaImage png{kSize * kFrames, kSize * 3, {}};
    png.pixels.resize(size_t(png.width) * png.height * 4);
    for (uint32_t f = 0; f < kFrames; ++f)
        for (uint32_t y = 0; y < kSize; ++y)
            for (uint32_t x = 0; x < kSize; ++x) {
                const uint8_t* c = colorFrame(f).at(x, y);
                const uint8_t* n = normalFrame(f).at(x, y);
                const uint8_t background = uint8_t(96 * (255 - c[3]) / 255);
                const uint8_t rows[3][3] = {
                    {uint8_t(c[0] + background), uint8_t(c[1] + background), uint8_t(c[2] + background)},
                    {n[0], n[1], n[2]},
                    {n[3], n[3], n[3]}};
                for (uint32_t r = 0; r < 3; ++r) {
                    uint8_t* out = &png.pixels[((size_t(r) * kSize + y) * png.width + f * kSize + x) * 4];
                    std::memcpy(out, rows[r], 3);
                    out[3] = 255;
                }
            }
    const std::filesystem::path dir = std::filesystem::path(PLANTFIELD_TEST_OUTPUT_DIR) / "impostor_test";
    std::filesystem::create_directories(dir);
    writePng((dir / "test_model_atlas.png").string(), png);
    std::printf("wrote %s\n", (dir / "test_model_atlas.png").string().c_str());
}

TEST(BillboardMesh, AppendsOneToThreeOutlineFansWithTheirCorners) {
    PlantModelPool pool;
    pool.vertices.resize(5);
    pool.indices.resize(7);
    constexpr uint32_t kTriangles = kOutlineCorners - 2;
    for (uint32_t quads = 1; quads <= 3; ++quads) {
        const size_t verticesBefore = pool.vertices.size(), indicesBefore = pool.indices.size();
        MeshRange range = appendBillboardMesh(pool, quads);
        EXPECT_EQ(range.firstIndex, indicesBefore);
        EXPECT_EQ(range.vertexOffset, verticesBefore);
        EXPECT_EQ(range.indexCount, 3 * kTriangles * quads);
        ASSERT_EQ(pool.vertices.size(), verticesBefore + kOutlineCorners * quads);
        ASSERT_EQ(pool.indices.size(), indicesBefore + 3 * kTriangles * quads);
        for (uint32_t i = 0; i < range.indexCount; ++i) {
            const uint32_t index = pool.indices[range.firstIndex + i];
            ASSERT_LT(index, kOutlineCorners * quads);
            // Each triangle stays within its quad's fan, and every fan
            // triangle starts at the quad's corner 0.
            EXPECT_EQ(index / kOutlineCorners, i / (3 * kTriangles));
            if (i % 3 == 0) {
                EXPECT_EQ(index % kOutlineCorners, 0u);
            }
        }
        for (uint32_t v = 0; v < kOutlineCorners * quads; ++v) {
            const gpu::FieldVertex& vertex = pool.vertices[verticesBefore + v];
            EXPECT_EQ(vertex.position.x, float(v % kOutlineCorners)); // corner
            EXPECT_EQ(vertex.position.z, float(v / kOutlineCorners)); // quad
        }
    }
    EXPECT_THROW(appendBillboardMesh(pool, 0), std::runtime_error);
    EXPECT_THROW(appendBillboardMesh(pool, 4), std::runtime_error);
}

TEST(ImpostorFrames, Frame0LooksAlongMinusZWithPlusXRight) {
    const float quarter = gpu::impostorFrameAzimuth(3, 12);
    EXPECT_NEAR(glm::distance(gpu::impostorFrameToView(0.0f, 0.0f, 1.0f), glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(gpu::impostorFrameRight(0.0f), glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(gpu::impostorFrameToView(quarter, 0.0f, 1.0f), glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(gpu::impostorFrameRight(quarter), glm::vec3(0, 0, -1)), 0.0f, 1e-6f);
    // right × up = toward the viewer: a right-handed view, on every ring.
    for (uint32_t ring = 0; ring < IMPOSTOR_RINGS; ++ring)
        for (uint32_t f = 0; f < 12; ++f) {
            const float a = gpu::impostorFrameAzimuth(f, 12), e = gpu::impostorRingElevation(ring);
            const glm::vec3 up = gpu::impostorFrameUp(a, std::sin(e), std::cos(e));
            EXPECT_NEAR(glm::distance(glm::cross(gpu::impostorFrameRight(a), up),
                                      gpu::impostorFrameToView(a, std::sin(e), std::cos(e))),
                        0.0f, 1e-6f);
            EXPECT_NEAR(up.y, std::cos(e), 1e-6f) << "up tilts away from the view by the elevation";
        }
}

TEST(ImpostorFrames, ViewsTakeTheNearestRing) {
    EXPECT_EQ(gpu::impostorRingOf(-0.5f), 0u);
    EXPECT_EQ(gpu::impostorRingOf(glm::radians(14.0f)), 0u);
    EXPECT_EQ(gpu::impostorRingOf(glm::radians(16.0f)), 1u);
    EXPECT_EQ(gpu::impostorRingOf(glm::radians(44.0f)), 1u);
    EXPECT_EQ(gpu::impostorRingOf(glm::radians(46.0f)), 2u);
    EXPECT_EQ(gpu::impostorRingOf(glm::radians(90.0f)), IMPOSTOR_RINGS - 1);
}

} // namespace
