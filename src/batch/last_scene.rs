//! The scenes a thread solved last, for the engine rows. An engine's log runs each scene at
//! every time step and iteration count it tries, row after row (in Rapier's fixture, 944 of
//! 1,062 rows follow a row of the same scene), and often runs its whole list of scenes again
//! under another setting (PyBullet's log: every scene at 50, then at 200 iterations). The
//! solve, its reductions and the outputs' text are done once a scene, not once a row: a row of
//! the scene solved last is answered from it, and a row of another scene looks in a table of
//! [`SLOTS`] recent scenes before it is solved (and kept there, in place of the scene of its
//! slot).
//!
//! A solved scene is a function of its cells as written and of which outputs are claimed
//! alone, and those are its key: a row gets the same line whether its scene was solved now or
//! kept. A scene the word rows cannot take is kept too (as `None`), so the rows of its run go
//! to the general row without trying again.

use std::any::Any;
use std::cell::RefCell;
use std::rc::Rc;

/// The recent scenes a thread keeps, `2^SLOT_BITS`: enough for a log's list of scenes (88 in
/// each of the engine fixtures), about 2 kB each (up to 12 kB for a scene audited in 2,560
/// bits), so a few megabytes a thread at most.
const SLOTS: usize = 1 << SLOT_BITS;
/// The bits of a slot's number.
const SLOT_BITS: u32 = 8;

/// A solved scene and its key: the claimed outputs (a byte each) and every cell, one after
/// another, with where each ends.
struct Kept {
    key: Box<[u8]>,
    ends: Box<[usize]>,
    solved: Rc<dyn Any>,
}

/// A thread's recent scenes, by their key's slot, and the slot of the last one.
struct Recent {
    table: Vec<Option<Kept>>,
    last: usize,
}

thread_local! {
    /// This thread's scenes.
    static RECENT: RefCell<Recent> = const {
        RefCell::new(Recent {
            table: Vec::new(),
            last: 0,
        })
    };
}

impl Kept {
    /// Whether this is the scene of `cells` with `wanted` claimed.
    #[inline]
    fn is_for(&self, cells: &[&[u8]], wanted: &[bool]) -> bool {
        let Some((flags, text)) = self.key.split_at_checked(wanted.len()) else {
            return false;
        };
        let mut start = 0;
        flags.iter().zip(wanted).all(|(&f, &w)| f == u8::from(w))
            && self.ends.len() == cells.len()
            && self.ends.iter().zip(cells).all(|(&end, cell)| {
                let same = text[start..end] == **cell;
                start = end;
                same
            })
    }

    /// `solved`, kept as the scene of `cells` with `wanted` claimed.
    fn of(cells: &[&[u8]], wanted: &[bool], solved: Rc<dyn Any>) -> Kept {
        let length = wanted.len() + cells.iter().map(|c| c.len()).sum::<usize>();
        let mut key = Vec::with_capacity(length);
        key.extend(wanted.iter().map(|&w| u8::from(w)));
        let ends = cells
            .iter()
            .map(|cell| {
                key.extend_from_slice(cell);
                key.len() - wanted.len()
            })
            .collect();
        Kept {
            key: key.into_boxed_slice(),
            ends,
            solved,
        }
    }

    /// The solved scene, if it is an `S`'s.
    fn as_a<S: Any>(&self) -> Option<Rc<Option<S>>> {
        Rc::clone(&self.solved).downcast::<Option<S>>().ok()
    }
}

/// The slot of the key of `cells` with `wanted` claimed in the table: a multiplicative hash
/// (rustc's FxHash step) of its bytes, eight at a time, and of each cell's length.
fn slot(cells: &[&[u8]], wanted: &[bool]) -> usize {
    let mut hash = 0u64;
    let mut mix = |x: u64| hash = (hash.rotate_left(5) ^ x).wrapping_mul(0x517c_c1b7_2722_0a95);
    for &w in wanted {
        mix(u64::from(w));
    }
    for cell in cells {
        let eights = cell.chunks_exact(8);
        let rest = eights.remainder();
        for eight in eights {
            mix(eight.try_into().map_or(0, u64::from_le_bytes));
        }
        let mut last = [0u8; 8];
        last[..rest.len()].copy_from_slice(rest);
        mix(u64::from_le_bytes(last) ^ ((cell.len() as u64) << 56));
    }
    // The top bits, which the multiplications mix best.
    (hash >> (64 - SLOT_BITS)) as usize
}

/// The scene of `cells` with `wanted` claimed, as `solve` gives it (`None`: the general row
/// takes its rows): this thread's last scene, or a recent one, when its key and type are the
/// same; else solved now and kept. (The unit test below shows a run solved once.)
pub(super) fn solved<S: Any>(
    cells: &[&[u8]],
    wanted: &[bool],
    solve: impl FnOnce() -> Option<S>,
) -> Rc<Option<S>> {
    RECENT.with(|recent| {
        let mut recent = recent.borrow_mut();
        let kept_for = |recent: &Recent, at: usize| {
            recent
                .table
                .get(at)?
                .as_ref()
                .filter(|kept| kept.is_for(cells, wanted))?
                .as_a::<S>()
        };
        if let Some(solved) = kept_for(&recent, recent.last) {
            return solved;
        }
        let at = slot(cells, wanted);
        recent.last = at;
        if let Some(solved) = kept_for(&recent, at) {
            return solved;
        }
        if recent.table.is_empty() {
            recent.table.resize_with(SLOTS, || None);
        }
        // The table stays borrowed while the scene is solved (letting it go and taking it
        // again cost 100 instructions a row): a solve never looks a scene up.
        let fresh = Rc::new(solve());
        recent.table[at] = Some(Kept::of(cells, wanted, Rc::clone(&fresh) as Rc<dyn Any>));
        fresh
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A run of rows of one scene is solved once; another scene, other claims or another
    /// type of solved scene is solved anew; cells that only join to the same text are another
    /// scene; a list of scenes run again is not solved again.
    #[test]
    fn a_scene_is_solved_once_for_its_run_of_rows() {
        let solves = std::cell::Cell::new(0);
        let solve = |x: u32| {
            solves.set(solves.get() + 1);
            Some(x)
        };
        let a: [&[u8]; 2] = [b"1", b"1/2"];
        assert_eq!(*solved(&a, &[true], || solve(1)), Some(1));
        assert_eq!(*solved(&a, &[true], || solve(2)), Some(1));
        assert_eq!(*solved(&a, &[false], || solve(3)), Some(3));
        let joined: [&[u8]; 2] = [b"11", b"/2"];
        assert_eq!(*solved(&joined, &[true], || solve(4)), Some(4));
        assert_eq!(*solved(&joined, &[true], || solve(5)), Some(4));
        assert_eq!(solves.get(), 3);
        // The first scene again, after two others: kept in the table.
        assert_eq!(*solved(&a, &[true], || solve(6)), Some(1));
        assert_eq!(solves.get(), 3);
        // The same key as another type: solved anew.
        assert_eq!(*solved(&joined, &[true], || Some("x")), Some("x"));
        // A scene the word rows cannot take is kept as such.
        let b: [&[u8]; 2] = [b"2", b"1/2"];
        assert_eq!(*solved::<u32>(&b, &[true], || None), None);
        assert_eq!(*solved(&b, &[true], || solve(7)), None);
        assert_eq!(solves.get(), 3);
    }

    /// A log's list of 40 scenes (of distinct slots) run at three settings, each scene a run of
    /// two rows: each scene is solved once; a scene whose slot another took since is solved
    /// again.
    #[test]
    fn a_list_of_scenes_run_again_is_solved_once() {
        // The first 40 scenes of distinct slots among 1/7, 2/7, ...
        let mut taken = std::collections::BTreeSet::new();
        let texts: Vec<String> = (1..)
            .map(|k| format!("{k}/7"))
            .filter(|t| taken.insert(slot(&[t.as_bytes(), b"uniform"], &[true])))
            .take(40)
            .collect();
        let scene = |k: usize| [texts[k].as_bytes(), b"uniform".as_slice()];
        let solves = std::cell::Cell::new(0);
        for _setting in 0..3 {
            for k in 0..40 {
                for _row in 0..2 {
                    let got = solved(&scene(k), &[true], || {
                        solves.set(solves.get() + 1);
                        Some(k)
                    });
                    assert_eq!(*got, Some(k));
                }
            }
        }
        assert_eq!(solves.get(), 40);
        // Another scene in the first one's slot takes it.
        let first = slot(&scene(0), &[true]);
        let rival = (41..)
            .map(|k| format!("{k}/7"))
            .find(|t| !texts.contains(t) && slot(&[t.as_bytes(), b"uniform"], &[true]) == first)
            .expect("some scene shares the slot");
        assert_eq!(
            *solved(&[rival.as_bytes(), b"uniform"], &[true], || Some(99)),
            Some(99)
        );
        assert_eq!(*solved(&scene(0), &[true], || Some(100)), Some(100));
    }
}
