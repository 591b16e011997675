//! Writing output files: one file atomically ([`AtomicFile`], [`write_atomic`]), a directory
//! of files all-or-nothing ([`write_directory`]), and the removal of temporary files when the
//! process is interrupted (`remove_temporaries_on_signals`, with the feature `signals`). What the files hold is rendered
//! by [`crate::report`]; this module only gets the bytes to disk without a reader ever seeing
//! half of them.

mod atomic;
mod output_dir;

#[cfg(feature = "signals")]
pub use atomic::remove_temporaries_on_signals;
pub use atomic::{AtomicFile, may_follow_link, write_atomic, write_atomic_bytes};
pub use output_dir::write_directory;
