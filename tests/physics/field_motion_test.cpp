// The field's motion (engine/physics/field_motion.h): preparing a frame
// submits no GPU work, and the frame's command buffer takes every sub-step —
// the catch-up from rest included — exactly as dispatches submitted one by
// one would. Validation on.
#include "engine/physics/field_motion.h"
#include "engine/scene/field_content.h"
#include "gpu_test.h"

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
