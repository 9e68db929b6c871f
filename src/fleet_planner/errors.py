"""The one error type of the helpers: bad input, named by file, line and (where known) robot.

`str(InputError(...))` reads like a compiler message, e.g.
``config/fleet.yaml:12: robot 'tug_1': footprint needs at least 3 points``; the line is left
out when the problem is the file as a whole. Scripts print it and exit 1, without a traceback.
"""


class InputError(Exception):
    """Bad input: a file (or a service request) that cannot be used as given."""

    def __init__(self, source, line, reason, robot=None):
        """`source`: the file (or e.g. "request"); `line`: 1-based, 0 or None when unknown;
        `reason`: what is wrong, in words; `robot`: the robot id it concerns, if any."""
        self.source = source
        self.line = line or 0
        self.reason = reason
        self.robot = robot
        super().__init__(self._text())

    def _text(self):
        where = "%s:%d" % (self.source, self.line) if self.line else str(self.source)
        who = "robot '%s': " % self.robot if self.robot is not None else ""
        return "%s: %s%s" % (where, who, self.reason)
