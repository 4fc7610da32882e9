"""Fabrication: a created tool sized by the engine's size model, written, split and sliced
(:mod:`manufacture`), and checked against the force its trial measured (:mod:`strength`)."""
