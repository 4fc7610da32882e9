"""Run INSIDE a loopback-only namespace (test_ros_network.py): the learner asked for DDS
Security (SROS2: ROS_SECURITY_ENABLE=true, a keystore with an enclave) on the PyPI
wheels' Fast DDS. Prints one JSON line: the learner's exit code and stderr, and what
rclpy itself said when asked for a node."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[4]

with tempfile.TemporaryDirectory() as tmp:
    enclave = Path(tmp) / "enclaves" / "creative"
    enclave.mkdir(parents=True)
    for name in ("identity_ca.cert.pem", "cert.pem", "key.pem", "permissions_ca.cert.pem",
                 "governance.p7s", "permissions.p7s"):
        (enclave / name).write_text("not a certificate: the security plugins are asked for "
                                    "before any file is read\n")
    env = dict(os.environ, ROS_SECURITY_ENABLE="true", ROS_SECURITY_STRATEGY="Enforce",
               ROS_SECURITY_KEYSTORE=tmp, ROS_SECURITY_ENCLAVE_OVERRIDE="/creative",
               CREATIVE_ROS_WAIT_S="2")
    p = subprocess.run([sys.executable, "-m", "creative_py.cli", "run", "hook", "--backend",
                        "ros", "--video", "none", "--out", str(Path(tmp) / "runs")],
                       env=env, cwd=ROOT, capture_output=True, text=True, timeout=120)
    runs = sorted(p.name for p in (Path(tmp) / "runs").glob("*"))
print(json.dumps({"rc": p.returncode, "stderr": p.stderr, "runs": runs}))
