"""The Python suite: the module under test comes from PYTHONPATH (ctest sets the build tree's);
python/examples/ holds the user-side code some tests run (a plant written in Python)."""

import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), os.pardir, "examples"))
