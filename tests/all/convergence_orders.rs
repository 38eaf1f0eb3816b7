//! The Problem 1 series against the high-precision solution, term by term: the remainder after m
//! corrections scales like Lambda^(2m+2), m = 1..8, for several (theta, T); fitted slopes within
//! 0.1 of the prediction (sliding issue).

use exact_series::Q;
use periodic_contact::verification::convergence::{parabola_case, sliding_convergence};

fn q(n: i64, d: i64) -> Q {
    Q::new(n.into(), d.into())
}

#[test]
fn series_remainders_have_the_predicted_orders() {
    let lambdas = [0.03, 0.042, 0.06, 0.085];
    let cases = [
        ("frictionless", parabola_case(q(3, 10), q(0, 1), q(0, 1), q(0, 1), q(1, 100))),
        ("friction mu = 0.3", parabola_case(q(3, 10), q(3, 10), q(0, 1), q(0, 1), q(1, 100))),
        ("wear cW = 0.4", parabola_case(q(1, 4), q(0, 1), q(0, 1), q(2, 5), q(1, 100))),
        ("friction + tau0", parabola_case(q(3, 10), q(1, 5), q(1, 500), q(0, 1), q(1, 100))),
    ];
    for (label, p) in cases {
        let study = sliding_convergence(label, &p, &lambdas, 8, 60).unwrap();
        eprintln!("{label}: theta = {:.5}, T = {:.5}, Lambda = {:?}", study.theta, study.t, study.lambdas);
        for row in &study.rows {
            eprintln!(
                "  m = {}: observed {:.4} (c: {:?}) predicted {} remainder {:.1e}..{:.1e}",
                row.corrections,
                row.observed_l,
                row.observed_c.map(|x| (x * 1e4).round() / 1e4),
                row.predicted,
                row.remainder_range.0,
                row.remainder_range.1
            );
            let ok = (row.observed_l - row.predicted_l).abs() < 0.1;
            assert!(
                ok,
                "{label} (theta = {}, T = {}): m = {}, observed {} vs {}",
                study.theta, study.t, row.corrections, row.observed_l, row.predicted
            );
            if let Some(oc) = row.observed_c {
                assert!((oc - row.predicted).abs() < 0.1, "{label}: centre, m = {}: {oc}", row.corrections);
            }
        }
    }
}
