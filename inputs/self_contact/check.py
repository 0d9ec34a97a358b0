"""Self-contact patch test (docs/verification.md, self-contact patch test): the computed fields
equal the analytic uniform-stress solution to 1e-8 (relative), on 1 and 2 ranks, and the runs
agree to 1e-10.

The body (slit_strip.py) is one block whose surface folds back onto itself along a closed slit
y = 1; the self-contact side set `fold` holds both flanks. Under a pressure p on the top, with
the bottom on rollers and x = 0 held in x, the exact solution of small-strain elasticity is a
uniform stress sigma = -p e_y e_y in the whole body (the slit stays closed, and its vertical
part carries no traction), so the displacement is linear, u = eps X, and the flanks press on
each other with the traction p. The mortar patch test (Popp et al. 2010, §5) then gives
contact_pressure = p at every node of the slave flank, status active, zero gap, and zero
pressure elsewhere (the master flank carries no multipliers).

Which flank is the slave is the rule of docs/input.md "Self-contact": each connected component
of the candidate-pair graph is 2-coloured from its lowest face id, which is a slave face. The
side set lists its faces by element, and the lower arm's elements come before the upper arm's,
so the lower flank is the slave in every variant. p = 1e8, E = 2.069e11, nu = 0.29.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
import contact_check as cc  # noqa: E402

P, E, NU = 1.0e8, 2.069e11, 0.29


def strip(dim):
    """{block: body_state}: plane strain in 2D, uniaxial stress in 3D (z free but for z = 0)."""
    if dim == 2:
        sigma = cc.plane_strain_stress(0.0, -P, 0.0, NU)
    else:
        sigma = np.zeros((3, 3))
        sigma[1, 1] = -P
    return {"strip": cc.body_state(sigma, E, NU, dim)}


def self_test():
    b = strip(2)["strip"]
    assert abs(b["grad"][1, 1] + (1 - NU**2) * P / E) < 1e-12 * P / E
    assert abs(b["grad"][0, 0] - NU * (1 + NU) * P / E) < 1e-12 * P / E
    b = strip(3)["strip"]
    assert abs(b["grad"][1, 1] + P / E) < 1e-12 * P / E
    assert abs(b["grad"][2, 2] - NU * P / E) < 1e-12 * P / E
    print("self_contact self-test: ok")


if __name__ == "__main__":
    if "--self-test" in sys.argv:
        self_test()
        sys.exit(0)
    failures = []
    failures += cc.check_uniform_case("patch_2d", strip(2), "lower_flank", P)
    failures += cc.check_uniform_case("patch_2d_fine_slave", strip(2), "lower_flank", P)
    failures += cc.check_uniform_case("patch_3d", strip(3), "lower_flank", P)
    # `self: [fold_upper, fold_lower]`: the same surface as `fold`, its faces numbered from the
    # upper flank's, which is then the slave (docs/input.md "Self-contact").
    failures += cc.check_uniform_case("patch_2d_split", strip(2), "upper_flank", P)
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)
