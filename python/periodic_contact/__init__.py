"""periodic-contact from Python (issue 16): exact series and verified solutions of the periodic
contact problem (Soldatenkov 2013), the Rust library through PyO3.

    import periodic_contact as pc
    s = pc.series("sliding", order=12, theta="1/10")
    s["l_over_ls"].coefficients[2]        # Fraction(-2, 25): l/l_s = 1 - 2/25 Lambda^2 + ...
    r = pc.solve(open("scenes/sliding_friction.toml").read())
    r["l"], r["digits_verified"]          # the keys of `periodic-contact solve ... --json`

Errors are typed (`pc.InputError`, its subclass `pc.SceneError`, `pc.NoSolutionError`,
`pc.NotPhysicalError`, `pc.NoConvergenceError`, `pc.SeriesError`, all subclasses of `pc.Error`)
and carry the command line's message (what `periodic-contact` prints after ``error: ``).
"""

from __future__ import annotations

import json
import os
import re
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any, Dict, List, Mapping, Optional, Union

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
    "Part",
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

_RATIONAL = re.compile(r"^-?\d+(/\d+)?$")

Coefficient = Union[Fraction, str]


def _coefficient(text: str) -> Coefficient:
    """A rational coefficient as a Fraction; any other as a SymPy-readable string (``**`` powers)."""
    t = text.strip()
    if _RATIONAL.match(t):
        return Fraction(t)
    return t.replace("^", "**")


@dataclass
class Part:
    """One derived object: exact coefficients by power of its variable.

    ``coefficients[k]`` is the coefficient of ``variable**k`` (only the non-zero ones are listed;
    every power through ``order`` is known, so a missing power below it is exactly 0):
    a ``Fraction`` when rational, else a SymPy-readable string in the symbols ``symbols``.
    ``latex[k]`` is its LaTeX.
    """

    object: str
    variable: str
    order: int
    symbols: List[str]
    coefficients: Dict[int, Coefficient]
    latex: Dict[int, str] = field(default_factory=dict)
    notes: List[str] = field(default_factory=list)

    def sympy(self) -> Dict[int, Any]:
        """The coefficients as SymPy expressions, every symbol an explicit ``sympy.Symbol`` (so
        names such as ``S``, ``B``, ``T`` never collide with SymPy's own objects). Needs sympy."""
        import sympy

        names = {name: sympy.Symbol(name) for name in self.symbols}
        out = {}
        for k, c in self.coefficients.items():
            if isinstance(c, Fraction):
                out[k] = sympy.Rational(c.numerator, c.denominator)
            else:
                out[k] = sympy.parse_expr(c, local_dict=names)
        return out


def _part(v: Mapping[str, Any]) -> Part:
    coeffs = {int(c["power"]): _coefficient(c["text"]) for c in v["coefficients"]}
    latex = {int(c["power"]): c.get("latex", "") for c in v["coefficients"]}
    return Part(
        object=v["object"],
        variable=v["variable"],
        order=int(v["order"]),
        symbols=list(v.get("symbols", [])),
        coefficients=coeffs,
        latex=latex,
        notes=list(v.get("notes", [])),
    )


def series(object: str, order: int = 12, **options: Any) -> Dict[str, Any]:
    """Derives ``object`` through power ``order`` as ``periodic-contact series OBJECT`` does.

    ``object``: ``kernel``, ``weight``, ``jacobi``, ``sliding``, ``adhesion``, ``loading-law``.
    ``options``: the command's flags without dashes, values exact as text or numbers
    (``theta="1/10"``, ``T="1/20"``, ``xh=0``, ``nu="3/10"``, ``ratio="1/5"``,
    ``shape="sinusoidal"``, ``coefficients="0,0,1,0,1/10"`` or a list, ``degree=4``,
    ``rbar_s="1/6"``, ``convention="periodic"``). Floats are refused: give exact values.

    Returns ``{part name: Part}`` (one entry for ``kernel``, ``weight``, ``jacobi``; ``l_over_ls``,
    ``rbar_minus_rbar_s``, ... for ``sliding``); for ``loading-law`` (numerical coefficients at
    given nu and n) the CLI's JSON as a dict.
    """
    opts = []
    for key, value in options.items():
        if isinstance(value, float):
            raise InputError(f"invalid {key} = {value!r}: give an exact value as text (e.g. \"1/10\"), not a float")
        if isinstance(value, (list, tuple)):
            value = ",".join(str(x) for x in value)
        opts.append((key, str(value)))
    v = json.loads(_native.series_json(object, int(order), opts))
    if object == "loading-law":
        return v
    parts = v["parts"] if "parts" in v else [v]
    return {p["object"]: _part(p) for p in parts}


def _toml_value(v: Any) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, Fraction):
        return json.dumps(str(v))
    if isinstance(v, float):
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v)  # a JSON string is a valid TOML basic string
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_toml_value(x) for x in v) + "]"
    raise InputError(f"invalid scene value {v!r}: must be a string, number, boolean or list")


def to_toml(scene: Mapping[str, Any]) -> str:
    """A scene dict ``{"problem": {"kind": "sliding"}, "material": {...}, ...}`` as TOML text
    (tables of scalars and lists, the layout of ``scenes/*.toml``)."""
    lines = []
    for table, body in scene.items():
        if not isinstance(body, Mapping):
            raise SceneError(f"invalid scene key {table} = {body!r}: every top-level key is a table (a dict)")
        lines.append(f"[{table}]")
        for key, value in body.items():
            lines.append(f"{key} = {_toml_value(value)}")
    return "\n".join(lines) + "\n"


def solve(
    scene: Union[str, os.PathLike, Mapping[str, Any]],
    *,
    digits: Optional[int] = None,
    method: Optional[str] = None,
    order: Optional[int] = None,
    convention: Optional[str] = None,
) -> Dict[str, Any]:
    """Solves a scene as ``periodic-contact solve SCENE --json`` does; returns its JSON as a dict
    (string values, the same keys).

    ``scene``: TOML text, a path to a scene file (``pathlib.Path``, or a one-line string ending in
    ``.toml`` naming an existing file), or a dict
    of tables (see :func:`to_toml`). ``digits``, ``method`` (``mpfr``, ``f64``, ``series``),
    ``order`` (series order) and ``convention`` (``paper``, ``periodic``) are the flags of
    ``solve``; ``None`` keeps the scene's own (or the CLI's default).
    """
    if isinstance(scene, Mapping):
        text = to_toml(scene)
    elif isinstance(scene, os.PathLike) or (
        isinstance(scene, str) and "\n" not in scene and scene.endswith(".toml") and os.path.isfile(scene)
    ):
        with open(scene, encoding="utf-8") as f:
            text = f.read()
    else:
        text = scene
    return json.loads(_native.solve_json(text, digits, method, order, convention))
