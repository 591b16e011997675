//! The scene a thread solved last, for the engine rows: an engine's log runs each scene at
//! every time step and iteration count it tries, row after row (in Rapier's fixture, 944 of
//! 1,062 rows follow a row of the same scene), so the solve, its reductions and the outputs'
//! text are done once a run, not once a row.
//!
//! A solved scene is a function of its cells as written and of which outputs are claimed
//! alone, and those are its key: a row gets the same line whether its scene was solved now or
//! kept. A scene the word rows cannot take is kept too (as `None`), so the rows of its run go
//! to the general row without trying again.

use std::any::Any;
use std::cell::RefCell;
use std::rc::Rc;

/// A solved scene and its key: the claimed outputs, and every cell, one after another, with
/// where each ends.
struct Last {
    wanted: Box<[bool]>,
    cells: Box<[u8]>,
    ends: Box<[usize]>,
    solved: Rc<dyn Any>,
}

thread_local! {
    /// The scene this thread solved last.
    static LAST: RefCell<Option<Last>> = const { RefCell::new(None) };
}

impl Last {
    /// Whether this is the scene of `cells` with `wanted` claimed.
    #[inline]
    fn is_for(&self, cells: &[&[u8]], wanted: &[bool]) -> bool {
        let mut start = 0;
        *self.wanted == *wanted
            && self.ends.len() == cells.len()
            && self.ends.iter().zip(cells).all(|(&end, cell)| {
                let same = self.cells[start..end] == **cell;
                start = end;
                same
            })
    }

    /// `solved`, kept as the scene of `cells` with `wanted` claimed.
    fn of(cells: &[&[u8]], wanted: &[bool], solved: Rc<dyn Any>) -> Last {
        let mut text = Vec::with_capacity(cells.iter().map(|c| c.len()).sum());
        let ends = cells
            .iter()
            .map(|cell| {
                text.extend_from_slice(cell);
                text.len()
            })
            .collect();
        Last {
            wanted: wanted.into(),
            cells: text.into_boxed_slice(),
            ends,
            solved,
        }
    }
}

/// The scene of `cells` with `wanted` claimed, as `solve` gives it (`None`: the general row
/// takes its rows): this thread's last one when its key and type are the same, else solved
/// now and kept.
/// (The unit test below shows a run solved once.)
pub(super) fn solved<S: Any>(
    cells: &[&[u8]],
    wanted: &[bool],
    solve: impl FnOnce() -> Option<S>,
) -> Rc<Option<S>> {
    LAST.with(|last| {
        let mut last = last.borrow_mut();
        if let Some(kept) = last.as_ref().filter(|l| l.is_for(cells, wanted))
            && let Ok(solved) = Rc::clone(&kept.solved).downcast::<Option<S>>()
        {
            return solved;
        }
        let fresh = Rc::new(solve());
        *last = Some(Last::of(cells, wanted, Rc::clone(&fresh) as Rc<dyn Any>));
        fresh
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A run of rows of one scene is solved once; another scene, other claims or another
    /// type of solved scene is solved anew; cells that only join to the same text are another
    /// scene.
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
        assert_eq!(
            *solved(&[b"1".as_slice(), b"1/3"], &[false], || solve(4)),
            Some(4)
        );
        assert_eq!(
            *solved(&[b"11".as_slice(), b"/3"], &[false], || solve(5)),
            Some(5)
        );
        assert_eq!(
            *solved(&[b"11".as_slice(), b"/3"], &[false], || solve(6)),
            Some(5)
        );
        assert_eq!(solves.get(), 4);
        // The same key as another type: solved anew.
        assert_eq!(
            *solved(&[b"11".as_slice(), b"/3"], &[false], || Some("x")),
            Some("x")
        );
        // A scene the word rows cannot take is kept as such.
        assert_eq!(*solved::<u32>(&a, &[true], || None), None);
        assert_eq!(*solved(&a, &[true], || solve(7)), None);
        assert_eq!(solves.get(), 4);
    }
}
