"""Reads one mpmcut particle snapshot with meshio (an independent VTU reader) and checks it.

usage: /usr/bin/python3 vtu_roundtrip_check.py FILE.vtu EXPECTED_PARTICLE_COUNT
Exit code 0 when every expected array is present with the right shape and finite values.
Imported by test_vtu_meshio.py, called by the C++ unit test test_output_writers.cpp.
"""
import sys

import meshio
import numpy as np

# name -> number of components: the arrays that tools/*.py and users rely on, which must stay.
# A field added to the registry (src/core/particle_fields.hpp) adds an array; it need not be
# listed here, but must have one row per point and finite values like every array.
EXPECTED_POINT_FIELDS = {
    "velocity_m_per_s": 3,
    "stress_Pa": 6,
    "von_mises_stress_Pa": 1,
    "pressure_Pa": 1,
    "effective_stress_Pa": 6,
    "mass_kg_per_m": 1,
    "volume_m3_per_m": 1,
    "density_kg_per_m3": 1,
    "body_id": 1,
    "material_id": 1,
    "plastic_strain": 1,
    "plastic_strain_rate_per_s": 1,
    "temperature_K": 1,
    "damage_initiation": 1,
    "damage": 1,
    "plastic_displacement_m": 1,
    "fracture_energy_J_per_m2": 1,
    "damage_dissipation_J_per_m": 1,
    "deformation_jacobian_J": 1,
    "velocity_gradient_per_s": 9,
}


def check_vtu(path, expected_count):
    """Returns a list of problems (empty when the file is good) and the mesh."""
    problems = []
    mesh = meshio.read(path)
    n = mesh.points.shape[0]
    if n != expected_count:
        problems.append(f"{path}: {n} points, expected {expected_count}")
    if mesh.points.shape[1] != 3 or not np.all(mesh.points[:, 2] == 0.0):
        problems.append(f"{path}: points are not (x, y, 0)")
    if not np.all(np.isfinite(mesh.points)):
        problems.append(f"{path}: non-finite point coordinates")
    vertices = [c for c in mesh.cells if c.type == "vertex"]
    if len(vertices) != 1 or len(vertices[0].data) != n:
        problems.append(f"{path}: expected one vertex cell per point")
    for name, components in EXPECTED_POINT_FIELDS.items():
        if name not in mesh.point_data:
            problems.append(f"{path}: missing point array '{name}'")
            continue
        a = np.asarray(mesh.point_data[name])
        shape = (n,) if components == 1 else (n, components)
        if a.shape != shape:
            problems.append(f"{path}: '{name}' has shape {a.shape}, expected {shape}")
        elif not np.all(np.isfinite(a)):
            problems.append(f"{path}: '{name}' has non-finite values")
    for name in sorted(set(mesh.point_data) - set(EXPECTED_POINT_FIELDS)):
        a = np.asarray(mesh.point_data[name])
        if a.shape[0] != n:
            problems.append(f"{path}: '{name}' has {a.shape[0]} rows, expected {n}")
        elif not np.all(np.isfinite(a)):
            problems.append(f"{path}: '{name}' has non-finite values")
    problems += check_with_vtk(path, n)
    return problems, mesh


def check_with_vtk(path, expected_count):
    """ParaView's own reader, where VTK's Python module is installed (optional: python3-vtk9)."""
    try:
        import vtk
    except ImportError:
        return []
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    problems = []
    if grid.GetNumberOfPoints() != expected_count:
        problems.append(f"{path}: VTK reads {grid.GetNumberOfPoints()} points")
    point_data = grid.GetPointData()
    for name, components in EXPECTED_POINT_FIELDS.items():
        a = point_data.GetArray(name)
        if a is None or a.GetNumberOfComponents() != components or \
                a.GetNumberOfTuples() != expected_count:
            problems.append(f"{path}: VTK does not read '{name}' as {components} components")
    return problems


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    problems, mesh = check_vtu(sys.argv[1], int(sys.argv[2]))
    for p in problems:
        print("FAIL:", p, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
