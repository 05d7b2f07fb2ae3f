"""The referee of the benchmarks against Gmsh: Gmsh's own AnalyseMeshQuality plugin."""
import gmsh


def referee():
    """(invalid, worst, triangles) of Gmsh's AnalyseMeshQuality per-element minJ/maxJ on the
    current model: the count of values <= 0, the smallest value, and the number of values
    (checked to be one per triangle)."""
    for name, value in [("JacobianDeterminant", 1), ("IGEMeasure", 0), ("ICNMeasure", 0),
                        ("CreateView", 1), ("Recompute", 1), ("DimensionOfElements", 2)]:
        gmsh.plugin.setNumber("AnalyseMeshQuality", name, value)
    before = set(gmsh.view.getTags())
    gmsh.plugin.run("AnalyseMeshQuality")
    for tag in set(gmsh.view.getTags()) - before:
        name = gmsh.option.getString(f"View[{gmsh.view.getIndex(tag)}].Name")
        if name.startswith("minJ/maxJ"):
            _, _, data, _, _ = gmsh.view.getModelData(tag, 0)
            values = [d[0] for d in data]
            triangles = sum(len(t) for t in gmsh.model.mesh.getElements(2)[1])
            if len(values) != triangles:
                raise RuntimeError(f"minJ/maxJ view has {len(values)} values, {triangles} triangles")
            return sum(v <= 0 for v in values), min(values), len(values)
    raise RuntimeError("AnalyseMeshQuality made no minJ/maxJ view")


def icn():
    """(min, mean, triangles, invalid) of Gmsh's AnalyseMeshQuality ICN (inverse condition
    number: the mean ratio of a linear triangle) and the count of its minJ/maxJ <= 0, on the
    current model."""
    import numpy as np
    for name, value in [("JacobianDeterminant", 1), ("IGEMeasure", 0), ("ICNMeasure", 1),
                        ("CreateView", 1), ("Recompute", 1), ("DimensionOfElements", 2)]:
        gmsh.plugin.setNumber("AnalyseMeshQuality", name, value)
    before = set(gmsh.view.getTags())
    gmsh.plugin.run("AnalyseMeshQuality")
    values = {}
    for tag in set(gmsh.view.getTags()) - before:
        name = gmsh.option.getString(f"View[{gmsh.view.getIndex(tag)}].Name")
        _, _, data, _, _ = gmsh.view.getModelData(tag, 0)
        values[name.split()[0]] = np.array([d[0] for d in data])
    q, jac = values["ICN"], values["minJ/maxJ"]
    return float(q.min()), float(q.mean()), len(q), int((jac <= 0).sum())
