//! insta snapshots of every foundation object through order 12 (the regenerated coefficient
//! tables, reviewed like code). Snapshot files live in the top-level `snapshots/` folder.

use periodic_contact::asymptotics::catalog::{derive_sliding, SeriesObject, Substitutions};
use periodic_contact::asymptotics::sliding::SlidingShape;
use periodic_contact::model::Convention;

fn snap(name: &str, object: SeriesObject, subs: Substitutions) {
    snap_parts(name, object.derive(12, &subs).unwrap());
}

fn snap_parts(name: &str, parts: Vec<periodic_contact::asymptotics::catalog::Derived>) {
    let mut settings = insta::Settings::clone_current();
    settings.set_snapshot_path("../../snapshots");
    settings.set_prepend_module_to_snapshot(false);
    settings.bind(|| {
        if let [d] = parts.as_slice() {
            insta::assert_snapshot!(format!("{name}_text"), d.text());
            insta::assert_snapshot!(format!("{name}_latex"), d.latex());
            insta::assert_json_snapshot!(format!("{name}_json"), d.json());
        } else {
            let text: Vec<String> = parts.iter().map(|d| d.text()).collect();
            let latex: Vec<String> = parts.iter().map(|d| d.latex()).collect();
            let json: Vec<serde_json::Value> = parts.iter().map(|d| d.json()).collect();
            insta::assert_snapshot!(format!("{name}_text"), text.join("\n"));
            insta::assert_snapshot!(format!("{name}_latex"), latex.join("\n"));
            insta::assert_json_snapshot!(format!("{name}_json"), json);
        }
    });
}

#[test]
fn kernel_order12() {
    snap("kernel_order12", SeriesObject::Kernel, Substitutions::default());
}

#[test]
fn weight_order12() {
    snap("weight_order12", SeriesObject::Weight, Substitutions::default());
}

#[test]
fn weight_order12_theta_1_10() {
    let subs = Substitutions { theta: Some(exact_series::Q::new(1.into(), 10.into())), ..Substitutions::default() };
    snap("weight_order12_theta_1_10", SeriesObject::Weight, subs);
}

#[test]
fn jacobi_order12() {
    snap("jacobi_order12", SeriesObject::Jacobi, Substitutions::default());
}

#[test]
fn sliding_parabolic_order12() {
    snap("sliding_parabolic_order12", SeriesObject::Sliding(SlidingShape::Parabolic), Substitutions::default());
}

#[test]
fn sliding_sinusoidal_order12() {
    snap("sliding_sinusoidal_order12", SeriesObject::Sliding(SlidingShape::Sinusoidal), Substitutions::default());
}

#[test]
fn adhesion_order12_nu_3_10() {
    // A_n through n = 13 and c_n through lambda^12, exact in eps, B, S, with their values at nu = 3/10.
    let subs = Substitutions { nu: Some(exact_series::Q::new(3.into(), 10.into())), ..Substitutions::default() };
    snap("adhesion_order12_nu_3_10", SeriesObject::Adhesion, subs);
}

#[test]
fn sliding_periodic_parabolic_order12() {
    let parts = derive_sliding(SlidingShape::Parabolic, Convention::PeriodicSurface, 12, &Substitutions::default());
    snap_parts("sliding_periodic_parabolic_order12", parts.unwrap());
}

#[test]
fn sliding_periodic_sinusoidal_order12() {
    let parts = derive_sliding(SlidingShape::Sinusoidal, Convention::PeriodicSurface, 12, &Substitutions::default());
    snap_parts("sliding_periodic_sinusoidal_order12", parts.unwrap());
}

#[test]
fn derive_sliding_paper_is_the_catalog_object() {
    for shape in [SlidingShape::Parabolic, SlidingShape::Sinusoidal] {
        let a = derive_sliding(shape, Convention::Paper, 12, &Substitutions::default()).unwrap();
        let b = SeriesObject::Sliding(shape).derive(12, &Substitutions::default()).unwrap();
        let text =
            |v: &[periodic_contact::asymptotics::catalog::Derived]| v.iter().map(|d| d.text()).collect::<Vec<_>>();
        assert_eq!(text(&a), text(&b));
    }
}
