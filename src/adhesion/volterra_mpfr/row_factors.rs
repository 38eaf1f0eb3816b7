//! The material-free factors of the collocation rows (module doc of [`super`]), computed once per
//! process for every solve that shares them.
//!
//! Row i of the collocation system at lambda needs, at every tanh-sinh node s_q, the integrand
//! s w(s) G(chi_i, s) of [`kernel`] at chi_i = lambda sigma_i (docs/theory.md section 4). Of its
//! transcendental functions, the two sines of sinc(chi(1 +- s)), the logarithm of their ratio and
//! the square root of their product depend on chi and the node only
//! ([`kernel::VolterraNodes::factors`]: the modulus mag and the phase's bracket L, theta = eps L);
//! only the sinh/cosh of 2 eps chi s and the sine/cosine of theta depend on the material (eps)
//! and the convention. Solves at the same lambda, Chebyshev size, quadrature rule and precision,
//! such as the cells of a stability map's column (six values of nu at one lambda), share
//! (chi_i, sin chi_i, cos chi_i, mag_iq, L_iq): [`row_factors`] keeps them in a process cache,
//! keyed exactly, bounded by [`CACHE_BITS`] (the least recently used dropped first). The integrand from
//! these factors is [`kernel::integrand_from_factors`], whose roundings are those of the
//! one-piece [`kernel::VolterraNodes::integrand`]: the solution does not move by one bit (tests
//! below; the report's snapshot).
//!
//! Measured on the default report (docs/performance.md, "The report").

use super::kernel;
use crate::numerics::tanh_sinh::TanhSinh;
use rug::{Float, Integer};
use std::collections::{HashMap, VecDeque};
use std::sync::{Arc, Mutex, OnceLock, PoisonError};

/// The factors of one row: chi = lambda sigma, (sin chi, cos chi), and per node (mag, L).
#[derive(Debug)]
pub struct RowFactors {
    /// chi = lambda sigma_i.
    pub chi: Float,
    /// (sin chi, cos chi).
    pub sc_chi: (Float, Float),
    /// Per node q: (mag_q, L_q) of [`kernel::VolterraNodes::factors`].
    pub nodes: Vec<(Float, Float)>,
}

/// What fixes the factors exactly: lambda (mantissa and exponent; None for 0), the Chebyshev size,
/// the quadrature rule ([`TanhSinh::spec`]: its accuracy, refinement and precision fix its nodes),
/// and whether the nodes are sigma (`periodic`) or sigma^2 (`paper`).
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct FactorsKey {
    lambda: Option<(Integer, i32)>,
    n: usize,
    rule: (u32, u64, u32),
    in_sigma: bool,
}

impl FactorsKey {
    /// The key of a solve at `lambda` with `n` Chebyshev nodes and the tanh-sinh rule `rule`
    /// (the factors are computed at its precision); `in_sigma`: the nodes are sigma (`periodic`).
    pub fn new(lambda: &Float, n: usize, rule: &TanhSinh, in_sigma: bool) -> Self {
        FactorsKey { lambda: lambda.to_integer_exp(), n, rule: rule.spec(), in_sigma }
    }

    /// The precision of the factors: the rule's.
    fn prec(&self) -> u32 {
        self.rule.2
    }
}

/// Most mantissa bits the cache holds: 2^25 (4 MiB of mantissa, about 16 MiB with MPFR's
/// headers), some fifteen tables of a 20-digit verified solve (57 rows of 149 nodes at 131 bits:
/// 2.2e6 bits), more than the two threads of a report work on at one lambda.
pub const CACHE_BITS: u64 = 1 << 25;

type Slot = Arc<OnceLock<Arc<Vec<RowFactors>>>>;

/// The cache: a slot per key (two threads asking one key compute it once) and the filled keys
/// with their mantissa bits, least recently used first.
#[derive(Default)]
struct Cache {
    slots: HashMap<FactorsKey, Slot>,
    filled: VecDeque<(FactorsKey, u64)>,
    bits: u64,
}

impl Cache {
    /// Accounts the filled `key` of `bits`, then drops the least recently used keys while the
    /// cache passes `bound` (the newest is always kept).
    fn filled(&mut self, key: FactorsKey, bits: u64, bound: u64) {
        self.filled.push_back((key, bits));
        self.bits += bits;
        while self.bits > bound && self.filled.len() > 1 {
            if let Some((old, b)) = self.filled.pop_front() {
                self.slots.remove(&old);
                self.bits -= b;
            }
        }
    }

    /// Marks `key` (when filled) as the most recently used.
    fn used(&mut self, key: &FactorsKey) {
        if let Some(i) = self.filled.iter().position(|(k, _)| k == key)
            && let Some(e) = self.filled.remove(i)
        {
            self.filled.push_back(e);
        }
    }
}

fn cache() -> &'static Mutex<Cache> {
    static CACHE: OnceLock<Mutex<Cache>> = OnceLock::new();
    CACHE.get_or_init(Default::default)
}

/// Tables and mantissa bits the process cache holds now (for tests of its bound).
pub fn cache_size() -> (usize, u64) {
    let c = cache().lock().unwrap_or_else(PoisonError::into_inner);
    (c.filled.len(), c.bits)
}

/// The factors of the rows at the interpolation nodes `tau` (sigma^2, or sigma when
/// `key` says so) for the rule `rule` with its per-node constants `pre`, from the process cache
/// when a solve of the same `key` computed them before.
pub fn row_factors(
    key: FactorsKey,
    lambda: &Float,
    tau: &[Float],
    rule: &TanhSinh,
    pre: &kernel::VolterraNodes,
) -> Arc<Vec<RowFactors>> {
    let slot = cache().lock().unwrap_or_else(PoisonError::into_inner).slots.entry(key.clone()).or_default().clone();
    let mut computed = false;
    let table = slot
        .get_or_init(|| {
            computed = true;
            Arc::new(compute(lambda, tau, rule, pre, key.prec(), key.in_sigma))
        })
        .clone();
    let mut c = cache().lock().unwrap_or_else(PoisonError::into_inner);
    if computed {
        let bits = table.iter().map(|r| r.nodes.len() as u64).sum::<u64>() * 2 * u64::from(key.prec());
        c.filled(key, bits, CACHE_BITS);
    } else {
        c.used(&key);
    }
    table
}

/// The factors without the cache.
fn compute(
    lambda: &Float,
    tau: &[Float],
    rule: &TanhSinh,
    pre: &kernel::VolterraNodes,
    prec: u32,
    in_sigma: bool,
) -> Vec<RowFactors> {
    tau.iter()
        .map(|tau_i| {
            let sigma = if in_sigma { tau_i.clone() } else { Float::with_val(prec, tau_i.sqrt_ref()) };
            let chi = Float::with_val(prec, lambda * &sigma);
            let sc_chi = chi.clone().sin_cos(Float::new(prec));
            let nodes = (0..rule.len()).map(|q| pre.factors(q, &rule.c[q], &chi, prec)).collect();
            RowFactors { chi, sc_chi, nodes }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::chebyshev;

    #[test]
    fn cached_factors_give_the_one_piece_integrand_bit_for_bit() {
        // Two materials (eps) and both conventions at one lambda: the integrand from the shared
        // factors equals the one-piece evaluation, every bit.
        let prec = 107;
        let rule = TanhSinh::new(83, 1.0, prec);
        let pre = kernel::VolterraNodes::new(&rule.s, &rule.c, prec);
        let tau = chebyshev::nodes(9, prec);
        let lambda = Float::with_val(prec, 1.1);
        for in_sigma in [false, true] {
            let key = FactorsKey::new(&lambda, tau.len(), &rule, in_sigma);
            let first = row_factors(key.clone(), &lambda, &tau, &rule, &pre);
            let again = row_factors(key, &lambda, &tau, &rule, &pre);
            assert!(Arc::ptr_eq(&first, &again), "the second ask is served from the cache");
            let (tables, bits) = cache_size();
            assert!(tables >= 1 && (bits <= CACHE_BITS || tables == 1), "{tables} tables, {bits} bits");
            for eps in [0.0, 0.0566, 0.2206] {
                let eps = Float::with_val(prec, eps);
                let shift = in_sigma.then(|| kernel::LateralShift::new(&eps, prec));
                for (tau_i, row) in tau.iter().zip(first.iter()) {
                    let sigma = if in_sigma { tau_i.clone() } else { Float::with_val(prec, tau_i.sqrt_ref()) };
                    let chi = Float::with_val(prec, &lambda * &sigma);
                    let sc = chi.clone().sin_cos(Float::new(prec));
                    assert_eq!((&row.chi, &row.sc_chi), (&chi, &sc));
                    for (q, (mag, l)) in row.nodes.iter().enumerate() {
                        let (s, c) = (&rule.s[q], &rule.c[q]);
                        let want = pre.integrand(q, s, c, &chi, &sc, &eps, shift.as_ref(), prec);
                        let mut w = kernel::FactorScratch::new(prec);
                        let got = kernel::integrand_from_factors(
                            &mut w,
                            mag,
                            l,
                            s,
                            &row.chi,
                            &row.sc_chi,
                            &eps,
                            shift.as_ref(),
                        );
                        assert_eq!(got, want, "node {q}");
                    }
                }
            }
        }
    }

    #[test]
    fn the_cache_drops_its_least_recently_used_tables_beyond_the_bound() {
        // A private cache with a bound of three tables of 100 bits: the fourth drops the least
        // recently used (the second, the first having been used since), a table larger than the
        // bound alone is kept alone.
        let rule = TanhSinh::new(83, 1.0, 53);
        let key = |n| FactorsKey::new(&Float::with_val(53, 0.5), n, &rule, false);
        let mut c = Cache::default();
        for n in 1..=4 {
            c.slots.insert(key(n), Slot::default());
            c.filled(key(n), 100, 300);
            if n == 3 {
                c.used(&key(1));
            }
        }
        assert_eq!((c.filled.len(), c.bits), (3, 300));
        assert!(!c.slots.contains_key(&key(2)), "the least recently used is dropped");
        assert!(c.slots.contains_key(&key(1)) && c.slots.contains_key(&key(4)));
        c.slots.insert(key(5), Slot::default());
        c.filled(key(5), 1000, 300);
        assert_eq!((c.filled.len(), c.bits, c.slots.len()), (1, 1000, 1));
    }
}
