//! Tension zones of Problem 2 (docs/theory.md section 4): near the oscillating edge singularity
//! (q2 + i q1) ~ C (1 - x/a)^{1/2 - i eps} the pressure q2 changes sign infinitely often, so for
//! eps > 0 there are zones of tension q2 < 0, each e^{2 pi/eps} times closer to the edge than the
//! last. Located from the edge factor C of a solution, the outermost refined on the full stress.

use rug::{Complex, Float};

/// A zone a < x/a < b near the edge where q2 < 0 (tension).
#[derive(Debug, Clone)]
pub struct TensionZone {
    /// Inner end (x/a).
    pub from_x_over_a: Float,
    /// Outer end (x/a).
    pub to_x_over_a: Float,
    /// 1 - x/a at the outer end (accurate even when x/a rounds to 1).
    pub delta_outer: Float,
    /// 1 - x/a at the inner end.
    pub delta_inner: Float,
    /// Whether the ends were refined on the full stress (else: the leading edge asymptote,
    /// relative error O(1 - x/a)).
    pub refined: bool,
}

/// Tension (q2 < 0) near the oscillating edges.
#[derive(Debug, Clone)]
pub struct TensionReport {
    /// C in (q2 + i q1)/(E* k a) ~ C (1 - x/a)^{1/2 - i eps} at the edge.
    pub edge_factor: Complex,
    /// The two outermost zones (infinitely many follow, each e^{2 pi/eps} times closer to the
    /// edge); empty when eps = 0 (nu = 1/2: no oscillation, no tension).
    pub zones: Vec<TensionZone>,
    /// Indices of requested points where the computed q2 < 0.
    pub at_points: Vec<usize>,
}

/// Tension zones from the edge asymptote q ~ C delta^{1/2 - i eps}: q2 < 0 where
/// cos(arg C - eps ln delta) < 0; the outermost zone is refined by bisection on the full q2
/// when it is not deep in the edge layer (delta > 1e-3).
///
/// `edge_factor` is C, `eps` the material's eps, `at_points` the indices of the requested points
/// where q2 < 0, `q2_near_edge(ln delta)` the dimensionless q2/(E* k a) at 1 - x/a = delta (a
/// cheap evaluation: a few digits suffice), called only when a zone is refined; `prec` the
/// precision of the returned ends.
pub(crate) fn tension_report(
    edge_factor: Complex,
    eps: f64,
    at_points: Vec<usize>,
    zones_wanted: bool,
    q2_near_edge: &mut dyn FnMut(f64) -> f64,
    prec: u32,
) -> TensionReport {
    let c = edge_factor;
    let mut zones = Vec::new();
    if eps > 0.0 && zones_wanted {
        let arg = Float::with_val(64, c.imag().clone().atan2(c.real())).to_f64();
        let pi = std::f64::consts::PI;
        let m0 = ((arg - pi / 2.0) / (2.0 * pi)).floor() + 1.0;
        for m in [m0, m0 + 1.0] {
            let hi = (arg - pi / 2.0 - 2.0 * pi * m) / eps; // ln delta, outer end
            let lo = (arg - 1.5 * pi - 2.0 * pi * m) / eps; // ln delta, inner end
            let mut ends = [lo, hi];
            let mut refined = false;
            if zones.is_empty() && hi > (1e-3f64).ln() {
                refined = true;
                for e in ends.iter_mut() {
                    if let Some(r) = refine_sign_change(q2_near_edge, *e, 0.6 * pi / eps) {
                        *e = r;
                    } else {
                        refined = false;
                    }
                }
            }
            let to_x = |ln_d: f64| {
                let d = Float::with_val(prec, ln_d).exp();
                Float::with_val(prec, 1u32) - d
            };
            // ends = [ln delta inner, ln delta outer]; x/a = 1 - delta.
            let delta = |ln_d: f64| Float::with_val(prec, ln_d.min(0.0)).exp();
            zones.push(TensionZone {
                from_x_over_a: to_x(ends[1].min(0.0)),
                to_x_over_a: to_x(ends[0].min(0.0)),
                delta_outer: delta(ends[1]),
                delta_inner: delta(ends[0]),
                refined,
            });
        }
    }
    TensionReport { edge_factor: c, zones, at_points }
}

/// Sign change of q2 in ln(delta) within +-half_width/2 of `guess`: Illinois (modified regula
/// falsi) to ~1e-9 in ln(delta), typically 6-10 stress evaluations.
fn refine_sign_change(q2: &mut dyn FnMut(f64) -> f64, guess: f64, half_width: f64) -> Option<f64> {
    let (mut a, mut b) = (guess - 0.5 * half_width, (guess + 0.5 * half_width).min(0.0));
    let (mut fa, mut fb) = (q2(a), q2(b));
    if !(fa * fb < 0.0) {
        return None;
    }
    for _ in 0..40 {
        let m = (a * fb - b * fa) / (fb - fa);
        let fm = q2(m);
        if fm == 0.0 {
            return Some(m);
        }
        if fm * fb < 0.0 {
            a = b;
            fa = fb;
        } else {
            fa *= 0.5;
        }
        b = m;
        fb = fm;
        if (b - a).abs() < 1e-9 {
            return Some(b);
        }
    }
    Some(0.5 * (a + b))
}
