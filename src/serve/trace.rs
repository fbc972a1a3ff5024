//! A [`Trace`] as the live page's step-through mode receives it: one JSON text message
//! with the two polygons' vertices (current positions, counter-clockwise) and the
//! steps, their kept and pruned vertices as `[start, len]` index ranges into those
//! arrays and their marks as point lists.

use crate::intersect::{Role, Shape, Span, Trace, Which};
use crate::kernel::Point;
use serde_json::{Value, json};

fn pt(p: Point) -> Value {
    json!([p.x, p.y])
}

fn spans(s: &[Span]) -> Value {
    Value::Array(s.iter().map(|s| json!([s.start, s.len])).collect())
}

fn role(r: Role) -> &'static str {
    match r {
        Role::Triangle => "triangle",
        Role::Bound => "bound",
        Role::Pencil => "pencil",
        Role::Window => "window",
        Role::Sample => "sample",
        Role::Chain => "chain",
        Role::Separator => "separator",
        Role::Witness => "witness",
    }
}

fn shape(s: &Shape) -> (&'static str, Vec<Value>) {
    match s {
        Shape::Points(v) => ("points", v.iter().copied().map(pt).collect()),
        Shape::Polyline(v) => ("polyline", v.iter().copied().map(pt).collect()),
        Shape::Polygon(v) => ("polygon", v.iter().copied().map(pt).collect()),
        Shape::Segment(a, b) => ("segment", vec![pt(*a), pt(*b)]),
        Shape::Line(a, b) => ("line", vec![pt(*a), pt(*b)]),
    }
}

/// The `trace` reply for polygons `a` (the trace's P, vertices `p`) and `b` (Q, `q`)
/// of scene `scene`.
pub fn trace_json(scene: u64, [a, b]: [usize; 2], p: &[Point], q: &[Point], trace: &Trace) -> Value {
    let steps: Vec<Value> = trace
        .steps
        .iter()
        .map(|s| {
            let marks: Vec<Value> = s
                .marks
                .iter()
                .map(|m| {
                    let (kind, points) = shape(&m.shape);
                    let of = match m.of {
                        Some(Which::P) => json!("p"),
                        Some(Which::Q) => json!("q"),
                        None => Value::Null,
                    };
                    json!({"role": role(m.role), "of": of, "kind": kind, "points": points})
                })
                .collect();
            json!({
                "text": s.text,
                "kept": [spans(&s.kept[0]), spans(&s.kept[1])],
                "pruned": [spans(&s.pruned[0]), spans(&s.pruned[1])],
                "marks": marks,
                "answer": s.answer,
            })
        })
        .collect();
    json!({
        "type": "trace",
        "scene": scene,
        "polygons": [a, b],
        "algorithm": trace.algorithm.name(),
        "p": p.iter().copied().map(pt).collect::<Vec<_>>(),
        "q": q.iter().copied().map(pt).collect::<Vec<_>>(),
        "steps": steps,
        "answer": trace.intersects(),
        "certificate": serde_json::to_value(trace.certificate).unwrap_or(Value::Null),
    })
}
