"""The written URDF and SDF load in pybullet with the right mass and rest on a plane."""

from __future__ import annotations

import numpy as np
import pybullet
import pybullet_data
import pytest

from creative_py.mesh.spec import spec_mass

from creative_py.kinds.hook_like import HookSpec

pytestmark = pytest.mark.sim

SETTLE_STEPS = 480  # 2 s at pybullet's default 1/240 s


@pytest.fixture
def client():
    cid = pybullet.connect(pybullet.DIRECT)
    pybullet.setAdditionalSearchPath(pybullet_data.getDataPath(), physicsClientId=cid)
    pybullet.setGravity(0, 0, -9.81, physicsClientId=cid)
    pybullet.loadURDF("plane.urdf", physicsClientId=cid)
    yield cid
    pybullet.disconnect(cid)


def _load(files, fmt, cid, height):
    if fmt == "urdf":
        return pybullet.loadURDF(str(files.urdf), [0, 0, height],
                                 flags=pybullet.URDF_USE_INERTIA_FROM_FILE, physicsClientId=cid)
    (body,) = pybullet.loadSDF(str(files.sdf), physicsClientId=cid)
    info = pybullet.getDynamicsInfo(body, -1, physicsClientId=cid)
    pos, orn = pybullet.multiplyTransforms([0, 0, height], [0, 0, 0, 1], info[3], info[4])
    pybullet.resetBasePositionAndOrientation(body, pos, orn, physicsClientId=cid)
    return body


def _link_pose(body, cid):
    """Return the tool frame's pose: pybullet reports the base's inertial frame."""
    pos, orn = pybullet.getBasePositionAndOrientation(body, physicsClientId=cid)
    info = pybullet.getDynamicsInfo(body, -1, physicsClientId=cid)
    inv = pybullet.invertTransform(info[3], info[4])
    return pybullet.multiplyTransforms(pos, orn, *inv)


@pytest.mark.parametrize("fmt", ["urdf", "sdf"])
def test_tool_loads_with_its_mass_and_comes_to_rest_on_a_plane(written, kind, fmt, client):
    files = written[kind]
    spec = files.spec
    rest_height = spec.handle_width / 2 if isinstance(spec, HookSpec) else 0.0
    body = _load(files, fmt, client, rest_height + 0.02)
    info = pybullet.getDynamicsInfo(body, -1, physicsClientId=client)
    assert info[0] == pytest.approx(spec_mass(spec), rel=1e-9)
    assert info[3] == pytest.approx(files.mass.center_of_mass, abs=1e-9)
    for _ in range(SETTLE_STEPS):
        pybullet.stepSimulation(physicsClientId=client)
    settled = _link_pose(body, client)
    for _ in range(SETTLE_STEPS // 2):
        pybullet.stepSimulation(physicsClientId=client)
    pos, orn = _link_pose(body, client)
    # At rest: it did not move in the last second (velocities are not a reliable test:
    # pybullet may put a body to sleep with a small residual velocity).
    assert np.linalg.norm(np.subtract(pos, settled[0])) < 1e-4
    assert abs(np.dot(orn, settled[1])) > 1 - 1e-6
    # It lies where it was dropped, upright, on the plane (pybullet keeps a contact
    # margin of up to about 1 mm for cylinders and meshes).
    assert pos[2] == pytest.approx(rest_height, abs=1.5e-3)
    assert abs(pybullet.getEulerFromQuaternion(orn)[0]) < 0.02
    assert abs(pybullet.getEulerFromQuaternion(orn)[1]) < 0.02


def test_urdf_inertia_is_taken_from_the_file(written, kind, client):
    files = written[kind]
    body = _load(files, "urdf", client, 0.1)
    principal = pybullet.getDynamicsInfo(body, -1, physicsClientId=client)[2]
    expected = np.linalg.eigvalsh(np.asarray(files.mass.inertia))
    np.testing.assert_allclose(sorted(principal), expected, rtol=1e-6)
