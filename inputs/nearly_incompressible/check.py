"""A nearly incompressible block in uniaxial compression (README.md): every run's displacements
equal the exact solution, which is linear and so reproduced by HEX8 and TET4 elements:
  u_x = ν p x / E,  u_y = ν p y / E,  u_z = −p z / E   (rollers on x = 0, y = 0, z = 0;
  pressure p on z = 1), to 1e-8 of its largest value, on 1 and 2 ranks.

Usage: check.py hex_mumps hex_belos ... (run in the case folder: results np<ranks>/<stem>.e).
"""
import sys

import numpy as np

from grout_results import Results

E, NU, P = 200.0, 0.49, 1.0
TOLERANCE = 1e-8


def main():
    failures, worst = [], 0.0
    for stem in sys.argv[1:]:
        for ranks in (1, 2):
            path = "np%d/%s.e" % (ranks, stem)
            r = Results(path)
            x, y, z = r.coordinates()
            exact = {"displ_x": NU * P * x / E, "displ_y": NU * P * y / E, "displ_z": -P * z / E}
            scale = max(np.abs(v).max() for v in exact.values())
            run_worst = 0.0
            for name, u in exact.items():
                d = float(np.abs(np.asarray(r.nodal(name)) - u).max()) / scale
                run_worst = max(run_worst, d)
                if not d <= TOLERANCE:
                    failures.append("%s: %s off the exact solution by %.2e (> %g)"
                                    % (path, name, d, TOLERANCE))
            worst = max(worst, run_worst)
            print("%-22s largest difference from the exact solution %.2e" % (path, run_worst))
    print("largest relative difference from the exact solution: %.2e" % worst)
    for f in failures:
        print("FAIL " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
