//! The work a rule's own search simulates, counted in simulated pieces (branch `slowcalls`):
//! the bounds that keep every call of the module finite are counts, never wall-clock time, so
//! an answer does not depend on the machine's speed.
//!
//! A rule that simulates inside its search (Arvanitis Algorithm III's fallback when Parseval
//! does not apply) bounds one design by its own limit and [`charge`]s what the design cost,
//! also when the design comes from its cache (the cost it had when computed: so the meter moves
//! by the same amount whatever the cache holds). A call that tunes many designs (an
//! `admissible()` scan, a sweep) reads [`spent`] before and after each design and refuses once
//! the sum passes [`SCAN_MAX_PIECES`].

use std::cell::Cell;

/// Most simulated pieces one design's own search may spend (Arvanitis Algorithm III's search
/// on simulations when J cannot be taken by Parseval). Measured on main 573ebce: issue 15's
/// plant with θ = 0.5 (0.478, 0.536, 2.80, 0.5) answers ζ 0.3-0.5 after 4.9·10⁶-7.74·10⁶
/// pieces (1.3-2.4 s natively), the boiler's failing designs at ζ < 0.37 spend
/// 303,375-385,020; this is twice the largest, 0.14-0.6 µs a piece natively (2-10 s).
pub const DESIGN_MAX_PIECES: u64 = 16_000_000;

/// Most simulated pieces the designs of one `admissible()` scan or one sweep may cost
/// together (the rules' own searches; a sweep's simulations of its points are bounded by the
/// simulator's piece limit). Measured on main 573ebce: the ζ scan of Algorithm III on issue
/// 15's plant with θ = 0.5 costs 10,371,476 (3.5 s natively), on the boiler 1,427,852, on
/// (1, 1, 0.5, 0.5) 542,739; this is 2.3 times the largest.
pub const SCAN_MAX_PIECES: u64 = 24_000_000;

std::thread_local! {
    /// Simulated pieces charged on this thread since it started.
    static SPENT: Cell<u64> = const { Cell::new(0) };
    /// The limits in force: ([`DESIGN_MAX_PIECES`], [`SCAN_MAX_PIECES`]) unless a test lowered
    /// them ([`with_limits`]).
    static LIMITS: Cell<(u64, u64)> = const { Cell::new((DESIGN_MAX_PIECES, SCAN_MAX_PIECES)) };
}

/// The simulated-piece limit of one design in force on this thread.
pub fn design_limit() -> u64 {
    LIMITS.with(Cell::get).0
}

/// The simulated-piece limit of one scan or sweep in force on this thread.
pub fn scan_limit() -> u64 {
    LIMITS.with(Cell::get).1
}

/// Runs `f` with other limits (a design's, a scan's) on this thread, then restores them: for
/// tests, which check the refusals with limits that are cheap to reach. Not part of the API.
#[doc(hidden)]
pub fn with_limits<R>(design: u64, scan: u64, f: impl FnOnce() -> R) -> R {
    let old = LIMITS.with(|c| c.replace((design, scan)));
    let r = f();
    LIMITS.with(|c| c.set(old));
    r
}

/// Charges `pieces` simulated pieces to this thread's meter.
pub(crate) fn charge(pieces: u64) {
    SPENT.with(|c| c.set(c.get().saturating_add(pieces)));
}

/// The simulated pieces charged on this thread so far (a difference of two readings is the
/// work between them).
pub fn spent() -> u64 {
    SPENT.with(Cell::get)
}

/// The rules' own simulated work of one `admissible()` scan or one sweep since it began,
/// against [`scan_limit`].
pub(crate) struct Scan {
    start: u64,
}

impl Scan {
    /// A scan beginning now.
    pub(crate) fn begin() -> Scan {
        Scan { start: spent() }
    }

    /// Simulated pieces charged since the scan began.
    pub(crate) fn spent(&self) -> u64 {
        spent() - self.start
    }

    /// Whether the scan passed its limit.
    pub(crate) fn over(&self) -> bool {
        self.spent() > scan_limit()
    }
}
