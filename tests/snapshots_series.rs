//! insta snapshots of every foundation object through order 12 (the regenerated coefficient
//! tables, reviewed like code). Snapshot files live in the top-level `snapshots/` folder.

use periodic_contact::asymptotics::catalog::{SeriesObject, Substitutions};

fn snap(name: &str, object: SeriesObject, subs: Substitutions) {
    let d = object.derive(12, &subs).unwrap();
    let mut settings = insta::Settings::clone_current();
    settings.set_snapshot_path("../snapshots");
    settings.set_prepend_module_to_snapshot(false);
    settings.bind(|| {
        insta::assert_snapshot!(format!("{name}_text"), d.text());
        insta::assert_snapshot!(format!("{name}_latex"), d.latex());
        insta::assert_json_snapshot!(format!("{name}_json"), d.json());
    });
}

#[test]
fn kernel_order12() {
    snap(
        "kernel_order12",
        SeriesObject::Kernel,
        Substitutions::default(),
    );
}

#[test]
fn weight_order12() {
    snap(
        "weight_order12",
        SeriesObject::Weight,
        Substitutions::default(),
    );
}

#[test]
fn weight_order12_theta_1_10() {
    let subs = Substitutions {
        theta: Some(exact_series::Q::new(1.into(), 10.into())),
        xh: None,
    };
    snap("weight_order12_theta_1_10", SeriesObject::Weight, subs);
}

#[test]
fn jacobi_order12() {
    snap(
        "jacobi_order12",
        SeriesObject::Jacobi,
        Substitutions::default(),
    );
}
