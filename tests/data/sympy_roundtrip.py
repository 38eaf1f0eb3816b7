"""Reads `periodic-contact series --format sympy` output with plain sympy.sympify and compares it,
coefficient by coefficient, with the exact text of `--format json` (parsed here independently,
names kept as printed). Usage: python sympy_roundtrip.py SYMPY_FILE JSON_FILE. Exit 1 on any mismatch."""
import json
import sys

import sympy
from sympy.parsing.sympy_parser import parse_expr


def plain(name):
    """Whether sympify reads `name` as the symbol of that name."""
    try:
        v = sympy.sympify(name)
    except Exception:
        return False
    return isinstance(v, sympy.Symbol) and v.name == name


def main():
    d = sympy.sympify(open(sys.argv[1]).read())
    top = json.load(open(sys.argv[2]))
    assert isinstance(d, dict), type(d)
    checked = 0
    for part in top["parts"]:
        names = list(part["symbols"]) + [part["variable"]]
        # The printed name of each symbol, decided here from SymPy itself.
        back = {sympy.Symbol(n if plain(n) else n + "_"): sympy.Symbol(n) for n in names}
        expr = d[part["object"]]
        local = {n: sympy.Symbol(n) for n in names}
        exact = {c["power"]: parse_expr(c["text"].replace("^", "**"), local_dict=local) for c in part["coefficients"]}
        if isinstance(expr, (list, tuple)):
            got = {k: sympy.sympify(e).xreplace(back) for k, e in enumerate(expr) if e != 0}
        else:
            var = sympy.Symbol(part["variable"])
            expr = sympy.sympify(expr).xreplace(back)
            order = expr.getO()
            if part["order"] > 0:
                assert order == sympy.O(var ** (part["order"] + 1)), (part["object"], order)
            got = {}
            for term in sympy.Add.make_args(expr.removeO()):
                c, e = term.as_independent(var, as_Add=False)
                k = 0 if e == 1 else int(sympy.degree(e, var))
                assert e == var**k, (part["object"], term)
                got[k] = got.get(k, 0) + c
        assert set(got) == set(exact), (part["object"], sorted(got), sorted(exact))
        for k, e in exact.items():
            diff = sympy.cancel(sympy.together(got[k] - e))
            assert diff == 0, (part["object"], k, got[k], e)
            checked += 1
    print(f"{top['object']}: {len(top['parts'])} parts, {checked} coefficients agree")


if __name__ == "__main__":
    main()
