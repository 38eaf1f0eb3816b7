"""periodic-contact from Python: exact series and verified solutions of the periodic contact
problem (Soldatenkov 2013), the Rust library through PyO3.

    import periodic_contact as pc
    s = pc.series("sliding", order=12, theta="1/10")
    s["l_over_ls"].coefficients[2]        # _Fraction(-2, 25): l/l_s = 1 - 2/25 Lambda^2 + ...
    r = pc.solve("scenes/sliding_friction.toml")
    r.P2, r.digits_verified               # Python numbers (float); r.text("P2") the exact decimal
    r.pressure.p                          # numpy array of the pressure at the scene's points
    r.to_dict()                           # the JSON of `periodic-contact solve SCENE --json`

Errors are typed (`pc.InputError`, its subclass `pc.SceneError`, `pc.NoSolutionError`,
`pc.NotPhysicalError`, `pc.NoConvergenceError`, `pc.SeriesError`, all subclasses of `pc.Error`)
and carry the command line's message (what `periodic-contact` prints after ``error: ``).
Long computations release the GIL and stop on Ctrl-C (KeyboardInterrupt).
"""

from __future__ import annotations

import copy as _copy
import json as _json
import os as _os
import re as _re
from dataclasses import dataclass as _dataclass, field as _field
from collections.abc import Mapping as _Mapping
from decimal import Decimal as _Decimal
from fractions import Fraction as _Fraction

from . import _native
from ._native import (
    Error,
    InputError,
    NoConvergenceError,
    NoSolutionError,
    NotPhysicalError,
    SceneError,
    SeriesError,
)

__all__ = [
    "series",
    "solve",
    "Series",
    "Part",
    "Expr",
    "Solution",
    "Points",
    "to_toml",
    "Error",
    "InputError",
    "SceneError",
    "NoSolutionError",
    "NotPhysicalError",
    "NoConvergenceError",
    "SeriesError",
]

__version__ = _native.version()

_RATIONAL = _re.compile(r"^-?\d+(/\d+)?$")
_INTEGER = _re.compile(r"^-?\d+$")
_DECIMAL = _re.compile(r"^-?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")


class Expr(str):
    """A coefficient that is not a rational number: its text (``**`` powers, SymPy syntax) with the
    symbols it is written in. ``.sympy()`` (or ``sympy.sympify(expr)``) gives the SymPy
    expression with every name an explicit ``sympy.Symbol``: ``S``, ``B``, ``T`` stay symbols
    (plain ``sympify`` of the text would read ``S`` as SymPy's singleton registry)."""

    symbols: list[str]

    def __new__(cls, text: str, symbols: list[str]):
        obj = super().__new__(cls, text)
        obj.symbols = list(symbols)
        return obj

    def sympy(self):
        import sympy

        names = {name: sympy.Symbol(name) for name in self.symbols}
        return sympy.parse_expr(str(self), local_dict=names)

    def _sympy_(self):  # read by sympy.sympify
        return self.sympy()


def _coefficient(text: str, symbols: list[str]) -> "Fraction | Expr | Decimal":
    """A rational coefficient as a Fraction; any other as an :class:`Expr` in ``symbols``."""
    t = text.strip()
    if _RATIONAL.match(t):
        return _Fraction(t)
    return Expr(t.replace("^", "**"), symbols)


@_dataclass
class Part:
    """One derived object: coefficients by power of its variable.

    ``coefficients[k]`` is the coefficient of ``variable**k`` (only the non-zero ones are listed;
    every power through ``order`` is known, so a missing power below it is exactly 0). The exact
    route gives a ``Fraction`` when rational, else an :class:`Expr` in the symbols ``symbols``
    (``latex[k]`` its LaTeX); the numerical routes (``adhesion`` at a given ``nu`` beyond order 24
    or with ``digits``, ``loading-law``) give a ``Decimal`` whose ``digits[k]`` significant digits
    are verified by a second run.
    """

    object: str
    variable: str
    order: int
    symbols: list[str]
    coefficients: dict[int, "Fraction | Expr | Decimal"]
    latex: dict[int, str] = _field(default_factory=dict)
    digits: dict[int, float] = _field(default_factory=dict)
    formula: str = ""
    notes: list[str] = _field(default_factory=list)

    def sympy(self) -> dict[int, object]:
        """The coefficients as SymPy numbers and expressions, every symbol an explicit
        ``sympy.Symbol``. Needs sympy."""
        import sympy

        out = {}
        for k, c in self.coefficients.items():
            if isinstance(c, _Fraction):
                out[k] = sympy.Rational(c.numerator, c.denominator)
            elif isinstance(c, _Decimal):
                out[k] = sympy.Float(str(c), max(15, len(c.as_tuple().digits)))
            else:
                out[k] = c.sympy()
        return out


class Series(dict):
    """What :func:`series` returns: ``{part name: Part}`` in the order the command line prints
    them, with the whole answer as attributes: ``route`` (``exact`` or ``numeric``), ``mode`` (the
    loading law's homogeneous mode, a dict) and ``to_dict()``, the JSON of ``periodic-contact
    series OBJECT ... --format json``."""

    def __init__(self, data: _Mapping[str, object], parts: list[Part]):
        super().__init__((p.object, p) for p in parts)
        self._data = data

    @property
    def route(self) -> str:
        return self._data.get("route", "exact")

    @property
    def mode(self) -> dict[str, object] | None:
        return self._data.get("mode")

    def to_dict(self) -> dict[str, object]:
        return _copy.deepcopy(self._data)


def _part(v: _Mapping[str, object], order: int) -> Part:
    symbols = list(v.get("symbols", []))
    coeffs: dict[int, "Fraction | Expr | Decimal"] = {}
    latex: dict[int, str] = {}
    digits: dict[int, float] = {}
    for c in v.get("coefficients", []):
        k = int(c["power"])
        if "text" in c:
            coeffs[k] = _coefficient(c["text"], symbols)
            latex[k] = c.get("latex", "")
        elif "value" in c:
            coeffs[k] = _Decimal(c["value"])
            if c.get("digits") is not None:
                digits[k] = float(c["digits"])
        else:
            raise SeriesError(f"coefficient {c!r} of {v.get('object')!r} has neither text nor value")
    return Part(
        object=v["object"],
        variable=v.get("variable", ""),
        order=int(v.get("order", order)),
        symbols=symbols,
        coefficients=coeffs,
        latex=latex,
        digits=digits,
        formula=v.get("formula", ""),
        notes=list(v.get("notes", [])),
    )


def series(object: str, order: int = 12, **options: object) -> Series:
    """Derives ``object`` through power ``order`` as ``periodic-contact series OBJECT`` does, every
    object and route: ``kernel``, ``weight``, ``jacobi``, ``sliding``, ``adhesion`` (exact in eps,
    B, S; with ``nu`` beyond order 24 or with ``digits``, the numerical route), ``loading-law``
    (numerical, with its ``mode``).

    ``options``: the command's flags without dashes, values exact as text or integers
    (``theta="1/10"``, ``T="1/20"``, ``xh=0``, ``nu="3/10"``, ``digits=40``, ``ratio="1/5"``,
    ``shape="sinusoidal"``, ``coefficients="0,0,1,0,1/10"`` or a list, ``degree=4``,
    ``rbar_s="1/6"``, ``convention="periodic"``). Floats are refused: give exact values.
    """
    opts = []
    for key, value in options.items():
        if isinstance(value, float):
            raise InputError(f"invalid {key} = {value!r}: give an exact value as text (e.g. \"1/10\"), not a float")
        if isinstance(value, (list, tuple)):
            value = ",".join(str(x) for x in value)
        opts.append((key, str(value)))
    if isinstance(order, bool) or not isinstance(order, int) or not 0 <= order < 2**31:
        raise InputError(f"invalid order = {order!r}: must be a non-negative integer")
    v = _json.loads(_native.series_json(object, order, opts))
    parts = v["parts"] if "parts" in v else [v]
    return Series(v, [_part(p, int(v.get("order", order))) for p in parts])


def _number(text: str) -> "int | float | Fraction | str":
    t = text.strip()
    if _INTEGER.match(t):
        return int(t)
    if _DECIMAL.match(t):
        return float(t)
    if _RATIONAL.match(t):
        return _Fraction(t)
    return text


def _value(v: object) -> object:
    if isinstance(v, str):
        return _number(v)
    if isinstance(v, list):
        if v and all(isinstance(x, _Mapping) for x in v) and len({tuple(x) for x in v}) == 1:
            return Points(v)
        return [_value(x) for x in v]
    if isinstance(v, _Mapping):
        return Solution(v)
    return v


class Points:
    """Values at points (a JSON list of records with the same keys): each key an attribute
    holding a numpy array of floats (``pressure.x``, ``pressure.p``), ``len()``, iteration over
    the records (each a :class:`Solution`), ``text(key)`` the exact decimal strings."""

    def __init__(self, records: list[_Mapping[str, object]]):
        self._records = list(records)
        self._keys = list(records[0]) if records else []

    def __len__(self) -> int:
        return len(self._records)

    def __iter__(self):
        return (Solution(r) for r in self._records)

    def __getitem__(self, i: int) -> "Solution":
        return Solution(self._records[i])

    def keys(self) -> list[str]:
        return list(self._keys)

    def text(self, key: str) -> list[str | None]:
        return [r.get(key) for r in self._records]

    def __getattr__(self, key: str):
        if key.startswith("_") or key not in self._keys:
            raise AttributeError(f"no values {key!r} at these points (there are: {', '.join(self._keys)})")
        import numpy

        return numpy.array(
            [float(x) if isinstance(x, str) and _DECIMAL.match(x.strip()) else float("nan") for x in self.text(key)]
        )

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._keys))

    def __repr__(self) -> str:
        return f"Points({len(self)} points: {', '.join(self._keys)})"


class Solution:
    """A solved scene: every key of ``periodic-contact solve SCENE --json`` as an attribute, its
    value a Python number (``P2``, ``a``, ``digits_verified``: float; integers as int; exact
    ratios as Fraction), a :class:`Points` for values at points (``pressure``, ``points``), a
    nested :class:`Solution` for a table (``accuracy``, ``provenance``, ``choice``), ``None`` for
    null. ``text(key)`` gives the printed decimal string (every digit of it holds the stated
    accuracy), ``decimal(key)`` the same as a ``Decimal``, ``to_dict()`` the JSON as the command
    line prints it, ``keys()`` the keys. ``lambda`` is also ``lambda_``."""

    def __init__(self, data: _Mapping[str, object]):
        self._data = data

    def keys(self) -> list[str]:
        return list(self._data)

    def to_dict(self) -> dict[str, object]:
        return _copy.deepcopy(dict(self._data))

    def text(self, key: str) -> str | None:
        v = self._data[key]
        if v is not None and not isinstance(v, str):
            raise TypeError(f"{key!r} is not a single value")
        return v

    def decimal(self, key: str) -> Decimal | None:
        t = self.text(key)
        return None if t is None else _Decimal(t)

    def __getitem__(self, key: str) -> object:
        return _value(self._data[key])

    def __contains__(self, key: str) -> bool:
        return key in self._data

    def __getattr__(self, key: str) -> object:
        if key.startswith("_"):
            raise AttributeError(key)
        name = "lambda" if key == "lambda_" else key
        if name not in self._data:
            raise AttributeError(f"no key {key!r} in this answer (keys: {', '.join(self._data)})")
        return _value(self._data[name])

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._data))

    def __repr__(self) -> str:
        shown = [f"{k}={self._data[k]}" for k in ("problem", "P2", "l", "half_width", "digits_verified") if k in self._data]
        return f"Solution({', '.join(shown)})"


def _toml_value(v: object) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, _Fraction):
        return _json.dumps(str(v))
    if isinstance(v, float):
        return repr(v)
    if isinstance(v, str):
        return _json.dumps(v)  # a JSON string is a valid TOML basic string
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_toml_value(x) for x in v) + "]"
    raise InputError(f"invalid scene value {v!r}: must be a string, number, boolean or list")


def to_toml(scene: _Mapping[str, object]) -> str:
    """A scene dict ``{"problem": {"kind": "sliding"}, "material": {...}, ...}`` as TOML text
    (tables of scalars and lists, the layout of ``scenes/*.toml``)."""
    lines = []
    for table, body in scene.items():
        if not isinstance(body, _Mapping):
            raise SceneError(f"invalid scene key {table} = {body!r}: every top-level key is a table (a dict)")
        lines.append(f"[{table}]")
        for key, value in body.items():
            lines.append(f"{key} = {_toml_value(value)}")
    return "\n".join(lines) + "\n"


def solve(
    scene: "str | _os.PathLike[str] | _Mapping[str, object]",
    *,
    digits: int | None = None,
    method: str | None = None,
    order: int | None = None,
    convention: str | None = None,
) -> Solution:
    """Solves a scene as ``periodic-contact solve SCENE --json`` does; returns a :class:`Solution`
    (``to_dict()`` is that JSON).

    ``scene``: TOML text, a path to a scene file (``pathlib.Path``, or a one-line string ending in
    ``.toml``), or a dict of tables (see :func:`to_toml`). ``digits``, ``method`` (``mpfr``,
    ``f64``, ``series``, ``pade``), ``order`` (series order) and ``convention`` (``paper``,
    ``periodic``) are the flags of ``solve``; ``None`` keeps the scene's own (or the default).
    """
    if isinstance(scene, _Mapping):
        text = to_toml(scene)
    elif isinstance(scene, _os.PathLike) or (isinstance(scene, str) and "\n" not in scene and scene.endswith(".toml")):
        try:
            with open(scene, encoding="utf-8") as f:
                text = f.read()
        except OSError as e:
            raise InputError(f"invalid SCENE = {_os.fspath(scene)}: cannot be read: {e}") from None
    else:
        text = scene
    for name, v in (("digits", digits), ("order", order)):
        if v is not None and (isinstance(v, bool) or not isinstance(v, int) or not 0 <= v < 2**31):
            raise InputError(f"invalid {name} = {v!r}: must be a non-negative integer")
    return Solution(_json.loads(_native.solve_json(text, digits, method, order, convention)))


del annotations  # the __future__ import binds the name; keep the namespace to what __all__ lists
