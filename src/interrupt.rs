//! Interrupting long exact work from outside: a host that owns the signals (Python, whose Ctrl-C
//! the library cannot see) installs a hook once, and the iterated work of the general solver
//! asks it between units of work (a sweep, a pivot, an impact, a contact mode; see
//! [`crate::impact::Work`]), stopping with [`crate::impact::Stopped::Interrupted`]. The command
//! line installs none: the default signal action ends the process.
//!
//! # Examples
//! ```
//! fn never() -> bool { false }
//! rodimpact::interrupt::set_hook(never);
//! assert!(!rodimpact::interrupt::requested());
//! ```

use std::sync::OnceLock;

static HOOK: OnceLock<fn() -> bool> = OnceLock::new();

/// Installs `hook`, which says whether the host asked to stop (it may run the host's signal
/// handlers). The first hook installed stays; returns whether this one was.
pub fn set_hook(hook: fn() -> bool) -> bool {
    HOOK.set(hook).is_ok()
}

/// Whether the host asked to stop (false without a hook).
pub fn requested() -> bool {
    HOOK.get().is_some_and(|hook| hook())
}
