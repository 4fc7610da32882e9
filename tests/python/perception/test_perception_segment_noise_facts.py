"""Segmentation masks, the noise model and the facts written from estimates."""

from __future__ import annotations

import numpy as np
import pytest

from creative_py.perception import Frame, NoiseModel, ObjectEstimate, facts_from_estimates
from creative_py.perception.segment import body_mask, link_index
from creative_py.perception.unproject import depth_buffer_to_metres, near_far_from_projection

PROJ = (1.0, 0, 0, 0, 0, 1.0, 0, 0, 0, 0, -31 / 29, -1, 0, 0, -6 / 29, 0)  # near 0.1, far 3


def frame(h=40, w=50) -> Frame:
    seg = np.full((h, w), -1, np.int32)
    seg[10:20, 10:20] = 3                     # body 3, base link
    seg[10:20, 30:40] = 3 + (5 << 24)         # body 3, link 4
    seg[25:30, 10:20] = 7 + (1 << 24)         # body 7, link 0
    view = tuple(np.eye(4).ravel())
    return Frame("cam", np.zeros((h, w, 3), np.uint8), np.full((h, w), 0.9, np.float32), seg,
                 view, PROJ, w, h)


def test_body_mask_gathers_all_links_and_never_background():
    f = frame()
    assert body_mask(f.seg, 3).sum() == 200
    assert body_mask(f.seg, 7).sum() == 50
    assert body_mask(f.seg, 0xFFFFFF).sum() == 0  # -1 & 0xFFFFFF must not count
    assert set(np.unique(link_index(f.seg[body_mask(f.seg, 3)]))) == {-1, 4}
    with pytest.raises(ValueError, match="body id"):
        body_mask(f.seg, -1)


def test_noise_is_deterministic_per_seed_and_has_the_stated_size():
    f = frame(200, 200)
    model = NoiseModel(depth_sigma_m=0.004, dropout=0.1)
    a = model.apply(f, np.random.default_rng(1))
    b = model.apply(f, np.random.default_rng(1))
    c = model.apply(f, np.random.default_rng(2))
    assert np.array_equal(a.depth, b.depth) and np.array_equal(a.seg, b.seg)
    assert not np.array_equal(a.depth, c.depth)
    near, far = near_far_from_projection(f.proj)
    dz = depth_buffer_to_metres(a.depth, near, far) - depth_buffer_to_metres(f.depth, near, far)
    assert abs(dz.std() - 0.004) < 0.0003
    shown = f.seg != -1
    dropped = (a.seg == -1) & shown
    assert abs(dropped.sum() / shown.sum() - 0.1) < 0.03
    assert f.seg[15, 15] == 3 and np.all(f.depth == np.float32(0.9))  # input untouched


def test_noise_model_rejects_bad_fields_naming_them():
    with pytest.raises(ValueError, match="depth_sigma_m"):
        NoiseModel(depth_sigma_m=-0.1)
    with pytest.raises(ValueError, match="dropout"):
        NoiseModel(dropout=1.0)
    with pytest.raises(ValueError, match="scene.toml: noise: unknown field.*sigma"):
        NoiseModel.from_dict({"sigma": 0.1}, "scene.toml")
    with pytest.raises(ValueError, match="scene.toml: .*dropout"):
        NoiseModel.from_dict({"dropout": "lots"}, "scene.toml")
    assert NoiseModel.from_dict({"depth_sigma_m": 0.001}, "s").depth_sigma_m == 0.001


def test_frame_refuses_mismatched_arrays():
    f = frame()
    with pytest.raises(ValueError, match="depth has shape"):
        f.replace(depth=np.zeros((3, 3)))
    with pytest.raises(ValueError, match="view must have 16"):
        f.replace(view=(1.0,) * 9)


def test_facts_are_pose_then_size_in_name_order():
    cube = ObjectEstimate("cube1", 0.9, -0.1, -0.185, 0.2, (0.03, 0.03, 0.03), 100, ("top",),
                          "half_pi")
    wedge = ObjectEstimate("wedge_a2", 0.4, 0.3, 0.015, -2.0, (0.06, 0.05, 0.03), 200,
                           ("top", "side"))
    facts = facts_from_estimates({"wedge_a2": wedge, "cube1": cube})
    assert facts == [("pose", "cube1", 0.9, -0.1, -0.185, 0.2),
                     ("size", "cube1", 0.03, 0.03, 0.03),
                     ("pose", "wedge_a2", 0.4, 0.3, 0.015, -2.0),
                     ("size", "wedge_a2", 0.06, 0.05, 0.03)]
    assert all(type(v) is float for fact in facts for v in fact[2:])
