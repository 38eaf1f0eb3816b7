//! The seeded generator of valid scenes (issue 34): every problem (sliding, adhesion, loading law),
//! shape, convention and option, sizes from lambda = 1e-12 to past the physical limit, loads as
//! exact decimals near every limit, E*, L, k, D, R over decades. Each case comes with a twin scaled
//! exactly (lengths times s, stresses times t), whose answers must follow the scaling laws.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

/// A small seeded generator (SplitMix64): the same (seed, index) gives the same case on every
/// machine.
pub struct Rng(u64);

impl Rng {
    /// The generator of case `index` under `seed`.
    pub fn new(seed: u64, index: u64) -> Self {
        let mut r = Rng(seed ^ index.wrapping_mul(0x9E37_79B9_7F4A_7C15));
        r.next();
        r
    }
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Uniform in lo..=hi.
    pub fn int(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next() % ((hi - lo + 1) as u64)) as i64
    }
    /// True with probability `p`.
    pub fn chance(&mut self, p: f64) -> bool {
        self.unit() < p
    }
    /// One of `items`.
    pub fn pick<T: Clone>(&mut self, items: &[T]) -> T {
        items[self.int(0, items.len() as i64 - 1) as usize].clone()
    }
    /// Log-uniform in [lo, hi].
    pub fn log_uniform(&mut self, lo: f64, hi: f64) -> f64 {
        (lo.ln() + self.unit() * (hi.ln() - lo.ln())).exp()
    }
}

/// An exact rational.
pub type Q = BigRational;

/// `x` as an exact decimal of `sig` significant digits (x > 0 finite).
pub fn decimal(x: f64, sig: usize) -> Q {
    let text = format!("{:.*e}", sig.max(1) - 1, x);
    exact_series::parse_rational(&text).expect("a decimal")
}

/// 10^e exactly.
pub fn pow10(e: i32) -> Q {
    let ten = BigInt::from(10);
    if e >= 0 {
        Q::from_integer(num_traits::pow(ten, e as usize))
    } else {
        Q::new(BigInt::one(), num_traits::pow(ten, (-e) as usize))
    }
}

/// TOML text of an exact number ("n/d" or "n").
pub fn text(q: &Q) -> String {
    if q.denom().is_one() {
        format!("\"{}\"", q.numer())
    } else {
        format!("\"{}/{}\"", q.numer(), q.denom())
    }
}

/// Which problem a case states.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Problem {
    /// Problem 1.
    Sliding,
    /// Problem 2.
    Adhesion,
    /// Problem 2 under a loading law.
    Law,
}

/// The punch.
#[derive(Debug, Clone)]
pub enum Shape {
    Parabolic {
        k: Q,
    },
    Sinusoidal {
        d: Q,
    },
    /// Coefficients c_0.. (c_0 = 0).
    Polynomial {
        c: Vec<Q>,
    },
    Circular {
        r: Q,
    },
}

/// The load or size given.
#[derive(Debug, Clone)]
pub enum Given {
    NormalLoad(Q),
    /// Sliding and the loading law: l; adhesion: the half-width a.
    Size(Q),
}

/// One scene's statement, exactly.
#[derive(Debug, Clone)]
pub struct Statement {
    pub problem: Problem,
    pub nu: Q,
    pub e_star: Q,
    /// None: a single punch.
    pub period: Option<Q>,
    pub shape: Shape,
    pub given: Given,
    pub friction: Q,
    pub tau0: Q,
    pub wear: Q,
    pub speed: Option<Q>,
    pub periodic_convention: bool,
    /// Loading law P1 = sum c_j P2^j (c_0 = 0).
    pub law: Vec<Q>,
    /// Output points (xh in (-1, 1), or x/a in [0, 1] for adhesion).
    pub points: Vec<Q>,
    /// What the generator aimed at (for the report of a disagreement).
    pub note: String,
}

/// The exact similarity of a statement: lengths times `s`, stresses (E*, tau0) times `t`; the wear
/// coefficient (1/stress) times 1/t; loads (force/length) times s t.
#[derive(Debug, Clone)]
pub struct Scaling {
    pub s: Q,
    pub t: Q,
}

impl Statement {
    /// The statement scaled by `sc` (exactly).
    pub fn scaled(&self, sc: &Scaling) -> Statement {
        let (s, t) = (&sc.s, &sc.t);
        let st = s * t;
        let shape = match &self.shape {
            Shape::Parabolic { k } => Shape::Parabolic { k: k / s },
            Shape::Sinusoidal { d } => Shape::Sinusoidal { d: d * s },
            Shape::Circular { r } => Shape::Circular { r: r * s },
            Shape::Polynomial { c } => Shape::Polynomial {
                // g(x) = sum c_j x^j is a length: c_j scales as s^(1 - j).
                c: c.iter().enumerate().map(|(j, cj)| cj * num_traits::pow(s.recip(), j) * s).collect(),
            },
        };
        let given = match &self.given {
            Given::NormalLoad(p) => Given::NormalLoad(p * &st),
            Given::Size(l) => Given::Size(l * s),
        };
        // P1 = sum c_j P2^j: P1 and P2 both scale as s t, so c_j scales as (s t)^(1 - j).
        let law = self.law.iter().enumerate().map(|(j, cj)| cj * num_traits::pow(st.recip(), j) * &st).collect();
        Statement {
            e_star: &self.e_star * t,
            period: self.period.as_ref().map(|l| l * s),
            shape,
            given,
            tau0: &self.tau0 * t,
            wear: &self.wear / t,
            law,
            note: format!("{} (scaled: lengths x {}, stresses x {})", self.note, s, t),
            ..self.clone()
        }
    }

    /// The scene's TOML text.
    pub fn toml(&self) -> String {
        let mut out = String::new();
        let kind = if self.problem == Problem::Sliding { "sliding" } else { "adhesion" };
        out += &format!("[problem]\nkind = \"{kind}\"\n");
        if self.periodic_convention {
            out += "convention = \"periodic\"\n";
        }
        out += &format!("[material]\npoisson_ratio = {}\ncontact_modulus = {}\n", text(&self.nu), text(&self.e_star));
        out += "[punch]\n";
        match &self.shape {
            Shape::Parabolic { k } => out += &format!("shape = \"parabolic\"\nk = {}\n", text(k)),
            Shape::Sinusoidal { d } => out += &format!("shape = \"sinusoidal\"\namplitude = {}\n", text(d)),
            Shape::Circular { r } => out += &format!("shape = \"circular\"\nradius = {}\n", text(r)),
            Shape::Polynomial { c } => {
                let list: Vec<String> = c.iter().map(text).collect();
                out += &format!("shape = \"polynomial\"\ncoefficients = [{}]\n", list.join(", "));
            }
        }
        out += &format!("period = {}\n", self.period.as_ref().map_or("\"inf\"".to_string(), text));
        match self.problem {
            Problem::Sliding => {
                out += "[sliding]\n";
                match &self.given {
                    Given::NormalLoad(p) => out += &format!("normal_load = {}\n", text(p)),
                    Given::Size(l) => out += &format!("half_length = {}\n", text(l)),
                }
                out += &format!("friction = {}\n", text(&self.friction));
                if !self.tau0.is_zero() {
                    out += &format!("adhesive_friction = {}\n", text(&self.tau0));
                }
                if !self.wear.is_zero() {
                    out += &format!("wear = {}\n", text(&self.wear));
                }
                if let Some(v) = &self.speed {
                    out += &format!("speed = {}\n", text(v));
                }
            }
            Problem::Adhesion => {
                out += "[adhesion]\n";
                match &self.given {
                    Given::NormalLoad(p) => out += &format!("normal_load = {}\n", text(p)),
                    Given::Size(a) => out += &format!("half_width = {}\n", text(a)),
                }
            }
            Problem::Law => {
                out += "[adhesion]\n";
                if self.law.len() == 2 {
                    out += &format!("tangential_ratio = {}\n", text(&self.law[1]));
                } else {
                    let list: Vec<String> = self.law.iter().map(text).collect();
                    out += &format!("loading_law = [{}]\n", list.join(", "));
                }
                match &self.given {
                    Given::NormalLoad(p) => out += &format!("normal_load = {}\n", text(p)),
                    Given::Size(l) => out += &format!("half_length = {}\n", text(l)),
                }
            }
        }
        let pts: Vec<String> = self.points.iter().map(text).collect();
        out += &format!("[output]\npoints = [{}]\n", pts.join(", "));
        out
    }
}

/// One generated case: the statement, its scaled twin's similarity.
#[derive(Debug, Clone)]
pub struct Case {
    pub index: u64,
    pub statement: Statement,
    pub scaling: Scaling,
}

/// `x` rounded once to f64 (for aiming only: every input stays exact).
fn qf(x: &Q) -> f64 {
    periodic_contact::numerics::exact::to_f64(x).unwrap_or(f64::NAN)
}

fn q(x: f64, sig: usize) -> Q {
    decimal(x, sig)
}

/// A decade-spread positive number: mantissa of 1-3 digits times 10^e, e in lo..=hi.
fn spread(r: &mut Rng, lo: i32, hi: i32) -> Q {
    let e = r.int(lo as i64, hi as i64) as i32;
    let m = r.pick(&[1.0, 2.0, 2.5, 3.7, 5.0, 7.0, 1.25]);
    q(m, 3) * pow10(e)
}

/// The size parameter lambda = pi l/L aimed at: log-uniform from 1e-12 to 1.5 (past the physical
/// limit of most problems), with extra weight at both ends.
fn lambda(r: &mut Rng) -> f64 {
    match r.int(0, 9) {
        0 => r.log_uniform(1e-12, 1e-6),
        1 => r.log_uniform(1.2, 1.5),
        _ => r.log_uniform(1e-4, 1.3),
    }
}

/// Case `index` of `seed`.
pub fn case(seed: u64, index: u64) -> Case {
    let mut r = Rng::new(seed, index);
    let problem = match r.int(0, 99) {
        0..=69 => Problem::Sliding,
        70..=91 => Problem::Adhesion,
        _ => Problem::Law,
    };
    let nu = match r.int(0, 6) {
        0 => Q::zero(),
        1 => q(0.25, 2),
        2 => q(0.3, 1),
        3 => Q::new(1.into(), 3.into()),
        4 => q(0.45, 2),
        5 => Q::new(1.into(), 2.into()),
        _ => q(r.unit() * 0.5, 3),
    };
    let e_star = spread(&mut r, -6, 9);
    let period_len = spread(&mut r, -3, 3);
    let periodic = match problem {
        Problem::Sliding => r.chance(0.85),
        _ => r.chance(0.8),
    };
    // Shape, relative to the period (or to a length scale of 1 period for a single punch).
    let big_l = period_len.clone();
    let lf = qf(&big_l);
    let shape_pick = match problem {
        Problem::Sliding => r.int(0, 99),
        Problem::Adhesion => [0, 0, 0, 60, 80][r.int(0, 4) as usize],
        Problem::Law => 0,
    };
    let shape = match shape_pick {
        0..=44 => Shape::Parabolic { k: spread(&mut r, -2, 2) / &big_l },
        45..=64 if problem == Problem::Sliding && periodic => {
            Shape::Sinusoidal { d: q(r.log_uniform(1e-4, 5e-2), 3) * &big_l }
        }
        45..=79 => {
            // g = c2 x^2 + c3 x^3 + c4 x^4 (c3 = 0 for adhesion: an even profile), convex with a small slope
            // on most contacts; the methods refuse the others with a reason.
            let c2 = spread(&mut r, -1, 1) / &big_l;
            let c3 = if problem == Problem::Sliding && r.chance(0.4) {
                q(r.unit() * 0.5, 2) * &c2 / &big_l
            } else {
                Q::zero()
            };
            let c4 = q(r.log_uniform(1e-3, 3.0), 2) * &c2 / (&big_l * &big_l);
            Shape::Polynomial { c: vec![Q::zero(), Q::zero(), c2, c3, c4] }
        }
        _ => Shape::Circular { r: q(r.log_uniform(0.3, 100.0), 3) * &big_l },
    };
    let shape = match (&shape, periodic) {
        // A sinusoid needs a period.
        (Shape::Sinusoidal { .. }, false) => Shape::Parabolic { k: spread(&mut r, -2, 2) / &big_l },
        _ => shape,
    };
    let k_osc = match &shape {
        Shape::Parabolic { k } => qf(k),
        Shape::Sinusoidal { d } => 2.0 * std::f64::consts::PI.powi(2) * qf(d) / (lf * lf),
        Shape::Polynomial { c } => qf(&c[2]),
        Shape::Circular { r } => 0.5 / qf(r),
    };
    let ef = qf(&e_star);
    // Friction, wear, adhesive shear (sliding only).
    let (mut friction, mut tau0, mut wear, mut speed) = (Q::zero(), Q::zero(), Q::zero(), None);
    if problem == Problem::Sliding {
        if r.chance(0.6) {
            let any = q(r.unit().max(0.01), 2);
            friction = r.pick(&[q(0.1, 1), q(0.3, 1), q(0.5, 1), q(0.8, 1), any]);
        }
        if r.chance(0.25) {
            wear = q(r.log_uniform(1e-3, 0.5), 2) / &e_star;
            if r.chance(0.5) {
                speed = Some(spread(&mut r, -2, 2));
            }
        }
        if r.chance(0.2) {
            tau0 = q(r.log_uniform(1e-5, 1e-2), 2) * &e_star;
        }
    }
    let periodic_convention = problem != Problem::Adhesion && r.chance(0.4);
    let law = if problem == Problem::Law {
        match r.int(0, 4) {
            0 => vec![Q::zero(), Q::zero()],
            1 | 2 => vec![Q::zero(), r.pick(&[q(0.1, 1), q(0.2, 1), q(0.5, 1), q(0.05, 1)])],
            _ => vec![Q::zero(), q(0.2, 1), q(r.log_uniform(1e-3, 1.0), 2) / (q(ef * k_osc * lf * lf, 6))],
        }
    } else {
        vec![]
    };
    // Size or load.
    // The loading law's verified solve near full contact takes minutes (its collocation grows
    // without bound): its sizes stop at lambda = 1.
    let lam = if problem == Problem::Law { lambda(&mut r).min(1.0) } else { lambda(&mut r) };
    let pi = std::f64::consts::PI;
    let size = if periodic { lam * lf / pi } else { lam * lf };
    let mut note = format!("lambda ~ {lam:.3e}");
    let given = if r.chance(0.45) {
        let dig = r.int(2, 8) as usize;
        match problem {
            // The contact must stay inside its cell: 2 l < L (2 a < L), the builders' checks.
            _ if periodic && 2.0 * size >= lf => Given::Size(q(0.49 * lf, 2)),
            _ => Given::Size(q(size, dig)),
        }
    } else {
        let near_limit = matches!(shape, Shape::Sinusoidal { .. }) && r.chance(0.3);
        if near_limit {
            // Near Westergaard's full-contact load pi E* D: 25-digit decimals just below or above it.
            let Shape::Sinusoidal { d } = &shape else { unreachable!() };
            let j = r.int(1, 22) as i32;
            let above = r.chance(0.3);
            let pi_text = "3.14159265358979323846264338327950288";
            let pi_q = exact_series::parse_rational(pi_text).expect("pi");
            let gap = pow10(-j);
            let factor = if above { &pi_q * (Q::one() + &gap) } else { &pi_q * (Q::one() - &gap) };
            let p = factor * &e_star * d;
            note = format!("P2 = pi E* D (1 {} 1e-{j})", if above { "+" } else { "-" });
            Given::NormalLoad(round_sig(&p, 25))
        } else {
            // Kuznetsov-like load for the osculating parabola (Hertz for a single punch); for the
            // sinusoid Westergaard's pi E* D sin^2 lambda.
            let p = match (&shape, periodic) {
                (Shape::Sinusoidal { d }, _) => pi * ef * qf(d) * lam.min(1.55).sin().powi(2),
                (_, true) => -(lam.min(1.55).cos().ln()) * ef * k_osc * lf * lf / pi,
                (_, false) => pi * ef * k_osc * size * size / 2.0,
            };
            let p = if p > 0.0 && p.is_finite() { p } else { ef * k_osc * lf * lf * 1e-20 };
            Given::NormalLoad(q(p, r.int(1, 8) as usize))
        }
    };
    let n_points = r.int(0, 3);
    let points = (0..n_points)
        .map(|_| match problem {
            Problem::Adhesion => q(r.unit().max(1e-3), 2),
            _ => q(1.8 * r.unit() - 0.9, 2),
        })
        .collect();
    let statement = Statement {
        problem,
        nu,
        e_star,
        period: periodic.then_some(period_len),
        shape,
        given,
        friction,
        tau0,
        wear,
        speed,
        periodic_convention,
        law,
        points,
        note,
    };
    let scaling = Scaling { s: pow10(r.int(-3, 3) as i32), t: pow10(r.int(-3, 3) as i32) };
    Case { index, statement, scaling }
}

/// `x` (> 0) rounded down to `sig` significant decimal digits, exactly.
fn round_sig(x: &Q, sig: i32) -> Q {
    let f = qf(x);
    let e = f.abs().log10().floor() as i32;
    let unit = pow10(e - sig + 1);
    let n = (x / &unit).floor();
    let n = if n.is_positive() { n } else { Q::one() };
    n * unit
}
