#!/usr/bin/python3
"""The condition number κ(K) of the small-strain stiffness matrix of an Exodus mesh, restricted
to its free dofs (Dirichlet dofs removed): the ratio of its largest and smallest eigenvalues
(numpy's dense eigvalsh; meshes of a few thousand nodes). HEX8 with 2×2×2 Gauss points, TET4
with one; isotropic linear elasticity, D from Lamé's λ = Eν/((1+ν)(1−2ν)), μ = E/(2(1+ν)).
compare_paths.py's tolerance for an iterative run is 2 κ τ (τ the Krylov tolerance).

Usage: condition_number.py MESH.exo BLOCK:E[,BLOCK:E ...] NU NODESET:COMPONENTS[,...]
e.g.   condition_number.py hex8.exo block:1000 0.3 zmin_nodes:xyz
"""
import sys

import netCDF4
import numpy as np

if len(sys.argv) != 5:
    sys.exit(__doc__)
d = netCDF4.Dataset(sys.argv[1])
X = np.stack([np.asarray(d.variables[c][:]) for c in ('coordx', 'coordy', 'coordz')], 1)
n = len(X)
names = [str(s) for s in netCDF4.chartostring(d.variables['eb_names'][:])]
E = dict((k, float(v)) for k, v in (p.split(':') for p in sys.argv[2].split(',')))
nu = float(sys.argv[3])
K = np.zeros((3 * n, 3 * n))
def Dmat(E):
    l = E * nu / ((1 + nu) * (1 - 2 * nu)); m = E / (2 * (1 + nu))
    D = np.zeros((6, 6)); D[:3, :3] = l; D[range(3), range(3)] += 2 * m; D[range(3, 6), range(3, 6)] = m
    return D
def Bmat(dN):  # dN: (k,3) physical gradients
    k = len(dN); B = np.zeros((6, 3 * k))
    for a in range(k):
        gx, gy, gz = dN[a]
        B[0, 3*a] = gx; B[1, 3*a+1] = gy; B[2, 3*a+2] = gz
        B[3, 3*a] = gy; B[3, 3*a+1] = gx; B[4, 3*a+1] = gz; B[4, 3*a+2] = gy; B[5, 3*a] = gz; B[5, 3*a+2] = gx
    return B
hexref = np.array([[-1,-1,-1],[1,-1,-1],[1,1,-1],[-1,1,-1],[-1,-1,1],[1,-1,1],[1,1,1],[-1,1,1]], float)
g = 1 / np.sqrt(3)
for b, name in enumerate(names):
    conn = np.asarray(d.variables[f'connect{b+1}'][:]) - 1
    D = Dmat(E[name])
    for el in conn:
        x = X[el]; dofs = (3 * el[:, None] + np.arange(3)).ravel()
        if len(el) == 4:
            J = (x[1:] - x[0]).T
            dNr = np.array([[-1,-1,-1],[1,0,0],[0,1,0],[0,0,1]], float)
            dN = dNr @ np.linalg.inv(J); B = Bmat(dN); ke = B.T @ D @ B * abs(np.linalg.det(J)) / 6
        else:
            ke = 0
            for xi in (-g, g):
                for eta in (-g, g):
                    for ze in (-g, g):
                        r = hexref
                        dNr = 0.125 * np.stack([r[:,0]*(1+r[:,1]*eta)*(1+r[:,2]*ze), r[:,1]*(1+r[:,0]*xi)*(1+r[:,2]*ze), r[:,2]*(1+r[:,0]*xi)*(1+r[:,1]*eta)], 1)
                        J = x.T @ dNr
                        dN = dNr @ np.linalg.inv(J); B = Bmat(dN); ke = ke + B.T @ D @ B * np.linalg.det(J)
        K[np.ix_(dofs, dofs)] += ke
ns = [str(s) for s in netCDF4.chartostring(d.variables['ns_names'][:])]
fixed = set()
for p in sys.argv[4].split(','):
    s, comps = p.split(':')
    nodes = np.asarray(d.variables[f'node_ns{ns.index(s)+1}'][:]) - 1
    for c in comps: fixed.update(3 * nodes + 'xyz'.index(c))
free = np.array(sorted(set(range(3 * n)) - fixed))
w = np.linalg.eigvalsh(K[np.ix_(free, free)])
print(f'{sys.argv[1]}: {len(free)} free dofs, lambda {w[0]:.4g} .. {w[-1]:.4g}, kappa {w[-1]/w[0]:.4g}')
