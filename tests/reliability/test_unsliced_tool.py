"""`creative make-tool --no-slice` says when the tool cannot be printed (that no slicer
checked the pieces when it can: test_bad_input.py's make-tool test, whose tools are made
with --no-slice)."""

import subprocess
import sys

from test_bad_input import BANNER


def _make_tool(tmp_path, *extra):
    proc = subprocess.run([sys.executable, "-m", "creative_py.cli", "make-tool", "hook",
                           "handle_length=long", "--no-slice", "--out", str(tmp_path),
                           *extra], capture_output=True, text=True, timeout=300)
    return proc, [line for line in proc.stderr.splitlines() if line and BANNER not in line]


def test_a_tool_that_no_printer_bed_takes_is_a_warning(tmp_path):
    proc, lines = _make_tool(tmp_path, "--build-volume", "20,20,20")
    assert proc.returncode == 0, proc.stderr
    assert lines == ["warning: new_tool: cannot be printed: new_tool: the tool is 575.0 x "
                     "46.5 x 18.0 mm; cut across its x axis into up to 8 parts, some part "
                     "still does not fit the 20 x 20 x 20 mm build volume"]

