//! Layer 3 of the exact kernel, the exact fallback: the dyadic values `m · 2^e` of the
//! inputs as big integers, so every polynomial predicate evaluates exactly.

use crate::kernel::{Ring, Sign};
use num_bigint::BigInt;
use num_traits::{Signed, Zero};
use std::ops::{Add, Mul, Sub};

/// An exact dyadic rational `mantissa · 2^exponent` with a big-integer mantissa:
/// every finite `f64` is one, and `+ - *` on them are exact.
#[doc(hidden)]
#[derive(Clone, Debug, PartialEq)]
pub struct Dyadic {
    mantissa: BigInt,
    exponent: i64,
}

impl Dyadic {
    fn align(self, other: Dyadic) -> (BigInt, BigInt, i64) {
        let e = self.exponent.min(other.exponent);
        let a = self.mantissa << (self.exponent - e) as usize;
        let b = other.mantissa << (other.exponent - e) as usize;
        (a, b, e)
    }
}

impl Dyadic {
    /// The mantissa and the exponent: the value is `mantissa · 2^exponent`.
    pub fn parts(&self) -> (&BigInt, i64) {
        (&self.mantissa, self.exponent)
    }
}

/// Splits a finite `f64` into an integer mantissa and a power-of-two exponent.
pub(super) fn decompose(x: f64) -> (i64, i64) {
    let bits = x.to_bits();
    let negative = bits >> 63 == 1;
    let biased = ((bits >> 52) & 0x7ff) as i64;
    let fraction = (bits & ((1u64 << 52) - 1)) as i64;
    let (m, e) = if biased == 0 {
        (fraction, -1074)
    } else {
        (fraction | (1i64 << 52), biased - 1075)
    };
    (if negative { -m } else { m }, e)
}

impl Add for Dyadic {
    type Output = Dyadic;
    fn add(self, o: Dyadic) -> Dyadic {
        let (a, b, e) = self.align(o);
        Dyadic {
            mantissa: a + b,
            exponent: e,
        }
    }
}

impl Sub for Dyadic {
    type Output = Dyadic;
    fn sub(self, o: Dyadic) -> Dyadic {
        let (a, b, e) = self.align(o);
        Dyadic {
            mantissa: a - b,
            exponent: e,
        }
    }
}

impl Mul for Dyadic {
    type Output = Dyadic;
    fn mul(self, o: Dyadic) -> Dyadic {
        Dyadic {
            mantissa: self.mantissa * o.mantissa,
            exponent: self.exponent + o.exponent,
        }
    }
}

impl Ring for Dyadic {
    /// # Panics
    /// On NaN or infinity, which validated inputs never contain.
    fn from_f64(x: f64) -> Self {
        assert!(x.is_finite(), "exact arithmetic on a non-finite value");
        let (m, e) = decompose(x);
        Dyadic {
            mantissa: BigInt::from(m),
            exponent: e,
        }
    }
    fn certain_sign(&self) -> Option<Sign> {
        Some(if self.mantissa.is_zero() {
            Sign::Zero
        } else if self.mantissa.is_positive() {
            Sign::Positive
        } else {
            Sign::Negative
        })
    }
}
