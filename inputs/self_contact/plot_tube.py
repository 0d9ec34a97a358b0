"""Picture of the squeezed flat tube (flat_tube.yaml): the mesh at t = 0 and at the last step,
deformed (no magnification), with the slave side's contact_pressure at its nodes.

Usage (in the case's build folder): python3 plot_tube.py [RESULTS.e] [OUTPUT.png]
  default np1/flat_tube.e, self_contact_flat_tube.png (docs/figures/ holds a copy).
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

from grout_results import Results  # noqa: E402


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else "np1/flat_tube.e"
    out = sys.argv[2] if len(sys.argv) > 2 else "self_contact_flat_tube.png"
    r = Results(path)
    X = r.coordinates()
    fig, axes = plt.subplots(2, 1, figsize=(9, 4.6))
    for ax, step, title in ((axes[0], None, "t = 0"),
                            (axes[1], -1, "top moved down 0.33: cavity closed (self-contact)")):
        u = 0 * X if step is None else np.array([r.nodal("displ_x", step), r.nodal("displ_y", step)])
        x = X + u
        ax.add_collection(PolyCollection([x[:, row].T for row in r.connectivity(1)],
                                         facecolor="0.85", edgecolor="0.3", linewidth=0.4))
        if step is not None:
            cp = r.nodal("contact_pressure", step)
            on = np.nonzero(cp > 0)[0]
            sc = ax.scatter(x[0, on], x[1, on], c=cp[on], s=10, cmap="viridis", zorder=3)
            fig.colorbar(sc, ax=ax, label="contact_pressure (slave side)", fraction=0.03)
        ax.set_aspect("equal")
        ax.autoscale()
        ax.set_title(title, fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
