//! The objects of the asymptotic analysis (docs/theory.md section 5) as exact truncated series.
//!
//! Order convention (docs/theory.md section 5): "order N" keeps every term through lambda^N.

pub mod adhesion;
pub mod adhesion_mode;
pub mod adhesion_numeric;
pub mod adhesion_singularity;
pub mod catalog;
pub(crate) mod jacobi_moments;
pub mod kernel;
pub mod loading_law;
pub mod loading_law_modes;
pub mod pade;
pub mod polynomial;
pub mod print;
pub mod sliding;
pub mod weight;
