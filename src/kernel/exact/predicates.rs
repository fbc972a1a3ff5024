//! The predicates of [`Exact`](super::Exact): the static filter inline
//! (`static_filter.rs`), then the out-of-line layers (`out_of_line.rs`) for the calls it
//! cannot decide. Free functions, so that the undecided calls of
//! [`ExactWithin`](super::ExactWithin) reach the same code as the kernel's own.

use super::interval::Interval;
use super::out_of_line::{cross_products_slow, cross_slow, dot_slow, orient_slow, sign_slow};
use super::static_filter::{
    as_value, certain, cross_products, cross_products_filtered, dot_products, orient_products,
};
use crate::kernel::{DirectedLine, Orientation, Point, Polynomial, Ring, Sign};

/// `Exact::orient`.
#[inline(always)]
pub(super) fn orient(a: Point, b: Point, c: Point) -> Orientation {
    let (left, right) = orient_products(a, b, c);
    let mut det = left - right;
    if !certain(det, left) {
        det = as_value(orient_slow(a, b, c));
    }
    Sign::of(det).into()
}

/// `Exact::orient_line`.
#[inline(always)]
pub(super) fn orient_line(line: &DirectedLine, c: Point) -> Orientation {
    let (left, right) = line.products(c);
    let mut det = left - right;
    if !certain(det, left) {
        det = as_value(orient_slow(line.from(), line.to(), c));
    }
    Sign::of(det).into()
}

/// `Exact::sign`: the interval filter, then the exact fallback. Kept out of line: the
/// kernel's own predicates never come here on ordinary input, and inlining an interval
/// evaluation into an algorithm's loop costs it registers and code size.
#[inline(never)]
pub(super) fn sign<P: Polynomial>(poly: &P) -> Sign {
    match poly.eval::<Interval>().certain_sign() {
        Some(s) => s,
        None => sign_slow(poly),
    }
}

/// `Exact::cross`.
#[inline(always)]
pub(super) fn cross(a: Point, b: Point, c: Point, d: Point) -> Orientation {
    let (left, right) = cross_products(a, b, c, d);
    if !certain(left - right, left) {
        return cross_slow(a, b, c, d).into();
    }
    if left > right {
        Orientation::Ccw
    } else {
        Orientation::Cw
    }
}

/// `Exact::dot`.
#[inline(always)]
pub(super) fn dot(a: Point, b: Point, c: Point, d: Point) -> Sign {
    let (left, right) = dot_products(a, b, c, d);
    let mut det = left + right;
    if !certain(det, left) {
        det = as_value(dot_slow(a, b, c, d));
    }
    Sign::of(det)
}

/// `Exact::cross_products_sign`.
#[inline(always)]
pub(super) fn cross_products_sign(factors: [[Point; 4]; 4]) -> Sign {
    match cross_products_filtered(&factors) {
        Some(s) => s,
        None => cross_products_slow(factors),
    }
}
