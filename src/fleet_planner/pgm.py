"""A strict reader for PGM (netpbm graymap) images, P2 (plain) and P5 (binary), the format of
ROS map_server maps. The same rules as the C++ core's reader (docs/file_formats.md):
maxval 1..65535 (16-bit P5 samples are big-endian), `#` comments in the header and, in P2,
between values; truncated or extra data, or a value above maxval, is an error naming the file
and line (line 0 for binary data and for the file as a whole).
"""
import array
import functools
import sys
from collections import namedtuple

from fleet_planner.errors import InputError

#: Pixels are row-major, row 0 is the TOP row of the image. `alpha` is None, or per pixel 0..255
#: (only images read through PIL have one).
GrayImage = namedtuple("GrayImage", "width height maxval pixels alpha")

_MAX_SIDE = 100000
_MAX_PIXELS = 1 << 28
_SPACE = b" \t\n\r\v\f"


class _Cursor:
    """Walks the file's bytes, counting lines (1-based) for messages."""

    def __init__(self, path, data):
        self.path = path
        self.data = data
        self.pos = 0
        self.line = 1

    def at_end(self):
        return self.pos >= len(self.data)

    def peek(self):
        return self.data[self.pos:self.pos + 1]

    def advance(self):
        if self.data[self.pos] == 0x0A:
            self.line += 1
        self.pos += 1

    def skip_space_and_comments(self):
        while not self.at_end():
            c = self.peek()
            if c in _SPACE:
                self.advance()
            elif c == b"#":
                while not self.at_end() and self.peek() != b"\n":
                    self.advance()
            else:
                break

    def number(self, name, low, high):
        """Reads a decimal number in [low, high] after whitespace and comments; `name` (a string,
        or a function giving one, so that pixels only build it on error) names it in messages."""
        if callable(name):
            return self._number(name, low, high)
        return self._number(lambda: name, low, high)

    def _number(self, name_of, low, high):
        self.skip_space_and_comments()
        if self.at_end():
            raise InputError(self.path, 0, "file ends before the %s" % name_of())
        start = self.pos
        while not self.at_end() and self.peek().isdigit():
            self.advance()
        if self.pos == start:
            raise InputError(self.path, self.line, "expected the %s, found '%s'"
                             % (name_of(), self.peek().decode("latin-1")))
        if not self.at_end() and self.peek() not in _SPACE and self.peek() != b"#":
            raise InputError(self.path, self.line, "unexpected character '%s' after the %s"
                             % (self.peek().decode("latin-1"), name_of()))
        value = int(self.data[start:self.pos])
        if not low <= value <= high:
            raise InputError(self.path, self.line,
                             "%s must be in [%d, %d]" % (name_of(), low, high))
        return value


def is_pgm(data):
    """The bytes start like a P2 or P5 file."""
    return len(data) >= 2 and data[:2] in (b"P2", b"P5") and (
        len(data) == 2 or data[2:3] in _SPACE or data[2:3] == b"#")


def parse_pgm(data, path):
    """Parses the bytes of a P2/P5 file; `path` names it in errors. Returns a GrayImage."""
    if not is_pgm(data):
        raise InputError(path, 0, "not a PGM image (P2 or P5 netpbm graymap)")
    cursor = _Cursor(path, data)
    cursor.pos = 2
    width = cursor.number("image width", 1, _MAX_SIDE)
    height = cursor.number("image height", 1, _MAX_SIDE)
    maxval = cursor.number("maxval", 1, 65535)
    if width * height > _MAX_PIXELS:
        raise InputError(path, cursor.line, "image of %d x %d pixels is larger than 2^28 pixels"
                         % (width, height))
    if data[1:2] == b"5":
        pixels = _binary_pixels(cursor, width, height, maxval)
    else:
        pixels = _plain_pixels(cursor, width, height, maxval)
    return GrayImage(width, height, maxval, pixels, None)


def _binary_pixels(cursor, width, height, maxval):
    path, count = cursor.path, width * height
    if cursor.at_end():
        raise InputError(path, 0, "image data is missing")
    cursor.advance()  # the single whitespace byte after maxval
    size = 2 if maxval > 255 else 1
    body = cursor.data[cursor.pos:]
    if len(body) < count * size:
        raise InputError(path, 0, "image data is truncated: expected %d bytes of pixels, found %d"
                         % (count * size, len(body)))
    if len(body) > count * size:
        raise InputError(path, 0, "extra data after the %d bytes of pixels" % (count * size))
    if size == 1:
        pixels = bytes(body)
    else:
        pixels = array.array("H", body)
        if sys.byteorder == "little":
            pixels.byteswap()
    if max(pixels) > maxval:
        i = next(i for i, v in enumerate(pixels) if v > maxval)
        raise InputError(path, 0, "pixel (column %d, row %d) has value %d above maxval %d"
                         % (i % width, i // width, pixels[i], maxval))
    return pixels


def _plain_pixels(cursor, width, height, maxval):
    count = width * height
    pixels = array.array("H" if maxval > 255 else "B")
    for i in range(count):
        cursor.skip_space_and_comments()
        if cursor.at_end():
            raise InputError(cursor.path, 0, "image data is truncated: found %d of %d pixel values"
                             % (i, count))
        pixels.append(cursor.number(functools.partial(_pixel_name, i, width), 0, maxval))
    cursor.skip_space_and_comments()
    if not cursor.at_end():
        raise InputError(cursor.path, cursor.line,
                         "extra data after the %d pixel values" % count)
    return pixels


def _pixel_name(index, width):
    return "value of pixel (column %d, row %d)" % (index % width, index // width)
