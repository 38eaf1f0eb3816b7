"""Westergaard contact width with Tamaas PolonskyKeerRey (FFT BEM, basic_1d), one job per call.
After shared/peers/westergaard_tamaas.py: surface h = -D cos(2 pi x/L), E* = D = L = 1, mean
pressure pbar = (pi E* D/L) sin^2(pi a/L). Errors of the contact half-width against the closed form
a: counting contact nodes, and the sub-grid edge fit p^2 ~ (a - s) on the last 4 contact nodes.
Usage: python westergaard_tamaas.py A_OVER_L N REPEAT [TOL]   -> one JSON line (best time of
REPEAT solves; the model is built outside the timed region, as in the shared script).
"""
import json, math, sys, time
import numpy as np
import tamaas as tm

tm.set_log_level(tm.LogLevel.error)
L, D, Estar = 1.0, 1.0, 1.0


def exact_p(s, a, pbar):
    S2a = math.sin(math.pi * a / L) ** 2
    inside = np.clip(S2a - np.sin(np.pi * s / L) ** 2, 0, None)
    return 2 * pbar * np.cos(np.pi * s / L) / S2a * np.sqrt(inside)


def edge_fit(s, p):
    idx = np.where((p > 0) & (s > 0))[0]
    if len(idx) < 4:
        return float("nan")
    k = idx[np.argsort(s[idx])][-4:]
    A = np.vstack([s[k], np.ones_like(s[k])]).T
    c = np.linalg.lstsq(A, p[k] ** 2, rcond=None)[0]
    return -c[1] / c[0]


def run(N, a_over_L, tol):
    a = a_over_L * L
    pbar = math.pi * Estar * D / L * math.sin(math.pi * a / L) ** 2
    model = tm.ModelFactory.createModel(tm.model_type.basic_1d, [L], [N])
    model.E, model.nu = Estar, 0.0
    x = np.arange(N) * L / N
    surf = -D * np.cos(2 * np.pi * x / L)
    solver = tm.PolonskyKeerRey(model, surf, tol)
    solver.max_iter = 20000
    t0 = time.perf_counter()
    solver.solve(pbar)
    dt = time.perf_counter() - t0
    p = np.array(model.traction).reshape(-1)
    s = x - L / 2
    a_count = int(np.count_nonzero(p > 0)) * (L / N) / 2
    l2 = np.linalg.norm(p - exact_p(s, a, pbar)) / np.linalg.norm(exact_p(s, a, pbar))
    return dict(peer="tamaas", version=tm.__version__, aL=a_over_L, N=N, tol=tol, time_s=dt,
                err_count=abs(a_count - a) / a, err_fit=abs(edge_fit(s, p) - a) / a, l2_p=l2)


if __name__ == "__main__":
    aL, N, rep = float(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3])
    tol = float(sys.argv[4]) if len(sys.argv) > 4 else 1e-10
    print(json.dumps(min((run(N, aL, tol) for _ in range(rep)), key=lambda r: r["time_s"])))
