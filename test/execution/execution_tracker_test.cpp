// The execution tracker (execution_tracker.h): what it releases as progress comes in, who holds
// a robot, progress that never goes back, done, and misuse refused.
#include "fleet_planner/execution/execution_tracker.h"

#include <gtest/gtest.h>

#include "fleet_planner/runtime/errors.h"

namespace fleet_planner {
namespace {

using Report = ExecutionTracker::Report;

// The follower of step_dependencies_test: a (4 states) goes first, b (5 states) follows one
// step behind; b's moves 1, 2, 3 need a at states 1, 2, 3.
Plan followerPlan() {
  Plan plan;
  plan.paths = {{{1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}}, {{0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}};
  return plan;
}

StepDependencies followerDependencies() {
  StepDependencies deps;
  deps.before = {{{}, {}, {}}, {{}, {{0, 1}}, {{0, 2}}, {{0, 3}}}};
  return deps;
}

TEST(ExecutionTracker, ReleasesWhatTheProgressOfOthersAllows) {
  ExecutionTracker tracker(followerPlan(), followerDependencies());
  EXPECT_EQ(tracker.releasedUpTo(0), 3);  // a needs nothing: to its end
  EXPECT_FALSE(tracker.blockedBy(0));
  EXPECT_EQ(tracker.releasedUpTo(1), 1);  // b passes its wait, then its move 1 waits for a
  ASSERT_TRUE(tracker.blockedBy(1));
  EXPECT_EQ(*tracker.blockedBy(1), (Requirement{0, 1}));

  EXPECT_EQ(tracker.reportProgress(0, 1), Report::Advanced);
  EXPECT_EQ(tracker.releasedUpTo(1), 2);
  EXPECT_EQ(*tracker.blockedBy(1), (Requirement{0, 2}));
  EXPECT_EQ(tracker.reportProgress(0, 3), Report::Advanced);  // a jump over states is fine
  EXPECT_EQ(tracker.releasedUpTo(1), 4);
  EXPECT_FALSE(tracker.blockedBy(1));
}

TEST(ExecutionTracker, ProgressNeverGoesBack) {
  ExecutionTracker tracker(followerPlan(), followerDependencies());
  EXPECT_EQ(tracker.reportProgress(0, 2), Report::Advanced);
  EXPECT_EQ(tracker.reportProgress(0, 1), Report::Ignored);
  EXPECT_EQ(tracker.reportProgress(0, 2), Report::Ignored);
  EXPECT_EQ(tracker.progress(0), 2);
  EXPECT_EQ(tracker.releasedUpTo(1), 3);  // still released as far as a's state 2 allows
}

TEST(ExecutionTracker, AReportBeyondTheReleaseIsRecordedAndFlagged) {
  ExecutionTracker tracker(followerPlan(), followerDependencies());
  EXPECT_EQ(tracker.reportProgress(1, 1), Report::Advanced);  // its wait: released
  EXPECT_EQ(tracker.reportProgress(1, 2), Report::Overran);   // its move 1 was not
  EXPECT_EQ(tracker.progress(1), 2);
}

TEST(ExecutionTracker, DoneWhenEveryRobotHasReachedItsLastState) {
  ExecutionTracker tracker(followerPlan(), followerDependencies());
  EXPECT_FALSE(tracker.done());
  tracker.reportProgress(0, 3);
  EXPECT_TRUE(tracker.done(0));
  EXPECT_FALSE(tracker.done(1));
  EXPECT_FALSE(tracker.done());
  tracker.reportProgress(1, 4);
  EXPECT_TRUE(tracker.done());

  Plan still;  // a robot whose path is one state is done from the start
  still.paths = {{{0, 0, 0}}};
  StepDependencies none;
  none.before = {{}};
  EXPECT_TRUE(ExecutionTracker(still, none).done());
}

TEST(ExecutionTracker, RefusesMisuse) {
  ExecutionTracker tracker(followerPlan(), followerDependencies());
  EXPECT_THROW(tracker.reportProgress(2, 1), InvalidInput);
  EXPECT_THROW(tracker.reportProgress(0, 4), InvalidInput);
  EXPECT_THROW(tracker.reportProgress(0, -1), InvalidInput);
  EXPECT_THROW(tracker.releasedUpTo(-1), InvalidInput);

  StepDependencies short_list = followerDependencies();
  short_list.before[1].pop_back();
  EXPECT_THROW(ExecutionTracker(followerPlan(), short_list), InvalidInput);
  StepDependencies unknown = followerDependencies();
  unknown.before[1][1] = {{0, 7}};  // a has no state 7
  EXPECT_THROW(ExecutionTracker(followerPlan(), unknown), InvalidInput);
}

}  // namespace
}  // namespace fleet_planner
