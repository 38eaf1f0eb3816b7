"""Driver of bench/peers/solvers: runs this project and the peers (mpmath, Tamaas) on the same jobs,
interleaved (ours right before the peer, each job in its own process) so both see the same machine
load, and prints the ratios. Called by bench/peers/solvers with: OURS_BINARY PYTHON [--quick|--full].
"""
import itertools
import json
import math
import os
import platform
import subprocess
import sys
import time

from mpmath import mp, mpf

here = os.path.dirname(os.path.abspath(__file__))
ours_bin, py = sys.argv[1], sys.argv[2]
mode = sys.argv[3] if len(sys.argv) > 3 else ""
quick, full = mode == "--quick", mode == "--full"


def run(cmd):
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout.strip().splitlines()
    return json.loads(out[-1])


def ours(*args):
    return run([ours_bin, *map(str, args)])


def peer(script, *args):
    return run([py, os.path.join(here, script), *map(str, args)])


print(f"machine: {platform.machine()}, {os.cpu_count()} cores, {platform.system()} {platform.release()}, "
      f"python {platform.python_version()}")

# ---------------------------------------------------------------------------------------------
# 1. Problem 1 at 30 digits: mpmath implementation of the same method vs ours (MPFR, in-process).
# ---------------------------------------------------------------------------------------------
# (name, nu, E*, k, L, P2, mu, tau0, cW); periodic parabola g = k x^2.
CASES = [
    ("frictionless", "3/10", "1", "1", "1", "1/100", "0", "0", "0"),
    ("frictionless", "3/10", "1", "1", "1", "3/20", "0", "0", "0"),
    ("friction", "3/10", "1", "1", "1", "1/100", "3/10", "0", "0"),
    ("wear", "3/10", "1", "1", "1", "1/100", "0", "0", "1/5"),
    ("friction+tau0", "3/10", "1", "1", "1", "1/100", "3/10", "1/100", "0"),
    ("friction+wear", "3/10", "1", "1", "1", "3/20", "3/10", "0", "1/5"),
]
DIGITS = [30] if quick else [30, 60]
REP = 3
mp.dps = 100
print()
print("1. Problem 1, periodic parabola (E* = k = L = 1, nu = 0.3): exact reduction [2.13]-[2.14], Gauss-Jacobi")
print("   ours: MPFR, in-process time of one sliding::solve_at call (no verification run, no physicality")
print("   checks, rule cache cleared); mpmath: the same method in Python (bench/peers/sliding_mpmath.py).")
print(f"   Best of {REP} inside each process. 'agree' = digits of agreement (scales as in sliding::verify).")
print(f"{'case':14} {'P2':>5} {'lambda':>7} {'dig':>4} {'n':>4} {'mpmath s':>9} {'ours s':>9} {'mpmath/ours':>11} {'agree':>6}")
ratios1 = []
agree_ok = True
for digits in DIGITS:
    for name, *args in CASES:
        o = ours("sliding", *args, digits, REP)
        m = peer("sliding_mpmath.py", *args, digits, REP)
        l = (mpf(o["a"]) + mpf(o["b"])) / 2
        p2 = mpf(o["P2"])
        pmax = max(abs(mpf(v)) for v in o["p"])
        k = mpf(1)
        agree = []
        for key, scale in (("a", l), ("b", l), ("c", l), ("P1", p2), ("P2", p2), ("F_def", k * l * p2)):
            d = abs(mpf(o[key]) - mpf(m[key])) / scale
            agree.append(-float(mp.log10(d)) if d else 80.0)
        for po, pm in zip(o["p"], m["p"]):
            d = abs(mpf(po) - mpf(pm)) / pmax
            agree.append(-float(mp.log10(d)) if d else 80.0)
        r = m["time_s"] / o["time_s"]
        ratios1.append(r)
        agree_ok &= min(agree) >= digits
        assert o["nodes"] == m["nodes"], (o["nodes"], m["nodes"])
        print(f"{name:14} {args[4]:>5} {float(mpf(o['lambda'])):7.3f} {digits:4d} {o['nodes']:4d} "
              f"{m['time_s']:9.4f} {o['time_s']:9.4f} {r:11.1f} {min(agree):6.1f}", flush=True)
print(f"   mpmath backend: {m['backend']}; ratio range {min(ratios1):.1f}x .. {max(ratios1):.1f}x, "
      f"geometric mean {math.exp(sum(map(math.log, ratios1)) / len(ratios1)):.1f}x")
print(f"   every case agrees to at least the requested digits: {'yes' if agree_ok else 'NO'}")

# Whole processes, for reference: the CLI on scenes/sliding_friction.toml (the "friction" case above)
# runs the solver twice (main run + verification run at 32 more bits and 1.5x the nodes) and parses
# the scene; the mpmath script solves once. Wall time of the process, best of 3, interleaved.
cli = os.path.join(os.path.dirname(ours_bin), "..", "periodic-contact")
scene = os.path.join(here, "..", "..", "scenes", "sliding_friction.toml")
t_cli, t_mpm = [], []
for _ in range(3):
    t0 = time.perf_counter()
    subprocess.run([cli, "solve", scene, "--json", "--digits", "30"], check=True, capture_output=True)
    t_cli.append(time.perf_counter() - t0)
    t0 = time.perf_counter()
    peer("sliding_mpmath.py", "3/10", "1", "1", "1", "1/100", "3/10", "0", "0", 30, 1)
    t_mpm.append(time.perf_counter() - t0)
print(f"   whole processes, friction case, 30 digits: mpmath script (one solve, Python start-up and imports)")
print(f"   {min(t_mpm):.3f} s; `periodic-contact solve scenes/sliding_friction.toml --json --digits 30` (solve +")
print(f"   verification run) {min(t_cli):.3f} s: mpmath/ours {min(t_mpm) / min(t_cli):.1f}x")

# ---------------------------------------------------------------------------------------------
# 2. Westergaard contact width: Tamaas PolonskyKeerRey vs ours (f64 collocation, MPFR).
# ---------------------------------------------------------------------------------------------
TAMAAS_N = [2**k for k in range(8, 19 if full else (15 if quick else 17), 2)]
F64_N = [2, 3, 4, 6, 8, 12, 16, 24, 32]
# As in shared/peers/out_tamaas.txt. tol 1e-8 is about 2x faster with the same error up to N = 2^14,
# but at N = 2^16 (a/L = 0.05) its error grows from 2.6e-5 to 4.7e-5: it is not converged there.
TAMAAS_TOL = 1e-10
MPFR_D = [8, 16, 30, 60, 100] + ([] if quick else [200, 300])
print()
print("2. Westergaard contact width, sinusoid, frictionless, E* = D = L = 1; error = |a - a_exact|/a_exact.")
print(f"   Tamaas 2.9.0 PolonskyKeerRey (cpp backend, 1 thread), tol {TAMAAS_TOL:g}; its error from the sub-grid")
print("   edge fit (its better measure; 'count' = counting contact nodes); time of solver.solve() only,")
print("   best of 3 (1 at N >= 2^16).")
print("   ours f64: collocation with n nodes, in-process time of solve_sliding_f64, which includes its")
print("   built-in check run (n + max(8, n/4) nodes); best of 5. ours MPFR: one solve_at at the digits")
print("   shown (no verification run), rule cache cleared, best of 1-2. Runs interleaved per a/L.")
summary = []
for aL in (0.05, 0.25):
    tam, f64, mpfr = [], [], []
    for N, n, d in itertools.zip_longest(TAMAAS_N, F64_N, MPFR_D):
        if n is not None:
            f64.append(ours("westergaard-f64", aL, n, 5))
        if N is not None:
            tam.append(peer("westergaard_tamaas.py", aL, N, 3 if N < 2**16 else 1, TAMAAS_TOL))
        if d is not None:
            mpfr.append(ours("westergaard-mpfr", aL, d, 2 if d <= 100 else 1))
    print()
    print(f"a/L = {aL}")
    print(f"  {'Tamaas N':>9} {'time s':>9} {'err fit':>9} {'err count':>9}")
    for t in tam:
        print(f"  {t['N']:9d} {t['time_s']:9.4f} {t['err_fit']:9.2e} {t['err_count']:9.2e}")
    print(f"  {'ours f64 n':>10} {'time s':>9} {'err':>9}        {'ours MPFR digits':>16} {'nodes':>5} {'time s':>9} {'err':>9}")
    for x, y in itertools.zip_longest(f64, mpfr):
        left = f"  {x['n']:10d} {x['time_s']:9.2e} {10**x['log10_err']:9.1e}" if x else " " * 32
        right = f"        {y['digits']:16d} {y['nodes']:5d} {y['time_s']:9.3f}   1e{y['log10_err']:.0f}" if y else ""
        print(left + right)
    best = min(tam, key=lambda t: t["err_fit"])
    e_star, t_star = best["err_fit"], best["time_s"]
    print(f"  (a) Tamaas's best error {e_star:.2e} (N = {best['N']}, {t_star:.3f} s). Time to reach it:")
    for label, runs in (("ours f64", f64), ("ours MPFR", mpfr)):
        ok = [r for r in runs if 10 ** r["log10_err"] <= e_star]
        if ok:
            r = min(ok, key=lambda r: r["time_s"])
            what = f"n = {r['n']}" if "n" in r else f"{r['digits']} digits"
            print(f"      {label:9}: {r['time_s']:.2e} s ({what}, err {10**r['log10_err']:.1e}): "
                  f"Tamaas/ours = {t_star / r['time_s']:.3g}x")
            summary.append((aL, "a", label, t_star / r["time_s"]))
    print("  (b) Equal time: the error each reaches within Tamaas's time at each N")
    print(f"      {'N':>7} {'time s':>8} {'Tamaas err':>10} {'f64 err':>16} {'MPFR err':>20}")
    for t in tam:
        cols = []
        for runs in (f64, mpfr):
            ok = [r for r in runs if r["time_s"] <= t["time_s"]]
            if ok:
                r = min(ok, key=lambda r: r["log10_err"])
                if "n" in r:
                    cols.append(f"{10 ** r['log10_err']:.1e} (n={r['n']})")
                else:
                    cols.append(f"1e{r['log10_err']:.0f} ({r['digits']} dig)")
            else:
                cols.append("slower")
        print(f"      {t['N']:7d} {t['time_s']:8.4f} {t['err_fit']:10.2e} {cols[0]:>16} {cols[1]:>20}")
print()
print("Summary (a): Tamaas time for its best error / our time for the same error:")
for aL, _, label, r in summary:
    print(f"  a/L = {aL}: {label}: {r:.3g}x")
