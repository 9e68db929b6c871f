#pragma once
// A planning answer checked as the planning tests need it: SUCCESS, and the plan valid on the
// map's own cells by the independent validator, on the steps it is returned on (PlanningResult::plan_step).
#include <gtest/gtest.h>

#include "fleet_planner/model/plan_validator.h"
#include "fleet_planner/planning/plan_fleet.h"

namespace fleet_planner::test {

inline ::testing::AssertionResult validOnCells(const GridMap& map, const Instance& instance,
                                               const PlanningResult& r) {
  if (!r.success())
    return ::testing::AssertionFailure() << statusName(r.status) << ": " << r.reason;
  ActionModel model;
  model.step = r.plan_step;
  const ValidationResult v = validatePlan(map, instance, r.plan, model);
  if (!v.valid()) return ::testing::AssertionFailure() << v.violation.message;
  return ::testing::AssertionSuccess();
}

}  // namespace fleet_planner::test
