"""pytest tests of the Python module. They compare with the command line itself: the
binary `periodic-contact` of this repository (env PERIODIC_CONTACT_CLI, else target/debug or
target/release; `cargo build` makes it, `scripts/test --long` runs these after `cargo test`)."""

import json
import os
import subprocess
import tomllib
from decimal import Decimal
from fractions import Fraction
from math import comb
from pathlib import Path

import pytest

import periodic_contact as pc

ROOT = Path(__file__).resolve().parents[2]
SCENE = ROOT / "scenes" / "sliding_friction.toml"


def cli():
    env = os.environ.get("PERIODIC_CONTACT_CLI")
    candidates = [Path(env)] if env else [ROOT / "target" / d / "periodic-contact" for d in ("debug", "release")]
    for c in candidates:
        if c.exists():
            return str(c)
    raise AssertionError(f"no periodic-contact binary at {candidates}: run `cargo build` first")


def run_cli(*args):
    r = subprocess.run([cli(), *args], capture_output=True, text=True)
    return r.returncode, r.stdout, r.stderr


def cli_message(*args):
    code, _, err = run_cli(*args)
    assert code != 0
    assert err.startswith("error: "), err
    return code, err[len("error: "):].strip()


def bernoulli(n):
    """B_0 .. B_n by the recurrence sum_{k<m+1} C(m+1, k) B_k = 0 (B_1 = -1/2)."""
    b = [Fraction(1)]
    for m in range(1, n + 1):
        b.append(-sum(comb(m + 1, k) * b[k] for k in range(m)) / (m + 1))
    return b


def test_kernel_is_z_cot_z_by_bernoulli_numbers():
    # z cot z = sum_n (-1)^n 2^(2n) B_2n z^(2n) / (2n)!  (DLMF 4.19.6), computed here independently.
    part = pc.series("kernel", order=12)["kernel"]
    b = bernoulli(12)
    fact = lambda k: 1 if k == 0 else k * fact(k - 1)
    want = {2 * n: Fraction((-1) ** n * 4**n) * b[2 * n] / fact(2 * n) for n in range(7)}
    assert part.coefficients == want
    assert all(isinstance(c, Fraction) for c in part.coefficients.values())
    assert part.variable == "z" and part.order == 12


def test_sliding_series_at_theta_one_tenth_is_exact():
    s = pc.series("sliding", order=12, theta="1/10")
    assert list(s)[:2] == ["l_over_ls", "rbar_minus_rbar_s"]
    l = s["l_over_ls"].coefficients
    # [Lambda^2] = theta^2/3 - 1/12, [Lambda^4] = 73/270 theta^4 - 41/540 theta^2 + 1/480 (paper [3.11]).
    t = Fraction(1, 10)
    assert l[0] == 1
    assert l[2] == t**2 / 3 - Fraction(1, 12) == Fraction(-2, 25)
    assert l[4] == Fraction(73, 270) * t**4 - Fraction(41, 540) * t**2 + Fraction(1, 480)
    assert max(l) == 12 and all(isinstance(c, Fraction) for c in l.values())
    # T stays a symbol: SymPy-readable strings.
    r = s["rbar_minus_rbar_s"]
    assert "T" in r.symbols and isinstance(r.coefficients[2], str) and "^" not in r.coefficients[2]
    # The same as the CLI's JSON.
    code, out, _ = run_cli("series", "sliding", "--order", "12", "--theta", "1/10", "--format", "json")
    assert code == 0
    cli_parts = {p["object"]: p for p in json.loads(out)["parts"]}
    for name, part in s.items():
        texts = {c["power"]: c["text"].replace("^", "**") for c in cli_parts[name]["coefficients"]}
        assert {k: str(v) for k, v in part.coefficients.items()} == texts


def test_symbolic_coefficients_read_back_in_sympy():
    sympy = pytest.importorskip("sympy")
    w = pc.series("weight", order=2)["weight"]
    xh, theta = sympy.symbols("xh theta")
    assert sympy.simplify(w.sympy()[2] - (-xh**2 / 6 - sympy.Rational(2, 3) * theta * xh - sympy.Rational(1, 6))) == 0
    # Problem 2 in eps, B, S: S must stay a Symbol, not SymPy's singleton registry.
    a = pc.series("adhesion", order=4)["load_c"]
    exprs = a.sympy()
    assert all(isinstance(e, sympy.Expr) for e in exprs.values())
    assert {str(x) for e in exprs.values() for x in e.free_symbols} <= set(a.symbols)


def test_options_accept_lists_and_refuse_floats():
    q = pc.series("sliding", order=4, shape="polynomial", coefficients=[0, 0, 1, 0, "1/10"], theta=0, rbar_s=0)
    assert "l_over_ls" in q
    with pytest.raises(pc.InputError, match="not a float"):
        pc.series("sliding", order=4, theta=0.1)


def test_solve_reproduces_the_cli_json():
    code, out, _ = run_cli("solve", str(SCENE), "--json")
    assert code == 0
    want = json.loads(out)
    assert pc.solve(SCENE).to_dict() == want
    assert pc.solve(str(SCENE)).to_dict() == want
    text = SCENE.read_text()
    assert pc.solve(text).to_dict() == want
    with open(SCENE, "rb") as f:
        as_dict = tomllib.load(f)
    assert pc.solve(as_dict).to_dict() == want
    assert pc.solve(text).keys() == list(want), "same keys in the same order"


def test_finite_friction_scene_gives_the_stick_half_width():
    """Issue 32: the single punch with mu = 1/2 at nu = 0, c/a = 0.5219(1) by boundary elements."""
    d = pc.solve(ROOT / "scenes" / "adhesion_friction_single.toml").to_dict()
    c, a = float(d["stick_half_width"]), float(d["half_width"])
    assert abs(c / a - 0.5219) <= 1e-4 + 10 ** -float(d["accuracy"]["stick"])
    assert d["provenance"]["method"] == "f64" and d["friction"] == "1/2"


def test_solve_flags_are_the_cli_flags():
    code, out, _ = run_cli("solve", str(SCENE), "--json", "--method", "f64", "--digits", "12")
    assert code == 0
    assert pc.solve(SCENE, method="f64", digits=12).to_dict() == json.loads(out)


def test_scene_errors_carry_the_cli_message(tmp_path):
    bad = SCENE.read_text().replace('friction = "0.3"', 'friction = "-1"')
    path = tmp_path / "bad.toml"
    path.write_text(bad)
    code, message = cli_message("solve", str(path))
    assert code == 2
    with pytest.raises(pc.SceneError) as e:
        pc.solve(bad)
    assert str(e.value) == message
    assert isinstance(e.value, pc.InputError) and isinstance(e.value, pc.Error)
    with pytest.raises(pc.SceneError):
        pc.solve({"problem": {"kind": "rolling"}})


def test_option_errors_carry_the_cli_message():
    code, message = cli_message("solve", str(SCENE), "--digits", "0")
    assert code == 2
    with pytest.raises(pc.InputError) as e:
        pc.solve(SCENE, digits=0)
    assert str(e.value) == message and not isinstance(e.value, pc.SceneError)
    code, message = cli_message("series", "sliding", "--order", "4", "--theta", "1/2")
    with pytest.raises(pc.InputError) as e:
        pc.series("sliding", order=4, theta="1/2")
    assert str(e.value) == message == "invalid --theta = 1/2: must satisfy |theta| < 1/2"


def test_no_solution_carries_the_cli_message(tmp_path):
    # The sinusoid carries at most pi E* D = 0.0314 per period (Westergaard): P2 = 1 has no contact.
    text = (ROOT / "scenes" / "westergaard_sinusoid.toml").read_text().replace('normal_load = "0.005"', 'normal_load = "1"')
    text = text.split("[sweep]")[0]
    path = tmp_path / "heavy.toml"
    path.write_text(text)
    code, message = cli_message("solve", str(path), "--method", "f64")
    assert code == 1
    with pytest.raises(pc.Error) as e:
        pc.solve(text, method="f64")
    assert str(e.value) == message
    assert type(e.value) in (pc.NoSolutionError, pc.NotPhysicalError, pc.NoConvergenceError)
    assert not isinstance(e.value, pc.InputError)


# Every object and route the CLI derives, with the CLI's flags: (object, order, options).
ROUTES = [
    ("kernel", 12, {}),
    ("weight", 6, {"theta": "1/10", "xh": "1/2"}),
    ("jacobi", 8, {}),
    ("sliding", 8, {}),
    ("sliding", 6, {"shape": "sinusoidal", "theta": "1/10"}),
    ("sliding", 6, {"convention": "periodic"}),
    ("sliding", 4, {"shape": "polynomial", "coefficients": "0,0,1,0,1/10", "theta": "0", "rbar_s": "0"}),
    ("adhesion", 6, {}),
    ("adhesion", 6, {"nu": "3/10"}),
    ("adhesion", 4, {"coefficients": "0,0,1,0,1/10"}),
    ("adhesion", 30, {"nu": "1/4"}),
    ("adhesion", 8, {"nu": "1/4", "digits": "40"}),
    ("loading-law", 6, {"nu": "3/10", "ratio": "1/5"}),
]


@pytest.mark.parametrize("obj,order,options", ROUTES)
def test_every_object_and_route_equals_the_cli(obj, order, options):
    args = ["series", obj, "--order", str(order), "--format", "json"]
    for k, v in options.items():
        args += [f"--{k.replace('_', '-')}", v]
    code, out, err = run_cli(*args)
    assert code == 0, err
    want = json.loads(out)
    s = pc.series(obj, order=order, **options)
    assert s.to_dict() == want
    parts = want["parts"] if "parts" in want else [want]
    assert list(s) == [p["object"] for p in parts]
    for p in parts:
        part = s[p["object"]]
        for c in p["coefficients"]:
            k = int(c["power"])
            if "text" in c:
                assert str(part.coefficients[k]) == c["text"].replace("^", "**")
                assert isinstance(part.coefficients[k], (Fraction, pc.Expr))
            else:
                assert part.coefficients[k] == Decimal(c["value"])
                assert part.digits[k] == float(c["digits"])


def test_adhesion_at_order_30_is_the_numerical_route():
    s = pc.series("adhesion", order=30, nu="1/4")
    assert s.route == "numeric"
    c = s["load_c"].coefficients
    assert isinstance(c[0], Decimal) and c[0] == 1 and max(c) <= 30


def test_loading_law_carries_its_mode():
    s = pc.series("loading-law", order=4, nu="3/10", ratio="1/5")
    assert s.mode is not None and s.mode == s.to_dict()["mode"]
    assert isinstance(s["c_over_l"].coefficients[0], Decimal)


def test_adhesion_coefficients_sympify():
    sympy = pytest.importorskip("sympy")
    part = pc.series("adhesion", order=4)["load_c"]
    c = next(v for v in part.coefficients.values() if isinstance(v, pc.Expr))
    e = sympy.sympify(c)
    assert e == c.sympy()
    assert all(isinstance(x, sympy.Symbol) for x in e.free_symbols)
    assert {str(x) for x in e.free_symbols} <= set(part.symbols)


def test_solution_values_are_numbers_and_arrays():
    np = pytest.importorskip("numpy")
    code, out, _ = run_cli("solve", str(SCENE), "--json")
    want = json.loads(out)
    r = pc.solve(SCENE)
    assert isinstance(r.P2, float) and r.P2 == float(want["P2"])
    assert r.text("P2") == want["P2"] and r.decimal("P2") == Decimal(want["P2"])
    assert isinstance(r.digits_verified, float) and r.digits_verified == float(want["digits_verified"])
    assert r.lambda_ == float(want["lambda"])
    assert isinstance(r.pressure.p, np.ndarray)
    assert list(r.pressure.p) == [float(p["p"]) for p in want["pressure"]]
    assert r.provenance.method == "mpfr" and r.accuracy.P2 == float(want["accuracy"]["P2"])
    with pytest.raises(AttributeError):
        r.no_such_key


def test_invalid_scene_raises_the_modules_own_exception():
    with pytest.raises(pc.SceneError):
        pc.solve("[problem]\nkind = 3\n")
    with pytest.raises(pc.InputError):
        pc.solve("/no/such/scene.toml")
    with pytest.raises(pc.InputError):
        pc.series("adhesion", order=30, nu="7/10")
    with pytest.raises(pc.InputError):
        pc.series("no-such-object", order=3)


def test_the_namespace_is_clean():
    public = {n for n in dir(pc) if not n.startswith("_")}
    assert not public & {"json", "os", "re", "copy", "dataclass", "field", "Any", "Dict"}, public
    assert set(pc.__all__) <= public


def test_ctrl_c_stops_a_long_solve(tmp_path):
    # A 1000-digit solve takes far longer than the 1.5 s before SIGINT; the interpreter must leave
    # the call with KeyboardInterrupt at once.
    script = tmp_path / "long.py"
    script.write_text(
        "import signal, sys, time, periodic_contact as pc\n"
        # A shell that starts the tests in the background (`nohup ... &`) ignores SIGINT, and the
        # child inherits that: restore Python's own handler so the test measures the module.
        "signal.signal(signal.SIGINT, signal.default_int_handler)\n"
        "print('started', flush=True)\n"
        "t = time.time()\n"
        "try:\n"
        f"    pc.solve({str(SCENE)!r}, digits=1000)\n"
        "    print('finished')\n"
        "except KeyboardInterrupt:\n"
        "    print('interrupted after %.1f s' % (time.time() - t))\n"
        "    sys.exit(130)\n"
    )
    import signal
    import sys
    import time

    p = subprocess.Popen([sys.executable, str(script)], stdout=subprocess.PIPE, text=True)
    assert p.stdout.readline().strip() == "started"
    time.sleep(1.5)
    p.send_signal(signal.SIGINT)
    out, _ = p.communicate(timeout=20)
    assert p.returncode == 130 and out.startswith("interrupted"), out
