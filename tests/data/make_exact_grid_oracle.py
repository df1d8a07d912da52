#!/usr/bin/env python3
"""The mpmath oracle of tests/it/exact_grid.rs: the benchmark body's torque-free motion on an equal grid.

Body: principal moments I = (1, 2, 3) kg m^2 (body axes principal), omega(0) = (0.3, 0, 2) rad/s, q(0) = identity;
rows t_k = k * 1e-3 s (the binary64 product, as eulerdyn's schedule forms it), k = 0 .. 100 000 (10^5 row intervals over 100 s). The oracle keeps every 331st row (331 is
prime, so the rows sample every position between two re-anchorings of the Rust recurrence) and the last one.

Formulas, evaluated with mpmath at 40 significant digits from the exact binary64 inputs:

* omega (Landau & Lifshitz, Mechanics, section 37): omega = (a cn tau, b sn tau, c dn tau), tau = lambda t + tau0,
  a^2 = (2E I3 - M^2)/(I1 (I3 - I1)), b^2 = (2E I3 - M^2)/(I2 (I3 - I2)), c^2 = (M^2 - 2E I1)/(I3 (I3 - I1)),
  lambda^2 = (I3 - I2)(M^2 - 2E I1)/(I1 I2 I3), m = (I2 - I1)(2E I3 - M^2)/((I3 - I2)(M^2 - 2E I1)), tau0 = 0
  (omega_2(0) = 0, omega_1(0) > 0); sn, cn, dn by mpmath.ellipfun.
* attitude: body -> space, q = Q R_z(phi) R_x(theta) R_z(psi) (z-x-z Euler angles of the body relative to the frame
  whose z axis is H; L&L section 37): M sin(theta) sin(psi) = I1 omega_1, M sin(theta) cos(psi) = I2 omega_2,
  M cos(theta) = I3 omega_3, and the precession angle by QUADRATURE of its rate (not by the third-kind integral the
  Rust code uses, so that the oracle is independent of that formula):
      dphi/dt = M (I1 omega_1^2 + I2 omega_2^2) / (I1^2 omega_1^2 + I2^2 omega_2^2)
  integrated by mpmath.quad (Gauss-Legendre) between consecutive oracle rows; Q = (R_x(theta0) R_z(psi0))^-1 so that
  q(0) = identity. psi is unwrapped along the rows (it turns by less than 1 rad between two oracle rows).

Checks printed (not written): H_s = q (I omega) is constant to 1e-30 relative at every oracle row, and omega, q at
t = 2 s agree with mpmath's Taylor ODE solver (odefun) of Euler's equations and q' = q (0, omega)/2.

Run: python3 tests/data/make_exact_grid_oracle.py > tests/data/exact_grid_oracle.csv  (needs mpmath; ~1 min)
"""

import sys

import mpmath as mp

mp.mp.dps = 40

I1, I2, I3 = mp.mpf(1), mp.mpf(2), mp.mpf(3)
W0 = [mp.mpf(0.3), mp.mpf(0), mp.mpf(2)]  # 0.3 as the binary64 value the Rust test uses
EVERY = 1e-3
ROWS = 100_000
STRIDE = 331

M2 = (I1 * W0[0]) ** 2 + (I2 * W0[1]) ** 2 + (I3 * W0[2]) ** 2
E2 = I1 * W0[0] ** 2 + I2 * W0[1] ** 2 + I3 * W0[2] ** 2
M = mp.sqrt(M2)
A = mp.sqrt((E2 * I3 - M2) / (I1 * (I3 - I1)))
B = mp.sqrt((E2 * I3 - M2) / (I2 * (I3 - I2)))
C = mp.sqrt((M2 - E2 * I1) / (I3 * (I3 - I1)))
LAM = mp.sqrt((I3 - I2) * (M2 - E2 * I1) / (I1 * I2 * I3))
PARAM = (I2 - I1) * (E2 * I3 - M2) / ((I3 - I2) * (M2 - E2 * I1))


def omega(t):
    tau = LAM * t
    return [A * mp.ellipfun("cn", tau, m=PARAM), B * mp.ellipfun("sn", tau, m=PARAM), C * mp.ellipfun("dn", tau, m=PARAM)]


def phi_rate(t):
    w1, w2, _ = omega(t)
    return M * (I1 * w1**2 + I2 * w2**2) / ((I1 * w1) ** 2 + (I2 * w2) ** 2)


def qmul(p, q):
    return [
        p[0] * q[0] - p[1] * q[1] - p[2] * q[2] - p[3] * q[3],
        p[0] * q[1] + p[1] * q[0] + p[2] * q[3] - p[3] * q[2],
        p[0] * q[2] - p[1] * q[3] + p[2] * q[0] + p[3] * q[1],
        p[0] * q[3] + p[1] * q[2] - p[2] * q[1] + p[3] * q[0],
    ]


def qconj(q):
    return [q[0], -q[1], -q[2], -q[3]]


def rotate(q, v):
    return qmul(qmul(q, [0] + list(v)), qconj(q))[1:]


def rz(angle):
    return [mp.cos(angle / 2), 0, 0, mp.sin(angle / 2)]


def rx(angle):
    return [mp.cos(angle / 2), mp.sin(angle / 2), 0, 0]


def euler_theta_psi(w):
    h = [I1 * w[0], I2 * w[1], I3 * w[2]]
    theta = mp.atan2(mp.sqrt(h[0] ** 2 + h[1] ** 2), h[2])
    psi = mp.atan2(h[0], h[1])
    return theta, psi


def main():
    theta0, psi0 = euler_theta_psi(omega(mp.mpf(0)))
    q_fixed = qconj(qmul(rx(theta0), rz(psi0)))
    h_s0 = rotate(qmul(q_fixed, qmul(rx(theta0), rz(psi0))), [I1 * W0[0], I2 * W0[1], I3 * W0[2]])
    rows = list(range(0, ROWS + 1, STRIDE))
    if rows[-1] != ROWS:
        rows.append(ROWS)
    out = sys.stdout
    out.write("# mpmath oracle, see tests/data/make_exact_grid_oracle.py; k, t = k*1e-3 s, omega_b (rad/s), q_b (w,x,y,z)\n")
    out.write("k,t,omega_x,omega_y,omega_z,q_w,q_x,q_y,q_z\n")
    phi, psi_prev, t_prev, worst_h = mp.mpf(0), psi0, mp.mpf(0), mp.mpf(0)
    for k in rows:
        t = mp.mpf(float(k) * EVERY)  # the binary64 product k * every, as the Rust schedule forms it
        if t > t_prev:
            phi += mp.quad(phi_rate, mp.linspace(t_prev, t, 4), method="gauss-legendre")
        w = omega(t)
        theta, psi = euler_theta_psi(w)
        psi = psi_prev + mp.atan2(mp.sin(psi - psi_prev), mp.cos(psi - psi_prev))
        q = qmul(q_fixed, qmul(rz(phi), qmul(rx(theta), rz(psi))))
        h_s = rotate(q, [I1 * w[0], I2 * w[1], I3 * w[2]])
        worst_h = max(worst_h, mp.norm(mp.matrix(h_s) - mp.matrix(h_s0)) / M)
        out.write(f"{k},{mp.nstr(t, 17)}," + ",".join(mp.nstr(x, 20, min_fixed=-1, max_fixed=1) for x in list(w) + list(q)) + "\n")
        t_prev, psi_prev = t, psi
    print(f"largest |H_s(t) - H_s(0)|/|H| over the oracle rows: {mp.nstr(worst_h, 3)}", file=sys.stderr)
    check_against_taylor(q_fixed)


def check_against_taylor(q_fixed):
    """omega and q at t = 2 s from mpmath's Taylor ODE solver, against the closed form with quadrature."""
    mp.mp.dps = 30

    def rhs(_t, y):
        w, q = y[:3], y[3:]
        dw = [(I2 - I3) * w[1] * w[2] / I1, (I3 - I1) * w[2] * w[0] / I2, (I1 - I2) * w[0] * w[1] / I3]
        dq = [x / 2 for x in qmul(q, [0] + list(w))]
        return dw + dq

    sol = mp.odefun(rhs, 0, list(W0) + [mp.mpf(1), 0, 0, 0])
    t = mp.mpf(2)
    y = sol(t)
    w = omega(t)
    theta, psi = euler_theta_psi(w)
    psi0 = euler_theta_psi(omega(mp.mpf(0)))[1]
    # psi turns once per period of omega (3.14 s), so at t = 2 s unwrap from psi0 through t = 1 s.
    _, psi1 = euler_theta_psi(omega(mp.mpf(1)))
    psi1 = psi0 + mp.atan2(mp.sin(psi1 - psi0), mp.cos(psi1 - psi0))
    psi = psi1 + mp.atan2(mp.sin(euler_theta_psi(w)[1] - psi1), mp.cos(euler_theta_psi(w)[1] - psi1))
    phi = mp.quad(phi_rate, mp.linspace(0, t, 8), method="gauss-legendre")
    q = qmul(q_fixed, qmul(rz(phi), qmul(rx(theta), rz(psi))))
    dw = max(abs(y[i] - w[i]) for i in range(3))
    dq = min(max(abs(y[3 + i] - q[i]) for i in range(4)), max(abs(y[3 + i] + q[i]) for i in range(4)))
    print(f"t = 2 s, closed form against odefun: |d omega| {mp.nstr(dw, 3)}, |d q| {mp.nstr(dq, 3)}", file=sys.stderr)


if __name__ == "__main__":
    main()
