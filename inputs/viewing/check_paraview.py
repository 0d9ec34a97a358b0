"""Grout's Exodus results as ParaView reads them (Debian python3-paraview, no display needed):

    /usr/bin/python3 check_paraview.py contact_2d.e contact_3d.e

IOSS reader (ParaView's default for .e files):
- the time values are 0.1, 0.2, ..., 1.0 exactly, and asking for t = 0.3 or t = 1 gives that
  step (contact_pressure = 4 t on the slave side set, the exact patch-test value);
- `displ` is one vector (2 components in 2D, 3 in 3D) and `stress` one symmetric tensor
  (6 components xx yy zz xy yz zx, in 2D too), both grouped by IOSS from Grout's names;
- side set `upper_bottom` and node set `upper_bottom_nodes` are read as two sets with their
  own points and values (when a node set and a side set share a name, IOSS returns one).
ExodusIIReader: `displ_` is a 3-vector in 2D too (what Warp By Vector needs), same times.

Exit code 77 (ctest: skipped) when ParaView's Python modules are not installed.
"""
import sys

try:
    from paraview import servermanager as sm
    from paraview import simple
    from vtkmodules.numpy_interface import dataset_adapter as dsa
except ImportError as e:
    print("check_paraview: skipped: ParaView's Python modules are not installed "
          "(Debian: apt-get install python3-paraview): %s" % e)
    sys.exit(77)

import numpy as np

TIMES = [k / 10 for k in range(1, 11)]  # the doubles nearest 0.1, ..., 1.0
failures = []


def expect(ok, what):
    print("  %s %s" % ("ok  " if ok else "FAIL", what))
    if not ok:
        failures.append(what)


def merged(reader, time):
    """Everything the reader outputs at `time`, merged into one unstructured grid (numpy view)."""
    merge = simple.MergeBlocks(Input=reader, MergePoints=0)
    merge.UpdatePipeline(time)
    data = dsa.WrapDataObject(sm.Fetch(merge))
    simple.Delete(merge)
    return data


def components(reader, name):
    array = reader.PointData.GetArray(name) or reader.CellData.GetArray(name)
    return array.GetNumberOfComponents() if array else 0


def check_ioss(path, dim, n_slave):
    print("%s, IOSS reader (%dD)" % (path, dim))
    r = simple.IOSSReader(FileName=[path])
    r.UpdatePipelineInformation()
    times = list(r.TimestepValues)
    expect(times == TIMES, "times %s" % times)
    r.UpdatePipeline(1.0)
    expect(components(r, "displ") == dim, "displ is a %d-vector (%d components)" % (dim, components(r, "displ")))
    n_stress = 6  # xx yy zz xy yz zx, in 2D too (docs/viewing.md)
    expect(components(r, "stress") == n_stress,
           "stress is one tensor of %d components (got %d; cell arrays %s)"
           % (n_stress, components(r, "stress"), r.CellData.keys()))
    expect(components(r, "contact_pressure") == 1, "contact_pressure is a scalar")
    side_sets = set(r.GetPropertyValue("SideSetInfo")[::2])
    node_sets = set(r.GetPropertyValue("NodeSetInfo")[::2])
    expect(side_sets and not side_sets & node_sets,
           "side set names %s and node set names %s are distinct" % (sorted(side_sets), sorted(node_sets)))
    # The slave side set and its node set, alone: the values of the step asked for.
    r.ElementBlocks = []
    r.SideSets = ["upper_bottom"]
    r.NodeSets = ["upper_bottom_nodes"]
    for t in (0.3, 1.0):
        d = merged(r, t)
        p = np.array(d.PointData["contact_pressure"])
        n = d.GetNumberOfPoints()
        expect(n == 2 * n_slave and np.allclose(p, 4 * t, rtol=1e-8, atol=0),
               "t = %g: side set upper_bottom + node set upper_bottom_nodes: %d points (expected "
               "2 x %d), contact_pressure %s (expected 4 t = %g)" % (t, n, n_slave, np.unique(p.round(12)), 4 * t))
    simple.Delete(r)


def check_exodus_reader(path, dim):
    print("%s, ExodusIIReader (%dD)" % (path, dim))
    r = simple.ExodusIIReader(FileName=[path])
    r.UpdatePipelineInformation()
    expect(list(r.TimestepValues) == TIMES, "times %s" % list(r.TimestepValues))
    r.PointVariables = r.PointVariables.Available
    r.ElementVariables = r.ElementVariables.Available
    r.UpdatePipeline(1.0)
    expect(components(r, "displ_") == 3, "displ_ is a 3-vector (%d components)" % components(r, "displ_"))
    d = merged(r, 0.3)
    p = np.array(d.PointData["contact_pressure"])
    expect(np.isclose(p.max(), 1.2, rtol=1e-8), "t = 0.3: max contact_pressure %.12g (expected 1.2)" % p.max())
    simple.Delete(r)


def main(path_2d, path_3d):
    # Slave nodes: 5 upper cells along the 2D interface, 3 x 3 in 3D (CMakeLists.txt).
    for path, dim, n_slave in ((path_2d, 2, 6), (path_3d, 3, 16)):
        check_ioss(path, dim, n_slave)
    check_exodus_reader(path_2d, 2)
    if failures:
        print("check_paraview: %d failure(s)" % len(failures))
        return 1
    print("check_paraview: ok")
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(__doc__)
        sys.exit(2)
    sys.exit(main(sys.argv[1], sys.argv[2]))
