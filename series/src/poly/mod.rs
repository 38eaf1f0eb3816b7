//! Multivariate polynomials over Q in named symbols, in common-denominator form.
//!
//! Representation (canonical, checked in debug builds): a list of terms `(monomial, numerator)`
//! sorted by monomial, numerators non-zero integers, one positive denominator `den`, and
//! `gcd(den, all numerators) = 1`. The zero polynomial has no terms and `den = 1`. Keeping one
//! denominator costs one content gcd per operation instead of a gcd per coefficient (FLINT's
//! `fmpq_poly` does the same).

mod coprime;
mod gcd;
mod heu;

use crate::ring::{q_latex, q_text, Q};
use crate::{Ring, Symbol};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};
use std::collections::BTreeMap;

/// A monomial: symbols with positive exponents, sorted by symbol name.
#[derive(Clone, PartialEq, Eq, Hash, PartialOrd, Ord, Debug, Default)]
pub struct Monomial(Vec<(Symbol, u32)>);

impl Monomial {
    /// The monomial 1.
    pub fn one() -> Self {
        Monomial(Vec::new())
    }
    /// `s^e` (the monomial 1 when `e == 0`).
    pub fn power(s: Symbol, e: u32) -> Self {
        if e == 0 {
            Monomial::one()
        } else {
            Monomial(vec![(s, e)])
        }
    }
    /// The factors `(symbol, exponent)`, sorted by symbol.
    pub fn factors(&self) -> &[(Symbol, u32)] {
        &self.0
    }
    /// Total degree.
    pub fn degree(&self) -> u32 {
        self.0.iter().map(|&(_, e)| e).sum()
    }
    /// Exponent of `s`.
    pub fn exponent(&self, s: Symbol) -> u32 {
        self.0.iter().find(|&&(t, _)| t == s).map_or(0, |&(_, e)| e)
    }
    /// The product of two monomials.
    pub fn mul(&self, other: &Monomial) -> Monomial {
        if self.0.is_empty() {
            return other.clone();
        }
        if other.0.is_empty() {
            return self.clone();
        }
        let mut out = Vec::with_capacity(self.0.len() + other.0.len());
        let (mut i, mut j) = (0, 0);
        while i < self.0.len() && j < other.0.len() {
            let (a, b) = (self.0[i], other.0[j]);
            match a.0.cmp(&b.0) {
                std::cmp::Ordering::Less => {
                    out.push(a);
                    i += 1;
                }
                std::cmp::Ordering::Greater => {
                    out.push(b);
                    j += 1;
                }
                std::cmp::Ordering::Equal => {
                    out.push((a.0, a.1 + b.1));
                    i += 1;
                    j += 1;
                }
            }
        }
        out.extend_from_slice(&self.0[i..]);
        out.extend_from_slice(&other.0[j..]);
        Monomial(out)
    }
    /// This monomial without the symbol `s`, and the exponent `s` had.
    pub fn remove(&self, s: Symbol) -> (Monomial, u32) {
        let e = self.exponent(s);
        (Monomial(self.0.iter().copied().filter(|&(t, _)| t != s).collect()), e)
    }
    fn text(&self) -> String {
        self.0
            .iter()
            .map(|&(s, e)| if e == 1 { s.name().to_string() } else { format!("{}^{e}", s.name()) })
            .collect::<Vec<_>>()
            .join("*")
    }
    fn latex(&self) -> String {
        self.0
            .iter()
            .map(|&(s, e)| if e == 1 { s.latex() } else { format!("{}^{{{e}}}", s.latex()) })
            .collect::<Vec<_>>()
            .join(" ")
    }
}

/// A polynomial over Q in named symbols (see the module doc for the canonical form).
///
/// ```
/// use exact_series::{Poly, Ring, Q};
/// let theta = Poly::var("theta").unwrap();
/// let alpha = theta.add(&Poly::from_q(&Q::new(1.into(), 2.into()))); // 1/2 + theta
/// assert_eq!(alpha.mul(&alpha).text(), "theta^2 + theta + 1/4");
/// ```
#[derive(Clone, PartialEq, Eq, Hash, Debug)]
pub struct Poly {
    terms: Vec<(Monomial, BigInt)>,
    den: BigInt,
}

impl Poly {
    /// The polynomial consisting of the single symbol `name`.
    pub fn var(name: &str) -> Result<Poly, crate::SeriesError> {
        Ok(Poly::symbol(Symbol::new(name)?))
    }
    /// The polynomial `s`.
    pub fn symbol(s: Symbol) -> Poly {
        Poly { terms: vec![(Monomial::power(s, 1), BigInt::one())], den: BigInt::one() }
    }
    /// `q * m` for a rational `q` and a monomial `m`.
    pub fn term(q: &Q, m: Monomial) -> Poly {
        if Zero::is_zero(q) {
            return <Poly as Ring>::zero();
        }
        Poly { terms: vec![(m, q.numer().clone())], den: q.denom().clone() }
    }
    /// The terms as `(monomial, rational coefficient)`, in the internal (sorted) order.
    pub fn terms(&self) -> impl Iterator<Item = (&Monomial, Q)> + '_ {
        self.terms.iter().map(move |(m, n)| (m, Q::new(n.clone(), self.den.clone())))
    }
    /// Number of terms.
    pub fn len(&self) -> usize {
        self.terms.len()
    }
    /// Whether there are no terms (the zero polynomial).
    pub fn is_empty(&self) -> bool {
        self.terms.is_empty()
    }
    /// The coefficient of the monomial `m` (0 when absent).
    pub fn coefficient(&self, m: &Monomial) -> Q {
        match self.terms.binary_search_by(|(t, _)| t.cmp(m)) {
            Ok(i) => Q::new(self.terms[i].1.clone(), self.den.clone()),
            Err(_) => <Q as Zero>::zero(),
        }
    }
    /// The symbols that occur, sorted by name.
    pub fn symbols(&self) -> Vec<Symbol> {
        let mut v: Vec<Symbol> = Vec::new();
        for (m, _) in &self.terms {
            for &(s, _) in &m.0 {
                if !v.contains(&s) {
                    v.push(s);
                }
            }
        }
        v.sort();
        v
    }
    /// Degree in the symbol `s`.
    pub fn degree_in(&self, s: Symbol) -> u32 {
        self.terms.iter().map(|(m, _)| m.exponent(s)).max().unwrap_or(0)
    }
    /// Total degree (0 for constants and for zero).
    pub fn total_degree(&self) -> u32 {
        self.terms.iter().map(|(m, _)| m.degree()).max().unwrap_or(0)
    }

    /// Substitutes the exact rational `value` for the symbol `s`.
    ///
    /// ```
    /// use exact_series::{Poly, Ring, Symbol, Q};
    /// let t = Symbol::new("theta").unwrap();
    /// let p = Poly::symbol(t).mul(&Poly::symbol(t)).add(&Poly::from_int(1)); // theta^2 + 1
    /// assert_eq!(p.subs(t, &Q::new(1.into(), 3.into())).text(), "10/9");
    /// ```
    pub fn subs(&self, s: Symbol, value: &Q) -> Poly {
        let mut acc: BTreeMap<Monomial, Q> = BTreeMap::new();
        for (m, c) in self.terms() {
            let (rest, e) = m.remove(s);
            let v = c * num_traits::pow(value.clone(), e as usize);
            let entry = acc.entry(rest).or_insert_with(<Q as Zero>::zero);
            *entry += v;
        }
        Poly::from_rational_terms(acc)
    }

    /// Exact division `self / d`; `None` when `d` does not divide `self` (or `d = 0`).
    ///
    /// ```
    /// use exact_series::{Poly, Ring};
    /// let t = Poly::var("theta").unwrap();
    /// let p = t.mul(&t).sub(&Poly::one()); // theta^2 - 1
    /// assert_eq!(p.div_exact(&t.add(&Poly::one())).unwrap().text(), "theta - 1");
    /// assert!(p.div_exact(&t).is_none());
    /// ```
    pub fn div_exact(&self, d: &Poly) -> Option<Poly> {
        gcd::div_exact(self, d)
    }

    /// The coefficient of the leading monomial in pure lex order (symbols by name, the
    /// alphabetically first most significant); 0 for the zero polynomial.
    pub fn leading_coefficient_lex(&self) -> Q {
        if self.is_zero() {
            return <Q as Zero>::zero();
        }
        gcd::leading(self).1
    }

    /// The monic greatest common divisor (lex-leading coefficient 1; gcd(0, 0) = 0).
    pub fn gcd(&self, other: &Poly) -> Poly {
        gcd::gcd(self, other)
    }

    /// The monic gcd `g` with the cofactors `self / g` and `other / g` (both non-zero; for
    /// zeros the cofactors are computed by [`Poly::div_exact`] as well).
    ///
    /// ```
    /// use exact_series::{Poly, Ring};
    /// let (a, b) = (Poly::var("a").unwrap(), Poly::var("b").unwrap());
    /// let g = a.add(&b); // a + b
    /// let (x, y) = (g.mul(&a.sub(&b)), g.mul(&g).mul_int(3));
    /// let (d, fx, fy) = x.gcd_cofactors(&y);
    /// assert_eq!((d, fx, fy), (g.clone(), a.sub(&b), g.mul_int(3)));
    /// ```
    pub fn gcd_cofactors(&self, other: &Poly) -> (Poly, Poly, Poly) {
        gcd::gcd_cofactors(self, other)
    }

    /// Substitutes the polynomial `value` for the symbol `s`.
    pub fn subs_poly(&self, s: Symbol, value: &Poly) -> Poly {
        let mut out = <Poly as Ring>::zero();
        for (m, c) in self.terms() {
            let (rest, e) = m.remove(s);
            let mut t = Poly::term(&c, rest);
            for _ in 0..e {
                t = t.mul(value);
            }
            out = out.add(&t);
        }
        out
    }

    /// Builds a polynomial from `(monomial, rational)` pairs (zeros dropped, canonical form).
    pub fn from_rational_terms(terms: impl IntoIterator<Item = (Monomial, Q)>) -> Poly {
        let mut map: BTreeMap<Monomial, Q> = BTreeMap::new();
        for (m, q) in terms {
            *map.entry(m).or_insert_with(<Q as Zero>::zero) += q;
        }
        let mut den = BigInt::one();
        for q in map.values() {
            if !Zero::is_zero(q) {
                den = den.lcm(q.denom());
            }
        }
        let terms = map
            .into_iter()
            .filter(|(_, q)| !Zero::is_zero(q))
            .map(|(m, q)| {
                let n = q.numer() * (&den / q.denom());
                (m, n)
            })
            .collect();
        Poly::normalized(terms, den)
    }

    /// The associate of `self` with coprime integer coefficients (denominator 1, the gcd of the
    /// numerators divided out by GMP's gcd) and the sign of its first term positive: the scalar
    /// normalisation of the gcd's remainder sequence, where any non-zero multiple will do.
    pub(crate) fn primitive_integer(&self) -> Poly {
        let Some(first) = self.terms.first() else { return self.clone() };
        let mut g = first.1.abs();
        for (_, n) in &self.terms[1..] {
            if g.is_one() {
                break;
            }
            g = crate::gmp::gcd(&g, n);
        }
        if first.1.is_negative() {
            g = -g;
        }
        let terms = self.terms.iter().map(|(m, n)| (m.clone(), n / &g)).collect();
        Poly { terms, den: BigInt::one() }
    }

    /// The coefficients of `self` as a polynomial in `x`: `self = sum_k c_k x^k`, `c_k` free of
    /// `x` (index k). Works on the integer numerators and the common denominator directly (each
    /// part reduced by its content with GMP's gcd), with no rational per term.
    pub(crate) fn split_in(&self, x: Symbol) -> Vec<Poly> {
        let d = self.degree_in(x) as usize;
        let mut parts: Vec<Vec<(Monomial, BigInt)>> = vec![Vec::new(); d + 1];
        for (m, n) in &self.terms {
            let (rest, e) = m.remove(x);
            parts[e as usize].push((rest, n.clone()));
        }
        parts
            .into_iter()
            .map(|mut t| {
                t.sort_by(|a, b| a.0.cmp(&b.0));
                Poly::normalized(t, self.den.clone())
            })
            .collect()
    }

    fn normalized(terms: Vec<(Monomial, BigInt)>, mut den: BigInt) -> Poly {
        let mut terms: Vec<(Monomial, BigInt)> = terms.into_iter().filter(|(_, n)| !n.is_zero()).collect();
        if terms.is_empty() {
            return Poly { terms, den: BigInt::one() };
        }
        if den.is_negative() {
            den = -den;
            for t in terms.iter_mut() {
                t.1 = -std::mem::take(&mut t.1);
            }
        }
        if !den.is_one() {
            let mut g = den.clone();
            for (_, n) in &terms {
                g = crate::gmp::gcd(&g, n);
                if g.is_one() {
                    break;
                }
            }
            if !g.is_one() {
                den /= &g;
                for t in terms.iter_mut() {
                    t.1 /= &g;
                }
            }
        }
        let p = Poly { terms, den };
        // The content was divided out just above; re-deriving it here (a big-integer gcd per
        // call) dominated debug builds, so the debug check is structural. Tests call
        // `is_canonical` in full.
        debug_assert!(p.is_structurally_canonical());
        p
    }

    /// The canonical form of the module doc (content 1 included).
    #[cfg(test)]
    pub(crate) fn is_canonical(&self) -> bool {
        self.is_structurally_canonical() && (self.terms.is_empty() && self.den.is_one() || self.content_is_one())
    }

    /// Sorted distinct monomials, non-zero numerators, positive exponents, den > 0.
    fn is_structurally_canonical(&self) -> bool {
        self.den.is_positive()
            && self.terms.windows(2).all(|w| w[0].0 < w[1].0)
            && self.terms.iter().all(|(m, n)| !n.is_zero() && m.0.iter().all(|&(_, e)| e > 0))
    }

    #[cfg(test)]
    /// Whether gcd(den, all numerators) = 1, stopping at the first partial gcd equal to 1 (the
    /// debug check of every result: a full fold over large numerators dominated debug builds).
    fn content_is_one(&self) -> bool {
        let mut g = self.den.clone();
        for (_, n) in &self.terms {
            if g.is_one() {
                return true;
            }
            g = crate::gmp::gcd(&g, n);
        }
        g.is_one()
    }

    /// Prints the terms in print order with the given forms of a rational and of a monomial,
    /// joined as `c<sep>m` (the coefficient 1 is omitted), signs pulled out as " + " / " - ".
    fn render(&self, coeff: fn(&Q) -> String, mono: fn(&Monomial) -> String, sep: &str) -> String {
        if self.terms.is_empty() {
            return "0".to_string();
        }
        let mut s = String::new();
        for (i, (m, q)) in self.print_order().into_iter().enumerate() {
            let neg = q.is_negative();
            let a = q.abs();
            if i == 0 {
                if neg {
                    s.push('-');
                }
            } else {
                s.push_str(if neg { " - " } else { " + " });
            }
            if m.0.is_empty() {
                s.push_str(&coeff(&a));
            } else if One::is_one(&a) {
                s.push_str(&mono(m));
            } else {
                s.push_str(&format!("{}{sep}{}", coeff(&a), mono(m)));
            }
        }
        s
    }

    /// Terms in print order: higher total degree first, then reverse internal order.
    fn print_order(&self) -> Vec<(&Monomial, Q)> {
        let mut v: Vec<(&Monomial, Q)> = self.terms().collect();
        v.sort_by(|a, b| b.0.degree().cmp(&a.0.degree()).then_with(|| b.0.cmp(a.0)));
        v
    }

    /// Evaluates every symbol through `value` (e.g. into `f64` or MPFR in the main crate):
    /// returns the list of `(rational coefficient, [(symbol, exponent)])` for the caller to sum.
    pub fn rational_terms(&self) -> Vec<(Q, Vec<(Symbol, u32)>)> {
        self.terms().map(|(m, q)| (q, m.0.clone())).collect()
    }

    fn merge(a: &Poly, sa: &BigInt, b: &Poly, sb: &BigInt, negate_b: bool) -> Vec<(Monomial, BigInt)> {
        let mut out = Vec::with_capacity(a.terms.len() + b.terms.len());
        let (mut i, mut j) = (0, 0);
        let fb = |n: &BigInt| if negate_b { -(n * sb) } else { n * sb };
        while i < a.terms.len() && j < b.terms.len() {
            match a.terms[i].0.cmp(&b.terms[j].0) {
                std::cmp::Ordering::Less => {
                    out.push((a.terms[i].0.clone(), &a.terms[i].1 * sa));
                    i += 1;
                }
                std::cmp::Ordering::Greater => {
                    out.push((b.terms[j].0.clone(), fb(&b.terms[j].1)));
                    j += 1;
                }
                std::cmp::Ordering::Equal => {
                    let n = &a.terms[i].1 * sa + fb(&b.terms[j].1);
                    if !n.is_zero() {
                        out.push((a.terms[i].0.clone(), n));
                    }
                    i += 1;
                    j += 1;
                }
            }
        }
        out.extend(a.terms[i..].iter().map(|(m, n)| (m.clone(), n * sa)));
        out.extend(b.terms[j..].iter().map(|(m, n)| (m.clone(), fb(n))));
        out
    }

    fn add_sub(&self, other: &Poly, negate: bool) -> Poly {
        let mut r = self.add_raw(other, negate);
        r.canonicalize();
        r
    }

    /// `self +- other` without the final content reduction (terms sorted, den > 0).
    fn add_raw(&self, other: &Poly, negate: bool) -> Poly {
        if other.terms.is_empty() {
            return self.clone();
        }
        if self.terms.is_empty() {
            return if negate { other.neg() } else { other.clone() };
        }
        if self.den == other.den {
            let one = BigInt::one();
            let t = Poly::merge(self, &one, other, &one, negate);
            return Poly { terms: t, den: self.den.clone() };
        }
        let g = crate::gmp::gcd(&self.den, &other.den);
        let sa = &other.den / &g;
        let sb = &self.den / &g;
        let den = &self.den * &sa;
        Poly { terms: Poly::merge(self, &sa, other, &sb, negate), den }
    }

    /// The single symbol of a univariate polynomial (`Ok(None)` for a constant), `Err` otherwise.
    fn univariate_symbol(&self) -> Result<Option<Symbol>, ()> {
        let mut sym = None;
        for (m, _) in &self.terms {
            match m.0.as_slice() {
                [] => {}
                [(s, _)] => match sym {
                    None => sym = Some(*s),
                    Some(t) if t == *s => {}
                    Some(_) => return Err(()),
                },
                _ => return Err(()),
            }
        }
        Ok(sym)
    }

    /// The product without content reduction: `(terms, den)` with `den = den_a den_b`.
    fn mul_raw(&self, other: &Poly) -> (Vec<(Monomial, BigInt)>, BigInt) {
        let den = &self.den * &other.den;
        if self.terms.is_empty() || other.terms.is_empty() {
            return (Vec::new(), BigInt::one());
        }
        // A constant factor scales the other polynomial.
        if self.terms.len() == 1 && self.terms[0].0 .0.is_empty() {
            let n = &self.terms[0].1;
            return (other.terms.iter().map(|(m, x)| (m.clone(), x * n)).collect(), den);
        }
        if other.terms.len() == 1 && other.terms[0].0 .0.is_empty() {
            let n = &other.terms[0].1;
            return (self.terms.iter().map(|(m, x)| (m.clone(), x * n)).collect(), den);
        }
        // Univariate in one common symbol: dense convolution by exponent.
        if let (Ok(sa), Ok(sb)) = (self.univariate_symbol(), other.univariate_symbol())
            && (sa.is_none() || sb.is_none() || sa == sb)
        {
            let s = sa.or(sb).expect("non-constant: handled above");
            let exp = |m: &Monomial| m.0.first().map_or(0, |&(_, e)| e as usize);
            let da = self.terms.iter().map(|(m, _)| exp(m)).max().unwrap_or(0);
            let db = other.terms.iter().map(|(m, _)| exp(m)).max().unwrap_or(0);
            let mut acc = vec![BigInt::zero(); da + db + 1];
            for (ma, na) in &self.terms {
                let ea = exp(ma);
                for (mb, nb) in &other.terms {
                    acc[ea + exp(mb)] += na * nb;
                }
            }
            let terms = acc
                .into_iter()
                .enumerate()
                .filter(|(_, n)| !n.is_zero())
                .map(|(e, n)| (Monomial::power(s, e as u32), n))
                .collect();
            return (terms, den);
        }
        let terms = self.mul_dense(other).unwrap_or_else(|| self.mul_sparse(other));
        (terms, den)
    }

    /// The product's terms through a map keyed by monomial (any number of symbols).
    fn mul_sparse(&self, other: &Poly) -> Vec<(Monomial, BigInt)> {
        let mut acc: BTreeMap<Monomial, BigInt> = BTreeMap::new();
        for (ma, na) in &self.terms {
            for (mb, nb) in &other.terms {
                let m = ma.mul(mb);
                let v = na * nb;
                match acc.entry(m) {
                    std::collections::btree_map::Entry::Vacant(e) => {
                        e.insert(v);
                    }
                    std::collections::btree_map::Entry::Occupied(mut e) => {
                        *e.get_mut() += v;
                    }
                }
            }
        }
        acc.into_iter().filter(|(_, n)| !n.is_zero()).collect()
    }
}

impl Poly {
    /// The product's terms by dense accumulation over GMP integers: every exponent vector of the
    /// product indexes one slot of the box of its degrees (mixed radix), each slot a GMP
    /// multiply-add (no allocation per product term, no map); the non-zero slots are put in
    /// [`Monomial`] order by a packed key ([`monomial_order_key`]). `None` (the caller's sparse
    /// map decides) for more than 4 symbols, or when the box is more than 16 times the number of
    /// term products or above 2^22 slots.
    fn mul_dense(&self, other: &Poly) -> Option<Vec<(Monomial, BigInt)>> {
        let mut syms = self.symbols();
        for s in other.symbols() {
            if !syms.contains(&s) {
                syms.push(s);
            }
        }
        syms.sort();
        if syms.len() > 4 {
            return None;
        }
        let pairs = self.terms.len().checked_mul(other.terms.len())?;
        // (stride, dim) per symbol, in name order.
        let mut radix: Vec<(usize, usize)> = Vec::with_capacity(syms.len());
        let mut slots: usize = 1;
        for &s in &syms {
            let d = (self.degree_in(s) + other.degree_in(s)) as usize + 1;
            radix.push((slots, d));
            slots = slots.checked_mul(d)?;
            if slots > (1 << 22) || slots > 16 * pairs || d >= 0xFFFF {
                return None;
            }
        }
        let index = |m: &Monomial| -> usize {
            m.0.iter().map(|&(s, e)| radix[syms.binary_search(&s).expect("symbol")].0 * e as usize).sum()
        };
        let a: Vec<(usize, rug::Integer)> = self.terms.iter().map(|(m, n)| (index(m), crate::gmp::to_rug(n))).collect();
        let b: Vec<(usize, rug::Integer)> =
            other.terms.iter().map(|(m, n)| (index(m), crate::gmp::to_rug(n))).collect();
        let mut acc: Vec<rug::Integer> = (0..slots).map(|_| rug::Integer::new()).collect();
        for (ia, na) in &a {
            for (ib, nb) in &b {
                acc[ia + ib] += na * nb;
            }
        }
        let exps = |k: usize| radix.iter().map(move |&(stride, dim)| ((k / stride) % dim) as u32);
        let mut keyed: Vec<(u64, usize)> = acc
            .iter()
            .enumerate()
            .filter(|(_, n)| n.cmp0() != std::cmp::Ordering::Equal)
            .map(|(k, _)| (monomial_order_key(exps(k)), k))
            .collect();
        keyed.sort_unstable();
        let terms = keyed
            .into_iter()
            .map(|(_, k)| {
                let f = syms.iter().copied().zip(exps(k)).filter(|&(_, e)| e > 0).collect();
                (Monomial(f), crate::gmp::to_big(&acc[k]))
            })
            .collect();
        Some(terms)
    }
}

/// A `u64` whose order is [`Monomial`]'s (lexicographic on the list of non-zero factors, symbols
/// by name) for the exponents of at most 4 symbols in name order, each below 0xFFFF: per symbol
/// 16 bits, the exponent when positive, 0xFFFF when zero but a later symbol occurs (a list that
/// skips a symbol starts with a later one: greater), 0 when no later symbol occurs (a list that
/// ends there is a prefix: smaller).
fn monomial_order_key(exps: impl Iterator<Item = u32>) -> u64 {
    let mut e = [0u32; 4];
    for (slot, x) in e.iter_mut().zip(exps) {
        *slot = x;
    }
    // From the last symbol back: whether a later symbol occurs.
    let mut key = 0u64;
    let mut later = false;
    for i in (0..4).rev() {
        let field = if e[i] > 0 {
            u64::from(e[i])
        } else if later {
            0xFFFF
        } else {
            0
        };
        later |= e[i] > 0;
        key |= field << (16 * (3 - i));
    }
    key
}

impl Ring for Poly {
    fn zero() -> Self {
        Poly { terms: Vec::new(), den: BigInt::one() }
    }
    fn one() -> Self {
        Poly { terms: vec![(Monomial::one(), BigInt::one())], den: BigInt::one() }
    }
    fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }
    fn add(&self, other: &Self) -> Self {
        self.add_sub(other, false)
    }
    fn sub(&self, other: &Self) -> Self {
        self.add_sub(other, true)
    }
    fn neg(&self) -> Self {
        Poly { terms: self.terms.iter().map(|(m, n)| (m.clone(), -n)).collect(), den: self.den.clone() }
    }
    fn mul(&self, other: &Self) -> Self {
        let (t, d) = self.mul_raw(other);
        Poly::normalized(t, d)
    }
    fn fma_lazy(&mut self, a: &Self, b: &Self) {
        if a.terms.is_empty() || b.terms.is_empty() {
            return;
        }
        let (t, d) = a.mul_raw(b);
        let prod = Poly { terms: t, den: d };
        *self = self.add_raw(&prod, false);
    }
    fn canonicalize(&mut self) {
        let terms = std::mem::take(&mut self.terms);
        let den = std::mem::replace(&mut self.den, BigInt::one());
        *self = Poly::normalized(terms, den);
    }
    fn from_q(q: &Q) -> Self {
        Poly::term(q, Monomial::one())
    }
    fn as_q(&self) -> Option<Q> {
        match self.terms.as_slice() {
            [] => Some(<Q as Zero>::zero()),
            [(m, n)] if m.0.is_empty() => Some(Q::new(n.clone(), self.den.clone())),
            _ => None,
        }
    }
    fn inv(&self) -> Option<Self> {
        self.as_q().filter(|q| !Zero::is_zero(q)).map(|q| Poly::from_q(&q.recip()))
    }
    fn text(&self) -> String {
        self.render(q_text, Monomial::text, "*")
    }
    fn latex(&self) -> String {
        self.render(q_latex, Monomial::latex, " ")
    }
    fn is_sum(&self) -> bool {
        self.terms.len() > 1
    }
    fn scale(&self, q: &Q) -> Self {
        if Zero::is_zero(q) || self.terms.is_empty() {
            return Poly::zero();
        }
        let t = self.terms.iter().map(|(m, n)| (m.clone(), n * q.numer())).collect();
        Poly::normalized(t, &self.den * q.denom())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn arb_poly() -> impl Strategy<Value = Poly> {
        let terms = proptest::collection::vec((proptest::collection::vec(0u32..4, 4), -50i64..=50), 0..=12);
        (terms, 1usize..=4).prop_map(|(terms, nsym)| {
            let syms = ["B", "S", "a", "eps"].map(|s| Symbol::new(s).unwrap());
            Poly::from_rational_terms(terms.into_iter().map(|(e, c)| {
                let m = (0..nsym).fold(Monomial::one(), |m, k| m.mul(&Monomial::power(syms[k], e[k])));
                (m, Q::from_integer(c.into()))
            }))
        })
    }

    static DENSE: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(128))]
        /// The dense GMP product gives the sparse map's terms in the same (Monomial) order, and
        /// the packed order key sorts exponent vectors as `Monomial`'s order does.
        #[test]
        fn dense_product_matches_the_sparse_one(a in arb_poly(), b in arb_poly()) {
            if let Some(d) = a.mul_dense(&b) {
                DENSE.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                prop_assert_eq!(d, a.mul_sparse(&b));
            } else {
                prop_assert!(a.is_zero() || b.is_zero() || a.terms.len() * b.terms.len() * 16 < 4096);
            }
            let syms = ["B", "S", "a", "eps"].map(|s| Symbol::new(s).unwrap());
            let ms: Vec<&Monomial> = a.terms.iter().chain(&b.terms).map(|(m, _)| m).collect();
            for x in &ms {
                for y in &ms {
                    let key = |m: &Monomial| monomial_order_key(syms.iter().map(|&s| m.exponent(s)));
                    prop_assert_eq!(key(x).cmp(&key(y)), x.cmp(y));
                }
            }
        }
    }

    /// The property above took the dense route in most cases (else it would test nothing).
    #[test]
    fn dense_route_is_exercised() {
        dense_product_matches_the_sparse_one();
        assert!(DENSE.load(std::sync::atomic::Ordering::Relaxed) > 40);
    }
}
