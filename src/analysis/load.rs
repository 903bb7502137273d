//! External loads after seating and the safe load envelope.
//!
//! A load (force F at a point of the moving half, moment M) is applied after
//! the preload, which is held: the quasi-static solver continues from the
//! seated pose and the at-rest contact states
//! ([`crate::solve::quasistatic::apply_load`]) and ramps lambda (F, M) from
//! lambda = 0. Static friction governs at rest, so a contact that slid
//! during seating (|F_t| = mu_d F_n) sticks until |F_t| reaches mu_s F_n.
//!
//! The envelope is the smallest load factor lambda* at which a contact
//! separates (F_n -> 0) or starts to slip (|F_t| -> mu_s F_n): below it the
//! coupling returns to its seat when the load is removed (the response is
//! elastic), above it the seat is lost or changed. lambda* is found with
//! full nonlinear load paths: factors 1, 4, 16, ... until a path shows an
//! event (each path locates its first event between two of its increments,
//! halved 2^max_splits times), then bisection on the end factor of fresh
//! paths from the seated state, until the bracket is below
//! [`ENVELOPE_TOLERANCE`] of lambda*.

use crate::assembly::Coupling;
use crate::solve::quasistatic::{ExternalLoad, LoadEvent, LoadPath, apply_load, at_rest_states};
use crate::solve::{Load, Seating, SolveError, SolverOptions};

/// Relative width of the final bracket of the envelope factor.
pub const ENVELOPE_TOLERANCE: f64 = 1e-5;
/// The envelope search stops at this load factor.
pub const MAX_FACTOR: f64 = 1e6;

/// Largest distance of a load point from the origin, in multiples of the
/// coupling's size (the largest distance of a ball centre from the
/// origin): a lever a thousand times the coupling is no load a coupling is
/// built for, and a far larger one (1e300 m) turns the moment into
/// rounding noise or infinity, so the point is refused (usually
/// millimetres typed as metres).
pub const LEVER_RATIO_MAX: f64 = 1e3;

/// The distance of `point` from the origin (its largest coordinate, which
/// cannot overflow) over the coupling's size (see [`LEVER_RATIO_MAX`]),
/// and that size [m].
pub fn lever_ratio(coupling: &Coupling, point: &nalgebra::Vector3<f64>) -> (f64, f64) {
    let size = (coupling.balls.iter()).map(|b| b.centre.norm()).fold(0.0, f64::max);
    (point.amax() / size, size)
}

/// The safe load envelope along one load direction.
#[derive(Debug, Clone, PartialEq)]
pub struct Envelope {
    /// The first event and its bracket [previous, factor] (relative width
    /// below [`ENVELOPE_TOLERANCE`]); `None` if no event up to `searched_to`.
    pub event: Option<LoadEvent>,
    /// Largest factor solved without an event.
    pub searched_to: f64,
}

impl Envelope {
    /// The critical factor: the middle of the bracket.
    pub fn factor(&self) -> Option<f64> {
        self.event.map(|e| 0.5 * (e.previous + e.factor))
    }
}

/// A load path from the state `seating` seated under `seated` to
/// `factor` x `external`.
pub fn load_path(
    coupling: &Coupling,
    seated: &Load,
    seating: &Seating,
    external: &ExternalLoad,
    factor: f64,
    opts: &SolverOptions,
) -> Result<LoadPath, SolveError> {
    let states = at_rest_states(seating);
    apply_load(coupling, seated, &seating.pose(), &states, external, factor, opts)
}

/// The safe load envelope (module doc).
pub fn envelope(
    coupling: &Coupling,
    seated: &Load,
    seating: &Seating,
    external: &ExternalLoad,
    opts: &SolverOptions,
) -> Result<Envelope, SolveError> {
    let run = |f: f64| load_path(coupling, seated, seating, external, f, opts);
    let mut lo = 0.0;
    let mut f = 1.0;
    let first = loop {
        match run(f) {
            Ok(LoadPath { first_event: Some(e), .. }) => break e,
            Ok(_) => lo = f,
            Err(e) if f <= 1.0 => return Err(e),
            // A path that fails without an event beyond the given load ends
            // the search (the solver's travel limit, far beyond any event).
            Err(_) => f = MAX_FACTOR,
        }
        if f >= MAX_FACTOR {
            return Ok(Envelope { event: None, searched_to: lo });
        }
        f *= 4.0;
    };
    let mut best = first;
    let mut lo = first.previous.max(lo);
    let mut hi = first.factor;
    while hi - lo > ENVELOPE_TOLERANCE * hi {
        let mid = 0.5 * (lo + hi);
        let p = run(mid)?;
        match p.first_event {
            Some(e) => {
                best = e;
                hi = e.factor.min(mid);
                lo = lo.max(e.previous).min(hi);
            }
            None => lo = mid,
        }
    }
    Ok(Envelope { event: Some(LoadEvent { previous: lo, factor: hi, ..best }), searched_to: lo })
}
