//! The loading law's limit n = 0 checked against the symmetric solver of complete adhesion
//! (docs/theory.md section 10): section 4's problem, by the collocation alone (the load to 1e-17
//! at 16 nodes) and by the verified solve (b = a, P2, the loading path and the fields at the same
//! points). Tests only: the two methods live side by side in [`crate::loading_law`] and
//! [`crate::adhesion`], and neither imports the other.

#[cfg(test)]
mod tests {
    use crate::adhesion::volterra_mpfr::{solve as volterra_solve, VolterraParams};
    use crate::loading_law::collocation::{self, LawSetting};
    use crate::loading_law::verified;
    use crate::model::{Convention, Exact, LawSize, LoadingLaw, LoadingLawProblem, Material, Period, PunchShape};
    use crate::params::adhesion::AdhesionParamsMpfr;
    use num_traits::Signed;
    use rug::Float;

    fn material(nu: (i64, i64)) -> Material {
        Material::from_contact_modulus(Exact::new(nu.0.into(), nu.1.into()), Exact::from_integer(1.into())).unwrap()
    }

    fn q(n: i64, d: i64) -> Exact {
        Exact::new(n.into(), d.into())
    }

    /// n = 0: the symmetric problem of section 4 (gamma = 0, the same load as the Volterra
    /// method's at 30 digits). The error is the collocation's: 16 nodes 1.3e-18, 24 nodes 1.2e-26,
    /// 32 nodes 1.3e-34 at Lambda = 0.5, nu = 0.3 (`LAW_NODES=24 cargo test --release --lib
    /// verification::law_limits::tests::zero -- --nocapture`).
    #[test]
    fn zero_ratio_is_the_symmetric_solution() {
        let m = material((3, 10));
        // l/L = 100000/628318, Lambda = pi l/L = 0.49999...
        let size = Exact::new(100000.into(), 628318.into());
        let setting = LawSetting::linear(m.clone(), Exact::from_integer(0.into()), size, Convention::Paper);
        let t = std::time::Instant::now();
        let nodes: usize = std::env::var("LAW_NODES").ok().and_then(|v| v.parse().ok()).unwrap_or(16);
        let sol = collocation::solve(&setting, nodes, 100, 140).unwrap();
        eprintln!("{:.2}s, {} steps, residual {:.1e}", t.elapsed().as_secs_f64(), sol.steps, sol.residual);
        let params = VolterraParams::for_digits(30);
        let constants = AdhesionParamsMpfr::new(&m, params.prec);
        let lam = Float::with_val(params.prec, &sol.lambda_max);
        let sym = volterra_solve(&constants, &lam, params).unwrap();
        let p_sym = sym.load_ratio() * Float::with_val(params.prec, lam.square_ref());
        let p = sol.load();
        let rel = Float::with_val(140, &p - &p_sym).to_f64() / p_sym.to_f64();
        eprintln!("P = {} vs {}: rel {rel:.1e}; c/l = {:.1e}", p.to_f64(), p_sym.to_f64(), sol.centre_ratio().to_f64());
        let tol = [(16, 1e-17), (24, 1e-25), (32, 1e-33)].iter().find(|(n, _)| *n == nodes).map_or(1e-17, |v| v.1);
        assert!(rel.abs() < tol, "{rel:e}");
        assert!(sol.centre_ratio().abs().to_f64() < 1e-25);
    }

    /// Verified digits at 12 requested (20 requested, measured in session 4 with
    /// `cargo test --release --lib verification::law_limits -- --nocapture`: 23.6 verified, 27 nodes,
    /// 21.6 s), and the limit n = 0 against the symmetric solver
    /// (`adhesion::solve_verified`): b = a, P2 and the fields at the same points agree to the
    /// verified digits.
    #[test]
    fn verified_solution_and_the_symmetric_limit() {
        let material = Material::from_contact_modulus(q(3, 10), q(1, 1)).unwrap();
        let problem = LoadingLawProblem::new(
            material.clone(),
            Period::Finite(q(1, 1)),
            PunchShape::Parabolic { k: q(1, 1) },
            LoadingLaw::Linear(q(0, 1)),
            LawSize::HalfLength(q(1, 6)),
            Convention::Paper,
        )
        .unwrap();
        let xh = [q(-1, 2), q(1, 5), q(9, 10)];
        let t = std::time::Instant::now();
        let sol = verified::solve_law(&problem, &xh, 12).unwrap();
        eprintln!("{:.1}s, digits {:?}, nodes {}", t.elapsed().as_secs_f64(), sol.digits, sol.values.nodes);
        assert!(sol.digits.headline >= 12.0, "{:?}", sol.digits);
        let sym = crate::model::AdhesionProblem::new(
            material,
            crate::model::Period::Finite(q(1, 1)),
            crate::model::PunchShape::Parabolic { k: q(1, 1) },
            crate::model::AdhesionSize::HalfWidth(q(1, 6)),
        )
        .unwrap();
        let pts: Vec<Exact> = xh.iter().map(|h| h.abs()).collect();
        let s = crate::adhesion::solve_verified(&sym, &pts, 25).unwrap().solution;
        let v = &sol.values;
        let rel = |a: &Float, b: &Float, scale: f64| Float::with_val(200, a - b).to_f64().abs() / scale;
        assert!(rel(&v.p2, &s.normal_load, s.normal_load.to_f64()) < 1e-12);
        assert!(rel(&v.a, &v.b, 1.0) < 1e-12);
        // The loading path stays centred (n = 0), ends at the final contact, and its digits hold.
        assert_eq!(v.path.len(), verified::PATH_STEPS as usize);
        for p in &v.path {
            assert!(rel(&p.a, &p.b, p.l.to_f64()) < 1e-12, "path at l = {}", p.l);
        }
        assert!(rel(&v.path[verified::PATH_STEPS as usize - 1].p2, &v.p2, v.p2.to_f64()) < 1e-30);
        assert!(sol.digits.path >= 12.0, "{:?}", sol.digits);
        for (p, (h, r)) in v.points.iter().zip(xh.iter().zip(&s.points)) {
            // psi and q are even, phi odd in x.
            let sign = if h.is_negative() { -1.0 } else { 1.0 };
            let scale = s.half_width.to_f64();
            assert!(rel(&p.psi, &r.psi, scale) < 1e-12, "psi at {h}: {} vs {}", p.psi, r.psi);
            assert!((p.phi.to_f64() - sign * r.phi.to_f64()).abs() < 1e-12 * scale * scale, "phi at {h}");
            assert!(rel(&p.q1, &Float::with_val(200, &r.q1 * sign), scale) < 1e-12, "q1 at {h}: {} vs {}", p.q1, r.q1);
            assert!(rel(&p.q2, &r.q2, scale) < 1e-12, "q2 at {h}");
        }
    }
}
