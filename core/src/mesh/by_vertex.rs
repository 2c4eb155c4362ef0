//! Values listed under a mesh's vertices in one flat array: the edges
//! leaving or touching each vertex, found without hashing every edge.

/// Values grouped by vertex (a counting sort), each vertex's list sorted.
pub(super) struct ByVertex<T> {
    /// Where each vertex's list begins in `values`; one more entry than
    /// vertices, the last the total.
    starts: Vec<u32>,
    values: Vec<T>,
}

impl<T: Copy + Default + Ord> ByVertex<T> {
    /// The `(vertex, value)` pairs that `items` yields, grouped by vertex.
    /// `items` is called twice: once to count, once to fill, so that the
    /// lists take one allocation. Each list is sorted, so that a vertex with
    /// thousands of values (the apex of a fan in an imported mesh) costs a
    /// sort and searches, not their square. Every vertex must be below
    /// `vertex_count`.
    pub(super) fn new<I: Iterator<Item = (u32, T)>>(vertex_count: usize, items: impl Fn() -> I) -> Self {
        let mut starts = vec![0u32; vertex_count + 1];
        for (v, _) in items() {
            starts[v as usize + 1] += 1;
        }
        for v in 0..vertex_count {
            starts[v + 1] += starts[v];
        }
        let mut filled = starts.clone();
        let mut values = vec![T::default(); starts[vertex_count] as usize];
        for (v, value) in items() {
            values[filled[v as usize] as usize] = value;
            filled[v as usize] += 1;
        }
        for v in 0..vertex_count {
            values[starts[v] as usize..starts[v + 1] as usize].sort_unstable();
        }
        ByVertex { starts, values }
    }

    /// The values listed under vertex `v`, in order.
    pub(super) fn of(&self, v: u32) -> &[T] {
        &self.values[self.starts[v as usize] as usize..self.starts[v as usize + 1] as usize]
    }

    /// Every vertex's list, vertex by vertex.
    pub(super) fn lists(&self) -> impl Iterator<Item = &[T]> + '_ {
        self.starts.windows(2).map(|w| &self.values[w[0] as usize..w[1] as usize])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_vertex_lists_its_values_sorted() {
        let pairs = [(2u32, 9u32), (0, 4), (2, 1), (3, 7), (2, 5)];
        let by = ByVertex::new(4, || pairs.iter().copied());
        assert_eq!(by.of(0), &[4]);
        assert!(by.of(1).is_empty());
        assert_eq!(by.of(2), &[1, 5, 9]);
        assert_eq!(by.lists().map(<[u32]>::len).collect::<Vec<_>>(), [1, 0, 3, 1]);
    }
}
