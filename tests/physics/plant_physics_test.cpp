// The plant physics (engine/physics/plant_physics.h, docs/PHYSICS.md) against
// physics: a rod settles where its spring balances its weight, an undamped
// joint swings with period 2π·sqrt(I/k), energy only decays without wind,
// every plant of data/plants stays finite in a gale over the whole stiffness
// range, and the model's parameters follow beam theory and the leaves.
#include "engine/physics/plant_physics.h"
#include "engine/scene/plant_models.h"
#include "shaders/shared/joint_physics.h"

#include "lsystem/dialects/dialect.h"
#include "lsystem/language/parser.h"
#include "lsystem/rewriting/plant_from_grammar.h"
#include "lsystem/rewriting/rewriter.h"
#include "lsystem/turtle/surfaces.h"
#include "lsystem/turtle/turtle.h"

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <optional>

namespace {

const std::filesystem::path kData = PLANTFIELD_DATA_DIR;
constexpr float kPi = std::numbers::pi_v<float>;

// One segment of `length` and `radius` in the rest frame `rest` at the origin.
lsys::PlantAsset rodAsset(const glm::quat& rest, float length, float radius, float stiffness = 0.0f) {
    lsys::PlantAsset asset;
    asset.materials = {{"bark", glm::vec3(0.5f), false}, {"leaf", glm::vec3(0.3f), true}};
    asset.joints.push_back({-1, {glm::vec3(0.0f), rest}, length, radius, radius, stiffness});
    asset.primitives.push_back(
        {{glm::vec3(0.0f), rest}, lsys::PrimitiveKind::Segment, 0, 0, 0, length, radius, radius});
    return asset;
}

// Rest frame turning the segment's +Y onto plant +X: a horizontal rod.
glm::quat horizontal() { return glm::angleAxis(-0.5f * kPi, glm::vec3(0, 0, 1)); }

pf::SkeletonSet oneSkeleton(std::vector<gpu::JointParams> params, float scale = 1.0f) {
    pf::SkeletonSet set;
    set.params = std::move(params);
    pf::addSkeleton(set, 0, 0, uint32_t(set.params.size()), glm::vec3(3.0f, 0.0f, -2.0f), 0.4f, scale);
    return set;
}

pf::Wind calm() {
    pf::Wind wind;
    wind.speed = 0.0f;
    return wind;
}

pf::Wind gale() {
    pf::Wind wind;
    wind.speed = 20.0f;
    wind.directionDegrees = 30.0f;
    wind.gustStrength = 0.8f;
    wind.gustSpeed = 12.0f;
    wind.turbulence = 0.4f;
    return wind;
}

// `frames` frames of `subSteps` sub-steps each, the poses recomputed after each.
void simulate(pf::SkeletonSet& set, const pf::Wind& wind, const pf::PhysicsSettings& settings, uint32_t frames,
              uint32_t subSteps = 1, uint64_t firstStep = 0) {
    for (uint32_t frame = 0; frame < frames; ++frame) {
        const uint64_t step = firstStep + uint64_t(frame) * subSteps;
        const gpu::PhysicsUniforms u =
            pf::makePhysicsUniforms(wind, settings, float(double(step) * settings.subStep), settings.subStep, subSteps,
                                    uint32_t(set.skeletons.size()), uint32_t(set.states.size()));
        pf::stepSkeletonsOnCpu(set, u);
        pf::poseSkeletonsOnCpu(set);
    }
}

glm::vec3 rotationVector(const gpu::JointState& s) { return gpu::rotationVectorOf(s.rotation); }
glm::vec3 xyz(const gpu::vec4& v) { return {v.x, v.y, v.z}; }

// A root joint's energy: kinetic, spring and the height of the weight it carries.
double energyOf(const gpu::JointParams& p, const gpu::JointState& s, const pf::PhysicsSettings& settings) {
    const glm::vec3 omega = xyz(s.angularVelocity);
    const double angle = glm::length(rotationVector(s));
    const gpu::vec4 frame = gpu::quatMultiply(p.restRotation, s.rotation);
    const double height = gpu::quatRotate(frame, xyz(p.load)).y;
    return 0.5 * p.dynamics.y * glm::dot(omega, omega) + 0.5 * p.dynamics.z * angle * angle +
           double(p.load.w) * settings.gravity * height;
}

// Derives and interprets a plant file as plant_models does; nothing when it
// does not parse or derive within the module budget.
std::optional<lsys::PlantAsset> plantOf(const std::filesystem::path& file) {
    std::string problem;
    const std::string source = lsys::readTextFile(file.string(), problem);
    if (!problem.empty()) return std::nullopt;
    lsys::ParseOptions options;
    options.file = file.string();
    lsys::ParseResult parsed = lsys::parseDialect(std::nullopt, source, options);
    if (!parsed.ok()) return std::nullopt;
    lsys::DeriveOptions derive;
    derive.maxModules = 400'000;
    try {
        const lsys::ModuleString derived = lsys::derive(parsed.grammar, derive);
        return lsys::plantFromGrammar(parsed.grammar, derived, lsys::SurfaceLibrary(lsys::meshDirectoriesFor(file)));
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

// The scale that makes a plant `height` metres tall (its largest extent when it has no height).
float scaleTo(const lsys::PlantAsset& asset, float height) {
    if (asset.bounds.empty()) return 1.0f;
    const glm::vec3 size = asset.bounds.max - asset.bounds.min;
    return height / std::max({size.x, size.y, size.z, 1e-6f});
}

// Every state and pose finite, quaternions unit, angular speeds below `maxSpeed`.
void expectFiniteAndBounded(const pf::SkeletonSet& set, float maxSpeed, const std::string& what) {
    float fastest = 0.0f;
    for (size_t i = 0; i < set.states.size(); ++i) {
        const gpu::JointState& s = set.states[i];
        const gpu::JointPose& p = set.poses[i];
        for (int c = 0; c < 4; ++c) {
            ASSERT_TRUE(std::isfinite(s.rotation[c]) && std::isfinite(s.angularVelocity[c]) &&
                        std::isfinite(p.rotation[c]) && std::isfinite(p.translation[c]))
                << what << " joint " << i;
        }
        ASSERT_NEAR(glm::length(glm::vec4(s.rotation)), 1.0f, 1e-4f) << what << " joint " << i;
        ASSERT_LE(glm::length(rotationVector(s)), kPi + 1e-4f) << what << " joint " << i;
        fastest = std::max(fastest, glm::length(xyz(s.angularVelocity)));
    }
    EXPECT_LT(fastest, maxSpeed) << what;
}

// The branch-free log and exp of joint_physics.h against the exact formulas
// in double precision, over every angle they are documented for, about
// axes in all directions.
TEST(PlantPhysics, RotationLogMatchesExactFormulaOverTheWholeAngleRange) {
    double worst = 0.0;
    for (int a = 0; a <= 1000; ++a) {
        const double angle = std::numbers::pi * a / 1000.0;
        const glm::dvec3 axis = glm::normalize(glm::dvec3(std::sin(0.37 * a), std::cos(0.11 * a), 0.5));
        const glm::dvec3 exact = axis * angle;
        for (double sign : {1.0, -1.0}) { // q and −q are the same rotation
            const glm::dvec3 v = axis * std::sin(0.5 * angle) * sign;
            const gpu::vec4 q(float(v.x), float(v.y), float(v.z), float(std::cos(0.5 * angle) * sign));
            const glm::dvec3 got(gpu::rotationVectorOf(q));
            // Near π the axis flips with float rounding of w: compare the turn.
            const double error =
                angle < std::numbers::pi - 1e-3 ? glm::length(got - exact) : std::abs(glm::length(got) - angle);
            worst = std::max(worst, error);
        }
    }
    EXPECT_LT(worst, 2e-6) << "rad";
    EXPECT_EQ(gpu::rotationVectorOf(gpu::vec4(0.0f, 0.0f, 0.0f, 1.0f)), glm::vec3(0.0f));
}

TEST(PlantPhysics, RotationExpIsExactUpToOneRadianAndCloseUpToPi) {
    for (int a = 0; a <= 1000; ++a) {
        const double angle = std::numbers::pi * a / 1000.0;
        const glm::dvec3 axis = glm::normalize(glm::dvec3(0.3, std::cos(0.07 * a), std::sin(0.07 * a)));
        const gpu::vec4 q = glm::normalize(gpu::quatFromRotationVector(glm::vec3(axis * angle)));
        // The turn it makes, and about which axis.
        const glm::dvec3 back(gpu::rotationVectorOf(q));
        const double tolerance = angle <= 1.0 ? 2e-6 : 1e-4;
        EXPECT_NEAR(glm::length(back), angle, tolerance) << "at " << angle << " rad";
        // At π itself the axis is only defined up to sign.
        if (angle > 1e-3 && angle < std::numbers::pi - 1e-3) {
            EXPECT_GT(glm::dot(glm::normalize(back), axis), 1.0 - 1e-6) << "at " << angle << " rad";
        }
    }
}

TEST(PlantPhysics, RodSettlesWhereSpringBalancesWeight) {
    pf::PhysicsSettings settings;
    settings.dampingRatio = 1.0f;
    // A horizontal rod drooping by θ carries its weight M·g at d·cos θ from
    // the base: it rests where k·θ = M·g·d·cos θ. Choosing θ* sets k exactly.
    for (float expected : {0.05f, 0.3f, 0.8f, 1.2f}) {
        std::vector<gpu::JointParams> params =
            pf::buildJointParams(rodAsset(horizontal(), 1.2f, 0.02f), 1.0f, settings);
        gpu::JointParams& p = params[0];
        const double weightTorque = double(p.load.w) * settings.gravity * p.load.y;
        ASSERT_NEAR(p.load.y, 0.6f, 1e-6f); // a rod's centre of mass is half way
        p.dynamics.z = float(weightTorque * std::cos(double(expected)) / expected);
        p.dynamics.w = 2.0f * settings.dampingRatio * std::sqrt(p.dynamics.z * p.dynamics.y);
        pf::SkeletonSet set = oneSkeleton(params);
        simulate(set, calm(), settings, 240 * 30);
        const glm::vec3 droop = rotationVector(set.states[0]);
        const glm::vec3 tip = gpu::quatRotate(gpu::quatMultiply(p.restRotation, set.states[0].rotation), {0, 1, 0});
        std::cout << "settled at " << glm::length(droop) << " rad, analytic " << expected << " rad\n";
        EXPECT_NEAR(glm::length(droop), expected, 1e-3f);
        EXPECT_LT(tip.y, 0.0f) << "the rod droops down";
        EXPECT_LT(glm::length(xyz(set.states[0].angularVelocity)), 1e-4f);
    }
}

TEST(PlantPhysics, UndampedPeriodIsTwoPiSqrtInertiaOverStiffness) {
    pf::PhysicsSettings settings;
    settings.dampingRatio = 0.0f;
    settings.gravity = 0.0f;
    settings.airDensity = 0.0f;
    settings.subStep = 1.0f / 240.0f;
    for (float radius : {0.01f, 0.02f}) {
        const std::vector<gpu::JointParams> params =
            pf::buildJointParams(rodAsset(glm::quat(1, 0, 0, 0), 1.0f, radius), 1.0f, settings);
        pf::SkeletonSet set = oneSkeleton(params);
        set.states[0].rotation = gpu::quatFromRotationVector({0.01f, 0.0f, 0.0f});
        const double expected = 2.0 * std::numbers::pi * std::sqrt(double(params[0].dynamics.y) / params[0].dynamics.z);
        std::vector<double> upward; // times the angle crosses zero going up
        double previous = rotationVector(set.states[0]).x;
        for (uint32_t step = 1; upward.size() < 6 && step < 240 * 60; ++step) {
            simulate(set, calm(), settings, 1, 1, step - 1);
            const double angle = rotationVector(set.states[0]).x;
            if (previous < 0.0 && angle >= 0.0)
                upward.push_back(settings.subStep * (step - 1 + previous / (previous - angle)));
            previous = angle;
        }
        ASSERT_EQ(upward.size(), 6u);
        const double period = (upward.back() - upward.front()) / 5.0;
        std::cout << "period " << period << " s, 2π·sqrt(I/k) " << expected << " s, error "
                  << 100.0 * (period / expected - 1.0) << " %\n";
        EXPECT_NEAR(period / expected, 1.0, 0.02);
    }
}

TEST(PlantPhysics, EnergyOnlyDecaysWithoutWind) {
    pf::PhysicsSettings settings; // default damping, gravity and air
    const std::vector<gpu::JointParams> params =
        pf::buildJointParams(rodAsset(horizontal(), 1.0f, 0.01f), 1.0f, settings);
    ASSERT_GT(params[0].dynamics.z, params[0].load.w * settings.gravity * params[0].load.y);
    pf::SkeletonSet set = oneSkeleton(params);
    double energy = energyOf(params[0], set.states[0], settings);
    const double start = energy;
    // Float states carry about 7 digits of each term, which are of the order M·g·d.
    const double rounding = 1e-6 * params[0].load.w * settings.gravity * params[0].load.y;
    for (uint32_t step = 0; step < 240 * 20; ++step) {
        simulate(set, calm(), settings, 1, 1, step);
        const double next = energyOf(params[0], set.states[0], settings);
        ASSERT_LE(next, energy + rounding) << "step " << step;
        energy = next;
    }
    EXPECT_LT(energy, start) << "released from rest it falls and loses energy";
    EXPECT_LT(glm::length(xyz(set.states[0].angularVelocity)), 1e-4f) << "and comes to rest";

    // A whole plant, bent and let go in still air, comes to rest too.
    const std::optional<lsys::PlantAsset> plant = plantOf(kData / "plants" / "leafy_bush.lsys");
    ASSERT_TRUE(plant);
    pf::SkeletonSet bush = oneSkeleton(pf::buildJointParams(*plant, scaleTo(*plant, 1.4f), settings));
    for (gpu::JointState& s : bush.states) s.angularVelocity = gpu::vec4(2.0f, 0.0f, -1.0f, 0.0f);
    simulate(bush, calm(), settings, 60 * 30, 4);
    float fastest = 0.0f;
    for (const gpu::JointState& s : bush.states) fastest = std::max(fastest, glm::length(xyz(s.angularVelocity)));
    EXPECT_LT(fastest, 1e-2f);
}

// Plant files to stress: every .lsys and the dialect files without an .lsys twin.
std::vector<std::filesystem::path> plantFiles() {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(kData / "plants"))
        if (entry.path().extension() == ".lsys") files.push_back(entry.path());
    for (const auto& entry : std::filesystem::directory_iterator(kData / "plants" / "dialects")) {
        const std::filesystem::path twin = kData / "plants" / entry.path().stem().concat(".lsys");
        if (entry.path().extension() != ".lsys" && !std::filesystem::exists(twin)) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

TEST(PlantPhysics, EveryPlantStaysFiniteInAGale) {
    const pf::PhysicsSettings settings;
    size_t simulated = 0;
    for (const std::filesystem::path& file : plantFiles()) {
        const std::optional<lsys::PlantAsset> plant = plantOf(file);
        if (!plant || plant->joints.empty()) continue;
        if (plant->joints.size() > 30'000) {
            std::cout << "skipped (too many joints for the CPU): " << file.filename() << "\n";
            continue;
        }
        pf::SkeletonSet set = oneSkeleton(pf::buildJointParams(*plant, scaleTo(*plant, 6.0f), settings));
        simulate(set, gale(), settings, 150, 4); // 600 steps
        expectFiniteAndBounded(set, 2000.0f, file.filename().string());
        ++simulated;
    }
    EXPECT_GE(simulated, 20u);
}

TEST(PlantPhysics, WholeStiffnessRangeStaysFinite) {
    const pf::PhysicsSettings settings;
    const std::optional<lsys::PlantAsset> plant = plantOf(kData / "plants" / "broadleaf.lsys");
    ASSERT_TRUE(plant);
    const std::vector<gpu::JointParams> built = pf::buildJointParams(*plant, scaleTo(*plant, 12.0f), settings);
    for (float stiffness = 1e-6f; stiffness <= 1.5e6f; stiffness *= 100.0f) {
        std::vector<gpu::JointParams> params = built;
        for (gpu::JointParams& p : params) {
            p.dynamics.z = stiffness;
            p.dynamics.w = 2.0f * settings.dampingRatio * std::sqrt(stiffness * p.dynamics.y);
        }
        pf::SkeletonSet set = oneSkeleton(params, 1.3f);
        simulate(set, gale(), settings, 150, 4);
        expectFiniteAndBounded(set, 2000.0f, "k = " + std::to_string(stiffness));
    }
}

TEST(PlantPhysics, RestPoseAtTimeZero) {
    const pf::PhysicsSettings settings;
    const std::optional<lsys::PlantAsset> plant = plantOf(kData / "plants" / "broadleaf.lsys");
    ASSERT_TRUE(plant);
    pf::SkeletonSet set = oneSkeleton(pf::buildJointParams(*plant, scaleTo(*plant, 12.0f), settings));
    const std::vector<gpu::JointState> rest = set.states;
    EXPECT_EQ(pf::subStepsBetween(0.0, 0.0, settings), 0u);
    const gpu::PhysicsUniforms u =
        pf::makePhysicsUniforms(gale(), settings, 0.0f, settings.subStep, pf::subStepsBetween(0.0, 0.0, settings), 1,
                                uint32_t(set.states.size()));
    pf::stepSkeletonsOnCpu(set, u);
    pf::poseSkeletonsOnCpu(set);
    ASSERT_EQ(std::memcmp(rest.data(), set.states.data(), rest.size() * sizeof(gpu::JointState)), 0);
    for (size_t i = 0; i < set.poses.size(); ++i) {
        const glm::vec3 base = xyz(set.params[i].restBase);
        // The map moves no rest point: a point of the joint and one 12 m away.
        EXPECT_LT(glm::distance(gpu::posePoint(set.poses[i], base), base), 1e-5f) << "joint " << i;
        EXPECT_LT(glm::distance(gpu::posePoint(set.poses[i], base + glm::vec3(12.0f)), base + glm::vec3(12.0f)), 1e-5f);
        EXPECT_NEAR(std::abs(set.poses[i].rotation.w), 1.0f, 1e-6f) << "joint " << i;
    }
}

TEST(PlantPhysics, SubStepsDependOnlyOnTheTimesReached) {
    pf::PhysicsSettings settings;
    settings.subStep = 1.0f / 240.0f;
    EXPECT_EQ(pf::subStepsBetween(0.0, 1.0, settings), 240u);
    EXPECT_EQ(pf::subStepsBetween(0.0, 10.0, settings), 2400u);
    // Frames of any length add up to the same steps as one jump.
    uint64_t total = 0;
    double t = 0.0;
    for (double frame : {0.013, 0.0167, 0.031, 0.0005, 0.0166, 0.3}) {
        total += pf::subStepsBetween(t, t + frame, settings);
        t += frame;
    }
    EXPECT_EQ(total, pf::subStepsBetween(0.0, t, settings));
}

TEST(PlantPhysics, BeamTheoryStiffnessAndStiffnessOverride) {
    pf::PhysicsSettings settings;
    const auto stiffnessOf = [&](float length, float radius, float k) {
        return pf::buildJointParams(rodAsset(glm::quat(1, 0, 0, 0), length, radius, k), 1.0f, settings)[0].dynamics.z;
    };
    const float thin = stiffnessOf(1.0f, 0.01f, 0.0f);
    EXPECT_NEAR(thin, settings.youngsModulus * kPi * std::pow(0.01f, 4.0f) / 4.0f, 1e-4f * thin);
    EXPECT_NEAR(stiffnessOf(1.0f, 0.02f, 0.0f) / thin, 16.0f, 1e-3f) << "k ∝ r⁴";
    EXPECT_NEAR(stiffnessOf(2.0f, 0.01f, 0.0f) / thin, 0.5f, 1e-4f) << "k ∝ 1/l";
    EXPECT_EQ(stiffnessOf(1.0f, 0.01f, 3.5f), 3.5f) << "@K wins";
    EXPECT_EQ(stiffnessOf(1.0f, 0.08f, 3.5f), 3.5f) << "@K wins whatever the radius";
    settings.stiffnessScale = 2.0f;
    EXPECT_NEAR(stiffnessOf(1.0f, 0.01f, 0.0f), 2.0f * thin, 1e-4f * thin);
    EXPECT_EQ(stiffnessOf(1.0f, 0.01f, 3.5f), 7.0f);
    // @K is physical: the height scale does not change it; beam theory scales as s³.
    settings.stiffnessScale = 1.0f;
    const lsys::PlantAsset k = rodAsset(glm::quat(1, 0, 0, 0), 1.0f, 0.01f, 3.5f);
    EXPECT_EQ(pf::buildJointParams(k, 3.0f, settings)[0].dynamics.z, 3.5f);
    const lsys::PlantAsset beam = rodAsset(glm::quat(1, 0, 0, 0), 1.0f, 0.01f);
    EXPECT_NEAR(pf::buildJointParams(beam, 3.0f, settings)[0].dynamics.z, 27.0f * thin, 1e-3f * 27.0f * thin);
    // Mass, inertia and damping as documented.
    const gpu::JointParams p = pf::buildJointParams(beam, 1.0f, settings)[0];
    EXPECT_NEAR(p.dynamics.x, settings.woodDensity * kPi * 1e-4f, 1e-6f);
    EXPECT_NEAR(p.dynamics.y, p.dynamics.x / 3.0f, 1e-7f);
    EXPECT_NEAR(p.dynamics.w, 2.0f * settings.dampingRatio * std::sqrt(p.dynamics.z * p.dynamics.y), 1e-6f);
}

TEST(PlantPhysics, DegenerateJointsStayFinite) {
    const pf::PhysicsSettings settings;
    lsys::PlantAsset asset = rodAsset(horizontal(), 0.0f, 0.0f);
    asset.joints.push_back({0, {glm::vec3(0.0f), horizontal()}, 0.5f, 0.0f, 0.0f, 0.0f});
    asset.joints.push_back({1, {glm::vec3(0.5f, 0, 0), horizontal()}, 0.0f, 0.01f, 0.01f, 0.0f});
    const std::vector<gpu::JointParams> params = pf::buildJointParams(asset, 1.0f, settings);
    for (const gpu::JointParams& p : params)
        for (int c = 0; c < 4; ++c)
            ASSERT_TRUE(std::isfinite(p.dynamics[c]) && std::isfinite(p.load[c]) && std::isfinite(p.aero[c]));
    pf::SkeletonSet set = oneSkeleton(params);
    simulate(set, gale(), settings, 150, 4);
    expectFiniteAndBounded(set, 1e6f, "degenerate joints");
}

TEST(PlantPhysics, LeavesAddDragAndChildrenLoadTheirParent) {
    pf::PhysicsSettings settings;
    settings.leafDrag = 1.5f;
    lsys::PlantAsset asset = rodAsset(glm::quat(1, 0, 0, 0), 1.0f, 0.02f);
    const std::vector<gpu::JointParams> bare = pf::buildJointParams(asset, 2.0f, settings);

    // A 0.2 × 0.3 leaf card, drawn at length 0.5, hanging at the segment's tip.
    lsys::SurfaceMesh leaf;
    leaf.positions = {{-0.1f, 0.0f, 0.0f}, {0.1f, 0.0f, 0.0f}, {0.0f, 0.3f, 0.0f}};
    asset.surfaces.push_back(leaf);
    lsys::Primitive card;
    card.frame.position = glm::vec3(0.0f, 1.0f, 0.0f);
    card.kind = lsys::PrimitiveKind::Surface;
    card.material = 1;
    card.joint = 0;
    card.length = 0.5f;
    asset.primitives.push_back(card);
    const std::vector<gpu::JointParams> leafy = pf::buildJointParams(asset, 2.0f, settings);
    const float cardArea = 0.2f * 0.3f * 0.5f * 0.5f * 2.0f * 2.0f;
    EXPECT_NEAR(leafy[0].aero.x - bare[0].aero.x, settings.leafDrag * cardArea, 1e-5f);
    EXPECT_GT(leafy[0].aero.y, bare[0].aero.y) << "the leaf at the tip moves the centre of pressure out";
    EXPECT_LE(leafy[0].aero.y, leafy[0].restBase.w);
    EXPECT_GT(leafy[0].load.w, bare[0].load.w) << "leaves weigh";
    EXPECT_GT(leafy[0].dynamics.y, bare[0].dynamics.y) << "and turn with the joint";

    // A blade (two-sided segment) is foliage: leaf drag instead of Cd.
    lsys::PlantAsset blade = rodAsset(glm::quat(1, 0, 0, 0), 1.0f, 0.02f);
    blade.primitives[0].material = 1;
    EXPECT_NEAR(pf::buildJointParams(blade, 1.0f, settings)[0].aero.x, settings.leafDrag * 2.0f * 0.02f, 1e-6f);

    // A child bent off the parent's tip: the parent carries both masses.
    asset = rodAsset(glm::quat(1, 0, 0, 0), 1.0f, 0.02f);
    const glm::quat bent = glm::angleAxis(0.5f * kPi, glm::vec3(0, 0, 1)); // +Y → −X
    asset.joints.push_back({0, {glm::vec3(0, 1, 0), bent}, 1.0f, 0.01f, 0.01f, 0.0f});
    asset.primitives.push_back({{glm::vec3(0, 1, 0), bent}, lsys::PrimitiveKind::Segment, 0, 1, 0, 1.0f, 0.01f, 0.01f});
    const std::vector<gpu::JointParams> tree = pf::buildJointParams(asset, 1.0f, settings);
    ASSERT_EQ(tree.size(), 2u);
    EXPECT_EQ(tree[1].links.x, 0u);
    EXPECT_EQ(tree[1].links.y, 1u);
    EXPECT_EQ(tree[0].links.x, JOINT_NO_PARENT);
    const float m0 = tree[0].dynamics.x, m1 = tree[1].dynamics.x;
    EXPECT_NEAR(tree[0].load.w, m0 + m1, 1e-6f);
    EXPECT_NEAR(tree[1].load.w, m1, 1e-7f);
    // Centre of mass in the parent's rest frame: its own at (0, ½), the child's at (−½, 1).
    const glm::vec3 expected = (m0 * glm::vec3(0, 0.5f, 0) + m1 * glm::vec3(-0.5f, 1.0f, 0)) / (m0 + m1);
    EXPECT_LT(glm::distance(xyz(tree[0].load), expected), 1e-5f);
    // The child's, in its own rest frame: straight along its segment.
    EXPECT_LT(glm::distance(xyz(tree[1].load), glm::vec3(0, 0.5f, 0)), 1e-5f);
    // The parent turns the child with it: the child, a rod about its centre (−½, 1), adds m₁·(1/12 + 5/4).
    EXPECT_NEAR(tree[1].dynamics.y, m1 / 3.0f, 1e-7f);
    EXPECT_NEAR(tree[0].dynamics.y, m0 / 3.0f + m1 * (1.0f / 12.0f + 1.25f), 1e-6f);
}

TEST(PlantPhysics, RunsAreIdenticalBitForBit) {
    const pf::PhysicsSettings settings;
    const std::optional<lsys::PlantAsset> plant = plantOf(kData / "plants" / "broadleaf.lsys");
    ASSERT_TRUE(plant);
    const std::vector<gpu::JointParams> params = pf::buildJointParams(*plant, scaleTo(*plant, 12.0f), settings);
    EXPECT_EQ(0, std::memcmp(params.data(), pf::buildJointParams(*plant, scaleTo(*plant, 12.0f), settings).data(),
                             params.size() * sizeof(gpu::JointParams)));
    pf::SkeletonSet a = oneSkeleton(params), b = oneSkeleton(params);
    simulate(a, gale(), settings, 50, 4);
    simulate(b, gale(), settings, 50, 4);
    EXPECT_EQ(0, std::memcmp(a.states.data(), b.states.data(), a.states.size() * sizeof(gpu::JointState)));
    EXPECT_EQ(0, std::memcmp(a.poses.data(), b.poses.data(), a.poses.size() * sizeof(gpu::JointPose)));
    bool moved = false;
    for (const gpu::JointState& s : a.states) moved = moved || s.rotation.w != 1.0f;
    EXPECT_TRUE(moved);
}

// Angle between two rotations (rad), from the rotation taking one to the other.
float angleBetween(const gpu::vec4& a, const gpu::vec4& b) {
    return glm::length(gpu::rotationVectorOf(gpu::quatMultiply(a, gpu::quatConjugate(b))));
}

// The default forest in its own wind: broadleaf twigs sway visibly, trunks
// barely. The sway is measured against the pose the tree settles into
// without wind (gravity alone bends it too).
TEST(PlantPhysics, DefaultForestSwaysTwigsMoreThanTrunks) {
    const pf::Scene scene = pf::loadScene(kData / "scenes" / "default.json");
    const pf::PlantModelPool pool = pf::buildPlantModels(scene);
    ASSERT_EQ(pool.models.size(), pool.firstModel.back() + scene.species.back().variants);
    for (const pf::PlantModelInfo& model : pool.models) {
        ASSERT_LE(uint64_t(model.firstJoint) + model.joints, pool.joints.size()) << model.name;
        for (uint32_t lod = 0; lod < pf::kMeshLodCount; ++lod)
            for (const pf::MeshRange& range : model.meshes[lod])
                for (uint32_t i = 0; i < range.indexCount; ++i)
                    ASSERT_LT(pool.vertices[range.vertexOffset + pool.indices[range.firstIndex + i]].joint.x,
                              std::max(model.joints, 1u))
                        << model.name;
    }
    const pf::PlantModelInfo& tree = pool.models[pool.modelOf(0, 0)];
    ASSERT_EQ(scene.species[0].name, "broadleaf");
    pf::SkeletonSet set;
    set.params = pool.joints;
    pf::addSkeleton(set, pool.modelOf(0, 0), tree.firstJoint, tree.joints, glm::vec3(0.0f), 0.0f, 1.0f);
    const uint32_t settleFrames = 60 * 20;
    simulate(set, calm(), scene.physics, settleFrames, 4);
    const std::vector<gpu::JointPose> settled = set.poses;

    const auto params = [&](uint32_t j) { return set.params[tree.firstJoint + j]; };
    std::vector<bool> hasChild(tree.joints, false);
    float thickest = 0.0f; // mass per length, ∝ r²
    for (uint32_t j = 0; j < tree.joints; ++j) {
        if (params(j).links.x != JOINT_NO_PARENT) hasChild[params(j).links.x] = true;
        thickest = std::max(thickest, params(j).dynamics.x / params(j).restBase.w);
    }
    std::vector<float> sway(tree.joints, 0.0f), sag(tree.joints, 0.0f);
    for (uint32_t j = 0; j < tree.joints; ++j) sag[j] = angleBetween(settled[j].rotation, gpu::vec4(0, 0, 0, 1));
    const uint64_t start = uint64_t(settleFrames) * 4;
    for (uint32_t second = 0; second < 20 * 60; ++second) {
        simulate(set, scene.wind, scene.physics, 1, 4, start + uint64_t(second) * 4);
        for (uint32_t j = 0; j < tree.joints; ++j)
            sway[j] = std::max(sway[j], angleBetween(set.poses[j].rotation, settled[j].rotation));
    }
    std::vector<float> twigs, trunk, twigSag, trunkSag;
    for (uint32_t j = 0; j < tree.joints; ++j) {
        const float massPerLength = params(j).dynamics.x / params(j).restBase.w; // ∝ r²
        if (!hasChild[j]) {
            twigs.push_back(sway[j]);
            twigSag.push_back(sag[j]);
        } else if (massPerLength >= 0.25f * thickest) { // r at least half the thickest
            trunk.push_back(sway[j]);
            trunkSag.push_back(sag[j]);
        }
    }
    ASSERT_FALSE(twigs.empty());
    ASSERT_FALSE(trunk.empty());
    const auto median = [](std::vector<float> v) {
        std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
        return v[v.size() / 2];
    };
    const float twigSway = median(twigs), trunkSway = *std::max_element(trunk.begin(), trunk.end());
    std::cout << tree.name << ": " << tree.joints << " joints; twigs sway (median of max) " << twigSway
              << " rad, trunk sway (max) " << trunkSway << " rad; gravity sag: twigs (median) " << median(twigSag)
              << " rad, trunk (max) " << *std::max_element(trunkSag.begin(), trunkSag.end()) << " rad\n";
    EXPECT_GT(twigSway, 0.1f);
    EXPECT_LT(twigSway, 0.5f);
    EXPECT_LT(trunkSway, 0.02f);
}

} // namespace
