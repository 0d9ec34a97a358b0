"""tools/render draws a result: the PNG of contact_2d.e at t = 1 has the requested size, the
white background, and both ends of the colour map (the blue of contact_pressure = 0 in the
bodies, the red of the maximum, 4, along the interface).

    python3 check_render.py np1/contact_2d.e picture.png

Exit code 77 (ctest: skipped) without ParaView's Python modules or Xvfb.
"""
import importlib.util
import os
import shutil
import subprocess
import sys

import matplotlib.image
import numpy as np

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")


def main(exodus, png):
    if shutil.which("Xvfb") is None:
        print("check_render: skipped: Xvfb is not installed (Debian: xvfb)")
        return 77
    if importlib.util.find_spec("paraview") is None:
        print("check_render: skipped: ParaView's Python modules are not installed (python3-paraview)")
        return 77
    if os.path.exists(png):
        os.remove(png)
    run = subprocess.run([os.path.join(ROOT, "tools", "render"), exodus, png, "--size", "600", "400"],
                         capture_output=True, text=True)
    print(run.stdout.strip())
    if run.returncode != 0 or not os.path.exists(png):
        print("FAIL: tools/render exited with %d:\n%s" % (run.returncode, run.stderr[-2000:]))
        return 1
    image = matplotlib.image.imread(png)[:, :, :3]
    rgb = image.reshape(-1, 3)
    white = np.all(rgb > 0.97, axis=1).mean()
    red = np.mean((rgb[:, 0] > 0.6) & (rgb[:, 1] < 0.25) & (rgb[:, 2] < 0.25))
    blue = np.mean((rgb[:, 2] > 0.45) & (rgb[:, 0] < 0.3))
    print("check_render: %s: %dx%d, white %.1f %%, red %.2f %%, blue %.1f %%"
          % (png, image.shape[1], image.shape[0], 100 * white, 100 * red, 100 * blue))
    ok = image.shape[:2] == (400, 600) and white > 0.2 and red > 0.001 and blue > 0.05
    print("check_render: %s" % ("ok" if ok else "FAIL"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
