// readComponentGraph: a .comp.json file (docs/COMPONENTS.md) checked value by
// value, each error located by lsystem/common/json_reader.h.
#include "lsystem/components/component_graph.h"

#include <algorithm>
#include <map>
#include <optional>

#include "lsystem/common/json_reader.h"
#include "lsystem/turtle/turtle_builder.h"

namespace lsys::components {
namespace {

// A component file is a few kilobytes; 4 MiB is plenty for any.
constexpr size_t kMaxComponentFileBytes = size_t(4) << 20;
// Past this a stem or leaf is tessellated more finely than any screen shows.
constexpr uint32_t kMaxDetail = 256;
// Nodes of one tree or radial: far more than any plant's, few enough that a
// single misplaced digit is an error rather than a budget overrun.
constexpr uint32_t kMaxNodes = 10'000;
// A budget past this would let a plant outgrow memory (56 bytes a primitive)
// before the budget stopped it.
constexpr uint32_t kMaxBudget = 100'000'000;

// Coordinates, lengths, radii and scales: a million is any plant many times
// over, and far enough below float's limit that a size times a scale stays
// finite (deeper products are checked as the plant is drawn).
constexpr double kMaxMagnitude = 1e6;
Range magnitude() { return between(-kMaxMagnitude, kMaxMagnitude); }
Range size() { return between(0.0, kMaxMagnitude); }
Range positiveSize() { return {.min = 0.0, .max = kMaxMagnitude, .minOpen = true}; }

const std::vector<std::string_view> kKinds = {"stem", "leaf", "tree", "radial"};

// Names of components and materials, for references.
struct Names {
    std::map<std::string, uint32_t, std::less<>> components;
    std::map<std::string, uint32_t, std::less<>> materials;
};

std::vector<std::string_view> keysOf(const std::map<std::string, uint32_t, std::less<>>& map) {
    std::vector<std::string_view> keys;
    for (const auto& entry : map) keys.push_back(entry.first);
    return keys;
}

uint32_t reference(const JsonNode& node, const std::map<std::string, uint32_t, std::less<>>& names,
                   std::string_view what) {
    const std::string name = readString(node);
    const auto found = names.find(name);
    if (found == names.end())
        failAt(node, "names no " + std::string(what) + " \"" + name + "\"" + didYouMean(name, keysOf(names)));
    return found->second;
}

glm::vec3 toVec3(glm::vec2 v) { return {v, 0.0f}; }
glm::vec3 toVec3(glm::vec3 v) { return v; }

// Points as [x, y(, z)] (tangents Catmull–Rom) or all as {"at": …, "tangent": …}.
template <int N>
Spline readCurve(const JsonNode& node, std::string_view expected) {
    Spline spline;
    const std::vector<JsonNode> elements = arrayElements(node, expected);
    if (elements.size() < 2) failAt(node, "needs at least 2 control points");
    bool explicitTangents = false;
    for (size_t i = 0; i < elements.size(); ++i) {
        const JsonNode& element = elements[i];
        const bool object = element.value->is_object();
        if (i > 0 && object != explicitTangents)
            failAt(element, "mixes points with and without tangents: give all as [..] or all as {\"at\", \"tangent\"}");
        explicitTangents = object;
        SplinePoint point;
        if (object) {
            requireObject(element, {"at", "tangent"});
            point.position = toVec3(readVector<N>(requireMember(element, "at", "the point"), magnitude()));
            point.tangent = toVec3(readVector<N>(requireMember(element, "tangent", "the direction"), magnitude()));
        } else {
            point.position = toVec3(readVector<N>(element, magnitude()));
        }
        spline.points.push_back(point);
    }
    if (!explicitTangents) setCatmullRomTangents(spline.points);
    return spline;
}

// A number, or an array of numbers evenly spaced along u.
Attribute readAttribute(const JsonNode& node, Range range) {
    if (!node.value->is_array()) return constant(float(readNumber(node, range)));
    Attribute attribute;
    const std::vector<JsonNode> elements = arrayElements(node, "a number or an array of numbers");
    if (elements.empty()) failAt(node, "needs at least one value");
    for (size_t i = 0; i < elements.size(); ++i) {
        const float value = float(readNumber(elements[i], range));
        const float u = elements.size() == 1 ? 0.0f : float(i) / float(elements.size() - 1);
        attribute.spline.points.push_back({{value, u, 0.0f}, {}});
    }
    setCatmullRomTangents(attribute.spline.points);
    return attribute;
}

void readAttributeField(const JsonNode& object, std::string_view key, Attribute& out, Range range) {
    if (auto node = member(object, key)) out = readAttribute(*node, range);
}

void readMaterialField(const JsonNode& object, const Names& names, uint32_t& out) {
    if (auto node = member(object, "material")) out = reference(*node, names.materials, "material");
}

Stem readStem(const JsonNode& node, const Names& names) {
    requireObject(node, {"kind", "shape", "length", "radius", "detail", "stiffness", "material", "children"});
    Stem stem;
    stem.material = names.materials.at("bark");
    if (auto shape = member(node, "shape"))
        stem.shape = readCurve<3>(*shape, "an array of [x, y, z] points");
    else
        stem.shape.points = {{{0, 0, 0}, {0, 1, 0}}, {{0, 1, 0}, {0, 1, 0}}};
    readField(node, "length", stem.length, positiveSize());
    readAttributeField(node, "radius", stem.radius, size());
    readField(node, "detail", stem.detail, between(1, kMaxDetail));
    readField(node, "stiffness", stem.stiffness, atLeast(0.0));
    readMaterialField(node, names, stem.material);
    return stem;
}

Leaf readLeaf(const JsonNode& node, const Names& names) {
    requireObject(node, {"kind", "outline", "polygon", "length", "detail", "fold", "material"});
    Leaf leaf;
    leaf.material = names.materials.at("leaf");
    const std::optional<JsonNode> outline = member(node, "outline");
    const std::optional<JsonNode> polygon = member(node, "polygon");
    if (outline && polygon)
        failAt(*polygon, "cannot be given together with \"outline\": a leaf is one or the other", true);
    if (polygon) {
        const std::vector<JsonNode> points = arrayElements(*polygon, "an array of [x, y] points");
        if (points.size() < 3) failAt(*polygon, "needs at least 3 points");
        for (const JsonNode& point : points) leaf.polygon.push_back(glm::vec3(readVector<2>(point, magnitude()), 0.0f));
    } else if (outline) {
        leaf.halfOutline = readCurve<2>(*outline, "an array of [x, y] points");
    } else {
        // An ovate blade with a pointed tip.
        leaf.halfOutline.points = {
            {{0, 0, 0}, {0.5f, 0.2f, 0}}, {{0.3f, 0.4f, 0}, {0, 0.4f, 0}}, {{0, 1, 0}, {-0.2f, 0.3f, 0}}};
    }
    readField(node, "length", leaf.length, positiveSize());
    readField(node, "detail", leaf.detail, between(2, kMaxDetail));
    readField(node, "fold", leaf.fold, between(-90, 90));
    readMaterialField(node, names, leaf.material);
    return leaf;
}

Tree readTree(const JsonNode& node, const Names& names, const std::vector<std::optional<JsonNode>>& kinds) {
    requireObject(node, {"kind", "stem", "stem_visible", "count", "start", "end", "angle", "phyllotaxis", "azimuth",
                         "twist", "scale", "scale_variation", "angle_variation", "children"});
    Tree tree;
    const JsonNode stem = requireMember(node, "stem", "the name of the stem component the branches grow on");
    tree.stem = reference(stem, names.components, "component");
    if (kinds[tree.stem] && readString(*kinds[tree.stem]) != "stem") failAt(stem, "must name a stem component");
    readField(node, "stem_visible", tree.stemVisible);
    readField(node, "count", tree.count, between(0, kMaxNodes));
    readField(node, "start", tree.start, between(0, 1));
    readField(node, "end", tree.end, between(0, 1));
    if (tree.end < tree.start) failAt(*member(node, "end"), "must not be less than \"start\"");
    readAttributeField(node, "angle", tree.angle, between(-180, 180));
    readAttributeField(node, "phyllotaxis", tree.phyllotaxis, between(-360, 360));
    readField(node, "azimuth", tree.azimuth, between(-360, 360));
    readField(node, "twist", tree.twist, between(-360, 360));
    readAttributeField(node, "scale", tree.scale, size());
    readField(node, "scale_variation", tree.scaleVariation, between(0, 1));
    readField(node, "angle_variation", tree.angleVariation, between(0, 180));
    return tree;
}

Radial readRadial(const JsonNode& node) {
    requireObject(node,
                  {"kind", "count", "inter_child_angle", "node_angle", "node_twist", "angle_variation", "children"});
    Radial radial;
    readField(node, "count", radial.count, between(1, kMaxNodes));
    radial.interChildAngle = 360.0f / float(radial.count);
    readField(node, "inter_child_angle", radial.interChildAngle, between(-360, 360));
    readField(node, "node_angle", radial.nodeAngle, between(-180, 180));
    readField(node, "node_twist", radial.nodeTwist, between(-360, 360));
    readField(node, "angle_variation", radial.angleVariation, between(0, 180));
    return radial;
}

std::vector<Material> readMaterials(const std::optional<JsonNode>& node, Names& names) {
    std::vector<Material> materials = defaultPalette();
    for (uint32_t i = 0; i < materials.size(); ++i) names.materials[materials[i].name] = i;
    if (!node) return materials;
    requireMap(*node);
    for (const auto& [name, value] : node->value->items()) {
        const JsonNode entry = *member(*node, name);
        requireObject(entry, {"albedo", "two_sided"});
        Material material{name, glm::vec3(0.5f), false};
        if (const auto given = names.materials.find(name); given != names.materials.end())
            material = materials[given->second];
        readField(entry, "albedo", material.albedo, between(0, 1));
        readField(entry, "two_sided", material.twoSided);
        const auto [slot, added] = names.materials.try_emplace(name, uint32_t(materials.size()));
        if (added)
            materials.push_back(material);
        else
            materials[slot->second] = material;
    }
    return materials;
}

// A component's references to the components it draws (its children, a
// tree's stem), each with where the file names it.
using Edges = std::vector<std::vector<std::pair<uint32_t, JsonNode>>>;

// Past any plant's nesting (a tree's branches' leaves are three levels
// deep): drawing and counting walk the graph recursively, so a deeper graph
// is refused here, before they would run out of stack.
constexpr uint32_t kMaxNesting = 1000;

// Depth-first from every component, with a stack of its own: a component
// reached again while still on the path closes a cycle, which would draw
// forever; one that starts a chain of more than kMaxNesting components nests
// too deep. Each component and reference is visited once.
void requireAcyclic(const ComponentGraph& graph, const Edges& edges, const std::vector<JsonNode>& nodes) {
    enum class Mark : uint8_t { Unvisited, OnPath, Done };
    std::vector<Mark> marks(graph.components.size(), Mark::Unvisited);
    std::vector<uint32_t> chain(graph.components.size(), 0); // the longest chain a component starts
    struct Visit {
        uint32_t index;
        size_t nextEdge = 0;
    };
    std::vector<Visit> path;
    for (uint32_t start = 0; start < graph.components.size(); ++start) {
        if (marks[start] != Mark::Unvisited) continue;
        marks[start] = Mark::OnPath;
        path.push_back({start});
        while (!path.empty()) {
            const uint32_t index = path.back().index;
            if (path.back().nextEdge < edges[index].size()) {
                const auto& [child, reference] = edges[index][path.back().nextEdge++];
                if (marks[child] == Mark::OnPath) {
                    std::string cycle;
                    for (auto it = std::find_if(path.begin(), path.end(),
                                                [c = child](const Visit& v) { return v.index == c; });
                         it != path.end(); ++it)
                        cycle += graph.components[it->index].name + " → ";
                    failAt(reference,
                           "makes a cycle (" + cycle + graph.components[child].name + "): the plant would never end");
                }
                if (marks[child] == Mark::Unvisited) {
                    marks[child] = Mark::OnPath;
                    path.push_back({child});
                }
                continue;
            }
            chain[index] = 1;
            for (const auto& [child, reference] : edges[index]) chain[index] = std::max(chain[index], chain[child] + 1);
            if (chain[index] > kMaxNesting)
                failAt(nodes[index], "starts a chain of more than " + std::to_string(kMaxNesting) +
                                         " components, each drawing the next: deeper than any plant nests");
            marks[index] = Mark::Done;
            path.pop_back();
        }
    }
}

ComponentGraph readGraph(const JsonSource& source) {
    const JsonNode root = rootNode(source);
    requireObject(root, {"description", "seed", "root", "materials", "components", "budget"});
    ComponentGraph graph;
    graph.file = source.file;
    readField(root, "description", graph.description);
    if (auto seed = member(root, "seed")) graph.seed = readInteger(*seed, anyNumber());

    if (auto budget = member(root, "budget")) {
        requireObject(*budget, {"max_instances", "max_primitives"});
        if (auto instances = member(*budget, "max_instances"))
            graph.budget.maxInstances = readInteger(*instances, between(1, kMaxBudget));
        if (auto primitives = member(*budget, "max_primitives"))
            graph.budget.maxPrimitives = readInteger(*primitives, between(1, kMaxBudget));
    }

    Names names;
    graph.materials = readMaterials(member(root, "materials"), names);

    const JsonNode list = requireMember(root, "components", "an object of named components");
    requireMap(list);
    std::vector<JsonNode> nodes;
    std::vector<std::optional<JsonNode>> kinds;
    for (const auto& [name, value] : list.value->items()) {
        names.components[name] = uint32_t(nodes.size());
        nodes.push_back(*member(list, name));
        requireMap(nodes.back());
        kinds.push_back(member(nodes.back(), "kind"));
    }
    if (nodes.empty()) failAt(list, "must name at least one component");

    const std::map<std::string, std::string, std::less<>> locations = memberLocations(list);
    Edges edges(nodes.size());
    for (size_t i = 0; i < nodes.size(); ++i) {
        const JsonNode& node = nodes[i];
        Component component;
        component.name = node.path.back();
        const auto located = locations.find(component.name); // found unless the text walk disagrees with the parse
        component.location = (located != locations.end() ? located->second : locationOf(node)) + ": " + node.pointer();
        if (!kinds[i]) failAt(node, "needs \"kind\": one of \"stem\", \"leaf\", \"tree\", \"radial\"");
        const std::string kind = readString(*kinds[i]);
        if (kind == "stem")
            component.kind = readStem(node, names);
        else if (kind == "leaf")
            component.kind = readLeaf(node, names);
        else if (kind == "tree") {
            component.kind = readTree(node, names, kinds);
            edges[i].emplace_back(std::get<Tree>(component.kind).stem, *member(node, "stem"));
        } else if (kind == "radial")
            component.kind = readRadial(node);
        else
            failAt(*kinds[i], "is an unknown component kind \"" + kind + "\"" + didYouMean(kind, kKinds) +
                                  " (expected \"stem\", \"leaf\", \"tree\" or \"radial\")");
        if (auto children = member(node, "children"))
            for (const JsonNode& child : arrayElements(*children, "an array of component names")) {
                component.children.push_back(reference(child, names.components, "component"));
                edges[i].emplace_back(component.children.back(), child);
            }
        graph.components.push_back(std::move(component));
    }
    graph.root = reference(requireMember(root, "root", "the name of the component the plant grows from"),
                           names.components, "component");
    requireAcyclic(graph, edges, nodes);

    return graph;
}

} // namespace

bool isComponentFile(const std::filesystem::path& file) { return file.string().ends_with(".comp.json"); }

ComponentGraph readComponentGraph(const std::filesystem::path& file) {
    try {
        const JsonSource source = readJsonFile(file, {"component plant", kMaxComponentFileBytes});
        return readGraph(source);
    } catch (const JsonError& error) {
        throw ComponentError(error.what());
    }
}

PlantAsset loadComponentPlant(const std::filesystem::path& file, const MemoryBudget& memory) {
    return buildComponentPlant(readComponentGraph(file), memory);
}

} // namespace lsys::components
