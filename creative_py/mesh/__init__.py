"""Tool geometry and manufacturing: parametric specs -> solids -> URDF, SDF, SCAD, STL, PNG.

Modules (import them directly; this package imports nothing heavy so that ``spec`` stays
cheap for the simulator):

- ``spec``: HookSpec / BlockSpec and their parts (pure Python, shared with sim/ontology).
- ``solid``: manifold3d union of the parts, trimesh mass properties.
- ``printability``: minimum feature (refused) and build-volume fit (flagged).
- ``link``, ``urdf``, ``sdf``, ``scad``, ``render``: one writer per format.
- ``export``: ``write_tool_files(spec, out_dir) -> ToolFiles`` (atomic tool folder).
- ``check``: ``check_tool_files(files) -> ToolCheck`` (reads the files back, runs OpenSCAD).
- ``tolerances``: every tolerance and printer limit.

Only this package imports trimesh and manifold3d.
"""
