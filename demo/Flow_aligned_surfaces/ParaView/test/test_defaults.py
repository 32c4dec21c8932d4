"""Every filter applied with its defaults on the package's real CFD data (defaults_check.py says
what is checked), in pvbatch.

Run as  pvbatch test_defaults.py PLUGIN REFERENCE WORKDIR DATA_FOLDER."""
from paraview.simple import *  # first: an error before it would leave MPI ranks spinning

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fas_plugin_test as t

setup = t.Setup(globals())
import defaults_check

for name in defaults_check.DATA_SETS:
    print(defaults_check.check_defaults(sys.argv[4], name, setup.filters))
