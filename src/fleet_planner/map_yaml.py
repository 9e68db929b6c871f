"""ROS map_server maps (YAML + image) as nav_msgs/OccupancyGrid-ready data, without ROS.

The YAML keys and their checks are those of the C++ core's reader (docs/file_formats.md):
`image` (relative to the YAML's folder, or absolute), `resolution` (> 0), `origin` [x, y, yaw]
are required; `negate` (0/1, true/false; default 0), `occupied_thresh` (0.65) and
`free_thresh` (0.196) in [0, 1] with free < occupied, `mode` (trinary, scale or raw) are
optional; any other key is an error. Cell values are those of ROS map_server
(http://wiki.ros.org/map_server), for a pixel v of an image with maximum value maxval:

- p = (maxval - v) / maxval, or v / maxval with negate;
- trinary: p > occupied_thresh -> 100, p < free_thresh -> 0, else -1;
- scale: the same, except that values in between become 1 + 98 * (p - free) / (occ - free),
  truncated (-1 for a fully transparent pixel);
- raw: the pixel itself is the value, r = round(v' * 255 / maxval) with v' = v, or maxval - v
  with negate (r = v for 8-bit images); r > 100 -> -1 (map_server would store 255 as -1 too).

Image row 0 is the top of the map; OccupancyGrid row 0 is the bottom (at the origin), so the
rows are flipped.
"""
import array
import math
import os
from collections import namedtuple

from fleet_planner.errors import InputError
from fleet_planner.map_image import read_image
from fleet_planner.yaml_fields import Fields, is_number, load_yaml_file

MODES = ("trinary", "scale", "raw")
KEYS = ("image", "resolution", "origin", "negate", "occupied_thresh", "free_thresh", "mode")

#: How to turn an image into cells. `image` is resolved (absolute or relative to the cwd).
MapSettings = namedtuple(
    "MapSettings", "image resolution origin negate occupied_thresh free_thresh mode")

#: A loaded map. `data` is an array('b') of width * height cell values, row-major, row 0 at
#: the bottom (the OccupancyGrid layout); `origin` is (x, y, yaw); `source` the file read.
OccupancyMap = namedtuple("OccupancyMap", "width height resolution origin data settings source")


def read_map_yaml(path):
    """The settings of a map_server YAML file. Raises InputError naming the file, line, key."""
    fields = Fields(load_yaml_file(path), path, "the map file", KEYS)
    image = fields.string("image")
    image = os.path.join(os.path.dirname(path), image)
    resolution = fields.number("resolution")
    if resolution <= 0:
        raise fields.error("resolution", "resolution must be positive, got %g" % resolution)
    origin = fields.require("origin")
    if not isinstance(origin, list) or len(origin) != 3:
        raise fields.error("origin", "origin must be a list [x, y, yaw]")
    origin = tuple(fields.check_number(value, "origin", "origin " + name)
                   for value, name in zip(origin, ("x", "y", "yaw")))
    negate = fields.mapping.get("negate", 0)
    if negate not in (0, 1):  # true and false are 1 and 0 too
        raise fields.error("negate", "negate must be 0 or 1, got %s" % (negate,))
    occupied = _threshold(fields, "occupied_thresh", 0.65)
    free = _threshold(fields, "free_thresh", 0.196)
    if free >= occupied:
        blame = "free_thresh" if fields.has("free_thresh") else "occupied_thresh"
        raise fields.error(blame, "free_thresh (%g) must be below occupied_thresh (%g)"
                           % (free, occupied))
    mode = fields.mapping.get("mode", "trinary")
    if mode not in MODES:
        raise fields.error("mode", "mode must be trinary, scale or raw, got '%s'" % (mode,))
    if not os.path.isfile(image):
        raise fields.error("image", "cannot open image file '%s'" % image)
    return MapSettings(image, resolution, origin, bool(negate), occupied, free, mode)


def _threshold(fields, key, default):
    value = fields.number(key, default)
    if not 0.0 <= value <= 1.0:
        raise fields.error(key, "%s must be in [0, 1], got %g" % (key, value))
    return value


def load_map(yaml_path):
    """Reads a map_server YAML file and its image into an OccupancyMap."""
    return load_image_map(read_map_yaml(yaml_path), yaml_path)


def image_settings(image, resolution, negate=False, occupied_thresh=0.65, free_thresh=0.196):
    """Settings for the old `map_server image resolution` form: origin (0, 0, 0), trinary."""
    if not (is_number(resolution) and math.isfinite(resolution) and resolution > 0):
        raise InputError(image, 0, "resolution must be a positive number, got %s" % resolution)
    for name, value in (("occupied_thresh", occupied_thresh), ("free_thresh", free_thresh)):
        if not (is_number(value) and 0.0 <= value <= 1.0):
            raise InputError(image, 0, "%s must be in [0, 1], got %s" % (name, value))
    if free_thresh >= occupied_thresh:
        raise InputError(image, 0, "free_thresh (%g) must be below occupied_thresh (%g)"
                         % (free_thresh, occupied_thresh))
    return MapSettings(image, float(resolution), (0.0, 0.0, 0.0), bool(negate),
                       float(occupied_thresh), float(free_thresh), "trinary")


def load_image_map(settings, source=None):
    """Reads `settings.image` and turns it into cells as map_server would."""
    image = read_image(settings.image)
    table = [cell_value(v, image.maxval, settings) for v in range(image.maxval + 1)]
    width, height = image.width, image.height
    data = array.array("b")
    for row in reversed(range(height)):  # grid row 0 is the image's bottom row
        start = row * width
        values = [table[v] for v in image.pixels[start:start + width]]
        if image.alpha is not None and settings.mode == "scale":
            alpha = image.alpha[start:start + width]
            values = [-1 if a == 0 and 0 < c < 100 else c for c, a in zip(values, alpha)]
        data.extend(values)
    return OccupancyMap(width, height, settings.resolution, settings.origin, data, settings,
                        source or settings.image)


def cell_value(value, maxval, settings):
    """The OccupancyGrid value (-1, or 0..100) of one pixel value."""
    if settings.mode == "raw":
        shade = maxval - value if settings.negate else value
        percent = int(math.floor(shade * 255.0 / maxval + 0.5))
        return percent if percent <= 100 else -1
    p = value / maxval if settings.negate else (maxval - value) / maxval
    if p > settings.occupied_thresh:
        return 100
    if p < settings.free_thresh:
        return 0
    if settings.mode == "trinary":
        return -1
    ratio = (p - settings.free_thresh) / (settings.occupied_thresh - settings.free_thresh)
    return int(1 + 98 * ratio)


def describe(occupancy_map):
    """One line about a map, e.g. "120 x 80 cells at 0.2 m/cell (24 x 16 m), origin (0, 0, 0)"."""
    m = occupancy_map
    return "%d x %d cells at %g m/cell (%g x %g m), origin (%g, %g, %g)" % (
        m.width, m.height, m.resolution, m.width * m.resolution, m.height * m.resolution,
        m.origin[0], m.origin[1], m.origin[2])
