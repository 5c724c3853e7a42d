#include "lsystem/vlab/surface_file.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <utility>

#include <glm/geometric.hpp>

#include "lsystem/common/file_reader.h"
#include "lsystem/language/lexer.h"

namespace lsys::vlab {

namespace {

constexpr size_t kMaxSurfaceFileBytes = size_t(4) << 20; // a full 64-patch file is some 40 KiB
constexpr int kDefaultPrecision = 5;                     // cpfg's S_COUNT / 2, without a PRECISION line

// Reads as cpfg's fscanf calls do: literals and values separated by any
// white space, line ends included; a problem is reported at its line and
// column and stops the reading.
class Scanner : public ErrorReport {
public:
    Scanner(std::string_view text, std::string file, std::vector<Diagnostic>& diagnostics)
        : ErrorReport{std::move(file), diagnostics}, lines_(splitLines(text)), cursor_{lines_[0], 0, 1} {}

    // The words ("CONTACT POINT", "X:") that must come next.
    bool literal(std::string_view words) {
        for (size_t begin = 0, end = 0; begin < words.size(); begin = end + 1) {
            end = std::min(words.find(' ', begin), words.size());
            const std::string quoted = std::string(1, '\'').append(words).append(1, '\'');
            if (skip(); !cursor_.accept(words.substr(begin, end - begin)))
                return fail(cursor_, "expected " + quoted, quoted);
        }
        return true;
    }

    // Where the next value begins (at the end of the text: atEnd()).
    Cursor here() {
        skip();
        return cursor_;
    }

    // The next run of non-blank characters (cpfg's "%s"), and where it begins.
    std::string word(Cursor& at) {
        skip();
        at = cursor_;
        while (!cursor_.atEnd() && !std::isspace(static_cast<unsigned char>(cursor_.peek()))) ++cursor_.pos;
        return std::string(cursor_.text.substr(at.pos, cursor_.pos - at.pos));
    }

    // A number, read as a float as cpfg's "%f" reads it.
    std::optional<float> number(std::string_view what) {
        Cursor at;
        const std::string token = word(at);
        char* end = nullptr;
        const float value = std::strtof(token.c_str(), &end);
        if (!token.empty() && end == token.c_str() + token.size() && std::isfinite(value)) return value;
        return failed(at, "malformed " + std::string(what), "a number");
    }

    // "x y z", or with `labels` "X: x Y: y Z: z".
    std::optional<glm::vec3> vector(std::string_view what, bool labels = true) {
        glm::vec3 v;
        for (int i = 0; i < 3; ++i) {
            const char label[] = {static_cast<char>('X' + i), ':', '\0'};
            const std::optional<float> value = !labels || literal(label) ? number(what) : std::nullopt;
            if (!value) return std::nullopt;
            v[i] = *value;
        }
        return v;
    }

private:
    void skip() {
        for (cursor_.skipSpaces(); cursor_.atEnd() && static_cast<size_t>(cursor_.line) < lines_.size();
             cursor_.skipSpaces())
            cursor_ = {lines_[cursor_.line], 0, cursor_.line + 1};
    }

    std::vector<std::string_view> lines_;
    Cursor cursor_;
};

// How the file's points become cpfg's local ones (patches.c, determine_transform and get_patch).
struct Placement {
    glm::vec3 contact{0.0f}, end{0.0f}, left{0.0f}, heading{0.0f}, up{0.0f};
    float scale = 1.0f;
    int filePrecision = kDefaultPrecision; // the file's S (cpfg never reads its T)

    glm::vec3 place(glm::vec3 p) const {
        p = (p - contact) * scale;
        return p.x * left + p.y * heading + p.z * up;
    }
};

// cpfg draws local x, y, z along its turtle's L, H and U (irisGL.c,
// iGlPredefinedSurface); its U is L x H (interpret.c starts it at -Z), the
// opposite of lsystem/turtle/turtle.h's: here x and z change sign, a half turn about Y.
glm::vec3 turtleSpace(glm::vec3 v) { return {-v.x, v.y, -v.z}; }

// cpfg's Normalize: a zero vector stays zero.
glm::vec3 normalise(glm::vec3 v) {
    const float length = std::sqrt(glm::dot(v, v));
    if (length == 0.0f) return v;
    for (int i = 0; i < 3; ++i) v[i] = static_cast<float>(v[i] * (1.0 / length));
    return v;
}

// The header: a bounding box (unused, as in cpfg), an optional PRECISION,
// CONTACT POINT, END POINT, HEADING, UP and SIZE. cpfg normalises HEADING
// and UP, takes left = heading x up (not normalised) and makes up = left x
// heading; points are scaled by the view file's size over SIZE (a view size
// of 0 or less counting as 1, as cpfg reads the view file).
std::optional<Placement> header(Scanner& in, float viewScale) {
    for (int i = 0; i < 6; ++i)
        if (!in.number("bounding box")) return std::nullopt;
    Placement placement;
    if (in.here().startsWith("PRECISION")) {
        const std::optional<float> s = in.literal("PRECISION S:") ? in.number("s precision") : std::nullopt;
        if (!s || !in.literal("T:") || !in.number("t precision")) return std::nullopt;
        placement.filePrecision = static_cast<int>(std::clamp(*s, -1e6f, 1e6f));
    }
    std::array<Cursor, 5> at;
    const std::pair<std::string_view, glm::vec3*> vectors[] = {{"CONTACT POINT", &placement.contact},
                                                               {"END POINT", &placement.end},
                                                               {"HEADING", &placement.heading},
                                                               {"UP", &placement.up}};
    for (size_t i = 0; i < 4; ++i) {
        const auto v = in.literal(vectors[i].first) ? (at[i] = in.here(), in.vector(vectors[i].first)) : std::nullopt;
        if (!v) return std::nullopt;
        *vectors[i].second = *v;
    }
    const std::optional<float> size = in.literal("SIZE:") ? (at[4] = in.here(), in.number("SIZE")) : std::nullopt;
    if (!size) return std::nullopt;
    placement.heading = normalise(placement.heading);
    placement.left = glm::cross(placement.heading, normalise(placement.up));
    if (placement.heading == glm::vec3(0.0f)) return in.failed(at[2], "HEADING is the zero vector", "a direction");
    if (glm::dot(placement.left, placement.left) < 1e-12f)
        return in.failed(at[3], "UP is zero or parallel to HEADING", "a direction across the heading");
    if (*size == 0.0f) return in.failed(at[4], "SIZE is 0", "the surface's size");
    placement.up = glm::cross(placement.left, placement.heading);
    placement.scale = (viewScale > 0.0f ? viewScale : 1.0f) / *size;
    return placement;
}

// Neighbour directions in cpfg's order (patches.c, struct Neighbour): the
// opposite of direction n is 7 - n.
constexpr std::array<std::string_view, 8> kNeighbourLabels = {"AL:", "A:", "AR:", "L:", "R:", "BL:", "B:", "BR:"};
constexpr std::array<std::string_view, 8> kNeighbourNames = {"above left", "above",      "above right", "left",
                                                             "right",      "below left", "below",       "below right"};

using Matrix = std::array<std::array<double, 4>, 4>;

struct Patch {
    std::string name;
    std::array<std::string, 8> neighbours; // "~" for none
    std::array<Cursor, 8> neighbourAt;
    std::array<Matrix, 3> control; // x, y and z of the placed control points, [row][column]
};

// A patch: its name, colours (unused here), neighbours and 4 x 4 control points.
std::optional<Patch> patch(Scanner& in, const Placement& placement) {
    Patch patch;
    Cursor at;
    patch.name = in.word(at);
    for (const char* side : {"TOP", "BOTTOM"})
        if (!(in.literal(side) && in.literal("COLOR:") && in.number("colour index") && in.literal("DIFFUSE:") &&
              in.number("diffuse factor")))
            return std::nullopt;
    for (size_t n = 0; n < kNeighbourLabels.size(); ++n) {
        if (!in.literal(kNeighbourLabels[n])) return std::nullopt;
        patch.neighbours[n] = in.word(patch.neighbourAt[n]);
        if (patch.neighbours[n].empty()) return in.failed(patch.neighbourAt[n], "missing neighbour", "a name or '~'");
    }
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const std::optional<glm::vec3> p = in.vector("control point", false);
            if (!p) return std::nullopt;
            for (int c = 0; c < 3; ++c) patch.control[c][i][j] = placement.place(*p)[c];
        }
    return patch;
}

// Each patch's neighbour in each direction (-1: none), checked as cpfg's
// check_connections does: the neighbour exists and names the patch back.
std::optional<std::vector<std::array<int, 8>>> link(Scanner& in, const std::vector<Patch>& patches) {
    std::vector<std::array<int, 8>> links(patches.size());
    for (size_t p = 0; p < patches.size(); ++p)
        for (size_t n = 0; n < 8; ++n) {
            const std::string& name = patches[p].neighbours[n];
            links[p][n] = -1;
            if (name == "~") continue;
            const auto found =
                std::find_if(patches.begin(), patches.end(), [&](const Patch& q) { return q.name == name; });
            if (found == patches.end() || found->neighbours[7 - n] != patches[p].name)
                return in.failed(patches[p].neighbourAt[n],
                                 "no patch '" + name + "' names '" + patches[p].name + "' as its " +
                                     std::string(kNeighbourNames[7 - n]) + " neighbour",
                                 "the name of a patch that names this one back, or '~'");
            links[p][n] = static_cast<int>(found - patches.begin());
        }
    return links;
}

std::optional<std::vector<Patch>> readPatches(Scanner& in, const Placement& placement) {
    std::vector<Patch> patches;
    while (!in.here().atEnd()) {
        if (patches.size() == static_cast<size_t>(kMaxSurfacePatches))
            return in.failed(in.here(), "too many patches", "at most " + std::to_string(kMaxSurfacePatches));
        std::optional<Patch> next = patch(in, placement);
        if (!next) return std::nullopt;
        patches.push_back(std::move(*next));
    }
    if (patches.empty()) return in.failed(in.here(), "the surface has no patches", "a patch");
    return patches;
}

// A patch's points and normals on an (s + 1) x (t + 1) grid, row by row,
// in cpfg's local space.
struct Grid {
    int s = 0, t = 0;
    std::vector<glm::vec3> points, normals;
    size_t at(int i, int j) const { return static_cast<size_t>(i) * static_cast<size_t>(t + 1) + j; }
};

// a b, or a b^T: cpfg's MatMult4x4D, term by term.
Matrix multiply(const Matrix& a, const Matrix& b, bool transposed = false) {
    Matrix c{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) c[i][j] += a[i][k] * (transposed ? b[j][k] : b[k][j]);
    return c;
}

// The Bézier basis matrix (cpfg's m_bezier, its own transpose).
constexpr Matrix kBezier = {{{-1, 3, -3, 1}, {3, -6, 3, 0}, {-3, 3, 0, 0}, {1, 0, 0, 0}}};

// cpfg's forward-difference matrices for n steps of 1 / n (patches.c,
// initialize_matrices): applied to a cubic's coefficients, the rows give its
// value and first three differences at 0, or those of its slope.
Matrix steps(int n, bool slope) {
    const double e = 1.0 / n;
    if (slope) return {{{0, 0, 1, 0}, {3.0 * e * e, 2.0 * e, 0, 0}, {6.0 * e * e, 0, 0, 0}, {0, 0, 0, 0}}};
    return {{{0, 0, 0, 1}, {e * e * e, e * e, e, 0}, {6.0 * e * e * e, 2.0 * e * e, 0, 0}, {6.0 * e * e * e, 0, 0, 0}}};
}

// One coordinate of a cubic on the grid by forward differences, stored as
// floats, as cpfg's calculate_surface does; `d` holds the differences at
// s = 0 (rows) and t = 0 (columns).
void differences(Matrix d, Grid& grid, std::vector<glm::vec3>& out, int coordinate) {
    for (int i = 0; i <= grid.s; ++i) {
        std::array<double, 4> f = d[0]; // the value and its three differences
        for (int j = 0; j <= grid.t; ++j) {
            out[grid.at(i, j)][coordinate] = static_cast<float>(f[0]);
            for (int k = 0; k < 3; ++k) f[k] += f[k + 1];
        }
        for (int r = 0; r <= 2; ++r)
            for (int k = 0; k < 4; ++k) d[r][k] += d[r + 1][k];
    }
}

// cpfg blends each corner's normal with its two neighbours along the edges
// (calculate_surface), in this order.
void blendCorners(Grid& grid) {
    const int s = grid.s, t = grid.t;
    const int corners[4][6] = {
        {0, 0, 0, 1, 1, 0}, {s, 0, s, 1, s - 1, 0}, {s, t, s, t - 1, s - 1, t}, {0, t, 0, t - 1, 1, t}};
    for (const auto& c : corners) {
        glm::vec3& normal = grid.normals[grid.at(c[0], c[1])];
        normal = normalise(normal * 0.5f + grid.normals[grid.at(c[2], c[3])] + grid.normals[grid.at(c[4], c[5])]);
    }
}

// The patch on the grid step by step as cpfg's calculate_d00 and
// calculate_surface compute it, so that where a tangent vanishes (a row
// collapsed to a point) the normal is cpfg's: s runs down the rows of control
// points, t along them; the normal is the t tangent x the s tangent, or +Y.
Grid tessellate(const Patch& patch, int s, int t) {
    Grid grid{s, t, std::vector<glm::vec3>((s + 1) * (t + 1)), {}};
    std::vector<glm::vec3> alongT(grid.points.size()), alongS(grid.points.size());
    const Matrix rows = steps(s, false), rowSlopes = steps(s, true);
    const Matrix columns = steps(t, false), columnSlopes = steps(t, true); // used transposed
    for (int c = 0; c < 3; ++c) {
        const Matrix coefficients = multiply(multiply(kBezier, patch.control[c]), kBezier);
        differences(multiply(multiply(rows, coefficients), columns, true), grid, grid.points, c);
        differences(multiply(multiply(rows, coefficients), columnSlopes, true), grid, alongT, c);
        differences(multiply(multiply(rowSlopes, coefficients), columns, true), grid, alongS, c);
    }
    for (size_t k = 0; k < grid.points.size(); ++k) {
        const glm::dvec3 normal = glm::cross(alongT[k], alongS[k]);
        const double length = static_cast<float>(std::sqrt(glm::dot(normal, normal)));
        grid.normals.push_back(length == 0.0 ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(normal / length));
    }
    blendCorners(grid);
    return grid;
}

// The vertices a patch shares with its neighbour in direction n: (index
// here, index there). Above is row 0, against the neighbour's last row; left
// is column 0, against its last column.
std::vector<std::pair<size_t, size_t>> shared(const Grid& grid, size_t n) {
    const int row = n <= 2 ? 0 : n >= 5 ? grid.s : -1; // -1: every row
    const int column = n == 0 || n == 3 || n == 5 ? 0 : n == 2 || n == 4 || n == 7 ? grid.t : -1;
    std::vector<std::pair<size_t, size_t>> pairs;
    for (int i = row < 0 ? 0 : row; i <= (row < 0 ? grid.s : row); ++i)
        for (int j = column < 0 ? 0 : column; j <= (column < 0 ? grid.t : column); ++j)
            pairs.emplace_back(grid.at(i, j), grid.at(row < 0 ? i : grid.s - i, column < 0 ? j : grid.t - j));
    return pairs;
}

// cpfg's calculate_neighbouring_vertex_normals: patch by patch, the normals
// of its shared vertices are summed with the neighbours', normalised and
// copied to them; the neighbour's side of an edge done is not done again.
void averageNormals(std::vector<Grid>& grids, const std::vector<std::array<int, 8>>& links) {
    std::vector<std::array<bool, 8>> averaged(grids.size(), std::array<bool, 8>{});
    for (size_t p = 0; p < grids.size(); ++p) {
        const auto pending = [&](size_t n) { return links[p][n] >= 0 && !averaged[p][n]; };
        for (size_t n = 0; n < 8; ++n)
            if (pending(n))
                for (auto [here, there] : shared(grids[p], n))
                    grids[p].normals[here] += grids[links[p][n]].normals[there];
        for (size_t n = 0; n < 8; ++n) {
            if (!pending(n)) continue;
            for (auto [here, there] : shared(grids[p], n))
                grids[links[p][n]].normals[there] = grids[p].normals[here] = normalise(grids[p].normals[here]);
            averaged[links[p][n]][7 - n] = true;
        }
    }
}

// The grid's vertices, with cpfg's per-patch texture coordinates (s, t) in
// [0, 1], and two triangles per cell wound counter-clockwise about the normal.
void append(SurfaceMesh& mesh, const Grid& grid) {
    const auto base = static_cast<uint32_t>(mesh.positions.size());
    for (int i = 0; i <= grid.s; ++i)
        for (int j = 0; j <= grid.t; ++j) {
            mesh.positions.push_back(turtleSpace(grid.points[grid.at(i, j)]));
            mesh.normals.push_back(turtleSpace(grid.normals[grid.at(i, j)]));
            mesh.uvs.emplace_back(float(i) / float(grid.s), float(j) / float(grid.t));
        }
    for (int i = 0; i < grid.s; ++i)
        for (int j = 0; j < grid.t; ++j) {
            const uint32_t a = base + static_cast<uint32_t>(grid.at(i, j)), b = a + grid.t + 1;
            mesh.indices.insert(mesh.indices.end(), {a, a + 1, b, b, a + 1, b + 1});
        }
}

} // namespace

SurfaceReadResult readSurfaceFile(const std::filesystem::path& path, const std::string& name, float scale,
                                  int sPrecision, int tPrecision) {
    SurfaceReadResult result;
    result.mesh.name = name;
    const std::optional<std::string> text = readTextFileOf("surface", path, kMaxSurfaceFileBytes, result.diagnostics);
    if (!text) return result;
    Scanner in(*text, path.string(), result.diagnostics);
    const std::optional<Placement> placement = header(in, scale);
    const std::optional<std::vector<Patch>> patches = placement ? readPatches(in, *placement) : std::nullopt;
    const auto links = patches ? link(in, *patches) : std::nullopt;
    if (!links) return result;
    // The view's precisions, else the file's S for both (cpfg's determine_transform), within cpfg's bounds.
    const auto precision = [&](int view) {
        return std::clamp(view != 0 ? view : placement->filePrecision, 1, kMaxSurfacePrecision);
    };
    std::vector<Grid> grids;
    for (const Patch& patch : *patches)
        grids.push_back(tessellate(patch, precision(sPrecision), precision(tPrecision)));
    averageNormals(grids, *links);
    for (const Grid& grid : grids) append(result.mesh, grid);
    result.endPoint = turtleSpace(placement->place(placement->end));
    return result;
}

} // namespace lsys::vlab
