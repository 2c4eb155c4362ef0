//! Which of a loop's searches runs when.

use std::sync::atomic::{AtomicUsize, Ordering};

use rayon::prelude::*;

/// `search(s)` for every start piece `s`, on every core, started in the
/// given order; the results by start piece.
///
/// A loop's searches differ in size by orders of magnitude, and the largest
/// decides how long the loop takes: it must start first, not after the
/// small searches that happen to share its half of a split range (round
/// `circle:40`, `pgfhan61` with two parts began its largest search after
/// 221 ms of others, and one core stood idle for the last 377 ms). Pieces
/// ranked early may use more pieces after them, so their searches tend to
/// be the larger: each core takes the next start in `order` as it frees up.
/// Which search runs where does not change what any search finds, and the
/// results are read in the order of the start pieces, as before, so ties are
/// broken alike. (Only near the state cap, which the searches running at
/// once share, could another schedule pass it at another moment.)
pub(super) fn in_order_of_size<T: Send>(order: &[usize], search: impl Fn(usize) -> T + Sync) -> Vec<T> {
    let next = AtomicUsize::new(0);
    let workers = rayon::current_num_threads().clamp(1, order.len().max(1));
    let mut done: Vec<(usize, T)> = (0..workers)
        .into_par_iter()
        .flat_map_iter(|_| {
            std::iter::from_fn(|| {
                let s = *order.get(next.fetch_add(1, Ordering::Relaxed))?;
                Some((s, search(s)))
            })
            .collect::<Vec<_>>()
        })
        .collect();
    done.sort_by_key(|&(s, _)| s);
    done.into_iter().map(|(_, result)| result).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_start_is_searched_once_and_read_back_by_start_piece() {
        // Searches of very different lengths, started largest first: the
        // results still come back in the order of the start pieces.
        let order = [3, 0, 4, 1, 2];
        let searched = AtomicUsize::new(0);
        let results = in_order_of_size(&order, |s| {
            searched.fetch_add(1, Ordering::Relaxed);
            std::thread::sleep(std::time::Duration::from_millis([1, 1, 1, 20, 5][s]));
            s * 10
        });
        assert_eq!(results, vec![0, 10, 20, 30, 40]);
        assert_eq!(searched.load(Ordering::Relaxed), order.len());
    }

    #[test]
    fn the_first_in_order_starts_first() {
        // One core at a time: the order given is the order searched.
        let pool = rayon::ThreadPoolBuilder::new().num_threads(1).build().unwrap();
        let started = std::sync::Mutex::new(Vec::new());
        pool.install(|| {
            in_order_of_size(&[2, 0, 1], |s| started.lock().unwrap().push(s));
        });
        assert_eq!(started.into_inner().unwrap(), vec![2, 0, 1]);
    }
}
