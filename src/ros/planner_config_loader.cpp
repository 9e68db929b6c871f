// loadPlannerConfig: the parameter server -> PlannerConfig, with type checks that name the
// parameter (ros::NodeHandle::param would silently keep the default for a mistyped value).
#include <ros/param.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include "fleet_planner/runtime/errors.h"
#include "fleet_planner/ros/planner_config.h"

namespace fleet_planner {

namespace {

class Reader {
 public:
  explicit Reader(const ros::NodeHandle& nh) : nh_(nh) {}

  void read(const char* name, double& out) {
    XmlRpc::XmlRpcValue v;
    if (!get(name, v)) return;
    if (v.getType() == XmlRpc::XmlRpcValue::TypeDouble) out = static_cast<double>(v);
    else if (v.getType() == XmlRpc::XmlRpcValue::TypeInt) out = static_cast<int>(v);
    else wrongType(name, "a number", v);
  }
  void read(const char* name, int& out) {
    XmlRpc::XmlRpcValue v;
    if (!get(name, v)) return;
    if (v.getType() != XmlRpc::XmlRpcValue::TypeInt) wrongType(name, "an integer", v);
    out = static_cast<int>(v);
  }
  void read(const char* name, bool& out) {
    XmlRpc::XmlRpcValue v;
    if (!get(name, v)) return;
    if (v.getType() != XmlRpc::XmlRpcValue::TypeBoolean) wrongType(name, "true or false", v);
    out = static_cast<bool>(v);
  }
  /// {backend: {option: number or bool}}.
  void read(const char* name, BackendParameters& out) {
    XmlRpc::XmlRpcValue v;
    if (!get(name, v)) return;
    if (v.getType() != XmlRpc::XmlRpcValue::TypeStruct) wrongType(name, "a dictionary {backend: {option: value}}", v);
    for (auto& [backend, options] : v) {
      if (options.getType() != XmlRpc::XmlRpcValue::TypeStruct) {
        wrongType((std::string(name) + "/" + backend).c_str(), "a dictionary {option: value}", options);
      }
      for (auto& [option, value] : options) {
        const std::string full = std::string(name) + "/" + backend + "/" + option;
        if (value.getType() == XmlRpc::XmlRpcValue::TypeDouble) out[backend][option] = static_cast<double>(value);
        else if (value.getType() == XmlRpc::XmlRpcValue::TypeInt) out[backend][option] = static_cast<int>(value);
        else if (value.getType() == XmlRpc::XmlRpcValue::TypeBoolean) out[backend][option] = static_cast<bool>(value) ? 1 : 0;
        else wrongType(full.c_str(), "a number or true/false", value);
      }
    }
  }
  void read(const char* name, std::string& out) {
    XmlRpc::XmlRpcValue v;
    if (!get(name, v)) return;
    if (v.getType() != XmlRpc::XmlRpcValue::TypeString) wrongType(name, "a string", v);
    out = static_cast<std::string>(v);
  }

 private:
  bool get(const char* name, XmlRpc::XmlRpcValue& v) const { return nh_.getParam(name, v); }
  static std::string describe(XmlRpc::XmlRpcValue& v) {
    std::string xml = v.toXml();  // "<value>abc</value>", "<value><double>1.5</double></value>"
    for (const char* tag : {"<value>", "</value>"}) {
      for (auto at = xml.find(tag); at != std::string::npos; at = xml.find(tag)) xml.erase(at, std::string(tag).size());
    }
    return xml;
  }
  [[noreturn]] void wrongType(const char* name, const char* expected, XmlRpc::XmlRpcValue& v) const {
    throw InvalidInput("parameter " + nh_.resolveName(name) + " must be " + expected + " (got " + describe(v) + ")");
  }
  const ros::NodeHandle& nh_;
};

}  // namespace

const std::vector<std::string>& plannerParameterNames() {
  static const std::vector<std::string> names = {
      "backend",           "time_limit",         "max_time_limit",  "decomposition",     "decomposition_steps",
      "threads",           "fallback",           "backend_parameters", "lattice_resolution", "allow_backward", "refine", "compress",
      "cell_steps",
      "busy_policy",       "max_map_cells",      "max_robots",      "max_memory_mb",     "occupied_threshold",
      "unknown_policy",    "position_tolerance", "heading_tolerance", "sweep_tolerance", "seconds_per_step",
      "map_frame",         "base_frame",         "tf_timeout",      "playback",          "planned_frame",
      "playback_rate",     "playback_loop",      "execute",         "execution_rate",    "progress_tolerance",
      "progress_heading_tolerance", "blocked_timeout", "late_warning", "off_path_tolerance",
      "replan_blocked", "replan_off_path", "replan_time_limit"};
  return names;
}

std::vector<std::string> unknownPlannerParameters(const ros::NodeHandle& nh) {
  std::vector<std::string> names, unknown;
  if (!ros::param::getParamNames(names)) return unknown;
  const std::string prefix = nh.getNamespace() + "/";
  for (const std::string& name : names) {
    if (name.rfind(prefix, 0) != 0) continue;
    const std::string key = name.substr(prefix.size());
    bool known = key.rfind("backend_parameters/", 0) == 0;  // checked by checkBackendParameters
    for (const std::string& k : plannerParameterNames()) known = known || key == k;
    if (!known) unknown.push_back(name);
  }
  return unknown;
}

PlannerConfig loadPlannerConfig(const ros::NodeHandle& nh) {
  PlannerConfig c;
  Reader r(nh);
  r.read("backend", c.backend);
  r.read("time_limit", c.time_limit);
  r.read("max_time_limit", c.max_time_limit);
  r.read("decomposition", c.decomposition);
  r.read("decomposition_steps", c.decomposition_steps);
  r.read("threads", c.threads);
  r.read("refine", c.refine);
  r.read("compress", c.compress);
  r.read("cell_steps", c.cell_steps);
  r.read("fallback", c.fallback);
  r.read("backend_parameters", c.backend_parameters);
  r.read("lattice_resolution", c.lattice_resolution);
  r.read("allow_backward", c.allow_backward);
  r.read("busy_policy", c.busy_policy);
  r.read("max_map_cells", c.max_map_cells);
  r.read("max_robots", c.max_robots);
  r.read("max_memory_mb", c.max_memory_mb);
  r.read("occupied_threshold", c.occupied_threshold);
  r.read("unknown_policy", c.unknown_policy);
  r.read("position_tolerance", c.position_tolerance);
  r.read("heading_tolerance", c.heading_tolerance);
  r.read("sweep_tolerance", c.sweep_tolerance);
  r.read("seconds_per_step", c.seconds_per_step);
  r.read("map_frame", c.map_frame);
  r.read("base_frame", c.base_frame);
  r.read("tf_timeout", c.tf_timeout);
  r.read("playback", c.playback);
  r.read("planned_frame", c.planned_frame);
  r.read("playback_rate", c.playback_rate);
  r.read("playback_loop", c.playback_loop);
  r.read("execute", c.execute);
  r.read("execution_rate", c.execution_rate);
  r.read("progress_tolerance", c.progress_tolerance);
  r.read("progress_heading_tolerance", c.progress_heading_tolerance);
  r.read("blocked_timeout", c.blocked_timeout);
  r.read("late_warning", c.late_warning);
  r.read("off_path_tolerance", c.off_path_tolerance);
  r.read("replan_blocked", c.replan_blocked);
  r.read("replan_off_path", c.replan_off_path);
  r.read("replan_time_limit", c.replan_time_limit);
  return c;
}

}  // namespace fleet_planner
