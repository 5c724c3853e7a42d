// The field's motion (engine/physics/field_motion.h): preparing a frame
// submits no GPU work, and the frame's command buffer takes every sub-step —
// the catch-up from rest included — exactly as dispatches submitted one by
// one would. Validation on.
#include "engine/physics/field_motion.h"
#include "engine/scene/field_content.h"
#include "gpu_test.h"

#include <cmath>
#include <cstring>
#include <set>

namespace pf {
namespace {

class FieldMotionTest : public test::GpuTest {
protected:
    void SetUp() override {
        test::GpuTest::SetUp();
        content = buildFieldContent(loadScene(std::string(PLANTFIELD_DATA_DIR) + "/scenes/gust.json"));
    }

    struct Snapshot {
        std::vector<gpu::JointState> states;
        std::vector<gpu::JointPose> poses;
        bool operator==(const Snapshot& o) const {
            return states.size() == o.states.size() && poses.size() == o.poses.size() &&
                   std::memcmp(states.data(), o.states.data(), states.size() * sizeof(gpu::JointState)) == 0 &&
                   std::memcmp(poses.data(), o.poses.data(), poses.size() * sizeof(gpu::JointPose)) == 0;
        }
    };
    Snapshot snapshot(const FieldMotion& motion) {
        Snapshot s;
        readPhysicsState(ctx, motion.pass, s.states, s.poses);
        return s;
    }

    FieldContent content;
    // Near the broadleaf, so near plants get skeletons of their own (copies in the plan).
    const glm::vec3 camera{-5.0f, 2.0f, 4.0f};
};

TEST_F(FieldMotionTest, PreparingAFrameRunsNoPhysics) {
    FieldMotion motion = createFieldMotion(resources, content);
    const Snapshot rest = snapshot(motion);
    advanceFieldMotion(motion, 3.0, true, camera, false);
    EXPECT_TRUE(snapshot(motion) == rest) << "advanceFieldMotion stepped the simulation itself";
    EXPECT_TRUE(motion.next.restart);
    EXPECT_FALSE(motion.next.ownStates.empty()) << "the camera stands by the broadleaf";
}

// The shared copies simulated are exactly those some plant follows: of a
// field cut down to one plant, one.
TEST_F(FieldMotionTest, SimulatesOnlyTheSharedCopiesSomePlantFollows) {
    for (const size_t plants : {content.plants.size(), size_t(1)}) {
        content.plants.resize(plants);
        FieldMotion motion = createFieldMotion(resources, content);
        size_t own = 0;
        for (const std::vector<uint32_t>& free : motion.near.freeOfModel) own += free.size();
        const size_t shared = motion.pass.skeletonCount - own;
        const std::set<uint32_t> followed(motion.sharedOf.begin(), motion.sharedOf.end());
        EXPECT_EQ(followed.size(), shared) << plants << " plants";
        EXPECT_EQ(*followed.rbegin(), shared - 1) << plants << " plants";
    }
    EXPECT_EQ(content.plants.size(), 1u);
}

TEST_F(FieldMotionTest, PlanCoversEveryStepFromRestInFrameSizedDispatches) {
    FieldMotion motion = createFieldMotion(resources, content);
    const double time = 7.5; // from rest at 2.5 s
    advanceFieldMotion(motion, time, true, camera, false);
    const PhysicsSettings& settings = content.scene.physics;
    uint64_t step = subStepsUntil(time - kSettleSeconds, settings);
    for (const gpu::PhysicsDispatch& d : motion.next.dispatches) {
        EXPECT_GT(d.subSteps, 0u);
        EXPECT_LE(d.subSteps, kFrameSubSteps);
        EXPECT_EQ(d.time, float(double(step) * settings.subStep));
        step += d.subSteps;
    }
    EXPECT_EQ(step, subStepsUntil(time, settings));
    EXPECT_EQ(motion.simulatedStep, step);
}

// In real time a gap between frames longer than one dispatch is one
// dispatch of longer sub-steps, up to twice the scene's; beyond that the
// wind slows. Captures keep the scene's sub-step.
TEST_F(FieldMotionTest, RealTimeTakesALongGapInOneDispatchOfLongerSubSteps) {
    FieldMotion motion = createFieldMotion(resources, content);
    const PhysicsSettings& settings = content.scene.physics;
    const double step = settings.subStep;
    double time = 3.0;
    advanceFieldMotion(motion, time, true, camera, true);
    EXPECT_DOUBLE_EQ(motion.next.subStepSeconds, step) << "the catch-up from rest";
    struct Gap {
        uint64_t steps;
        bool realTime;
        std::vector<uint32_t> dispatches;
        double stepsPerSubStep;
    };
    for (const Gap& gap : {Gap{5, true, {5}, 1.0}, Gap{12, true, {8}, 1.5}, Gap{16, true, {8}, 2.0},
                           Gap{40, true, {8}, 2.0}, Gap{12, false, {8, 4}, 1.0}}) {
        const uint64_t before = subStepsUntil(time, settings);
        time = double(before + gap.steps) * step;
        advanceFieldMotion(motion, time, false, camera, gap.realTime);
        std::vector<uint32_t> counts;
        for (const gpu::PhysicsDispatch& d : motion.next.dispatches) counts.push_back(d.subSteps);
        EXPECT_EQ(counts, gap.dispatches) << gap.steps << " steps";
        EXPECT_NEAR(motion.next.subStepSeconds, gap.stepsPerSubStep * step, 1e-12) << gap.steps << " steps";
        EXPECT_EQ(motion.simulatedStep, subStepsUntil(time, settings)) << gap.steps << " steps";
        const uint64_t simulated = gap.realTime ? std::min<uint64_t>(gap.steps, kMaxFrameGapSubSteps) : gap.steps;
        EXPECT_EQ(motion.next.dispatches.front().time, float(double(motion.simulatedStep - simulated) * step))
            << gap.steps << " steps";
    }
}

// The longer sub-steps sway the plants as the scene's do: three seconds of
// strong gusts in frames of a window at 15 frames a second (8 sub-steps of
// 1/120 s) against the same frames at the scene's 1/240 s.
TEST_F(FieldMotionTest, RealTimeSubStepsSwayAsTheScenesDo) {
    auto swayAfter = [&](bool realTime) {
        FieldMotion motion = createFieldMotion(resources, content);
        for (int frame = 0; frame <= 45; ++frame) {
            advanceFieldMotion(motion, 2.0 + frame / 15.0, frame == 0, camera, realTime);
            submitAndWait(ctx, [&](VkCommandBuffer cmd) { recordFieldMotion(cmd, motion); });
        }
        if (realTime) {
            EXPECT_NEAR(motion.next.subStepSeconds, 2.0 * content.scene.physics.subStep, 1e-9);
        }
        std::vector<float> angles;
        for (const gpu::JointState& s : snapshot(motion).states)
            angles.push_back(2.0f * std::acos(std::min(std::abs(s.rotation.w), 1.0f)));
        return angles;
    };
    const std::vector<float> fixed = swayAfter(false), longer = swayAfter(true);
    ASSERT_EQ(fixed.size(), longer.size());
    double fixedSum = 0.0, longerSum = 0.0, differenceSum = 0.0;
    float largestDifference = 0.0f, largest = 0.0f;
    for (size_t i = 0; i < fixed.size(); ++i) {
        ASSERT_TRUE(std::isfinite(longer[i])) << "joint " << i;
        fixedSum += fixed[i] * fixed[i];
        longerSum += longer[i] * longer[i];
        differenceSum += (fixed[i] - longer[i]) * (fixed[i] - longer[i]);
        largestDifference = std::max(largestDifference, std::abs(fixed[i] - longer[i]));
        largest = std::max(largest, fixed[i]);
    }
    const double fixedRms = std::sqrt(fixedSum / fixed.size()), longerRms = std::sqrt(longerSum / fixed.size());
    const double differenceRms = std::sqrt(differenceSum / fixed.size());
    std::printf("sway rms: fixed %.4f, longer %.4f, difference %.4f rad; largest %.3f, largest difference %.3f rad\n",
                fixedRms, longerRms, differenceRms, largest, largestDifference);
    EXPECT_GT(fixedRms, 0.01) << "the gusts should bend the plants";
    EXPECT_NEAR(longerRms, fixedRms, 0.1 * fixedRms);
    EXPECT_LT(differenceRms, 0.25 * fixedRms);
    EXPECT_LT(largestDifference, 0.25f * largest) << "a joint strayed: the longer sub-steps are unstable";
}

TEST_F(FieldMotionTest, OneRecordedFrameEqualsItsDispatchesSubmittedOneByOne) {
    FieldMotion recorded = createFieldMotion(resources, content);
    FieldMotion oneByOne = createFieldMotion(resources, content);
    const Snapshot rest = snapshot(recorded);
    advanceFieldMotion(recorded, 2.0, true, camera, false);
    advanceFieldMotion(oneByOne, 2.0, true, camera, false);
    ASSERT_GT(recorded.next.dispatches.size(), 1u);

    submitAndWait(ctx, [&](VkCommandBuffer cmd) { recordFieldMotion(cmd, recorded); });
    // The same copies, then each dispatch in a submit of its own.
    FieldMotionFrame copiesOnly = oneByOne.next;
    copiesOnly.dispatches.clear();
    const std::vector<gpu::PhysicsDispatch> dispatches = oneByOne.next.dispatches;
    oneByOne.next = copiesOnly;
    oneByOne.next.dispatches = {dispatches.front()};
    submitAndWait(ctx, [&](VkCommandBuffer cmd) { recordFieldMotion(cmd, oneByOne); });
    for (size_t i = 1; i < dispatches.size(); ++i)
        submitAndWait(ctx, [&](VkCommandBuffer cmd) { recordPhysicsPass(cmd, oneByOne.pass, {&dispatches[i], 1}); });

    const Snapshot a = snapshot(recorded), b = snapshot(oneByOne);
    EXPECT_FALSE(a == rest) << "two seconds of gusts moved nothing";
    EXPECT_TRUE(a == b) << "one command buffer and one submit per dispatch disagree";
}

} // namespace
} // namespace pf
