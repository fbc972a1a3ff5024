//! serde for [`Point`]: written as `[x, y]` (the command line's form), read from
//! `[x, y]` or `{"x": x, "y": y}` (the form of earlier versions). Formats that are
//! not self-describing (such as bincode) write and read the two-element tuple.

use super::Point;
use serde::de::{self, MapAccess, SeqAccess, Visitor};
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use std::fmt;

impl Serialize for Point {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        [self.x, self.y].serialize(s)
    }
}

struct PointVisitor;

impl<'de> Visitor<'de> for PointVisitor {
    type Value = Point;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a point [x, y] or {\"x\": x, \"y\": y}")
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Point, A::Error> {
        let x = seq
            .next_element()?
            .ok_or_else(|| de::Error::invalid_length(0, &self))?;
        let y = seq
            .next_element()?
            .ok_or_else(|| de::Error::invalid_length(1, &self))?;
        if seq.next_element::<de::IgnoredAny>()?.is_some() {
            return Err(de::Error::invalid_length(3, &self));
        }
        Ok(Point::new(x, y))
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Point, A::Error> {
        let (mut x, mut y) = (None, None);
        while let Some(key) = map.next_key::<std::borrow::Cow<'de, str>>()? {
            let slot = match &*key {
                "x" => &mut x,
                "y" => &mut y,
                other => return Err(de::Error::unknown_field(other, &["x", "y"])),
            };
            if slot.is_some() {
                return Err(de::Error::custom(format_args!("duplicate field `{key}`")));
            }
            *slot = Some(map.next_value()?);
        }
        Ok(Point::new(
            x.ok_or_else(|| de::Error::missing_field("x"))?,
            y.ok_or_else(|| de::Error::missing_field("y"))?,
        ))
    }
}

impl<'de> Deserialize<'de> for Point {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Point, D::Error> {
        if d.is_human_readable() {
            d.deserialize_any(PointVisitor)
        } else {
            d.deserialize_tuple(2, PointVisitor)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn writes_arrays_and_reads_both_forms() {
        let p = Point::new(0.1, -2.0);
        assert_eq!(serde_json::to_string(&p).unwrap(), "[0.1,-2.0]");
        for text in ["[0.1, -2]", r#"{"x": 0.1, "y": -2}"#, r#"{"y": -2.0, "x": 0.1}"#] {
            assert_eq!(serde_json::from_str::<Point>(text).unwrap(), p, "{text}");
        }
        for bad in [
            "[1]",
            "[1, 2, 3]",
            r#"{"x": 1}"#,
            r#"{"x": 1, "y": 2, "z": 3}"#,
            r#"{"x": 1, "x": 2, "y": 3}"#,
            r#""1, 2""#,
            r#"["1", 2]"#,
        ] {
            assert!(serde_json::from_str::<Point>(bad).is_err(), "{bad}");
        }
        let extremes = Point::new(f64::MAX, 5e-324);
        let text = serde_json::to_string(&extremes).unwrap();
        assert_eq!(serde_json::from_str::<Point>(&text).unwrap(), extremes);
    }
}
