"""Grout's results as the tools read them, with end times that are not binary fractions:

    /usr/bin/python3 check.py        (in the folder holding np1/decimal_2d.e, np1/decimal_3d.e)

- time values (netCDF, ParaView's IOSS reader and its ExodusIIReader): step k of n to end T
  is the double nearest the decimal k T / n, the reference being Python's correctly rounded
  float(Fraction(k * D, n * 10^d)) for T = D / 10^d (1.4 = 14/10: 0.07, ..., 1.05, ..., 1.4;
  0.3 = 3/10 in 13 steps: 0.3 k / 13, no finite decimal);
- element variables: stress_xx yy zz xy yz zx in 2D as in 3D (yz, zx zero in 2D);
- IOSS reader: `stress` is one array of 6 components that ParaView labels XX YY ZZ XY YZ XZ,
  in 2D as in 3D (4 components would be labelled 0 1 2 3);
- docs/viewing.md's GetClientSideObject snippet, asked for t = 1.05 (2D) and t = 0.9 / 13 (3D),
  reads that step: the uniform stress of the patch, sigma_yy (3D: sigma_zz) = -p and in 2D
  plane strain sigma_zz = -nu p, p = 4 t, other components 0, to 1e-8 relative;
- the same stresses in the file at every step (netCDF, tools/grout_results.py).
"""
import sys
from fractions import Fraction

import numpy as np
from grout_results import Results

NU = 0.3
CASES = {  # file: (dim, end as a fraction D / 10^d, steps)
    "np1/decimal_2d.e": (2, Fraction(14, 10), 20),
    "np1/decimal_3d.e": (3, Fraction(3, 10), 13),
}
NAMES = ["stress_xx", "stress_yy", "stress_zz", "stress_xy", "stress_yz", "stress_zx"]
LABELS = ["XX", "YY", "ZZ", "XY", "YZ", "XZ"]
failures = []


def expect(ok, what):
    print("  %s %s" % ("ok  " if ok else "FAIL", what))
    if not ok:
        failures.append(what)


def exact_stress(dim, t):
    """Uniform patch stress in the output order of NAMES at time t."""
    p = 4.0 * t
    s = dict.fromkeys(NAMES, 0.0)
    if dim == 2:
        s["stress_yy"], s["stress_zz"] = -p, -NU * p
    else:
        s["stress_zz"] = -p
    return np.array([s[n] for n in NAMES])


def check_netcdf(path, dim, times):
    r = Results(path)
    got = [float(t) for t in r.times()]
    expect(got == times, "%s: times %s" % (path, " ".join(repr(t) for t in got)))
    expect(r.element_names == NAMES, "%s: element variables %s" % (path, r.element_names))
    worst = 0.0
    for k, t in enumerate(got):
        ref = exact_stress(dim, t)
        for name, value in zip(NAMES, ref):
            if name in r.element_names:
                worst = max(worst, np.abs(r.element(name, k) - value).max() / (4.0 * t))
    expect(worst < 1e-8, "%s: stresses at every step, worst relative error %.1e" % (path, worst))


def check_paraview(path, dim, times, at):
    from paraview import simple
    from vtkmodules.numpy_interface import dataset_adapter as dsa

    r = simple.IOSSReader(FileName=[path])
    r.UpdatePipelineInformation()
    got = list(r.TimestepValues)
    expect(got == times, "%s: IOSS reader times %s" % (path, " ".join(repr(t) for t in got)))
    r.UpdatePipeline(at)
    info = r.GetDataInformation().DataInformation.GetCellDataInformation().GetArrayInformation(
        "stress")
    labels = [info.GetComponentName(c) for c in range(info.GetNumberOfComponents())] if info else []
    expect(labels == LABELS, "%s: IOSS `stress` components labelled %s" % (path, labels))
    # The snippet of docs/viewing.md ("Data in pvpython").
    data = r.GetClientSideObject().GetOutputDataObject(0)
    worst, blocks = np.inf, []
    for i in range(data.GetNumberOfPartitionedDataSets()):
        name = data.GetMetaData(i).Get(data.NAME())
        for j in range(data.GetNumberOfPartitions(i)):
            part = dsa.WrapDataObject(data.GetPartition(i, j))
            if "stress" in part.CellData.keys():
                blocks.append(name)
                stress = np.asarray(part.CellData["stress"])
                if stress.ndim != 2 or stress.shape[1] != len(NAMES):
                    worst = np.nan  # not the 6 components: fails below
                    continue
                error = np.abs(stress - exact_stress(dim, at)).max() / (4.0 * at)
                worst = error if np.isinf(worst) else max(worst, error)
    expect(sorted(blocks) == ["lower", "upper"] and worst < 1e-8,
           "%s: GetClientSideObject at t = %r: blocks %s, stress relative error %.1e"
           % (path, at, sorted(blocks), worst))
    simple.Delete(r)
    e = simple.ExodusIIReader(FileName=[path])
    e.UpdatePipelineInformation()
    got = list(e.TimestepValues)
    expect(got == times, "%s: ExodusIIReader times %s" % (path, " ".join(repr(t) for t in got)))
    simple.Delete(e)


def main():
    for path, (dim, end, steps) in CASES.items():
        times = [float(end * k / steps) for k in range(1, steps + 1)]  # correctly rounded
        print("%s (%dD, end %s in %d steps)" % (path, dim, float(end), steps))
        check_netcdf(path, dim, times)
        check_paraview(path, dim, times, times[14] if steps > 14 else times[2])
    if failures:
        print("check: %d failure(s)" % len(failures))
        return 1
    print("check: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
