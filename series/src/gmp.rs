//! GMP (through `rug`) for the big-integer operations where num-bigint's algorithms are slow: the
//! gcd (num-bigint's is binary, quadratic in the length, and took 67% of `series sliding --order
//! 24` in `Poly`'s content reduction) and the conversions to and from [`rug::Integer`].

use num_bigint::{BigInt, BigUint, Sign};
use rug::integer::Order;
use rug::Integer;

/// A num-bigint integer as a GMP integer.
pub(crate) fn to_rug(b: &BigInt) -> Integer {
    if let Some(x) = num_traits::ToPrimitive::to_i64(b) {
        return Integer::from(x); // one word: no digit vector
    }
    let (sign, digits) = b.to_u32_digits();
    let i = Integer::from_digits(&digits, Order::Lsf);
    if sign == Sign::Minus {
        -i
    } else {
        i
    }
}

/// A GMP integer as a num-bigint integer.
pub(crate) fn to_big(i: &Integer) -> BigInt {
    if let Some(x) = i.to_i64() {
        return BigInt::from(x); // one word: no digit vector
    }
    let sign = match i.cmp0() {
        std::cmp::Ordering::Less => Sign::Minus,
        std::cmp::Ordering::Equal => Sign::NoSign,
        std::cmp::Ordering::Greater => Sign::Plus,
    };
    BigInt::from_biguint(sign, BigUint::new(i.to_digits::<u32>(Order::Lsf)))
}

/// `gcd(a, b) >= 0`: machine words when both fit in 128 bits, GMP above.
pub(crate) fn gcd(a: &BigInt, b: &BigInt) -> BigInt {
    if let (Some(x), Some(y)) =
        (num_traits::ToPrimitive::to_u128(a.magnitude()), num_traits::ToPrimitive::to_u128(b.magnitude()))
    {
        return BigInt::from(gcd_u128(x, y));
    }
    to_big(&to_rug(a).gcd(&to_rug(b)))
}

fn gcd_u128(mut a: u128, mut b: u128) -> u128 {
    while b != 0 {
        if a <= u64::MAX as u128 && b <= u64::MAX as u128 {
            let (mut x, mut y) = (a as u64, b as u64);
            while y != 0 {
                (x, y) = (y, x % y);
            }
            return x as u128;
        }
        (a, b) = (b, a % b);
    }
    a
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gcd_and_round_trip_match_num_bigint() {
        let a: BigInt = BigInt::from(3u32).pow(400) * BigInt::from(-7919i64) * BigInt::from(2u32).pow(90);
        let b: BigInt = BigInt::from(3u32).pow(250) * BigInt::from(104729u64) * BigInt::from(2u32).pow(200);
        assert_eq!(gcd(&a, &b), num_integer::Integer::gcd(&a, &b));
        assert_eq!(gcd(&a, &BigInt::from(0)), num_integer::Integer::gcd(&a, &BigInt::from(0)));
        assert_eq!(gcd(&BigInt::from(-12), &BigInt::from(18)), BigInt::from(6));
        let (c, d) = (BigInt::from(3u32).pow(70) * 5, BigInt::from(3u32).pow(60) * 7 * BigInt::from(2u32).pow(20));
        assert_eq!(gcd(&c, &d), BigInt::from(3u32).pow(60));
        assert_eq!(gcd(&BigInt::from(0), &BigInt::from(0)), BigInt::from(0));
        for x in [a.clone(), -a, b, BigInt::from(0), BigInt::from(-1)] {
            assert_eq!(to_big(&to_rug(&x)), x);
        }
        // the one-word fast paths at their edges, against the digit route
        for x in [i64::MIN as i128, i64::MIN as i128 - 1, i64::MAX as i128, i64::MAX as i128 + 1, -7, 1 << 70] {
            let b = BigInt::from(x);
            let r = to_rug(&b);
            assert_eq!(r, Integer::from(x));
            assert_eq!(to_big(&r), b);
        }
    }
}
