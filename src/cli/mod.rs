//! The command line, in two stages (ripgrep style): raw clap arguments ([`args`]) are validated
//! into a typed configuration ([`config`]) before any work; invalid input is a
//! [`crate::model::ModelError`] naming the parameter, its value and the valid range (exit code 2).

pub mod args;
pub mod config;
