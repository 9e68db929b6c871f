"""Strict YAML reading with line numbers, for messages that point at the offending line.

`load_yaml_file(path)` parses with PyYAML's safe loader, but every mapping becomes a
`MarkedDict` and every list a `MarkedList` that remember their lines (1-based), and a repeated
key is an error (plain PyYAML silently keeps the last one). `Fields` wraps one mapping with the
checks every reader needs: only known keys, required keys, finite numbers, strings.
"""
import math

import yaml

from fleet_planner.errors import InputError


class MarkedDict(dict):
    """A YAML mapping: `line` is where it starts, `key_lines[key]` where each key is."""

    line = 0

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self.key_lines = {}

    def line_of(self, key):
        return self.key_lines.get(key, self.line)


class MarkedList(list):
    """A YAML sequence: `line` is where it starts, `item_lines[i]` where item i is."""

    line = 0

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self.item_lines = []

    def line_of(self, index):
        return self.item_lines[index] if index < len(self.item_lines) else self.line


def _line(node):
    return node.start_mark.line + 1


def _loader_class(source):
    """A SafeLoader whose mappings and lists carry lines; `source` names the file in errors."""

    class Loader(yaml.SafeLoader):
        pass

    def construct_mapping(loader, node):
        loader.flatten_mapping(node)
        result = MarkedDict()
        result.line = _line(node)
        for key_node, value_node in node.value:
            key = loader.construct_object(key_node, deep=True)
            try:
                repeated = key in result
            except TypeError:
                raise InputError(source, _line(key_node), "a mapping key must be a plain value")
            if repeated:
                raise InputError(source, _line(key_node), "key '%s' appears twice" % (key,))
            result[key] = loader.construct_object(value_node, deep=True)
            result.key_lines[key] = _line(key_node)
        return result

    def construct_sequence(loader, node):
        result = MarkedList(loader.construct_object(child, deep=True) for child in node.value)
        result.line = _line(node)
        result.item_lines = [_line(child) for child in node.value]
        return result

    Loader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, construct_mapping)
    Loader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_SEQUENCE_TAG, construct_sequence)
    return Loader


def parse_yaml(text, source):
    """Parses YAML text; `source` names it in errors. Raises InputError on a syntax error."""
    try:
        return yaml.load(text, Loader=_loader_class(source))  # noqa: S506 (a SafeLoader)
    except yaml.MarkedYAMLError as error:
        mark = error.problem_mark or error.context_mark
        line = mark.line + 1 if mark is not None else 0
        raise InputError(source, line, "not valid YAML: %s" % (error.problem or error))
    except yaml.YAMLError as error:
        raise InputError(source, 0, "not valid YAML: %s" % error)


def load_yaml_file(path):
    """Reads and parses a YAML file. Raises InputError naming `path` if it cannot be read."""
    try:
        with open(path, "r", encoding="utf-8") as stream:
            text = stream.read()
    except (OSError, UnicodeDecodeError) as error:
        raise InputError(path, 0, "cannot read the file: %s" % _os_reason(error))
    return parse_yaml(text, path)


def _os_reason(error):
    return error.strerror if isinstance(error, OSError) and error.strerror else str(error)


def is_number(value):
    """An int or float, not a bool (YAML `true` is a bool, which Python counts as an int)."""
    return isinstance(value, (int, float)) and not isinstance(value, bool)


class Fields:
    """One YAML mapping being read: `what` names it in messages ("the map file", "robot 3")."""

    def __init__(self, mapping, source, what, allowed, robot=None, line=0):
        self.source = source
        self.robot = robot
        self.what = what
        if not isinstance(mapping, dict):
            raise InputError(source, getattr(mapping, "line", line),
                             "%s must be a mapping of keys to values" % what, robot)
        self.mapping = mapping
        for key in mapping:
            if key not in allowed:
                raise self.error(key, "unknown key '%s' in %s (expected one of: %s)"
                                 % (key, what, ", ".join(allowed)))

    def line(self, key=None):
        if key is not None and isinstance(self.mapping, MarkedDict):
            return self.mapping.line_of(key)
        return getattr(self.mapping, "line", 0)

    def error(self, key, reason):
        """An InputError at `key`'s line (the mapping's line for None)."""
        return InputError(self.source, self.line(key), reason, self.robot)

    def has(self, key):
        return key in self.mapping

    def require(self, key):
        if key not in self.mapping:
            raise self.error(None, "%s has no '%s'" % (self.what, key))
        return self.mapping[key]

    def number(self, key, default=None, name=None):
        """The finite number at `key` (required unless a default is given), as a float."""
        if key not in self.mapping and default is not None:
            return float(default)
        return self.check_number(self.require(key), key, name or key)

    def check_number(self, value, key, name):
        """`value` (found at `key`) as a finite float; `name` says what it is in messages."""
        if not is_number(value) or not math.isfinite(value):
            raise self.error(key, "%s must be a finite number, got %s" % (name, _show(value)))
        return float(value)

    def string(self, key, default=None):
        if key not in self.mapping and default is not None:
            return default
        value = self.require(key)
        if not isinstance(value, str) or not value:
            raise self.error(key, "%s must be a non-empty string, got %s" % (key, _show(value)))
        return value


def _show(value):
    """A value as it would read in YAML, for messages."""
    if value is None:
        return "nothing"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return "'%s'" % value
    if isinstance(value, (dict, list)):
        return "a %s" % ("mapping" if isinstance(value, dict) else "list")
    return str(value)
