"""Every tool a run creates is a valid simulation model and a printable design.

Runs the wedge case's tool creation (the faster case) once and checks all tools it
wrote: STL watertight, OpenSCAD renders the .scad to the same volume within 1 %, URDF and
SDF load in pybullet with the right mass, every printed piece fits the bed and has its
G-code, and the pieces unite into the tool.
"""

import pybullet as pb
import pytest

from creative_py.learning.options import RunOptions
from creative_py.learning.run import run_case
from creative_py.mesh.check import check_print_files, check_tool_files
from creative_py.mesh.export import read_tool_files

pytestmark = [pytest.mark.slow, pytest.mark.sim]


def test_every_created_tool_checks(tmp_path):
    # The catalogued wedge_a3 solves the big door first; --demonstrate-creation still
    # makes the tool whose files are checked here.
    folder = run_case("wedge", tmp_path, RunOptions(seed=1, eval_trials=0,
                                                    create_eval_trials=1,
                                                    demonstrate_creation=True))
    tools = sorted((folder.path / "tools").iterdir())
    assert tools, "the run created no tool"
    for d in tools:
        files = read_tool_files(d)
        report = check_tool_files(files)
        assert report.ok, report.problems
        printed = check_print_files(files)            # pieces united again, G-code read
        assert printed.ok, printed.problems
        assert printed.pieces >= 1 and printed.sliced == printed.pieces
        client = pb.connect(pb.DIRECT)
        try:
            body = pb.loadURDF(str(files.urdf), flags=pb.URDF_USE_INERTIA_FROM_FILE,
                               physicsClientId=client)
            assert body >= 0
            assert abs(pb.getDynamicsInfo(body, -1, physicsClientId=client)[0]
                       - files.mass.mass) < 1e-6
            (sdf_body,) = pb.loadSDF(str(files.sdf), physicsClientId=client)
            assert abs(pb.getDynamicsInfo(sdf_body, -1, physicsClientId=client)[0]
                       - files.mass.mass) < 1e-6
        finally:
            pb.disconnect(client)
