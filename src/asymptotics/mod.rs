//! The objects of the asymptotic analysis (THEORY.md section 5) as exact truncated series.
