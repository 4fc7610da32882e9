"""Scene expressions: the numbers of a scene's ``[[body]]`` tables and its ``[values]``.

Each ``[[body]]`` names a registered body kind
(:data:`creative_py.world.bodies.BODY_KINDS`) and gives its fields; a number may be
written as an arithmetic expression over the scene's ``[values]`` and other bodies'
fields, so that a variant or a location changes one value and everything built from it
follows::

    [values]
    table_top = -0.20

    [[body]]
    name = "tube1"
    kind = "tube"
    length = 0.30                               # a variant sets "tube1.length"
    floor_z = "table_top + 0.10 + tube1.wall"
    ...

    [[body]]
    name = "cube1"
    kind = "box"
    position = ["tube1.mouth_x + tube1.length - back_gap", "tube1.axis_y + lateral", ...]

Expressions take ``+ - * / **``, parentheses, numbers, ``pi``, names of ``[values]``,
``body.field`` (``body.field[i]`` for a vector), ``tool.<quantity>`` of the episode's
tool (:mod:`creative_py.backends.pybullet.tools`) and the functions ``min max abs sqrt sin cos
radians``. Variants (``case.toml``) and locations (``tasks.toml``) override values
with dotted keys (``"tube1.length" = 0.45``, ``back_gap = 0.04``).
"""

from __future__ import annotations

import ast
import math
from typing import Any, Callable, Mapping

from creative_py.world_files import WorldFileError

_FUNCTIONS: dict[str, Callable[..., float]] = {
    "min": min, "max": max, "abs": abs, "sqrt": math.sqrt, "sin": math.sin,
    "cos": math.cos, "radians": math.radians}
_BINOPS = {ast.Add: lambda a, b: a + b, ast.Sub: lambda a, b: a - b,
           ast.Mult: lambda a, b: a * b, ast.Div: lambda a, b: a / b,
           ast.Pow: lambda a, b: a ** b}


class Namespace:
    """Resolve scene values: ``[values]`` names, ``body.field`` and ``tool.quantity``.

    Parameters
    ----------
    values : mapping
        ``name -> raw value`` of the ``[values]`` table (numbers or expressions).
    bodies : mapping
        ``body name -> {field: raw value}``.
    tool : mapping
        ``quantity -> number`` of the episode's tool (empty when there is none).
    source : str
        Where the values come from (named in errors).
    """

    def __init__(self, values: Mapping[str, Any], bodies: Mapping[str, Mapping[str, Any]],
                 tool: Mapping[str, float] | None = None, source: str = "scene.toml") -> None:
        self.values = dict(values)
        self.bodies = {k: dict(v) for k, v in bodies.items()}
        self.tool = dict(tool or {})
        self.source = source
        self._cache: dict[str, Any] = {}
        self._busy: set[str] = set()

    def override(self, settings: Mapping[str, Any], source: str) -> None:
        """Replace values by dotted keys (``"tube1.length"``, ``"back_gap"``)."""
        for key, value in settings.items():
            if "." in key:
                body, _, name = key.partition(".")
                if body not in self.bodies or name not in self.bodies[body]:
                    raise WorldFileError(f"{source}: key {key!r}: no such scene value (body "
                                         f"fields are set as 'body.field'; bodies: "
                                         f"{', '.join(self.bodies)})")
                self.bodies[body][name] = value
            else:
                if key not in self.values:
                    raise WorldFileError(f"{source}: key {key!r}: no such scene value "
                                         f"([values]: {', '.join(self.values) or 'none'})")
                self.values[key] = value
        self._cache.clear()

    def get(self, key: str) -> Any:
        """Return the resolved value of ``key`` (a number or a tuple of numbers)."""
        if key in self._cache:
            return self._cache[key]
        if key in self._busy:
            raise WorldFileError(f"{self.source}: value {key!r} is defined through itself")
        self._busy.add(key)
        try:
            if key.startswith("tool."):
                name = key[5:]
                if name not in self.tool:
                    raise WorldFileError(f"{self.source}: {key!r}: the tool has no such "
                                         f"quantity (it has {', '.join(self.tool) or 'none'})")
                raw = self.tool[name]
            elif "." in key:
                body, _, name = key.partition(".")
                if body not in self.bodies or name not in self.bodies[body]:
                    raise WorldFileError(f"{self.source}: {key!r}: no such body field")
                raw = self.bodies[body][name]
            elif key in self.values:
                raw = self.values[key]
            else:
                raise WorldFileError(f"{self.source}: {key!r}: no such value in [values]")
            value = self.evaluate(raw, key)
        finally:
            self._busy.discard(key)
        self._cache[key] = value
        return value

    def evaluate(self, raw: Any, where: str) -> Any:
        """Return ``raw`` with every expression string evaluated (lists element-wise)."""
        if isinstance(raw, bool):
            return raw
        if isinstance(raw, (int, float)):
            return float(raw)
        if isinstance(raw, (list, tuple)):
            return tuple(self.evaluate(v, f"{where}[{i}]") for i, v in enumerate(raw))
        if isinstance(raw, str):
            try:
                tree = ast.parse(raw, mode="eval")
            except SyntaxError:
                raise WorldFileError(f"{self.source}: {where}: not an expression: "
                                     f"{raw!r}") from None
            try:
                value = self._node(tree.body, raw, where)
            except WorldFileError as exc:
                raise WorldFileError(f"{exc} (in {where} = {raw!r})") from None
            except (TypeError, ValueError, ZeroDivisionError, OverflowError) as exc:
                raise WorldFileError(f"{self.source}: {where}: {raw!r}: {exc}") from None
            if not isinstance(value, (int, float)) or not math.isfinite(value):
                raise WorldFileError(f"{self.source}: {where}: {raw!r} is not finite")
            return float(value)
        return raw

    def _node(self, node: ast.AST, text: str, where: str) -> Any:
        if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)) \
                and not isinstance(node.value, bool):
            return node.value
        if isinstance(node, ast.BinOp) and type(node.op) in _BINOPS:
            return _BINOPS[type(node.op)](self._node(node.left, text, where),
                                          self._node(node.right, text, where))
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
            v = self._node(node.operand, text, where)
            return -v if isinstance(node.op, ast.USub) else v
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) \
                and node.func.id in _FUNCTIONS and not node.keywords:
            return _FUNCTIONS[node.func.id](*(self._node(a, text, where) for a in node.args))
        if isinstance(node, ast.Subscript) and isinstance(node.slice, ast.Constant):
            seq = self._node(node.value, text, where)
            try:
                return seq[node.slice.value]
            except (TypeError, IndexError):
                raise WorldFileError(f"{self.source}: {where}: bad index in {text!r}") from None
        if isinstance(node, ast.Name):
            if node.id == "pi":
                return math.pi
            return self.get(node.id)
        if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name):
            return self.get(f"{node.value.id}.{node.attr}")
        raise WorldFileError(f"{self.source}: {where}: {text!r} uses something an "
                             "expression cannot (numbers, + - * / **, values, body.field, "
                             "tool.quantity, min max abs sqrt sin cos radians)")

