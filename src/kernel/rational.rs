//! Exact rationals and their correctly rounded conversion to `f64`: the one place where
//! constructed values (distances, closest points, overlap vertices, areas) are rounded.
//!
//! A [`Rational`] is a quotient of big integers, built exactly from `f64` values with
//! `+ − × ÷`. [`Rational::to_f64`] returns the double nearest its value, ties to even,
//! subnormals included, `±∞` beyond the largest finite double (as IEEE rounding would);
//! [`Rational::sqrt_to_f64`] does the same for the square root of a non-negative value.
//!
//! # Complexity
//! Each operation is a few big-integer products; the conversions one division (and one
//! integer square root) of numbers of about `b + 110` bits, `b` the operands' size.
//! Nothing is reduced by the gcd: common powers of two are shifted out, which keeps
//! the numbers built from `f64` inputs (dyadic denominators) small; callers that sum
//! many quotients with different denominators pay for the growth.
//!
//! # Precision
//! Everything is exact; only the two conversions round, once.

use crate::kernel::Sign;
use num_bigint::{BigInt, Sign as BigSign};
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::cmp::Ordering;
use std::ops::{Add, Mul, Neg, Sub};

/// An exact rational number `num / den`, `den > 0`.
#[derive(Clone, Debug)]
pub struct Rational {
    num: BigInt,
    den: BigInt,
}

/// The integer mantissa and exponent of a finite `f64`: the value is `m · 2^e`.
fn decompose(x: f64) -> (i64, i64) {
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

/// `2^e` as an `f64`, for `-1074 ≤ e ≤ 1023`.
fn pow2(e: i64) -> f64 {
    if e >= -1022 {
        f64::from_bits(((e + 1023) as u64) << 52)
    } else {
        f64::from_bits(1u64 << (e + 1074))
    }
}

impl Rational {
    /// Zero.
    pub(crate) fn zero() -> Rational {
        Rational {
            num: BigInt::zero(),
            den: BigInt::one(),
        }
    }

    /// The exact value of a finite `f64`.
    ///
    /// # Panics
    /// On NaN or infinity (validated polygons never hold them).
    pub(crate) fn from_f64(x: f64) -> Rational {
        assert!(x.is_finite(), "exact arithmetic on a non-finite value");
        let (m, e) = decompose(x);
        let m = BigInt::from(m);
        if e >= 0 {
            Rational {
                num: m << e as usize,
                den: BigInt::one(),
            }
        } else {
            Rational {
                num: m,
                den: BigInt::one() << (-e) as usize,
            }
            .reduced()
        }
    }

    /// `num / den`.
    ///
    /// # Panics
    /// When `den` is zero.
    pub(crate) fn new(num: BigInt, den: BigInt) -> Rational {
        assert!(!den.is_zero(), "a rational with denominator zero");
        if den.is_negative() {
            Rational { num: -num, den: -den }.reduced()
        } else {
            Rational { num, den }.reduced()
        }
    }

    /// The numerator and the (positive) denominator.
    pub fn parts(&self) -> (&BigInt, &BigInt) {
        (&self.num, &self.den)
    }

    /// Shifts out the powers of two common to numerator and denominator.
    fn reduced(mut self) -> Rational {
        if self.num.is_zero() {
            self.den = BigInt::one();
            return self;
        }
        let shift = self
            .num
            .trailing_zeros()
            .unwrap_or(0)
            .min(self.den.trailing_zeros().unwrap_or(0));
        if shift > 0 {
            self.num >>= shift as usize;
            self.den >>= shift as usize;
        }
        self
    }

    /// Whether the value is zero.
    pub fn is_zero(&self) -> bool {
        self.num.is_zero()
    }

    /// The sign of the value.
    pub fn sign(&self) -> Sign {
        match self.num.sign() {
            BigSign::Minus => Sign::Negative,
            BigSign::NoSign => Sign::Zero,
            BigSign::Plus => Sign::Positive,
        }
    }

    /// The absolute value.
    pub fn abs(&self) -> Rational {
        Rational {
            num: self.num.abs(),
            den: self.den.clone(),
        }
    }

    /// The quotient `self / other`.
    ///
    /// # Panics
    /// When `other` is zero.
    pub fn div(&self, other: &Rational) -> Rational {
        Rational::new(&self.num * &other.den, &self.den * &other.num)
    }

    /// The square `self · self`.
    pub(crate) fn square(&self) -> Rational {
        self * self
    }

    /// The double nearest the value, ties to even; `±∞` when that rounding overflows
    /// (the value is at least the largest finite double plus half its ulp).
    pub fn to_f64(&self) -> f64 {
        let negative = self.num.is_negative();
        let magnitude = round_quotient(&self.num.abs(), &self.den);
        if negative { -magnitude } else { magnitude }
    }

    /// The double nearest the square root of the value, ties to even; `+∞` when that
    /// overflows.
    ///
    /// # Panics
    /// When the value is negative.
    pub(crate) fn sqrt_to_f64(&self) -> f64 {
        assert!(!self.num.is_negative(), "square root of a negative rational");
        round_sqrt_quotient(&self.num, &self.den)
    }
}

/// `n / (d · 2^e)` as quotient and remainder, with the divisor `d · 2^e` (or the
/// numerator scaled when `e < 0`): `(q, r, divisor)`, `n · 2^-e = q · divisor' + r`.
fn divide_scaled(n: &BigInt, d: &BigInt, e: i64) -> (BigInt, BigInt, BigInt) {
    let (num, den) = if e >= 0 {
        (n.clone(), d << e as usize)
    } else {
        (n << (-e) as usize, d.clone())
    };
    let q = &num / &den;
    let r = num - &q * &den;
    (q, r, den)
}

/// The nearest double to `n / d` (`n ≥ 0`, `d > 0`), ties to even.
fn round_quotient(n: &BigInt, d: &BigInt) -> f64 {
    if n.is_zero() {
        return 0.0;
    }
    // Choose e so that the quotient n / (d · 2^e) has exactly 53 bits, or e = -1074
    // (a subnormal result, fewer bits).
    let mut e = n.bits() as i64 - d.bits() as i64 - 53;
    let (mut q, mut r, mut den);
    loop {
        if e < -1074 {
            e = -1074;
        }
        (q, r, den) = divide_scaled(n, d, e);
        let bits = q.bits();
        if bits > 53 {
            e += 1;
        } else if bits < 53 && e > -1074 {
            e -= 1;
        } else {
            break;
        }
    }
    let twice = &r << 1usize;
    let up = match twice.cmp(&den) {
        Ordering::Greater => true,
        Ordering::Equal => q.bit(0),
        Ordering::Less => false,
    };
    if up {
        q += 1;
    }
    compose(&q, e)
}

/// `q · 2^e` for `q ≤ 2^53` (as a rounded mantissa) and `e ≥ -1074`; `+∞` beyond the
/// largest finite double.
fn compose(q: &BigInt, e: i64) -> f64 {
    let q = q.to_u64().expect("a rounded mantissa has at most 54 bits");
    if q == 0 {
        return 0.0;
    }
    let bits = 64 - i64::from(q.leading_zeros());
    if e + bits > 1024 {
        return f64::INFINITY;
    }
    // q is exact in f64, and the product is representable, so it is exact.
    if e > 971 {
        // 2^e itself may not be representable as a factor of q's size: split it.
        (q as f64) * pow2(971) * pow2(e - 971)
    } else {
        (q as f64) * pow2(e)
    }
}

/// The nearest double to `√(n / d)` (`n ≥ 0`, `d > 0`), ties to even.
fn round_sqrt_quotient(n: &BigInt, d: &BigInt) -> f64 {
    if n.is_zero() {
        return 0.0;
    }
    // M = ⌊√(n / (d · 2^2e))⌋ with exactly 53 bits, or e = -1074.
    let log = n.bits() as i64 - d.bits() as i64;
    let mut e = log.div_euclid(2) - 53;
    let mut m;
    loop {
        if e < -1074 {
            e = -1074;
        }
        let (q, _, _) = divide_scaled(n, d, 2 * e);
        // ⌊√⌊y⌋⌋ = ⌊√y⌋ for y ≥ 0.
        m = q.sqrt();
        let bits = m.bits();
        if bits > 53 {
            e += 1;
        } else if bits < 53 && e > -1074 {
            e -= 1;
        } else {
            break;
        }
    }
    // Round up iff √(n/d) ≥ (M + ½)·2^e ⟺ 4n ≥ d (2M + 1)² 2^2e.
    let odd: BigInt = (&m << 1usize) + 1;
    let rhs = d * &odd * &odd;
    let lhs: BigInt = n << 2usize;
    let (lhs, rhs) = if e >= 0 {
        (lhs, rhs << (2 * e) as usize)
    } else {
        (lhs << (-2 * e) as usize, rhs)
    };
    let up = match lhs.cmp(&rhs) {
        Ordering::Greater => true,
        // A tie: √(n/d) is exactly halfway (a rational square root).
        Ordering::Equal => m.bit(0),
        Ordering::Less => false,
    };
    if up {
        m += 1;
    }
    compose(&m, e)
}

impl PartialEq for Rational {
    fn eq(&self, other: &Rational) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl Eq for Rational {}

impl PartialOrd for Rational {
    fn partial_cmp(&self, other: &Rational) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Rational {
    fn cmp(&self, other: &Rational) -> Ordering {
        (&self.num * &other.den).cmp(&(&other.num * &self.den))
    }
}

impl Add for &Rational {
    type Output = Rational;
    fn add(self, o: &Rational) -> Rational {
        if self.den == o.den {
            return Rational {
                num: &self.num + &o.num,
                den: self.den.clone(),
            }
            .reduced();
        }
        Rational {
            num: &self.num * &o.den + &o.num * &self.den,
            den: &self.den * &o.den,
        }
        .reduced()
    }
}

impl Sub for &Rational {
    type Output = Rational;
    fn sub(self, o: &Rational) -> Rational {
        self + &(-o)
    }
}

impl Mul for &Rational {
    type Output = Rational;
    fn mul(self, o: &Rational) -> Rational {
        Rational {
            num: &self.num * &o.num,
            den: &self.den * &o.den,
        }
        .reduced()
    }
}

impl Neg for &Rational {
    type Output = Rational;
    fn neg(self) -> Rational {
        Rational {
            num: -&self.num,
            den: self.den.clone(),
        }
    }
}

impl Add for Rational {
    type Output = Rational;
    fn add(self, o: Rational) -> Rational {
        &self + &o
    }
}

impl Sub for Rational {
    type Output = Rational;
    fn sub(self, o: Rational) -> Rational {
        &self - &o
    }
}

impl Mul for Rational {
    type Output = Rational;
    fn mul(self, o: Rational) -> Rational {
        &self * &o
    }
}

impl Neg for Rational {
    type Output = Rational;
    fn neg(self) -> Rational {
        -&self
    }
}

impl From<f64> for Rational {
    fn from(x: f64) -> Rational {
        Rational::from_f64(x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r(x: f64) -> Rational {
        Rational::from_f64(x)
    }

    fn int(n: i64) -> BigInt {
        BigInt::from(n)
    }

    #[test]
    fn doubles_round_trip_exactly() {
        for x in [
            0.0,
            -0.0,
            1.0,
            -1.5,
            0.1,
            f64::MAX,
            -f64::MAX,
            f64::MIN_POSITIVE,
            5e-324,
            -5e-324,
            f64::MIN_POSITIVE.next_down(),
            1e300,
            1e-300,
            2f64.powi(1000),
            2f64.powi(-1000),
        ] {
            assert_eq!(r(x).to_f64().to_bits(), (x + 0.0).to_bits(), "{x:e}");
        }
    }

    #[test]
    fn quotients_round_to_nearest_like_ieee_division() {
        // IEEE division of two doubles is correctly rounded: compare on many pairs,
        // including quotients that underflow into subnormals and overflow.
        let values = [
            1.0,
            3.0,
            7.0,
            0.1,
            1e-300,
            1e300,
            5e-324,
            1e-310,
            f64::MAX,
            2f64.powi(1000),
            2f64.powi(-1000),
            1.0 + f64::EPSILON,
            123456789.0,
            9007199254740993.0,
            0.3,
        ];
        for &a in &values {
            for &b in &values {
                for (x, y) in [(a, b), (-a, b), (a, -b)] {
                    let q = r(x).div(&r(y)).to_f64();
                    assert_eq!(q.to_bits(), (x / y).to_bits(), "{x:e} / {y:e}");
                }
            }
        }
    }

    #[test]
    fn products_and_sums_round_like_ieee() {
        let values = [
            1.0,
            0.1,
            3.0,
            1e-160,
            1e160,
            5e-324,
            1e-200,
            1e200,
            2f64.powi(-537),
            1.0 + f64::EPSILON,
        ];
        for &a in &values {
            for &b in &values {
                assert_eq!(
                    (r(a) * r(b)).to_f64().to_bits(),
                    (a * b).to_bits(),
                    "{a:e} * {b:e}"
                );
                assert_eq!(
                    (r(a) + r(b)).to_f64().to_bits(),
                    (a + b).to_bits(),
                    "{a:e} + {b:e}"
                );
                assert_eq!(
                    (r(a) - r(b)).to_f64().to_bits(),
                    (a - b).to_bits(),
                    "{a:e} - {b:e}"
                );
            }
        }
    }

    #[test]
    fn halfway_cases_round_to_even() {
        // 1 + 2^-53 is halfway between 1 and 1 + 2^-52: rounds to 1 (even).
        let half_ulp = Rational::new(int(1), BigInt::one() << 53usize);
        assert_eq!((r(1.0) + half_ulp.clone()).to_f64(), 1.0);
        // 1 + 3·2^-53 is halfway between 1 + 2^-52 and 1 + 2^-51: rounds up (even).
        let three = Rational::new(int(3), BigInt::one() << 53usize);
        assert_eq!((r(1.0) + three).to_f64(), 1.0 + 2.0 * f64::EPSILON);
        // Just above halfway rounds up.
        let above = Rational::new((BigInt::one() << 60usize) + 1, BigInt::one() << 113usize);
        assert_eq!((r(1.0) + above).to_f64(), 1.0 + f64::EPSILON);
        // Halfway between the two smallest subnormals: 0.5 · 2^-1074 rounds to 0, 1.5 to 2.
        let tiny = Rational::new(int(1), BigInt::one() << 1075usize);
        assert_eq!(tiny.to_f64(), 0.0);
        let tiny3 = Rational::new(int(3), BigInt::one() << 1075usize);
        assert_eq!(tiny3.to_f64(), 1e-323);
        // Just below MAX + half an ulp stays finite; at it and above, infinity.
        let max = r(f64::MAX);
        let half = Rational::new(BigInt::one() << 970usize, int(1));
        let below = &(&max + &half) - &Rational::new(int(1), int(1));
        assert_eq!(below.to_f64(), f64::MAX);
        assert_eq!((&max + &half).to_f64(), f64::INFINITY);
        assert_eq!((-(&max + &half)).to_f64(), f64::NEG_INFINITY);
    }

    #[test]
    fn square_roots_are_correctly_rounded() {
        // Exact squares, at every scale.
        for x in [
            1.0,
            4.0,
            0.25,
            9.0,
            2f64.powi(1000),
            2f64.powi(-1000),
            2f64.powi(-1074),
            3.0 * 2f64.powi(500),
        ] {
            let s = (r(x) * r(x)).sqrt_to_f64();
            assert_eq!(s, x, "√({x:e}²)");
        }
        // IEEE sqrt is correctly rounded: compare on doubles.
        for x in [
            2.0,
            3.0,
            0.1,
            1e-310,
            5e-324,
            f64::MAX,
            1e300,
            1e-300,
            1.0 + f64::EPSILON,
            7e22,
        ] {
            assert_eq!(r(x).sqrt_to_f64().to_bits(), x.sqrt().to_bits(), "√{x:e}");
        }
        // Quotients: √(a/b) against an exact check of the neighbours.
        for (a, b) in [
            (2.0, 3.0),
            (1.0, 7.0),
            (1e-300, 3e300),
            (f64::MAX, 1e-300),
            (5e-324, 7.0),
        ] {
            let x = r(a).div(&r(b));
            let s = x.sqrt_to_f64();
            if s.is_finite() {
                let err = |y: f64| (&r(y).square() - &x).abs();
                assert!(err(s) <= err(s.next_up()) && err(s) <= err(s.next_down()) || s == 0.0);
                // The nearest in √ terms: check the midpoints bracket √x.
                let lo = (r(s) + r(s.next_down())).square();
                let hi = (r(s) + r(s.next_up())).square();
                let four_x = &x * &r(4.0);
                assert!(lo <= four_x && four_x <= hi, "√({a:e}/{b:e}) = {s:e}");
            } else {
                assert!(a / b > 1e300);
            }
        }
        // Beyond the largest double.
        let huge = r(f64::MAX) * r(f64::MAX) * r(4.0);
        assert_eq!(huge.sqrt_to_f64(), f64::INFINITY);
        assert_eq!((r(f64::MAX) * r(f64::MAX)).sqrt_to_f64(), f64::MAX);
        assert_eq!(Rational::zero().sqrt_to_f64(), 0.0);
    }

    #[test]
    fn square_root_ties_round_to_even() {
        // (2^53 + 1)² / 4 = ((2^53 + 1)/2)²: its root 2^52 + ½ is halfway between
        // 2^52 and 2^52 + 1; ties to even gives 2^52.
        let m = (BigInt::one() << 53usize) + 1;
        let x = Rational::new(&m * &m, int(4));
        assert_eq!(x.sqrt_to_f64(), 2f64.powi(52));
        // (2^53 + 3)/2 = 2^52 + 1.5: halfway between 2^52 + 1 and 2^52 + 2: even is + 2.
        let m = (BigInt::one() << 53usize) + 3;
        let x = Rational::new(&m * &m, int(4));
        assert_eq!(x.sqrt_to_f64(), 2f64.powi(52) + 2.0);
    }

    #[test]
    fn comparisons_and_signs() {
        assert!(r(0.1) < r(0.2));
        assert_eq!(r(0.5), Rational::new(int(2), int(4)));
        assert_eq!((r(-3.0) * r(2.0)).sign(), Sign::Negative);
        assert_eq!(Rational::zero().sign(), Sign::Zero);
        assert_eq!(Rational::new(int(-1), int(-2)).to_f64(), 0.5);
    }
}
