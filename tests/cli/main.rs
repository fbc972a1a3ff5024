//! The `polysect` binary from outside, one test crate for every subcommand (each module
//! is one subcommand's contract or one concern of all of them): the binary is built
//! once and the tests link the library once.

#[path = "../common/mod.rs"]
mod common;

mod certificates;
mod check;
mod contact;
mod crossings;
mod gen_simple;
mod hull;
mod options;
mod scene;
