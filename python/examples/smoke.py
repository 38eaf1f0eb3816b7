"""A first use of the installed module: one solve and one series, each checked against a closed
form. Run by `scripts/test --long` in a fresh venv where only the wheel (and numpy) is installed."""

from fractions import Fraction
from pathlib import Path

import periodic_contact as pc

# The exact kernel series z cot z = 1 - z^2/3 - z^4/45 - ... (DLMF 4.19.6).
kernel = pc.series("kernel", order=4)["kernel"].coefficients
assert kernel == {0: Fraction(1), 2: Fraction(-1, 3), 4: Fraction(-1, 45)}, kernel

scene = Path(__file__).resolve().parents[2] / "scenes" / "sliding_friction.toml"
r = pc.solve(scene, method="f64")
# l = 0.0794891890084214444... (verified MPFR, 34 digits; README).
assert abs(r.l - 0.0794891890084214444) < 1e-13, r.l
assert r.digits_verified >= 13, r.digits_verified
print(f"periodic-contact {pc.__version__}: kernel series and one f64 solve (l = {r.l}, {r.digits_verified} digits) OK")
