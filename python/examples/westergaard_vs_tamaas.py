"""Load-size curve of the Westergaard problem (issue 16): a row of sinusoidal punches
g = D (1 - cos(2 pi x/L)) pressed without friction on an elastic half-plane, E* = L = 1, D = 1/100.
This project (pc.solve, f64 collocation and verified MPFR) beside Tamaas (PolonskyKeerRey, FFT
boundary elements on N nodes, as bench/peers/westergaard_tamaas.py runs it), against Westergaard's
closed form P2 = pi E* D sin^2(pi a/L) (paper [2.17]).

    pip install ./python matplotlib tamaas==2.9.0
    python python/examples/westergaard_vs_tamaas.py [OUT.png]     # default westergaard_vs_tamaas.png

Writes the figure (half-width a/L against the load, and each method's relative error of a against
the closed form) and prints the table. The errors are taken in float64 (the closed form too), so
about 1e-16 is the comparison's floor: the verified MPFR values sit on it (their own 20 digits are
not visible here). Run on 2026-11-23 (this machine, shared): f64 and MPFR within 4e-15 of the
closed form at every load, Tamaas at N = 4096 within 7e-5 to 3.5e-3 (counting contact nodes).
"""

import math
import sys
import time
from fractions import Fraction

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import periodic_contact as pc

E_STAR, L, D = 1.0, 1.0, Fraction(1, 100)
LOADS = [Fraction(k, 10000) for k in (5, 20, 50, 100, 150, 200, 250, 300)]  # below pi D = 0.0314


def westergaard_a(p2):
    """a from P2 = pi E* D sin^2(pi a/L)."""
    return L / math.pi * math.asin(math.sqrt(float(p2) / (math.pi * E_STAR * float(D))))


def ours(p2, method):
    scene = {
        "problem": {"kind": "sliding"},
        "material": {"poisson_ratio": "0.3", "contact_modulus": "1"},
        "punch": {"shape": "sinusoidal", "amplitude": str(D), "period": "1"},
        "sliding": {"normal_load": str(p2)},
    }
    t0 = time.perf_counter()
    r = pc.solve(scene, method=method, digits=15 if method == "f64" else 20)
    return float(r["l"]), time.perf_counter() - t0, r["digits_verified"]


def tamaas_a(p2, n):
    import tamaas as tm

    tm.set_log_level(tm.LogLevel.error)
    model = tm.ModelFactory.createModel(tm.model_type.basic_1d, [L], [n])
    model.E, model.nu = E_STAR, 0.0
    x = np.arange(n) * L / n
    surface = -float(D) * np.cos(2 * np.pi * x / L)
    solver = tm.PolonskyKeerRey(model, surface, 1e-10)
    solver.max_iter = 20000
    t0 = time.perf_counter()
    solver.solve(float(p2) / L)  # mean pressure
    dt = time.perf_counter() - t0
    p = np.array(model.traction).reshape(-1)
    return np.count_nonzero(p > 0) * (L / n) / 2, dt


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "westergaard_vs_tamaas.png"
    n_tamaas = 2**12
    rows = []
    for p2 in LOADS:
        a_exact = westergaard_a(p2)
        a_f64, t_f64, d_f64 = ours(p2, "f64")
        a_mpfr, t_mpfr, d_mpfr = ours(p2, "mpfr")
        a_tm, t_tm = tamaas_a(p2, n_tamaas)
        rows.append((float(p2), a_exact, a_f64, a_mpfr, a_tm, t_f64, t_mpfr, t_tm, d_f64, d_mpfr))
    print("P2        a (closed form)     rel. err f64  rel. err MPFR  rel. err Tamaas  t f64 [s]  t MPFR [s]  t Tamaas [s]")
    for p2, a, f, m, tm_, tf, tmp, tt, *_ in rows:
        print(f"{p2:.4f}  {a:.15f}  {abs(f - a) / a:.1e}       {abs(m - a) / a:.1e}        {abs(tm_ - a) / a:.1e}          {tf:.3f}      {tmp:.3f}       {tt:.3f}")

    p = np.array([r[0] for r in rows])
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    fine = np.linspace(1e-5, float(LOADS[-1]) * 1.02, 300)
    ax1.plot(fine, [westergaard_a(x) for x in fine], "k-", lw=1, label="Westergaard closed form")
    ax1.plot(p, [r[3] for r in rows], "o", color="tab:blue", label="periodic-contact (MPFR, verified)")
    ax1.plot(p, [r[4] for r in rows], "x", color="tab:red", ms=8, label=f"Tamaas PolonskyKeerRey, N = {n_tamaas}")
    ax1.set_xlabel("load per period P2 [units of E* L]")
    ax1.set_ylabel("contact half-width a/L [-]")
    ax1.set_title("Westergaard: load-size curve (D/L = 1/100)")
    ax1.legend(fontsize=8)
    floor = 1e-17
    for k, (name, style) in enumerate([("f64 collocation", "s-"), ("MPFR, verified", "o-"), (f"Tamaas, N = {n_tamaas}", "x-")]):
        err = [max(abs(r[2 + k] - r[1]) / r[1], floor) for r in rows]
        ax2.semilogy(p, err, style, label=name)
    ax2.axhline(np.finfo(float).eps, color="grey", lw=0.8, ls=":", label="f64 epsilon")
    ax2.set_xlabel("load per period P2 [units of E* L]")
    ax2.set_ylabel("|a - a_Westergaard| / a [-] (float64; 0 drawn at 1e-17)")
    ax2.set_title("relative error of the half-width")
    ax2.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
