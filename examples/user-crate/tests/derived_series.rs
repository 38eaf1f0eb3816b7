//! The user's own snapshot of a derived series: l/l_s of the sliding parabola at theta = 1/10
//! through Lambda^8, kept in `tests/snapshots/` and reviewed like code. A change in the library
//! that changes a coefficient fails here (`cargo insta review` to accept a deliberate one).

use periodic_contact_user_example::sliding_part;

#[test]
fn l_over_ls_at_theta_one_tenth() {
    let coefficients = sliding_part("l_over_ls", "1/10", 8).unwrap();
    let table: String = coefficients.iter().map(|c| format!("Lambda^{}: {}\n", c.power, c.text)).collect();
    insta::assert_snapshot!("l_over_ls_theta_1_10_order_8", table);

    // Independent checks of the first two corrections from the general formulas in theta
    // (paper [3.11]; `periodic-contact series sliding --order 4`):
    // [Lambda^2] = theta^2/3 - 1/12, [Lambda^4] = 73/270 theta^4 - 41/540 theta^2 + 1/480.
    let (t2, t4) = ((1i128, 100i128), (1i128, 10_000i128));
    let add = |(a, b): (i128, i128), (c, d): (i128, i128)| reduce((a * d + c * b, b * d));
    let mul = |(a, b): (i128, i128), (c, d): (i128, i128)| reduce((a * c, b * d));
    let c2 = add(mul((1, 3), t2), (-1, 12));
    let c4 = add(add(mul((73, 270), t4), mul((-41, 540), t2)), (1, 480));
    assert_eq!(coefficients[1].text, text(c2));
    assert_eq!(coefficients[2].text, text(c4));
    assert_eq!((coefficients[1].power, coefficients[2].power), (2, 4));
}

fn gcd(a: i128, b: i128) -> i128 {
    if b == 0 {
        a.abs()
    } else {
        gcd(b, a % b)
    }
}

fn reduce((n, d): (i128, i128)) -> (i128, i128) {
    let g = gcd(n, d).max(1) * d.signum();
    (n / g, d / g)
}

fn text((n, d): (i128, i128)) -> String {
    if d == 1 {
        n.to_string()
    } else {
        format!("{n}/{d}")
    }
}
