#!/usr/bin/python3
"""Bad input on the distributed mesh: the replicated mesh's exit code and message.

Usage: compare_errors.py GROUT [LAUNCHER ...]

Writes inputs with one defect each (a block, node set or side set the mesh lacks, an empty side
or node set (empty_sets.exo), a block without a material, a 2D model on a 3D mesh), from the working directory's meshes, and runs each
on 1 and 2 ranks as the driver chooses (these static inputs without contact read the
distributed mesh) and with GROUT_MESH=replicated: both must exit 2 with the same
"grout: error: ..." line, naming the file and the key. LAUNCHER: the MPI launcher and its
options, for the runs on 2 ranks.
"""
import os
import subprocess
import sys

BASE = """grout:
  mesh: {file: MESH}
  model: {dimension: 2, plane: strain}
  materials:
    solid: {block: block, law: linear_elastic, youngs_modulus: 1000.0, poissons_ratio: 0.3}
  dirichlet:
    fix_x: {node_set: left_nodes, component: x, value: "0"}
    fix_y: {node_set: bottom_nodes, component: y, value: "0"}
  loads:
    pull: {side_set: right, type: traction, components: {x: "10.0*t", y: "0"}}
  output: {file: NAME.e, summary: NAME.csv}
"""
CASES = {  # name: (mesh, replacements, regex the message must match)
    "unknown_block": ("quad4.exo", [("block: block", "block: blok")],
                      "grout/materials/solid/block: no element block 'blok'"),
    "missing_node_set": ("quad4.exo", [("left_nodes", "lft_nodes")],
                         "grout/dirichlet/fix_x/node_set: no node set 'lft_nodes'"),
    "missing_side_set": ("quad4.exo", [("side_set: right", "side_set: rigth")],
                         "grout/loads/pull/side_set: no side set 'rigth'"),
    "empty_side_set": ("empty_sets.exo", [("side_set: right", "side_set: empty")],
                       "grout/loads/pull/side_set: side set 'empty' in mesh 'empty_sets.exo' is "
                       "empty (it has no faces)"),
    "empty_node_set": ("empty_sets.exo", [("node_set: left_nodes", "node_set: empty")],
                       "grout/dirichlet/fix_x/node_set: node set 'empty' in mesh "
                       "'empty_sets.exo' is empty (it has no nodes)"),
    "block_without_material": ("stacked.exo", [("block: block", "block: lower"),
                                               ("left_nodes", "lower_left_nodes"),
                                               ("bottom_nodes", "lower_bottom_nodes"),
                                               ("side_set: right", "side_set: upper_right")],
                               "grout/materials: element block 'upper' of mesh 'stacked.exo' "
                               "has no material"),
    "dimension": ("hex8.exo", [],
                  "grout/model/dimension: the model is 2D but mesh 'hex8.exo' is 3D"),
}


def run(command, env):
    result = subprocess.run(command, env=env, capture_output=True, text=True, timeout=120)
    lines = [l for l in result.stderr.splitlines() if l.startswith("grout: error")]
    return result.returncode, lines


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    grout, launcher = sys.argv[1], sys.argv[2:]
    failed = False
    for name, (mesh, replacements, expected) in CASES.items():
        text = BASE.replace("MESH", mesh).replace("NAME", name)
        for old, new in replacements:
            text = text.replace(old, new)
        with open(f"{name}.yaml", "w") as f:
            f.write(text)
        for np in (1, 2):
            prefix = launcher + ["-np", str(np)] if np > 1 else []
            command = prefix + [grout, f"{name}.yaml", "--output-dir", "errors"]
            env = {k: v for k, v in os.environ.items() if k != "GROUT_MESH"}
            distributed = run(command, env)
            replicated = run(command, dict(env, GROUT_MESH="replicated"))
            ok = (distributed == replicated and distributed[0] == 2 and len(distributed[1]) == 1
                  and f"{name}.yaml: {expected}" in distributed[1][0])
            failed = failed or not ok
            print(f"{name} np{np}: {'ok' if ok else 'DIFFERS'}: distributed {distributed}, "
                  f"replicated {replicated}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
