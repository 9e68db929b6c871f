# Installs the fleet_planner Python package (src/fleet_planner: shared helpers of the rospy nodes).
from setuptools import setup
from catkin_pkg.python_setup import generate_distutils_setup

setup(**generate_distutils_setup(packages=["fleet_planner"], package_dir={"": "src"}))
