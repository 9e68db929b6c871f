"""Reads a map image into gray values: PGM with our own strict reader (fleet_planner.pgm), any
other format (PNG, BMP, ...) through PIL (python3-pil, which python3-matplotlib pulls in) when it
is installed, as map_server reads them with SDL_image:

- colour channels are averaged (a pixel's gray value is (r + g + b) / 3, kept exact by
  reporting maxval 765 and the sum of the channels);
- an alpha channel is returned separately (map_server's scale mode makes a fully transparent
  pixel unknown). map_server's trinary mode averages alpha in with the colours; we do not copy
  that quirk: alpha never changes a pixel's gray value.

The C++ core's own map reader (used by fleet_planner_cli) reads PGM only.
"""
import array

from fleet_planner.errors import InputError
from fleet_planner.pgm import GrayImage, is_pgm, parse_pgm

try:
    from PIL import Image, UnidentifiedImageError
except ImportError:  # PGM still works
    Image = UnidentifiedImageError = None


def read_image(path):
    """The image at `path` as a GrayImage (row 0 = top). Raises InputError naming `path`."""
    try:
        with open(path, "rb") as stream:
            data = stream.read()
    except OSError as error:
        raise InputError(path, 0, "cannot read the image: %s" % (error.strerror or error))
    if is_pgm(data):
        return parse_pgm(data, path)
    if Image is None:
        raise InputError(path, 0, "only PGM images are supported (P2 or P5) without python3-pil; "
                         "convert the image to PGM, or install python3-pil")
    return _read_with_pil(path)


def _read_with_pil(path):
    try:
        with Image.open(path) as image:
            image.load()
            return _gray(image)
    except UnidentifiedImageError:
        raise InputError(path, 0, "not a PGM (P2 or P5) image, and python3-pil cannot read it "
                         "as PNG, BMP, ... either")
    except (OSError, ValueError, SyntaxError) as error:
        raise InputError(path, 0, "cannot read the image: %s" % error)


def _gray(image):
    width, height = image.size
    if image.mode in ("I;16", "I;16B", "I;16L", "I"):
        values = array.array("L", (max(0, min(65535, v)) for v in image.getdata()))
        return GrayImage(width, height, 65535, values, None)
    if image.mode in ("1", "L", "LA"):
        gray = image.convert("LA")
        alpha = gray.getchannel("A").tobytes() if image.mode == "LA" else None
        return GrayImage(width, height, 255, gray.getchannel("L").tobytes(), alpha)
    has_alpha = image.mode in ("RGBA", "PA", "La") or "transparency" in image.info
    r, g, b, a = (band.tobytes() for band in image.convert("RGBA").split())
    sums = array.array("H", map(lambda x, y, z: x + y + z, r, g, b))
    return GrayImage(width, height, 765, sums, a if has_alpha else None)
