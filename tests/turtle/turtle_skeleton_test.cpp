// What the turtle builds around the primitives: the joint skeleton, organs
// attached to joints, the material table, the bounds, the frame convention
// of plant_asset.h, and the per-module state transition the InstanceGraph
// composes.

#include <cmath>
#include <numbers>

#include "lsystem/dialects/dialect.h"
#include "lsystem/rewriting/plant_from_grammar.h"
#include "turtle_test_support.h"

namespace lsys::test {
namespace {

std::vector<int32_t> parentsOf(const PlantAsset& plant) {
    std::vector<int32_t> parents;
    for (const Joint& joint : plant.joints) parents.push_back(joint.parent);
    return parents;
}

TEST(LsysTurtleSkeleton, EverySegmentIsAJointOnItsPath) {
    const PlantAsset plant = plantOf("Axiom: F[+F[-F]F]F[-F]\n");
    EXPECT_EQ(parentsOf(plant), (std::vector<int32_t>{-1, 0, 1, 1, 0, 4}));
    ASSERT_EQ(plant.primitives.size(), plant.joints.size());
    for (size_t i = 0; i < plant.primitives.size(); ++i) {
        const Primitive& segment = plant.primitives[i];
        const Joint& joint = plant.joints[i];
        EXPECT_EQ(segment.joint, static_cast<int32_t>(i)); // a segment is its own joint
        expectNear(joint.rest.position, segment.frame.position);
        EXPECT_NEAR(std::abs(glm::dot(joint.rest.rotation, segment.frame.rotation)), 1.0f, 1e-6f);
        EXPECT_FLOAT_EQ(joint.length, segment.length);
    }
}

TEST(LsysTurtleSkeleton, JointsStartAtTheirParentsTip) {
    const PlantAsset plant = plantOf("angle: 30\nAxiom: F(2)[&F/F]+F(0.5)[^F]F\n");
    for (const Joint& joint : plant.joints) {
        if (joint.parent < 0) continue;
        const Joint& parent = plant.joints[static_cast<size_t>(joint.parent)];
        expectNear(joint.rest.position, parent.rest.position + headingOf(parent.rest) * parent.length);
    }
}

TEST(LsysTurtleSkeleton, MovesDoNotBreakTheChain) {
    EXPECT_EQ(parentsOf(plantOf("Axiom: Ff(2)F\n")), (std::vector<int32_t>{-1, 0}));
}

TEST(LsysTurtleSkeleton, JointRadiiThroughBranches) {
    const PlantAsset plant = plantOf("width: 2\nAxiom: F[!(1)F(1,0.5)]F(1,1)F\n");
    ASSERT_EQ(plant.joints.size(), 4u);
    EXPECT_FLOAT_EQ(plant.joints[0].startRadius, 1.0f);
    EXPECT_FLOAT_EQ(plant.joints[1].startRadius, 0.5f);
    EXPECT_FLOAT_EQ(plant.joints[1].endRadius, 0.25f);
    EXPECT_FLOAT_EQ(plant.joints[2].startRadius, 1.0f); // the branch's width was popped
    EXPECT_FLOAT_EQ(plant.joints[2].endRadius, 0.5f);
    EXPECT_FLOAT_EQ(plant.joints[3].startRadius, 0.5f);
}

TEST(LsysTurtleSkeleton, CrankshawSpringConstantBecomesStiffness) {
    ParseResult parsed =
        parseDialect(Dialect::Crankshaw, "#n = 1;\n#w : A;\n#p1 : A : * : F(1, 30)[+(20)F(0.5, 12)]F(1, 30);\n");
    ASSERT_TRUE(parsed.ok());
    const PlantAsset plant = plantFromGrammar(parsed.grammar, derive(parsed.grammar));
    EXPECT_EQ(stiffnessOf(plant), (std::vector<float>{30, 12, 30}));
    EXPECT_EQ(parentsOf(plant), (std::vector<int32_t>{-1, 0, 0}));
    EXPECT_FLOAT_EQ(plant.joints.at(1).length, 0.5f);
}

TEST(LsysTurtleSkeleton, OrgansAttachToTheSegmentTheyGrowOn) {
    const PlantAsset plant = plantOf("angle: 90\nAxiom: ~leaf F[+F~leaf@O(1)]F~petal[{.f.+f.+f.}]\n");
    std::vector<int32_t> organJoints;
    for (const Primitive& p : plant.primitives)
        if (p.kind != PrimitiveKind::Segment) organJoints.push_back(p.joint);
    EXPECT_EQ(organJoints, (std::vector<int32_t>{-1, 1, 1, 2, 2}));
}

TEST(LsysTurtleSkeleton, PolygonTakesTheFrameMaterialAndJointOfItsBrace) {
    const PlantAsset plant = plantOf("angle: 90\nAxiom: F;(4){.f.;(6)+f.+f.}\n");
    ASSERT_EQ(plant.primitives.size(), 2u);
    const Primitive& polygon = plant.primitives[1];
    EXPECT_EQ(polygon.kind, PrimitiveKind::Polygon);
    EXPECT_EQ(polygon.material, 4u);
    EXPECT_EQ(polygon.joint, 0);
    expectNear(polygon.frame.position, {0, 1, 0});
}

TEST(LsysTurtleSkeleton, FrameMapsLocalAxesToTheTurtle) {
    // Local +Y -> H, -X -> L, +Z -> U; the start frame is the identity.
    EXPECT_EQ(frameOf(TurtleState{}).rotation, glm::quat(1, 0, 0, 0));
    TurtleState state;
    state.heading = glm::normalize(glm::vec3(1, 1, 0));
    state.left = glm::normalize(glm::vec3(-1, 1, 0));
    state.up = glm::cross(state.heading, state.left);
    const Frame frame = frameOf(state);
    expectNear(headingOf(frame), state.heading);
    expectNear(leftOf(frame), state.left);
    expectNear(frame.rotation * glm::vec3(0, 0, 1), state.up);
}

TEST(LsysTurtleSkeleton, MaterialTableHoldsThePaletteAndEveryIndexUsed) {
    const PlantAsset plant = plantOf("Axiom: F;(12)F\n");
    ASSERT_EQ(plant.materials.size(), 13u);
    EXPECT_EQ(plant.materials[0].name, "bark");
    EXPECT_EQ(plant.materials[1].name, "leaf");
    EXPECT_EQ(plant.materials[2].name, "petal");
    EXPECT_FALSE(plant.materials[0].twoSided);
    EXPECT_TRUE(plant.materials[1].twoSided);
    EXPECT_TRUE(plant.materials[2].twoSided);
    EXPECT_EQ(plant.materials[12].name, "fruit 12"); // the palette repeats
    EXPECT_EQ(plant.materials[12].albedo, plant.materials[4].albedo);
    for (const Primitive& p : plant.primitives) EXPECT_LT(p.material, plant.materials.size());
}

TEST(LsysTurtleSkeleton, MaterialsOfSurfacesAndPolygonsAreTwoSided) {
    const PlantAsset plant = plantOf("angle: 90\nAxiom: F~leaf;(3){.f.+f.+f.};(4)F\n");
    EXPECT_TRUE(plant.materials[0].twoSided);  // a leaf drawn with the bark material
    EXPECT_TRUE(plant.materials[3].twoSided);  // a polygon
    EXPECT_FALSE(plant.materials[4].twoSided); // segments only
}

// Points on the surface of every primitive, in plant space.
std::vector<glm::vec3> geometryOf(const PlantAsset& plant) {
    std::vector<glm::vec3> points;
    for (const Primitive& p : plant.primitives) {
        const glm::mat3 axes = glm::mat3_cast(p.frame.rotation);
        switch (p.kind) {
        case PrimitiveKind::Segment:
            for (int k = 0; k < 64; ++k) {
                const float a = 2.0f * std::numbers::pi_v<float> * static_cast<float>(k) / 64.0f;
                const glm::vec3 around = axes * glm::vec3(std::cos(a), 0, std::sin(a));
                points.push_back(p.frame.position + around * p.startRadius);
                points.push_back(p.frame.position + axes[1] * p.length + around * p.endRadius);
            }
            break;
        case PrimitiveKind::Sphere:
            for (int axis = 0; axis < 3; ++axis)
                for (float sign : {-1.0f, 1.0f}) {
                    glm::vec3 offset(0.0f);
                    offset[axis] = sign * p.startRadius;
                    points.push_back(p.frame.position + offset);
                }
            break;
        case PrimitiveKind::Surface:
            for (const glm::vec3& v : plant.surfaces[p.shape].positions)
                points.push_back(p.frame.position + p.frame.rotation * (v * p.length));
            break;
        case PrimitiveKind::Polygon:
            for (const glm::vec3& v : plant.polygons[p.shape].outline) points.push_back(v);
            break;
        }
    }
    return points;
}

TEST(LsysTurtleSkeleton, BoundsContainEveryPrimitive) {
    const PlantAsset plant = plantOf(
        "angle: 40\nwidth: 0.3\nAxiom: F(2)[&F~leaf(1.5)][/&@O(0.8)]!(0.1)^F(1,0.05)~petal[{.f.+f.+f.}]F(-1)\n");
    ASSERT_FALSE(plant.bounds.empty());
    const std::vector<glm::vec3> points = geometryOf(plant);
    ASSERT_GT(points.size(), 100u);
    glm::vec3 lowest(1e30f), highest(-1e30f);
    for (const glm::vec3& p : points) {
        for (int axis = 0; axis < 3; ++axis) {
            EXPECT_GE(p[axis], plant.bounds.min[axis] - 1e-5f);
            EXPECT_LE(p[axis], plant.bounds.max[axis] + 1e-5f);
        }
        lowest = glm::min(lowest, p);
        highest = glm::max(highest, p);
    }
    // And they are not much larger than the geometry (surfaces are bounded by their box).
    expectNear(plant.bounds.min, lowest, 0.2f);
    expectNear(plant.bounds.max, highest, 0.2f);
}

TEST(LsysTurtleSkeleton, BoundsOfASegmentIncludeItsRadius) {
    const PlantAsset plant = plantOf("width: 2\nAxiom: F(3)\n");
    expectNear(plant.bounds.min, {-1, 0, -1});
    expectNear(plant.bounds.max, {1, 3, 1});
    EXPECT_TRUE(plantOf("Axiom: f\n").bounds.empty());
}

// The state transition: interpreting a string in two pieces, the second from
// the state and stack the first left, gives what interpreting it whole gives.
TEST(LsysTurtleSkeleton, InterpretationComposesFromAnyEntryState) {
    ParseResult parsed = parseLsystem("angle: 30\nAxiom: F[+F{.f.]@K(2)!(0.5)F&(10)\\(20)F~leaf.}[-F]F\n");
    ASSERT_TRUE(parsed.ok());
    const ModuleString whole = derive(parsed.grammar);
    const TurtleSettings settings = turtleSettings(parsed.grammar);
    const PlantAsset expected = interpretPlant(whole, parsed.grammar.symbols, settings, SurfaceLibrary{});

    // Split inside the open branch and the open polygon.
    const size_t split = 8;
    ModuleString first, second;
    for (size_t i = 0; i < whole.size(); ++i) (i < split ? first : second).push(whole.symbols[i], whole.parameters(i));

    const std::vector<TurtleCommand> commands = turtleCommands(parsed.grammar.symbols);
    const SurfaceLibrary surfaces;
    PlantAssetBuilder builder(surfaces);
    TurtleState state = initialTurtleState(settings);
    TurtleStack stack;
    interpretModules(first, commands, settings, state, stack, builder);
    EXPECT_EQ(stack.branches.size(), 1u);
    EXPECT_EQ(stack.polygons.size(), 1u);
    interpretModules(second, commands, settings, state, stack, builder);
    const PlantAsset pieces = builder.finish();
    ASSERT_EQ(pieces.primitives.size(), expected.primitives.size());
    for (size_t i = 0; i < expected.primitives.size(); ++i) {
        expectNear(pieces.primitives[i].frame.position, expected.primitives[i].frame.position);
        EXPECT_EQ(pieces.primitives[i].joint, expected.primitives[i].joint);
    }
    EXPECT_EQ(pieces.polygons.size(), 1u);
}

TEST(LsysTurtleSkeleton, AModuleActsOnTheStateItIsGiven) {
    const SurfaceLibrary surfaces;
    PlantAssetBuilder builder(surfaces);
    TurtleState state;
    state.position = {5, 0, 0};
    state.heading = {1, 0, 0};
    state.left = {0, 1, 0};
    state.up = {0, 0, 1};
    state.width = 0.5f;
    state.joint = 7; // a joint of an enclosing node
    state.stiffness = 4.0f;
    TurtleStack stack;
    const float length = 2.0f;
    applyModule(turtleCommand("F"), std::span<const float>(&length, 1), TurtleSettings{}, state, stack, builder);
    expectNear(state.position, {7, 0, 0});
    EXPECT_EQ(state.joint, 0);
    const PlantAsset plant = builder.finish();
    ASSERT_EQ(plant.joints.size(), 1u);
    EXPECT_EQ(plant.joints[0].parent, 7);
    EXPECT_EQ(plant.joints[0].stiffness, 4.0f);
    EXPECT_FLOAT_EQ(plant.joints[0].startRadius, 0.25f);
    expectNear(plant.joints[0].rest.position, {5, 0, 0});
}

} // namespace
} // namespace lsys::test
