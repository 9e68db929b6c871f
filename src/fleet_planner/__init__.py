"""fleet_planner's Python helpers, shared by the rospy nodes in scripts/ (map server, footprint
registry, demo client). The generated messages live next to this package as fleet_planner.msg
and fleet_planner.srv."""
