//! The single-punch (order-0) system of the loading-law expansion (`asymptotics::loading_law`,
//! module doc "The exact question"): g_0 = c/l and f_0 = 2 C_0 against n, and their Taylor
//! coefficients in n at n = 0 by Richardson extrapolation in n^2 (g_0 is odd, f_0 even in n).
//! Run: `cargo run --release --example loading_law_single_punch`.

use periodic_contact::asymptotics::loading_law::law_coefficients;
use periodic_contact::model::{Exact, Material};
use periodic_contact::numerics::tanh_sinh::TanhSinh;
use periodic_contact::params::adhesion::AdhesionParamsMpfr;
use rug::Float;

const PREC: u32 = 260;

fn order0(params: &AdhesionParamsMpfr, n: &Float) -> (Float, Float) {
    try_order0(params, n).unwrap()
}

fn try_order0(params: &AdhesionParamsMpfr, n: &Float) -> Result<(Float, Float), String> {
    let rule = TanhSinh::new(PREC - 20, 1.0, PREC);
    let e = law_coefficients(params, n, 1, &rule, PREC).map_err(|e| e.to_string())?;
    Ok((e.f[0].clone(), e.g[0].clone()))
}

fn main() {
    for (num, den) in [(3, 10), (1, 4), (0, 1), (9, 20)] {
        let nu = Exact::new(num.into(), den.into());
        let material = Material::from_contact_modulus(nu.clone(), Exact::from_integer(1.into())).unwrap();
        let params = AdhesionParamsMpfr::new(&material, PREC);
        let eps = params.eps.clone();
        let e2 = Float::with_val(PREC, eps.square_ref());
        let g1 = -(Float::with_val(PREC, &eps * 2u32)) / (1u32 - Float::with_val(PREC, &e2 * 4u32));
        let f00 = Float::with_val(PREC, &params.load_constant * 2u32);
        println!("nu = {nu}: eps = {}, B = {}, S = {}", eps.to_f64(), params.b.to_f64(), params.s.to_f64());
        for n in [0.001, 0.2, 0.5, 1.0, 2.0, 3.0, 4.0, 6.0, 10.0] {
            let nf = Float::with_val(PREC, n);
            match try_order0(&params, &nf) {
                Ok((f, g)) => println!(
                    "  n = {n}: g_0 = {:.20}, g_0/n = {:.12}, f_0 = {:.20}",
                    g.to_f64(),
                    g.to_f64() / n,
                    f.to_f64()
                ),
                Err(e) => println!("  n = {n}: {e}"),
            }
        }
        // Richardson: h = 1e-6 * 2^k; (g/n - g1)/n^2 -> g3, (f - f00)/n^2 -> f2, each + O(n^2).
        let mut g3 = Vec::new();
        let mut f2 = Vec::new();
        for k in 0..3 {
            let h = Float::with_val(PREC, 1e-8) * Float::with_val(PREC, 1u32 << k);
            let (f, g) = order0(&params, &h);
            let h2 = Float::with_val(PREC, h.square_ref());
            g3.push((Float::with_val(PREC, &g / &h) - &g1) / &h2);
            f2.push((f - &f00) / h2);
        }
        let rich = |v: &[Float]| {
            let a = Float::with_val(PREC, &v[0] * 4u32) - &v[1];
            let b = Float::with_val(PREC, &v[1] * 4u32) - &v[2];
            (Float::with_val(PREC, &a * 16u32) / 3u32 - Float::with_val(PREC, &b / 3u32)) / 15u32
        };
        println!(
            "  g_0 = g1 n + g3 n^3 + ...: g1 = {:.20} (-2 eps/(1 - 4 eps^2)), g3 = {:.15}",
            g1.to_f64(),
            rich(&g3).to_f64()
        );
        println!("  f_0 = f00 + f2 n^2 + ...: f00 = {:.20} (2 C_P), f2 = {:.15}", f00.to_f64(), rich(&f2).to_f64());
    }
}
