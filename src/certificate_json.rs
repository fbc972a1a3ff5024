//! The JSON form of a [`Certificate`], as the CLI contract (`check --certificate`,
//! the scene's `intersects`) prints it:
//!
//! ```text
//! {"separating_edge": {"of": "p"|"q", "from": [x, y], "to": [x, y]}}
//! {"vertex_inside": {"of": "p"|"q", "point": [x, y]}}
//! {"crossing_edges": {"p": [[x, y], [x, y]], "q": [[x, y], [x, y]]}}
//! ```
//!
//! Numbers are printed by serde_json's shortest round-trip formatting, so each parses
//! back to the same `f64` (and with serde_json's `float_roundtrip`, which this crate
//! enables, parsing is exact too): a certificate read back verifies exactly as the one
//! written. [`Certificate`] implements `Serialize` and `Deserialize` in this form, so it
//! can be embedded in any serde output.

use crate::intersect::{Certificate, Which};
use crate::kernel::Point;
use serde::{Deserialize, Deserializer, Serialize, Serializer};

/// The certificate as one compact JSON object in the CLI contract's shape (module docs).
///
/// ```
/// use polysect::{ConvexPolygon, certificate_json::certificate_json};
/// use polysect::intersect::{ArrayIntersection, Linear};
/// let p = ConvexPolygon::new([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
/// let q = ConvexPolygon::new([[3.0, 0.0], [4.0, 0.0], [4.0, 1.0]])?;
/// assert_eq!(
///     certificate_json(&Linear.certified(&p, &q)),
///     r#"{"separating_edge":{"of":"p","from":[2.0,0.0],"to":[2.0,2.0]}}"#
/// );
/// # Ok::<(), polysect::PolygonError>(())
/// ```
///
/// # Panics
/// Never: a certificate holds only points and tags, which always serialise.
pub fn certificate_json(certificate: &Certificate) -> String {
    serde_json::to_string(certificate).expect("a certificate serialises")
}

/// Parses the JSON form back (what `verify` needs from a file of answers).
///
/// # Errors
/// serde_json's message when the text is not one of the three shapes.
pub fn certificate_from_json(text: &str) -> Result<Certificate, String> {
    serde_json::from_str(text).map_err(|e| e.to_string())
}

/// The contract's polygon names.
#[derive(Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
enum Of {
    P,
    Q,
}

impl From<Which> for Of {
    fn from(w: Which) -> Self {
        match w {
            Which::P => Of::P,
            Which::Q => Of::Q,
        }
    }
}

impl From<Of> for Which {
    fn from(o: Of) -> Self {
        match o {
            Of::P => Which::P,
            Of::Q => Which::Q,
        }
    }
}

/// The wire shape: an externally tagged enum whose fields serialise in contract order.
#[derive(Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
enum Wire {
    SeparatingEdge { of: Of, from: [f64; 2], to: [f64; 2] },
    VertexInside { of: Of, point: [f64; 2] },
    CrossingEdges { p: [[f64; 2]; 2], q: [[f64; 2]; 2] },
}

impl From<Certificate> for Wire {
    fn from(c: Certificate) -> Self {
        match c {
            Certificate::Separated { of, from, to } => Wire::SeparatingEdge {
                of: of.into(),
                from: from.into(),
                to: to.into(),
            },
            Certificate::VertexInside { of, point } => Wire::VertexInside {
                of: of.into(),
                point: point.into(),
            },
            Certificate::CrossingEdges { p, q } => Wire::CrossingEdges {
                p: p.map(Into::into),
                q: q.map(Into::into),
            },
        }
    }
}

impl From<Wire> for Certificate {
    fn from(w: Wire) -> Self {
        match w {
            Wire::SeparatingEdge { of, from, to } => Certificate::Separated {
                of: of.into(),
                from: from.into(),
                to: to.into(),
            },
            Wire::VertexInside { of, point } => Certificate::VertexInside {
                of: of.into(),
                point: point.into(),
            },
            Wire::CrossingEdges { p, q } => Certificate::CrossingEdges {
                p: p.map(Point::from),
                q: q.map(Point::from),
            },
        }
    }
}

impl Serialize for Certificate {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        Wire::from(*self).serialize(s)
    }
}

impl<'de> Deserialize<'de> for Certificate {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        Wire::deserialize(d).map(Certificate::from)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pt(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    #[test]
    fn exact_output_strings() {
        let sep = Certificate::Separated {
            of: Which::Q,
            from: pt(1.0, -0.5),
            to: pt(3.0, 2.0),
        };
        assert_eq!(
            certificate_json(&sep),
            r#"{"separating_edge":{"of":"q","from":[1.0,-0.5],"to":[3.0,2.0]}}"#
        );
        let inside = Certificate::VertexInside {
            of: Which::P,
            point: pt(0.1, 1e300),
        };
        assert_eq!(
            certificate_json(&inside),
            r#"{"vertex_inside":{"of":"p","point":[0.1,1e+300]}}"#
        );
        let cross = Certificate::CrossingEdges {
            p: [pt(0.0, 0.0), pt(2.0, 0.0)],
            q: [pt(1.0, -1.0), pt(1.0, 1.0)],
        };
        assert_eq!(
            certificate_json(&cross),
            r#"{"crossing_edges":{"p":[[0.0,0.0],[2.0,0.0]],"q":[[1.0,-1.0],[1.0,1.0]]}}"#
        );
        // The extremes: the largest finite, the smallest subnormal, negative zero.
        let extreme = Certificate::VertexInside {
            of: Which::Q,
            point: pt(f64::MAX, -5e-324),
        };
        assert_eq!(
            certificate_json(&extreme),
            r#"{"vertex_inside":{"of":"q","point":[1.7976931348623157e+308,-5e-324]}}"#
        );
        let zero = Certificate::VertexInside {
            of: Which::P,
            point: pt(-0.0, 2f64.powi(-1022)),
        };
        assert_eq!(
            certificate_json(&zero),
            r#"{"vertex_inside":{"of":"p","point":[-0.0,2.2250738585072014e-308]}}"#
        );
    }

    #[test]
    fn parses_back_to_the_same_bits() {
        let awkward = [
            0.1,
            1.0 / 3.0,
            f64::MIN_POSITIVE,
            5e-324,
            f64::MAX,
            -0.0,
            2f64.powi(52) + 1.0,
        ];
        for (i, &x) in awkward.iter().enumerate() {
            let y = awkward[(i + 3) % awkward.len()];
            for c in [
                Certificate::Separated {
                    of: Which::P,
                    from: pt(x, y),
                    to: pt(y, x),
                },
                Certificate::VertexInside {
                    of: Which::Q,
                    point: pt(x.next_down(), y),
                },
                Certificate::CrossingEdges {
                    p: [pt(x, y), pt(y, x)],
                    q: [pt(-x, y), pt(x, -y)],
                },
            ] {
                let back = certificate_from_json(&certificate_json(&c)).unwrap();
                assert_eq!(format!("{back:?}"), format!("{c:?}"));
                let bits = |c: &Certificate| {
                    match *c {
                        Certificate::Separated { from, to, .. } => vec![from, to],
                        Certificate::VertexInside { point, .. } => vec![point],
                        Certificate::CrossingEdges { p, q } => vec![p[0], p[1], q[0], q[1]],
                    }
                    .iter()
                    .flat_map(|p| [p.x.to_bits(), p.y.to_bits()])
                    .collect::<Vec<_>>()
                };
                assert_eq!(bits(&back), bits(&c));
            }
        }
    }

    #[test]
    fn rejects_other_shapes() {
        for bad in [
            r#"{"separating_edge":{"of":"r","from":[0,0],"to":[1,0]}}"#,
            r#"{"vertex_inside":{"of":"p"}}"#,
            r#"{"vertex_inside":{"of":"p","point":[0,0],"extra":1}}"#,
            r#"{"crossing_edges":{"p":[[0,0]],"q":[[0,0],[1,1]]}}"#,
            r#"{"separated":{"of":"p","from":[0,0],"to":[1,0]}}"#,
            r#"[]"#,
        ] {
            assert!(certificate_from_json(bad).is_err(), "{bad}");
        }
        // Integer tokens are coordinates, as in the input lines.
        assert_eq!(
            certificate_from_json(r#"{"vertex_inside":{"of":"p","point":[1,2]}}"#),
            Ok(Certificate::VertexInside {
                of: Which::P,
                point: pt(1.0, 2.0)
            })
        );
    }
}
