"""Tool geometry and manufacturing: parametric specs -> solids -> URDF, SDF, SCAD, STL, PNG.

Modules (import them directly; this package imports nothing heavy so that ``spec`` stays
cheap for the simulator):

- ``spec``: the mesh view of a tool kind's spec (:mod:`creative_py.kinds`): parts, volume, mass.
- ``solid``: manifold3d union of the parts, trimesh mass properties.
- ``printability``: minimum feature (refused) and build-volume fit (flagged).
- ``link``, ``urdf``, ``sdf``, ``scad``, ``render``: one writer per format.
- ``split``: a tool larger than the build volume -> pieces that fit, dowel-pin joints.
- ``slicer``: PrusaSlicer's command line: a piece's STL -> G-code, print time, filament
  (profile in ``profiles/``).
- ``export``: ``write_tool_files(spec, out_dir) -> ToolFiles`` (atomic tool folder, with
  the printed pieces and, ``gcode=True``, their G-code).
- ``check``: ``check_tool_files(files) -> ToolCheck`` (reads the files back, runs OpenSCAD);
  ``check_print_files(files) -> PrintCheck`` (the pieces, united again, and their G-code).
- ``tolerances``: every tolerance and printer limit.

Only this package imports trimesh and manifold3d.
"""
