"""A method registered in one C++ file (tests/examples/my_method.cpp) and compiled into the
module (LEXEL_METHOD_SOURCES) is in lexel.methods() after the built-in ones, with the record it
declared, and lexel.compute() runs it: my-focused is focused-tight."""
import unittest

import lexel


class RegisteredMethodTest(unittest.TestCase):
    def test_listed_with_its_record(self):
        methods = lexel.methods()
        self.assertEqual([m["name"] for m in methods[-2:]], ["my-focused", "focused-wide"])
        mine = methods[-2]
        self.assertEqual(mine["family"], "registered")
        self.assertEqual(mine["storage_model"], "unwarped")
        self.assertTrue(mine["default"])
        self.assertIn("Practical Shadow Mapping", mine["citation"])
        self.assertEqual(sum(m["family"] != "registered" for m in methods), 31)

    def test_computed_as_focused_tight(self):
        camera = lexel.Camera(position=(0.0, 3.0, 8.0), target=(0.0, 0.0, -4.0),
                              resolution=(120, 80), near=0.5, far=100.0)
        bounds = lexel.Bounds((-5.0, 0.0, -5.0), (5.0, 2.0, 5.0))
        light_space = lexel.LightSpace(lexel.Light.directional((0.0, -1.0, -0.2)), bounds)
        context = lexel.BaselineContext(light_space, camera, (256, 256), bounds,
                                        [[0.0, 0.0, 0.0], [1.0, 0.0, 1.0], [-1.0, 1.0, 0.5]])
        mine = lexel.compute("my-focused", context)["matrix"]
        tight = lexel.compute("focused-tight", context)["matrix"]
        for a, b in ((mine.p1, tight.p1), (mine.p2, tight.p2), (mine.p4, tight.p4)):
            self.assertEqual(list(a), list(b))


if __name__ == "__main__":
    unittest.main()
