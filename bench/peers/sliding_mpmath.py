"""Problem 1 (steady sliding with friction, adhesive friction and wear; periodic parabolic punches)
at high precision with mpmath: the SAME method as the project's MPFR solver (src/sliding/), written
for bench/peers/solvers.

Method (THEORY.md section 3):
- theta = arctan(kappa)/pi, kappa = E* cW/2 - beta mu; tangent map t = tan(pi (x-c)/L) = m u,
  m = tan(lambda), lambda = pi l/L.
- [2.14] as K int g'(x(u)) (m u + i)/((1 + m^2 u^2) omega(u)) du = P2/L - i beta tau0,
  K = E* cos(pi theta) e^{-2 i theta lambda}/(2 pi cos lambda): the imaginary part gives the centre c
  (affine in c for the parabola), the real part the load; lambda by the secant method.
- [2.13] p(u) = omega(u) cos^2(pi theta)/pi sum_j w_j [F(u_j) - F(u)]/(u_j - u), F = (E*/2) g'.
- F_def = int p g' dx with the Gauss-Jacobi rule for the weight omega.
- Gauss-Jacobi rules generated at the working precision: f64 eigenvalues of the Jacobi matrix
  (numpy) as the start, Newton on the three-term recurrence of the orthonormal polynomials,
  Christoffel-Darboux weights (the project's src/numerics/gauss_jacobi_mpfr.rs does the same).
- Node count from the same error model (quadrature error ~ tan(lambda/2)^(2n)), the same working
  precision (ceil(digits log2 10) + 32 bits), the same two stages (locate at 64 bits for 16 digits,
  then secant refinement at the working precision). No verification run, no physicality checks
  (the project's timed call skips them too).

Usage: python sliding_mpmath.py NU ESTAR K L P2 MU TAU0 CW DIGITS REPEAT   (rationals like 3/10)
Prints one JSON line: best wall time of REPEAT solves (nothing cached between them) and the values.
"""
import json
import math
import sys
import time
from fractions import Fraction

import mpmath
import numpy as np
from mpmath import mp, mpf

GUARD_BITS = 32


def nodes_for(lam, digits):
    r = -math.log(math.tan(lam / 2))
    return max(8, math.ceil((digits + 4) * math.log(10) / (2 * r)))


def bucket(n):
    for b in (8, 16, 24, 32, 48, 64, 96, 128, 192, 256, 384, 512):
        if n <= b:
            return b
    return -(-n // 64) * 64


def gauss_jacobi(alpha, beta, n):
    """n-point rule for (1-u)^alpha (1+u)^beta on (-1, 1) at mp.prec (+ guard bits)."""
    prec = mp.prec
    mp.prec = prec + GUARD_BITS
    try:
        s = alpha + beta
        a = [(beta - alpha) / (s + 2)]
        b = [mpf(0)]
        for k in range(1, n + 1):
            t = 2 * k + s
            if k == 1:
                b2 = 4 * (1 + alpha) * (1 + beta) / ((2 + s) ** 2 * (3 + s))
            else:
                b2 = 4 * k * (k + alpha) * (k + beta) * (k + s) / (t * t * (t + 1) * (t - 1))
            b.append(mp.sqrt(b2))
            if k < n:
                a.append((beta * beta - alpha * alpha) / (t * (t + 2)))
        # f64 start: eigenvalues of the symmetric tridiagonal Jacobi matrix.
        jm = np.diag([float(x) for x in a]) + np.diag([float(x) for x in b[1:n]], 1) + np.diag(
            [float(x) for x in b[1:n]], -1)
        x0 = np.linalg.eigvalsh(jm)
        mu0 = mpf(2) ** (s + 1) * mp.gamma(alpha + 1) * mp.gamma(beta + 1) / mp.gamma(s + 2)
        ib = [1 / x if x else mpf(0) for x in b]
        full = mp.prec
        eps = mpf(2) ** (-(prec + 8))
        nodes, weights = [], []
        for xf in x0:
            x = mpf(float(xf))
            bits = 26  # correct bits of the f64 start (conservative); Newton doubles them
            for _ in range(60):
                mp.prec = min(full, 2 * bits + 32)
                p0, p1, d0, d1 = mpf(0), mpf(1), mpf(0), mpf(0)
                for k in range(n):
                    xa = x - a[k]
                    p2 = (xa * p1 - b[k] * p0) * ib[k + 1]
                    d2 = (xa * d1 + p1 - b[k] * d0) * ib[k + 1]
                    p0, p1, d0, d1 = p1, p2, d1, d2
                dx = p1 / d1
                x -= dx
                if mp.prec == full and abs(dx) <= eps:
                    break
                bits = min(2 * bits, full)
            mp.prec = full
            # weight from the last pass (p0 = p_{n-1}, d1 = p_n'): sum p_k^2 = b_n p_n' p_{n-1}
            nodes.append(x)
            weights.append(mu0 / (b[n] * d1 * p0))
        return [+u for u in nodes], [+w for w in weights]
    finally:
        mp.prec = prec


class Case:
    def __init__(self, nu, es, k, L, p2, mu, tau0, cw):
        f = lambda v: mpf(Fraction(v).numerator) / Fraction(v).denominator
        nuq = Fraction(nu)
        betaq = (1 - 2 * nuq) / (2 * (1 - nuq))
        kappaq = Fraction(es) * Fraction(cw) / 2 - betaq * Fraction(mu)
        self.es, self.k, self.L, self.p2t = f(es), f(k), f(L), f(p2)
        self.mu, self.tau0, self.beta = f(mu), f(tau0), f(betaq)
        self.kappa = f(kappaq)
        self.theta = mp.atan(self.kappa) / mp.pi
        self.cpt = mp.cos(mp.pi * self.theta)

    def terms(self, lam, rule):
        """(re0, re1, im0, im1) of [2.14] over the slope basis B = (1, (L/pi) atan(m u))."""
        m = mp.tan(lam)
        sr0 = sr1 = si0 = si1 = mpf(0)
        for u, w in zip(*rule):
            s = m * u
            wi = w / (1 + s * s)
            wr = wi * s
            b1 = self.L / mp.pi * mp.atan(s)
            sr0 += wr
            sr1 += wr * b1
            si0 += wi
            si1 += wi * b1
        kmag = self.es * self.cpt / (2 * mp.pi * mp.cos(lam))
        psi = 2 * self.theta * lam
        sn, cs = mp.sin(psi), mp.cos(psi)
        re = [(cs * sr + sn * si) * kmag * self.L for sr, si in ((sr0, si0), (sr1, si1))]
        im = [(cs * si - sn * sr) * kmag for sr, si in ((sr0, si0), (sr1, si1))]
        return re, im

    def centre_load(self, lam, rule):
        re, im = self.terms(lam, rule)
        bt = self.beta * self.tau0
        c = -(2 * self.k * im[1] + bt) / (2 * self.k * im[0])
        return c, 2 * self.k * (c * re[0] + re[1])

    def secant(self, lam0, rule, prec):
        f = lambda x: self.centre_load(x, rule)[1] - self.p2t
        x0, x1 = mpf(lam0), mpf(lam0) * (1 + mpf(10) ** -12)
        f0, f1 = f(x0), f(x1)
        tol = mpf(2) ** (-(prec - 8))
        for _ in range(40):
            if f1 == f0:
                return x1
            step = f1 * (x1 - x0) / (f1 - f0)
            x2 = x1 - step
            if abs(step) <= tol * abs(x2):
                return x2
            x0, f0, x1, f1 = x1, f1, x2, f(x2)
        raise RuntimeError("secant did not converge")


def solve(args, digits):
    nu, es, k, L, p2, mu, tau0, cw = args
    prec = math.ceil(digits * math.log2(10)) + GUARD_BITS
    # Stage 1: locate lambda at 64 bits (16 digits) from the Kuznetsov/single-punch estimate.
    mp.prec = 64
    cs = Case(*args)
    th = float(cs.theta)
    ls = math.sqrt(2 * float(cs.p2t) / (math.pi * float(cs.es) * float(cs.k))) / math.sqrt(1 - 4 * th * th)
    x = math.pi * ls / float(cs.L)
    lam0 = math.acos(math.exp(-x * x / 2))
    n_lo = bucket(nodes_for(lam0, 16))
    alpha, beta_ = cs.theta - mpf(1) / 2, -cs.theta - mpf(1) / 2
    lam_lo = float(cs.secant(lam0, gauss_jacobi(alpha, beta_, n_lo), 64))
    # Stage 2: refine at the working precision with the error-model node count.
    mp.prec = prec
    cs = Case(*args)
    n = -(-nodes_for(lam_lo, digits) // 4) * 4
    alpha, beta_ = cs.theta - mpf(1) / 2, -cs.theta - mpf(1) / 2
    rule = gauss_jacobi(alpha, beta_, n)
    lam = cs.secant(lam_lo, rule, prec)
    c, p2v = cs.centre_load(lam, rule)
    m = mp.tan(lam)
    l = lam * cs.L / mp.pi
    F = lambda u: cs.es / 2 * 2 * cs.k * (c + cs.L / mp.pi * mp.atan(m * u))
    fn = [F(u) for u in rule[0]]
    fac = cs.cpt ** 2 / mp.pi

    def D(u):
        fu = F(u)
        return mp.fsum(w * (fj - fu) / (uj - u) for uj, w, fj in zip(rule[0], rule[1], fn))

    omega = lambda u: (1 + u) ** (cs.theta + mpf(1) / 2) * (1 - u) ** (mpf(1) / 2 - cs.theta)
    ps = []
    for xh in (Fraction(-3, 5), Fraction(0), Fraction(7, 10)):
        u = mp.tan(lam * mpf(xh.numerator) / xh.denominator) / m
        ps.append(omega(u) * fac * D(u))
    # F_def = int p g' dx with the rule for the weight omega.
    ru = gauss_jacobi(mpf(1) / 2 - cs.theta, cs.theta + mpf(1) / 2, n)
    fdef = mpf(0)
    for u, w in zip(*ru):
        jac = cs.L / mp.pi * m / (1 + (m * u) ** 2)
        fdef += D(u) * w * jac * (2 * cs.k * (c + cs.L / mp.pi * mp.atan(m * u)))
    fdef *= fac
    p1 = cs.mu * p2v + 2 * l * cs.tau0
    return dict(nodes=n, prec=prec, lambda_=lam, a=l - c, b=l + c, c=c, P1=p1, P2=p2v, F_def=fdef, p=ps)


def main():
    args = sys.argv[1:9]
    digits, repeat = int(sys.argv[9]), int(sys.argv[10])
    best, out = float("inf"), None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = solve(args, digits)
        best = min(best, time.perf_counter() - t0)
    fmt = lambda v: mpmath.nstr(v, 80, min_fixed=1, max_fixed=0)
    res = {"time_s": best, "backend": mpmath.libmp.BACKEND, "nodes": out["nodes"], "prec": out["prec"]}
    for key in ("lambda_", "a", "b", "c", "P1", "P2", "F_def"):
        res[key.rstrip("_")] = fmt(out[key])
    res["p"] = [fmt(v) for v in out["p"]]
    print(json.dumps(res))


if __name__ == "__main__":
    main()
