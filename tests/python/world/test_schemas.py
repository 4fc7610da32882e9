"""The world package's schemas and the pybullet backend's implementations of them.

The reader of world files checks a skill's options, a tool's ``[tool_start]`` fields and
a camera against the schemas of ``creative_py.world`` (no pybullet); the pybullet
backend runs what they describe. These tests keep the two sides the same: every skill
schema has a primitive and every primitive a schema, every handling schema a tool kind
with its fields and grasp options, and the schema modules load without pybullet.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from creative_py.backends.pybullet import primitives, tools
from creative_py.world import handlings, skills

ROOT = Path(__file__).resolve().parents[3]
SCHEMA_MODULES = ("creative_py.world.skills", "creative_py.world.handlings",
                  "creative_py.world.cameras")


def test_every_skill_schema_has_a_pybullet_primitive_and_every_primitive_a_schema():
    assert list(primitives.PRIMITIVES) == list(skills.SKILLS)
    for name, schema in skills.SKILLS.items():
        p = primitives.PRIMITIVES[name]
        assert p.schema is schema and p.name == name, name
        assert (p.options, p.target, p.bounds, p.check) == (
            schema.options, schema.target, schema.bounds, schema.check), name
        assert callable(p.run), name


def test_every_handling_schema_has_a_pybullet_tool_kind_with_its_fields():
    assert list(tools.HANDLINGS) == list(handlings.HANDLINGS)
    for name, schema in handlings.HANDLINGS.items():
        kind = tools.HANDLINGS[name]
        assert kind.START_FIELDS == schema.start_fields, name
        assert kind.GRASP_OPTIONS == schema.grasp_options, name


def test_the_grasp_primitive_takes_every_handling_s_grasp_options():
    union = {}
    for h in handlings.HANDLINGS.values():
        union.update(h.grasp_options)
    assert skills.SKILLS["grasp"].options == union
    assert list(union) == ["approach", "free_speed", "speed", "lift_to", "carry_z",
                           "clearance", "gripper_yaw"]


class _Spec:
    name = "odd"
    HANDLING = "tongs"


def test_a_spec_without_a_registered_handling_is_refused_naming_the_handlings():
    message = "'odd': no handling 'tongs' in the simulator; handlings: handle, top"
    with pytest.raises(TypeError) as schema_error:
        handlings.handling(_Spec())
    with pytest.raises(TypeError) as kind_error:
        tools.tool_kind(_Spec())
    assert str(schema_error.value) == str(kind_error.value) == message


@pytest.mark.parametrize("module", SCHEMA_MODULES)
def test_the_world_schema_modules_load_without_pybullet_or_a_backend(module):
    code = (f"import sys, {module}\n"
            "print(sorted(m for m in sys.modules if m.split('.')[0] == 'pybullet'\n"
            "             or m.startswith('creative_py.backends')))")
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(
        [str(ROOT), *filter(None, [os.environ.get("PYTHONPATH")])])}
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         cwd=ROOT, env=env, check=True).stdout
    assert out.strip() == "[]", (module, out)
