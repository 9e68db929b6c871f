// fleet_planner_node: loads and checks the configuration, loads the backend plugins, and serves
// PlanFleet until shutdown. A bad configuration stops it at startup with every problem named.
#include <cstdlib>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <ros/ros.h>

#include "fleet_planner/ros/backend_loader.h"
#include "fleet_planner/ros/planner_config.h"
#include "fleet_planner/ros/planner_node.h"

int main(int argc, char** argv) {
#ifdef __GLIBC__
  // Blocks of 1 MiB and more (a search's tables) from mmap, and back to the system when freed.
  // Without a fixed threshold glibc raises it to the largest block freed so far, and later
  // tables of that size come from the threads' arenas, where the node, planning and re-planning
  // for hours, keeps them: its resident memory then stays at several times what it uses.
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
#endif
  ros::init(argc, argv, "fleet_planner");
  ros::NodeHandle nh, private_nh("~");
  try {
    const fleet_planner::PlannerConfig config = fleet_planner::loadPlannerConfig(private_nh);
    for (const auto& name : fleet_planner::unknownPlannerParameters(private_nh)) {
      ROS_WARN("fleet_planner: unknown parameter %s (ignored; see config/planner.yaml)", name.c_str());
    }
    fleet_planner::BackendPlugins plugins;
    for (const auto& p : plugins.load()) ROS_WARN("fleet_planner: %s", p.c_str());
    // Every parameter is checked here, the backends against the plugins just loaded: a bad one
    // stops the node now rather than failing each call.
    auto problems = fleet_planner::checkPlannerConfig(config);
    for (const auto& p : fleet_planner::checkPlannerBackends(config)) problems.push_back(p);
    for (const auto& p : problems) ROS_FATAL("fleet_planner: parameter %s/%s", private_nh.getNamespace().c_str(), p.c_str());
    if (!problems.empty()) return 1;
    const std::string backend = fleet_planner::resolveBackendName(config.backend, nullptr);
    std::string names;
    for (const auto& n : plugins.declared()) names += " " + n;
    ROS_INFO("fleet_planner: backend plugins:%s; default backend %s", names.c_str(), backend.c_str());

    fleet_planner::PlannerNode node(nh, private_nh, config);
    ros::AsyncSpinner spinner(2);  // map, registry, playback; PlanFleet has its own threads
    spinner.start();
    ros::waitForShutdown();
  } catch (const std::exception& e) {
    ROS_FATAL("fleet_planner: %s", e.what());
    return 1;
  }
  return 0;
}
