"""echoplan from Python: plan which sound to make to identify an object.

The compiled core (echoplan._echoplan) holds problems, beliefs and planners, the exact solver and
certify, audio features and observation models, the loop with robot parts, and campaigns. This
package adds what is more natural in Python: problems built from dicts, robot parts that only
have the methods (no base class), and a campaign's results read back as Python objects.
docs/python.md is the guide; help(echoplan.Planner) and friends the reference.
"""
import os as _os
from pathlib import Path as _Path


def _find_data_dir():
    """Where the shipped problems/ and objects/ are: beside the installed package (data/), or
    the build tree's share/echoplan. ECHOPLAN_DATA_DIR, when set, wins (common/data_dir.h)."""
    here = _Path(__file__).resolve().parent
    for candidate in (here / "data", here.parent.parent / "share" / "echoplan"):
        if (candidate / "problems").is_dir() and (candidate / "objects").is_dir():
            return str(candidate)
    return None


# The C++ code finds shipped files through ECHOPLAN_DATA_DIR when it cannot find them beside the
# running program (here python3 itself), so point it at the package's data unless the user did.
if not _os.environ.get("ECHOPLAN_DATA_DIR") and _find_data_dir():
    _os.environ["ECHOPLAN_DATA_DIR"] = _find_data_dir()

from ._echoplan import *  # noqa: E402,F401,F403
from ._echoplan import __version__  # noqa: E402,F401
from . import _echoplan  # noqa: E402
from ._problems import problem_from_dict, shipped_file  # noqa: E402,F401
from ._robots import Loop, as_robot, as_recorder, as_service  # noqa: E402,F401
from ._campaigns import Campaign, read_campaign, run_campaign  # noqa: E402,F401

Problem.from_dict = staticmethod(problem_from_dict)  # noqa: F405
