// cpfg's surface files (.s) read, placed and tessellated as cpfg's patches.c
// does. The expected numbers are cpfg's own: cpfg 6.6 run headless on a
// view file "surface: l leaf.s 1 4 3" and an L-system drawing ~l(1)@O,
// written with -ray (its triangles' points and normals, and the sphere
// where ~l leaves the turtle), printed with 6 significant digits.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <glm/geometric.hpp>

#include "lsystem/vlab/surface_file.h"

namespace lsys::vlab {
namespace {

// A surface file in a fresh temporary folder, removed with it.
struct TempSurface {
    std::filesystem::path folder;
    std::filesystem::path path;
    explicit TempSurface(const std::string& text)
        : folder(std::filesystem::temp_directory_path() /
                 ("plantfield_surface_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()))),
          path(folder / "leaf.s") {
        std::filesystem::create_directories(folder);
        std::ofstream(path, std::ios::binary) << text;
    }
    ~TempSurface() { std::filesystem::remove_all(folder); }
};

// vlab's cpfg/leaf.s: two curved patches, Patch_2 below Patch_1, tilted
// heading and up vectors.
const char* const kLeaf = "-44.89 44.89   -18.16 105.59   -23.99 29.64\n"
                          "PRECISION S: 5 T: 5\n"
                          "CONTACT POINT  X: 0.21 Y: -1.55 Z: -37.04\n"
                          "END POINT  X: 6.41 Y: 31.51 Z: 22.83\n"
                          "HEADING  X: 0.00 Y: 0.83 Z: 0.55\n"
                          "UP  X: 0.00 Y: 0.55 Z: -0.83\n"
                          "SIZE: 122.040001\n"
                          "Patch_1\n"
                          "TOP COLOR: 16 DIFFUSE: 0.00 BOTTOM COLOR: 16 DIFFUSE: 0.00\n"
                          "AL: ~ A: ~ AR: ~ \nL: ~ R: ~ \nBL: ~ B: Patch_2 BR: ~ \n"
                          "-25.00 -16.45 -20.22  -35.00 -18.16 -19.39  -44.89 2.43 -19.80  -35.17 31.02 -11.00  \n"
                          "-20.00 -15.87 -23.99  -5.53 10.00 4.08  -20.00 29.88 -5.00  -26.50 42.46 0.00  \n"
                          "-10.00 -17.02 -21.90  -10.00 13.12 29.64  -10.00 17.30 20.43  -5.63 91.75 2.50  \n"
                          "0.00 -15.87 -21.76  0.00 1.80 9.67  0.00 43.71 0.45  0.00 105.59 19.72  \n"
                          "Patch_2\n"
                          "TOP COLOR: 16 DIFFUSE: 0.00 BOTTOM COLOR: 16 DIFFUSE: 0.00\n"
                          "AL: ~ A: Patch_1 AR: ~ \nL: ~ R: ~ \nBL: ~ B: ~ BR: ~ \n"
                          "0.00 -15.87 -21.76  0.00 1.80 9.67  0.00 43.71 0.45  0.00 105.59 19.72  \n"
                          "10.00 -17.02 -20.93  10.00 5.10 7.43  10.00 17.30 16.65  5.63 91.75 2.50  \n"
                          "20.00 -15.87 -23.02  5.53 10.00 9.95  20.00 29.88 16.65  26.50 42.46 0.00  \n"
                          "25.00 -16.45 -18.83  35.00 -18.16 -13.52  44.89 2.43 -5.00  35.17 31.02 -2.50  \n";

SurfaceReadResult readOk(const std::string& text, float scale = 1.0f, int s = 0, int t = 0) {
    TempSurface file(text);
    SurfaceReadResult result = readSurfaceFile(file.path, "l", scale, s, t);
    EXPECT_TRUE(result.ok()) << (result.diagnostics.empty() ? "" : result.diagnostics[0].message);
    return result;
}

void expectNear(glm::vec3 actual, glm::vec3 expected, float tolerance) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(actual[i], expected[i], tolerance) << "coordinate " << i;
}

TEST(SurfaceFile, ARealFileIsTessellatedAsCpfgTessellatesIt) {
    const SurfaceReadResult read = readOk(kLeaf, 1.0f, 4, 3);
    const SurfaceMesh& mesh = read.mesh;
    EXPECT_EQ(mesh.name, "l");
    ASSERT_EQ(mesh.positions.size(), 2u * 5 * 4); // per patch (4 + 1) x (3 + 1) points
    EXPECT_EQ(mesh.indices.size(), 3u * 2 * 2 * 4 * 3);
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
    glm::vec3 low(1e9f), high(-1e9f);
    for (const glm::vec3& p : mesh.positions) low = glm::min(low, p), high = glm::max(high, p);
    // Grown along +Y to about 1 (SIZE), the contact point at the origin.
    expectNear(low, {-0.321907f, -0.035244f, -0.0972414f}, 2e-6f);
    expectNear(high, {0.318466f, 0.988726f, 0.228404f}, 2e-6f);
    expectNear(read.endPoint, {0.050803f, 0.496801f, 0.259304f}, 2e-6f);
    // Points of cpfg's triangles and their normals (cpfg's ray-tracer output
    // turns a normal to face its triangle's side, so only the line is compared).
    const glm::vec3 cpfg[][2] = {{{-0.206572f, -0.0256431f, 0.182329f}, {0.178006f, -0.184386f, -0.9666f}},
                                 {{-0.321907f, 0.139193f, 0.103602f}, {0.448901f, -0.334403f, -0.828651f}},
                                 {{-0.11951f, -0.035244f, 0.16671f}, {0.0223031f, 0.377331f, -0.92581f}},
                                 {{-0.136472f, 0.647824f, -0.0452559f}, {0.558814f, -0.483251f, -0.67394f}}};
    for (const auto& [point, normal] : cpfg) {
        const auto found = std::find_if(mesh.positions.begin(), mesh.positions.end(),
                                        [&](glm::vec3 p) { return glm::length(p - point) < 3e-6f; });
        ASSERT_NE(found, mesh.positions.end()) << point.x << " " << point.y << " " << point.z;
        EXPECT_NEAR(std::abs(glm::dot(mesh.normals[found - mesh.positions.begin()], normal)), 1.0f, 2e-6f);
    }
    for (const glm::vec3& n : mesh.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    for (const glm::vec2& uv : mesh.uvs) EXPECT_TRUE(uv.x >= 0 && uv.x <= 1 && uv.y >= 0 && uv.y <= 1);
    // Triangles wind counter-clockwise about the normals.
    for (size_t i = 0; i < mesh.indices.size(); i += 3) {
        const glm::vec3 a = mesh.positions[mesh.indices[i]], b = mesh.positions[mesh.indices[i + 1]];
        const glm::vec3 face = glm::cross(b - a, mesh.positions[mesh.indices[i + 2]] - a);
        EXPECT_GT(glm::dot(face, mesh.normals[mesh.indices[i]] + mesh.normals[mesh.indices[i + 1]]), 0.0f) << i;
    }
}

// A flat patch 1 long (rows from y = top down to top - 1) and 1 wide.
std::string flatPatch(const std::string& name, const std::string& below = "~", const std::string& above = "~",
                      float top = 1.0f) {
    std::string text = name + "\nTOP COLOR: 1 DIFFUSE: 0.5 BOTTOM COLOR: 2 DIFFUSE: 0.5\nAL: ~ A: " + above +
                       " AR: ~\nL: ~ R: ~\nBL: ~ B: " + below + " BR: ~\n";
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            text += std::to_string(-0.5 + j / 3.0) + " " + std::to_string(top - i / 3.0) + " 0" + (j < 3 ? " " : "\n");
    return text;
}

std::string header(const std::string& up = "X: 0 Y: 0 Z: 1", const std::string& size = "1",
                   const std::string& extra = "") {
    return "-0.5 0.5 0 1 0 0\n" + extra + "CONTACT POINT X: 0 Y: 0 Z: 0\nEND POINT X: 0 Y: 1 Z: 0\n" +
           "HEADING X: 0 Y: 1 Z: 0\nUP " + up + "\nSIZE: " + size + "\n";
}

// cpfg's left is heading x up, and its turtle's up is the opposite of ours:
// with UP +Z a file's +x ends on the turtle's left (-X) and the patch faces
// +Z; with UP -Z the file's axes are kept.
TEST(SurfaceFile, HeadingUpAndSizePlaceThePatch) {
    const std::string up[] = {"X: 0 Y: 0 Z: 1", "X: 0 Y: 0 Z: -1"};
    const float corner[] = {-0.5f, 0.5f}, facing[] = {1.0f, -1.0f};
    for (int k = 0; k < 2; ++k) {
        const SurfaceReadResult read = readOk(header(up[k]) + flatPatch("P"), 1.0f, 3, 3);
        expectNear(read.mesh.positions.at(3), {corner[k], 1.0f, 0.0f}, 1e-6f); // row 0, last column: file (0.5, 1)
        for (const glm::vec3& n : read.mesh.normals) expectNear(n, {0.0f, 0.0f, facing[k]}, 1e-6f);
        expectNear(read.endPoint, {0.0f, 1.0f, 0.0f}, 1e-6f);
    }
    // Scaled by the view's size over SIZE; a view size of 0 or less is 1, as cpfg reads it.
    expectNear(readOk(header("X: 0 Y: 0 Z: 1", "4") + flatPatch("P"), 2.0f).mesh.positions.at(0), {0.25f, 0.5f, 0.0f},
               1e-6f);
    expectNear(readOk(header("X: 0 Y: 0 Z: 1", "2") + flatPatch("P"), -1.0f).endPoint, {0.0f, 0.5f, 0.0f}, 1e-6f);
}

// The view file's precisions; else the file's S for both s and t, as cpfg
// has it; else 5; always within 1..10.
TEST(SurfaceFile, PrecisionsComeFromTheViewFileOrTheFile) {
    const std::string twoPatches = flatPatch("P", "Q") + flatPatch("Q", "~", "P", 0.0f);
    const std::string file36 = header("X: 0 Y: 0 Z: 1", "1", "PRECISION S: 3 T: 6\n") + twoPatches;
    const struct {
        std::string text;
        int s, t;
        size_t vertices;
    } cases[] = {{file36, 0, 0, 2 * 4 * 4},
                 {file36, 8, 5, 2 * 9 * 6},
                 {file36, 40, -3, 2 * 11 * 2},
                 {header() + twoPatches, 0, 0, 2 * 6 * 6}};
    for (const auto& c : cases) {
        const SurfaceReadResult read = readOk(c.text, 1.0f, c.s, c.t);
        EXPECT_EQ(read.mesh.positions.size(), c.vertices) << c.s << " " << c.t;
        EXPECT_EQ(read.mesh.indices.size() % 6, 0u);
    }
}

// Where neighbouring patches meet (Patch_1's last row, Patch_2's first), cpfg
// gives both the same normals; within a patch they differ.
TEST(SurfaceFile, NeighboursShareTheirEdgesNormals) {
    const SurfaceMesh mesh = readOk(kLeaf, 1.0f, 4, 3).mesh;
    for (int j = 0; j < 4; ++j) {
        expectNear(mesh.positions[16 + j], mesh.positions[20 + j], 1e-6f);
        expectNear(mesh.normals[16 + j], mesh.normals[20 + j], 1e-6f);
    }
    EXPECT_GT(glm::length(mesh.normals[12] - mesh.normals[16]), 0.01f);
}

struct MalformedSurfaceFile {
    std::string text;
    int line, column;
    const char* message; // a part of the diagnostic's message
};

TEST(SurfaceFile, MalformedFilesAreReportedWhereTheyGoWrong) {
    const std::string patch = flatPatch("P");
    std::string many = header();
    for (int i = 0; i <= kMaxSurfacePatches; ++i) many += flatPatch("P" + std::to_string(i));
    const MalformedSurfaceFile cases[] = {
        {"", 1, 1, "malformed bounding box"},
        {"0 1 0 1 0 x\n", 1, 11, "malformed bounding box"},
        {"0 1 0 1 0 1\nCONTACT X: 0\n", 2, 9, "expected 'CONTACT POINT'"},
        {header().replace(header().find("HEADING X: 0 Y: 1"), 17, "HEADING X: 0 Y: 0") + patch, 4, 9,
         "HEADING is the zero vector"},
        {header("X: 0 Y: 2 Z: 0") + patch, 5, 4, "UP is zero or parallel to HEADING"},
        {header("X: 0 Y: 0 Z: 1", "0") + patch, 6, 7, "SIZE is 0"},
        {header(), 7, 1, "the surface has no patches"},
        {header() + flatPatch("P", "Q"), 11, 10, "no patch 'Q' names 'P'"},
        {header() + flatPatch("P", "Q") + flatPatch("Q"), 11, 10, "no patch 'Q' names 'P' as its above neighbour"},
        {header() + patch.substr(0, patch.size() - 12), 15, 71, "malformed control point"},
        {header() + patch + "Q\nTOP COLOR: 1 DIFFUSE: 1 BOTTOM\n", 18, 1, "expected 'COLOR:'"},
        {many, 7 + 9 * kMaxSurfacePatches, 1, "too many patches"},
    };
    for (const MalformedSurfaceFile& bad : cases) {
        TempSurface file(bad.text);
        const SurfaceReadResult read = readSurfaceFile(file.path, "l");
        ASSERT_EQ(read.diagnostics.size(), 1u) << bad.text;
        const Diagnostic& first = read.diagnostics.front();
        EXPECT_EQ(first.file, file.path.string());
        EXPECT_EQ(first.line, bad.line) << first.message;
        EXPECT_EQ(first.column, bad.column) << first.message;
        EXPECT_NE(first.message.find(bad.message), std::string::npos) << first.message;
        EXPECT_TRUE(read.mesh.positions.empty());
    }
}

TEST(SurfaceFile, AMissingFileIsNamed) {
    const std::filesystem::path missing = std::filesystem::temp_directory_path() / "plantfield_no_such.s";
    const SurfaceReadResult read = readSurfaceFile(missing, "l");
    ASSERT_EQ(read.diagnostics.size(), 1u);
    EXPECT_EQ(read.diagnostics[0].file, missing.string());
    EXPECT_NE(read.diagnostics[0].message.find(missing.string()), std::string::npos);
    EXPECT_NE(read.diagnostics[0].message.find("missing"), std::string::npos);
}

} // namespace
} // namespace lsys::vlab
