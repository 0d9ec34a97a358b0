"""The die's forces per step from a drag run's summary CSV (shared by check.py and
check_mu03.py): time, R_x and R_y (positive when the block pushes the die up) of the die-top
support, and the number of active slave nodes."""
import csv

import numpy as np


def summary(stem, np_):
    rows = list(csv.DictReader(open("np%d/%s.csv" % (np_, stem))))
    t = np.array([float(r["time"]) for r in rows])
    rx = np.array([float(r["reaction_die_top_nodes_x"]) for r in rows])
    ry = -np.array([float(r["reaction_die_top_nodes_y"]) for r in rows])
    active = np.array([int(r["active_nodes"]) for r in rows])
    return t, rx, ry, active
