#!/usr/bin/env python3
"""The elastic stiffness of the L-panel set-up of l_panel.prm, by an
independent finite element computation (numpy only): bilinear quadrilaterals
of h = 10 mm with 2 x 2 Gauss points, plane stress, E = 25.85 GPa,
nu = 0.18, thickness 0.1 m; the lower edge of the leg clamped, the grid
nodes of the arm's lower face within 10 mm of x = 0.47 m moved up by u_y.
The load over the displacement is what qsmpm's first step gives with
material points at the Gauss points (Placement = gauss); the test
l_panel_experiment checks it.

Run: python3 elastic_stiffness.py   (about 10 s; needs python3-numpy)
"""
import numpy as np

E, nu, thickness = 25.85e9, 0.18, 0.1
n = 50                      # cells along the 0.5 m edge
h = 0.5 / n
D = E / (1 - nu**2) * np.array([[1, nu, 0], [nu, 1, 0], [0, 0, (1 - nu) / 2]])

gauss = [-1 / np.sqrt(3), 1 / np.sqrt(3)]
Ke = np.zeros((8, 8))
for xi in gauss:
    for eta in gauss:
        dN = np.array([[-(1 - eta), (1 - eta), (1 + eta), -(1 + eta)],
                       [-(1 - xi), -(1 + xi), (1 + xi), (1 - xi)]]) / 4
        dNx = dN * 2 / h
        B = np.zeros((3, 8))
        B[0, 0::2] = dNx[0]
        B[1, 1::2] = dNx[1]
        B[2, 0::2] = dNx[1]
        B[2, 1::2] = dNx[0]
        Ke += B.T @ D @ B * (h / 2)**2


def node(i, j):
    return j * (n + 1) + i


N = 2 * (n + 1)**2
K = np.zeros((N, N))
for j in range(n):
    for i in range(n):
        if i >= n // 2 and j < n // 2:    # the cut-out
            continue
        nodes = [node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)]
        dofs = np.array([[2 * a, 2 * a + 1] for a in nodes]).ravel()
        K[np.ix_(dofs, dofs)] += Ke

prescribed = {}
for i in range(n + 1):                    # the clamped lower edge
    prescribed[2 * node(i, 0)] = 0.
    prescribed[2 * node(i, 0) + 1] = 0.
loaded = [2 * node(i, n // 2) + 1 for i in range(n + 1)
          if abs(i * h - 0.47) < 0.01 + 1e-9]
for d in loaded:                          # the loading plate, u_y = 1
    prescribed[d] = 1.
used = np.where(np.abs(np.diag(K)) > 0)[0]
fixed = np.array(sorted(prescribed))
free = np.array([d for d in used if d not in prescribed])
u = np.zeros(N)
u[fixed] = [prescribed[d] for d in fixed]
u[free] = np.linalg.solve(K[np.ix_(free, free)], -K[np.ix_(free, fixed)] @ u[fixed])
force = K @ u
print("elastic stiffness: %.10g kN/mm" % (sum(force[d] for d in loaded) * thickness / 1e6))
