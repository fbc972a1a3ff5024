//! Traces: an algorithm's run as a sequence of steps, each saying what the algorithm
//! keeps and what it has just pruned, ending with the answer and its certificate.
//!
//! The algorithms report their state through hook methods of [`Probe`] whose default
//! bodies are empty: [`Probe::kept`] (Barba–Langerman, Dobkin–Souvaine,
//! Chazelle–Dobkin, once per pruning iteration, before it decides) and CLM's
//! [`Probe::samples`], [`Probe::lp_call`] and [`Probe::chain_walk`] (with the point sets
//! themselves). With the no-op probe `()` of the plain calls the hooks compile away:
//! the arguments are built from values the loop holds anyway and are never read
//! (docs/live.md gives the measurement).
//!
//! [`Tracer`] records them; [`trace`] runs an algorithm's *certified* call with a
//! tracer and returns a [`Trace`]: its steps, then a last step with the answer and the
//! certificate, which are exactly those of the certified call without a tracer (tests
//! check this on the fuzz families).
//!
//! | algorithm | one step | kept | marks |
//! |---|---|---|---|
//! | Barba–Langerman | main loop iteration | P' and Q' (index ranges) | T_P (inner triangle of P'), the lines of T_Q's three edges (Q''s edge hull) |
//! | Barba–Langerman | finish against a small Q' | P' and Q''s ≤ 6 vertices | T_P |
//! | Dobkin–Souvaine | one chain-pair search iteration | the left chain of one polygon and the right chain of the other, in the common y-interval | the interval's bounding heights |
//! | Chazelle–Dobkin | pruning iteration | the chains F ⊆ P and G ⊆ Q | the pivot, the pencil's tangents, the window |
//! | CLM | samples, each LP, each walk | — | the sample points, each LP's point sets and its separating line, each walked chain |
//!
//! Linear and Convert report nothing (Convert's array test runs on the walked arrays,
//! whose reports a trace leaves out): their traces have the last step only.
//!
//! # Complexity
//! Recording allocates and costs O(n + m) per step (the pruned vertices are the
//! difference of two steps' kept sets, found vertex by vertex), so a trace of a
//! logarithmic algorithm costs O((n + m) log(n + m)): an illustration tool, not a
//! query path.
//!
//! # Precision
//! Whatever kernel the traced call uses; the marks are the input's points, unchanged.

use super::{
    Algorithm, Barba, Certificate, ChazelleDobkin, Clm, Convert, Dobkin, Fallback, Kept, Linear, Probe, Span,
    Which, fresh_rng,
};
use crate::intersect::{ArrayEngine, LinkedEngine};
use crate::kernel::{Kernel, Point};
use crate::lp::{ArenaPoints, LpError, Separation};
use crate::polygon::{ConvexPolygon, LinkedPolygon};
use rand::Rng;

/// What a mark of a step shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Role {
    /// Barba–Langerman's inner triangle T_P.
    Triangle,
    /// A supporting line of what is kept (T_Q's edge lines, the y-interval's heights).
    Bound,
    /// Chazelle–Dobkin's pivot and pencil (segments from the pivot to the tangents).
    Pencil,
    /// Chazelle–Dobkin's window (segments from the pivot along its two directions).
    Window,
    /// CLM's sample points, or the point sets an LP was given.
    Sample,
    /// A CLM chain walk's vertices.
    Chain,
    /// A separating line (an LP's bitangent, a certificate's edge).
    Separator,
    /// A certificate's witness of intersection (a vertex, two crossing edges).
    Witness,
}

/// A shape, in the input's coordinates.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// Isolated points.
    Points(Vec<Point>),
    /// An open polyline.
    Polyline(Vec<Point>),
    /// A closed polygon.
    Polygon(Vec<Point>),
    /// The segment between two points.
    Segment(Point, Point),
    /// The whole line through two distinct points, directed from the first.
    Line(Point, Point),
}

/// One thing a step draws, and whose it is (`None`: neither polygon's alone).
#[derive(Clone, Debug, PartialEq)]
pub struct Mark {
    /// What it shows.
    pub role: Role,
    /// The polygon it belongs to.
    pub of: Option<Which>,
    /// Where.
    pub shape: Shape,
}

/// One step of a [`Trace`].
#[derive(Clone, Debug, PartialEq)]
pub struct TraceStep {
    /// What the step does, in one sentence.
    pub text: String,
    /// Vertices of P and of Q the algorithm keeps after this step's state was reported
    /// (empty for CLM, which keeps no index ranges, and for the last step).
    pub kept: [Vec<Span>; 2],
    /// Vertices of P and of Q pruned since the previous step.
    pub pruned: [Vec<Span>; 2],
    /// What else the step draws.
    pub marks: Vec<Mark>,
    /// On the last step only: the answer.
    pub answer: Option<bool>,
}

/// An algorithm's run, step by step (module docs).
#[derive(Clone, Debug, PartialEq)]
pub struct Trace {
    /// The algorithm traced.
    pub algorithm: Algorithm,
    /// The steps, the last one with the answer and the certificate.
    pub steps: Vec<TraceStep>,
    /// The certificate of the answer, as the certified call returns it.
    pub certificate: Certificate,
}

impl Trace {
    /// The answer ([`Certificate::intersects`]).
    pub fn intersects(&self) -> bool {
        self.certificate.intersects()
    }
}

/// A [`Probe`] that records the steps of a run on `p` and `q` (given as the arrays the
/// algorithm sees; for CLM also the linked polygons, to tell its point sets apart).
#[derive(Debug)]
pub struct Tracer<'a> {
    p: &'a [Point],
    q: &'a [Point],
    linked: Option<[&'a LinkedPolygon; 2]>,
    /// Per polygon, per vertex: still kept.
    flags: [Vec<bool>; 2],
    /// Whether [`Probe::kept`] reports are ignored (Convert's array test runs on walked
    /// arrays, not on `p` and `q`).
    arrays_hidden: bool,
    /// Dobkin's two searches' latest state (search 0 has P's left chain).
    dobkin: [Option<(Span, Span)>; 2],
    steps: Vec<TraceStep>,
}

impl<'a> Tracer<'a> {
    /// A tracer of a run on the arrays `p` and `q`.
    pub fn new(p: &'a [Point], q: &'a [Point]) -> Tracer<'a> {
        Tracer {
            p,
            q,
            linked: None,
            arrays_hidden: false,
            flags: [vec![true; p.len()], vec![true; q.len()]],
            dobkin: [None, None],
            steps: Vec::new(),
        }
    }

    /// A tracer of a linked-polygon run on `lp` and `lq`, whose vertices are `p` and `q`.
    pub fn linked(
        p: &'a [Point],
        q: &'a [Point],
        lp: &'a LinkedPolygon,
        lq: &'a LinkedPolygon,
    ) -> Tracer<'a> {
        Tracer {
            linked: Some([lp, lq]),
            ..Tracer::new(p, q)
        }
    }

    /// The steps recorded so far.
    pub fn steps(&self) -> &[TraceStep] {
        &self.steps
    }

    /// The recorded steps followed by the last step, showing `certificate`.
    pub fn finish(self, algorithm: Algorithm, certificate: Certificate) -> Trace {
        let mut steps = self.steps;
        steps.push(answer_step(&certificate));
        Trace {
            algorithm,
            steps,
            certificate,
        }
    }

    fn vertices(&self, which: Which) -> &'a [Point] {
        match which {
            Which::P => self.p,
            Which::Q => self.q,
        }
    }

    /// Records a step keeping `kept` (per polygon; `None`: the whole polygon).
    fn step(&mut self, text: String, kept: [Option<Vec<Span>>; 2], marks: Vec<Mark>) {
        let mut kept_out: [Vec<Span>; 2] = Default::default();
        let mut pruned_out: [Vec<Span>; 2] = Default::default();
        for (side, kept) in kept.into_iter().enumerate() {
            let n = self.flags[side].len();
            let mut now = vec![kept.is_none(); n];
            for span in kept.iter().flatten() {
                for i in span.indices(n) {
                    now[i] = true;
                }
            }
            let gone: Vec<bool> = self.flags[side]
                .iter()
                .zip(&now)
                .map(|(&a, &b)| a && !b)
                .collect();
            kept_out[side] = runs(&now);
            pruned_out[side] = runs(&gone);
            self.flags[side] = now;
        }
        self.steps.push(TraceStep {
            text,
            kept: kept_out,
            pruned: pruned_out,
            marks,
            answer: None,
        });
    }

    /// A step that keeps no index ranges (CLM's), only marks.
    fn note(&mut self, text: String, marks: Vec<Mark>) {
        self.steps.push(TraceStep {
            text,
            kept: Default::default(),
            pruned: Default::default(),
            marks,
            answer: None,
        });
    }

    /// Which polygon a CLM point set belongs to.
    fn owner(&self, set: &ArenaPoints<'_>) -> Option<Which> {
        let [lp, lq] = self.linked?;
        if std::ptr::eq(set.polygon, lp) {
            Some(Which::P)
        } else if std::ptr::eq(set.polygon, lq) {
            Some(Which::Q)
        } else {
            None
        }
    }
}

/// The maximal runs of `true` in `flags`, as spans (a run through the end continues at
/// index 0).
fn runs(flags: &[bool]) -> Vec<Span> {
    let n = flags.len();
    let mut out = Vec::new();
    if n == 0 {
        return out;
    }
    if flags.iter().all(|&f| f) {
        out.push(Span::new(0, n));
        return out;
    }
    // Start right after a `false`, so that no run is cut at the array's end.
    let first_false = flags.iter().position(|&f| !f).unwrap_or(0);
    let mut i = 0;
    while i < n {
        let at = (first_false + i) % n;
        if flags[at] {
            let mut len = 0;
            while i < n && flags[(first_false + i) % n] {
                len += 1;
                i += 1;
            }
            out.push(Span::new(at, len));
        } else {
            i += 1;
        }
    }
    out
}

fn points(set: &ArenaPoints<'_>) -> Vec<Point> {
    set.positions
        .iter()
        .map(|&i| set.polygon.point_at(i as usize))
        .collect()
}

fn at(v: &[Point], span: Span, pos: usize) -> Point {
    v[(span.start + pos) % v.len()]
}

fn name(which: Option<Which>) -> &'static str {
    match which {
        Some(Which::P) => "P",
        Some(Which::Q) => "Q",
        None => "?",
    }
}

/// The last step: the answer and the certificate's marks.
fn answer_step(certificate: &Certificate) -> TraceStep {
    let (text, marks) = match *certificate {
        Certificate::Separated { of, from, to } => (
            format!(
                "disjoint: the line of {}'s edge ({}, {}) → ({}, {}) has the other polygon strictly on its outer side",
                name(Some(of)),
                from.x,
                from.y,
                to.x,
                to.y
            ),
            vec![
                Mark {
                    role: Role::Separator,
                    of: Some(of),
                    shape: Shape::Line(from, to),
                },
                Mark {
                    role: Role::Separator,
                    of: Some(of),
                    shape: Shape::Segment(from, to),
                },
            ],
        ),
        Certificate::VertexInside { of, point } => (
            format!(
                "intersecting: {}'s vertex ({}, {}) lies in the other polygon",
                name(Some(of)),
                point.x,
                point.y
            ),
            vec![Mark {
                role: Role::Witness,
                of: Some(of),
                shape: Shape::Points(vec![point]),
            }],
        ),
        Certificate::CrossingEdges { p, q } => (
            "intersecting: an edge of P and an edge of Q share a point".to_string(),
            vec![
                Mark {
                    role: Role::Witness,
                    of: Some(Which::P),
                    shape: Shape::Segment(p[0], p[1]),
                },
                Mark {
                    role: Role::Witness,
                    of: Some(Which::Q),
                    shape: Shape::Segment(q[0], q[1]),
                },
            ],
        ),
    };
    TraceStep {
        text,
        kept: Default::default(),
        pruned: Default::default(),
        marks,
        answer: Some(certificate.intersects()),
    }
}

impl Probe for Tracer<'_> {
    fn fallback(&mut self, kind: Fallback) {
        let text = match kind {
            Fallback::Search => {
                "the algorithm's findings give the answer only: an O(log n + log m) search completes the certificate"
            }
            Fallback::Reference => {
                "the completing search contradicted the answer: the O(n + m) reference certifies it"
            }
        };
        self.note(text.to_string(), Vec::new());
    }

    fn samples(&mut self, p: &ArenaPoints<'_>, q: &ArenaPoints<'_>) {
        let marks = [p, q]
            .iter()
            .map(|s| Mark {
                role: Role::Sample,
                of: self.owner(s),
                shape: Shape::Points(points(s)),
            })
            .collect();
        let text = format!(
            "samples: {} vertices of P and {} of Q, drawn at random",
            p.positions.len(),
            q.positions.len()
        );
        self.note(text, marks);
    }

    fn lp_call(
        &mut self,
        a: &ArenaPoints<'_>,
        b: &ArenaPoints<'_>,
        work: u64,
        result: &Result<Separation, LpError>,
    ) {
        let (oa, ob) = (self.owner(a), self.owner(b));
        let mut marks: Vec<Mark> = [(a, oa), (b, ob)]
            .iter()
            .map(|(s, of)| Mark {
                role: Role::Sample,
                of: *of,
                shape: Shape::Points(points(s)),
            })
            .collect();
        let sets = format!(
            "LP on {} points of {} and {} of {} ({work} examined)",
            a.positions.len(),
            name(oa),
            b.positions.len(),
            name(ob)
        );
        let text = match result {
            Ok(Separation::Separated(t)) => {
                marks.push(Mark {
                    role: Role::Separator,
                    of: None,
                    shape: Shape::Line(t.start, t.end),
                });
                format!(
                    "{sets}: their hulls are disjoint, separated by this line; the far sides are walked next"
                )
            }
            Ok(Separation::Intersecting) => format!("{sets}: their hulls meet, so the polygons intersect"),
            Err(e) => format!("{sets}: {e:?}"),
        };
        self.note(text, marks);
    }

    fn sample_quads(&mut self, _tested: u64, inside: Option<(Which, Point, [Point; 4])>) {
        // Only the test that ends the query makes a step.
        let Some((of, point, quad)) = inside else {
            return;
        };
        let other = if of == Which::P { Which::Q } else { Which::P };
        let text = format!(
            "the sample vertex ({}, {}) of {} lies in a quadrilateral of {}'s sample vertices, so inside {}: the polygons intersect",
            point.x,
            point.y,
            name(Some(of)),
            name(Some(other)),
            name(Some(other))
        );
        let marks = vec![
            Mark {
                role: Role::Sample,
                of: Some(other),
                shape: Shape::Polygon(quad.to_vec()),
            },
            Mark {
                role: Role::Witness,
                of: Some(of),
                shape: Shape::Points(vec![point]),
            },
        ];
        self.note(text, marks);
    }

    fn chain_walk(&mut self, chain: &ArenaPoints<'_>) {
        let of = self.owner(chain);
        let text = format!(
            "walk: {} vertices of {} beyond the last line",
            chain.positions.len(),
            name(of)
        );
        let marks = vec![Mark {
            role: Role::Chain,
            of,
            shape: Shape::Polyline(points(chain)),
        }];
        self.note(text, marks);
    }

    fn kept(&mut self, kept: Kept<'_>) {
        if self.arrays_hidden {
            return;
        }
        let (p, q) = (self.p, self.q);
        match kept {
            Kept::Barba { p: pr, tp, q: qr } => {
                let t = tp.iter().map(|&i| at(p, pr, i)).collect();
                let m1 = (qr.len.max(2) - 2) / 2;
                let mut marks = vec![Mark {
                    role: Role::Triangle,
                    of: Some(Which::P),
                    shape: Shape::Polygon(t),
                }];
                for e in [0, m1, qr.len.max(2) - 2] {
                    marks.push(Mark {
                        role: Role::Bound,
                        of: Some(Which::Q),
                        shape: Shape::Line(at(q, qr, e), at(q, qr, e + 1)),
                    });
                }
                let text = format!(
                    "P' has {} vertices, Q' {}: T_P, P''s inner triangle, against the edge hull of three edges of Q'; one of them is halved",
                    pr.len, qr.len
                );
                self.step(text, [Some(vec![pr]), Some(vec![qr])], marks);
            }
            Kept::BarbaSmall { p: pr, tp, q: qs } => {
                let t = tp.iter().map(|&i| at(p, pr, i)).collect();
                let marks = vec![
                    Mark {
                        role: Role::Triangle,
                        of: Some(Which::P),
                        shape: Shape::Polygon(t),
                    },
                    Mark {
                        role: Role::Bound,
                        of: Some(Which::Q),
                        shape: Shape::Polygon(qs.iter().map(|&i| q[i % q.len()]).collect()),
                    },
                ];
                let text = format!(
                    "finish: T_P of P' ({} vertices) against Q' given by its {} vertices; a separating axis halves P'",
                    pr.len,
                    qs.len()
                );
                let q_kept = qs.iter().map(|&i| Span::new(i, 1)).collect();
                self.step(text, [Some(vec![pr]), Some(q_kept)], marks);
            }
            Kept::Dobkin {
                left,
                l,
                right: _,
                r,
                heights,
            } => {
                // Search 0 has P's left chain (when P and Q are the same array, either
                // reading is right).
                let search = usize::from(!std::ptr::eq(left, p));
                self.dobkin[search] = Some((l, r));
                let (lw, rw) = if search == 0 {
                    (Which::P, Which::Q)
                } else {
                    (Which::Q, Which::P)
                };
                let (lv, rv) = (self.vertices(lw), self.vertices(rw));
                let mut kept: [Option<Vec<Span>>; 2] = [Some(Vec::new()), Some(Vec::new())];
                for (s, state) in self.dobkin.iter().enumerate() {
                    let (l_of, r_of) = if s == 0 { (0, 1) } else { (1, 0) };
                    match state {
                        Some((l, r)) => {
                            if let Some(k) = kept[l_of].as_mut() {
                                k.push(*l);
                            }
                            if let Some(k) = kept[r_of].as_mut() {
                                k.push(*r);
                            }
                        }
                        None => kept = [None, None],
                    }
                }
                let (x0, x1) = p
                    .iter()
                    .chain(q)
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                        (a.min(v.x), b.max(v.x))
                    });
                let x1 = if x1 > x0 { x1 } else { x0 + 1.0 };
                let marks = vec![
                    Mark {
                        role: Role::Chain,
                        of: Some(lw),
                        shape: Shape::Polyline((0..l.len).map(|i| at(lv, l, i)).collect()),
                    },
                    Mark {
                        role: Role::Chain,
                        of: Some(rw),
                        shape: Shape::Polyline((0..r.len).map(|i| at(rv, r, i)).collect()),
                    },
                    Mark {
                        role: Role::Bound,
                        of: None,
                        shape: Shape::Line(Point::new(x0, heights[0]), Point::new(x1, heights[0])),
                    },
                    Mark {
                        role: Role::Bound,
                        of: None,
                        shape: Shape::Line(Point::new(x0, heights[1]), Point::new(x1, heights[1])),
                    },
                ];
                let text = format!(
                    "{}'s left chain ({} vertices) against {}'s right chain ({} vertices) in heights [{}, {}]: the middle edges' slopes halve one chain",
                    name(Some(lw)),
                    l.len,
                    name(Some(rw)),
                    r.len,
                    heights[0],
                    heights[1]
                );
                self.step(text, kept, marks);
            }
            Kept::ChazelleDobkin {
                f,
                g,
                pivot,
                tangents,
                window,
            } => {
                let marks = vec![
                    Mark {
                        role: Role::Pencil,
                        of: Some(Which::Q),
                        shape: Shape::Segment(pivot, tangents[0]),
                    },
                    Mark {
                        role: Role::Pencil,
                        of: Some(Which::Q),
                        shape: Shape::Segment(pivot, tangents[1]),
                    },
                    Mark {
                        role: Role::Window,
                        of: None,
                        shape: Shape::Line(pivot, window[0]),
                    },
                    Mark {
                        role: Role::Window,
                        of: None,
                        shape: Shape::Line(pivot, window[1]),
                    },
                    Mark {
                        role: Role::Chain,
                        of: Some(Which::P),
                        shape: Shape::Polyline((0..f.len).map(|i| at(p, f, i)).collect()),
                    },
                    Mark {
                        role: Role::Chain,
                        of: Some(Which::Q),
                        shape: Shape::Polyline((0..g.len).map(|i| at(q, g, i)).collect()),
                    },
                ];
                let text = format!(
                    "pencil of tangents from P's vertex 0 to Q; in its window, F ⊆ P ({} edges) and G ⊆ Q ({} edges): middle-edge slopes halve one",
                    f.len - 1,
                    g.len - 1
                );
                self.step(text, [Some(vec![f]), Some(vec![g])], marks);
            }
        }
    }
}

/// Traces `algorithm`'s certified call on `p` and `q` with `kernel` (module docs). CLM
/// and Convert link the polygons in shuffled order and draw from a generator seeded
/// from the operating system ([`trace_rng`] for reproducible runs).
///
/// # Cost
/// Unbounded by design: the trace keeps every step, and a step keeps the points of its
/// marks (a chain's vertices for Dobkin–Souvaine, the LP's point sets for CLM), so time
/// and memory grow as O((n + m) log(n + m)) points. Two polygons of 2^20 vertices under
/// Dobkin–Souvaine give tens of millions of points (hundreds of megabytes, seconds);
/// the live page traces polygons of at most a few thousand vertices. Bound the inputs
/// before tracing; the plain and certified calls allocate nothing of this.
///
/// ```
/// use polysect::intersect::{Algorithm, trace};
/// use polysect::{ConvexPolygon, Exact};
/// let p = polysect::generate::regular_polygon(64, 1.0);
/// let q = p.map(|v| polysect::Point::new(v.x + 1.5, v.y))?;
/// let t = trace(Algorithm::Barba, Exact, &p, &q);
/// assert!(t.steps.len() > 1);
/// assert_eq!(t.steps.last().unwrap().answer, Some(true));
/// assert_eq!(t.certificate, Algorithm::Barba.certified_with(Exact, &p, &q));
/// # Ok::<(), polysect::PolygonError>(())
/// ```
pub fn trace<K: Kernel>(algorithm: Algorithm, kernel: K, p: &ConvexPolygon, q: &ConvexPolygon) -> Trace {
    trace_rng(algorithm, kernel, p, q, &mut fresh_rng())
}

/// [`trace`] drawing from `rng` exactly as
/// [`Algorithm::run_certified_with_rng`] does, so that both give the same certificate
/// from generators in the same state.
pub fn trace_rng<K: Kernel, R: Rng + ?Sized>(
    algorithm: Algorithm,
    kernel: K,
    p: &ConvexPolygon,
    q: &ConvexPolygon,
    rng: &mut R,
) -> Trace {
    let (pv, qv) = (p.vertices(), q.vertices());
    let array = |tracer: &mut Tracer<'_>| match algorithm {
        Algorithm::Linear => Some(Linear.certified_probed(kernel, p, q, tracer)),
        Algorithm::Barba => Some(Barba.certified_probed(kernel, p, q, tracer)),
        Algorithm::Dobkin => Some(Dobkin.certified_probed(kernel, p, q, tracer)),
        Algorithm::ChazelleDobkin => Some(ChazelleDobkin.certified_probed(kernel, p, q, tracer)),
        Algorithm::Clm | Algorithm::Convert => None,
    };
    let mut tracer = Tracer::new(pv, qv);
    if let Some(certificate) = array(&mut tracer) {
        return tracer.finish(algorithm, certificate);
    }
    let lp = LinkedPolygon::from_convex_shuffled(p, rng);
    let lq = LinkedPolygon::from_convex_shuffled(q, rng);
    let mut tracer = Tracer::linked(pv, qv, &lp, &lq);
    tracer.arrays_hidden = algorithm == Algorithm::Convert;
    let certificate = match algorithm {
        Algorithm::Clm => Clm.certified_in(kernel, &lp, &lq, rng, &mut Default::default(), &mut tracer),
        _ => <Convert>::default().certified_in(kernel, &lp, &lq, rng, &mut Default::default(), &mut tracer),
    };
    tracer.finish(algorithm, certificate)
}
