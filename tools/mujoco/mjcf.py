"""MJCF of a HandSim scene: HandSim's triangles (`handsim mesh --obj`), its DH description and
Table III masses (src/main/resources/org/handsim/hand/barretthand.json) and the scenario's object
pose, gravity and friction. Used by tools/mujoco-compare; runs under the comparison's venv.

  python mjcf.py HAND.json SCENARIO.json MESHES_DIR OBJECT_PIECES LINK1_PIECES DT OUT.xml

OBJECT_PIECES / LINK1_PIECES: comma-separated OBJ files in MESHES_DIR (MuJoCo collides convex
hulls, so a non-convex mesh is given as its convex pieces).

Frames (vrml/README.md): standard DH, T = Rz(theta) Tz(d) Tx(a) Rx(alpha); finger k's base {k0}
at (r Aw, 0, Dw) turned by -(pi/2) j about z; link j's mesh lies in its distal frame {kj}. A body
per moving link sits at the joint's axis, the DH angle offset Phi folded into the body's
orientation, so MuJoCo's joint angle is HandSim's theta_kj.
"""
import json
import math
import sys

import numpy as np


def quat_axis(axis, angle):
    s = math.sin(angle / 2)
    return np.array([math.cos(angle / 2), axis[0] * s, axis[1] * s, axis[2] * s])


def quat_mul(a, b):
    w1, x1, y1, z1 = a
    w2, x2, y2, z2 = b
    return np.array([w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2, w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
                     w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2, w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2])


def rot_x(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])


def rotvec_quat(r):
    r = np.asarray(r, float)
    th = float(np.linalg.norm(r))
    return np.array([1.0, 0, 0, 0]) if th == 0 else quat_axis(r / th, th)


def nums(v):
    return ' '.join(repr(float(x)) for x in v)


def inertial(link, a, alpha):
    """<inertial> of a link in its body frame: {kj} = body . Tx(a) . Rx(alpha)."""
    m = link['mass_kg']
    c = np.array(link['com_m'])
    i = link['inertia_kgm2']
    tensor = np.array([[i['xx'], i['xy'], i['xz']], [i['xy'], i['yy'], i['yz']], [i['xz'], i['yz'], i['zz']]])
    r = rot_x(alpha)
    pos = np.array([a, 0, 0]) + r @ c
    t = r @ tensor @ r.T
    return f'<inertial pos="{nums(pos)}" mass="{m!r}" fullinertia="{nums([t[0, 0], t[1, 1], t[2, 2], t[0, 1], t[0, 2], t[1, 2]])}"/>'


def build(hand, scenario, meshdir, object_pieces, link1_pieces, dt):
    L = hand['links']
    a1, a2, a3 = L['A1_m'], L['A2_m'], L['A3_m']
    alpha1 = math.radians(L['alpha1_deg'])
    phi2, phi3 = math.radians(L['phi2_deg']), math.radians(L['phi3_deg'])
    aw, dw = hand['palm']['Aw_m'], hand['palm']['Dw_m']
    links = {l['link']: l for l in hand['mass_properties']['links']}
    lim = hand['joint_limits_deg']
    tau_break = hand['clutch']['tau_break_Nm']
    k_clutch = hand['clutch']['k_clutch_Nm_per_rad']
    obj = scenario['object']
    mu = obj.get('friction', 0.5)
    h = scenario.get('hand', {})
    if any(h.get('position_m', [0, 0, 0])) or any(h.get('rotation_rad', [0, 0, 0])):
        raise SystemExit('mjcf.py: only scenarios with the hand at the origin (palm frame = world)')
    z = (0, 0, 1)
    x = (1, 0, 0)
    out = []
    for f in hand['fingers']:
        k, r, j = f['finger'], f['r_palm'], f['j_palm']
        base_pos = np.array([r * aw, 0, dw])
        base_q = quat_axis(z, -(math.pi / 2) * j)
        spread = f['spread_deg_per_count'] != 0
        l1_geoms = ''.join(f'<geom class="link" mesh="link1_{p}" pos="{a1!r} 0 0" quat="{nums(quat_axis(x, alpha1))}"/>'
                           for p in range(len(link1_pieces)))
        l2_q = quat_mul(quat_axis(x, alpha1), quat_axis(z, phi2))
        inner = (f'<body name="f{k}_l2" pos="{a1!r} 0 0" quat="{nums(l2_q)}">{inertial(links[2], a2, 0)}'
                 f'<joint name="f{k}_j2" class="flex" range="{math.radians(lim["theta2"][0])!r} {math.radians(lim["theta2"][1])!r}"/>'
                 f'<geom class="link" mesh="link2" pos="{a2!r} 0 0"/>'
                 f'<body name="f{k}_l3" pos="{a2!r} 0 0" quat="{nums(quat_axis(z, phi3))}">{inertial(links[3], a3, 0)}'
                 f'<joint name="f{k}_j3" class="flex" range="{math.radians(lim["theta3"][0])!r} {math.radians(lim["theta3"][1])!r}"/>'
                 f'<geom class="link" mesh="link3" pos="{a3!r} 0 0"/><site name="f{k}_tip" pos="{a3!r} 0 0"/></body></body>')
        if spread:
            out.append(f'<body name="f{k}_l1" pos="{nums(base_pos)}" quat="{nums(base_q)}">{inertial(links[1], a1, alpha1)}'
                       f'<joint name="f{k}_j1" type="hinge" axis="0 0 1" damping="0.1"/>{l1_geoms}{inner}</body>')
        else:   # a fixed first link: part of the palm body
            out.append(f'<body name="f{k}_l1" pos="{nums(base_pos)}" quat="{nums(base_q)}">{inertial(links[1], a1, alpha1)}'
                       f'{l1_geoms}{inner}</body>')
    assets = ['<mesh name="palm" file="palm.obj"/>', '<mesh name="link2" file="finger_link2.obj"/>',
              '<mesh name="link3" file="finger_link3.obj"/>']
    assets += [f'<mesh name="link1_{i}" file="{p}"/>' for i, p in enumerate(link1_pieces)]
    assets += [f'<mesh name="object_{i}" file="{p}"/>' for i, p in enumerate(object_pieces)]
    object_geoms = ''.join(f'<geom class="object" mesh="object_{i}"/>' for i in range(len(object_pieces)))
    # the spread: fingers 1 and 2 turn by -s and +s (eqs 1-2); finger 3 has none
    spread_fingers = [f['finger'] for f in hand['fingers'] if f['spread_deg_per_count'] != 0]
    equality = ''
    if len(spread_fingers) == 2:
        a, b = spread_fingers
        equality += f'<joint joint1="f{b}_j1" joint2="f{a}_j1" polycoef="0 -1 0 0 0"/>'
    # the worm drive: after a breakaway the inner joint stays where it is (switched on by the controller)
    equality += ''.join(f'<joint name="f{f["finger"]}_worm" joint1="f{f["finger"]}_j2" polycoef="0 0 0 0 0" active="false" solref="0.004 1"/>'
                        for f in hand['fingers'])
    actuators = ''
    if spread_fingers:
        actuators += f'<position name="spread" joint="f{spread_fingers[0]}_j1" kp="10"/>'
    for f in hand['fingers']:
        k = f['finger']
        actuators += f'<position name="f{k}_inner" joint="f{k}_j2" class="clutch"/><position name="f{k}_outer" joint="f{k}_j3" class="clutch"/>'
    g = scenario.get('gravity_m_s2', [0, 0, -9.81])
    return f'''<mujoco model="handsim-{scenario.get('name', 'scene')}">
  <compiler angle="radian" meshdir="{meshdir}" autolimits="true"/>
  <option timestep="{dt!r}" gravity="{nums(g)}"/>
  <default>
    <geom friction="{mu!r} 0.005 0.0001" condim="3"/>
    <default class="link"><geom type="mesh" contype="1" conaffinity="0"/></default>
    <default class="object"><geom type="mesh" contype="0" conaffinity="1"/></default>
    <default class="flex"><joint type="hinge" axis="0 0 1" damping="0.05"/></default>
    <default class="clutch"><position kp="{k_clutch!r}" forcelimited="true" forcerange="{-tau_break!r} {tau_break!r}"/></default>
  </default>
  <asset>{''.join(assets)}</asset>
  <worldbody>
    <body name="palm"><geom type="mesh" mesh="palm" contype="0" conaffinity="0"/>{''.join(out)}</body>
    <body name="object" mocap="true" pos="{nums(obj['position_m'])}" quat="{nums(rotvec_quat(obj['rotation_rad']))}">{object_geoms}</body>
  </worldbody>
  <equality>{equality}</equality>
  <actuator>{actuators}</actuator>
</mujoco>
'''


if __name__ == '__main__':
    hand_file, scenario_file, meshdir, object_pieces, link1_pieces, dt, out_file = sys.argv[1:8]
    with open(hand_file) as f:
        hand = json.load(f)
    with open(scenario_file) as f:
        scenario = json.load(f)
    xml = build(hand, scenario, meshdir, object_pieces.split(','), link1_pieces.split(','), float(dt))
    with open(out_file, 'w') as f:
        f.write(xml)
