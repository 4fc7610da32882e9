"""The body kinds' schemas (``creative_py.world.bodies``) and the pybullet backend's builders.

The world package reads a scene without pybullet; the backend builds each kind it reads.
A kind without a builder could be written in a ``scene.toml`` and never built, a builder
without a kind could never be named: the two registries are checked against each other.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

import creative_py
from creative_py.backends.pybullet.scene import BODY_BUILDERS, SceneBody
from creative_py.world.bodies import BODY_KINDS, BodyKind


@pytest.mark.parametrize("kind", list(BODY_KINDS))
def test_every_body_kind_has_a_pybullet_builder_that_subclasses_it(kind):
    schema = BODY_KINDS[kind]
    assert issubclass(schema, BodyKind) and schema is not BodyKind
    assert kind in BODY_BUILDERS, f"body kind {kind!r} has no builder in BODY_BUILDERS"
    builder = BODY_BUILDERS[kind]
    assert issubclass(builder, schema) and issubclass(builder, SceneBody)
    # The kind's schema comes first: its fields, checks and geometry are the kind's own.
    assert builder.FIELDS is schema.FIELDS and builder.BOUNDS is schema.BOUNDS
    assert builder.__init__ is schema.__init__
    assert builder.build is not SceneBody.build


def test_no_builder_without_a_kind_and_the_same_order():
    assert list(BODY_BUILDERS) == list(BODY_KINDS)


def test_a_scatter_of_builders_draws_builders_of_boxes():
    assert issubclass(BODY_BUILDERS["scatter"].MEMBER, BODY_BUILDERS["box"])
    assert BODY_KINDS["scatter"].MEMBER is BODY_KINDS["box"]


@pytest.mark.parametrize("module", ["creative_py.world.bodies", "creative_py.world.expressions"])
def test_the_world_schemas_import_neither_pybullet_nor_a_backend(module):
    code = (f"import sys, json, {module}\n"
            "print(json.dumps(sorted(m for m in sys.modules if m.split('.')[0] == 'pybullet'"
            " or m.startswith('creative_py.backends'))))")
    root = str(Path(creative_py.__file__).resolve().parents[1])  # this checkout first
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(
        [root, *filter(None, [os.environ.get("PYTHONPATH")])])}
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True, env=env)
    assert json.loads(out.stdout) == []
