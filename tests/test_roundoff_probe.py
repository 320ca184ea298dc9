"""The round-off probe of `make test-roundoff` (tests/roundoff/sitecustomize.py).

It must change every Track's masses, stiffnesses and dampings by the relative
amount asked for, leave the geometry alone, and do nothing when not asked.
"""

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

PROBE = Path(__file__).resolve().parent / "roundoff"
SCRIPT = """
import json, railtrack as rt
t = rt.Track.paper(pad_damping=30e3)
print(json.dumps({name: getattr(t, name) for name in (
    "rail_linear_mass", "rail_bending_stiffness", "sleeper_mass", "pad_stiffness",
    "pad_damping", "sleeper_spacing")}))
"""
EXPECTED = {"rail_linear_mass": 60.0, "rail_bending_stiffness": 6.3e6, "sleeper_mass": 100.0,
            "pad_stiffness": 220e6, "pad_damping": 30e3, "sleeper_spacing": 0.6}


def _fields(delta: str | None) -> dict:
    env = {k: v for k, v in os.environ.items() if k != "RAILTRACK_ROUNDOFF_PROBE"}
    env["PYTHONPATH"] = str(PROBE)
    if delta is not None:
        env["RAILTRACK_ROUNDOFF_PROBE"] = delta
    out = subprocess.run([sys.executable, "-c", SCRIPT], env=env, capture_output=True,
                         text=True, check=True)
    return json.loads(out.stdout)


def test_without_the_variable_nothing_changes():
    assert _fields(None) == EXPECTED


def test_every_mass_stiffness_and_damping_moves_by_delta_and_the_spacing_does_not():
    fields = _fields("1e-9")
    for name, value in EXPECTED.items():
        change = fields[name] / value - 1
        if name == "sleeper_spacing":
            assert change == 0.0
        else:
            assert change == pytest.approx(1e-9, rel=1e-3), name
