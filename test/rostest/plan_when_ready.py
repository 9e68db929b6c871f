"""What the rostest scripts here share (they import it from their own folder): a PlanFleet call
made as soon as the planner has its inputs (the map and the footprint registry reach it
asynchronously, so a test's first calls may answer NO_MAP or UNKNOWN_ROBOT), and waiting for a
condition."""
import rospy

from fleet_planner.srv import PlanFleetResponse

NOT_READY = (PlanFleetResponse.NO_MAP, PlanFleetResponse.UNKNOWN_ROBOT)


def plan_when_ready(plan, request, seconds=30.0):
    """Calls plan(request) until the answer is not NOT_READY, for up to `seconds`; the last answer."""
    deadline = rospy.Time.now() + rospy.Duration(seconds)
    response = plan(request)
    while response.status in NOT_READY and rospy.Time.now() < deadline:
        rospy.sleep(0.2)
        response = plan(request)
    return response


def wait_until(condition, seconds, period=0.2):
    """Polls condition() every `period` seconds until it is true or `seconds` have passed (or ROS
    shuts down); its last value."""
    deadline = rospy.Time.now() + rospy.Duration(seconds)
    while not rospy.is_shutdown() and rospy.Time.now() < deadline:
        if condition():
            return True
        rospy.sleep(period)
    return condition()
