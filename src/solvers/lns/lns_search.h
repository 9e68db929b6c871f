#pragma once
// The state of one LA-LNS solve (la_lns.h), private to LA-LNS. Its members are defined in three
// files, one concern each:
//   la_lns.cpp            the run: the first plan, the loop of repairs, the outcome;
//   lns_neighborhoods.cpp which agents to replan: the adaptive choice of a method and its
//                         neighbourhood (collision graph, ideal path, random, knot);
//   lns_repair.cpp        replanning a neighbourhood: one by one, together (ordered, LA-CBS,
//                         joint search), pair proofs, local splices, the collision graph.
#include <array>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "fleet_planner/runtime/random.h"
#include "fleet_planner/solvers/lns/la_lns.h"
#include "fleet_planner/solvers/lns/lns_race.h"
#include "fleet_planner/solvers/lns/neighborhood_growth.h"
#include "fleet_planner/solvers/search/joint_path_search.h"
#include "fleet_planner/solvers/search/search_space.h"
#include "fleet_planner/solvers/search/soft_path_search.h"
#include "fleet_planner/solvers/search/soft_path_table.h"

namespace fleet_planner {

// planTogetherLater's first lead: steps before the group's members first meet.
constexpr int kLaterLead = 32;

/// How a repair chooses its neighbourhood (adaptive LNS: each method's weight grows with its help).
enum Method { kCollisionGraph = 0, kIdealPath = 1, kRandom = 2, kJoint = 3, kMethods = 4 };

class LnsSearch {
 public:
  LnsSearch(const SearchSpace& space, const Subproblem& problem, const LaLnsOptions& options,
            SolveStats& stats);

  SolveResult run();

 private:
  // The loop of repairs from the first plan; in a race, as search `me` (then a search that
  // cannot win returns early with no status, and the outcomes are recorded in `race`).
  SolveResult repairs(LnsRace* race, int me);
  // The first plan repaired by this search and a copy with another seed on a second thread.
  SolveResult race();

  std::optional<SolveResult> outOfBudget() const;

  // Subproblem::may_give_up, asked once.
  bool mayGiveUp();

  SolveResult timeout(const std::string& why) const;

  // " (a & b, c & d, ...)": the first few colliding pairs, to say where the plan is stuck.
  std::string somePairs() const;

  // With returning robots (robots of other subproblems stepping aside): a plan of the others
  // made without them (LA-LNS, at most a tenth of the time left and 2 s), and the returning
  // robots in its way clearing the stage for it (stage_clearing.h); none if either fails.
  std::optional<SolveResult> clearedStage();
  std::optional<SolveResult> parkFirst(const std::vector<int>& order, std::vector<char>& parked);

  // A path for a, around the agents planned so far as soft obstacles; if that search gives up,
  // its shortest path in the static world and the other subproblems' timed paths.
  std::optional<SolveResult> initialPath(int a, StatePath& path);

  // An agent whose new path still collides gets a higher collision cost next time (doubling up
  // to 64 times the base), so that a wait or a detour that a small cost would not pay for is
  // found in the end; a collision-free path resets it.
  SoftSearchResult search(int a);

  // Shortest path of a around hard obstacles only (empty if none or out of time); cached.
  const StatePath& idealPath(int a);
  StatePath shortestAlone(int a);

  int collidingPairs() const;

  void link(int a, int b);

  int pick(const std::vector<int>& from);

  void shuffle(std::vector<int>& v);

  Method chooseMethod();

  std::vector<int> neighborhood(Method method);

  // Colliding pairs with at least one agent of `group`, given each agent's partners.
  static int pairsTouching(const std::vector<int>& group,
                           const std::vector<std::vector<int>>& partners,
                           const std::vector<bool>& in);

  // Replans the group robot by robot (each around all others); false if a search gave up.
  bool planOneByOne(const std::vector<int>& group);

  // Replans the group jointly around all others' paths: first one after the other, in the
  // group's order and then in reverse, with the members not yet replanned at their starts
  // (ordered_repair.h: cheap, and collision-free if it works); then two of them trading places
  // through a pocket (pocket_repair.h, collision-free too); then by LA-CBS within a small share
  // of the time left (others hard); then alone by LA-LaCAM (planAlone); and if none of these
  // finds a plan, for a small group and once the neighbourhood has grown to the whole
  // subproblem, by a joint search (joint_path_search.h; others soft); false if none found one. A
  // joint search that exhausts the group's joint space proves that the subproblem has no plan
  // (proof_). The joint search waits for the deep stall because it costs time the repair needs:
  // run at every joint step, its budget spent 4-5 s of the 7 s that LA-LNS had for a 12-robot
  // level of maze-128-128-10 K=40, which it otherwise solves in that time. In a large
  // subproblem it also runs once per group and number of colliding pairs when at most
  // joint_search_pairs pairs are left: a large subproblem's neighbourhood may never grow to all
  // of it before its time runs out, while the knot left at its end needs the joint search.
  bool planTogether(const std::vector<int>& group);

  // The group's joint search started later (JointSearchOptions::from): its members keep their
  // paths of before the repair (joint_before_) until a lead of steps before the first step two
  // of them meet, and search jointly from there; their paths put in the table if it finds one.
  // A knot far from the starts (a robot that must make way for one that arrives hundreds of
  // steps later) is then a search of a few dozen steps, where the search from step 0 spends its
  // states on the way there.
  bool planTogetherLater(const std::vector<int>& group, JointSearchOptions options);
  // The step after which no agent outside the group comes near it (JointSearchOptions::static_from):
  // within lead + 8 moves of the box around the members' states `at` and their targets.
  int stillNear(const std::vector<int>& group, const std::vector<StateId>& at, int t0, int lead) const;
  // A held member's path before the later search (steps 0..t0-1 at least): to its start and
  // back around the others, or standing there.
  StatePath heldPrefix(int a, int t0);

  // The group alone among the static obstacles by LA-LaCAM, its paths put in the table (soft
  // towards the others); false if it found none or the subproblem has moving obstacles.
  bool planAlone(const std::vector<int>& group, double seconds);

  // Each member of the group in turn drives to its target while the others wait in pockets off
  // its way and then drive on, in the group's order (pocket_repair.h). False (and none of the
  // group in the table) if no pocket worked.
  bool planThroughPocket(const std::vector<int>& group);

  // A pair of the knot that cannot reach its targets even alone among the static obstacles
  // proves that the subproblem has no plan (proof_): dropping robots and obstacles only makes a
  // problem easier. LA-LaCAM decides the pair (its search over configurations is complete); the
  // joint search above rarely exhausts its timed joint space, and the pair's configurations are
  // far fewer. Each pair is tried once.
  void provePair(const std::vector<int>& group);

  // A colliding agent and up to joint_size - 1 of its partners.
  std::vector<int> knot();

  // Replaces agent a's path in the table and its edges in the collision graph (`partners`:
  // the agents the new path collides with).
  void replacePath(int a, const StatePath& path, const std::vector<int>& partners);

  // Local repairs (path_splice.h) before a repair: of each colliding agent, or of one
  // (LaLnsOptions::splice_each_colliding).
  void splices();
  // One local repair of a random collision of agent a: kept when a then meets fewer agents
  // (`fewer`: the windows are tried until one does), else unless it meets more. True if kept.
  bool splice(int a, bool fewer);

  void repair();

  SolveResult success(const std::vector<StatePath>& paths) const;

  const SearchSpace& space_;
  const Subproblem* problem_;  // a pointer: the copy that races this search has its own deadline
  const LaLnsOptions& options_;
  SolveStats* stats_;  // a pointer: the copy that races this search counts in its own
  const int n_;
  SoftPathTable table_;
  Rng rng_;
  std::vector<std::vector<int>> partners_;  // sorted; symmetric: the collision graph
  std::vector<StatePath> ideal_;
  std::vector<StatePath> joint_before_;  // a joint repair's group: their paths before it (by agent)
  bool parked_partly_ = false;  // the first plan began with a parking plan that left robots
  std::vector<bool> ideal_absent_;  // the search proved there is no such path
  std::vector<int> escalation_;     // per agent: factor of the collision cost
  // Paths kept in the table so far (local repairs and repairs; a repair that is not kept puts
  // the old paths back), and per agent the count at which its last local repair of a pass
  // failed (splices()).
  long long kept_ = 0;
  std::vector<long long> splice_failed_at_;
  int planned_ = 0;                 // robots with a path in the first plan so far
  std::optional<std::string> proof_;  // why the subproblem has no plan, once a search proved it
  std::vector<int> proof_culprits_;   // the robots of that proof (instance indices)
  std::set<std::pair<int, int>> pairs_tried_;  // by provePair
  std::map<std::vector<int>, int> pocket_failures_;  // by planThroughPocket, per sorted group
  // by planTogether: (sorted group, colliding pairs) searched jointly before the neighbourhood
  // held the whole subproblem, each once
  std::set<std::pair<std::vector<int>, int>> joint_tried_;
  // by planTogether: per sorted group, kept_ when it was last searched jointly
  std::map<std::vector<int>, long long> joint_searched_at_;
  NeighborhoodGrowth growth_;
  int size_ = 0;                    // agents in this repair's neighbourhood (growth_)
  std::array<double, kMethods> weights_;
  std::optional<bool> may_give_up_;  // the caller's answer, once asked
};

}  // namespace fleet_planner
