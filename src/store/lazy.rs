//! [`LazyLinked`]: a scene's linked polygon with its translations not yet applied.
//!
//! # Why
//! A rigid motion translates every polygon every frame. The array snapshot, which the
//! array test reads, is translated at once (a sequential pass over 16 bytes a vertex);
//! the linked polygon is read only by edits, by the tests on linked polygons, by
//! conversions and by callers who ask for it, so its translations wait here, in order,
//! until something reads it, and are then applied in one pass over the arena.
//!
//! # Exactness
//! The coordinates are bit-for-bit those of eager translation: a pending list holds the
//! vectors in the order they were asked for, and applying it gives each coordinate the
//! same IEEE additions in the same order (`(x + d₁) + d₂`, never `x + (d₁ + d₂)`). Whether
//! a translation is allowed (finite, strictly convex after rounding) is decided by the
//! scene when it is asked for, on the coordinates it then has (the snapshot's, equal to
//! the materialized ones); only translations already accepted wait here.
//!
//! # No way around it
//! The linked polygon is private to this file: [`get`](LazyLinked::get),
//! [`get_mut`](LazyLinked::get_mut), [`materialized`](LazyLinked::materialized) and
//! [`into_inner`](LazyLinked::into_inner) all give the translated coordinates;
//! [`arena`](LazyLinked::arena) and [`arena_bytes`](LazyLinked::arena_bytes) give only
//! what translations do not change. Paths holding `&mut` materialize in place (one pass);
//! a shared reference with translations pending (a caller's `Scene::polygon`, parallel
//! answers) gets a translated twin built once beside the polygon (same identity, so the
//! same vertex handles), which the next `&mut` access keeps in place of the old arena.
//!
//! # Poses
//! A posed polygon whose pose the scene accepted without building the image
//! ([`remap`](LazyLinked::remap): every image finite, the rounded image proved strictly
//! convex) is the shape's image under the pose, each coordinate as `Pose::apply` rounds
//! it; the same accessors build it (a twin of the shape, so the same vertex handles)
//! when first read, O(n), and the next `&mut` access keeps it as the arena.
//!
//! # Cost and memory
//! [`translate`](LazyLinked::translate) is O(1); materializing is one sequential pass
//! over the arena for up to [`MAX_PENDING`] translations (O(n · pending) additions,
//! bound by memory traffic, not by the additions). The list is a fixed array, and a
//! translation that finds it full materializes first: memory per polygon is bounded
//! (the arena, at most one twin of it while a shared reader needs it, and the fixed
//! list, allocated at the polygon's first translation so that a polygon never translated
//! costs its slot one pointer), whatever the number of translations.

use super::cost::ArenaProfile;
use crate::kernel::{Point, Pose};
use crate::polygon::LinkedPolygon;
use std::sync::{Arc, OnceLock};

/// Translations a polygon may hold unapplied: a translation beyond them applies them all
/// first. Eight makes the arena pass of rigid motion an eighth of eager translation's
/// (measured in docs/store.md) for a list of 128 bytes (168 with its bookkeeping) a
/// translated polygon.
pub(super) const MAX_PENDING: usize = 8;

/// A linked polygon and the translations accepted for it but not yet applied to its
/// arena; every accessor shows the translated polygon.
#[derive(Debug)]
pub(super) struct LazyLinked {
    /// The polygon before the pending translations.
    base: LinkedPolygon,
    /// Allocated at the first translation and kept (a polygon never translated pays
    /// one pointer: the slots of a scene stay small, and planning reads them).
    lazy: Option<Box<Pending>>,
    /// A posed polygon's pending pose: while `pending`, the polygon is the image of the
    /// shape under the pose (each coordinate as `Pose::apply` rounds it), not `base`.
    /// Allocated at the first lazy pose and kept.
    remap: Option<Box<Remap>>,
}

/// A pose accepted by the scene (every image finite, the rounded image strictly convex)
/// but not yet applied.
#[derive(Debug)]
struct Remap {
    shape: Arc<LinkedPolygon>,
    pose: Pose,
    pending: bool,
    /// The image, built for a shared reader; taken as `base` at the next `&mut` access.
    world: OnceLock<LinkedPolygon>,
}

impl Remap {
    fn image(&self) -> LinkedPolygon {
        let pose = self.pose;
        self.shape
            .mapped_twin_unchecked(|p| pose.apply(p).expect("an accepted pose has every image finite"))
    }
}

#[derive(Debug)]
struct Pending {
    /// The first `len` are pending, oldest first.
    steps: [Point; MAX_PENDING],
    len: u8,
    /// `base` with the pending translations applied, built for a shared reader; taken
    /// in place of `base` at the next `&mut` access. Empty when nothing is pending.
    twin: OnceLock<LinkedPolygon>,
}

impl Clone for LazyLinked {
    /// The same translated polygon: a clone of the arena and of the list (a clone's
    /// twin, if one is needed, is built from the clone's arena, so it has the clone's
    /// identity).
    fn clone(&self) -> Self {
        LazyLinked {
            base: self.base.clone(),
            lazy: self.lazy.as_ref().map(|p| {
                Box::new(Pending {
                    steps: p.steps,
                    len: p.len,
                    twin: OnceLock::new(),
                })
            }),
            remap: self.remap.as_ref().map(|r| {
                Box::new(Remap {
                    shape: r.shape.clone(),
                    pose: r.pose,
                    pending: r.pending,
                    world: OnceLock::new(),
                })
            }),
        }
    }
}

impl LazyLinked {
    /// `polygon`, nothing pending.
    pub(super) fn new(polygon: LinkedPolygon) -> Self {
        LazyLinked {
            base: polygon,
            lazy: None,
            remap: None,
        }
    }

    /// Records a pose the caller has accepted for `shape` (a twin of the polygon: the
    /// same vertex handles): from now on the polygon is the shape's image, built when
    /// it is next read. Pending translations are dropped (the image replaces every
    /// coordinate). O(1).
    pub(super) fn remap(&mut self, shape: &Arc<LinkedPolygon>, pose: Pose) {
        if let Some(p) = self.lazy.as_deref_mut() {
            p.len = 0;
            p.twin.take();
        }
        match self.remap.as_deref_mut() {
            Some(r) => {
                if !Arc::ptr_eq(&r.shape, shape) {
                    r.shape = shape.clone();
                }
                r.pose = pose;
                r.pending = true;
                r.world.take();
            }
            None => {
                self.remap = Some(Box::new(Remap {
                    shape: shape.clone(),
                    pose,
                    pending: true,
                    world: OnceLock::new(),
                }));
            }
        }
    }

    /// The pending pose's state, when one is pending.
    fn remapped(&self) -> Option<&Remap> {
        self.remap.as_deref().filter(|r| r.pending)
    }

    /// Whether the polygon is a pose's image not yet built in place.
    #[cfg(test)]
    pub(super) fn remap_pending(&self) -> bool {
        self.remapped().is_some()
    }

    /// The translations waiting, when there are any.
    fn waiting(&self) -> Option<&Pending> {
        self.lazy.as_deref().filter(|p| p.len > 0)
    }

    /// Number of translations not yet applied to the arena.
    #[cfg(test)]
    pub(super) fn pending(&self) -> usize {
        self.waiting().map_or(0, |p| p.len as usize)
    }

    /// The translated polygon. O(1) when nothing is pending (every `&mut` path leaves it
    /// so); otherwise the first call builds the translated twin, O(n · pending).
    pub(super) fn get(&self) -> &LinkedPolygon {
        if let Some(r) = self.remapped() {
            return r.world.get_or_init(|| r.image());
        }
        match self.waiting() {
            None => &self.base,
            Some(p) => p
                .twin
                .get_or_init(|| self.base.translated_twin(&p.steps[..p.len as usize])),
        }
    }

    /// Applies the pending translations in place (or keeps the twin a shared reader
    /// built) and returns the polygon. O(n · pending), O(1) when nothing is pending.
    pub(super) fn materialized(&mut self) -> &LinkedPolygon {
        self.materialize();
        &self.base
    }

    /// [`materialized`](Self::materialized), for an edit.
    pub(super) fn get_mut(&mut self) -> &mut LinkedPolygon {
        self.materialize();
        &mut self.base
    }

    /// The translated polygon, owned.
    pub(super) fn into_inner(mut self) -> LinkedPolygon {
        self.materialize();
        self.base
    }

    fn materialize(&mut self) {
        if let Some(r) = self.remap.as_deref_mut().filter(|r| r.pending) {
            self.base = match r.world.take() {
                Some(world) => world,
                None => r.image(),
            };
            r.pending = false;
        }
        let Some(p) = self.lazy.as_deref_mut().filter(|p| p.len > 0) else {
            return;
        };
        if let Some(twin) = p.twin.take() {
            self.base = twin;
        } else {
            self.base.translate_steps_unchecked(&p.steps[..p.len as usize]);
        }
        p.len = 0;
    }

    /// Records a translation by `(dx, dy)` that the caller has accepted: no translated
    /// coordinate overflows, and the rounded polygon is strictly convex. O(1), or one
    /// pass when the list is full (or a twin is kept: it becomes the arena first).
    pub(super) fn translate(&mut self, dx: f64, dy: f64) {
        if self.remapped().is_some() {
            self.materialize();
        }
        let full = self
            .lazy
            .as_deref()
            .is_some_and(|p| p.len as usize == MAX_PENDING || p.twin.get().is_some());
        if full {
            self.materialize();
        }
        let p = self.lazy.get_or_insert_with(|| {
            Box::new(Pending {
                steps: [Point::new(0.0, 0.0); MAX_PENDING],
                len: 0,
                twin: OnceLock::new(),
            })
        });
        p.steps[p.len as usize] = Point::new(dx, dy);
        p.len += 1;
    }

    /// The arena's size and order, for the cost model (translations change neither).
    pub(super) fn arena(&self) -> ArenaProfile {
        ArenaProfile::of(&self.base)
    }

    /// Heap bytes of the arena, of the list once allocated, and of the twin while one is
    /// kept.
    pub(super) fn arena_bytes(&self) -> usize {
        let lazy = self.lazy.as_deref().map_or(0, |p| {
            std::mem::size_of::<Pending>() + p.twin.get().map_or(0, LinkedPolygon::arena_bytes)
        });
        let remap = self.remap.as_deref().map_or(0, |r| {
            std::mem::size_of::<Remap>() + r.world.get().map_or(0, LinkedPolygon::arena_bytes)
        });
        self.base.arena_bytes() + lazy + remap
    }
}
