"""One MuJoCo process running a HandSim scenario, timed as a whole by tools/mujoco-compare:
import, compile the MJCF (mjcf.py), run the scenario's motor profiles for its duration, print
one JSON line.

  python mjrun.py SCENE.xml SCENARIO.json HAND.json

MuJoCo has no breakaway clutch, so each finger's inner and outer joints are driven by position
servos of stiffness k_clutch, force limited to tau_break (the MJCF's class "clutch"), and the
controller below follows HandSim's clutch state machine (docs/DESIGN.md, decision 1) once per
step from the servo's spring torque k_clutch (theta2* - theta2):
  FREE     theta2* = q / 125 deg, theta3* = q / 375 deg (eqs 3, 4);
  BLOCKED  (torque above a contact threshold while closing) theta3* held where it was;
  BROKEN   (torque reaches tau_break) the inner joint locked where it stands (the worm drive, an
           equality switched on) and theta3* = theta3_held + 4/375 deg (q - q_break) (eq 10);
  opening re-engages: BROKEN -> BLOCKED below q_break, BLOCKED -> FREE below the contact count.
"""
import json
import math
import sys
import time

import mujoco

DEG = math.pi / 180
FREE, BLOCKED, BROKEN = 0, 1, 2
TAU_CONTACT = 0.10   # N*m of spring torque that says the inner link is held


def profile(segments, dt, steps):
    """The motor's counts at the end of each step: trapezoids and holds from 0 (HandSim's Trapezoid)."""
    pieces, t0, q = [], 0.0, 0.0
    for s in segments:
        if s['type'] == 'trapezoid':
            q1, v, a = s['to'], s['v_max'], s['a_max']
            d = abs(q1 - q)
            sign = (q1 > q) - (q1 < q)
            if d >= v * v / a:
                vp, tr, tc = v, v / a, (d - v * v / a) / v
            else:
                vp = math.sqrt(d * a)
                tr, tc = vp / a, 0.0
            pieces.append((t0, 2 * tr + tc, q, sign, d, vp, tr, tc, a))
            t0 += 2 * tr + tc
            q = q1
        else:
            pieces.append((t0, s['duration_s'], q, 0, 0, 0, 0, 0, 0))
            t0 += s['duration_s']
    out = []
    for i in range(steps):
        t = (i + 1) * dt
        value = q
        for start, dur, q0, sign, d, vp, tr, tc, a in pieces:
            if t < start + dur:
                u = t - start
                if sign == 0:
                    value = q0
                elif u < tr:
                    value = q0 + sign * 0.5 * a * u * u
                elif u < tr + tc:
                    value = q0 + sign * (0.5 * vp * tr + vp * (u - tr))
                else:
                    r = 2 * tr + tc - u
                    value = q0 + sign * (d - 0.5 * a * r * r)
                break
        out.append(value)
    return out, t0


def main():
    xml, scenario_file, hand_file = sys.argv[1:4]
    with open(scenario_file) as f:
        scenario = json.load(f)
    with open(hand_file) as f:
        hand = json.load(f)
    k = hand['clutch']['k_clutch_Nm_per_rad']
    tau_break = hand['clutch']['tau_break_Nm']
    c2 = DEG / hand['transmission']['inner_counts_per_deg']
    c3 = DEG / hand['transmission']['outer_counts_per_deg']
    m = mujoco.MjModel.from_xml_path(xml)
    d = mujoco.MjData(m)
    dt = m.opt.timestep
    motors = scenario['motors']
    duration = 0.0
    for name, segs in motors.items():
        duration = max(duration, profile(segs, dt, 0)[1])
    steps = int(round(duration / dt))
    fingers = []
    for f in (1, 2, 3):
        if f'M{f}' not in motors:
            continue
        q, _ = profile(motors[f'M{f}'], dt, steps)
        fingers.append(dict(q=q, a2=m.joint(f'f{f}_j2').qposadr[0], a3=m.joint(f'f{f}_j3').qposadr[0],
                            inner=m.actuator(f'f{f}_inner').id, outer=m.actuator(f'f{f}_outer').id,
                            worm=m.equality(f'f{f}_worm').id, state=FREE, held3=0.0, q_contact=0.0, q_break=0.0))
    qpos, ctrl, eq_active, eq_data = d.qpos, d.ctrl, d.eq_active, m.eq_data
    step = mujoco.mj_step
    t0 = time.perf_counter()
    for i in range(steps):
        for f in fingers:
            qs = f['q']
            q = qs[i]
            closing = i == 0 or q >= qs[i - 1]
            th2 = qpos[f['a2']]
            st = f['state']
            if st == FREE:
                t2, t3 = q * c2, q * c3
                if closing and k * (t2 - th2) > TAU_CONTACT:
                    st, f['held3'], f['q_contact'] = BLOCKED, t3, q
            elif st == BLOCKED:
                t2, t3 = q * c2, f['held3']
                if closing and k * (t2 - th2) >= tau_break:
                    st, f['q_break'] = BROKEN, q
                    f.setdefault('breakaway_s', d.time)
                    eq_data[f['worm'], 0] = th2
                    eq_active[f['worm']] = 1
                elif not closing and q < f['q_contact']:
                    st = FREE
            else:
                t2, t3 = f['q_break'] * c2, f['held3'] + 4 * c3 * (q - f['q_break'])
                if not closing and q < f['q_break']:
                    st = BLOCKED
                    eq_active[f['worm']] = 0
            f['state'] = st
            ctrl[f['inner']] = t2
            ctrl[f['outer']] = t3
        step(m, d)
    print(json.dumps(dict(xml=xml, steps=steps, sim_time_s=d.time, contacts=int(d.ncon),
                          step_loop_s=time.perf_counter() - t0, states=[f['state'] for f in fingers],
                          breakaway_s=[f.get('breakaway_s') for f in fingers])))


if __name__ == '__main__':
    main()
