"""Friction base test after Dong (1999) (docs/verification.md #7) for mu = 1, 0.5, 0.25: the
boundary force on block I's held left side against the horizontal displacement of the interface is
linear while the stick/slip partition of the interface is unchanged and saturates at the
Coulomb plateau |F| = mu N once the whole interface slips; the three plateaus are in the
ratio 1 : 0.5 : 0.25. Writes dong_curve.csv and dong_curve.png; 1 and 2 ranks agree to 1e-10.

Reference. Literature: Dong, "A solution method for frictional contact problems" (1999),
as reproduced in Mataix Ferrandiz, thesis §4.5.3, Fig. 4.48b (force grows linearly while
the interface sticks and saturates at a plateau proportional to mu). Analytic part (exact
for the discrete problem, hence tight tolerances):
  - plateau: x-equilibrium of block I (held in x on its left side only, loaded vertically
    by the line load q) gives F = -(sum of the interface friction forces on I); when every
    active slave node slips in the same direction, |lambda_t| = mu lambda_n at each, so
    |F| = mu sum_j D_jj lambda_n,j = mu N, with N = q w = 2e7 Pa x 0.1 m = 2e6 N/m by
    y-equilibrium of block I (its left side is free in y): plateaus 2e6, 1e6, 5e5 N/m,
    checked to 1e-6 relative, and their ratios to 1e-6;
  - Coulomb bound: |F| <= mu N (1 + 1e-6) at every step;
  - linearity: the problem is linear as long as the partition (open / stick / slip and the
    slip direction of every slave node) does not change, so over the first drive steps with
    an unchanged partition (at least 3 states, at least one stick node) the increments
    dF/du_interface are equal to 1e-6 relative;
  - direction: during the drive (block II moved in +x) the friction drags block I in +x and
    the support pushes back: F < 0 on the plateau (support force convention of reaction_*).
Interface displacement: the mean u_x of block II's top under block I (node set
lower_top_contact), i.e. the master surface the block slides on (keeps growing on the
plateau; block I's own bottom stops moving once it slips).
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
import contact_check as cc  # noqa: E402
import friction_check as fc  # noqa: E402

Q_LINE, WIDTH_I = 2.0e7, 0.1
N = Q_LINE * WIDTH_I  # 2e6 N/m
T_DRIVE = 0.1  # the drive starts after the normal load is complete
RUNS = [(1.0, "dong_mu1"), (0.5, "dong_mu05"), (0.25, "dong_mu025")]
TOL = 1e-6


def read_curve(path):
    """Per step: t, F = reaction_upper_left_nodes_x, u = mean u_x of lower_top_contact, the normal
    reaction, and the partition key of every slave node (0 open, 1 stick, +-2 slip with the
    sign of lambda_x)."""
    from grout_results import Results
    r = Results(path)
    s = cc.side_set_nodes(r, "upper_bottom")
    m = cc.side_set_nodes(r, "lower_top_contact")
    t = r.times()
    F = np.array([r.global_var("reaction_upper_left_nodes_x", k) for k in range(t.size)])
    Ny = np.array([r.global_var("reaction_lower_bottom_nodes_y", k) for k in range(t.size)])
    u = np.array([r.nodal("displ_x", k)[m].mean() for k in range(t.size)])
    keys = []
    for k in range(t.size):
        st = r.nodal("contact_status", k)[s]
        lx = r.nodal("lm_x", k)[s]
        keys.append(np.where(st == fc.SLIP, 2 * np.sign(lx), st).astype(int))
    return {"t": t, "F": F, "u": u, "N": Ny, "keys": np.array(keys)}


def analyse(c, mu, n_load=N, tol=TOL):
    """Checks of one curve (dict of read_curve). Returns (summary dict, failures)."""
    failures = []
    t, F, u, keys = c["t"], c["F"], c["u"], c["keys"]
    drive = np.nonzero(t > T_DRIVE * (1 + 1e-9))[0]
    if drive.size < 3:
        return {}, ["mu = %g: only %d drive steps converged" % (mu, drive.size)]
    bound = mu * n_load
    # Coulomb bound at every step.
    worst = float(np.max(np.abs(F))) / bound
    if worst > 1 + tol:
        failures.append("mu = %g: |F| = %.8g exceeds mu N = %.8g" % (mu, np.max(np.abs(F)), bound))
    # Normal load carried by the interface.
    if "N" in c and not np.all(np.abs(np.abs(c["N"][drive]) - n_load) <= tol * n_load):
        failures.append("mu = %g: normal reaction != N = %g during the drive" % (mu, n_load))
    # Plateau: drive steps with no stick node and at least one slip node, all slipping alike.
    slipping = [k for k in drive if not np.any(keys[k] == fc.STICK) and np.any(np.abs(keys[k]) == 2)
                and len(set(keys[k][keys[k] != 0].tolist())) == 1]
    summary = {"mu": mu, "bound": bound, "plateau_steps": len(slipping)}
    if not slipping or slipping[-1] != drive[-1]:
        failures.append("mu = %g: the interface does not slip completely at the end of the drive "
                        "(last partition %s)" % (mu, keys[drive[-1]].tolist()))
    else:
        plateau = F[slipping]
        err = float(np.max(np.abs(np.abs(plateau) - bound))) / bound
        summary.update(plateau=float(np.abs(plateau[-1])), plateau_err=err)
        if err > tol:
            failures.append("mu = %g: plateau |F| = %.10g, expected mu N = %.10g (error %.2e > %g)"
                            % (mu, np.abs(plateau[-1]), bound, err, tol))
        if not np.all(plateau < 0):
            failures.append("mu = %g: plateau force not opposite to the drive (F = %.6g > 0)" % (mu, plateau[-1]))
    # Linear part: the longest run of equal partitions starting at the first drive step.
    run = [drive[0]]
    for k in drive[1:]:
        if np.array_equal(keys[k], keys[run[0]]):
            run.append(k)
        else:
            break
    summary["linear_steps"] = len(run)
    summary["linear_stick_nodes"] = int(np.sum(keys[run[0]] == fc.STICK))
    summary["all_stick"] = bool(np.all(keys[run[0]] == fc.STICK))
    if len(run) < 3:
        failures.append("mu = %g: the partition changes within the first drive steps (%d equal), "
                        "linearity not testable: refine the drive" % (mu, len(run)))
    elif summary["linear_stick_nodes"] == 0:
        failures.append("mu = %g: no stick node at the start of the drive" % mu)
    else:
        slopes = np.diff(F[run]) / np.diff(u[run])
        spread = float(np.max(np.abs(slopes - slopes[0])) / abs(slopes[0]))
        summary.update(slope=float(slopes[0]), slope_spread=spread)
        if spread > tol:
            failures.append("mu = %g: force not linear in the interface displacement while stuck "
                            "(slopes %s, spread %.2e)" % (mu, slopes.tolist(), spread))
    return summary, failures


def write_outputs(curves, prefix="dong_curve"):
    with open(prefix + ".csv", "w") as f:
        f.write("mu,step,t,u_interface,force,n_stick,n_slip,n_open\n")
        for mu, c in curves:
            for k in range(c["t"].size):
                keys = c["keys"][k]
                f.write("%g,%d,%.10g,%.10g,%.10g,%d,%d,%d\n" % (
                    mu, k + 1, c["t"][k], c["u"][k], c["F"][k], np.sum(keys == 1),
                    np.sum(np.abs(keys) == 2), np.sum(keys == 0)))
    print("wrote", prefix + ".csv")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for mu, c in curves:
        line, = ax.plot(c["u"] * 1e3, -c["F"] / 1e3, "o-", ms=3, lw=1, label="mu = %g" % mu)
        load = c["t"] <= T_DRIVE * (1 + 1e-9)  # normal-load phase: hollow markers
        ax.plot(c["u"][load] * 1e3, -c["F"][load] / 1e3, "o", ms=5, mfc="white", color=line.get_color())
        ax.axhline(mu * N / 1e3, color=line.get_color(), ls="--", lw=0.8)
    ax.set_xlabel("interface displacement u_x (mm)")
    ax.set_ylabel("boundary force -F (kN/m)")
    ax.set_title("Friction base test (Dong 1999): dashed = Coulomb plateau mu N,\n"
                 "hollow = normal-load phase", fontsize=10)
    ax.legend()
    fig.tight_layout()
    fig.savefig(prefix + ".png", dpi=120)
    plt.close(fig)
    print("wrote", prefix + ".png")


def synthetic(mu, k=8e10, f0=3e5, du=2e-6, steps=40, n_nodes=9, jitter=0.0):
    """A curve with the expected shape (tests of analyse): F = f0 - k u until -mu N, stick
    partition first (the corner node slipping), then progressive slip, then all slip."""
    t = np.concatenate([np.linspace(0.025, 0.1, 4), 0.1 + np.arange(1, steps + 1) / steps])
    u = np.concatenate([np.full(4, 1e-7), 1e-7 + du * np.arange(1, steps + 1)])
    F = np.concatenate([np.full(4, f0), np.maximum(f0 - k * (u[4:] - 1e-7), -mu * N)])
    F = F * (1 + jitter * np.arange(F.size))
    keys = np.ones((t.size, n_nodes), dtype=int)
    keys[:, 0] = 2
    for i in range(4, t.size):
        frac = abs(F[i]) / (mu * N)
        if frac > 0.6:  # progressive slip from the right end
            keys[i, n_nodes - 1 - int((frac - 0.6) / 0.4 * (n_nodes - 3)):] = 2
        if abs(F[i]) >= mu * N:
            keys[i, :] = 2
    return {"t": t, "F": F, "u": u, "N": np.full(t.size, N), "keys": keys}


def self_test():
    assert abs(N - 2e6) < 1e-9
    for mu, _ in RUNS:
        s, f = analyse(synthetic(mu), mu)
        assert not f, f
        assert abs(s["plateau"] - mu * N) < 1e-9 * N and s["linear_steps"] >= 3
    # Plateau above mu N, a kink within the "linear" part, no full slip: each fails.
    c = synthetic(0.5)
    c["F"] = np.where(c["F"] <= -0.5 * N, -0.5 * N * (1 + 1e-5), c["F"])
    assert any("exceeds" in m for m in analyse(c, 0.5)[1])
    assert len(analyse(synthetic(0.5, jitter=1e-4), 0.5)[1]) >= 1
    c = synthetic(1.0)
    c["keys"][-1, 3] = 1
    assert any("does not slip" in m for m in analyse(c, 1.0)[1])
    print("dong_friction self-test: ok (N = %g, plateaus %s)" % (N, [mu * N for mu, _ in RUNS]))


if __name__ == "__main__":
    if "--self-test" in sys.argv:
        self_test()
        sys.exit(0)
    failures, curves, plateaus, summaries = [], [], {}, []
    for mu, stem in RUNS:
        for n in (1, 2):
            path = "np%d/%s.e" % (n, stem)
            c = read_curve(path)
            s, f = analyse(c, mu)
            failures += ["%s: %s" % (path, m) for m in f]
            if n == 1:
                curves.append((mu, c))
                summaries.append(s)
                plateaus[mu] = s.get("plateau")
                print("%-20s mu = %-4g plateau |F| = %s (mu N = %.6g, err %s, %d steps), linear over "
                      "%d steps (%d stick nodes, slope %s, spread %s)"
                      % (path, mu, "%.10g" % s["plateau"] if "plateau" in s else "-", mu * N,
                         "%.1e" % s["plateau_err"] if "plateau_err" in s else "-", s.get("plateau_steps", 0),
                         s.get("linear_steps", 0), s.get("linear_stick_nodes", 0),
                         "%.6g" % s["slope"] if "slope" in s else "-",
                         "%.1e" % s["slope_spread"] if "slope_spread" in s else "-"))
        diff, msg = cc.compare_ranks("np1/%s.e" % stem, "np2/%s.e" % stem, ["displ_x", "displ_y", "lm_x", "lm_y"])
        print("%-20s 1 vs 2 ranks: %.1e; Newton iterations per step: %s"
              % (stem, diff, fc.newton_per_step("np1/%s.e" % stem)))
        if msg:
            failures.append(msg)
    # Same stiffness while stuck: the slopes agree wherever the linear part is all-stick.
    slopes = [s_["slope"] for s_ in summaries if "slope" in s_ and s_["all_stick"]]
    if len(slopes) >= 2:
        spread = max(abs(v - slopes[0]) for v in slopes) / abs(slopes[0])
        print("stick stiffness dF/du over the runs with an all-stick linear part: %s (spread %.1e)"
              % (["%.6g" % v for v in slopes], spread))
        if spread > TOL:
            failures.append("the stick stiffness differs between the runs (spread %.2e)" % spread)
    if all(plateaus.get(mu) for mu, _ in RUNS):
        ref = plateaus[1.0]
        for mu, _ in RUNS[1:]:
            ratio = plateaus[mu] / ref
            print("plateau ratio mu = %g : mu = 1 -> %.10f (expected %g)" % (mu, ratio, mu))
            if abs(ratio - mu) > TOL * mu:
                failures.append("plateau ratio %g : 1 = %.10f, expected %g" % (mu, ratio, mu))
    write_outputs(curves)
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)
