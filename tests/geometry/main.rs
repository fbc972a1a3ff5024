//! The library's geometry from outside, one test crate (each module one algorithm or
//! one concern): the array tests and their certificates, the exact references, the
//! property tests, the LP and its chain walk, extreme vertices, line queries, calipers
//! and the shape constructors. Every module checks against an exact reference.

mod cases;
mod hulls;

mod array_algorithms;
mod calipers;
mod certificates;
mod chazelle_dobkin;
mod extremes;
mod line_query;
mod lp;
mod lp_chains;
mod properties;
mod queries;
mod reference;
mod shapes;
