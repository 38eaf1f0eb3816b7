"""Peer timings for the series job of the foundation issue, printed as JSON lines.

Job: f(x) = (sin x / x)^(1/2 + th), th symbolic, to N coefficients, and the reversion of
y = x f(x). Peers (routes taken from shared/peers/series_sympy.py and series_flint.py):
  sympy : sympy.polys.ring_series over QQ[th] (rs_sin, rs_log, rs_exp, rs_series_reversion)
  flint : python-flint, QQ[th] coefficients (fmpq_poly), Miller power recurrence + Lagrange inversion
  fmpq  : python-flint fmpq_series at th = 1/3 (exact QQ, FLINT's C series routines)
Each figure is the best of `repeat` runs. The x^7 reversion coefficient is printed as a stamp.

Fraction-field job (issue 14; ours: series/examples/frac_series.rs): coefficients in Q(a, b),
f = 1 + x/(a+b) + a x^2/(a-b) + (1+ab) x^3/(a^2+b) + O(x^N); 1/f by the recurrence
b_n = -sum_k f_k b_(n-k) and log f = integral(f' (1/f)) (the inverse recomputed inside, as ours
does), every coefficient reduced to lowest terms. Peers:
  fracflint : python-flint fmpz_mpoly pairs (num, den) over Z[a, b], reduced by FLINT's C
              multivariate gcd, Henrici's sum and product (FLINT's fmpz_mpoly_q, which python-flint
              0.9.0 does not wrap, reduces the same way)
  fracsympy : SymPy's rational function field field("a,b", QQ) (FracElement, reduced on every op)
Prints the times and the last coefficient of each result as numerator / denominator text.

Usage: python series_peers.py PEER N [repeat]
       python series_peers.py check OURS_JSONL PEERS_JSONL   (equality of the last coefficients)
"""
import json
import sys
import time


def best(repeat, f):
    t_best, out = float("inf"), None
    for _ in range(max(1, repeat)):
        t0 = time.perf_counter()
        out = f()
        t_best = min(t_best, time.perf_counter() - t0)
    return t_best, out


def sympy_job(n, repeat):
    from sympy.polys.domains import QQ
    from sympy.polys.ring_series import rs_exp, rs_log, rs_mul, rs_series_reversion, rs_sin
    from sympy.polys.rings import ring

    R, X, TH = ring("x,th", QQ)

    def series():
        sx = rs_sin(X, X, n + 1)
        q = R({(k - 1, j): c for (k, j), c in sx.terms()})
        return rs_exp((QQ(1, 2) + TH) * rs_log(q, X, n), X, n)

    ts, f = best(repeat, series)
    g = rs_mul(X, f, X, n)
    tr, rev = best(repeat, lambda: rs_series_reversion(g, X, n, X))
    c7 = sum(c * TH ** j for (k, j), c in rev.terms() if k == 7)
    return {"series_s": ts, "reversion_s": tr, "rev_x7": str(c7)}


def flint_job(n, repeat):
    from math import factorial

    from flint import fmpq, fmpq_poly

    gc = [fmpq((-1) ** (k // 2), factorial(k + 1)) if k % 2 == 0 else fmpq(0) for k in range(n)]
    alpha = fmpq_poly([fmpq(1, 2), 1])

    def miller(gc, alpha, m):
        f = [fmpq_poly([1])]
        a1 = alpha + 1
        for k in range(1, m):
            acc = fmpq_poly(0)
            for j in range(1, k + 1):
                if gc[j] != 0:
                    acc += (a1 * j - k) * (f[k - j] * gc[j])
            f.append(acc / k)
        return f

    ts, _ = best(repeat, lambda: miller(gc, alpha, n))

    def reversion():
        rev = [fmpq_poly(0)]
        for m in range(1, n):
            fn = miller(gc[:m], alpha * (-m), m)
            rev.append(fn[m - 1] / m)
        return rev

    tr, rev = best(repeat, reversion)
    return {"series_s": ts, "reversion_s": tr, "rev_x7": str(rev[7]) if n > 7 else ""}


def fmpq_job(n, repeat):
    from math import factorial

    from flint import ctx, fmpq, fmpq_series

    ctx.cap = n
    gc = [fmpq((-1) ** (k // 2), factorial(k + 1)) if k % 2 == 0 else fmpq(0) for k in range(n)]
    th = fmpq(1, 3)
    ts, f = best(repeat, lambda: ((fmpq(1, 2) + th) * fmpq_series(gc).log()).exp())
    y = fmpq_series([0] + f.coeffs()[: n - 1])
    tr, _ = best(repeat, lambda: y.reversion())
    return {"series_s": ts, "reversion_s": tr}


def frac_recurrences(f, one, add, mul, neg, scale_int, div_int, n):
    """1/f and log f of the series with coefficients f (f[0] = 1) through x^(n-1)."""

    def inverse():
        b = [one]
        for m in range(1, n):
            acc = None
            for k in range(1, min(m, len(f) - 1) + 1):
                t = mul(f[k], b[m - k])
                acc = t if acc is None else add(acc, t)
            b.append(neg(acc))
        return b

    def log():
        inv = inverse()
        df = [scale_int(f[k], k) for k in range(1, len(f))]  # f' through x^2
        out = [None] * n
        out[0] = scale_int(one, 0)
        for m in range(1, n):
            acc = None
            for i in range(min(m, len(df))):
                t = mul(df[i], inv[m - 1 - i])
                acc = t if acc is None else add(acc, t)
            out[m] = div_int(acc, m)
        return out

    return inverse, log


def fracflint_job(n, repeat):
    from flint import fmpz_mpoly_ctx

    ctx = fmpz_mpoly_ctx.get(("a", "b"), "lex")
    a, b = ctx.gens()
    one, zero = ctx.from_dict({(0, 0): 1}), ctx.from_dict({})

    def canon(num, den):
        if num.is_zero():
            return (zero, one)
        g = num.gcd(den)
        if not g.is_one():
            num, den = num / g, den / g
        if den.leading_coefficient() < 0:
            num, den = -num, -den
        return (num, den)

    def add(x, y):
        (n1, d1), (n2, d2) = x, y
        if n1.is_zero():
            return y
        if n2.is_zero():
            return x
        if d1 == d2:
            return canon(n1 + n2, d1)
        g = d1.gcd(d2)
        if g.is_one():
            return (n1 * d2 + n2 * d1, d1 * d2)
        e1, e2 = d1 / g, d2 / g
        t = n1 * e2 + n2 * e1
        if t.is_zero():
            return (zero, one)
        g2 = t.gcd(g)
        return (t / g2, (g / g2) * e1 * e2)

    def mul(x, y):
        (n1, d1), (n2, d2) = x, y
        if n1.is_zero() or n2.is_zero():
            return (zero, one)
        g1, g2 = n1.gcd(d2), n2.gcd(d1)
        return ((n1 / g1) * (n2 / g2), (d1 / g2) * (d2 / g1))

    f = [(one, one), canon(one, a + b), canon(a, a - b), canon(one + a * b, a * a + b)]
    inverse, log = frac_recurrences(
        f, (one, one), add, mul, lambda x: (-x[0], x[1]),
        lambda x, k: canon(x[0] * k, x[1]), lambda x, k: canon(x[0], x[1] * k), n,
    )
    ti, inv = best(repeat, inverse)
    tl, lg = best(repeat, log)
    return {"inv_s": ti, "log_s": tl, "inv_last": [str(inv[-1][0]), str(inv[-1][1])],
            "log_last": [str(lg[-1][0]), str(lg[-1][1])]}


def fracsympy_job(n, repeat):
    from sympy import QQ, field

    K, a, b = field("a,b", QQ)
    f = [K.one, 1 / (a + b), a / (a - b), (1 + a * b) / (a * a + b)]
    inverse, log = frac_recurrences(
        f, K.one, lambda x, y: x + y, lambda x, y: x * y, lambda x: -x,
        lambda x, k: x * k, lambda x, k: x / k, n,
    )
    ti, inv = best(repeat, inverse)
    tl, lg = best(repeat, log)
    return {"inv_s": ti, "log_s": tl, "inv_last": [str(inv[-1].numer), str(inv[-1].denom)],
            "log_last": [str(lg[-1].numer), str(lg[-1].denom)]}


def frac_check(ours_path, peers_path):
    """Each peer's last coefficients equal ours as rational functions: n_ours d_peer = n_peer d_ours
    in Q[a, b] (python-flint's fmpq_mpoly), every text parsed with exact rationals."""
    import re

    from flint import fmpq, fmpq_mpoly_ctx

    ctx = fmpq_mpoly_ctx.get(("a", "b"), "lex")
    env = {"a": ctx.gens()[0], "b": ctx.gens()[1], "Q": fmpq}

    def poly(text):
        text = text.replace("^", "**")
        text = re.sub(r"(?<!\*\*)(?<!\d)(\d+)", r"Q(\1)", text)
        return ctx.from_dict({}) + eval(text, {"__builtins__": {}}, env)

    def ours_frac(text):
        if text.startswith("(") and ")/(" in text:
            num, den = text[1:-1].split(")/(")
            return poly(num), poly(den)
        return poly(text), poly("1")

    ours = {d["N"]: d for d in map(json.loads, open(ours_path))}
    ok = True
    for p in map(json.loads, open(peers_path)):
        o = ours[p["N"]]
        for part in ("inv_last", "log_last"):
            on, od = ours_frac(o[part])
            pn, pd = poly(p[part][0]), poly(p[part][1])
            same = on * pd == pn * od and not od.is_zero() and not pd.is_zero()
            ok &= same
            print(f"{p['peer']} N = {p['N']} {part}: {'equal to ours' if same else 'DIFFERS from ours'}")
    return ok


if __name__ == "__main__":
    if sys.argv[1] == "check":
        sys.exit(0 if frac_check(sys.argv[2], sys.argv[3]) else 1)
    peer, n = sys.argv[1], int(sys.argv[2])
    repeat = int(sys.argv[3]) if len(sys.argv) > 3 else 3
    job = {"sympy": sympy_job, "flint": flint_job, "fmpq": fmpq_job, "fracflint": fracflint_job,
           "fracsympy": fracsympy_job}[peer]
    out = job(n, repeat)
    out.update({"peer": peer, "N": n})
    print(json.dumps(out), flush=True)
