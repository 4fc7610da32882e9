"""The learner warns when ROS 2 discovery reaches beyond the host while DDS Security is
off (creative_py/backends/ros/client.py discovery_warning). No ROS traffic here."""

from __future__ import annotations

import pytest

from creative_py.backends.ros.client import discovery_warning


@pytest.mark.parametrize("env", [
    {"ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST"},
    {"ROS_AUTOMATIC_DISCOVERY_RANGE": "localhost"},
    {"ROS_AUTOMATIC_DISCOVERY_RANGE": "OFF"},
    {"ROS_LOCALHOST_ONLY": "1"},
    {"ROS_AUTOMATIC_DISCOVERY_RANGE": "SUBNET", "ROS_SECURITY_ENABLE": "true"},
    {"ROS_SECURITY_ENABLE": "true"},
])
def test_no_warning_on_the_host_alone_or_with_security(env):
    assert discovery_warning(env) is None


def test_a_subnet_without_security_is_warned_of_naming_the_setting_and_the_domain():
    w = discovery_warning({"ROS_AUTOMATIC_DISCOVERY_RANGE": "SUBNET", "ROS_DOMAIN_ID": "7"})
    assert w == (
        "ROS 2 discovery reaches beyond this host (ROS_AUTOMATIC_DISCOVERY_RANGE=SUBNET) "
        "and DDS Security is off (ROS_SECURITY_ENABLE is not true): any machine on the "
        "network on domain 7 can see the arm's topics and send it goals; use the lab's "
        "ROS 2 with SROS2 or an isolated robot network, or set "
        "ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST (docs/real-robot.md, Network safety)")
    # unset is SUBNET (ROS 2's default); SYSTEM_DEFAULT and a false flag are no better
    assert "(ROS_AUTOMATIC_DISCOVERY_RANGE=unset, so SUBNET)" in discovery_warning({})
    assert "on domain 0 " in discovery_warning({})
    assert discovery_warning({"ROS_AUTOMATIC_DISCOVERY_RANGE": "SYSTEM_DEFAULT"})
    assert discovery_warning({"ROS_AUTOMATIC_DISCOVERY_RANGE": "SUBNET",
                              "ROS_SECURITY_ENABLE": "false"})
    # ROS_LOCALHOST_ONLY does not narrow an explicit range
    assert discovery_warning({"ROS_LOCALHOST_ONLY": "1",
                              "ROS_AUTOMATIC_DISCOVERY_RANGE": "SUBNET"})


def test_static_peers_reach_beyond_the_host_even_on_localhost():
    w = discovery_warning({"ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST",
                           "ROS_STATIC_PEERS": "192.168.1.20"})
    assert w is not None and "(ROS_STATIC_PEERS=192.168.1.20)" in w


@pytest.mark.sim
def test_sros2_on_the_wheels_fast_dds_is_refused_in_one_line():
    # Measured: the PyPI wheels' Fast DDS has no DDS Security; the learner says so and
    # where to go instead, exit 2, no traceback, no run folder.
    import os
    from pathlib import Path

    from test_standin import run_in_namespace

    out = run_in_namespace(Path(__file__).parent / "_security.py",
                           domain=230 + os.getpid() % 20, timeout=180.0)
    assert out["rc"] == 2, out["stderr"]
    lines = out["stderr"].strip().splitlines()
    assert lines[-1] == (
        "error: ROS_SECURITY_ENABLE=true: this ROS 2's Fast DDS is built without DDS "
        "Security (it said: 'Please compile Fast DDS using the -DSECURITY=ON CMake option'; "
        "the PyPI wheels' is): run the learner with the lab's own ROS 2 install and SROS2, "
        "or on an isolated robot network (docs/real-robot.md, Network safety)")
    assert "Traceback" not in out["stderr"] and out["runs"] == []
