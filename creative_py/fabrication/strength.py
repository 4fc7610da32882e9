"""Is a created tool strong enough? A beam estimate from the force the physics measured.

After a created tool's successful trial, the force of the task's contact during the
tool action (the tool against the case's target, ``[roles] target``: the cube a hook
pulls, the door a wedge holds; the trial's ``tool_load``, measured by the backend:
:mod:`creative_py.backends.pybullet.loads`, :mod:`creative_py.backends.maniskill.loads`,
or over ROS 2 a wrist sensor, :func:`creative_py.backends.ros.episode.wrench_load`)
is turned into a stress and compared with the strength
of printed PLA (:data:`creative_py.mesh.spec.PLA_STRENGTH`), asking for a safety factor
of at least :data:`creative_py.mesh.spec.MIN_SAFETY_FACTOR`. The tool's kind gives the
load model (``KindSpec.load_model`` of :mod:`creative_py.kinds`); the shipped ones:

The force is the robust one (``robust_force_n``: the 95th percentile of the force
averaged over each 0.1 s of the action, over the windows with contact; the rule every
backend follows, :mod:`creative_py.simulator.load`), not the one-step peak
(``max_force_n``), which is a contact spike: the door's one-step peak on the created
wedge is 1,791 N where the load it bears is 436 N, and such a peak moves with the time
step (counting the floor as well, 3,557 N in one run of the same trial, 2,859 N in
another). The peak is kept beside it (``peak_force_n``, with the
safety factor it would give) and the check says so in its ``caveat``. What else the
tool touched (the table under a dragged tool, 1 mm from the grasp) is not the load:
the pull_cube_tool case's created tool was once checked against its table contact,
0.9 mm from the grasp, and passed with a safety factor of 4,018.

- **hook, stick, paddle** (a cantilever): the handle is held by the gripper and loaded where the
  contact acted, so it is a cantilever from the grasp to the contact. Its lever arm L
  is the distance along the handle (x of the tool frame) between the grasp and the
  contact point; the whole force F is taken as acting across the handle (an upper
  bound: a pull along the handle bends it less). With the square section of side w,
  I = w^4 / 12, c = w / 2 and ``sigma = M c / I = 6 F L / w^3``, M = F L.
- **block** (compression): nothing cantilevers, so the beam check does not apply; a
  block is squeezed between what it stops and the floor, and the check is
  ``sigma = F / A`` over its footprint A (length x width; pi d^2 / 4 for a cylinder).

A tool that fails is thickened within the task's constraints: the handle width that
passes, ``w = (6 F L s / strength)^(1/3)`` (s the safety factor, rounded up to 0.1 mm),
becomes a context fact ``min_handle_width_m(W)`` of the CLP size model (ontology
``size_constraint/3`` of the kind's file, ``ontology/kinds/hook_like.pl``, ``paddle.pl``) and the tool is sized again
(:func:`thicker_dims`); the creator then writes it and tries it in the physics, since the
physics is the oracle. When the size model cannot give such a width (the tool must
stay thin to pass under a shelf, or its literals say ``handle_width(T, thin)``), the
tool is rejected, naming the conflict.

Units: newtons, metres, pascals (the JSON also gives MPa).
"""

from __future__ import annotations

import json
import os
import tempfile
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any, Optional, Sequence

from creative_py.bridge import Compound, Engine, Term
from creative_py.kinds.parts import WIDTH_STEP, cantilever_stress, required_square_width
from creative_py.mesh.spec import MIN_SAFETY_FACTOR, PLA_STRENGTH, KindSpec

__all__ = ["MAX_THICKENINGS", "VERDICTS", "WIDTH_STEP", "StrengthCheck", "cantilever_stress",
           "check_strength", "rejected", "required_square_width", "thicker_dims",
           "thickening_fact", "write_strength"]

MAX_THICKENINGS = 3
"""How many times a created tool is thickened and tried again before it is rejected."""

VERDICTS = ("pass", "fail", "rejected", "unmeasured")
"""``pass``: the safety factor reaches the required one; ``fail``: it does not (the tool
was thickened into another, see ``thickened_into``); ``rejected``: it does not and no
thicker tool suits the task (``reason``); ``unmeasured``: the trial recorded no load."""


@dataclass(frozen=True)
class StrengthCheck:
    """The strength check of one tool from one trial's largest contact force.

    Attributes
    ----------
    tool : str
        The tool's name.
    model : {"cantilever", "compression"}
        The estimate: the handle as a cantilever from the grasp, or a block in
        compression over its footprint.
    force_n : float
        The force checked: the load's robust force (the 95th percentile of the task's
        contact force averaged over 0.1 s windows, over the windows with contact),
        newtons.
    lever_arm_m : float or None
        Cantilever: distance along the handle from the grasp to the contact, metres.
    section_m : tuple of float
        Cantilever: the handle's section (width, height); compression: the footprint
        (length, width) or (diameter, diameter), metres.
    area_m2, second_moment_m4, section_modulus_m3 : float or None
        Footprint area (compression); I and I / c of the handle's section (cantilever).
    moment_nm : float or None
        Bending moment at the grasp, F L, newton metres.
    stress_pa : float
        The estimated stress, pascals.
    strength_pa : float
        The material's strength, pascals.
    safety_factor : float or None
        ``strength_pa / stress_pa`` (None when the stress is 0).
    required_safety_factor : float
        The least safety factor accepted.
    verdict : str
        One of :data:`VERDICTS`.
    contact_point_m : tuple of float or None
        Where the force acted, tool frame, metres.
    grasp_point_m : tuple of float or None
        The grasp, tool frame, metres.
    bodies : tuple of str
        Whose contact the force is (the case's target; empty from a wrist sensor,
        which cannot tell contacts apart).
    trial : int or None
        The trial (number in ``trials.jsonl``) the force comes from.
    required_handle_width_m : float or None
        Cantilever: the handle width that would pass, metres.
    thickened_from : str or None
        The thinner tool this one was thickened from.
    thickened_into : str or None
        The thicker tool that replaced this one.
    note : str
        What the estimate assumes.
    reason : str
        Why the tool was rejected (empty otherwise).
    peak_force_n : float or None
        The one-step peak of the summed normal force (a contact spike), newtons.
    peak_safety_factor : float or None
        The safety factor the peak would give (the same model).
    caveat : str
        What the force figures rest on, in words.
    """

    tool: str
    model: str
    force_n: float
    lever_arm_m: Optional[float]
    section_m: tuple[float, float]
    area_m2: Optional[float]
    second_moment_m4: Optional[float]
    section_modulus_m3: Optional[float]
    moment_nm: Optional[float]
    stress_pa: float
    strength_pa: float
    safety_factor: Optional[float]
    required_safety_factor: float
    verdict: str
    contact_point_m: Optional[tuple[float, float, float]] = None
    grasp_point_m: Optional[tuple[float, float, float]] = None
    bodies: tuple[str, ...] = ()
    trial: Optional[int] = None
    required_handle_width_m: Optional[float] = None
    thickened_from: Optional[str] = None
    thickened_into: Optional[str] = None
    note: str = ""
    reason: str = ""
    peak_force_n: Optional[float] = None
    peak_safety_factor: Optional[float] = None
    caveat: str = ""

    @property
    def passed(self) -> bool:
        """Return whether the tool may be used (it passed, or no load was measured)."""
        return self.verdict in ("pass", "unmeasured")

    def to_dict(self) -> dict[str, Any]:
        """Return the figures as JSON-ready data (SI units, stresses also in MPa)."""
        def r(v, nd=9):
            return None if v is None else round(float(v), nd)
        return {
            "model": self.model,
            "force_n": r(self.force_n, 6),
            "lever_arm_m": r(self.lever_arm_m, 6),
            "section_m": [r(v, 6) for v in self.section_m],
            "area_m2": r(self.area_m2, 12),
            "second_moment_m4": None if self.second_moment_m4 is None
            else float(f"{self.second_moment_m4:.6g}"),
            "section_modulus_m3": None if self.section_modulus_m3 is None
            else float(f"{self.section_modulus_m3:.6g}"),
            "moment_nm": r(self.moment_nm, 6),
            "stress_mpa": r(self.stress_pa / 1e6, 6),
            "strength_mpa": r(self.strength_pa / 1e6, 6),
            "safety_factor": r(self.safety_factor, 3),
            "required_safety_factor": self.required_safety_factor,
            "verdict": self.verdict,
            "contact_point_m": None if self.contact_point_m is None
            else [r(v, 6) for v in self.contact_point_m],
            "grasp_point_m": None if self.grasp_point_m is None
            else [r(v, 6) for v in self.grasp_point_m],
            "bodies": list(self.bodies),
            "trial": self.trial,
            "required_handle_width_m": r(self.required_handle_width_m, 6),
            "thickened_from": self.thickened_from,
            "thickened_into": self.thickened_into,
            "note": self.note,
            "reason": self.reason,
            "peak_force_n": r(self.peak_force_n, 6),
            "peak_safety_factor": r(self.peak_safety_factor, 3),
            "caveat": self.caveat,
        }


def check_strength(spec: KindSpec, load: Optional[dict[str, Any]], *,
                   strength_pa: float = PLA_STRENGTH,
                   safety_factor: float = MIN_SAFETY_FACTOR,
                   trial: Optional[int] = None,
                   thickened_from: Optional[str] = None) -> StrengthCheck:
    """Return the strength check of ``spec`` under the trial's largest contact load.

    Parameters
    ----------
    spec : KindSpec
        The tool; its kind gives the load model (:meth:`KindSpec.load_model`).
    load : dict or None
        The trial's ``tool_load`` (:meth:`creative_py.simulator.load.ToolLoad.to_dict`):
        ``robust_force_n`` (the force checked; ``max_force_n`` for a load recorded
        before it existed), ``max_force_n`` (the peak, kept beside it), ``point`` and
        ``grasp_point`` in the tool frame (the lever arm runs from the grasp to the
        point), ``bodies``, ``contact_steps`` and ``window_s`` (for the caveat). None
        gives the verdict ``unmeasured``.
    strength_pa, safety_factor : float
        The material's strength and the least safety factor accepted.
    trial : int or None
        The trial the load comes from (recorded).
    thickened_from : str or None
        The thinner tool this one replaces (recorded).
    """
    peak = 0.0 if not load else float(load.get("max_force_n", 0.0))
    force = peak if not load else float(load.get("robust_force_n", peak))
    point = None if not load or load.get("point") is None else tuple(load["point"])
    bodies = tuple(load.get("bodies", ())) if load else ()
    common = dict(tool=spec.name, strength_pa=strength_pa,
                  required_safety_factor=safety_factor, contact_point_m=point,
                  bodies=bodies, trial=trial, thickened_from=thickened_from)
    grasp = (tuple(load["grasp_point"]) if load and load.get("grasp_point") is not None
             else None)
    figures = spec.load_model(force, point, grasp, strength_pa=strength_pa,
                              safety_factor=safety_factor)
    stress = figures["stress_pa"]
    check = StrengthCheck(force_n=force, safety_factor=strength_pa / stress if stress > 0
                          else None, verdict="", **figures, **common)
    peak_sf = None
    if load is not None and check.stress_pa > 0 and force > 0:
        peak_stress = check.stress_pa * peak / force  # every model is linear in F
        peak_sf = strength_pa / peak_stress if peak_stress > 0 else None
    check = replace(check, peak_force_n=peak if load is not None else None,
                    peak_safety_factor=peak_sf,
                    caveat="" if load is None else _load_caveat(load, force, peak, peak_sf))
    if load is None:
        verdict = "unmeasured"
    elif check.safety_factor is None or check.safety_factor >= safety_factor:
        verdict = "pass"
    else:
        verdict = "fail"
    return replace(check, verdict=verdict)


def _load_caveat(load: dict[str, Any], force: float, peak: float,
                 peak_sf: Optional[float]) -> str:
    """Return what the check's ``force`` (N) is, from the trial's ``load`` (windowed or
    per step, over how many steps with contact), and the safety factor the one-step
    ``peak`` (N) would give."""
    window = float(load.get("window_s") or 0.0)
    what = (f"the 95th percentile of the contact force averaged over {window:g} s windows "
            f"({load.get('contact_steps', 0)} steps with contact)" if window > 0 else
            f"the 95th percentile of the per-step contact force over "
            f"{load.get('contact_steps', 0) if load else 0} steps with contact")
    shown = f"{force:.3g}" if window > 0 else f"{force:.1f}"  # windowed: a few 0.1 N
    return (f"checked with {shown} N, {what}; the one-step peak "
            f"{peak:.1f} N (a contact spike, sensitive to the time step) would give a safety "
            f"factor of {'-' if peak_sf is None else f'{peak_sf:.1f}'}")


def thickening_fact(check: StrengthCheck) -> Compound:
    """Return the size-model context fact that asks for a handle which passes the check,
    ``min_handle_width_m(W)``.

    Raises
    ------
    ValueError
        The check is not a failed cantilever check (a block is not thickened).
    """
    if check.model != "cantilever" or check.verdict != "fail":
        raise ValueError(f"{check.tool}: only a failed cantilever check asks for a thicker "
                         f"handle (this is a {check.verdict} {check.model} check)")
    return Compound("min_handle_width_m", (check.required_handle_width_m,))


def thicker_dims(engine: Engine, case: str, kind: str, structural: Sequence[Term],
                 context: Sequence[Term], check: StrengthCheck) -> Term:
    """Size the tool again with a handle wide enough for ``check`` (CLP size model).

    Parameters
    ----------
    engine : Engine
        The Prolog engine.
    case : str
        The case the tool is for (its size constraints are the case's own).
    kind : str
        The size kind (``hook``, ``stick``).
    structural : sequence of terms
        The tool's structural literals (as Algorithm 2 sized it).
    context : sequence of terms
        The task's facts (tube, shelf, ...); the thickening fact is added.
    check : StrengthCheck
        The failed check.

    Returns
    -------
    Term
        ``dims([Field=Value, ...])`` or ``infeasible(Conflict)``
        (``geometry_clp:solve_size/5``).
    """
    return engine.solve_size(case, kind, list(structural),
                             list(context) + [thickening_fact(check)])


def rejected(check: StrengthCheck, conflict: Sequence[Term]) -> StrengthCheck:
    """Return ``check`` as rejected: no tool of the size model has a handle that wide.

    ``conflict`` is the size model's minimal conflict (its ``infeasible/1`` answer)."""
    names = ", ".join(str(t) for t in conflict)
    return replace(check, verdict="rejected", reason=(
        f"its handle would need to be at least {check.required_handle_width_m * 1e3:.1f} mm "
        f"wide for a safety factor of {check.required_safety_factor:g} under "
        f"{check.force_n:.2f} N at {check.lever_arm_m * 1e3:.0f} mm, and the size model "
        f"cannot give that: {names} cannot hold together"))


def write_strength(manifest: Path | str, check: StrengthCheck) -> None:
    """Add the check's figures under ``"strength"`` to a tool's JSON manifest
    (``tools/<name>/<name>.json``), replacing the file atomically."""
    manifest = Path(manifest)
    data = json.loads(manifest.read_text(encoding="utf-8"))
    data["strength"] = check.to_dict()
    fd, tmp = tempfile.mkstemp(prefix=f".{manifest.name}.", dir=manifest.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as fh:
            fh.write(json.dumps(data, indent=2) + "\n")
        os.chmod(tmp, manifest.stat().st_mode & 0o777)
        os.replace(tmp, manifest)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
