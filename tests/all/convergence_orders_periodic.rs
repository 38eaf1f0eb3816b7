//! The `periodic` Problem 1 series (THEORY.md section 8) against the MPFR `periodic` solution,
//! term by term: keeping every term through Lambda^m (m = 1..8), the remainder of the centre c
//! scales like Lambda^(m+1) (the series hold every power of Lambda: not Lambda^(2m+2) per two
//! terms as in `paper`); the parabola's l/l_s is even in both conventions, so its remainder is
//! Lambda^(m+1) for odd m and Lambda^(m+2) for even m. Fitted slopes within 0.1.

use exact_series::Q;
use periodic_contact::model::Convention;
use periodic_contact::verification::convergence::{parabola_case, sliding_convergence};

fn q(n: i64, d: i64) -> Q {
    Q::new(n.into(), d.into())
}

#[test]
fn periodic_series_remainders_have_the_predicted_orders() {
    // Smaller than the paper study's (0.03..0.085): the pairs of terms Lambda^(m+1), Lambda^(m+2)
    // are of more similar size, so the slope needs a smaller Lambda to settle within 0.1.
    let lambdas = [0.01, 0.014, 0.02, 0.028];
    let cases = [
        ("friction mu = 0.3", parabola_case(q(3, 10), q(3, 10), q(0, 1), q(0, 1), q(1, 100))),
        ("friction + tau0", parabola_case(q(3, 10), q(1, 5), q(1, 500), q(0, 1), q(1, 100))),
        ("wear cW = 0.3", parabola_case(q(3, 10), q(0, 1), q(0, 1), q(3, 10), q(1, 100))),
    ];
    for (label, p) in cases {
        let p = p.to_builder().convention(Convention::PeriodicSurface).build().unwrap();
        let study = sliding_convergence(label, &p, &lambdas, 4, 60).unwrap();
        eprintln!("{label}: theta = {:.5}, T = {:.5}, Lambda = {:?}", study.theta, study.t, study.lambdas);
        assert_eq!(study.rows.len(), 8);
        for row in &study.rows {
            eprintln!(
                "  m = {}: l {:.4} (predicted {}), c {:?} (predicted {}), remainder of l {:.1e}..{:.1e}",
                row.corrections,
                row.observed_l,
                row.predicted_l,
                row.observed_c.map(|x| (x * 1e4).round() / 1e4),
                row.predicted,
                row.remainder_range.0,
                row.remainder_range.1
            );
            assert_eq!(row.predicted, (row.corrections + 1) as f64);
            assert!(
                (row.observed_l - row.predicted_l).abs() < 0.1,
                "{label}: l, m = {}: {} vs {}",
                row.corrections,
                row.observed_l,
                row.predicted_l
            );
            let oc = row.observed_c.expect("c does not vanish with friction or wear");
            assert!(
                (oc - row.predicted).abs() < 0.1,
                "{label}: centre, m = {}: {oc} vs {}",
                row.corrections,
                row.predicted
            );
        }
    }
}
