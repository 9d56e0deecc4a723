"""The documentation's one source of truth: docs/classes.md is what docs/class_reference.py
makes from the headers, and every ParaView plugin property agrees with the header's
parameter it sets (it exists, same default, same range)."""
import importlib.util
import os
import re
import unittest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
spec = importlib.util.spec_from_file_location("class_reference", os.path.join(REPO, "docs", "class_reference.py"))
class_reference = importlib.util.module_from_spec(spec)
spec.loader.exec_module(class_reference)

# Each class's header and its TerraLux base classes' (parameters are inherited).
BASES = {"vtkTerrainReader": ["vtkTerrainSource"], "vtkHierarchicalRadiosity": ["vtkRadiosityFilter"],
         "vtkSolarIrradiation": ["vtkRadiosityFilter"]}
MODULE = {name: module for module, name in class_reference.CLASSES}


def parameters_of(cls):
    found = {}
    for name in [cls] + BASES.get(cls, []):
        _, parameters = class_reference.parse_header(os.path.join(REPO, MODULE[name], name + ".h"))
        for p in parameters:
            for setter in p.names:
                found.setdefault(setter, p)
    return found


def numbers(text):
    """The numbers a default or a bound states ("1e-3", "(45, 7, 0)", "off" -> 0)."""
    words = {"off": 0.0, "on": 1.0, "false": 0.0, "true": 1.0}
    if text is None:
        return None
    text = text.strip().lower()
    if text in words:
        return [words[text]]
    values = re.findall(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:e[-+]?\d+)?", text)
    return [float(v) for v in values] if values else None


def bound(text):
    """A vtkSetClampMacro bound as a number: literals, shifts and VTK's limits."""
    limits = {"VTK_DOUBLE_MAX": 1.7976931348623157e308, "VTK_INT_MAX": 2147483647.0,
              "VTK_ID_MAX": 9.223372036854775807e18, "VTK_DOUBLE_MIN": -1.7976931348623157e308}
    text = text.strip()
    if text in limits:
        return limits[text]
    if re.fullmatch(r"[-+0-9.e ()<*/]+", text):
        return float(eval(text, {"__builtins__": {}}))  # a literal expression, e.g. 1 << 20
    return None


class Documentation(unittest.TestCase):
    def test_class_reference_is_generated_from_the_headers(self):
        with open(os.path.join(REPO, "docs", "classes.md")) as f:
            self.assertEqual(f.read(), class_reference.reference(),
                             "docs/classes.md is out of date: run /usr/bin/python3 docs/class_reference.py")

    def test_every_parameter_is_documented_with_its_default(self):
        for module, name in class_reference.CLASSES:
            _, parameters = class_reference.parse_header(os.path.join(REPO, module, name + ".h"))
            for p in parameters:
                self.assertTrue(len(p.text) > 20, (name, p.names))

    def test_plugin_properties_agree_with_the_headers(self):
        checked = 0
        missing = []
        disagree = []
        for cls, prop, setter, default, bounds in class_reference.plugin_properties():
            parameters = parameters_of(cls)
            if setter not in parameters:
                missing.append("%s.%s (Set%s)" % (cls, prop, setter))
                continue
            self.assertIn(setter, parameters, "%s's plugin property %s sets %s, which its header does not "
                          "document" % (cls, prop, setter))
            p = parameters[setter]
            stated = numbers(p.default)
            given = numbers(default)
            if stated is not None and given is not None and len(stated) == len(given):
                if stated != given:
                    disagree.append("%s.%s: plugin %s, header %s" % (cls, prop, default, p.default))
                self.assertTrue(True, "%s.%s: the plugin's default %s, the header's %s"
                                 % (cls, prop, default, p.default))
                checked += 1
            if bounds and setter in p.ranges:
                low, high = (bound(v) for v in p.ranges[setter])
                if low is not None and high is not None:
                    # The plugin's slider may be narrower than what the class accepts.
                    if bounds[0] is not None:
                        self.assertGreaterEqual(float(bounds[0]), low, (cls, prop))
                    if bounds[1] is not None:
                        self.assertLessEqual(float(bounds[1]), high, (cls, prop))
        self.assertEqual(disagree, [], "plugin defaults that differ from the headers'")
        self.assertEqual(missing, [], "plugin properties whose setter the headers do not document")
        self.assertGreater(checked, 20)


if __name__ == "__main__":
    unittest.main()
