//! The admissible range of the load (or the contact size) at the problem's other parameters: the
//! sizes whose contacts pass the criterion of [`super::assess`], and the loads they carry. Quoted
//! by every "not physical" refusal (and by "no solution" when the load is out of reach), computed
//! from the method's own direct problem (contact size given, load returned), never guessed.
//!
//! The size parameter s is lambda = pi l/L for a period, l for a single punch. The scan samples
//! s_j = s_max j/48 (j = 1..48), groups the physical samples into runs, bisects each run's ends to
//! 2^-30 of a grid step, and takes the loads over each run: at the refined ends, at the samples,
//! and at a golden-section refinement of the largest sample (P2(lambda) need not be monotone: the
//! sinusoid with friction reaches a load twice). A run that starts at the first sample extends to
//! s -> 0 (load -> 0).

use crate::numerics::accuracy::readable_f64;

/// Samples of the scan.
pub const SCAN_POINTS: usize = 48;
/// Bisection steps per run end.
const BISECTIONS: usize = 30;
/// Golden-section steps on the largest load.
const GOLDEN_STEPS: usize = 40;
/// Largest lambda scanned for a period (contact fraction 2 lambda/pi = 0.971): the reach of the
/// MPFR method's locating stage (lambda_cap(16 digits, 512 nodes) = 1.5258, `reduction_mpfr`),
/// which the f64 method's load scan matches; beyond it the node counts grow without bound as the
/// contact fills the period. A run of physical sizes that reaches it is "open above": the load
/// may be carried beyond the scan ([`crate::sliding::physicality::refusal_in_reach`]).
pub const LAMBDA_SCAN_MAX: f64 = 1.525;

/// The contacts of the direct problem at one size: (load, physical) for each centre solution.
pub type SizeContacts = Vec<(f64, bool)>;

/// One run of physical sizes and the loads they carry.
#[derive(Debug, Clone, PartialEq)]
pub struct Run {
    /// Smallest physical size (0 when the run reaches s -> 0).
    pub size_lo: f64,
    /// Largest physical size found (the scan's end when the run reaches it).
    pub size_hi: f64,
    /// Whether the run reaches the end of the scan (the true end may lie beyond).
    pub open_above: bool,
    /// Smallest load carried (0 when the run reaches s -> 0).
    pub load_lo: f64,
    /// Largest load carried, and at which size.
    pub load_hi: (f64, f64),
}

/// The admissible sizes and loads.
#[derive(Debug, Clone, PartialEq)]
pub struct Admissible {
    /// The runs, by increasing size.
    pub runs: Vec<Run>,
}

impl Admissible {
    /// The largest physical load and its size, if any contact is physical.
    pub fn max_load(&self) -> Option<(f64, f64)> {
        self.runs.iter().map(|r| r.load_hi).fold(None, |m: Option<(f64, f64)>, v| match m {
            Some(b) if b.0 >= v.0 => Some(b),
            _ => Some(v),
        })
    }

    /// Whether a load is inside one of the runs' load ranges.
    pub fn carries(&self, load: f64) -> bool {
        self.runs.iter().any(|r| load >= r.load_lo && load <= r.load_hi.0)
    }

    /// The loads in words, e.g. "normal_load in (0, 0.0146] (contact fraction 2l/L up to 0.55)";
    /// `unit` multiplies loads (to the user's units), `fraction` turns a size into the words'
    /// size measure (2 lambda/pi for a period, l for a single punch) and `size_name` names it.
    pub fn loads_text(&self, unit: f64, fraction: impl Fn(f64) -> f64, size_name: &str) -> String {
        if self.runs.is_empty() {
            return "no contact size gives a physical contact at these parameters".into();
        }
        let parts: Vec<String> = self
            .runs
            .iter()
            .map(|r| {
                let lo =
                    if r.size_lo == 0.0 { "(0".to_string() } else { format!("[{}", readable_f64(r.load_lo * unit)) };
                format!(
                    "{lo}, {}] ({size_name} {} to {}{})",
                    readable_f64(r.load_hi.0 * unit),
                    readable_f64(fraction(r.size_lo)),
                    readable_f64(fraction(r.size_hi)),
                    if r.open_above { " and possibly beyond, the end of the scan" } else { "" }
                )
            })
            .collect();
        format!("physical contacts carry normal_load in {}", parts.join(" or "))
    }

    /// The largest load of the first admissible run quoted in a message built with
    /// [`Admissible::loads_text`] ("normal_load in (0, X]" -> X, as printed: 7 significant digits),
    /// for a caller that holds only the refusal's text (a script reading the CLI's stderr, a test).
    pub fn quoted_largest_load(message: &str) -> Option<f64> {
        message.split("normal_load in (0, ").nth(1)?.split(']').next()?.parse().ok()
    }

    /// The sizes in words, e.g. "half_length in (0, 0.21]"; `to_length` turns a size into l.
    pub fn sizes_text(&self, to_length: impl Fn(f64) -> f64) -> String {
        if self.runs.is_empty() {
            return "no contact size gives a physical contact at these parameters".into();
        }
        let parts: Vec<String> = self
            .runs
            .iter()
            .map(|r| {
                let lo = if r.size_lo == 0.0 {
                    "(0".to_string()
                } else {
                    format!("[{}", readable_f64(to_length(r.size_lo)))
                };
                format!(
                    "{lo}, {}]{}",
                    readable_f64(to_length(r.size_hi)),
                    if r.open_above { " (and possibly beyond, the end of the scan)" } else { "" }
                )
            })
            .collect();
        format!("physical contacts have half_length in {}", parts.join(" or "))
    }
}

/// The largest physical load at size s (None: no physical contact with a positive load).
fn best<E>(at: &mut impl FnMut(f64) -> Result<SizeContacts, E>, s: f64) -> Result<Option<f64>, E> {
    Ok(at(s)?
        .into_iter()
        .filter(|(p, ok)| *ok && *p > 0.0)
        .map(|(p, _)| p)
        .fold(None, |m: Option<f64>, p| Some(m.map_or(p, |m| m.max(p)))))
}

/// The end of a run between a physical size `good` (with its load) and a non-physical one `bad`,
/// by [`BISECTIONS`] bisections: the last physical size and its load.
fn boundary<E>(
    at: &mut impl FnMut(f64) -> Result<SizeContacts, E>,
    (mut good, mut load): (f64, f64),
    mut bad: f64,
) -> Result<(f64, f64), E> {
    for _ in 0..BISECTIONS {
        let mid = 0.5 * (good + bad);
        match best(at, mid)? {
            Some(p) => {
                good = mid;
                load = p;
            }
            None => bad = mid,
        }
    }
    Ok((good, load))
}

/// The admissible runs over s in (0, `s_max`] (module doc); `at(s)` solves the direct problem at
/// size s and judges each contact with [`super::assess`].
pub fn admissible<E>(s_max: f64, mut at: impl FnMut(f64) -> Result<SizeContacts, E>) -> Result<Admissible, E> {
    let n = SCAN_POINTS;
    let grid: Vec<f64> = (1..=n).map(|j| s_max * j as f64 / n as f64).collect();
    let mut vals = Vec::with_capacity(n);
    for &s in &grid {
        vals.push(best(&mut at, s)?);
    }
    let mut runs = Vec::new();
    let mut j = 0;
    while j < n {
        if vals[j].is_none() {
            j += 1;
            continue;
        }
        let j0 = j;
        while j + 1 < n && vals[j + 1].is_some() {
            j += 1;
        }
        let j1 = j;
        j += 1;
        // Lower end: bisect between the last non-physical sample and the first physical one.
        let (size_lo, load_at_lo) =
            if j0 == 0 { (0.0, 0.0) } else { boundary(&mut at, (grid[j0], vals[j0].unwrap_or(0.0)), grid[j0 - 1])? };
        // Upper end.
        let open_above = j1 == n - 1;
        let (size_hi, load_at_hi) = if open_above {
            (grid[j1], vals[j1].unwrap_or(0.0))
        } else {
            boundary(&mut at, (grid[j1], vals[j1].unwrap_or(0.0)), grid[j1 + 1])?
        };
        // Loads over the run: samples, ends, and the largest sample refined by golden section.
        let mut hi = if load_at_lo > load_at_hi { (load_at_lo, size_lo) } else { (load_at_hi, size_hi) };
        let mut load_lo = if size_lo > 0.0 { load_at_lo.min(load_at_hi) } else { 0.0 };
        let mut jbest = j0;
        for k in j0..=j1 {
            let v = vals[k].unwrap_or(0.0);
            if v > hi.0 {
                hi = (v, grid[k]);
                jbest = k;
            }
            if size_lo > 0.0 {
                load_lo = load_lo.min(v);
            }
        }
        if hi.1 != size_hi && hi.1 != size_lo {
            let g = 0.5 * (5f64.sqrt() - 1.0);
            let (mut lo, mut up) =
                (if jbest == 0 { 0.5 * grid[0] } else { grid[jbest - 1] }, grid[(jbest + 1).min(n - 1)]);
            lo = lo.max(size_lo);
            up = up.min(size_hi);
            for _ in 0..GOLDEN_STEPS {
                let x1 = up - g * (up - lo);
                let x2 = lo + g * (up - lo);
                let f1 = best(&mut at, x1)?.unwrap_or(f64::NEG_INFINITY);
                let f2 = best(&mut at, x2)?.unwrap_or(f64::NEG_INFINITY);
                if f1 > hi.0 {
                    hi = (f1, x1);
                }
                if f2 > hi.0 {
                    hi = (f2, x2);
                }
                if f1 >= f2 {
                    up = x2;
                } else {
                    lo = x1;
                }
            }
        }
        runs.push(Run { size_lo, size_hi, open_above, load_lo, load_hi: hi });
    }
    Ok(Admissible { runs })
}
