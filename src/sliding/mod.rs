pub mod collocation_f64;
