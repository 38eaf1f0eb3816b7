//! Regenerates coefficient tables into a folder: for each object, the exact coefficients as
//! JSON (`<object>.json`, the CLI's `--format json`) and as plain text (`<object>.txt`).
//!
//! ```sh
//! cargo run --example regenerate -- coefficients 12
//! ```
//! (folder, order; defaults `coefficients`, 8). Review the diff before committing them.

use periodic_contact::api;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let dir = std::path::PathBuf::from(args.next().unwrap_or_else(|| "coefficients".into()));
    let order: usize = args.next().map(|s| s.parse()).transpose()?.unwrap_or(8);
    std::fs::create_dir_all(&dir)?;
    let jobs: [(&str, &str, Vec<(&str, &str)>); 4] = [
        ("kernel", "kernel", vec![]),
        ("jacobi", "jacobi", vec![]),
        ("sliding_theta_1_10", "sliding", vec![("theta", "1/10")]),
        ("adhesion", "adhesion", vec![]),
    ];
    for (name, object, options) in jobs {
        let request = options.iter().fold(api::SeriesRequest::new(object, order), |r, (k, v)| r.option(k, v));
        let d = api::derive(&request)?;
        let json = dir.join(format!("{name}.json"));
        std::fs::write(&json, serde_json::to_string_pretty(&d.json())? + "\n")?;
        std::fs::write(dir.join(format!("{name}.txt")), d.text())?;
        println!("wrote {} (order {order})", json.display());
    }
    Ok(())
}
