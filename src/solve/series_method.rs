//! The truncated exact series of Problem 1 (THEORY.md section 5, [3.7]-[3.12]) evaluated in MPFR
//! at a scene's parameters: the cheap method for small contacts. Its error is the truncation
//! error; it is *estimated* from the last even term kept (order N against order N - 2), never
//! called verified.

use super::format::{digits_in_value, fmt_float};
use super::{provenance, SolveError, SolveRequest};
use crate::asymptotics::sliding::{sliding_expansion, SlidingExpansion, SlidingShape};
use crate::model::ModelError as InvalidInput;
use crate::model::{Period, PunchShape, SlidingLoad, SlidingProblem};
use crate::numerics::{evaluate, exact::to_float};
use crate::scene::Scene;
use exact_series::{Poly, Series, Symbol};
use rug::ops::Pow;
use rug::Float;
use serde_json::{json, Map, Value};

/// Values of the series quantities at one truncation order.
struct Values {
    l: Float,
    c: Float,
    f_def: Float,
    pressure: Vec<Float>,
}

/// Parameters of the evaluation at working precision.
pub struct SeriesPoint {
    /// theta.
    pub theta: Float,
    /// T = beta tau0/(E* k l_s).
    pub t: Float,
    /// Lambda = pi l_s/L.
    pub big_lambda: Float,
    /// l_s.
    pub l_s: Float,
    /// E* k (k osculating for the sinusoid).
    pub e_k: Float,
    /// k.
    pub k: Float,
}

impl SeriesPoint {
    /// The values of the symbols theta and T of the Problem 1 expansions.
    pub fn bindings(&self) -> [(Symbol, Float); 2] {
        [(Symbol::new("theta").expect("valid"), self.theta.clone()), (Symbol::new("T").expect("valid"), self.t.clone())]
    }

    /// A Lambda-series over Q[theta, T], truncated after Lambda^order, at this point.
    ///
    /// # Panics
    /// When `s` holds a symbol other than theta and T (a bug: the expansions' l/l_s,
    /// rbar - rbar_s and F_def series hold only these).
    pub fn eval(&self, s: &Series<Poly>, order: usize, prec: u32) -> Float {
        evaluate::series_mpfr(&s.truncate(order + 1), &self.big_lambda, &self.bindings(), prec)
            .expect("the expansions hold only theta and T")
    }

    /// The contact half-length l = l_s (l/l_s) and centre c = rbar l from the series truncated
    /// after Lambda^order, rbar = 2 theta - T + (rbar - rbar_s) [3.10].
    pub fn contact(&self, e: &SlidingExpansion, order: usize, prec: u32) -> (Float, Float) {
        let l = Float::with_val(prec, &self.l_s * self.eval(&e.l_over_ls, order, prec));
        let rbar =
            Float::with_val(prec, 2 * self.theta.clone() - &self.t) + self.eval(&e.rbar_minus_rbar_s, order, prec);
        let c = Float::with_val(prec, &rbar * &l);
        (l, c)
    }
}

/// theta, T, Lambda, l_s for a problem given by its load (THEORY.md [3.10]).
pub fn series_point(p: &SlidingProblem, prec: u32) -> Result<SeriesPoint, SolveError> {
    let big_l = match p.period() {
        Period::Finite(l) => to_float(l, prec),
        Period::Infinite => {
            return Err(SolveError::Invalid(InvalidInput::new(
                "punch.period",
                "inf",
                "the series method expands in pi l_s/L and needs a finite period",
            )))
        }
    };
    let p2 = match p.load() {
        SlidingLoad::NormalLoad(x) => to_float(x, prec),
        SlidingLoad::HalfLength(_) => {
            return Err(SolveError::Invalid(InvalidInput::new(
                "sliding.half_length",
                "(given)",
                "the series method expands at fixed load: give sliding.normal_load",
            )))
        }
    };
    let pi = Float::with_val(prec, rug::float::Constant::Pi);
    let e_star = to_float(p.material().contact_modulus(), prec);
    let k = match p.shape() {
        PunchShape::Parabolic { k } => to_float(k, prec),
        PunchShape::Sinusoidal { amplitude } => {
            // osculating parabola: k = 2 pi^2 D / L^2
            Float::with_val(
                prec,
                2 * Float::with_val(prec, &pi * &pi) * to_float(amplitude, prec)
                    / Float::with_val(prec, &big_l * &big_l),
            )
        }
    };
    let kappa = to_float(&p.kappa(), prec);
    let theta = Float::with_val(prec, kappa.atan() / &pi);
    let e_k = Float::with_val(prec, &e_star * &k);
    let a0 = (Float::with_val(prec, 2 * &p2) / Float::with_val(prec, &pi * &e_k)).sqrt();
    let one_m = Float::with_val(prec, 1 - Float::with_val(prec, 4 * Float::with_val(prec, &theta * &theta)));
    let l_s = Float::with_val(prec, &a0 / one_m.sqrt());
    let beta = to_float(&p.material().beta(), prec);
    let tau0 = to_float(p.adhesive_friction(), prec);
    let t = Float::with_val(prec, beta * tau0 / Float::with_val(prec, &e_k * &l_s));
    let big_lambda = Float::with_val(prec, Float::with_val(prec, &pi * &l_s) / &big_l);
    Ok(SeriesPoint { theta, t, big_lambda, l_s, e_k, k })
}

fn eval(e: &SlidingExpansion, n: usize, sp: &SeriesPoint, xh: &[Float], prec: u32) -> Result<Values, SolveError> {
    let theta_s = Symbol::new("theta").expect("valid");
    let t_s = Symbol::new("T").expect("valid");
    let xh_s = Symbol::new("xh").expect("valid");
    let (l, c) = sp.contact(e, n, prec);
    let fds = sp.eval(&e.f_def_scaled, n, prec);
    let pi = Float::with_val(prec, rug::float::Constant::Pi);
    let ls3 = Float::with_val(prec, sp.l_s.clone().square() * &sp.l_s);
    let f_def = Float::with_val(prec, &pi * &sp.e_k) * &sp.k * ls3 * fds;
    // p = E* k l cos(pi theta) omega(xh) (1 + sum_j Lambda^(2j) pi_j(xh)), j <= n/2.
    let cos = Float::with_val(prec, Float::with_val(prec, &pi * &sp.theta).cos());
    let half = Float::with_val(prec, 0.5);
    let mut pressure = Vec::new();
    for x in xh {
        let mut b = Float::with_val(prec, 1);
        let mut lam_pow = Float::with_val(prec, 1);
        let l2 = Float::with_val(prec, sp.big_lambda.clone().square());
        let binds = [(theta_s, sp.theta.clone()), (t_s, sp.t.clone()), (xh_s, x.clone())];
        for pj in e.pressure.iter().take(n / 2) {
            lam_pow *= &l2;
            let v = evaluate::poly_mpfr(pj, &binds, prec).map_err(|e| SolveError::Failed(e.to_string()))?;
            b += Float::with_val(prec, &lam_pow * v);
        }
        let ep = Float::with_val(prec, Float::with_val(prec, &half + &sp.theta));
        let em = Float::with_val(prec, Float::with_val(prec, &half - &sp.theta));
        let omega = Float::with_val(
            prec,
            Float::with_val(prec, 1 + x).pow(&ep) * Float::with_val(prec, 1 - x.clone()).pow(&em),
        );
        pressure.push(Float::with_val(prec, &sp.e_k * &l) * &cos * omega * b);
    }
    Ok(Values { l, c, f_def, pressure })
}

/// Runs the series method on a sliding scene.
pub fn sliding_series(p: &SlidingProblem, scene: &Scene, req: SolveRequest) -> Result<Value, SolveError> {
    let n = req.series_order;
    if n < 2 {
        return Err(SolveError::Invalid(InvalidInput::new(
            "--order",
            n,
            "the series method needs an order >= 2 (it estimates its error from the last term)",
        )));
    }
    let digits = req.digits;
    let prec = crate::sliding::precision_for(digits);
    let sp = series_point(p, prec)?;
    if sp.big_lambda >= 1.0 {
        return Err(SolveError::Failed(format!(
            "the series method is for small contacts: Lambda = pi l_s/L = {} >= 1; use --method mpfr",
            fmt_float(&sp.big_lambda, 6)
        )));
    }
    let shape = match p.shape() {
        PunchShape::Parabolic { .. } => SlidingShape::Parabolic,
        PunchShape::Sinusoidal { .. } => SlidingShape::Sinusoidal,
    };
    let e = sliding_expansion(shape, n).map_err(|e| SolveError::Failed(e.to_string()))?;
    let xh: Vec<Float> = scene.output.points.iter().map(|x| to_float(x, prec)).collect();
    let hi = eval(&e, n, &sp, &xh, prec)?;
    let lo = eval(&e, n - 2, &sp, &xh, prec)?;
    let est = |x: &Float, y: &Float, scale: &Float| -> f64 {
        let d = Float::with_val(prec, x - y).abs();
        if d.is_zero() {
            return digits as f64;
        }
        (-Float::with_val(64, d / scale.clone().abs()).log10().to_f64()).max(0.0)
    };
    let g = est(&hi.l, &lo.l, &hi.l).min(est(&hi.c, &lo.c, &hi.l));
    let pmax = hi.pressure.iter().fold(Float::with_val(prec, 0), |m, x| if *x > m { x.clone() } else { m });
    let p2 = match p.load() {
        SlidingLoad::NormalLoad(x) => to_float(x, prec),
        SlidingLoad::HalfLength(_) => unreachable!("checked in series_point"),
    };
    let kl_p2 = Float::with_val(prec, &sp.k * &hi.l) * &p2;
    let fd = est(&hi.f_def, &lo.f_def, &kl_p2);
    let pd = hi.pressure.iter().zip(&lo.pressure).map(|(x, y)| est(x, y, &pmax)).fold(f64::INFINITY, f64::min);
    let headline = g.min(fd).min(pd);
    let pi = Float::with_val(prec, rug::float::Constant::Pi);
    let big_l = match p.period() {
        Period::Finite(l) => to_float(l, prec),
        Period::Infinite => unreachable!("checked in series_point"),
    };
    let lambda = Float::with_val(prec, &pi * &hi.l) / &big_l;
    let a = Float::with_val(prec, &hi.l - &hi.c);
    let b = Float::with_val(prec, &hi.l + &hi.c);
    let mu = to_float(p.friction(), prec);
    let tau0 = to_float(p.adhesive_friction(), prec);
    let p1 = Float::with_val(prec, &mu * &p2) + Float::with_val(prec, 2 * &hi.l) * &tau0;
    let cw = to_float(p.wear(), prec);
    let wear = Float::with_val(prec, &cw * &p2) / &big_l;
    let show = |x: &Float, scale: &Float, d: f64| Value::String(fmt_float(x, digits_in_value(x, scale, d, digits)));
    let mut m = Map::new();
    m.insert("problem".into(), json!("sliding"));
    m.insert("theta".into(), json!(fmt_float(&sp.theta, digits as usize)));
    m.insert("kappa".into(), json!(fmt_float(&to_float(&p.kappa(), prec), digits as usize)));
    m.insert("lambda".into(), show(&lambda, &lambda, g));
    m.insert("l".into(), show(&hi.l, &hi.l, g));
    m.insert("a".into(), show(&a, &hi.l, g));
    m.insert("b".into(), show(&b, &hi.l, g));
    m.insert("c".into(), show(&hi.c, &hi.l, g));
    m.insert("P1".into(), show(&p1, &p2, g));
    m.insert("P2".into(), json!(fmt_float(&p2, digits as usize)));
    m.insert("F_def".into(), show(&hi.f_def, &kl_p2, fd));
    m.insert("wear_per_distance".into(), json!(fmt_float(&wear, digits as usize)));
    m.insert(
        "wear_rate".into(),
        match p.speed() {
            Some(v) => json!(fmt_float(&Float::with_val(prec, &wear * to_float(v, prec)), digits as usize)),
            None => Value::Null,
        },
    );
    m.insert("Lambda".into(), json!(fmt_float(&sp.big_lambda, 10)));
    m.insert("digits_requested".into(), json!(digits.to_string()));
    m.insert("digits_verified".into(), Value::Null);
    m.insert("digits_estimated".into(), json!(format!("{headline:.1}")));
    m.insert(
        "accuracy".into(),
        json!({"note": format!("estimated from the last kept term (order {n} against {}); not verified", n - 2),
               "a": format!("{g:.1}"), "b": format!("{g:.1}"), "c": format!("{g:.1}"), "F_def": format!("{fd:.1}"), "p": format!("{pd:.1}")}),
    );
    let pressure: Vec<Value> = xh
        .iter()
        .zip(&hi.pressure)
        .map(|(x, pv)| {
            let xx = Float::with_val(prec, &hi.c + Float::with_val(prec, &hi.l * x));
            json!({"xh": fmt_float(x, digits as usize), "x": fmt_float(&xx, digits_in_value(&xx, &hi.l, g, digits)), "p": fmt_float(pv, digits_in_value(pv, &pmax, pd, digits))})
        })
        .collect();
    m.insert("pressure".into(), Value::Array(pressure));
    let mut prov = provenance("series", Some(prec), None);
    prov["order"] = json!(n.to_string());
    m.insert("provenance".into(), prov);
    Ok(Value::Object(m))
}
