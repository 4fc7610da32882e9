"""A sweep attached to a Ray address where nothing answers is refused in one line."""

import subprocess
import sys

import pytest

from creative_py.sweep import check_ray_address

from test_bad_input import BANNER


def test_an_address_where_nothing_listens_is_one_line_and_writes_nothing(tmp_path):
    out = tmp_path / "runs"
    proc = subprocess.run([sys.executable, "-m", "creative_py.cli", "sweep", "hook",
                           "--address", "127.0.0.1:1", "--out", str(out)],
                          capture_output=True, text=True, timeout=60)
    lines = [line for line in proc.stderr.splitlines() if line and BANNER not in line]
    assert proc.returncode == 2
    assert lines == ["error: --address 127.0.0.1:1: no Ray cluster answers there "
                     "(Connection refused within 5 s)"]
    assert not out.exists()


@pytest.mark.parametrize("address", ["nohost", "host:port", "ray://:6379", "h:0", "h:70000"])
def test_an_address_that_is_not_host_and_port_is_refused(address):
    with pytest.raises(ValueError, match=r"--address must be host:port"):
        check_ray_address(address)


def test_a_listening_port_is_accepted(tmp_path):
    import socket

    with socket.socket() as server:
        server.bind(("127.0.0.1", 0))
        server.listen()
        check_ray_address(f"127.0.0.1:{server.getsockname()[1]}")
        check_ray_address(f"ray://127.0.0.1:{server.getsockname()[1]}")
