#!/usr/bin/env python3
"""Reference dynamics of a BarrettHand finger from Pinocchio, independent of HandSim's code.

Writes src/test/resources/org/handsim/dynamics/pinocchio-reference.json, which
PinocchioReferenceTest reads, and prints the mass matrix D(q = 0) of finger 1.

The finger is built here from the hand description (src/main/resources/org/handsim/hand/
barretthand.json: the DH table of paper Tables I-II and the mass properties of Table III)
with Pinocchio's own joints and spatial inertias; nothing of HandSim's dynamics is shared:

  * Standard DH, T(j-1 -> j) = Rz(th_j) Tz(d_j) Tx(a_j) Rx(al_j), th_j = q_j + offset_j: joint j
    is a revolute joint about z placed at X_{j-1} Rz(offset_j) in its parent joint's frame
    (X_0 = identity), and link j's frame {j} sits at X_j = Tz(d_j) Tx(a_j) Rx(al_j) in joint j's.
  * Table III read as the paper gives it: each tensor is about the ORIGIN of {j}, axes of {j},
    the listed products being +integral(x y dm) (the CAD sign), so the matrix is
        I_o = [[xx, -xy, -xz], [-xy, yy, -yz], [-xz, -yz, zz]].
    Pinocchio takes the tensor about the centre of mass c:
        I_c = I_o - m (|c|^2 E - c c^T)
    (the script checks that Pinocchio's spatial inertia gives I_o back about the origin, that
    I_c is positive definite and that its principal moments satisfy the triangle inequality).
  * Gravity is the base acceleration in the finger base frame {k0}, as in HandSim.

Outputs: the joint-space inertia matrix by the composite rigid body algorithm (pin.crba), the
inverse dynamics tau(q, qd, qdd) by the recursive Newton-Euler algorithm (pin.rnea) at fixed
states, and a 1 s free swing (zero torques, RK4 with h = 1 ms on pin.aba, from q = qd = 0 under
g = (0, 0, -9.81)): the scheme of `handsim swing`'s defaults.

Usage (from the repository root; needs Pinocchio and numpy, not part of the build):
    python3 -m venv build/py && build/py/bin/pip install pin numpy
    build/py/bin/python tools/dynamics/pinocchio_reference.py [OUT.json]
"""
import json
import math
import os
import sys

import numpy as np
import pinocchio as pin

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), '..', '..'))
HAND = os.path.join(ROOT, 'src', 'main', 'resources', 'org', 'handsim', 'hand', 'barretthand.json')
OUT = os.path.join(ROOT, 'src', 'test', 'resources', 'org', 'handsim', 'dynamics', 'pinocchio-reference.json')

# Fixed states (finger 1, three active joints): q, qd, qdd in rad, rad/s, rad/s^2; g in m/s^2.
STATES = [
    ([0, 0, 0], [0, 0, 0], [0, 0, 0], [0, 0, 0]),
    ([0, 0, 0], [0, 0, 0], [0, 0, 0], [0, 0, -9.81]),
    ([0.3, 0.8, 0.4], [0, 0, 0], [0, 0, 0], [0, 0, -9.81]),
    ([-0.5, 1.2, 0.7], [1.5, -2.0, 3.0], [4.0, -1.0, 2.5], [0, 0, -9.81]),
    ([0.9, 2.1, 0.3], [-0.7, 0.4, -1.1], [0.5, 3.0, -6.0], [3.0, -4.0, 7.0]),
    ([0, 2.443, 0.814], [0, 1.0, 0.33], [0, 0, 0], [0, 9.81, 0]),
]


def rot_x(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])


def rot_z(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def link_frame(a, alpha, d):
    """X = Tz(d) Tx(a) Rx(alpha): link frame {j} in the frame of joint j (after its rotation)."""
    return pin.SE3(rot_x(alpha), np.array([a, 0.0, d]))


def table3_inertia(link):
    """(m, c, I_o, I_c) of one Table III entry, origin reading with CAD products."""
    m = link['mass_kg']
    c = np.array(link['com_m'], dtype=float)
    t = link['inertia_kgm2']
    i_o = np.array([[t['xx'], -t['xy'], -t['xz']],
                    [-t['xy'], t['yy'], -t['yz']],
                    [-t['xz'], -t['yz'], t['zz']]])
    i_c = i_o - m * (c.dot(c) * np.eye(3) - np.outer(c, c))
    return m, c, i_o, i_c


def check_physical(j, m, c, i_o, i_c):
    inertia = pin.Inertia(m, c, i_c)
    back = inertia.matrix()[3:, 3:]          # the rotational block about the frame origin
    if not np.allclose(back, i_o, rtol=0, atol=1e-15):
        sys.exit(f'link {j}: Pinocchio does not give I_o back about the origin: {back} vs {i_o}')
    ev = np.linalg.eigvalsh(i_c)
    if not (ev[0] > 0 and ev[0] + ev[1] > ev[2]):
        sys.exit(f'link {j}: the tensor about the centre of mass is not physical: {ev}')
    return inertia


def build(hand):
    links = hand['links']
    a = [links['A1_m'], links['A2_m'], links['A3_m']]
    alpha = [math.radians(links[f'alpha{j}_deg']) for j in (1, 2, 3)]
    d = [links['d1_m'], links['d2_m'], links['d3_m']]
    offset = [0.0, math.radians(links['phi2_deg']), math.radians(links['phi3_deg'])]
    model = pin.Model()
    parent, placement = 0, pin.SE3.Identity()
    for j in range(3):
        placement = placement * pin.SE3(rot_z(offset[j]), np.zeros(3))
        jid = model.addJoint(parent, pin.JointModelRZ(), placement, f'joint{j + 1}')
        x = link_frame(a[j], alpha[j], d[j])
        m, c, i_o, i_c = table3_inertia(hand['mass_properties']['links'][j])
        model.appendBodyToJoint(jid, x.act(check_physical(j + 1, m, c, i_o, i_c)), pin.SE3.Identity())
        parent, placement = jid, x
    return model


def mass_matrix(model, data, q):
    m = pin.crba(model, data, np.array(q, dtype=float))
    return np.triu(m) + np.triu(m, 1).T


def swing(model, data, duration=1.0, h=1e-3):
    model.gravity.linear = np.array([0.0, 0.0, -9.81])
    tau = np.zeros(3)

    def f(y):
        return np.concatenate([y[3:], pin.aba(model, data, y[:3], y[3:], tau)])

    def energy(y):
        pin.computeAllTerms(model, data, y[:3], y[3:])
        return (pin.computeKineticEnergy(model, data, y[:3], y[3:])
                + pin.computePotentialEnergy(model, data, y[:3]))

    y = np.zeros(6)
    e0 = energy(y)
    steps = int(round(duration / h))
    for _ in range(steps):
        k1 = f(y)
        k2 = f(y + 0.5 * h * k1)
        k3 = f(y + 0.5 * h * k2)
        k4 = f(y + h * k3)
        y = y + h / 6.0 * (k1 + 2.0 * (k2 + k3) + k4)
    return {'duration_s': duration, 'dt_s': h, 'steps': steps, 'gravity': [0, 0, -9.81],
            'q_final': y[:3].tolist(), 'qd_final': y[3:].tolist(),
            'energy_initial_J': e0, 'energy_final_J': energy(y)}


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else OUT
    with open(HAND, encoding='utf-8') as fh:
        hand = json.load(fh)
    model = build(hand)
    data = model.createData()
    states = []
    for q, qd, qdd, g in STATES:
        model.gravity.linear = np.array(g, dtype=float)
        tau = pin.rnea(model, data, np.array(q, float), np.array(qd, float), np.array(qdd, float))
        states.append({'q': q, 'qd': qd, 'qdd': qdd, 'gravity': g, 'tau': tau.tolist(),
                       'D': mass_matrix(model, data, q).tolist()})
    ref = {
        'source': 'tools/dynamics/pinocchio_reference.py with Pinocchio ' + pin.__version__
                  + ' and numpy ' + np.__version__ + ': finger 1 of barretthand.json, Table III about '
                  'the origin of each link frame with +integral(xy dm) products; D by pin.crba, tau by '
                  'pin.rnea, the swing by RK4 on pin.aba',
        'finger': 1,
        'states': states,
        'swing': swing(model, data),
    }
    os.makedirs(os.path.dirname(out), exist_ok=True)
    with open(out, 'w', encoding='utf-8') as fh:
        fh.write('{\n "source": ' + json.dumps(ref['source']) + ',\n "finger": 1,\n "states": [\n  '
                 + ',\n  '.join(json.dumps(s) for s in states) + '\n ],\n "swing": '
                 + json.dumps(ref['swing']) + '\n}\n')
    d0 = states[0]['D']
    print('D(q = 0), finger 1, kg m^2:')
    for row in d0:
        print('  ' + '  '.join(f'{v: .6e}' for v in row))
    print('diagonal: ' + ', '.join(f'{d0[i][i]:.5e}' for i in range(3)))
    print(f"1 s free swing (RK4, 1 ms): q = {', '.join(f'{v:.6f}' for v in ref['swing']['q_final'])} rad")
    print('wrote ' + os.path.relpath(out, ROOT))


if __name__ == '__main__':
    main()
