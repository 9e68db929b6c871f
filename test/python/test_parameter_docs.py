"""The node's parameters have one source of truth: config/planner.yaml, the code's list
(plannerParameterNames in src/ros/planner_config_loader.cpp) and the table of docs/ros.md name
the same parameters, and the yaml's values are the code's defaults where both are plain."""
import os
import re
import unittest

import yaml

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))


def read(*path):
    with open(os.path.join(ROOT, *path)) as f:
        return f.read()


def yaml_parameters():
    return list(yaml.safe_load(read("config", "planner.yaml")).keys())


def code_parameters():
    text = read("src", "ros", "planner_config_loader.cpp")
    body = re.search(r"plannerParameterNames\(\) \{(.*?)\};", text, re.S)
    if body is None:
        raise AssertionError("plannerParameterNames() not found in planner_config_loader.cpp")
    return re.findall(r'"([a-z_]+)"', body.group(1))


def doc_parameters():
    text = read("docs", "ros.md")
    section = re.search(r"^## Parameters\n(.*?)(?=^## |\Z)", text, re.S | re.M)
    if section is None:
        raise AssertionError("docs/ros.md has no '## Parameters' section")
    return re.findall(r"^\| `([a-z_]+)` \|", section.group(1), re.M)


def code_defaults():
    """Field name -> default text of PlannerConfig's plain members (numbers, booleans, strings)."""
    text = read("include", "fleet_planner", "ros", "planner_config.h")
    found = {}
    for m in re.finditer(r"^\s+(?:std::string|double|int|bool) (\w+) = ([^;]+);", text, re.M):
        found[m.group(1)] = m.group(2).strip()
    return found


class ParameterDocsTest(unittest.TestCase):
    def test_yaml_code_and_doc_name_the_same_parameters(self):
        in_yaml, in_code, in_doc = yaml_parameters(), code_parameters(), doc_parameters()
        self.assertTrue(in_code, "no parameter names parsed from the code")
        self.assertEqual(len(in_code), len(set(in_code)), "a parameter is listed twice in the code")
        self.assertEqual(in_yaml, in_code, "config/planner.yaml and plannerParameterNames() differ (names or order)")
        self.assertEqual(sorted(in_doc), sorted(in_code), "docs/ros.md's parameter table and the code differ")

    def test_yaml_values_are_the_code_defaults(self):
        values = yaml.safe_load(read("config", "planner.yaml"))
        defaults = code_defaults()
        checked = 0
        for name, value in values.items():
            if name not in defaults:
                continue
            text = defaults[name].replace("'", "")
            if isinstance(value, bool):
                expected = "true" if value else "false"
            elif isinstance(value, str):
                expected = '"%s"' % value
            else:
                text = float(text.replace("_", ""))
                expected = float(value)
            self.assertEqual(text, expected, "config/planner.yaml's %s differs from PlannerConfig's default" % name)
            checked += 1
        self.assertGreater(checked, 20)


if __name__ == "__main__":
    unittest.main()
