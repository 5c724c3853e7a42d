#pragma once
// A component plant (Tankard 2001, §3.2 and §4.1, after Lintermann and
// Deussen 1998): named components linked into a graph whose root, drawn,
// draws its children in turn. Read from a .comp.json file
// (docs/COMPONENTS.md) by readComponentGraph, built into a PlantAsset by
// buildComponentPlant.

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "lsystem/common/memory_budget.h"
#include "lsystem/components/spline.h"
#include "lsystem/turtle/plant_asset.h"

namespace lsys::components {

// A generalised cylinder along a Hermite spline (Tankard §4.1.2.2.1): `shape`
// in units of `length`, y along the stem; `radius` in metres along it.
struct Stem {
    Spline shape;
    float length = 1.0f;
    Attribute radius = constant(0.02f);
    uint32_t detail = 8;    // segments sampled along the shape (Tankard's detail)
    float stiffness = 0.0f; // N·m/rad of each joint; 0: from beam theory when simulated
    uint32_t material = 0;
};

// A blade (Tankard §4.1.2.2): either half an outline, x ≥ 0 the half-width and
// y along the midrib, mirrored about x = 0 and sampled at `detail` points, or
// a whole polygon given point by point. In units of `length`.
struct Leaf {
    Spline halfOutline;             // empty when `polygon` is given
    std::vector<glm::vec3> polygon; // z = 0
    float length = 0.1f;
    uint32_t detail = 8;
    float fold = 0.0f; // degrees each half turns up about the midrib
    uint32_t material = 0;
};

// Branches along a stem (Tankard §3.2.3.4.1, §4.1.2.3.1): `count` nodes
// evenly spaced from `start` to `end` of the stem, each turned `phyllotaxis`
// degrees about the stem from the last, tilted `angle` degrees off it and
// scaled by `scale`, with the thesis's variations. `azimuth` and `twist` are
// ours: they let a frond hold its leaflets flat to either side.
struct Tree {
    uint32_t stem = 0; // index of a Stem component
    bool stemVisible = true;
    uint32_t count = 5;
    float start = 0.2f, end = 1.0f;
    Attribute angle = constant(45.0f);
    Attribute phyllotaxis = constant(137.5f);
    float azimuth = 0.0f; // degrees about the stem of the first node
    float twist = 0.0f;   // degrees about each branch's own axis (a blade's face)
    Attribute scale = constant(1.0f);
    float scaleVariation = 0.0f; // fraction
    float angleVariation = 0.0f; // degrees
};

// Children around one node (Tankard §3.2.3.4.2, §4.1.2.3.2; Lintermann and
// Deussen's Hydra).
struct Radial {
    uint32_t count = 5;
    float interChildAngle = 72.0f; // degrees about the node's axis between children
    float nodeAngle = 45.0f;       // degrees off the axis
    float nodeTwist = 0.0f;        // degrees about each child's own axis
    float angleVariation = 0.0f;   // degrees
};

struct Component {
    std::string name;
    std::variant<Stem, Leaf, Tree, Radial> kind;
    // Drawn at a stem's tip, at each node of a tree or radial (a leaf has none).
    std::vector<uint32_t> children;
    std::string location; // "file:line:column: /components/NAME", for budget errors
};

// How much a graph may draw: a graph instances its components
// multiplicatively, so a few lines can ask for millions (counted before
// drawing: countComponentPlant).
struct ComponentBudget {
    uint64_t maxInstances = 200'000; // components drawn
    uint64_t maxPrimitives = 2'000'000;
};

struct ComponentGraph {
    std::filesystem::path file;
    std::string description;
    uint64_t seed = 1;
    uint32_t root = 0;
    std::vector<Component> components;
    std::vector<Material> materials;
    ComponentBudget budget;
};

// The error of a malformed file or a graph past its budget:
// "file:line:column: /json/pointer message".
struct ComponentError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// What a graph draws, counted from the graph without drawing it: each
// component is drawn once per draw of each parent (a tree's stem once, its
// children `count` times; a radial's children `count` times; a stem's once).
// Saturating at UINT64_MAX.
struct ComponentCounts {
    std::vector<uint64_t> draws; // per component
    uint64_t instances = 0;      // all draws
    uint64_t primitives = 0;     // segments and blades
    uint64_t bytes = 0;          // the PlantAsset's records, twice for the vectors' growth
};
ComponentCounts countComponentPlant(const ComponentGraph& graph);

// Throws ComponentError when the counts pass the graph's budget (at the
// component drawn, or drawing primitives, most), MemoryBudgetError when the
// plant's records would pass `memory`.
void requireWithinBudgets(const ComponentGraph& graph, const ComponentCounts& counts, const MemoryBudget& memory);

// Files named *.comp.json are component plants.
bool isComponentFile(const std::filesystem::path& file);

// Reads and checks a .comp.json file; throws ComponentError.
ComponentGraph readComponentGraph(const std::filesystem::path& file);

// Draws the graph from its root at the origin, heading +Y; the same graph
// and seed give the same plant. Counts it first: throws ComponentError past
// the graph's budget, MemoryBudgetError past `memory`, before drawing.
PlantAsset buildComponentPlant(const ComponentGraph& graph, const MemoryBudget& memory = {});

// readComponentGraph then buildComponentPlant.
PlantAsset loadComponentPlant(const std::filesystem::path& file, const MemoryBudget& memory = {});

} // namespace lsys::components
