//! polysect: dynamic convex polygons with sublinear intersection queries.
//!
//! Convex polygons live either as validated sorted arrays ([`ConvexPolygon`]) or as
//! arena-backed doubly linked lists ([`LinkedPolygon`]) with O(1) validated edits and
//! O(1) uniform vertex sampling. "Do P and Q intersect?" is answered in O(log n) on
//! arrays ([`intersect::Barba`], [`intersect::Dobkin`], [`intersect::ChazelleDobkin`]),
//! in expected O(√n) straight on linked lists ([`intersect::Clm`], built on an in-crate
//! Seidel 2D LP), or by the O(n + m) reference [`intersect::Linear`]. A [`store::Scene`] keeps
//! many editable polygons and plans each query. [`crossings`] finds the points where
//! two simple polygons' boundaries meet.
//!
//! Polygons are closed sets: touching is intersecting. Every algorithm is generic over
//! a [`Kernel`]: [`Exact`] (the default) decides every predicate exactly for every
//! finite `f64` input; [`Fast`] uses plain floating point.
//!
//! Features: the default set builds the `polysect` command-line tool (`cli`) and
//! `geo-types` conversions. With `default-features = false` the library above needs
//! only 7 crates and builds for `wasm32-unknown-unknown`; add `os-rng` (unseeded
//! queries seeded from the OS), `serde`, `geo-types`, `parallel` (rayon) or `protocol`
//! (the JSON-lines protocols) as needed. See docs/design.md, "Features".
//!
//! ```
//! use polysect::intersect::{ArrayIntersection, Barba, Clm, LinkedIntersection};
//! use polysect::{ConvexPolygon, Fast, LinkedPolygon, Point};
//!
//! // Either orientation, any start vertex; repeats and collinear vertices are cleaned.
//! let p = ConvexPolygon::new([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
//! let q = ConvexPolygon::new([[2.0, 2.0], [3.0, 2.0], [3.0, 3.0]])?;
//! assert!(Barba.intersects(&p, &q)); // a shared vertex counts
//! assert!(Barba.intersects_with(Fast, &p, &q));
//!
//! // Linked polygons: edits keep convexity or are refused without changing anything.
//! let mut lp = LinkedPolygon::from_convex(&p);
//! let lq = LinkedPolygon::from_convex(&q);
//! let a = lp.first();
//! lp.insert_after(a, Point::new(1.0, -0.5))?;
//! assert!(lp.insert_after(a, Point::new(1.0, 0.5)).is_err());
//! assert!(Clm.intersects(&lp, &lq));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! A [`store::Scene`] holds many editable polygons and answers which of them meet; it
//! chooses per query between the sampled test and array snapshots:
//!
//! ```
//! use polysect::store::Scene;
//!
//! let mut scene = Scene::new();
//! let square = scene.insert_points([[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]])?;
//! let tri = scene.insert_points([[5.0, 1.0], [7.0, 1.0], [6.0, 3.0]])?;
//! assert!(!scene.intersects(square, tri)?);
//! scene.translate(tri, -1.0, 0.0)?; // now it touches the square: that counts
//! assert!(scene.intersects(square, tri)?);
//! assert_eq!(scene.intersecting_pairs(), vec![(square, tri)]);
//! assert_eq!(scene.intersecting(tri)?, vec![square]);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
#![forbid(unsafe_code)]
#![warn(missing_docs, clippy::missing_errors_doc, clippy::missing_panics_doc)]
#![cfg_attr(docsrs, feature(doc_cfg))]

/// Declares an item `pub` with the `instrument` feature and `pub(crate)` without it.
/// The research instruments (probes, the engines' probed entry points, work counts)
/// are part of the crate's own machinery, which every query runs through, but they are
/// an API only for experiments (docs/design.md, "Features"); this keeps one
/// declaration for both builds.
macro_rules! instrument_pub {
    ($(#[$attr:meta])* $kind:ident $($rest:tt)*) => {
        #[cfg(feature = "instrument")]
        $(#[$attr])*
        pub $kind $($rest)*
        #[cfg(not(feature = "instrument"))]
        $(#[$attr])*
        pub(crate) $kind $($rest)*
    };
}

#[cfg(all(feature = "serde", feature = "protocol"))]
pub mod certificate_json;
pub mod contact;
pub mod crossings;
// The measurements behind `polysect bench`: the tool's, not an API to build on.
#[doc(hidden)]
#[cfg(feature = "cli")]
pub mod experiments;
#[cfg(feature = "protocol")]
#[doc(hidden)]
pub mod fuzzing;
// Seeded generators: an API with the `generate` feature (the tool, the tests and the
// benches turn it on); without it, the crate's own calibration still draws from them.
#[cfg(feature = "generate")]
pub mod generate;
#[cfg(not(feature = "generate"))]
#[allow(dead_code)]
mod generate;
pub mod intersect;
pub mod kernel;
// The Seidel LP behind `Clm`: an API for experiments only (`instrument`).
#[cfg(feature = "instrument")]
pub mod lp;
#[cfg(not(feature = "instrument"))]
#[allow(dead_code)]
mod lp;
pub mod polygon;
#[cfg(feature = "protocol")]
pub mod protocol;
#[cfg(feature = "protocol")]
pub mod render;
// How unseeded entry points are seeded: an API for the tool (`instrument`), decided
// in one place for both builds.
#[cfg(feature = "instrument")]
pub mod seeding;
#[cfg(not(feature = "instrument"))]
mod seeding;
#[cfg(feature = "cli")]
pub mod serve;
pub mod store;

/// The README's examples, compiled and run as doctests.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;

pub use kernel::{BoundingBox, Exact, Fast, Kernel, Orientation, Point, Precision, Sign};

/// The `rand` crate (0.9) whose types appear in this crate's signatures: sampled
/// queries take any `R: rand::Rng` (and with `instrument`,
/// `LinkedPolygon::from_convex_shuffled` a generator to shuffle with). Use this re-export (`polysect::rand::SeedableRng`,
/// `polysect::rand::rngs::SmallRng`) to get the same version without naming it in
/// your own `Cargo.toml`.
pub use rand;

pub use polygon::{ConvexPolygon, EditError, LinkedPolygon, PolygonError, VertexId};
pub use polygon::{SimplePolygon, SimplePolygonError};
