"""Tests of fleet_planner.map_yaml (and the PGM reader behind it): map_server YAML + image to
OccupancyGrid values, and the messages for bad files. No ROS master needed.

Run: PYTHONPATH=src /usr/bin/python3 -m unittest discover -s test/python
"""
import os
import shutil
import tempfile
import unittest

from fleet_planner import map_yaml
from fleet_planner.errors import InputError

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data")


def rows(occupancy_map):
    """The map's values as rows, TOP row first (as the image is drawn)."""
    w = occupancy_map.width
    return [list(occupancy_map.data[y * w:(y + 1) * w])
            for y in reversed(range(occupancy_map.height))]


class TempDir(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="fleet_planner_test_")
        self.addCleanup(shutil.rmtree, self.dir)

    def write(self, name, content):
        path = os.path.join(self.dir, name)
        with open(path, "wb" if isinstance(content, bytes) else "w") as stream:
            stream.write(content)
        return path

    def assertInputError(self, function, file_name, line, *words):
        with self.assertRaises(InputError) as caught:
            function()
        error = caught.exception
        self.assertEqual(os.path.basename(error.source), file_name, str(error))
        self.assertEqual(error.line, line, str(error))
        for word in words:
            self.assertIn(word, str(error))
        prefix = "%s:%d: " % (error.source, line) if line else "%s: " % error.source
        self.assertTrue(str(error).startswith(prefix), str(error))


class LoadsMapServerMaps(TempDir):
    def test_p2_trinary_flips_rows_so_that_row_0_is_the_bottom(self):
        m = map_yaml.load_map(os.path.join(DATA, "map_server_p2.yaml"))
        self.assertEqual((m.width, m.height, m.resolution, m.origin), (4, 3, 0.5, (0, 0, 0)))
        # Image rows (top first): 0 254 254 205 / 254 254 0 254 / 254 205 254 254.
        self.assertEqual(rows(m), [[100, 0, 0, -1], [0, 0, 100, 0], [0, -1, 0, 0]])
        self.assertEqual(m.data[0], 0)  # grid (0, 0): the image's bottom-left pixel
        self.assertEqual(m.data[2 * 4], 100)  # grid (0, 2): the image's top-left pixel

    def test_negate(self):
        m = map_yaml.load_map(os.path.join(DATA, "map_server_p2_negate.yaml"))
        self.assertEqual(rows(m), [[0, 100, 100, 100], [100, 100, 0, 100], [100, 100, 100, 100]])

    def test_thresholds_of_the_yaml(self):
        low = map_yaml.load_map(os.path.join(DATA, "map_server_p2_low_thresholds.yaml"))
        self.assertEqual(rows(low)[0], [100, 0, 0, 100])
        high = map_yaml.load_map(os.path.join(DATA, "map_server_p2_high_free_thresh.yaml"))
        self.assertEqual(rows(high)[0], [100, 0, 0, 0])

    def test_scale_mode_gives_map_servers_intermediate_values(self):
        m = map_yaml.load_map(os.path.join(DATA, "map_server_p2_scale.yaml"))
        # 205: p = 50/255 = 0.196.. just above free_thresh 0.196 -> 1 + 98 * tiny ratio = 1.
        self.assertEqual(rows(m), [[100, 0, 0, 1], [0, 0, 100, 0], [0, 1, 0, 0]])
        self.write("gray.pgm", "P2\n3 1\n255\n128 60 30\n")
        yaml = self.write("gray.yaml", "image: gray.pgm\nresolution: 1\norigin: [0, 0, 0]\n"
                                       "mode: scale\nfree_thresh: 0.2\noccupied_thresh: 0.9\n")
        # p = 127/255, 195/255, 225/255 -> 1 + 98 * (p - 0.2) / 0.7
        self.assertEqual(rows(map_yaml.load_map(yaml)), [[42, 80, 100 - 4]])

    def test_raw_mode_copies_percentages_and_larger_values_are_unknown(self):
        m = map_yaml.load_map(os.path.join(DATA, "map_server_raw.yaml"))
        self.assertEqual(rows(m), [[0, 100, -1], [50, -1, 1]])

    def test_p5_with_resolution_and_origin(self):
        m = map_yaml.load_map(os.path.join(DATA, "map_server_p5.yaml"))
        self.assertEqual(rows(m), [[100, 0, -1], [0, 100, 0]])
        self.assertEqual((m.resolution, m.origin), (0.05, (-1.5, 2.0, 0.25)))
        self.assertEqual(m.settings.mode, "trinary")

    def test_sixteen_bit_p5(self):
        m = map_yaml.load_map(os.path.join(DATA, "map_server_p5_16bit.yaml"))
        self.assertEqual(rows(m), [[100, 0], [-1, 0]])

    def test_p2_comments_and_absolute_image_paths(self):
        image = self.write("commented.pgm", "P2 # magic\n# c\n2 # w\n1\n9\n9 0\n")
        yaml = self.write("absolute.yaml", "image: %s\nresolution: 1\norigin: [0, 0, 0]\n" % image)
        self.assertEqual(rows(map_yaml.load_map(yaml)), [[0, 100]])

    def test_old_form_settings(self):
        settings = map_yaml.image_settings(os.path.join(DATA, "map_server_p2.pgm"), 0.25)
        m = map_yaml.load_image_map(settings)
        self.assertEqual((m.resolution, m.origin, m.width), (0.25, (0.0, 0.0, 0.0), 4))
        self.assertEqual(rows(m)[0], [100, 0, 0, -1])
        with self.assertRaises(InputError):
            map_yaml.image_settings("x.pgm", 0)
        with self.assertRaises(InputError):
            map_yaml.image_settings("x.pgm", 1, occupied_thresh=0.1, free_thresh=0.2)

    def test_png_through_pil_when_installed(self):
        try:
            from PIL import Image
        except ImportError:
            self.skipTest("python3-pil is not installed")
        rgb = Image.new("RGB", (2, 1))
        rgb.putpixel((0, 0), (0, 0, 0))
        rgb.putpixel((1, 0), (254, 254, 254))
        rgb.save(os.path.join(self.dir, "map.png"))
        yaml = self.write("png.yaml", "image: map.png\nresolution: 0.1\norigin: [0, 0, 0]\n")
        self.assertEqual(rows(map_yaml.load_map(yaml)), [[100, 0]])


class RejectsBadMaps(TempDir):
    def yaml(self, body, image="map.pgm", pgm="P2\n2 1\n255\n0 254\n"):
        self.write(image, pgm)
        return self.write("map.yaml", body)

    def test_bad_yaml_names_the_file_line_and_key(self):
        head = "image: map.pgm\n"
        cases = [
            (head + "resolution: abc\norigin: [0, 0, 0]\n", 2, "resolution must be a finite"),
            (head + "resolution: .nan\norigin: [0, 0, 0]\n", 2, "resolution"),
            (head + "resolution: 0\norigin: [0, 0, 0]\n", 2, "positive"),
            (head + "resolution: 1\norigin: [0, 0]\n", 3, "origin must be a list"),
            (head + "resolution: 1\norigin: [0, nope, 0]\n", 3, "origin y"),
            (head + "resolution: 1\norigin: [0, 0, .inf]\n", 3, "origin yaw"),
            (head + "resolution: 1\norigin: [0, 0, 0]\noccupied_thresh: 1.5\n", 4,
             "occupied_thresh must be in [0, 1]"),
            (head + "resolution: 1\norigin: [0, 0, 0]\nfree_thresh: 0.7\n", 4,
             "free_thresh (0.7) must be below occupied_thresh (0.65)"),
            (head + "resolution: 1\norigin: [0, 0, 0]\nnegate: 2\n", 4, "negate must be 0 or 1"),
            (head + "resolution: 1\norigin: [0, 0, 0]\nmode: fancy\n", 4, "mode must be"),
            (head + "resolution: 1\norigin: [0, 0, 0]\nsize: 3\n", 4, "unknown key 'size'"),
            (head + "origin: [0, 0, 0]\n", 1, "has no 'resolution'"),
            (head + "resolution: 1\nresolution: 2\norigin: [0, 0, 0]\n", 3, "appears twice"),
            (head + "resolution: [1\n", 3, "not valid YAML"),
            ("", 0, "must be a mapping"),
        ]
        for body, line, word in cases:
            with self.subTest(body=body):
                path = self.yaml(body)
                self.assertInputError(lambda: map_yaml.load_map(path), "map.yaml", line, word)

    def test_missing_files(self):
        self.assertInputError(
            lambda: map_yaml.load_map(os.path.join(DATA, "bad_map_server_missing_image.yaml")),
            "bad_map_server_missing_image.yaml", 3, "cannot open image file", "no_such_image.pgm")
        self.assertInputError(lambda: map_yaml.load_map(os.path.join(self.dir, "none.yaml")),
                              "none.yaml", 0, "cannot read the file")

    def test_bad_images_name_the_image(self):
        cases = [
            ("P2\n2 2\n15\n0 15\n16 0\n", 5, "pixel (column 0, row 1)"),
            ("P2\n2 1\n255\n0 256\n", 4, "must be in [0, 255]"),
            ("P2\n2 2\n255\n0 0\n0\n", 0, "truncated: found 3 of 4"),
            ("P2\n2 1\n255\n0 0 0\n", 4, "extra data"),
            (b"P5\n2 2\n255\n\x00\x00", 0, "truncated: expected 4 bytes"),
            (b"P5\n2 1\n255\n\x00\x00\x00", 0, "extra data"),
            (b"P5\n2 1\n100\n\x00\x65", 0, "above maxval 100"),
            ("P2\n0 1\n255\n", 2, "image width must be in [1, 100000]"),
            ("P2\n2 x\n255\n", 2, "expected the image height"),
            ("P2\n2 1\n", 0, "file ends before the maxval"),
        ]
        for pgm, line, word in cases:
            with self.subTest(pgm=pgm):
                path = self.yaml("image: map.pgm\nresolution: 1\norigin: [0, 0, 0]\n", pgm=pgm)
                self.assertInputError(lambda: map_yaml.load_map(path), "map.pgm", line, word)

    def test_another_format_is_named(self):
        path = os.path.join(DATA, "bad_map_server_png.yaml")
        self.assertInputError(lambda: map_yaml.load_map(path), "not_a_pgm.png", 0, "PGM")
        text = self.yaml("image: map.txt\nresolution: 1\norigin: [0, 0, 0]\n", image="map.txt",
                         pgm="hello\n")
        self.assertInputError(lambda: map_yaml.load_map(text), "map.txt", 0, "PGM (P2 or P5)")


if __name__ == "__main__":
    unittest.main()
