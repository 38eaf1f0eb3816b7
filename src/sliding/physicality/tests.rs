use super::admissible::{admissible, SizeContacts};
use super::*;

/// Hertz (single punch, theta = 0, g = k x^2, E* = 1): p = 2 k sqrt(a^2 - x^2), so p/omega = 2 k a
/// (omega = sqrt(1 - u^2), x = a u); off the contact h' = 2 k sqrt(x^2 - a^2) sign(x), so the
/// surface slope is w = g' - h' = 2 k (x - sqrt(x^2 - a^2) sign(x)), and h = k (|x|
/// sqrt(x^2 - a^2) - a^2 acosh(|x|/a)) in closed form.
struct Hertz {
    k: f64,
    a: f64,
    /// A constant added to the slope (to make the gap fail on purpose).
    tilt: f64,
    /// A constant added to p/omega near u = 1 (to make p fail).
    dent: f64,
}

impl ContactFunctions for Hertz {
    fn pressure_factor(&self, u: f64) -> f64 {
        2.0 * self.k * self.a + if u > 0.99 { self.dent } else { 0.0 }
    }
    fn surface_slope(&self, xi: f64) -> f64 {
        2.0 * self.k * xi - (2.0 * self.k * (xi * xi - self.a * self.a).max(0.0).sqrt() * xi.signum() + self.tilt)
    }
    fn profile_height(&self, x: f64) -> f64 {
        self.k * x * x
    }
}

fn single(a: f64) -> Setting {
    Setting {
        convention: Convention::Paper,
        cell: Cell::Unbounded,
        a,
        b: a,
        edge_step: 0.0,
        closure_formula: 0.0,
        pressure_tol: 1e-9,
        extent: None,
        closure_tol: CLOSURE_TOL,
    }
}

#[test]
fn hertz_is_admissible_and_its_gap_matches_the_closed_form() {
    let (k, a) = (1.0, 0.3);
    let f = Hertz { k, a, tilt: 0.0, dent: 0.0 };
    let r = assess(&f, &single(a)).expect("Hertz is physical");
    assert_eq!(r.min_gap, 0.0);
    assert_eq!(r.closure_defect, None);
    assert!(r.warning.is_none());
    // The integrated gap at 4 l beyond the leading end against the closed form.
    let side = gap_side(&f, 0.0, a, 4.0 * a, 1.0);
    let (x, h) = side.last().map(|v| (v.x, v.h)).unwrap();
    let exact = k * (x * (x * x - a * a).sqrt() - a * a * (x / a).acosh());
    assert!((h - exact).abs() < 1e-10 * exact, "{h} vs {exact}");
    // By symmetry the trailing side ends at the same height.
    let back = gap_side(&f, 0.0, -a, 4.0 * a, -1.0);
    assert!((back.last().unwrap().h - h).abs() < 1e-12 * h);
}

#[test]
fn negative_pressure_is_refused_with_the_place() {
    let f = Hertz { k: 1.0, a: 0.3, tilt: 0.0, dent: -1.0 };
    match assess(&f, &single(0.3)) {
        Err(Refusal::NegativePressure { u, relative }) => {
            assert!(u > 0.99 && relative < 0.0, "{u} {relative}");
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_negative_gap_refuses_where_the_surface_closes_and_warns_where_it_does_not() {
    // A tilt of the slope makes the gap negative beyond the trailing end (h = -int over (x, -a)).
    let f = Hertz { k: 1.0, a: 0.1, tilt: 0.3, dent: 0.0 };
    let big_l = 1.0;
    // Periodic: refused. The two halves then differ by 2 tilt (L/2 - l), which is not 0: the
    // closure check catches it first, as it must (this slope cannot come from a closed surface).
    let periodic =
        Setting { convention: Convention::PeriodicSurface, cell: Cell::Periodic { period: big_l }, ..single(0.1) };
    assert!(matches!(assess(&f, &periodic), Err(Refusal::Inconsistent { .. })));
    // Paper with the closure defect the tilt implies (M = 2 tilt (L/2 - l)): a warning.
    let m = 2.0 * 0.3 * (0.5 * big_l - 0.1);
    let paper = Setting { cell: Cell::Periodic { period: big_l }, closure_formula: m, ..single(0.1) };
    let r = assess(&f, &paper).expect("paper: a warning, not a refusal");
    assert!(r.min_gap < 0.0 && r.min_gap_x < -0.1, "{r:?}");
    let defect = r.closure_defect.expect("measured");
    assert!((defect - m).abs() < 1e-9, "{defect}");
    assert!(r.warning.as_deref().unwrap_or("").contains("closure defect"), "{r:?}");
    // Single punch: refused as a negative gap, from the trailing end.
    match assess(&f, &single(0.1)) {
        Err(Refusal::NegativeGap { h, x, from }) => {
            assert!(h < 0.0 && x < -0.1 && from == End::Trailing, "{h} {x} {from:?}");
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn the_edge_step_is_left_out_and_the_closure_accounts_for_it() {
    // A closed surface (periodic) whose criterion slope is the Hertz-like one: the full slope has
    // -edge_step in it; the halves of the criterion's gap differ by edge_step (L - 2 l).
    struct Closed;
    impl ContactFunctions for Closed {
        fn pressure_factor(&self, _: f64) -> f64 {
            1.0
        }
        // A flat profile and a gap slope odd in xi: the two halves of the full gap (slope -
        // step) then differ by exactly 2 step reach, which the closure check removes.
        fn surface_slope(&self, xi: f64) -> f64 {
            -(xi * xi - 0.01f64).max(0.0).sqrt() * xi.signum()
        }
        fn profile_height(&self, _: f64) -> f64 {
            0.0
        }
    }
    let s = Setting {
        convention: Convention::PeriodicSurface,
        cell: Cell::Periodic { period: 1.0 },
        a: 0.1,
        b: 0.1,
        edge_step: 0.0,
        closure_formula: 0.0,
        pressure_tol: 1e-9,
        extent: None,
        closure_tol: CLOSURE_TOL,
    };
    // Without a step the odd slope gives halves of equal height: closes.
    let r = assess(&Closed, &s).expect("closes");
    assert!(r.closure_defect.expect("measured").abs() < 1e-12, "{:?}", r.closure_defect);
    // With a step the criterion's halves differ by 2 step reach; the check accounts for it, and
    // the defect of the full slope is -2 step reach (not 0): refused as inconsistent.
    let with_step = Setting { edge_step: 0.01, ..s };
    match assess(&Closed, &with_step) {
        Err(Refusal::Inconsistent { measured, expected }) => {
            assert!((measured + 0.01 * 2.0 * 0.4).abs() < 1e-12 && expected == 0.0, "{measured}");
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_contact_outside_its_cell_is_refused() {
    let f = Hertz { k: 1.0, a: 0.3, tilt: 0.0, dent: 0.0 };
    let s = Setting { cell: Cell::Fixed { half_period: 0.5 }, a: 0.2, b: 0.55, ..single(0.3) };
    assert!(matches!(assess(&f, &s), Err(Refusal::OutsideCell { .. })));
    assert!(Refusal::OutsideCell { neg_a: -0.2, b: 0.55, half_period: 0.5 }.why().contains("leaves the cell"));
}

#[test]
fn admissible_runs_find_the_ends_and_an_interior_maximum() {
    // Load s (1 - s) physical for s < 0.7 and for s in (0.9, 1.2): two runs; the first has its
    // maximum 1/4 inside (at s = 1/2), the second its largest load at its lower end.
    let at = |s: f64| -> Result<SizeContacts, ()> { Ok(vec![(s * (1.3 - s), s < 0.7 || (s > 0.9 && s < 1.2))]) };
    let adm = admissible(1.45, at).unwrap();
    assert_eq!(adm.runs.len(), 2, "{adm:?}");
    let (r0, r1) = (&adm.runs[0], &adm.runs[1]);
    assert_eq!(r0.size_lo, 0.0);
    assert!((r0.size_hi - 0.7).abs() < 1e-9, "{}", r0.size_hi);
    assert!((r0.load_hi.0 - 0.4225).abs() < 1e-12 && (r0.load_hi.1 - 0.65).abs() < 1e-5, "{:?}", r0.load_hi);
    assert!((r1.size_lo - 0.9).abs() < 1e-9 && (r1.size_hi - 1.2).abs() < 1e-9, "{r1:?}");
    assert!((r1.load_lo - 1.2 * 0.1).abs() < 1e-8 && (r1.load_hi.0 - 0.9 * 0.4).abs() < 1e-8, "{r1:?}");
    assert!(!r1.open_above);
    assert_eq!(adm.max_load().map(|m| m.0), Some(r0.load_hi.0));
    assert!(adm.carries(0.3) && !adm.carries(0.43));
    let text = adm.loads_text(1.0, |s| s, "lambda");
    assert!(text.starts_with("physical contacts carry normal_load in (0, 0.4225]"), "{text}");
}

#[test]
fn a_step_of_the_profile_at_the_cell_edge_enters_the_gap() {
    // The profile g = x/5 on the cell (-1/2, 1/2), repeated: it steps by g(-1/2) - g(1/2) = -1/5
    // crossing x = 1/2 to the right. With a gap slope odd about the centre c = 0.05 (so x = 1/2 is
    // inside the leading half) the halves differ by exactly that step.
    struct Ramp;
    impl ContactFunctions for Ramp {
        fn pressure_factor(&self, _: f64) -> f64 {
            1.0
        }
        fn surface_slope(&self, xi: f64) -> f64 {
            0.2 - (xi * xi - 0.01f64).max(0.0).sqrt() * xi.signum()
        }
        fn profile_height(&self, x: f64) -> f64 {
            0.2 * (x - x.round())
        }
    }
    let s = Setting {
        convention: Convention::Paper,
        cell: Cell::Fixed { half_period: 0.5 },
        a: 0.05,
        b: 0.15,
        edge_step: 0.0,
        closure_formula: -0.2,
        pressure_tol: 1e-9,
        extent: None,
        closure_tol: CLOSURE_TOL,
    };
    let r = assess(&Ramp, &s).expect("the step is the closure defect");
    assert!((r.closure_defect.unwrap() + 0.2).abs() < 1e-9, "{:?}", r.closure_defect);
    // In `periodic` the same surface cannot close: a numerical failure, not physics.
    let e = assess(&Ramp, &Setting { convention: Convention::PeriodicSurface, ..s }).unwrap_err();
    assert!(!e.is_physical(), "{e:?}");
}

/// The gap samples of [`gap_side`] (4 dyadic panels of 16-point Gauss–Legendre, partial panels by
/// the interpolant) against a fine reference (512 panels of 8-point Gauss–Legendre in the same s,
/// the integral accumulated exactly to each sample), for a slope with the end singularity
/// d^(1/2 - theta) of p's continuation at theta = +-0.45 and 0, and a complex pole at a distance
/// of 2 l behind the end (the other contact end's scale), on both sides, for a single punch's
/// reach (4 l), a short one and long ones (small contacts in a period).
#[test]
fn the_gap_quadrature_matches_a_fine_reference() {
    struct Singular {
        alpha: f64,
        l: f64,
    }
    impl ContactFunctions for Singular {
        fn pressure_factor(&self, _: f64) -> f64 {
            1.0
        }
        fn surface_slope(&self, xi: f64) -> f64 {
            let d = xi.abs() - self.l;
            let t = (d + 2.0 * self.l) / self.l;
            xi.signum() * (d.max(0.0).powf(self.alpha) * (1.0 + 0.3 * d) + 1.0 / (1.0 + t * t))
        }
        fn profile_height(&self, x: f64) -> f64 {
            0.7 * x * x
        }
    }
    let gl = gauss_jacobi(8, 0.0, 0.0).unwrap();
    for theta in [-0.45, 0.0, 0.45] {
        for (l, reach) in [(0.1, 0.4), (0.45, 0.05), (0.01, 0.49), (1e-4, 0.4999)] {
            for dir in [1.0, -1.0] {
                let f = Singular { alpha: 0.5 - theta, l };
                let start = dir * l;
                let side = gap_side(&f, 0.0, start, reach, dir);
                assert_eq!(side.len(), 32);
                let panels = 512;
                let mut w_int = 0.0;
                let mut hmax = 0.0f64;
                let mut worst = 0.0f64;
                for j in 0..panels {
                    let (s0, s1) = (j as f64 / panels as f64, (j + 1) as f64 / panels as f64);
                    let mut inc = 0.0;
                    for (z, w) in gl.nodes.iter().zip(&gl.weights) {
                        let s = 0.5 * (s0 + s1) + 0.5 * (s1 - s0) * z;
                        inc += w * f.surface_slope(start + dir * reach * s.powi(4)) * 4.0 * reach * s.powi(3);
                    }
                    w_int += dir * inc * 0.5 * (s1 - s0);
                    if (j + 1) % (panels / 32) == 0 {
                        let GapSample { x, h, .. } = side[(j + 1) / (panels / 32) - 1];
                        let x_ref = start + dir * reach * s1.powi(4);
                        assert_eq!(x, x_ref);
                        let h_ref = f.profile_height(x) - f.profile_height(start) - w_int;
                        hmax = hmax.max(h_ref.abs());
                        worst = worst.max((h - h_ref).abs());
                    }
                }
                // Observed at most 4.1e-12 (theta = -0.45, l = 0.01).
                assert!(worst <= 1e-11 * hmax, "theta {theta} l {l} dir {dir}: {worst:e} of {hmax:e}");
            }
        }
    }
}

/// A Hertz contact (k = 0.34, a = 3.5e-10) moved to c = -2.3e-5, 6.6e4 half-lengths off the
/// origin of its profile k x^2 (issue 34, fuzz seed 2026 case 3960: adhesive friction at a tiny
/// load): the surface slope there is 2 k c plus Hertz's, and the heights k x^2 ~ 1.8e-10 dwarf the
/// gap (at most ~7e-19 within 4 a). With the rise g(x) - g(end) in its cancellation-free form
/// ([`crate::params::sliding::row_rise_f64`]) and the rounding bound [`GAP_ROUNDING`], the
/// criterion admits it (the plain difference of heights, the default `profile_rise`, loses
/// eps k c^2 = 4e-26, far beyond [`GAP_TOL`] of the largest gap, and refused it), and still refuses
/// it tilted by 1e-6 of its surface slope.
#[test]
fn a_contact_far_off_the_origin_keeps_its_gap() {
    struct Off {
        k: f64,
        a: f64,
        c: f64,
        tilt: f64,
        exact_rise: bool,
    }
    impl ContactFunctions for Off {
        fn pressure_factor(&self, _: f64) -> f64 {
            2.0 * self.k * self.a
        }
        fn surface_slope(&self, xi: f64) -> f64 {
            let (k, a) = (self.k, self.a);
            2.0 * k * (self.c + xi) - 2.0 * k * (xi * xi - a * a).max(0.0).sqrt() * xi.signum() - self.tilt
        }
        fn profile_height(&self, x: f64) -> f64 {
            self.k * x * x
        }
        fn profile_rise(&self, end: f64, dx: f64) -> f64 {
            if self.exact_rise {
                crate::params::sliding::row_rise_f64(&ShapeF64::Parabolic { k: self.k }, None, end, dx)
            } else {
                self.profile_height(end + dx) - self.profile_height(end)
            }
        }
    }
    use crate::params::sliding::ShapeF64;
    let (k, a, c) = (25.0 / 74.0, 3.5e-10, -2.3e-5);
    let setting = Setting { a: a - c, b: a + c, ..single(a) };
    let off = Off { k, a, c, tilt: 0.0, exact_rise: true };
    let r = assess(&off, &setting).expect("Hertz off the origin is physical");
    assert_eq!(r.min_gap, 0.0);
    // The gap 4 a beyond the leading end against Hertz's closed form.
    let side = gap_side(&off, c, a, 4.0 * a, 1.0);
    let (xi, h) = side.last().map(|v| (v.x - c, v.h)).unwrap();
    let exact = k * (xi * (xi * xi - a * a).sqrt() - a * a * (xi / a).acosh());
    assert!((h - exact).abs() < 1e-9 * exact, "{h:e} vs {exact:e}");
    // The plain difference of heights: refused for a gap of the size of its rounding.
    let plain = Off { exact_rise: false, ..off };
    assert!(matches!(assess(&plain, &setting), Err(Refusal::NegativeGap { .. })), "plain difference admitted");
    // A tilt of 1e-6 of the slope 2 k |c| (the gap behind the trailing end falls to about
    // -tilt d/3 = -4e-24 at d = (2 tilt/(3 C))^2 ~ 8e-13, C = (4/3) k sqrt(2 a) of Hertz's
    // d^(3/2); 1e-5 of the largest gap, far beyond the rounding) is still refused.
    let tilted = Off { tilt: 1e-6 * 2.0 * k * c.abs(), ..off };
    match assess(&tilted, &setting) {
        Err(Refusal::NegativeGap { h, from, .. }) => assert!(h < 0.0 && from == End::Trailing, "{h} {from:?}"),
        other => panic!("tilted contact admitted: {other:?}"),
    }
}
