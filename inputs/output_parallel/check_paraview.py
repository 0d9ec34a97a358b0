"""Both output layouts as ParaView 5.11 reads them (Debian python3-paraview, no display):
the single file and the file-per-rank set of 1, 2 and 3 ranks, 2D and 3D, through the IOSS
reader (ParaView's default) and the ExodusIIReader, each opened from one file name (a set
from its first file, `case.e.3.0`, as ParaView's file dialog offers it):

- the time steps are those of the 1-rank single file;
- the point and cell arrays have the same names (IOSS: `displ`, `lm`, `slip` vectors,
  `stress` one tensor with components labelled XX YY ZZ XY YZ XZ);
- every node and element carries its global id (IOSS `ids`, ExodusIIReader `GlobalNodeId` /
  `GlobalElementId`), each id once in a single file and every id of the mesh in the set;
- the values, matched by global id, are those of the 1-rank single file: bitwise for the
  1-rank set, to 1e-8 relative (the solve's round-off on another partition; normal_gap,
  itself round-off where the contact is closed, relative to the displacement) otherwise; a
  node that two files of a set hold has the same values in both.

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

ROUND_OFF = 1e-8
LABELS = ["XX", "YY", "ZZ", "XY", "YZ", "XZ"]
failures = []


def expect(ok, what):
    print("  %s %s" % ("ok  " if ok else "FAIL", what))
    if not ok:
        failures.append(what)


class Read:
    """What one reader gives for one file name at one time: arrays keyed by global id."""

    def __init__(self, kind, path, time=None):
        if kind == "ioss":
            r = simple.IOSSReader(FileName=[path])
            r.UpdatePipelineInformation()
            r.SideSets = []
            r.NodeSets = []
            point_id, cell_id = "ids", "ids"
        else:
            r = simple.ExodusIIReader(FileName=[path])
            r.UpdatePipelineInformation()
            r.PointVariables = r.PointVariables.Available
            r.ElementVariables = r.ElementVariables.Available
            r.GenerateGlobalNodeIdArray = 1
            r.GenerateGlobalElementIdArray = 1
            point_id, cell_id = "GlobalNodeId", "GlobalElementId"
        self.times = list(r.TimestepValues)
        time = self.times[-1] if time is None else time
        r.UpdatePipeline(time)
        info = r.GetDataInformation().DataInformation.GetCellDataInformation()
        stress = info.GetArrayInformation("stress")
        self.stress_labels = ([stress.GetComponentName(c)
                               for c in range(stress.GetNumberOfComponents())] if stress else [])
        merge = simple.MergeBlocks(Input=r, MergePoints=0)
        merge.UpdatePipeline(time)
        d = dsa.WrapDataObject(sm.Fetch(merge))
        simple.Delete(merge)
        simple.Delete(r)
        self.point_names = sorted(k for k in d.PointData.keys() if k != point_id)
        self.cell_names = sorted(k for k in d.CellData.keys() if k != cell_id)
        self.point_ids = np.array(d.PointData[point_id]) if point_id in d.PointData.keys() else None
        self.cell_ids = np.array(d.CellData[cell_id]) if cell_id in d.CellData.keys() else None
        self.points = {k: np.array(d.PointData[k]) for k in self.point_names}
        self.cells = {k: np.array(d.CellData[k]) for k in self.cell_names}
        self.points["coordinates"] = np.array(d.Points)

    def by_id(self, arrays, ids, name):
        """Values of `name` in global-id order, and whether duplicates of an id agree."""
        values = arrays[name]
        order = np.argsort(ids, kind="stable")
        unique, first = np.unique(ids[order], return_index=True)
        sorted_values = values[order]
        consistent = np.array_equal(sorted_values, sorted_values[first][
            np.searchsorted(unique, ids[order])])
        return unique, sorted_values[first], consistent


def compare(kind, reference, got, what, exact):
    """`got` against `reference` (the same reader on the 1-rank single file), by global id."""
    expect(got.times == reference.times, "%s: times as the 1-rank file (%d steps)" %
           (what, len(got.times)))
    expect(got.point_names == reference.point_names and got.cell_names == reference.cell_names,
           "%s: arrays %s / %s" % (what, got.point_names, got.cell_names))
    if kind == "ioss":
        expect(got.stress_labels == LABELS, "%s: stress components %s" % (what, got.stress_labels))
    if got.point_ids is None or got.cell_ids is None:
        expect(False, "%s: global ids of points and cells" % what)
        return
    worst, consistent, ids_ok = 0.0, True, True
    for arrays, ref_arrays, ids, ref_ids, names in (
            (got.points, reference.points, got.point_ids, reference.point_ids,
             got.point_names + ["coordinates"]),
            (got.cells, reference.cells, got.cell_ids, reference.cell_ids, got.cell_names)):
        for name in names:
            ids_got, values, same = got.by_id(arrays, ids, name)
            ids_ref, ref_values, _ = reference.by_id(ref_arrays, ref_ids, name)
            consistent &= same
            if not np.array_equal(ids_got, ids_ref):
                ids_ok = False
                continue
            scale = max(np.abs(ref_values).max(initial=0.0), 1e-300)
            if name == "normal_gap":  # round-off where closed: against the displacement
                scale = np.abs(ref_arrays["displ" if kind == "ioss" else "displ_"]).max()
            worst = max(worst, np.abs(values - ref_values).max(initial=0.0) / scale)
    expect(ids_ok, "%s: every global id of the mesh (%d nodes, %d elements)" %
           (what, len(np.unique(got.point_ids)), len(np.unique(got.cell_ids))))
    expect(consistent, "%s: a node in two files has the same values in both" % what)
    tolerance = 0.0 if exact else ROUND_OFF
    expect(worst <= tolerance, "%s: values by global id within %g of the 1-rank file (%.1e)" %
           (what, tolerance, worst))


def main():
    for case in ("contact_2d", "contact_3d"):
        for kind in ("ioss", "exodus"):
            reference = Read(kind, "np1/%s.e" % case)
            single_ids = np.unique(reference.point_ids) if reference.point_ids is not None else []
            expect(reference.point_ids is not None and
                   len(single_ids) == len(reference.point_ids),
                   "%s %s np1 single file: one point per node" % (case, kind))
            middle = reference.times[len(reference.times) // 2]
            reference_middle = Read(kind, "np1/%s.e" % case, middle)
            for ranks in (1, 2, 3):
                per_rank = "np%d/%s_per_rank.e%s" % (ranks, case,
                                                     ".%d.0" % ranks if ranks > 1 else "")
                for path, exact in (("np%d/%s.e" % (ranks, case), ranks == 1),
                                    (per_rank, ranks == 1)):
                    what = "%s %s %s" % (case, kind, path)
                    compare(kind, reference, Read(kind, path), what, exact)
                    compare(kind, reference_middle, Read(kind, path, middle),
                            what + " at t = %g" % middle, exact)
    if failures:
        print("check_paraview: %d failure(s)" % len(failures))
        return 1
    print("check_paraview: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
