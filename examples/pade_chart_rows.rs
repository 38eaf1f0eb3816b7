//! The Pade resummation's table (docs/theory.md section 11): per object and lambda the digits of
//! the plain sum, the Pade approximant and the conformal map + Pade against the verified
//! references, printed with the wall time (about 50 s at the default plan: the sinusoid's symbolic
//! series through Lambda^24):
//! `cargo run --release --example pade_chart_rows [-- report]`.
//! Default plan: orders 24 (Problem 1) and 16 (Problem 2), references at 30 digits; `report`: the
//! default report's plan (orders 16, 12, 12; 20 digits). Another argument stops it with a message
//! naming the argument and the valid form, and exit code 2.

use periodic_contact::verification::pade::{pade_rows, PadePlan, LAMBDAS};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let report = match args.as_slice() {
        [] => false,
        [a] if a == "report" => true,
        _ => {
            eprintln!("pade_chart_rows: arguments {args:?}: expected none or `report`");
            std::process::exit(2)
        }
    };
    let t0 = std::time::Instant::now();
    let plan = if report {
        PadePlan::report()
    } else {
        PadePlan { parabola: 24, sinusoid: 24, adhesion: 16, lambdas: LAMBDAS.to_vec(), digits: 30 }
    };
    for r in &pade_rows(&plan) {
        println!(
            "{:12} {:4} w={:8.4} plain={:?} pade={:?} conformal={:?} ref={} refusal={:?}",
            r.object,
            r.lambda,
            r.w,
            r.plain.map(|x| (x * 10.0).round() / 10.0),
            r.pade,
            r.conformal,
            r.reference,
            r.refusal
        );
    }
    println!("wall {:.2} s", t0.elapsed().as_secs_f64());
}
