//! Solving a batch straight into preallocated output columns: [`Batch::fill`] hands each worker a
//! disjoint block of consecutive rows of every column ([`RowBlock`]), so no result is collected
//! and copied again on the calling thread. Rows are still solved chunk by chunk, with the caller's
//! check (an interrupt, progress) between chunks, and every row by the same sequential code, so
//! the output does not depend on the thread count or on how the rows were split.

use super::Batch;
use crate::error::{Error, Result};
use std::ops::ControlFlow;

/// Output storage for a run of consecutive rows that can be cut in two at a row: the columns
/// [`Batch::fill`] writes in place. Implemented for mutable slices, for pairs and for arrays of
/// blocks, so several columns of different types travel together, e.g.
/// `(&mut [i8], [&mut [f64]; 8])`.
pub trait RowBlock: Send + Sized {
    /// The number of rows every part holds.
    ///
    /// # Errors
    /// [`Error::UnequalColumns`] when the parts hold different numbers of rows.
    fn rows(&self) -> Result<usize>;

    /// The first `mid` rows and the rest (`mid` is at most [`RowBlock::rows`]).
    fn split_rows(self, mid: usize) -> (Self, Self);
}

impl<T: Send> RowBlock for &mut [T] {
    fn rows(&self) -> Result<usize> {
        Ok(self.len())
    }

    fn split_rows(self, mid: usize) -> (Self, Self) {
        self.split_at_mut(mid)
    }
}

impl<A: RowBlock, B: RowBlock> RowBlock for (A, B) {
    fn rows(&self) -> Result<usize> {
        same_rows(self.0.rows()?, self.1.rows()?)
    }

    fn split_rows(self, mid: usize) -> (Self, Self) {
        let (a, c) = self.0.split_rows(mid);
        let (b, d) = self.1.split_rows(mid);
        ((a, b), (c, d))
    }
}

/// An array of blocks of equal length (an empty array holds no rows).
impl<A: RowBlock + Default, const N: usize> RowBlock for [A; N] {
    fn rows(&self) -> Result<usize> {
        let Some(first) = self.first() else {
            return Ok(0);
        };
        let rows = first.rows()?;
        self.iter()
            .try_fold(rows, |rows, part| same_rows(rows, part.rows()?))
    }

    fn split_rows(mut self, mid: usize) -> (Self, Self) {
        let mut rest: [A; N] = std::array::from_fn(|_| A::default());
        for (part, tail) in self.iter_mut().zip(&mut rest) {
            let (head, end) = std::mem::take(part).split_rows(mid);
            *part = head;
            *tail = end;
        }
        (self, rest)
    }
}

fn same_rows(rows: usize, other: usize) -> Result<usize> {
    if rows == other {
        Ok(rows)
    } else {
        Err(Error::UnequalColumns { rows, other })
    }
}

/// Blocks per worker thread within a chunk: enough that a worker finishing early steals work
/// from a slower one, few enough that splitting costs nothing measurable.
const BLOCKS_PER_THREAD: usize = 8;

impl Batch {
    /// Solves every row of `out` in place, in parallel: `solve(first_row, block)` fills a block of
    /// consecutive rows (`first_row` is the index of its first row) and returns a value, for
    /// example the rows of the block that failed. Rows are solved chunk by chunk
    /// ([`Batch::chunk_rows`]); after each chunk `between(first_row_of_chunk, values)` receives
    /// the values of the chunk's blocks in row order and may return [`ControlFlow::Break`] to
    /// stop: the run then returns the break value, and the rows of later chunks keep what `out`
    /// held.
    ///
    /// How a chunk is split into blocks depends on the thread count, so `solve` must write each
    /// row from that row's inputs alone (as every analysis here does) for the output not to
    /// depend on it.
    ///
    /// # Errors
    /// [`Error::ThreadPool`] if the pool cannot be started; [`Error::UnequalColumns`] if the
    /// parts of `out` hold different numbers of rows.
    pub fn fill<P, R, B>(
        &self,
        out: P,
        solve: impl Fn(usize, P) -> R + Sync,
        mut between: impl FnMut(usize, Vec<R>) -> ControlFlow<B>,
    ) -> Result<Option<B>>
    where
        P: RowBlock,
        R: Send,
    {
        let rows = out.rows()?;
        self.with_pool(|pool| {
            let threads = pool.map_or(1, |p| p.current_num_threads().max(1));
            let leaf = self
                .chunk_rows()
                .div_ceil(threads.saturating_mul(BLOCKS_PER_THREAD))
                .max(1);
            let (mut first, mut rest) = (0, out);
            while first < rows {
                let take = self.chunk_rows().min(rows - first);
                let (chunk, tail) = rest.split_rows(take);
                rest = tail;
                let values = match pool {
                    Some(pool) => pool.install(|| solve_blocks(first, chunk, take, leaf, &solve)),
                    None => vec![solve(first, chunk)],
                };
                if let ControlFlow::Break(value) = between(first, values) {
                    return Some(value);
                }
                first += take;
            }
            None
        })
    }
}

/// Splits `block` (rows `first..first + rows`) in halves down to `leaf` rows, solves the halves
/// with `rayon::join`, and returns the blocks' values in row order.
fn solve_blocks<P: RowBlock, R: Send>(
    first: usize,
    block: P,
    rows: usize,
    leaf: usize,
    solve: &(impl Fn(usize, P) -> R + Sync),
) -> Vec<R> {
    if rows <= leaf {
        return vec![solve(first, block)];
    }
    let mid = rows / 2;
    let (head, tail) = block.split_rows(mid);
    let (mut values, later) = rayon::join(
        || solve_blocks(first, head, mid, leaf, solve),
        || solve_blocks(first + mid, tail, rows - mid, leaf, solve),
    );
    values.extend(later);
    values
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two columns of different types, each row a function of its index alone.
    fn square_and_parity(batch: &Batch, rows: usize) -> (Vec<u64>, Vec<bool>, Vec<usize>) {
        let (mut squares, mut odd) = (vec![0u64; rows], vec![false; rows]);
        let mut firsts = Vec::new();
        let stopped = batch
            .fill(
                (squares.as_mut_slice(), [odd.as_mut_slice()]),
                |first, (s, [o]): (&mut [u64], [&mut [bool]; 1])| {
                    for (k, (s, o)) in s.iter_mut().zip(o.iter_mut()).enumerate() {
                        let i = (first + k) as u64;
                        *s = i * i;
                        *o = i % 2 == 1;
                    }
                    first
                },
                |chunk_first, blocks| {
                    assert_eq!(
                        blocks.first(),
                        Some(&chunk_first),
                        "first block opens the chunk"
                    );
                    assert!(
                        blocks.windows(2).all(|w| w[0] < w[1]),
                        "blocks in row order"
                    );
                    firsts.extend(blocks);
                    ControlFlow::<()>::Continue(())
                },
            )
            .expect("pool starts");
        assert_eq!(stopped, None);
        (squares, odd, firsts)
    }

    #[test]
    fn every_row_is_written_whatever_the_threads_and_chunks() {
        let rows = 1000;
        let squares: Vec<u64> = (0..rows as u64).map(|i| i * i).collect();
        let odd: Vec<bool> = (0..rows).map(|i| i % 2 == 1).collect();
        for (threads, chunk) in [(1, 7), (2, 1000), (3, 64), (8, 1), (2, 5000)] {
            let batch = Batch::new(Some(threads))
                .and_then(|b| b.with_chunk_rows(chunk))
                .expect("valid batch");
            let (s, o, firsts) = square_and_parity(&batch, rows);
            assert_eq!(s, squares, "{threads} threads, chunks of {chunk}");
            assert_eq!(o, odd, "{threads} threads, chunks of {chunk}");
            assert_eq!(firsts.first(), Some(&0));
        }
        let (s, _, firsts) = square_and_parity(&Batch::new(Some(2)).expect("valid"), 0);
        assert!(s.is_empty() && firsts.is_empty(), "no rows, no blocks");
    }

    #[test]
    fn between_stops_the_run_and_later_chunks_keep_their_values() {
        let batch = Batch::new(Some(2))
            .and_then(|b| b.with_chunk_rows(10))
            .expect("valid");
        let mut out = vec![-1i64; 100];
        let mut chunks = 0;
        let stopped = batch
            .fill(
                out.as_mut_slice(),
                |first, block: &mut [i64]| {
                    for (k, v) in block.iter_mut().enumerate() {
                        *v = (first + k) as i64;
                    }
                },
                |_, _| {
                    chunks += 1;
                    if chunks == 3 {
                        ControlFlow::Break(chunks)
                    } else {
                        ControlFlow::Continue(())
                    }
                },
            )
            .expect("pool starts");
        assert_eq!(stopped, Some(3), "stopped after the third chunk");
        let expected: Vec<i64> = (0..30).chain(std::iter::repeat_n(-1, 70)).collect();
        assert_eq!(out, expected, "three chunks solved, the rest untouched");
    }

    #[test]
    fn columns_of_different_lengths_are_an_error() {
        let (mut a, mut b) = (vec![0.0; 10], vec![0.0; 9]);
        let batch = Batch::new(Some(1)).expect("valid");
        let outcome = batch.fill(
            (a.as_mut_slice(), b.as_mut_slice()),
            |_, _| (),
            |_, _| ControlFlow::<()>::Continue(()),
        );
        assert_eq!(
            outcome,
            Err(Error::UnequalColumns { rows: 10, other: 9 }),
            "pairs check both parts"
        );
        let (mut c, mut d) = (vec![0.0; 10], vec![0.0; 11]);
        let uneven = [a.as_mut_slice(), c.as_mut_slice(), d.as_mut_slice()];
        assert_eq!(
            uneven.rows(),
            Err(Error::UnequalColumns {
                rows: 10,
                other: 11
            }),
            "arrays check every part"
        );
        let empty: [&mut [f64]; 0] = [];
        assert_eq!(empty.rows(), Ok(0), "an empty array holds no rows");
    }
}
