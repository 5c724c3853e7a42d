// buildInstanceGraph: every object is the turtle's interpretation of a node's
// body from a local entry frame (Calgary b-grammar thesis, §4.2), with the
// turtle's own applyModule(); references to other nodes become instances of
// objects looked up by (node, entry values read), built on first use.
// deriveLazyInstanceGraph runs the same interpretation keeping only the
// objects, and expandObject replays one object's interpretation on demand
// (Robbins 1998, §3: a branch is expanded when a ray reaches its box).

#include <algorithm>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unordered_map>

#include <glm/mat3x3.hpp>

#include "lsystem/common/error.h"
#include "lsystem/instancing/instance_graph.h"
#include "lsystem/instancing/instance_graph_lazy.h"
#include "lsystem/instancing/instance_key.h"
#include "lsystem/instancing/status_function.h"

namespace lsys {

// Named rather than anonymous: GraphDerivation, declared in a header, holds a GraphBuilder.
namespace graph_build {

// What a node's whole word does to the two stacks, and whether it cuts.
struct NodeSummary {
    int32_t bracketChange = 0;
    int32_t bracketLowest = 0;
    int32_t polygonChange = 0;
    int32_t polygonLowest = 0;
    bool cut = false;

    // An object needs a status function: the node never pops a branch or
    // closes a polygon it did not open, leaves no polygon open (the caller
    // would have to trace it) and holds no '%' (which may cut the caller).
    // Other nodes are interpreted inline, as part of the body using them.
    bool object() const { return bracketLowest == 0 && polygonLowest == 0 && polygonChange == 0 && !cut; }
};

std::vector<NodeSummary> summarise(const BGrammar& bgrammar, std::span<const TurtleCommand> commands) {
    std::vector<NodeSummary> summaries(bgrammar.nodes.size());
    for (uint32_t node = 0; node < bgrammar.nodes.size(); ++node) {
        NodeSummary& summary = summaries[node];
        for (const BodyItem& item : bgrammar.bodyOf(node)) {
            if (item.isNode()) {
                const NodeSummary& child = summaries[item.index];
                summary.bracketLowest = std::min(summary.bracketLowest, summary.bracketChange + child.bracketLowest);
                summary.polygonLowest = std::min(summary.polygonLowest, summary.polygonChange + child.polygonLowest);
                summary.bracketChange += child.bracketChange;
                summary.polygonChange += child.polygonChange;
                summary.cut |= child.cut;
                continue;
            }
            const StackEffect& effect =
                turtleCommandDefinition(commands[bgrammar.modules[item.index].symbol].action).stacks;
            summary.bracketChange += effect.branches;
            summary.bracketLowest = std::min(summary.bracketLowest, summary.bracketChange);
            summary.polygonChange += effect.polygons;
            summary.polygonLowest = std::min(summary.polygonLowest, summary.polygonChange);
            summary.cut |= effect.cuts;
        }
    }
    return summaries;
}

// Whether a module of the word places the turtle in plant space (cpfg's @M
// and @R, kReadsPlantFrame): what follows it depends on where the instance
// holding it stands in the plant, not on its entry frame alone, so the root
// interprets the whole word as the turtle does, one object with no instances.
bool placesInPlant(const BGrammar& bgrammar, std::span<const TurtleCommand> commands) {
    for (const TerminalModule& module : bgrammar.modules)
        if (turtleCommandDefinition(commands[module.symbol].action).reads.always & kReadsPlantFrame) return true;
    return false;
}

// Per object, what building its parents needs and the graph does not keep.
struct BuiltObject {
    uint16_t reads = 0;
    StatusFunction status;
};

// Per object of a lazy graph, what replaying its interpretation needs: its
// entry, and where the build's numbering of objects and primitives stood.
struct ObjectOrigin {
    ObjectEntry entry;
    uint32_t objectsBefore = 0;          // objects finished when its interpretation began
    uint32_t firstNewChild = UINT32_MAX; // the object its first instance of a new object built
    uint32_t primitivesBefore = 0;       // the graph's primitives then
    uint32_t primitivesAfter = 0;        // and when it was finished
};

// Where a replayed interpretation stands in the build's numbering.
struct Replay {
    const ObjectOrigin& origin;
    uint32_t objects = 0;
    uint32_t primitives = 0;
    ObjectExpansion& expansion;
};

// Objects of one node already built whose reads were the same mask.
struct KeyedObjects {
    uint16_t mask = 0;
    std::unordered_map<StyleKey, uint32_t, StyleKeyHash> objects;
};

class GraphBuilder {
public:
    GraphBuilder(const BGrammar& bgrammar, const Grammar& grammar, const InstanceGraphOptions& options,
                 const SurfaceLibrary& surfaces, bool keepItems)
        : bgrammar_(bgrammar), options_(options), surfaces_(surfaces), keepItems_(keepItems),
          settings_(turtleSettings(grammar)), commands_(turtleCommands(grammar.symbols, grammar.style.cpfgModules)),
          summaries_(summarise(bgrammar, commands_)),
          oneObject_(placesInPlant(bgrammar, commands_) || !settings_.movements.empty()),
          lookup_(bgrammar.nodes.size()) {}

    InstanceGraph build() {
        graph_.nodes = bgrammar_.nodes.size();
        graph_.look = settings_.look;
        graph_.pixelLines = settings_.pixelLines;
        if (bgrammar_.nodes.empty()) return std::move(graph_);
        ObjectEntry start{initialTurtleState(settings_), glm::quat(1.0f, 0.0f, 0.0f, 0.0f), false};
        graph_.root = buildObject(bgrammar_.axiom(), start);
        if (settings_.pixelLines) growForPixelLines();
        if (keepItems_) return std::move(graph_);
        return graph_; // a lazy graph's builder keeps its objects for replays
    }

    // An object of node for this entry among the first `finished` objects
    // whose reads agree. Each (node, mask, key) names one object, entered
    // when it was finished: limited to the objects finished at some point of
    // the build, this is the answer the build got there.
    std::optional<uint32_t> existingObject(uint32_t node, const ObjectEntry& entry, uint32_t finished) const {
        for (const KeyedObjects& keyed : lookup_[node]) {
            auto found = keyed.objects.find(styleKey(entry, keyed.mask, options_.orientationGranularity));
            if (found != keyed.objects.end() && found->second < finished) return found->second;
        }
        return std::nullopt;
    }

    // An object of node for this entry: an existing one whose reads agree, or a new one.
    uint32_t objectFor(uint32_t node, const ObjectEntry& entry) {
        if (std::optional<uint32_t> found = existingObject(node, entry, UINT32_MAX)) return *found;
        const uint32_t object = buildObject(node, entry);
        const uint16_t mask = built_[object].reads;
        auto keyed = std::find_if(lookup_[node].begin(), lookup_[node].end(),
                                  [&](const KeyedObjects& k) { return k.mask == mask; });
        if (keyed == lookup_[node].end()) keyed = lookup_[node].insert(keyed, KeyedObjects{mask, {}});
        keyed->objects.emplace(styleKey(entry, mask, options_.orientationGranularity), object);
        return object;
    }

    uint32_t buildObject(uint32_t node, const ObjectEntry& entry);

    // The object the build placed where a replay stands: the one it found,
    // or the one it built there (which moved its numbering past that object).
    uint32_t replayedObjectFor(uint32_t node, const ObjectEntry& entry, Replay& replay) const {
        if (std::optional<uint32_t> found = existingObject(node, entry, replay.objects)) return *found;
        // Objects whose interpretations began together nest, outermost last:
        // the replayed object's own first new child, or the outermost.
        const uint32_t child = replay.objects == replay.origin.objectsBefore ? replay.origin.firstNewChild
                                                                             : outermostStartedAt_[replay.objects];
        replay.objects = child + 1;
        replay.primitives = origins_[child].primitivesAfter;
        return child;
    }

    ObjectExpansion expand(uint32_t object) const;

    // Lines drawn pixels wide become wider when flattened or exported
    // (InstanceGraph::pixelLines): every box grows by the widest of them, at
    // least what the flat plant's own bounds (within the root's) give.
    void growForPixelLines() {
        const float widest = widestSegmentRadius_ * worldPerPixel(graph_.objects[graph_.root].bounds);
        for (GraphObject& object : graph_.objects)
            if (!object.bounds.empty()) {
                object.bounds.min -= glm::vec3(widest);
                object.bounds.max += glm::vec3(widest);
            }
    }

    // Throws MemoryBudgetError when the graph with `primitives` more
    // primitives (and their items) would be past the budget: what it holds,
    // twice for the vectors' growth.
    void needRoomFor(uint64_t primitives) const {
        const uint64_t objectBytes = sizeof(GraphObject) + sizeof(BuiltObject) + sizeof(KeyedObjects) +
                                     (keepItems_ ? 0 : sizeof(ObjectOrigin) + sizeof(uint32_t));
        uint64_t bytes = bytesTimes(graph_.objects.size() + 1, objectBytes);
        bytes = bytesPlus(bytes, bytesTimes(graph_.items.size() + primitives, sizeof(GraphItem)));
        bytes = bytesPlus(bytes, bytesTimes(graph_.primitives.size() + primitives, sizeof(GraphPrimitive)));
        bytes = bytesPlus(bytes, bytesTimes(graph_.instances.size(), sizeof(GraphInstance)));
        need(options_.memory, "instance graph", bytesTimes(bytes, 2));
    }

    const BGrammar& bgrammar_;
    const InstanceGraphOptions& options_;
    const SurfaceLibrary& surfaces_;
    // false: a lazy graph's bounds pass, which keeps the objects and their
    // origins but none of their items, primitives, instances or polygons.
    const bool keepItems_;
    const TurtleSettings settings_;
    const std::vector<TurtleCommand> commands_;
    const std::vector<NodeSummary> summaries_;
    // Every node is interpreted inline: a module places the turtle in plant
    // space (placesInPlant), or the view file's movements bend it in plant
    // space by elasticities that are no StyleField.
    const bool oneObject_;
    std::vector<std::vector<KeyedObjects>> lookup_; // per node
    std::vector<BuiltObject> built_;                // per object
    std::unordered_map<std::string, uint32_t> surfaceIndex_;
    InstanceGraph graph_;
    uint32_t primitivesNumbered_ = 0; // graph_.primitives.size() when items are kept
    float widestSegmentRadius_ = 0.0f;
    std::vector<ObjectOrigin> origins_;        // per object, without kept items
    std::vector<uint32_t> outermostStartedAt_; // by objects finished then, without kept items
};

// Interprets one object's body (inlining the nodes that cannot be objects)
// from its local entry frame, and records its items, counts and bounds:
// building, into the graph (or, for a lazy graph, nowhere), or replaying
// an object the build made, into an expansion.
class ObjectInterpreter {
public:
    ObjectInterpreter(GraphBuilder& builder, const ObjectEntry& entry)
        : ObjectInterpreter(builder, entry, &builder, nullptr) {}
    ObjectInterpreter(const GraphBuilder& builder, Replay& replay)
        : ObjectInterpreter(builder, replay.origin.entry, nullptr, &replay) {}

private:
    ObjectInterpreter(const GraphBuilder& builder, const ObjectEntry& entry, GraphBuilder* building, Replay* replay)
        : b_(builder), building_(building), replay_(replay), entry_(entry), state_(entry.style),
          provenance_(Provenance::pristine()), chunk_(builder.surfaces_, builder.settings_.look) {
        state_.position = glm::vec3(0.0f);
        state_.heading = {0.0f, 1.0f, 0.0f};
        state_.left = {-1.0f, 0.0f, 0.0f};
        state_.up = {0.0f, 0.0f, 1.0f};
        state_.joint = -1; // the entry joint
        // A polygon open at the entry: F moves, and vertices go to it (the outer vertices).
        if (entry.polygonOpen) stack_.polygons.push_back({});
    }

public:
    void interpretBody(uint32_t node) {
        for (const BodyItem& item : b_.bgrammar_.bodyOf(node)) {
            if (!item.isNode()) {
                const TerminalModule& module = b_.bgrammar_.modules[item.index];
                applyTerminal(b_.commands_[module.symbol], b_.bgrammar_.parametersOf(module));
            } else if (b_.summaries_[item.index].object() && !b_.oneObject_) {
                placeInstance(item.index);
            } else {
                interpretBody(item.index);
            }
        }
    }

    // Closes the object: appends it to the graph with its status function.
    uint32_t finish(uint32_t node) {
        flushChunk();
        InstanceGraph& graph = building_->graph_;
        BuiltObject built;
        built.status.exit = {state_, provenance_, resolve(state_.joint)};
        for (size_t i = 0; i < stack_.branches.size(); ++i)
            built.status.pushed.push_back({stack_.branches[i], provenanceStack_[i], resolve(stack_.branches[i].joint)});
        if (entry_.polygonOpen) built.status.outerVertices = std::move(stack_.polygons.front().outline);
        built.reads = reads_ | exitReads(built.status);

        const uint32_t object = static_cast<uint32_t>(graph.objects.size());
        graph.objects.push_back({node, static_cast<uint32_t>(graph.items.size()), static_cast<uint32_t>(items_.size()),
                                 bounds_, primitives_, static_cast<uint64_t>(joints_)});
        graph.items.insert(graph.items.end(), items_.begin(), items_.end());
        building_->built_.push_back(std::move(built));
        return object;
    }

    // Closes a replayed object: its items, in the order the build made them.
    void finishReplay() {
        flushChunk();
        replay_->expansion.items = std::move(items_);
    }

    // The object whose interpretation this one built first, if any.
    uint32_t firstNewChild() const { return firstNewChild_; }

private:
    size_t localPolygons() const { return stack_.polygons.size() - (entry_.polygonOpen ? 1 : 0); }

    // A handle for TurtleState::joint (32 bits) standing for a JointRef (64).
    int32_t handleFor(JointRef ref) {
        if (ref == kEntryJoint) return -1;
        jointRefs_.push_back(ref);
        return static_cast<int32_t>(jointRefs_.size() - 1);
    }
    JointRef resolve(int32_t handle) const { return handle < 0 ? kEntryJoint : jointRefs_[handle]; }

    void applyTerminal(const TurtleCommand& command, std::span<const float> p) {
        if (skippingCut(command)) return;
        const size_t open = stack_.polygons.size();
        reads_ |= readsOf(command, p, state_, provenance_, open, localPolygons());
        switch (command.action) {
        case TurtleAction::Cut: cutDepth_ = 0; return;
        case TurtleAction::RollHorizontal: rollInPlantSpace(command, p); break;
        case TurtleAction::TropismVector:
            applyModule(command, p, b_.settings_, state_, stack_, chunk_);
            if (p.size() >= 3)
                state_.tropism = glm::conjugate(entry_.orientation) * state_.tropism; // to the entry frame
            break;
        default: applyModule(command, p, b_.settings_, state_, stack_, chunk_); break;
        }
        if (command.action == TurtleAction::Push) provenanceStack_.push_back(provenance_);
        if (command.action == TurtleAction::Pop && !provenanceStack_.empty()) {
            provenance_ = provenanceStack_.back();
            provenanceStack_.pop_back();
        }
        updateProvenance(command, p, open, provenance_);
        if (drawsSegment(command.action, open)) {
            // The builder numbered the joint within the chunk; it is the subtree's next.
            chunkSegments_.push_back(handleFor(joints_++));
            state_.joint = chunkSegments_.back();
        }
    }

    // '%' skips to the ']' closing its branch (as interpretModules does), which is applied.
    bool skippingCut(const TurtleCommand& command) {
        if (cutDepth_ < 0) return false;
        if (command.action == TurtleAction::Push) ++cutDepth_;
        if (command.action == TurtleAction::Pop) --cutDepth_;
        return cutDepth_ >= 0;
    }

    // `$` levels L against the world's vertical: applied to the first entry's
    // plant-space frame, which the key's world-up (kSourceWorldUp) stands for.
    void rollInPlantSpace(const TurtleCommand& command, std::span<const float> p) {
        const glm::mat3 toPlant = glm::mat3_cast(entry_.orientation);
        TurtleState plant = state_;
        plant.heading = toPlant * state_.heading;
        plant.left = toPlant * state_.left;
        plant.up = toPlant * state_.up;
        applyModule(command, p, b_.settings_, plant, stack_, chunk_);
        const glm::mat3 toLocal = glm::transpose(toPlant);
        state_.heading = toLocal * plant.heading;
        state_.left = toLocal * plant.left;
        state_.up = toLocal * plant.up;
    }

    void placeInstance(uint32_t node) {
        if (cutDepth_ >= 0) {
            cutDepth_ += b_.summaries_[node].bracketChange; // legal: it cannot close the cut branch
            return;
        }
        flushChunk();
        const Frame frame = frameOf(state_);
        const glm::mat3 toParent(-state_.left, state_.heading, state_.up);
        ObjectEntry entry{state_, entry_.orientation * frame.rotation, !stack_.polygons.empty()};
        entry.style.tropism = glm::transpose(toParent) * state_.tropism;
        const uint32_t child = replay_ ? b_.replayedObjectFor(node, entry, *replay_) : newOrExistingObject(node, entry);

        const BuiltObject& built = b_.built_[child];
        const GraphObject& object = b_.graph_.objects[child];
        reads_ |= parentReads(built.reads, provenance_, localPolygons());
        if (std::vector<GraphInstance>* instances = keptInstances()) {
            items_.push_back({GraphItem::Kind::Instance, static_cast<uint32_t>(instances->size())});
            instances->push_back({child, frame, resolve(state_.joint)});
        }
        bounds_.extend(transformed(object.bounds, frame));

        // The child's status function applied to the state where it starts.
        const JointRef offset = joints_;
        auto childJoint = [&](JointRef ref) { return ref == kEntryJoint ? state_.joint : handleFor(offset + ref); };
        for (const LocalState& pushed : built.status.pushed) {
            auto [state, provenance] = composeState(state_, provenance_, pushed, childJoint(pushed.joint));
            stack_.branches.push_back(state);
            provenanceStack_.push_back(provenance);
        }
        for (const glm::vec3& vertex : built.status.outerVertices)
            stack_.polygons.back().outline.push_back(state_.position + toParent * vertex);
        std::tie(state_, provenance_) =
            composeState(state_, provenance_, built.status.exit, childJoint(built.status.exit.joint));
        joints_ += static_cast<JointRef>(object.joints);
        primitives_ += object.primitives;
    }

    uint32_t newOrExistingObject(uint32_t node, const ObjectEntry& entry) {
        const size_t finished = b_.graph_.objects.size();
        const uint32_t child = building_->objectFor(node, entry);
        if (child >= finished && firstNewChild_ == UINT32_MAX) firstNewChild_ = child;
        return child;
    }

    // Where instances, primitives and polygons go: the graph's arrays, a
    // replay's expansion, or nowhere in a lazy graph's bounds pass.
    std::vector<GraphInstance>* keptInstances() const {
        if (replay_) return &replay_->expansion.instances;
        return b_.keepItems_ ? &building_->graph_.instances : nullptr;
    }
    std::vector<GraphPrimitive>* keptPrimitives() const {
        if (replay_) return &replay_->expansion.primitives;
        return b_.keepItems_ ? &building_->graph_.primitives : nullptr;
    }
    std::vector<PolygonShape>* keptPolygons() const {
        if (replay_) return &replay_->expansion.polygons;
        return b_.keepItems_ ? &building_->graph_.polygons : nullptr;
    }

    // The graph's index of a surface by name; a replay finds every name the build entered.
    uint32_t surfaceIndex(const std::string& name) {
        if (replay_) return b_.surfaceIndex_.at(name);
        InstanceGraph& graph = building_->graph_;
        auto [found, added] =
            building_->surfaceIndex_.try_emplace(name, static_cast<uint32_t>(graph.surfaceNames.size()));
        if (added) graph.surfaceNames.push_back(name);
        return found->second;
    }

    // Moves what the turtle drew since the last instance into the graph (or the expansion).
    void flushChunk() {
        PlantAsset drawn = chunk_.finish();
        if (building_) b_.needRoomFor(drawn.primitives.size());
        uint32_t& numbered = replay_ ? replay_->primitives : building_->primitivesNumbered_;
        std::vector<GraphPrimitive>* primitives = keptPrimitives();
        std::vector<PolygonShape>* polygons = keptPolygons();
        for (const Primitive& p : drawn.primitives) {
            GraphPrimitive primitive{p.frame, p.kind, p.material, p.shape, p.length, p.startRadius, p.endRadius};
            if (p.kind == PrimitiveKind::Segment) {
                const Joint& joint = drawn.joints[p.joint];
                primitive.joint = resolve(chunkSegments_[p.joint]);
                primitive.parentJoint = resolve(joint.parent);
                primitive.stiffness = joint.stiffness;
                if (building_)
                    building_->widestSegmentRadius_ =
                        std::max({building_->widestSegmentRadius_, p.startRadius, p.endRadius});
            } else {
                primitive.joint = resolve(p.joint);
            }
            if (p.kind == PrimitiveKind::Surface) primitive.shape = surfaceIndex(drawn.surfaces[p.shape].name);
            if (p.kind == PrimitiveKind::Polygon && polygons) {
                primitive.shape = static_cast<uint32_t>(polygons->size());
                polygons->push_back(std::move(drawn.polygons[p.shape]));
            }
            if (primitives) {
                items_.push_back({GraphItem::Kind::Primitive, static_cast<uint32_t>(primitives->size())});
                primitives->push_back(primitive);
            }
            if (replay_) replay_->expansion.primitiveIds.push_back(numbered);
            ++numbered;
        }
        primitives_ += drawn.primitives.size();
        bounds_.extend(drawn.bounds);
        chunkSegments_.clear();
    }

    const GraphBuilder& b_;
    GraphBuilder* building_; // null in a replay, which changes nothing of the builder's
    Replay* replay_;         // null while building
    uint32_t firstNewChild_ = UINT32_MAX;
    const ObjectEntry& entry_;
    TurtleState state_;
    TurtleStack stack_;
    Provenance provenance_;
    std::vector<Provenance> provenanceStack_; // beside stack_.branches
    uint16_t reads_ = 0;
    int cutDepth_ = -1;               // inside a cut branch: its depth so far
    std::vector<JointRef> jointRefs_; // what TurtleState::joint handles stand for
    JointRef joints_ = 0;             // the subtree's so far
    uint64_t primitives_ = 0;
    PlantAssetBuilder chunk_;            // primitives drawn since the last instance
    std::vector<int32_t> chunkSegments_; // handle of each joint the chunk's segments made
    std::vector<GraphItem> items_;
    Bounds bounds_;
};

uint32_t GraphBuilder::buildObject(uint32_t node, const ObjectEntry& entry) {
    if (graph_.objects.size() >= options_.maxObjects)
        throw DerivationError("the instance graph would hold more than " + std::to_string(options_.maxObjects) +
                              " objects");
    needRoomFor(0);
    ObjectOrigin origin{entry, static_cast<uint32_t>(graph_.objects.size()), UINT32_MAX, primitivesNumbered_, 0};
    ObjectInterpreter interpreter(*this, entry);
    interpreter.interpretBody(node);
    const uint32_t object = interpreter.finish(node);
    if (!keepItems_) {
        origin.firstNewChild = interpreter.firstNewChild();
        origin.primitivesAfter = primitivesNumbered_;
        origins_.push_back(std::move(origin));
        // Finished last of those that began together: the outermost.
        if (outermostStartedAt_.size() <= origins_.back().objectsBefore) outermostStartedAt_.resize(object + 1);
        outermostStartedAt_[origins_.back().objectsBefore] = object;
    }
    return object;
}

ObjectExpansion GraphBuilder::expand(uint32_t object) const {
    const ObjectOrigin& origin = origins_.at(object);
    ObjectExpansion expansion;
    Replay replay{origin, origin.objectsBefore, origin.primitivesBefore, expansion};
    ObjectInterpreter interpreter(*this, replay);
    interpreter.interpretBody(graph_.objects[object].node);
    interpreter.finishReplay();
    return expansion;
}

} // namespace graph_build

using graph_build::GraphBuilder;

namespace {

void requireInterpretedWord(const BGrammar& bgrammar, const Grammar& grammar) {
    if (!grammar.interpretation.empty() && !bgrammar.interpreted)
        throw std::invalid_argument("the instance graph needs the b-grammar of the interpreted word "
                                    "(BGrammarOptions::interpreted)");
}

} // namespace

InstanceGraph buildInstanceGraph(const BGrammar& bgrammar, const Grammar& grammar, const InstanceGraphOptions& options,
                                 const SurfaceLibrary& surfaces) {
    requireInterpretedWord(bgrammar, grammar);
    return GraphBuilder(bgrammar, grammar, options, surfaces, true).build();
}

// The builder of a lazy graph with what it reads: it stays, to replay objects.
struct GraphDerivation {
    GraphDerivation(const BGrammar& bgrammar, const Grammar& grammar, const InstanceGraphOptions& options,
                    const SurfaceLibrary& surfaces)
        : bgrammar(bgrammar), options(options), surfaces(surfaces.meshDirectories()),
          builder(this->bgrammar, grammar, this->options, this->surfaces, false) {}
    const BGrammar bgrammar;
    const InstanceGraphOptions options;
    const SurfaceLibrary surfaces; // the same folders, its own cache
    GraphBuilder builder;
};

LazyInstanceGraph deriveLazyInstanceGraph(const BGrammar& bgrammar, const Grammar& grammar,
                                          const InstanceGraphOptions& options, const SurfaceLibrary& surfaces) {
    requireInterpretedWord(bgrammar, grammar);
    auto derivation = std::make_shared<GraphDerivation>(bgrammar, grammar, options, surfaces);
    InstanceGraph graph = derivation->builder.build();
    return {std::move(graph), std::move(derivation)};
}

ObjectExpansion expandObject(const LazyInstanceGraph& graph, uint32_t object) {
    return graph.derivation->builder.expand(object);
}

} // namespace lsys
