#!/usr/bin/env python3
"""Generates src/main/java/org/handsim/dynamics/BarrettFingerKernel.java: the closed-form
("analytical", paper Section II.C) inertia matrix D, Coriolis/centrifugal vector H, gravity
vector C and potential energy V of a BarrettHand finger, paper eq (8).

Usage (from the repository root; needs sympy, e.g. `pip install sympy`):

    python3 tools/dynamics/gen_barrett_closed_form.py [--check]

--check regenerates in memory and fails (exit 1) if the committed Java file differs.

Derivation (Fu-Gonzalez-Lee, Robotics, 1987, section 3.2, the Lagrange-Euler formulation):

  * Structure: three revolute joints, standard DH T(j-1 -> j) = Rz(th_j) Tz(d_j) Tx(a_j) Rx(al_j)
    with al = (90 deg, 0, 0) and d = (0, 0, 0) (paper Table I). The link lengths a1, a2, a3 and
    the ten inertial parameters of each link stay symbols, so the generated code serves any hand
    description file with this structure; the DH angle th_j = q_j + offset_j is an input.
  * Symbols c_j = cos th_j, s_j = sin th_j make every entry a polynomial.
  * D_ik = sum_j Tr(U_jk J_j U_ji^T)                           (LE3)
    U_ji = T_{i-1} Q ^{i-1}T_j                                   (LE1)
    J_j  = pseudo-inertia about the origin of frame {j}           (FGL §3.2)
    The ten parameters of each J_j stay symbols: their numbers come at run time from
    LinkChain.pseudoInertia (Table III read about each link frame's origin, J = tr(I)/2 E - I),
    so the reading of Table III is not in this file and a change of it needs no regeneration.
  * c_i  = -sum_j m_j g U_ji rbar_j                               (FGL §3.2, c)
  * V    = -sum_j m_j g T_j rbar_j                                (FGL §3.2)
  * h_i  = sum_k sum_m c_ikm qd_k qd_m with the Christoffel symbols
    c_ikm = (dD_ik/dq_m + dD_im/dq_k - dD_km/dq_i) / 2, equal to FGL's h_ikm: both
    are the symmetric coefficients of the same quadratic form in qd.
  * Every polynomial is reduced modulo s_j^2 + c_j^2 - 1 (a Groebner basis), which is exact;
    each output is then written in whichever basis gives fewer terms: (c3, s3) or the angle sum
    (c23, s23) = (cos, sin)(th2 + th3) of the two parallel joints.
  * Each output is then a sum of (parameter-only coefficient) x (monomial in c, s, qd, g).
    The coefficients are hoisted into constants computed once in the constructor; what is left
    per call is sin/cos of three angles, the shared monomials and multiply-adds.

The generated Java is tested against the general algorithms (LagrangeEuler, NewtonEuler) by
ClosedFormFingerTest.
"""
import argparse
import os
import sys

import sympy as sp

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), '..', '..'))
OUT = os.path.join(ROOT, 'src', 'main', 'java', 'org', 'handsim', 'dynamics', 'BarrettFingerKernel.java')

c1, s1, c2, s2, c3, s3 = sp.symbols('c1 s1 c2 s2 c3 s3')
c23, s23 = sp.symbols('c23 s23')   # cos, sin of th2 + th3 (joints 2 and 3 are parallel)
TRIG = [c1, s1, c2, s2, c3, s3, c23, s23]
CS = [(c1, s1), (c2, s2), (c3, s3)]
a1, a2, a3 = sp.symbols('a1 a2 a3')
A = [a1, a2, a3]
ALPHA_CS = [(0, 1), (1, 0), (1, 0)]  # (cos alpha_j, sin alpha_j): 90, 0, 0 degrees
qd = sp.symbols('qd1 qd2 qd3')
qdd = sp.symbols('qdd1 qdd2 qdd3')
gx, gy, gz = sp.symbols('gx gy gz')
G = [gx, gy, gz]

# Pseudo-inertia parameters of link j: name -> index into the 16 row-major values of J_j.
PARAM_SLOTS = [('Jxx', 0), ('Jxy', 1), ('Jxz', 2), ('mx', 3), ('Jyy', 5), ('Jyz', 6), ('my', 7),
               ('Jzz', 10), ('mz', 11), ('m', 15)]
PARAMS = {}
J = []
for j in range(1, 4):
    p = {name: sp.Symbol(f'{name}{j}') for name, _ in PARAM_SLOTS}
    for name, slot in PARAM_SLOTS:
        PARAMS[p[name]] = (j - 1, slot)
    J.append(sp.Matrix([[p['Jxx'], p['Jxy'], p['Jxz'], p['mx']],
                        [p['Jxy'], p['Jyy'], p['Jyz'], p['my']],
                        [p['Jxz'], p['Jyz'], p['Jzz'], p['mz']],
                        [p['mx'], p['my'], p['mz'], p['m']]]))
LENGTHS = {a1: 'a1', a2: 'a2', a3: 'a3'}

IDEAL = [s1**2 + c1**2 - 1, s2**2 + c2**2 - 1, s3**2 + c3**2 - 1]
ORDER_GENS = (s1, s2, s3, c1, c2, c3)
# the same polynomials in the angle-sum basis (c2, s2, c23, s23) instead of (c3, s3)
IDEAL_SUM = [s1**2 + c1**2 - 1, s2**2 + c2**2 - 1, s23**2 + c23**2 - 1]
ORDER_GENS_SUM = (s1, s2, s23, c1, c2, c23)


def dh(j):
    c, s = CS[j]
    ca, sa = ALPHA_CS[j]
    a = A[j]
    return sp.Matrix([[c, -s * ca, s * sa, a * c],
                      [s, c * ca, -c * sa, a * s],
                      [0, sa, ca, 0],
                      [0, 0, 0, 1]])


def chain(i, j):
    """^iT_j for 0 <= i <= j <= 3."""
    m = sp.eye(4)
    for l in range(i, j):
        m = m * dh(l)
    return m.applyfunc(sp.expand)


def reduce_trig(e):
    e = sp.expand(e)
    if e == 0:
        return e
    _, r = sp.reduced(e, IDEAL, *ORDER_GENS, order='lex')
    return sp.expand(r)


def shortest_basis(e, outer_vars):
    """e in the (c3, s3) basis, or rewritten with c3 = c23 c2 + s23 s2, s3 = s23 c2 - c23 s2 and
    reduced modulo the angle-sum ideal, whichever has fewer terms (same value either way)."""
    e = sp.expand(e)
    alt = sp.expand(e.subs({c3: c23 * c2 + s23 * s2, s3: s23 * c2 - c23 * s2}, simultaneous=True))
    if alt != 0:
        _, alt = sp.reduced(alt, IDEAL_SUM, *ORDER_GENS_SUM, order='lex')
        alt = sp.expand(alt)
    gens = list(outer_vars) + TRIG
    n_e = len(sp.Poly(e, *gens).terms()) if e != 0 else 0
    n_alt = len(sp.Poly(alt, *gens).terms()) if alt != 0 else 0
    return alt if n_alt < n_e else e


def d_dtheta(e, i):
    """Partial derivative with respect to the DH angle th_{i+1} (c -> -s, s -> c)."""
    c, s = CS[i]
    return reduce_trig(sp.diff(e, c) * (-s) + sp.diff(e, s) * c)


def derive():
    Q = sp.zeros(4)
    Q[0, 1] = -1
    Q[1, 0] = 1
    T = [chain(0, j) for j in range(4)]
    U = {}
    for j in range(1, 4):
        for i in range(1, j + 1):
            U[(j, i)] = (T[i - 1] * Q * chain(i - 1, j)).applyfunc(sp.expand)
    D = [[None] * 3 for _ in range(3)]
    for i in range(1, 4):
        for k in range(i, 4):
            tot = 0
            for j in range(max(i, k), 4):
                tot += (U[(j, k)] * J[j - 1] * U[(j, i)].T).trace()
            D[i - 1][k - 1] = D[k - 1][i - 1] = reduce_trig(tot)
    g4 = sp.Matrix([gx, gy, gz, 0])
    C = []
    for i in range(1, 4):
        tot = 0
        for j in range(i, 4):
            tot += -(g4.T * U[(j, i)] * J[j - 1][:, 3])[0]
        C.append(reduce_trig(tot))
    V = 0
    for j in range(1, 4):
        V += -(g4.T * T[j] * J[j - 1][:, 3])[0]
    V = reduce_trig(V)
    dD = [[[d_dtheta(D[i][k], m) for m in range(3)] for k in range(3)] for i in range(3)]
    H = []
    for i in range(3):
        tot = 0
        for k in range(3):
            for m in range(3):
                tot += sp.Rational(1, 2) * (dD[i][k][m] + dD[i][m][k] - dD[k][m][i]) * qd[k] * qd[m]
        H.append(reduce_trig(tot))
    return D, H, C, V


# ---------------------------------------------------------------- Java printing

def jnum(x):
    x = sp.nsimplify(x)
    if x.is_Integer:
        return f'{int(x)}.0'
    return repr(float(x))


def jexpr(e, names):
    """Java text of a polynomial expression; names maps symbols to Java identifiers."""
    e = sp.expand(e)
    if e.is_Add:
        parts = []
        for t in sorted(e.args, key=sp.default_sort_key):
            s = jexpr(t, names)
            if parts and s.startswith('-'):
                parts.append('- ' + s[1:])
            elif parts:
                parts.append('+ ' + s)
            else:
                parts.append(s)
        return ' '.join(parts)
    if e.is_Mul:
        coeff, rest = e.as_coeff_Mul()
        factors = []
        for f in sp.Mul.make_args(rest):
            if f.is_Pow:
                b, p = f.args
                factors += [names[b]] * int(p)
            else:
                factors.append(names[f])
        body = ' * '.join(factors)
        if coeff == 1:
            return body
        if coeff == -1:
            return '-' + body
        return f'{jnum(coeff)} * {body}' if coeff > 0 else f'-{jnum(-coeff)} * {body}'
    if e.is_Pow:
        b, p = e.args
        return ' * '.join([names[b]] * int(p))
    if e.is_Symbol:
        return names[e]
    return jnum(e)


class Constants:
    """Parameter-only coefficients, hoisted to constructor-computed fields k0, k1, ..."""

    def __init__(self):
        self.exprs = []
        self.index = {}

    def ref(self, coeff):
        """Java text (with sign) of a reference to the constant equal to coeff."""
        coeff = sp.expand(coeff)
        if coeff.is_number:
            return jnum(coeff)
        if coeff in self.index:
            return f'k{self.index[coeff]}'
        neg = sp.expand(-coeff)
        if neg in self.index:
            return f'-k{self.index[neg]}'
        # prefer storing the form with fewer leading minus signs
        self.index[coeff] = len(self.exprs)
        self.exprs.append(coeff)
        return f'k{len(self.exprs) - 1}'


def mono_name(exps, vars_):
    parts = []
    for v, e in zip(vars_, exps):
        parts += [str(v)] * e
    return '_'.join(parts)


class Method:
    """Emits one Java method body: shared trig monomials, then the outputs."""

    def __init__(self, consts):
        self.consts = consts
        self.monos = {}
        self.outer = {}

    def trig_term(self, exps):
        """Java name of the trig monomial with exponents exps over TRIG (registering it)."""
        if sum(exps) == 0:
            return None
        if sum(exps) == 1:
            return str(TRIG[exps.index(1)])
        self.monos[tuple(exps)] = mono_name(exps, TRIG)
        return self.monos[tuple(exps)]

    def linear_form(self, expr, outer_vars):
        """expr as sum over monomials of outer_vars of (sum of K * trig monomial)."""
        poly = sp.Poly(shortest_basis(expr, outer_vars), *(outer_vars + TRIG))
        groups = {}
        for exps, coeff in poly.terms():
            outer = exps[:len(outer_vars)]
            trig = list(exps[len(outer_vars):])
            groups.setdefault(outer, []).append((trig, coeff))
        pieces = []
        for outer in sorted(groups):
            inner = []
            for trig, coeff in sorted(groups[outer], key=lambda t: (sum(t[0]), t[0])):
                k = self.consts.ref(coeff)
                t = self.trig_term(trig)
                inner.append(k if t is None else f'{k} * {t}')
            inner_txt = ' + '.join(inner).replace('+ -', '- ')
            factor = mono_name(outer, outer_vars)
            if sum(outer) > 1:
                self.outer[factor] = ' * '.join(factor.split('_'))
            if factor:
                pieces.append(f'{factor} * ({inner_txt})' if len(inner) > 1 else f'{factor} * {inner_txt}')
            else:
                pieces.append(inner_txt if len(inner) == 1 else f'({inner_txt})')
        return '\n                + '.join(pieces) if pieces else '0.0'

    def monomial_lines(self):
        """Java lines computing every registered trig monomial from smaller ones."""
        nt = len(TRIG)
        have = {tuple(1 if i == k else 0 for i in range(nt)): str(TRIG[k]) for k in range(nt)}
        lines = []
        todo = sorted(self.monos, key=lambda e: (sum(e), e))
        # include every prefix needed to build each monomial one factor at a time
        needed = set()
        for e in todo:
            e = list(e)
            while sum(e) > 1:
                needed.add(tuple(e))
                k = max(i for i in range(nt) if e[i] > 0)
                e[k] -= 1
        for e in sorted(needed, key=lambda e: (sum(e), e)):
            k = max(i for i in range(nt) if e[i] > 0)
            sub = list(e)
            sub[k] -= 1
            name = mono_name(e, TRIG)
            lines.append(f'        final double {name} = {have[tuple(sub)]} * {TRIG[k]};')
            have[e] = name
        for name in sorted(self.outer):
            lines.append(f'        final double {name} = {self.outer[name]};')
        return lines


TRIG_LINES = [
    '        final double c1 = Math.cos(t1), s1 = Math.sin(t1);',
    '        final double c2 = Math.cos(t2), s2 = Math.sin(t2);',
    '        final double c3 = Math.cos(t3), s3 = Math.sin(t3);',
    '        final double c23 = c2 * c3 - s2 * s3, s23 = s2 * c3 + c2 * s3;',
]

HEADER = '''package org.handsim.dynamics;

// GENERATED by tools/dynamics/gen_barrett_closed_form.py (sympy {sympy}); do not edit.
// Regenerate: python3 tools/dynamics/gen_barrett_closed_form.py

/**
 * Closed-form Lagrange–Euler terms of a BarrettHand finger (paper eq 8; Fu–Gonzalez–Lee §3.2),
 * generated symbolically: the "analytical representation of the matrices" the paper
 * implemented. Valid for three revolute joints with standard DH twists α = (90°, 0, 0) and
 * offsets d = (0, 0, 0) (paper Table I); the link lengths and the ten inertial parameters of each
 * link (the pseudo-inertia J_j about the origin of frame {{j}}, FGL §3.2) are constructor
 * arguments, folded once into the constants k0…k{nk}.
 *
 * <p>Inputs are the DH angles t_j = q_j + offset_j (radians), joint velocities (rad/s),
 * accelerations (rad/s²) and gravity (m/s², base frame {{0}}); outputs in kg·m² (D, row-major
 * 3×3), N·m (H, C, τ) and J (V). No argument checks, no allocation: {{@link ClosedFormFinger}}
 * is the public face. Immutable and thread-safe.
 *
 * <p>How the expressions were derived (see the generator's docstring): D_ik = Σ_j Tr(U_jk J_j
 * U_jiᵀ) (formula LE3 of {{@link LagrangeEuler}}), C_i = −Σ_j m_j g U_ji r̄_j (LE5),
 * V = −Σ_j m_j g T_j r̄_j, H_i = Σ_km c_ikm q̇_k q̇_m with the Christoffel symbols c_ikm of D
 * (equal to FGL's h_ikm, LE4), each reduced modulo sin² + cos² = 1.
 */
final class BarrettFingerKernel {{
'''


def generate():
    D, H, C, V = derive()
    consts = Constants()
    methods = []

    def method(signature, body_fn):
        m = Method(consts)
        body = body_fn(m)
        lines = [f'    {signature} {{'] + TRIG_LINES + m.monomial_lines() + body + ['    }', '']
        methods.append('\n'.join(lines))

    def d_lines(m, local):
        out = []
        for i in range(3):
            for k in range(i, 3):
                out.append(f'        final double d{i + 1}{k + 1} = {m.linear_form(D[i][k], [])};')
        if not local:
            for i in range(3):
                for k in range(3):
                    a, b = min(i, k) + 1, max(i, k) + 1
                    out.append(f'        d[{3 * i + k}] = d{a}{b};')
        return out

    def h_lines(m, store):
        out = [f'        final double h{i + 1} = {m.linear_form(H[i], list(qd))};' for i in range(3)]
        if store:
            out += [f'        h[{i}] = h{i + 1};' for i in range(3)]
        return out

    def c_lines(m, store):
        out = [f'        final double g{i + 1} = {m.linear_form(C[i], G)};' for i in range(3)]
        if store:
            out += [f'        c[{i}] = g{i + 1};' for i in range(3)]
        return out

    method('/** D(q), eq (8): writes the 9 entries of the symmetric 3×3 inertia matrix, row-major. */\n'
           '    void massMatrix(double t1, double t2, double t3, double[] d)',
           lambda m: d_lines(m, False))
    method('/** H(q, q̇), eq (8): Coriolis and centrifugal torques. */\n'
           '    void coriolisCentrifugal(double t1, double t2, double t3, double qd1, double qd2, double qd3, double[] h)',
           lambda m: h_lines(m, True))
    method('/** C(q), eq (8): gravity torques for gravity (gx, gy, gz) in the base frame. */\n'
           '    void gravityTorque(double t1, double t2, double t3, double gx, double gy, double gz, double[] c)',
           lambda m: c_lines(m, True))
    method('/** D, H and C of eq (8) in one evaluation (shared sin/cos and monomials). */\n'
           '    void terms(double t1, double t2, double t3, double qd1, double qd2, double qd3,\n'
           '               double gx, double gy, double gz, double[] d, double[] h, double[] c)',
           lambda m: d_lines(m, False) + h_lines(m, True) + c_lines(m, True))

    def tau_body(m):
        out = d_lines(m, True) + h_lines(m, False) + c_lines(m, False)
        out += [
            '        tau[0] = d11 * qdd1 + d12 * qdd2 + d13 * qdd3 + h1 + g1;',
            '        tau[1] = d12 * qdd1 + d22 * qdd2 + d23 * qdd3 + h2 + g2;',
            '        tau[2] = d13 * qdd1 + d23 * qdd2 + d33 * qdd3 + h3 + g3;',
        ]
        return out

    method('/** τ = D·q̈ + H + C, eq (8). */\n'
           '    void inverseDynamics(double t1, double t2, double t3, double qd1, double qd2, double qd3,\n'
           '                         double qdd1, double qdd2, double qdd3, double gx, double gy, double gz, double[] tau)',
           tau_body)
    method('/** Potential energy V = −Σ m_j g·p_j (FGL §3.2), J. */\n'
           '    double potentialEnergy(double t1, double t2, double t3, double gx, double gy, double gz)',
           lambda m: [f'        return {m.linear_form(V, G)};'])

    names = dict(LENGTHS)
    for sym, (link, slot) in PARAMS.items():
        names[sym] = f'p[{16 * link + slot}]'
    fields = '\n'.join(f'    private final double k{i};' for i in range(len(consts.exprs)))
    ctor = ['    /**',
            '     * @param a1 DH length a of link 1, metres (likewise a2, a3)',
            '     * @param p  the pseudo-inertias J_1, J_2, J_3 (FGL §3.2), 16 row-major values each',
            '     *          ({@link LinkChain#pseudoInertia}): kg, kg·m, kg·m²',
            '     */',
            '    BarrettFingerKernel(double a1, double a2, double a3, double[] p) {']
    for i, e in enumerate(consts.exprs):
        ctor.append(f'        k{i} = {jexpr(e, names)};')
    ctor += ['    }', '']
    text = HEADER.format(sympy=sp.__version__, nk=len(consts.exprs) - 1)
    text += f'    /** Number of hoisted constants. */\n    static final int CONSTANTS = {len(consts.exprs)};\n\n'
    text += fields + '\n\n' + '\n'.join(ctor) + '\n' + '\n'.join(methods).rstrip() + '\n}\n'
    return text


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--check', action='store_true', help='fail if the committed file is out of date')
    args = ap.parse_args()
    text = generate()
    if args.check:
        with open(OUT, encoding='utf-8') as f:
            if f.read() != text:
                print(f'{OUT} is out of date; run {sys.argv[0]}', file=sys.stderr)
                return 1
        print('up to date')
        return 0
    with open(OUT, 'w', encoding='utf-8') as f:
        f.write(text)
    print(f'wrote {OUT}')
    return 0


if __name__ == '__main__':
    sys.exit(main())
