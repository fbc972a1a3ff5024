//! Timing: a query repeated in doubling batches until a minimum time, the median of
//! three such loops per pair, the median over pairs.

use std::hint::black_box;
use std::time::{Duration, Instant};

/// Nanoseconds per call of `f`: batches of doubling size until one batch takes at
/// least `min_time`; the median of three such batches.
pub fn time_per_query(min_time: Duration, mut f: impl FnMut() -> bool) -> f64 {
    let mut batch: u64 = 1;
    let mut rounds = Vec::with_capacity(3);
    while rounds.len() < 3 {
        let start = Instant::now();
        for _ in 0..batch {
            black_box(f());
        }
        let elapsed = start.elapsed();
        if elapsed >= min_time / 3 {
            rounds.push(elapsed.as_secs_f64() * 1e9 / batch as f64);
        } else {
            batch *= 2;
        }
    }
    median(&mut rounds)
}

/// The median (the mean of the two middle values for an even count); NaN when empty.
pub fn median(values: &mut [f64]) -> f64 {
    if values.is_empty() {
        return f64::NAN;
    }
    values.sort_by(f64::total_cmp);
    let m = values.len() / 2;
    if values.len() % 2 == 1 {
        values[m]
    } else {
        (values[m - 1] + values[m]) / 2.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn median_of_odd_and_even_counts() {
        assert_eq!(median(&mut [3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median(&mut [4.0, 1.0, 2.0, 3.0]), 2.5);
        assert!(median(&mut []).is_nan());
    }

    #[test]
    fn timed_loop_calls_the_query_and_returns_a_positive_time() {
        let mut calls = 0u64;
        let t = time_per_query(Duration::from_micros(300), || {
            calls += 1;
            calls.is_multiple_of(2)
        });
        assert!(calls >= 3);
        assert!(t > 0.0 && t.is_finite());
    }
}
