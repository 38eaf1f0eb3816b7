//! Report section 12's Problem 2 stability map with friction (`src/friction_map.rs`, issue 32
//! Build item 5): its cells are direct `row_loads` runs (the convention's node rule). At nu = 0,
//! mu = 1/2, `paper`, on a column to lambda = 0.8: the top cell's two loads are the load solved at
//! 0.8 on `COARSE` and `FINE`, bit for bit; the cell at 0.4 (P from the column's collocation on
//! (0, 0.8)) is within the cell's own difference of the two discretisations of the load solved at
//! 0.4, so the digits it shows hold for the direct load too.

use periodic_contact::solve::answer_friction_row::{row_loads, COARSE, FINE};
use periodic_contact_report::friction_map::{column, MU};

#[test]
#[ignore = "long tier: 7.4 s of CPU in the test profile (opt-level 2; 18.8 s wall at load 10), 46 f64 increment roots (scripts/test --long)"]
fn the_cells_are_direct_row_loads() {
    let cells = column(0, 1, &[0.4, 0.8], false);
    let pair = |i: usize| cells[i].load.clone().unwrap_or_else(|e| panic!("cell {i} refused: {e}"));
    // nu = 0: beta = 1/2
    let direct = |lambda: f64, mesh| row_loads(0.5, MU, lambda, &[lambda], mesh, false).unwrap()[0];
    let (coarse, fine) = pair(1);
    assert_eq!((cells[1].nu, cells[1].lambda), (0.0, 0.8));
    assert_eq!(coarse.to_bits(), direct(0.8, COARSE).to_bits(), "{coarse}");
    assert_eq!(fine.to_bits(), direct(0.8, FINE).to_bits(), "{fine}");
    let (coarse, fine) = pair(0);
    let at = direct(0.4, FINE);
    eprintln!("lambda 0.4: column {fine} (coarse {coarse}), direct {at}: {:.1e}", fine / at - 1.0);
    assert!((fine - at).abs() <= (fine - coarse).abs(), "{fine} {coarse} {at}");
    let digits = cells[0].digits().unwrap();
    assert!((4.0..16.0).contains(&digits), "{digits}");
}
