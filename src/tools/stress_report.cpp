// The stress command's report helpers; see stress_report.h.
#include "stress_report.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "fleet_planner/io/instance_io.h"
#include "fleet_planner/io/map_io.h"

namespace fleet_planner::cli {

namespace {

std::string shellWord(const std::string& s) {
  if (!s.empty() && s.find_first_not_of(
                        "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-./,=:") ==
                        std::string::npos) {
    return s;
  }
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

std::string number(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

std::string reproducer(const StressOptions& o, int index, const std::string& backend,
                       const std::string& mode, double limit) {
  std::string cmd = "fleet_planner_cli stress --seed " + std::to_string(o.seed) + " --first " +
                    std::to_string(index) + " --instances 1";
  if (!backend.empty()) {
    cmd += " --backends " + backend + " --modes " + mode + " --time-limit " + number(limit) +
           " --min-time-limit " + number(limit);
  } else {
    cmd +=
        " --time-limit " + number(o.time_limit) + " --min-time-limit " + number(o.min_time_limit);
  }
  const StressCaseOptions defaults;
  if (o.cases.min_robots != defaults.min_robots)
    cmd += " --min-agents " + std::to_string(o.cases.min_robots);
  if (o.cases.max_robots != defaults.max_robots)
    cmd += " --max-agents " + std::to_string(o.cases.max_robots);
  if (o.cases.min_side != defaults.min_side)
    cmd += " --min-side " + std::to_string(o.cases.min_side);
  if (o.cases.max_side != defaults.max_side)
    cmd += " --max-side " + std::to_string(o.cases.max_side);
  if (o.threads != 1) cmd += " --threads " + std::to_string(o.threads);
  if (!o.maps_dir.empty()) cmd += " --maps-dir " + shellWord(o.maps_dir);
  cmd += " --dump-dir " +
         shellWord(o.dump_dir.empty() ? std::string("/tmp/fleet_planner_stress") : o.dump_dir);
  return cmd;
}

std::string dumpInstance(const StressOptions& o, int index, const nlohmann::json& violations) {
  namespace fs = std::filesystem;
  const StressCase c = makeStressCase(o.cases, index);
  fs::create_directories(o.dump_dir);
  const std::string stem = "stress-s" + std::to_string(o.seed) + "-i" + std::to_string(index);
  const fs::path dir(o.dump_dir);
  std::ofstream(dir / (stem + ".map")) << movingAiText(c.map);
  Instance instance = c.instance;
  instance.map_file = stem + ".map";
  saveScenario(instance, (dir / (stem + ".yaml")).string());
  std::ofstream txt(dir / (stem + ".txt"));
  txt << "stress instance " << index << " of seed " << o.seed << " (instance seed " << c.seed
      << "): " << c.map_kind << " " << c.map.width() << " x " << c.map.height() << ", "
      << c.instance.robots.size() << " robots"
      << (c.model.allow_backward
              ? ", backward moves allowed (solve --backward)"
              : "")
      << "\n\nviolations:\n";
  for (const auto& v : violations) txt << "  " << v.dump() << "\n";
  txt << "\nre-run in the sweep:\n  " << reproducer(o, index, "", "", 0)
      << "\n\nsolve one configuration:\n";
  for (const auto& v : violations) {
    if (!v.contains("backend")) continue;
    const std::string mode = v["mode"].get<std::string>();
    txt << "  fleet_planner_cli solve --map " << (dir / (stem + ".map")).string() << " --instance "
        << (dir / (stem + ".yaml")).string() << " --backend " << v["backend"].get<std::string>()
        << " --mode " << (mode == "raw" ? "raw" : "layered --steps " + mode) << " --time-limit "
        << number(v["limit_s"].get<double>()) << " --seed " << c.seed << "\n";
  }
  return (dir / (stem + ".txt")).string();
}


}  // namespace fleet_planner::cli
